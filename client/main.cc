// meshseg: the command-line client. `meshseg help` lists the subcommands.
// Exit code 0 on success; otherwise one line on stderr and 1 (2 for usage).
#include <cstdio>
#include <map>
#include <string>

#include "absl/strings/str_replace.h"
#include "client/commands.h"

namespace {

constexpr char kUsage[] =
    "usage: meshseg <command> ...\n"
    "  info FILE [--json] [--memory-estimate]\n"
    "  generate PART -o FILE [--voxel-size H] [--noise S] [--ground-truth GT.json]\n"
    "           [--volume OUT.nrrd [--binary]]\n"
    "  generate PART --scan CLOUD.xyz [--scan-points N] [--views N] [--scan-noise S]\n"
    "           [--outliers F] [--scan-normals] [--ground-truth GT.json]\n"
    "  generate PART --surface-points N -o CLOUD.xyz [--scan-noise S]\n"
    "  generate CAD_PART --cad -o FILE.stl|obj [--deflection coarse|fine] [--unit m|mm|um]\n"
    "           [--ground-truth GT.json]\n"
    "  convert IN OUT\n"
    "  reconstruct CLOUD -o MESH.ply [--format FMT] [--open]\n"
    "  segment INPUT -o RESULT.json [--colored-ply OUT.ply] [--distance-tolerance X]\n"
    "          [--angle-tolerance DEG] [--format FMT] [--server HOST:PORT]\n"
    "          [--path exact|scan] [--exact-tolerance X]\n"
    "  jobs --server HOST:PORT\n"
    "  status JOB --server HOST:PORT\n"
    "  watch JOB --server HOST:PORT\n"
    "  result JOB -o RESULT.json --server HOST:PORT\n"
    "  cancel JOB --server HOST:PORT\n"
    "  report RESULT.json [MESH] -o REPORT.html [--format FMT]\n"
    "(segment also takes --report REPORT.html)\n"
    "(segment also takes --step OUT.step [--unit U], --include-mesh, --length-unit U,\n"
    " and with --server --request-id ID)\n"
    "(reconstruct and segment of a point cloud take --open: areas no point supports\n"
    " are left open instead of closed by minimal patches)\n"
    "(segment also takes --freeform-fit on|off (default on: freeform regions get a Loop\n"
    " control mesh, regions[].subdivision) and --freeform-fraction F (control faces per\n"
    " region face, default 0.05))\n"
    "  brep RESULT.json MESH -o OUT.step [--unit mm|cm|m|in|...]\n"
    "  simplify IN -o OUT (--target-faces N | --max-error E) [--regions RESULT.json\n"
    "           [--labels-out LABELS.json]]\n"
    "  subdivide-fit IN -o CONTROL.obj [--faces N | --tolerance E] [--limit OUT.ply]\n"
    "volumes (nrrd, mha, mhd, raw) go through info and segment; options:\n"
    "  [--iso V] [--volume-mode auto|grey|binary] [--dims X,Y,Z --spacing SX,SY,SZ\n"
    "   --type uint8|uint16|int16|float32 [--origin X,Y,Z] [--big-endian]] (raw)\n"
    "(--server defaults to $MESHSEG_SERVER)\n"
    "Commands with --server also take --tls-ca CA.pem (TLS; the server's CA),\n"
    "--tls-cert CERT.pem --tls-key KEY.pem (mutual TLS) and --token TOKEN\n"
    "(default $MESHSEG_TOKEN; sent as \"authorization: Bearer TOKEN\").\n";

}  // namespace

int main(int argc, char** argv) {
  using Command = absl::Status (*)(const meshseg::cli::Argv&);
  const std::map<std::string, Command> commands = {
      {"info", meshseg::cli::RunInfo},       {"generate", meshseg::cli::RunGenerate},
      {"convert", meshseg::cli::RunConvert}, {"segment", meshseg::cli::RunSegment},
      {"jobs", meshseg::cli::RunJobs},       {"status", meshseg::cli::RunStatus},
      {"watch", meshseg::cli::RunWatch},     {"result", meshseg::cli::RunResult},
      {"cancel", meshseg::cli::RunCancel},  {"reconstruct", meshseg::cli::RunReconstruct},
      {"report", meshseg::cli::RunReport},
      {"brep", meshseg::cli::RunBrep},
      {"simplify", meshseg::cli::RunSimplify},
      {"subdivide-fit", meshseg::cli::RunSubdivideFit},
  };
  if (argc < 2 || std::string(argv[1]) == "help" || std::string(argv[1]) == "--help") {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const auto it = commands.find(argv[1]);
  if (it == commands.end()) {
    std::fprintf(stderr, "meshseg: unknown command \"%s\" (try: meshseg help)\n", argv[1]);
    return 2;
  }
  const absl::Status status = it->second(meshseg::cli::Argv(argv + 2, argv + argc));
  if (status.ok()) return 0;
  // One line, whatever the message holds.
  const std::string message = absl::StrReplaceAll(std::string(status.message()), {{"\n", " "}});
  std::fprintf(stderr, "meshseg %s: %s\n", argv[1], message.c_str());
  return 1;
}
