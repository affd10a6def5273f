// meshseg simplify through the real binary: --target-faces and --max-error
// reduce a finely split box without leaving its surface or losing a corner
// (a corner may slide along a box edge by less than one input edge);
// --regions keeps every face's label and the label boundaries (also across a
// flat side, where no crease holds them), written by --labels-out; bad
// arguments and unreadable files are one line on stderr and exit code 1.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "meshseg/proto/result_json.h"
#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::SizeIs;
using testing_cli::Lines;
using testing_cli::RunCli;
using testing_files::ReadText;
using testing_server::FreshDir;

const Eigen::Vector3d kBox(2.0, 1.0, 0.5);
constexpr int kSplits = 20;  // 6 sides x 20 x 20 x 2 = 4800 faces
constexpr double kOnSurface = 1e-9;
// The input's shortest edge (the box's 0.5 side in 20 steps).
constexpr double kInputEdge = 0.5 / kSplits;

struct OffMesh {
  std::vector<Eigen::Vector3d> v;
  std::vector<std::array<int, 3>> f;
};

// Reads the OFF file meshseg writes (triangles only).
OffMesh ReadOff(const std::string& path) {
  OffMesh m;
  std::istringstream in(ReadText(path));
  std::string magic;
  size_t nv = 0, nf = 0, ne = 0;
  in >> magic >> nv >> nf >> ne;
  EXPECT_EQ(magic, "OFF") << path;
  m.v.resize(nv);
  for (Eigen::Vector3d& p : m.v) in >> p.x() >> p.y() >> p.z();
  m.f.resize(nf);
  for (std::array<int, 3>& t : m.f) {
    int n = 0;
    in >> n >> t[0] >> t[1] >> t[2];
    EXPECT_EQ(n, 3);
  }
  EXPECT_TRUE(in) << path << " is truncated";
  return m;
}

// Distance of p from the box's surface (p inside or on it).
double OffSurface(const Eigen::Vector3d& p) {
  double d = HUGE_VAL;
  for (int a = 0; a < 3; ++a) d = std::min({d, std::abs(p[a]), std::abs(kBox[a] - p[a])});
  const bool inside =
      (p.array() >= -kOnSurface).all() && (p.array() <= kBox.array() + kOnSurface).all();
  return inside ? d : HUGE_VAL;
}

// Every vertex on the box's surface and each of its 8 corners near a vertex
// (within one input edge: a corner's collapse may slide it along a box edge,
// which keeps the surface but rounds the corner that little).
void ExpectOnTheBoxWithItsCorners(const OffMesh& m) {
  for (const Eigen::Vector3d& p : m.v) ASSERT_LE(OffSurface(p), kOnSurface) << p.transpose();
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d corner(c & 1 ? kBox.x() : 0.0, c & 2 ? kBox.y() : 0.0,
                                 c & 4 ? kBox.z() : 0.0);
    const bool kept = std::any_of(m.v.begin(), m.v.end(), [&](const Eigen::Vector3d& p) {
      return (p - corner).norm() < kInputEdge;
    });
    EXPECT_TRUE(kept) << "corner " << corner.transpose();
  }
}

std::string WriteBox(const std::string& dir) {
  const std::string path = dir + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(kSplits, kBox), path);
  return path;
}

