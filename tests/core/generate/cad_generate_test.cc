// GenerateCadPart(): every CAD-mode part, coarse and fine, is a watertight
// tessellation whose every facet is labelled with a B-rep face whose surface
// holds the facet's vertices to 1e-9 of the diagonal; units scale vertices
// and surfaces alike; bad arguments get errors naming them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "meshseg/fit.h"
#include "meshseg/generate.h"

namespace meshseg {
namespace {

double Diagonal(const TriMesh& mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto v : mesh.vertices()) {
    lo = lo.cwiseMin(ToEigen(mesh.point(v)));
    hi = hi.cwiseMax(ToEigen(mesh.point(v)));
  }
  return (hi - lo).norm();
}

class CadPart : public ::testing::TestWithParam<std::tuple<std::string, CadDeflection>> {};

TEST_P(CadPart, EveryFacetLiesOnItsLabelledFace) {
  const auto& [name, deflection] = GetParam();
  CadParams params;
  params.deflection = deflection;
  const absl::StatusOr<GeneratedPart> part = GenerateCadPart(name, params);
  ASSERT_TRUE(part.ok()) << part.status();
  const TriMesh& mesh = part->mesh.tri;
  ASSERT_EQ(part->face_primitive.size(), mesh.n_faces());
  // No triangle dropped while building the mesh, none without a label.
  for (const int f : part->mesh.face_of_input) ASSERT_GE(f, 0);
  for (const int p : part->face_primitive) {
    ASSERT_GE(p, 0);
    ASSERT_LT(p, static_cast<int>(part->primitives.size()));
  }
  // Welded along the B-rep's edges: a closed surface.
  for (const auto e : mesh.edges()) ASSERT_FALSE(mesh.is_boundary(e)) << "edge " << e.idx();
  // Every B-rep face has facets, and holds every corner of them.
  const double diagonal = Diagonal(mesh);
  std::vector<int> facets(part->primitives.size(), 0);
  double worst = 0.0;
  for (const auto f : mesh.faces()) {
    const PrimitiveTruth& p = part->primitives[part->face_primitive[f.idx()]];
    ++facets[p.id];
    ASSERT_FALSE(p.freeform) << p.name;
    for (const auto v : mesh.fv_range(f)) {
      worst = std::max(worst, std::abs(SignedDistance(p.surface, ToEigen(mesh.point(v)))));
    }
  }
  for (const PrimitiveTruth& p : part->primitives) EXPECT_GT(facets[p.id], 0) << p.name;
  EXPECT_LE(worst / diagonal, 1e-9);
  // Outward facets: the enclosed volume is positive.
  double volume = 0.0;
  for (const auto f : mesh.faces()) {
    std::vector<Eigen::Vector3d> c;
    for (const auto v : mesh.fv_range(f)) c.push_back(ToEigen(mesh.point(v)));
    volume += c[0].dot(c[1].cross(c[2])) / 6.0;
  }
  EXPECT_GT(volume, 0.0);
  std::printf("%s %s: %zu facets, %zu faces, worst vertex %.2g of the diagonal\n", name.c_str(),
              deflection == CadDeflection::kFine ? "fine" : "coarse", mesh.n_faces(),
              part->primitives.size(), worst / diagonal);
}

INSTANTIATE_TEST_SUITE_P(Parts, CadPart,
                         ::testing::Combine(::testing::ValuesIn(CadPartNames()),
                                            ::testing::Values(CadDeflection::kCoarse,
                                                              CadDeflection::kFine)),
                         [](const auto& info) {
                           return std::get<0>(info.param) +
                                  (std::get<1>(info.param) == CadDeflection::kFine ? "_fine"
                                                                                   : "_coarse");
                         });

// The surface types each part is built to hold (counted over B-rep faces).
TEST(GenerateCadPart, PartsHoldTheSurfacesTheyAreBuiltOf) {
  const std::map<std::string, std::map<SurfaceType, int>> expected = {
      // Two cylinders, two annular ends.
      {"cad_tube", {{SurfaceType::kPlane, 2}, {SurfaceType::kCylinder, 2}}},
      // Six flats, two ends, the bore, 6 + 6 chamfer patches; the patch at
      // the corner on the cones' seam (angle 0) is two faces on each cone.
      {"cad_nut",
       {{SurfaceType::kPlane, 8}, {SurfaceType::kCylinder, 1}, {SurfaceType::kCone, 14}}},
      // Bend r 3 and r 5, three holes.
      {"cad_bracket", {{SurfaceType::kCylinder, 5}}},
      // Four corner fillets, three small holes, countersink, counterbore.
      {"cad_plate_holes", {{SurfaceType::kCylinder, 10}, {SurfaceType::kCone, 1}}},
      // Two fillet tori, the chamfer cone, the dimple sphere.
      {"cad_flange_shaft",
       {{SurfaceType::kTorus, 2}, {SurfaceType::kCone, 1}, {SurfaceType::kSphere, 1}}},
  };
  for (const auto& [name, counts] : expected) {
    const absl::StatusOr<GeneratedPart> part = GenerateCadPart(name);
    ASSERT_TRUE(part.ok()) << part.status();
    std::map<SurfaceType, int> found;
    for (const PrimitiveTruth& p : part->primitives) ++found[TypeOf(p.surface)];
    for (const auto& [type, n] : counts) {
      EXPECT_EQ(found[type], n) << name << " " << SurfaceTypeName(type);
    }
  }
}

// A bore split by a groove and a cross hole split by the bore: two faces
// each on one cylinder.
TEST(GenerateCadPart, SplitSurfacesAreSeparateFacesOnOneSurface) {
  const absl::StatusOr<GeneratedPart> part = GenerateCadPart("cad_cross_bore");
  ASSERT_TRUE(part.ok()) << part.status();
  std::map<double, int> cylinders;  // radius -> faces
  for (const PrimitiveTruth& p : part->primitives) {
    if (const auto* c = std::get_if<Cylinder>(&p.surface)) ++cylinders[c->radius];
  }
  EXPECT_EQ(cylinders[4.0], 2);
  EXPECT_EQ(cylinders[2.0], 2);
  EXPECT_EQ(cylinders[6.0], 1);
}

TEST(GenerateCadPart, UnitsScaleVerticesAndSurfaces) {
  const absl::StatusOr<GeneratedPart> mm = GenerateCadPart("cad_flange_shaft");
  ASSERT_TRUE(mm.ok()) << mm.status();
  for (const char* unit : {"m", "um"}) {
    const absl::StatusOr<double> scale = UnitScale(unit);
    ASSERT_TRUE(scale.ok());
    CadParams params;
    params.unit_scale = *scale;
    const absl::StatusOr<GeneratedPart> part = GenerateCadPart("cad_flange_shaft", params);
    ASSERT_TRUE(part.ok()) << part.status();
    ASSERT_EQ(part->mesh.tri.n_vertices(), mm->mesh.tri.n_vertices());
    ASSERT_EQ(part->face_primitive, mm->face_primitive);
    for (const auto v : mm->mesh.tri.vertices()) {
      const Eigen::Vector3d p = ToEigen(mm->mesh.tri.point(v)) * *scale;
      ASSERT_LE((ToEigen(part->mesh.tri.point(v)) - p).norm(), 1e-15 * 50.0 * *scale);
    }
    for (size_t k = 0; k < part->primitives.size(); ++k) {
      if (const auto* t = std::get_if<Torus>(&part->primitives[k].surface)) {
        const Torus& t0 = std::get<Torus>(mm->primitives[k].surface);
        EXPECT_DOUBLE_EQ(t->major_radius, t0.major_radius * *scale);
        EXPECT_DOUBLE_EQ(t->minor_radius, t0.minor_radius * *scale);
      }
      if (const auto* c = std::get_if<Cone>(&part->primitives[k].surface)) {
        EXPECT_DOUBLE_EQ(c->half_angle, std::get<Cone>(mm->primitives[k].surface).half_angle);
      }
    }
  }
}

TEST(GenerateCadPart, FineHasMoreFacetsThanCoarse) {
  CadParams fine;
  fine.deflection = CadDeflection::kFine;
  // Parts with planes, cylinders and cones (the fillet-heavy flange shaft,
  // 13,696 facets fine, is left to the per-part tests).
  for (const std::string name : {"cad_tube", "cad_nut", "cad_bracket"}) {
    const absl::StatusOr<GeneratedPart> a = GenerateCadPart(name);
    const absl::StatusOr<GeneratedPart> b = GenerateCadPart(name, fine);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_GT(b->mesh.tri.n_faces(), a->mesh.tri.n_faces()) << name;
    EXPECT_EQ(b->primitives.size(), a->primitives.size()) << name;
  }
}

TEST(GenerateCadPart, BadArgumentsAreNamed) {
  const absl::StatusOr<GeneratedPart> unknown = GenerateCadPart("cad_teapot");
  ASSERT_EQ(unknown.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(unknown.status().message().find("cad_teapot"), std::string_view::npos);
  EXPECT_NE(unknown.status().message().find("cad_tube"), std::string_view::npos);
  // A voxel part is not a CAD part.
  EXPECT_EQ(GenerateCadPart("test_piece").status().code(), absl::StatusCode::kInvalidArgument);
  for (const double scale : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    CadParams params;
    params.unit_scale = scale;
    const absl::StatusOr<GeneratedPart> part = GenerateCadPart("cad_tube", params);
    ASSERT_EQ(part.status().code(), absl::StatusCode::kInvalidArgument) << scale;
    EXPECT_NE(part.status().message().find("unit_scale"), std::string_view::npos);
  }
  const absl::StatusOr<double> inch = UnitScale("inch");
  ASSERT_EQ(inch.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(inch.status().message().find("\"inch\""), std::string_view::npos);
  EXPECT_NE(inch.status().message().find("um"), std::string_view::npos);
}

TEST(GenerateCadPart, GroundTruthJsonListsEveryFaceAndFacet) {
  const absl::StatusOr<GeneratedPart> part = GenerateCadPart("cad_tube");
  ASSERT_TRUE(part.ok()) << part.status();
  const std::string json = GroundTruthJson(*part);
  EXPECT_NE(json.find(absl::StrCat("\"face_count\": ", part->mesh.tri.n_faces())),
            std::string::npos);
  EXPECT_NE(json.find("\"type\": \"cylinder\", \"cylinder\": {"), std::string::npos);
  EXPECT_NE(json.find("\"radius\": 9.4000000000000004"), std::string::npos);
  EXPECT_EQ(json.find("-1,"), std::string::npos);  // every facet labelled
}

}  // namespace
}  // namespace meshseg
