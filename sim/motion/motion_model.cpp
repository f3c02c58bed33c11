/// @file motion_model.cpp
/// @brief The sliding model's per-vertex boundary conditions and each vertex's direction of motion.
#include "sim/motion/motion_model.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace lungar::sim {

SlidingFaces default_sliding_faces() {
  SlidingFaces f;
  const auto at = [](SurfaceRegion r) { return static_cast<std::size_t>(r); };
  f.tether[at(SurfaceRegion::costal)] = 0.03;
  f.tether[at(SurfaceRegion::diaphragmatic)] = 0.03;
  f.tether[at(SurfaceRegion::mediastinal)] = 2.0;
  // The apex slides in its cupola as the costal face does along the ribs (a strong tether here froze it: apex : base
  // 0.06 against 4-D CT's 0.13-0.55), and the upper ribs lift it a little as they lift the costal face.
  f.tether[at(SurfaceRegion::apical)] = 0.03;
  f.drive[at(SurfaceRegion::costal)] = 0.3;
  f.drive[at(SurfaceRegion::diaphragmatic)] = 1.0;
  f.drive[at(SurfaceRegion::mediastinal)] = 0.0;
  f.drive[at(SurfaceRegion::apical)] = 0.3;
  return f;
}

MotionBoundary sliding_boundary(const std::vector<SurfaceRegion>& regions, const TriMesh& mesh,
                                const std::vector<Eigen::Vector3d>& normals, const SlidingFaces& faces) {
  const auto n = static_cast<Eigen::Index>(regions.size());
  Eigen::AlignedBox3d box;  // the lung's extent: its depth (y) weights the drives, its height (z) fades the slide
  for (const Eigen::Vector3d& p : mesh.positions) box.extend(p);
  const double mid = box.center().y(), depth = std::max(box.sizes().y(), 1e-9);
  const double bottom = box.min().z(), height = std::max(box.sizes().z(), 1e-9);
  MotionBoundary b;
  b.tether_scale.resize(regions.size());
  b.drive = Eigen::MatrixXd::Zero(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(regions[static_cast<std::size_t>(i)]);
    b.tether_scale[static_cast<std::size_t>(i)] = faces.tether[r];
    const bool diaphragm = regions[static_cast<std::size_t>(i)] == SurfaceRegion::diaphragmatic;
    const Eigen::Vector3d dir = diaphragm ? Eigen::Vector3d(0, 0, -1)  // caudal: LPS +z is superior
                                          : normals[static_cast<std::size_t>(i)];
    const double y = mesh.positions[static_cast<std::size_t>(i)].y();
    const double weight = diaphragm ? std::max(0.0, 1.0 + faces.dorsal_gain * (y - mid) / depth) : 1.0;
    b.drive.row(i) = faces.drive[r] * weight * dir.transpose();
    if (regions[static_cast<std::size_t>(i)] == SurfaceRegion::costal) {
      // The costal face is drawn down along the ribs with the base: fully at the bottom, fading to none at the top.
      const double up = std::clamp((mesh.positions[static_cast<std::size_t>(i)].z() - bottom) / height, 0.0, 1.0);
      const double dorsal = std::max(0.0, 1.0 + faces.slide_dorsal_gain * (y - mid) / depth);
      b.drive(i, 2) -= faces.costal_slide * dorsal * std::sqrt(1.0 - up);
    }
  }
  return b;
}

Eigen::Vector3d principal_direction(const Eigen::Vector3d& tau0, const Eigen::Matrix3d& tau_grad, double p0,
                                    double gamma_radius, const Eigen::Vector3d& fallback) {
  Eigen::Matrix3d s = p0 * p0 * tau0 * tau0.transpose();
  s += gamma_radius * gamma_radius * tau_grad * tau_grad.transpose();
  if (!(s.trace() > 0)) return fallback;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s);
  Eigen::Vector3d e = eig.eigenvectors().col(2);  // eigenvalues ascend
  if (e.dot(tau0) < 0 || (e.dot(tau0) == 0 && e.dot(fallback) < 0)) e = -e;
  return e;
}

}  // namespace lungar::sim
