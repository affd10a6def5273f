#include "server/usage.h"

#include <algorithm>
#include <vector>

#include "absl/flags/commandlineflag.h"
#include "absl/flags/reflection.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"

namespace meshseg::server {

bool WantsHelp(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") return false;
    const std::string_view name = arg.substr(0, arg.find('='));
    if (name == "--help" || name == "-h" || name == "--helpfull" || name == "--helpshort" ||
        name == "-help") {
      return true;
    }
  }
  return false;
}

std::string UsageText(std::string_view synopsis) {
  std::vector<const absl::CommandLineFlag*> flags;
  for (const auto& [name, flag] : absl::GetAllFlags()) {
    // Abseil's own flags (--flagfile, --fromenv, ...) are defined elsewhere.
    if (absl::StrContains(flag->Filename(), "server/")) flags.push_back(flag);
  }
  std::sort(flags.begin(), flags.end(),
            [](const auto* a, const auto* b) { return a->Name() < b->Name(); });
  std::string text = absl::StrCat(
      "usage: ", std::string(synopsis.data(), synopsis.size()),
      "\n\nFlags (--name=value or --name value; a boolean as --name or --name=false):\n");
  for (const absl::CommandLineFlag* flag : flags) {
    const std::string name = absl::StrReplaceAll(flag->Name(), {{"_", "-"}});
    const std::string value = flag->IsOfType<bool>() ? "" : "=VALUE";
    std::string fallback = flag->DefaultValue();
    if (flag->IsOfType<std::string>()) fallback = absl::StrCat("\"", fallback, "\"");
    absl::StrAppend(&text, "  --", name, value, "  (default: ", fallback, ")\n      ", flag->Help(),
                    "\n");
  }
  return text;
}

}  // namespace meshseg::server
