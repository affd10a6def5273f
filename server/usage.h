// File: usage.h
// -----------------------------------------------------------------------------
// `meshseg-server --help`: every flag the server defines (any ABSL_FLAG in a
// server/ source file), in the hyphenated form the command line takes, with
// its default and help, printed to stdout with exit code 0. Handled before
// absl parses the command line: Debian's Abseil (20220623) lists only flags
// defined in a file named after the program ("No flags matched") and exits 1.
#ifndef MESHSEG_SERVER_USAGE_H_
#define MESHSEG_SERVER_USAGE_H_

#include <string>
#include <string_view>

namespace meshseg::server {

// Returns true if any argument before a bare "--" is --help, -h, --helpfull
// or --helpshort (with or without a value).
bool WantsHelp(int argc, char** argv);

// Returns `synopsis`, then one entry per server flag, sorted by name:
//   --spool-dir=VALUE  (default: "/tmp/meshseg-spool")
//       uploads and results, one folder per job
std::string UsageText(std::string_view synopsis);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_USAGE_H_
