// Writes the CT volume for the end-to-end volume benchmark (issue #33): a
// generated part's grey volume (GenerateVolume, uint16) centred in a cube
// of N^3 samples (default 512) of air, as NRRD (raw encoding). Time and peak
// memory of `meshseg segment` on it come from run_volume_bench.sh.
// Usage: voxel_volume_bench OUT.nrrd [PART] [--size N] [--voxel-size H] [--noise S]
#include <algorithm>
#include <cstdio>
#include <string>

#include "meshseg/generate.h"
#include "meshseg/voxel.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s OUT.nrrd [PART] [--size N] [--voxel-size H] [--noise S]\n",
                 argv[0]);
    return 2;
  }
  const std::string out = argv[1];
  std::string part = "test_piece";
  int n = 512;
  meshseg::GenerateParams gen{.voxel_size = 0.2, .noise = 0.05};
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc)
      n = std::stoi(argv[++i]);
    else if (a == "--voxel-size" && i + 1 < argc)
      gen.voxel_size = std::stod(argv[++i]);
    else if (a == "--noise" && i + 1 < argc)
      gen.noise = std::stod(argv[++i]);
    else
      part = a;
  }
  const absl::StatusOr<meshseg::VolumeData> v =
      meshseg::GenerateVolume(part, /*binary=*/false, gen);
  if (!v.ok()) {
    std::fprintf(stderr, "%s\n", std::string(v.status().message()).c_str());
    return 1;
  }
  const auto& d = v->geometry.dims;
  if (d[0] > n || d[1] > n || d[2] > n) {
    std::fprintf(stderr, "part grid %lld x %lld x %lld exceeds %d^3; raise --voxel-size\n",
                 (long long)d[0], (long long)d[1], (long long)d[2], n);
    return 1;
  }
  meshseg::VolumeData cube;
  cube.type = meshseg::VoxelType::kUint16;
  cube.geometry = v->geometry;
  cube.geometry.dims = {n, n, n};
  int64_t off[3];
  for (int a = 0; a < 3; ++a) {
    off[a] = (n - d[a]) / 2;
    cube.geometry.origin -= static_cast<double>(off[a]) * v->geometry.axes[a];
  }
  // Air is the part volume's own first sample (a corner, always air).
  cube.values.assign(static_cast<size_t>(n) * n * n, v->values.front());
  for (int64_t k = 0; k < d[2]; ++k) {
    for (int64_t j = 0; j < d[1]; ++j) {
      const double* src = v->values.data() + (k * d[1] + j) * d[0];
      double* dst = cube.values.data() + ((k + off[2]) * n + j + off[1]) * n + off[0];
      std::copy(src, src + d[0], dst);
    }
  }
  if (!meshseg::WriteNrrd(cube, out, /*gzip=*/false).ok()) return 1;
  std::printf("wrote %s: %s, part grid %lld x %lld x %lld in %d^3 uint16, h %g\n", out.c_str(),
              part.c_str(), (long long)d[0], (long long)d[1], (long long)d[2], n,
              v->geometry.axes[0].norm());
  return 0;
}
