// GenerateCadPart: builds the named B-rep, tessellates it at the chosen
// deflection, scales it to the chosen unit and labels every facet with its
// B-rep face.
#include "meshseg/generate.h"

#include <cmath>
#include <numbers>
#include <type_traits>
#include <utility>
#include <variant>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "generate/cad_parts.h"
#include "generate/cad_tessellation.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

// Chordal deflection relative to the bounding-box diagonal and angular
// deflection: the two settings CAD systems offer for STL export (e.g.
// "coarse" and "fine"; both bound the chord's sag and the angle between
// neighbouring facets' normals).
struct Deflection {
  double chordal;  // of the diagonal
  double angular;  // radians
};

Deflection DeflectionOf(CadDeflection d) {
  constexpr double kDegree = std::numbers::pi / 180.0;
  return d == CadDeflection::kFine ? Deflection{2e-4, 10.0 * kDegree}
                                   : Deflection{2e-3, 30.0 * kDegree};
}

// `surface` with every length multiplied by s (angles and directions kept).
Surface Scaled(const Surface& surface, double s) {
  return std::visit(
      [s](auto x) -> Surface {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Plane>) {
          x.point *= s;
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          x.axis_origin *= s, x.radius *= s;
        } else if constexpr (std::is_same_v<T, Cone>) {
          x.apex *= s;
        } else if constexpr (std::is_same_v<T, Sphere>) {
          x.center *= s, x.radius *= s;
        } else if constexpr (std::is_same_v<T, Torus>) {
          x.center *= s, x.major_radius *= s, x.minor_radius *= s;
        }
        return x;
      },
      surface);
}

}  // namespace

std::vector<std::string> CadPartNames() { return generate_internal::CadCatalogueNames(); }

absl::StatusOr<double> UnitScale(std::string_view unit) {
  if (unit == "m") return 1e-3;
  if (unit == "mm") return 1.0;
  if (unit == "um") return 1e3;
  return absl::InvalidArgumentError(
      absl::StrCat("generate: unknown unit \"", std::string(unit), "\"; known units: m, mm, um"));
}

absl::StatusOr<GeneratedPart> GenerateCadPart(std::string_view name, const CadParams& params,
                                              const RunContext& ctx) {
  if (!std::isfinite(params.unit_scale) || params.unit_scale <= 0.0) {
    return absl::InvalidArgumentError(absl::StrCat("generate: part \"", std::string(name),
                                                   "\": unit_scale ", params.unit_scale,
                                                   " must be finite and > 0"));
  }
  const std::optional<TopoDS_Shape> shape = generate_internal::FindCadPart(name);
  if (!shape) {
    return absl::InvalidArgumentError(
        absl::StrCat("generate: unknown CAD part \"", std::string(name),
                     "\"; known CAD parts: ", absl::StrJoin(CadPartNames(), ", ")));
  }
  if (shape->IsNull()) {
    return absl::InternalError(
        absl::StrCat("generate: OpenCASCADE failed to build CAD part \"", std::string(name), "\""));
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("generate"));
  Bnd_Box box;
  BRepBndLib::AddOptimal(*shape, box, /*useTriangulation=*/false);
  const double diagonal = std::sqrt(box.SquareExtent());
  const Deflection d = DeflectionOf(params.deflection);
  MESHSEG_ASSIGN_OR_RETURN(generate_internal::CadTessellation t,
                           generate_internal::Tessellate(*shape, d.chordal * diagonal, d.angular));
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("generate"));

  GeneratedPart part;
  part.name = std::string(name);
  for (size_t k = 0; k < t.faces.size(); ++k) {
    const generate_internal::CadFace& f = t.faces[k];
    part.primitives.push_back({static_cast<int>(k), absl::StrCat("face_", k, "_", f.kind),
                               Scaled(f.surface, params.unit_scale), f.freeform});
  }
  for (Eigen::Vector3d& v : t.vertices) v *= params.unit_scale;
  part.vertex_primitive = std::move(t.vertex_face);
  MESHSEG_ASSIGN_OR_RETURN(part.mesh, BuildMesh(std::move(t.vertices), t.triangles, part.name));
  const size_t nf = part.mesh.tri.n_faces();
  part.face_primitive.assign(nf, -1);
  part.face_near_boundary.assign(nf, 0);
  for (size_t i = 0; i < part.mesh.face_of_input.size(); ++i) {
    const int f = part.mesh.face_of_input[i];
    if (f >= 0) part.face_primitive[f] = t.triangle_face[i];
  }
  ctx.Progress("generate", 1.0);
  return part;
}

}  // namespace meshseg