TEST(MeshsegSimplify, TargetFacesKeepsTheSurfaceAndTheCorners) {
  const std::string dir = FreshDir("simplify");
  const std::string in = WriteBox(dir), out = dir + "/small.off";
  const testing_cli::CliRun r = RunCli({"simplify", in, "-o", out, "--target-faces", "480"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_THAT(r.out, HasSubstr("wrote " + out + ": 4800 -> "));
  EXPECT_THAT(r.out, HasSubstr("Hausdorff"));
  const OffMesh m = ReadOff(out);
  // Each collapse removes two faces of a closed mesh: the target or one under.
  EXPECT_GE(m.f.size(), 479u);
  EXPECT_LE(m.f.size(), 480u);
  ExpectOnTheBoxWithItsCorners(m);
}

TEST(MeshsegSimplify, MaxErrorAloneReducesFlatSidesFar) {
  const std::string dir = FreshDir("simplify");
  const std::string in = WriteBox(dir), out = dir + "/coarse.off";
  const testing_cli::CliRun r = RunCli({"simplify", in, "-o", out, "--max-error", "0.001"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const OffMesh m = ReadOff(out);
  // Planar sides cost nothing to collapse: under a quarter of the faces.
  EXPECT_LT(m.f.size(), 1200u);
  EXPECT_GE(m.f.size(), 12u);
  ExpectOnTheBoxWithItsCorners(m);
}

// Labels: the side a face lies on, with the top (z = kBox.z) cut in two at
// x = 1 (a label boundary on a flat side); 7 regions.
int TrueLabel(const Eigen::Vector3d& centroid) {
  for (int a = 0; a < 3; ++a) {
    if (std::abs(centroid[a]) <= kOnSurface) return 2 * a;
    if (std::abs(centroid[a] - kBox[a]) <= kOnSurface) {
      if (a == 2 && centroid.x() > 1.0) return 6;
      return 2 * a + 1;
    }
  }
  return -1;
}

TEST(MeshsegSimplify, RegionsKeepEveryLabelAndTheirBoundaries) {
  const std::string dir = FreshDir("simplify");
  const std::string in = WriteBox(dir);
  const testing_files::TestMesh box = testing_files::SplitBox(kSplits, kBox);
  v1::SegmentationResult regions;
  for (const std::array<int, 3>& t : box.f) {
    regions.add_face_labels(TrueLabel((box.v[t[0]] + box.v[t[1]] + box.v[t[2]]) / 3.0));
  }
  for (int r = 0; r < 7; ++r) {
    v1::Region* region = regions.add_regions();
    region->set_id(r);
    region->set_type(v1::SURFACE_TYPE_PLANE);
  }
  const absl::StatusOr<std::string> json = ResultJson(regions);
  ASSERT_TRUE(json.ok()) << json.status();
  testing_files::WriteText(dir + "/regions.json", *json);

  const std::string out = dir + "/small.off", labels = dir + "/labels.json";
  const testing_cli::CliRun r =
      RunCli({"simplify", in, "-o", out, "--target-faces", "480", "--regions",
              dir + "/regions.json", "--labels-out", labels});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wrote " + labels));
  const OffMesh m = ReadOff(out);
  const absl::StatusOr<v1::SegmentationResult> result = ParseResultJson(ReadText(labels));
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_EQ(result->face_labels_size(), static_cast<int>(m.f.size()));
  ASSERT_EQ(result->regions_size(), 7);
  std::vector<int64_t> faces(7, 0);
  for (size_t f = 0; f < m.f.size(); ++f) {
    const Eigen::Vector3d centroid = (m.v[m.f[f][0]] + m.v[m.f[f][1]] + m.v[m.f[f][2]]) / 3.0;
    // The face lies wholly on one side of the top's cut: its label is its
    // centroid's, and no corner is on the other side.
    const int label = TrueLabel(centroid);
    ASSERT_EQ(result->face_labels(static_cast<int>(f)), label) << centroid.transpose();
    if (label == 5 || label == 6) {
      for (int c = 0; c < 3; ++c) {
        const double x = m.v[m.f[f][c]].x();
        EXPECT_TRUE(label == 6 ? x >= 1.0 - kOnSurface : x <= 1.0 + kOnSurface)
            << "face " << f << " crosses the label boundary";
      }
    }
    ++faces[label];
  }
  for (int region = 0; region < 7; ++region) {
    EXPECT_GT(faces[region], 0) << "region " << region << " lost";
    EXPECT_EQ(result->regions(region).face_count(), faces[region]);
  }
}

// One line on stderr naming the problem, exit code 1, no output written.
void ExpectOneLineError(const std::vector<std::string>& args, const std::string& names) {
  const testing_cli::CliRun r = RunCli(args);
  EXPECT_EQ(r.exit_code, 1) << args.back() << "\n" << r.out;
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr(names));
}

TEST(MeshsegSimplify, BadArgumentsAndFilesAreOneLineAndExitOne) {
  const std::string dir = FreshDir("simplify");
  const std::string in = WriteBox(dir), out = dir + "/never.off";
  ExpectOneLineError({"simplify", in, "-o", out}, "give a target face count or a max error");
  ExpectOneLineError({"simplify", dir + "/missing.ply", "-o", out, "--target-faces", "10"},
                     "missing.ply");
  testing_files::WriteText(dir + "/truncated.off", "OFF\n8 12 0\n0 0 0\n1 0 0\n");
  ExpectOneLineError({"simplify", dir + "/truncated.off", "-o", out, "--target-faces", "10"},
                     "truncated.off");
  for (const std::string bad : {"abc", "-5", "2.5", "0", "1e30"}) {
    ExpectOneLineError({"simplify", in, "-o", out, "--target-faces", bad}, "--target-faces");
  }
  for (const std::string bad : {"nan", "0", "-1", "x"}) {
    ExpectOneLineError({"simplify", in, "-o", out, "--max-error", bad}, "--max-error");
  }
  ExpectOneLineError(
      {"simplify", in, "-o", out, "--target-faces", "10", "--labels-out", dir + "/l.json"},
      "--labels-out needs --regions");
  testing_files::WriteText(dir + "/few.json", "{\"face_labels\":[0,0,0]}");
  ExpectOneLineError(
      {"simplify", in, "-o", out, "--target-faces", "10", "--regions", dir + "/few.json"},
      "few.json\" has 3 face labels, the mesh 4800 faces");
  EXPECT_FALSE(std::ifstream(out).good()) << "nothing is written on error";
}

}  // namespace
}  // namespace meshseg
