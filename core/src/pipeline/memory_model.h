// The admission memory model: a job's peak resident memory, predicted from
// its input's declared size (ProbeInput) before the input is read, so a
// server admits only jobs that fit its budget and a reader never allocates
// for a header that lies about a size no budget could hold.
//
// How it was measured (bench/memory/peak_rss.sh reproduces it): peak RSS
// ("Maximum resident set size" of /usr/bin/time -v) of `meshseg segment` on
// a 2-core machine, one job per process, for each input kind at several
// sizes, then a least-squares line through the points:
//   scan-like meshes (a machined part sampled at h = 1.0 .. 0.35, binary PLY):
//       45 548 faces 36.3 MiB, 93 032 faces 55.1 MiB, 182 516 faces 91.5 MiB,
//       372 756 faces 166.8 MiB  ->  18.2 MiB + 418 B per face (binary PLY's
//       own 25 B per face included; the file is mapped whole)
//   CAD tessellations segmented on a remesh (the script's STL, 1 252 faces
//       remeshed to 136 406): 93.6 MiB  ->  580 B per remesh face over the
//       base; the remesh holds at most RemeshParams::max_faces faces
//   point clouds (XYZ of the same parts' vertices, 22 774 .. 91 258 points):
//       33.6, 49.1, 78.8 MiB  ->  18.5 MiB + 693 B per point (reconstruction
//       and the segmentation of the reconstructed mesh, ~0.95 faces per point)
// The model takes the base, the mapped file, 400 B per mesh face (418 less
// the binary file's share, which the file term counts for every format),
// room for a full-size remesh whenever the remesh may run, and 700 B per
// point, and multiplies the sum by a safety margin of 1.5 (threads' scratch,
// shapes with more regions than the measured parts).
#ifndef MESHSEG_PIPELINE_MEMORY_MODEL_H_
#define MESHSEG_PIPELINE_MEMORY_MODEL_H_

#include <cstdint>

#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/voxel.h"

namespace meshseg::pipeline_internal {

inline constexpr int64_t kBaseBytes = int64_t{19} << 20;
inline constexpr int64_t kBytesPerMeshFace = 400;
inline constexpr int64_t kBytesPerRemeshFace = 580;
inline constexpr int64_t kBytesPerPoint = 700;
inline constexpr double kSafetyMargin = 1.5;
// PipelineParams::include_mesh: the returned mesh is held three times at the
// end of a job (MeshGeometry: 24 B per vertex at V ~ F / 2 plus 16 B of ids
// and input face per face, ~28 B per face; the result message's copy; its
// serialized bytes), computed from those layouts rather than measured: 96 B
// per face, or per point of a cloud (about one reconstructed face per point).
inline constexpr int64_t kBytesPerReturnedFace = 96;

// Returns the faces a mesh input is costed at: its declared faces, or twice
// its vertices when those are more (a closed mesh has F = 2 V; a header
// declaring far more vertices than faces still pays for them). STL declares
// corners (3 per triangle), so only its faces count.
int64_t CostedFaces(const InputSize& input);

// Returns the predicted peak resident bytes of RunPipeline on `input`.
int64_t PeakBytes(const InputSize& input, const PipelineParams& params);

// Volumes (#33): the surface's faces are not in the header. Marching cubes
// puts about 1.5 triangles on every voxel face of surface (measured on a
// 498 x 340 x 246 grid of a machined part: a box surface of 7.5e5 voxel
// faces gave 1.16e6 triangles); a part's surface is costed at twice its bounding box's
// (holes, pockets): faces = 2 * 1.5 * 2 (nx ny + ny nz + nx nz), i.e. 6 per
// face of the box product. Samples stream two slices at a time (16 B per
// slice voxel).
// A volume that may be binary (mode binary, or auto with 8-bit samples, the
// usual occupancy type) adds ALGORITHMS.md S4's 15 B per voxel (occupancy and
// the morphology's masks and distance map, voxel.h).
inline constexpr int64_t kVolumeFacesPerBoxFace = 6;
inline constexpr int64_t kBytesPerSliceVoxel = 16;
inline constexpr int64_t kBinaryBytesPerVoxel = 15;

// Returns the InputSize a volume is costed as (faces and vertices of its
// expected surface, file bytes) and, in `extra_bytes`, its voxel terms.
InputSize VolumeInputSize(const VolumeInfo& info, const PipelineParams& params,
                          int64_t file_bytes, int64_t* extra_bytes);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_MEMORY_MODEL_H_
