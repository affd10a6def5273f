// WriteStepFile: the unit names BrepParams accepts, an unknown one refused,
// and a face name written where a reader finds it.
// step_checks.h (OpenMesh) before any OpenCASCADE header: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "step_checks.h"

#include "brep/step_file.h"

#include <fstream>
#include <iterator>

#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scratch_dir.h"

namespace meshseg::brep_internal {
namespace {

using ::testing::HasSubstr;

TEST(StepUnitName, KnowsTheUsualUnitsInAnyCase) {
  EXPECT_EQ(StepUnitName("mm"), "MM");
  EXPECT_EQ(StepUnitName("M"), "M");
  EXPECT_EQ(StepUnitName("in"), "INCH");
  EXPECT_EQ(StepUnitName("um"), "UM");
  EXPECT_EQ(StepUnitName("furlong"), "");
  EXPECT_EQ(StepUnitName(""), "");
}

TEST(WriteStepFile, NamesFacesAndDeclaresTheUnit) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape();
  const std::string path = testing_files::ScratchPath("box.step");
  int k = 0;
  const absl::Status s = WriteStepFile(
      box, [&](const TopoDS_Face&) { return "face " + std::to_string(k++); }, "in", "box", path);
  ASSERT_TRUE(s.ok()) << s;
  absl::StatusOr<testing::StepModel> model = testing::ReadStep(path);
  ASSERT_TRUE(model.ok()) << model.status();
  ASSERT_EQ(model->face_names.size(), 6u);
  for (const std::string& name : model->face_names) EXPECT_THAT(name, HasSubstr("face "));
  // The reader names the unit as the file does; the file converts it to
  // millimetres by the exact factor.
  EXPECT_EQ(model->length_unit, "INCH");
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("CONVERSION_BASED_UNIT('INCH'"));
  EXPECT_THAT(text, HasSubstr("25.4"));
}

TEST(WriteStepFile, UnknownUnitIsInvalidArgumentNamingIt) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape();
  const absl::Status s = WriteStepFile(
      box, [](const TopoDS_Face&) { return std::string(); }, "furlong", "box",
      testing_files::ScratchPath("never.step"));
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("\"furlong\""));
}

}  // namespace
}  // namespace meshseg::brep_internal
