#include "client/args.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"

namespace meshseg::cli {
namespace {

bool Contains(std::initializer_list<std::string_view> names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// How a command that talks to a server (it knows --server) reaches it
// securely: the CA of the server's certificate, a client certificate for
// mutual TLS, and the bearer token.
constexpr std::string_view kConnectionFlags[] = {"--tls-ca", "--tls-cert", "--tls-key", "--token"};

bool IsValueFlag(std::initializer_list<std::string_view> value_flags, std::string_view name) {
  if (Contains(value_flags, name)) return true;
  return Contains(value_flags, "--server") &&
         std::find(std::begin(kConnectionFlags), std::end(kConnectionFlags), name) !=
             std::end(kConnectionFlags);
}

}  // namespace

absl::StatusOr<Args> Args::Parse(const std::vector<std::string>& argv,
                                 std::initializer_list<std::string_view> value_flags,
                                 std::initializer_list<std::string_view> switches,
                                 std::size_t positionals) {
  return Parse(argv, value_flags, switches, positionals, positionals);
}

absl::StatusOr<Args> Args::Parse(const std::vector<std::string>& argv,
                                 std::initializer_list<std::string_view> value_flags,
                                 std::initializer_list<std::string_view> switches,
                                 std::size_t min_positionals, std::size_t max_positionals) {
  Args args;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& arg = argv[i];
    if (arg.size() < 2 || arg[0] != '-') {
      args.positional_.push_back(arg);
      continue;
    }
    std::string name = arg;
    std::optional<std::string> value;
    if (const std::size_t eq = arg.find('='); eq != std::string::npos) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
    }
    if (Contains(switches, name) && !value) {
      args.switches_.insert(name);
    } else if (IsValueFlag(value_flags, name)) {
      if (!value) {
        if (i + 1 >= argv.size()) {
          return absl::InvalidArgumentError(absl::StrCat(name, " needs a value"));
        }
        value = argv[++i];
      }
      args.values_[name] = *value;
    } else {
      return absl::InvalidArgumentError(absl::StrCat("unknown option ", arg));
    }
  }
  const std::size_t n = args.positional_.size();
  if (n < min_positionals || n > max_positionals) {
    const std::string expected = min_positionals == max_positionals
                                     ? absl::StrCat(min_positionals)
                                     : absl::StrCat(min_positionals, " to ", max_positionals);
    return absl::InvalidArgumentError(absl::StrCat("expected ", expected, " argument",
                                                   max_positionals == 1 ? "" : "s", ", got ", n));
  }
  return args;
}

bool Args::Has(std::string_view flag) const {
  return switches_.contains(flag) || values_.contains(flag);
}

std::optional<std::string> Args::Value(std::string_view flag) const {
  const auto it = values_.find(flag);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

absl::StatusOr<std::optional<double>> Args::Double(std::string_view flag) const {
  const std::optional<std::string> text = Value(flag);
  if (!text) return std::optional<double>();
  double value = 0.0;
  if (!absl::SimpleAtod(*text, &value) || !std::isfinite(value)) {
    return absl::InvalidArgumentError(
        absl::StrCat(std::string(flag), " must be a number, got \"", *text, "\""));
  }
  return std::optional<double>(value);
}

}  // namespace meshseg::cli
