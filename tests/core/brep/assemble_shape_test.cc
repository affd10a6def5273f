// AssembleShape on the faces of boxes (BRepPrimAPI_MakeBox): each closed
// body becomes a solid oriented outward whatever the orientation of its
// faces, several bodies several solids, a body inside another a void of it,
// and faces that do not close stay shells.
// step_checks.h (OpenMesh) comes before OpenCASCADE headers: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "step_checks.h"

#include "brep/assemble_shape.h"
#include "brep/step_file.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

namespace meshseg::brep_internal {
namespace {

constexpr double kSewing = 1e-6;

// The faces of the box [lo, hi], each reversed if `reversed`.
std::vector<TopoDS_Face> BoxFaces(const gp_Pnt& lo, const gp_Pnt& hi, bool reversed = false) {
  std::vector<TopoDS_Face> out;
  for (TopExp_Explorer it(BRepPrimAPI_MakeBox(lo, hi).Shape(), TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face f = TopoDS::Face(it.Current());
    out.push_back(reversed ? TopoDS::Face(f.Reversed()) : f);
  }
  return out;
}

std::vector<TopoDS_Face> Join(std::vector<TopoDS_Face> a, const std::vector<TopoDS_Face>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(AssembleShape, OneBoxIsOneSolid) {
  const AssembledShape s = AssembleShape(BoxFaces({0, 0, 0}, {2, 3, 4}), kSewing);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.solid);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.solid_count, 1);
  EXPECT_EQ(s.face_count, 6);
  EXPECT_NEAR(s.volume, 24.0, 1e-9);
}

TEST(AssembleShape, FacesOrientedInwardGiveAnOutwardSolid) {
  const AssembledShape s = AssembleShape(BoxFaces({0, 0, 0}, {2, 3, 4}, true), kSewing);
  EXPECT_TRUE(s.solid);
  EXPECT_NEAR(s.volume, 24.0, 1e-9);
  EXPECT_NEAR(testing::FactsOf(s.shape).volume, 24.0, 1e-9);
}

// Written and read back (ReadBack, what a reader sees), the solid of faces
// that came in facing inward is outward, with positive volume, and so is a
// body with a void.
TEST(AssembleShape, SolidsReadBackOutward) {
  const std::string path = testing_files::ScratchPath("assembled.step");
  for (const auto& [faces, volume] :
       {std::pair{BoxFaces({0, 0, 0}, {2, 3, 4}, true), 24.0},
        std::pair{Join(BoxFaces({1, 1, 1}, {2, 2, 2}, true), BoxFaces({0, 0, 0}, {3, 3, 3})),
                  26.0}}) {
    const AssembledShape s = AssembleShape(faces, kSewing);
    ASSERT_TRUE(s.solid);
    ASSERT_TRUE(WriteStepFile(s.shape, [](const TopoDS_Face&) { return ""; }, "mm", "box", path)
                    .ok());
    const absl::StatusOr<ReadBackFacts> back = ReadBack(path, "mm");
    ASSERT_TRUE(back.ok()) << back.status();
    EXPECT_TRUE(back->valid);
    EXPECT_EQ(back->solids, 1);
    EXPECT_EQ(back->free_edges, 0);
    EXPECT_NEAR(back->volume, volume, 1e-9 * volume);
  }
}

TEST(AssembleShape, TwoBodiesAreTwoSolids) {
  const AssembledShape s = AssembleShape(
      Join(BoxFaces({0, 0, 0}, {1, 1, 1}), BoxFaces({5, 0, 0}, {7, 1, 1}, true)), kSewing);
  EXPECT_TRUE(s.solid);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.solid_count, 2);
  EXPECT_EQ(s.face_count, 12);
  EXPECT_NEAR(s.volume, 3.0, 1e-9);
  const testing::ShapeFacts facts = testing::FactsOf(s.shape);
  EXPECT_EQ(facts.solids, 2);
  EXPECT_NEAR(facts.volume, 3.0, 1e-9);
}

// A cavity's faces face into it (as the mesh's normals do), the other way
// than its body's.
TEST(AssembleShape, ABodyInsideAnotherIsItsVoid) {
  const AssembledShape s = AssembleShape(
      Join(BoxFaces({1, 1, 1}, {2, 2, 2}, true), BoxFaces({0, 0, 0}, {3, 3, 3})), kSewing);
  EXPECT_TRUE(s.solid);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.solid_count, 1);
  EXPECT_NEAR(s.volume, 26.0, 1e-9);
  const testing::ShapeFacts facts = testing::FactsOf(s.shape);
  EXPECT_EQ(facts.solids, 1);
  EXPECT_EQ(facts.shells, 2);
  EXPECT_NEAR(facts.volume, 26.0, 1e-9);
}

TEST(AssembleShape, AnIslandInAVoidIsABodyOfItsOwn) {
  const AssembledShape s = AssembleShape(
      Join(Join(BoxFaces({0, 0, 0}, {5, 5, 5}), BoxFaces({1, 1, 1}, {4, 4, 4}, true)),
           BoxFaces({2, 2, 2}, {3, 3, 3})),
      kSewing);
  EXPECT_TRUE(s.solid);
  EXPECT_EQ(s.solid_count, 2);
  EXPECT_NEAR(s.volume, 125.0 - 27.0 + 1.0, 1e-9);
}

// Faces facing out like its encloser's: a body inside another (an assembly's
// part the mesh holds as a separate body), both solids, neither a void.
TEST(AssembleShape, ABodyFacingOutInsideAnotherIsASolidOfItsOwn) {
  const AssembledShape s =
      AssembleShape(Join(BoxFaces({1, 1, 1}, {2, 2, 2}), BoxFaces({0, 0, 0}, {3, 3, 3})), kSewing);
  EXPECT_TRUE(s.solid);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.solid_count, 2);
  EXPECT_NEAR(s.volume, 28.0, 1e-9);
  const testing::ShapeFacts facts = testing::FactsOf(s.shape);
  EXPECT_EQ(facts.solids, 2);
  EXPECT_NEAR(facts.volume, 28.0, 1e-9);
}

TEST(AssembleShape, AnOpenBoxStaysAShell) {
  std::vector<TopoDS_Face> faces = BoxFaces({0, 0, 0}, {1, 1, 1});
  faces.pop_back();
  const AssembledShape s = AssembleShape(faces, kSewing);
  EXPECT_FALSE(s.closed);
  EXPECT_FALSE(s.solid);
  EXPECT_EQ(s.solid_count, 0);
  EXPECT_EQ(s.volume, 0.0);
  EXPECT_EQ(s.face_count, 5);
  EXPECT_EQ(testing::FactsOf(s.shape).free_edges, 4);
}

}  // namespace
}  // namespace meshseg::brep_internal
