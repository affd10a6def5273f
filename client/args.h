// File: args.h
// -----------------------------------------------------------------------------
// Command-line arguments of one `meshseg` subcommand: positionals, flags with
// a value (`--x v` or `--x=v`) and switches (`--json`), each checked against
// the names the subcommand knows.
#ifndef MESHSEG_CLIENT_ARGS_H_
#define MESHSEG_CLIENT_ARGS_H_

#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"

namespace meshseg::cli {

class Args {
 public:
  // Returns `argv` parsed. Errors (INVALID_ARGUMENT): an unknown flag, a
  // value flag without a value, a wrong number of positionals.
  static absl::StatusOr<Args> Parse(const std::vector<std::string>& argv,
                                    std::initializer_list<std::string_view> value_flags,
                                    std::initializer_list<std::string_view> switches,
                                    std::size_t positionals);
  // As above, with between `min_positionals` and `max_positionals`.
  static absl::StatusOr<Args> Parse(const std::vector<std::string>& argv,
                                    std::initializer_list<std::string_view> value_flags,
                                    std::initializer_list<std::string_view> switches,
                                    std::size_t min_positionals, std::size_t max_positionals);

  const std::string& positional(std::size_t i) const { return positional_[i]; }
  std::size_t positional_count() const { return positional_.size(); }
  bool Has(std::string_view flag) const;
  std::optional<std::string> Value(std::string_view flag) const;
  // Errors (INVALID_ARGUMENT): a value that is not a finite number.
  absl::StatusOr<std::optional<double>> Double(std::string_view flag) const;

 private:
  std::vector<std::string> positional_;
  std::map<std::string, std::string, std::less<>> values_;
  std::set<std::string, std::less<>> switches_;
};

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_ARGS_H_
