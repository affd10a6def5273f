#include <sstream>

#include "control_meshes.h"
#include "meshseg/subdiv.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

TEST(WriteControlObj, WritesVerticesFacesAndOpenSubdivTags) {
  const ControlMesh m = testing::CreasedOctahedron();
  const std::string path = ::testing::TempDir() + "/octahedron_control.obj";
  ASSERT_TRUE(WriteControlObj(m, path).ok());
  std::ifstream in(path);
  std::string line;
  std::vector<Eigen::Vector3d> v;
  std::vector<std::array<int, 3>> f;
  std::vector<std::array<int, 2>> creases;
  std::vector<int> corners;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Eigen::Vector3d p;
      s >> p.x() >> p.y() >> p.z();
      v.push_back(p);
    } else if (tag == "f") {
      std::array<int, 3> t;
      s >> t[0] >> t[1] >> t[2];
      f.push_back({t[0] - 1, t[1] - 1, t[2] - 1});
    } else if (tag == "t") {
      std::string name, counts;
      s >> name >> counts;
      if (name == "crease") {
        EXPECT_EQ(counts, "2/1/0");
        std::array<int, 2> c;
        double sharpness = 0;
        s >> c[0] >> c[1] >> sharpness;
        EXPECT_EQ(sharpness, 10.0);
        creases.push_back(c);
      } else {
        EXPECT_EQ(name, "corner");
        EXPECT_EQ(counts, "1/1/0");
        int c = -1;
        s >> c;
        corners.push_back(c);
      }
    }
  }
  EXPECT_EQ(v, m.vertices);  // %.17g reads back bit-identical
  EXPECT_EQ(f, m.faces);
  EXPECT_EQ(creases, m.creases);
  EXPECT_EQ(corners, m.corners);
}

TEST(WriteControlObj, NamesAPathItCannotWrite) {
  const absl::Status s =
      WriteControlObj(testing::CreasedOctahedron(), "/nonexistent_dir/control.obj");
  EXPECT_EQ(s.code(), absl::StatusCode::kInternal);
  EXPECT_THAT(s.message(), HasSubstr("\"/nonexistent_dir/control.obj\""));
}

}  // namespace
}  // namespace meshseg
