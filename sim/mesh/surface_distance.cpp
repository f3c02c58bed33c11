/// @file surface_distance.cpp
/// @brief Each vertex's distance to the other surface through its triangle tree (sim/mesh/triangle_tree.h).
#include "sim/mesh/surface_distance.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/mesh/triangle_tree.h"
#include "sim/parallel/parallel_for.h"

namespace lungar::sim {
namespace {

/// The largest distance from a vertex of `from` to the surface `to`.
double one_sided(const TriMesh& from, const TriMesh& to, const Workers& workers) {
  const TriangleTree tree(to);
  std::vector<double> d2(from.positions.size(), 0.0);
  parallel_for(d2.size(), workers, [&](std::size_t i) { d2[i] = tree.nearest_d2(from.positions[i]); });
  return d2.empty() ? 0.0 : std::sqrt(*std::max_element(d2.begin(), d2.end()));
}

}  // namespace

double hausdorff_mm(const TriMesh& a, const TriMesh& b, const Workers& workers) {
  return std::max(one_sided(a, b, workers), one_sided(b, a, workers));
}

}  // namespace lungar::sim
