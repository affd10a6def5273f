// WriteControlObj(): the control mesh as Wavefront OBJ with OpenSubdiv's
// tag lines for creases and corners.
#include <fstream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "meshseg/subdiv.h"

namespace meshseg {

absl::Status WriteControlObj(const ControlMesh& control, const std::string& path) {
  std::ofstream out(path);
  if (!out) {
    return absl::InternalError(absl::StrCat("subdiv: cannot write \"", path, "\""));
  }
  out << "# meshseg Loop subdivision control mesh (scheme: loop)\n"
      << "# creases: t crease 2/1/0 A B 10 (infinitely sharp edge A-B, 0-based)\n"
      << "# corners: t corner 1/1/0 V 10 (vertex V stays put, 0-based)\n"
      << "# boundary edges are sharp whether tagged or not\n";
  for (const Eigen::Vector3d& v : control.vertices) {
    out << absl::StrFormat("v %.17g %.17g %.17g\n", v.x(), v.y(), v.z());
  }
  for (const auto& f : control.faces) {
    out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  }
  for (const auto& c : control.creases) {
    out << "t crease 2/1/0 " << c[0] << ' ' << c[1] << " 10\n";
  }
  for (int v : control.corners) out << "t corner 1/1/0 " << v << " 10\n";
  out.close();
  if (!out) {
    return absl::InternalError(absl::StrCat("subdiv: writing \"", path, "\" failed"));
  }
  return absl::OkStatus();
}

}  // namespace meshseg
