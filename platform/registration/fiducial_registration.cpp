/// @file fiducial_registration.cpp
/// @brief Umeyama rigid registration, stylus dwell detection and the fiducial file formats.
#include "platform/registration/fiducial_registration.h"

#include "config/base/atomic_file.h"
#include "config/toml_writer.h"
#include "platform/registration/csv_header.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>

#include <Eigen/Dense>

namespace lungar::platform {

namespace {

/// A points file's columns, which its optional header names.
const CsvColumns kPointColumns{{"x_mm", "y_mm", "z_mm"}, {}};

}  // namespace

Result<Registration> register_fiducials(const std::vector<Eigen::Vector3d>& model,
                                        const std::vector<Eigen::Vector3d>& tracked) {
  Registration out;
  if (model.size() != tracked.size()) {
    return fail("fiducials: expected as many tracked points as model points, got " + std::to_string(tracked.size()) +
            " tracked and " + std::to_string(model.size()) + " model points");
  }
  const auto n = static_cast<Eigen::Index>(model.size());
  if (n < 3) {
    return fail("fiducials: expected at least 3 point pairs, got " + std::to_string(n));
  }
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    src.col(k) = model[static_cast<std::size_t>(k)];
    dst.col(k) = tracked[static_cast<std::size_t>(k)];
  }
  // Collinear (or coincident) model points leave the rotation about their line undetermined.
  // The spread's singular values are the square roots of the 3x3 scatter matrix's eigenvalues (ascending here); a
  // fixed-size eigen solver rather than an SVD of the 3 x n points, which costs the build far more to instantiate.
  const Eigen::Matrix3Xd centred = src.colwise() - src.rowwise().mean();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> scatter(centred * centred.transpose(), Eigen::EigenvaluesOnly);
  const Eigen::Vector3d sv = scatter.eigenvalues().cwiseMax(0.0).cwiseSqrt().reverse();
  if (sv(1) < 1e-6 * std::max(1.0, sv(0))) {
    return fail("fiducials: expected model points spanning a plane, got collinear points");
  }
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, false);
  const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
  out.rotation = Eigen::Quaterniond(R).normalized();
  out.translation_mm = T.topRightCorner<3, 1>();
  double sum2 = 0, worst = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double e = (R * src.col(k) + out.translation_mm - dst.col(k)).norm();
    sum2 += e * e;
    worst = std::max(worst, e);
  }
  out.fre_rms_mm = std::sqrt(sum2 / static_cast<double>(n));
  out.fre_max_mm = worst;
  out.fiducials = static_cast<int>(n);
  return out;
}

Result<std::vector<Eigen::Vector3d>> read_points_csv(const std::string& path) {
  std::vector<Eigen::Vector3d> out;
  std::ifstream in(path);
  if (!in) {
    return fail(path + ": cannot open: expected a CSV of fiducial points (x, y, z in mm per line)");
  }
  out.clear();
  std::string line;
  bool first = true;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (std::exchange(first, false)) {
      auto header = is_csv_header(line, kPointColumns, path, line_no);
      if (!header) return header.with_context("");
      if (*header) continue;
    }
    for (char& c : line) {
      if (c == ',') c = ' ';
    }
    std::istringstream fields(line);
    Eigen::Vector3d p;
    std::string extra;
    if (!(fields >> p.x() >> p.y() >> p.z()) || (fields >> extra) || !p.allFinite()) {
      return fail(path + ":" + std::to_string(line_no) + ": expected three finite numbers x, y, z (mm), got '" + line + "'");
    }
    out.push_back(p);
  }
  return out;
}

Status write_registration_toml(const std::string& path, const Registration& r) {
  config::TomlWriter document;
  config::TomlWriter section = document.section("registration");
  const Eigen::Vector3d& t = r.translation_mm;
  section.numbers("translation_mm", std::array<double, 3>{t.x(), t.y(), t.z()}, -1e4, 1e4, "mm");
  section.numbers("rotation_wxyz",
                  std::array<double, 4>{r.rotation.w(), r.rotation.x(), r.rotation.y(), r.rotation.z()}, -1.0, 1.0, "");
  char comment[160];
  std::snprintf(comment, sizeof comment,
                "# Written by `lungar calibrate` from %d fiducials: RMS error %.3f mm, worst %.3f mm.\n", r.fiducials,
                r.fre_rms_mm, r.fre_max_mm);
  return write_file_atomically(path, comment + document.str());
}

}  // namespace lungar::platform
