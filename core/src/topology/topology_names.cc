#include "meshseg/topology.h"

namespace meshseg {

const char* CurveGeometryTypeName(CurveGeometryType type) {
  switch (type) {
    case CurveGeometryType::kPolyline: return "polyline";
    case CurveGeometryType::kLine: return "line";
    case CurveGeometryType::kCircle: return "circle";
  }
  return "polyline";
}

const char* CurveConvexityName(CurveConvexity convexity) {
  switch (convexity) {
    case CurveConvexity::kConvex: return "convex";
    case CurveConvexity::kConcave: return "concave";
    case CurveConvexity::kBorder: return "border";
  }
  return "border";
}

const char* LoopKindName(LoopKind kind) {
  switch (kind) {
    case LoopKind::kOuter: return "outer";
    case LoopKind::kInner: return "inner";
    case LoopKind::kAxial: return "axial";
  }
  return "outer";
}

}  // namespace meshseg
