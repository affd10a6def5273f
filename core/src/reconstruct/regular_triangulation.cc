#include "reconstruct/regular_triangulation.h"

#include <algorithm>
#include <iterator>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: tetrahedralization";

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase =
    CGAL::Triangulation_vertex_base_with_info_3<int, K,
                                                CGAL::Regular_triangulation_vertex_base_3<K>>;
using CellBase = CGAL::Regular_triangulation_cell_base_3<K>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Regular = CGAL::Regular_triangulation_3<K, Tds>;
using WeightedPoint = Regular::Weighted_point;

}  // namespace

std::vector<double> RadiiSquared(const std::vector<Support>& supports) {
  std::vector<double> weights(supports.size());
  for (size_t i = 0; i < supports.size(); ++i) weights[i] = supports[i].radius * supports[i].radius;
  return weights;
}

absl::StatusOr<TetMesh> RegularTetrahedralization(const std::vector<Support>& supports,
                                                  const RunContext& ctx) {
  return RegularTetrahedralization(supports, RadiiSquared(supports), ctx);
}

absl::StatusOr<TetMesh> RegularTetrahedralization(const std::vector<Support>& supports,
                                                  const std::vector<double>& weights,
                                                  const RunContext& ctx) {
  std::vector<std::pair<WeightedPoint, int>> input;
  input.reserve(supports.size());
  for (size_t i = 0; i < supports.size(); ++i) {
    if (weights[i] < 0) continue;
    const auto& c = supports[i].center;
    input.emplace_back(WeightedPoint(K::Point_3(c.x(), c.y(), c.z()), weights[i]),
                       static_cast<int>(i));
  }
  Regular rt;
  rt.insert(input.begin(), input.end());
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  if (rt.dimension() < 3) {
    return absl::InvalidArgumentError(absl::StrCat(kStage, ": the ", supports.size(),
                                                   " support centres span dimension ",
                                                   rt.dimension(), ", need 3"));
  }
  // Number tet vertices by increasing support index, so the output does not
  // depend on CGAL's internal order.
  TetMesh out;
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) {
    out.support.push_back(v->info());
  }
  std::sort(out.support.begin(), out.support.end());
  std::vector<int> vertex_of_support(supports.size(), -1);
  for (size_t i = 0; i < out.support.size(); ++i) {
    vertex_of_support[out.support[i]] = static_cast<int>(i);
  }
  const auto id = [&](Regular::Vertex_handle v) { return vertex_of_support[v->info()]; };
  for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c) {
    out.tets.push_back({id(c->vertex(0)), id(c->vertex(1)), id(c->vertex(2)), id(c->vertex(3))});
  }
  for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e) {
    const int a = id(e->first->vertex(e->second));
    const int b = id(e->first->vertex(e->third));
    out.edges.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(out.tets.begin(), out.tets.end());
  std::sort(out.edges.begin(), out.edges.end());
  out.on_hull.assign(out.support.size(), 0);
  std::vector<Regular::Vertex_handle> hull;
  rt.finite_adjacent_vertices(rt.infinite_vertex(), std::back_inserter(hull));
  for (const auto& v : hull) out.on_hull[id(v)] = 1;
  return out;
}

}  // namespace meshseg::reconstruct_internal
