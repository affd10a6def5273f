// Region growing of ALGORITHMS.md S1 step 2.2, written once against a model
// that can be refitted to a vertex set and projects a vertex onto itself: the
// local height function, or any analytic surface / quadric of the fit stage.
#ifndef MESHSEG_SRC_SEGMENT_GROW_REGION_H_
#define MESHSEG_SRC_SEGMENT_GROW_REGION_H_

#include <span>
#include <vector>

#include "meshseg/fit.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

class GrowModel {
 public:
  virtual ~GrowModel() = default;
  // Refits the model to `vertices`; false if the fit is degenerate.
  virtual bool Refit(const SegmentContext& c, std::span<const int> vertices) = 0;
  virtual Projection ProjectOne(const SegmentContext& c, int v) const = 0;
};

// The quadratic height function h(u, w) over the region, in the frame of the
// region's first vertex and its mean smoothed normal.
class HeightModel : public GrowModel {
 public:
  bool Refit(const SegmentContext& c, std::span<const int> vertices) override;
  Projection ProjectOne(const SegmentContext& c, int v) const override;

 private:
  HeightFunction h_;
};

// An analytic surface or general quadric of a fixed type.
class SurfaceModel : public GrowModel {
 public:
  explicit SurfaceModel(SurfaceType type) : type_(type) {}
  bool Refit(const SegmentContext& c, std::span<const int> vertices) override;
  Projection ProjectOne(const SegmentContext& c, int v) const override;
  const FitResult& fit() const { return fit_; }

 private:
  SurfaceType type_;
  FitResult fit_;
};

// Grows `region` (whose vertices have labels[v] == id) over vertices with
// labels[v] == -1 that meet (5) and (6) for `model`, refitting after each
// round until no vertex is added (ALGORITHMS.md S1 step 2.2). Added vertices
// get labels[v] = id. Returns false if the model could not be fitted at all.
bool GrowRegion(const SegmentContext& c, GrowModel* model, const Tolerance& tol, int id,
                std::vector<int>* labels, std::vector<int>* region);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_GROW_REGION_H_
