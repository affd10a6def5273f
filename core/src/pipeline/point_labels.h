// Labels the points of a cloud by the nearest face of the mesh made from it.
#ifndef MESHSEG_PIPELINE_POINT_LABELS_H_
#define MESHSEG_PIPELINE_POINT_LABELS_H_

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::pipeline_internal {

// Returns one label per point: the label of the face of `mesh` closest to
// it (point-to-triangle distance over the faces around the nearest vertex),
// or -1 where is_outlier[k] is set. `face_labels` has one entry per face;
// `is_outlier` is empty or one flag per point.
std::vector<int> PointLabels(const TriMesh& mesh, std::span<const int> face_labels,
                             std::span<const Eigen::Vector3d> points,
                             std::span<const uint8_t> is_outlier);

// Which fitted surfaces PointLabelsBySurface trusts, and when.
struct SurfaceLabelParams {
  // A point within this distance of its nearest face's region's surface
  // keeps that label: the band its noise spreads it over (2 sigma holds 95 %
  // of a normal distribution's points).
  double keep_distance = 0.0;
  // One per region: 1 if its surface describes its points and may take
  // points from a neighbour; other regions take part only through their
  // faces. Only analytic regions (plane, cylinder, cone, sphere, torus) can
  // take part (a quadric's distance is an iteration, a freeform region has
  // no surface).
  std::span<const uint8_t> trusted;
};

// Returns one label per point as PointLabels, except that a point farther
// than keep_distance from its nearest face's region's surface takes, among
// the regions of the faces within two rings of its nearest vertex, the one
// whose fitted surface is nearest to it. The reconstruction rounds a crease
// over about one point spacing and the segmentation assigns that rounded
// band to one side, so the nearest face can lie on the wrong side of the
// true edge; the fitted surfaces run on to the edge itself, and a point of
// one surface, off it only by noise, is nearer to that surface than to a
// neighbour's, which leaves the edge at an angle. The two rings (about three
// spacings on the refined mesh) cover the rounded band and keep surfaces of
// regions elsewhere on the part, which extend far beyond their faces, out.
// Only `trusted` regions take part.
std::vector<int> PointLabelsBySurface(const TriMesh& mesh, std::span<const int> face_labels,
                                      std::span<const Region> regions,
                                      const SurfaceLabelParams& params,
                                      std::span<const Eigen::Vector3d> points,
                                      std::span<const uint8_t> is_outlier);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_POINT_LABELS_H_
