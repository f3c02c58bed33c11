/// @file stiffness.cpp
/// @brief Assembles K from the mesh edges (each undirected edge once) and the tether.
#include "sim/transfer/stiffness.h"

#include <algorithm>

namespace lungar::sim {

Eigen::VectorXd youngs_modulus(const TriMesh& mesh) {
  const auto n = static_cast<Eigen::Index>(mesh.positions.size());
  Eigen::VectorXd e(n);
  double lo = 1e300, hi = -1e300;
  for (const auto& p : mesh.positions) {
    lo = std::min(lo, p.z());
    hi = std::max(hi, p.z());
  }
  const double height = std::max(hi - lo, 1e-9);
  for (Eigen::Index i = 0; i < n; ++i)
    e[i] = 1.0 + (kApexBaseStiffnessRatio - 1.0) * (mesh.positions[i].z() - lo) / height;
  return e;
}

Eigen::SparseMatrix<double> stiffness_matrix(const TriMesh& mesh, const Eigen::VectorXd& youngs,
                                             const std::vector<double>& areas, double decay_length_mm) {
  const auto n = static_cast<Eigen::Index>(mesh.positions.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(mesh.triangles.size() * 6 + n);
  // Each interior edge of a closed surface belongs to two triangles: visit it from the one where it runs
  // low -> high index, so that it is counted once.
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a > b) continue;
      const double w = 0.5 * (youngs[a] + youngs[b]) / (mesh.positions[a] - mesh.positions[b]).norm();
      entries.emplace_back(a, b, -w);
      entries.emplace_back(b, a, -w);
      entries.emplace_back(a, a, w);
      entries.emplace_back(b, b, w);
    }
  const double inv_l2 = 1.0 / (decay_length_mm * decay_length_mm);
  for (Eigen::Index i = 0; i < n; ++i) entries.emplace_back(i, i, youngs[i] * areas[i] * inv_l2);
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

}  // namespace lungar::sim
