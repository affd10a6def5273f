// RunPipeline() on the CAD-mode generated parts (meshseg/generate.h:
// GenerateCadPart), coarse and fine, in metres, millimetres and micrometres,
// written as CAD systems export them (coarse: binary STL, float32; fine:
// OBJ with 17 digits). Scored against the parts' B-rep faces with
// tests/cad_truth.h: issue 31's bar for generated parts is >= 99.5 % of the
// area right, every face (of any size) found with its type and its
// parameters to 1e-6 of the diagonal, and faces on one surface sharing one
// surface_id.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <tuple>

#include "cad_truth.h"
#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "scratch_dir.h"

namespace meshseg {
namespace {

constexpr double kMinAreaRight = 0.995;
constexpr double kMaxParameterError = 1e-6;  // of the diagonal; radians

std::vector<testing::TruthFace> TruthOf(const GeneratedPart& part) {
  std::vector<testing::TruthFace> truth;
  for (const PrimitiveTruth& p : part.primitives) {
    truth.push_back({p.freeform ? SurfaceType::kFreeform : TypeOf(p.surface), p.surface});
  }
  return truth;
}

using Case = std::tuple<std::string, CadDeflection, std::string>;  // part, deflection, unit

class CadGenerated : public ::testing::TestWithParam<Case> {};

TEST_P(CadGenerated, FacesAndSurfacesAreFoundExactly) {
  const auto& [name, deflection, unit] = GetParam();
  CadParams params;
  params.deflection = deflection;
  const absl::StatusOr<double> scale = UnitScale(unit);
  ASSERT_TRUE(scale.ok()) << scale.status();
  params.unit_scale = *scale;
  const absl::StatusOr<GeneratedPart> part = GenerateCadPart(name, params);
  ASSERT_TRUE(part.ok()) << part.status();
  const bool fine = deflection == CadDeflection::kFine;
  const std::string path =
      testing_files::ScratchPath(absl::StrCat(name, "_", unit, fine ? ".obj" : ".stl"));
  ASSERT_TRUE(WriteMesh(part->mesh.tri, path).ok());

  const auto start = std::chrono::steady_clock::now();
  const absl::StatusOr<PipelineResult> result = RunPipeline(path);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->estimates.path, SegmentationPath::kExactFacets);
  // The file's triangles are the mesh's faces, in order (none dropped).
  ASSERT_EQ(result->face_labels.size(), part->mesh.tri.n_faces());

  const std::vector<testing::TruthFace> truth = TruthOf(*part);
  const testing::CadScore s = testing::ScoreCad(part->mesh, result->face_labels, result->regions,
                                                part->face_primitive, truth, /*min_triangles=*/1);
  std::printf(
      "%s %s %s: %zu facets, %d regions for %d faces (%zu surfaces), area %.3f %%, found %d/%d, "
      "worst %.2g, shared %d/%d, %.2f s\n",
      name.c_str(), fine ? "fine" : "coarse", unit.c_str(), part->mesh.tri.n_faces(), s.regions,
      s.faces, result->surfaces.size(), 100.0 * s.area_right, s.found, s.big_faces, s.worst_error,
      s.shared_once, s.shared, seconds);
  EXPECT_GE(s.area_right, kMinAreaRight);
  EXPECT_EQ(s.found, s.big_faces) << ::testing::PrintToString(s.misses);
  EXPECT_LE(s.worst_error, kMaxParameterError);
  EXPECT_EQ(s.shared_once, s.shared);
}

std::string CaseName(const ::testing::TestParamInfo<Case>& info) {
  return absl::StrCat(std::get<0>(info.param),
                      std::get<1>(info.param) == CadDeflection::kFine ? "_fine_" : "_coarse_",
                      std::get<2>(info.param));
}

auto Cases(std::vector<std::string> parts,
           std::vector<CadDeflection> deflections = {CadDeflection::kCoarse, CadDeflection::kFine},
           std::vector<std::string> units = {"m", "mm", "um"}) {
  return ::testing::Combine(::testing::ValuesIn(parts), ::testing::ValuesIn(deflections),
                            ::testing::ValuesIn(units));
}

// Thin walls, a sheet-metal bend, a bore split by a groove and a cross hole
// split by the bore, countersunk and counterbored holes and small holes in
// a large plate: all pass in all six settings (0.01-1.3 s each).
INSTANTIATE_TEST_SUITE_P(Parts, CadGenerated,
                         Cases({"cad_tube", "cad_cross_bore", "cad_bracket", "cad_plate_holes"}),
                         CaseName);

// Fillet tori (R 8 r 2, R 14 r 1) whose bands are each an exact cone, a
// chamfer cone, a spherical dimple and four small holes: coarse in all three
// units (1-2 s each); fine (13,696 facets, 2-4 s) in millimetres only, to
// keep the suite fast (the results are the same in every unit), the other
// units under DISABLED_Heavy.
INSTANTIATE_TEST_SUITE_P(Tori, CadGenerated, ::testing::ValuesIn([] {
                           std::vector<Case> cases;
                           for (const char* unit : {"m", "mm", "um"}) {
                             cases.emplace_back("cad_flange_shaft", CadDeflection::kCoarse, unit);
                           }
                           cases.emplace_back("cad_flange_shaft", CadDeflection::kFine, "mm");
                           return cases;
                         }()),
                         CaseName);
INSTANTIATE_TEST_SUITE_P(DISABLED_Heavy, CadGenerated,
                         Cases({"cad_flange_shaft"}, {CadDeflection::kFine}, {"m", "um"}),
                         CaseName);

// Segmentation failures these parts reveal (measured 2026-11-26 at main
// d8d71cf's exact-facet segmenter; the same in every unit, so the numbers
// are per deflection). Kept, disabled, until item 2/3 of issue 31 handles
// them; run with --gtest_also_run_disabled_tests.
// - cad_nut (hex 20 AF, both ends chamfered by cones of half angle 60 that
//   the flats cut into 6 + 6 patches, 14 faces with the seam splits):
//   coarse (292 facets, patches of 4-5 facets): every patch is absorbed by
//   the end planes, 9 regions for 23 faces, 97.69 % area right, 9/23 faces
//   found; fine (1008 facets, patches of 14-27): each patch is a FREEFORM
//   region of 25 facets plus a 2-facet plane (patches on the seam: one
//   FREEFORM of 28), 31 regions, 100 % area, 9/23 found, shared 0/2.
INSTANTIATE_TEST_SUITE_P(DISABLED_KnownFailures, CadGenerated, Cases({"cad_nut"}), CaseName);

}  // namespace
}  // namespace meshseg
