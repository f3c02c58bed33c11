/// @file pivot_calibration.cpp
/// @brief The least-squares pivot calibration of pivot_calibration.h.
#include "platform/registration/pivot_calibration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "config/base/atomic_file.h"
#include "config/toml_writer.h"

namespace lungar::platform {
namespace {

/// How far the stylus direction u that turned least moved: sqrt(min over unit u of the mean |R_i u - R̄ u|²), in
/// degrees. Eliminating the pivot q leaves Σ (R_i - R̄)ᵀ(R_i - R̄) as the normal matrix of the tip, so this is
/// also how well the poses pin the tip down along its worst direction; 0 when every turn is about one axis u.
double least_turn_deg(const std::vector<Eigen::Isometry3d>& poses) {
  Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
  for (const Eigen::Isometry3d& p : poses) mean += p.rotation();
  mean /= static_cast<double>(poses.size());
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  for (const Eigen::Isometry3d& p : poses) {
    const Eigen::Matrix3d d = p.rotation() - mean;
    normal += d.transpose() * d;
  }
  normal /= static_cast<double>(poses.size());
  const double least = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(normal, Eigen::EigenvaluesOnly).eigenvalues()(0);
  return std::sqrt(std::max(least, 0.0)) * 180.0 / M_PI;
}

}  // namespace

Result<PivotFit> fit_pivot(const std::vector<Eigen::Isometry3d>& poses) {
  const auto n = static_cast<Eigen::Index>(poses.size());
  if (n < kMinPivotPoses) {
    return fail("pivot: expected at least " + std::to_string(kMinPivotPoses) + " stylus poses, got " +
                std::to_string(n));
  }
  PivotFit fit;
  fit.poses = static_cast<int>(n);
  const Eigen::Quaterniond first(poses.front().rotation());
  for (const Eigen::Isometry3d& p : poses)
    fit.spread_deg = std::max(fit.spread_deg, Eigen::Quaterniond(p.rotation()).angularDistance(first) * 180.0 / M_PI);
  if (fit.spread_deg < kMinPivotSpreadDeg) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "pivot: the stylus turned at most %.1f degrees, expected at least %.0f (pivot it about its tip in a "
                  "dimple, sweeping a cone)",
                  fit.spread_deg, kMinPivotSpreadDeg);
    return fail(line);
  }
  fit.least_turn_deg = least_turn_deg(poses);
  if (fit.least_turn_deg < kMinPivotLeastTurnDeg) {
    char line[240];
    std::snprintf(line, sizeof line,
                  "pivot: the stylus turned about one axis only (its least-turned direction moved %.2f degrees, "
                  "expected at least %.1f), which leaves the tip anywhere along that axis; sweep a cone about the tip",
                  fit.least_turn_deg, kMinPivotLeastTurnDeg);
    return fail(line);
  }
  Eigen::MatrixXd a(3 * n, 6);
  Eigen::VectorXd b(3 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a.block<3, 3>(3 * i, 0) = poses[static_cast<std::size_t>(i)].rotation();
    a.block<3, 3>(3 * i, 3) = -Eigen::Matrix3d::Identity();
    b.segment<3>(3 * i) = -poses[static_cast<std::size_t>(i)].translation();
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 6) return fail("pivot: the poses leave the tip undetermined (rank " + std::to_string(qr.rank()) + ")");
  const Eigen::VectorXd x = qr.solve(b);
  fit.tip_mm = x.head<3>();
  fit.pivot_mm = x.tail<3>();
  double sum = 0;
  for (const Eigen::Isometry3d& p : poses) {
    const double r = (p.rotation() * fit.tip_mm + p.translation() - fit.pivot_mm).norm();
    sum += r * r;
    fit.max_mm = std::max(fit.max_mm, r);
  }
  fit.rms_mm = std::sqrt(sum / static_cast<double>(n));
  return fit;
}

Status write_tip_offset_toml(const std::string& path, const PivotFit& f) {
  config::TomlWriter document;
  document.section("trackers")
      .section("stylus")
      .numbers("tip_offset_mm", std::array<double, 3>{f.tip_mm.x(), f.tip_mm.y(), f.tip_mm.z()}, -1000.0, 1000.0, "mm");
  char comment[200];
  std::snprintf(comment, sizeof comment,
                "# Written by `lungar calibrate pivot` from %d stylus poses turning up to "
                "%.1f degrees: RMS error %.3f mm, worst %.3f mm.\n",
                f.poses, f.spread_deg, f.rms_mm, f.max_mm);
  return write_file_atomically(path, comment + document.str());
}

}  // namespace lungar::platform
