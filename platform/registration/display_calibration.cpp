/// @file display_calibration.cpp
/// @brief SPAAM: the alignments file, the normalised DLT and its decomposition (display_calibration.h).
#include "platform/registration/display_calibration.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "config/base/atomic_file.h"
#include "platform/registration/csv_header.h"

namespace lungar::platform {
namespace {

/// Hartley's normalisation: centroid to the origin, mean distance to sqrt(dim).
template <int D>
Eigen::Matrix<double, D + 1, D + 1> normalising(const std::vector<Eigen::Matrix<double, D, 1>>& pts) {
  Eigen::Matrix<double, D, 1> c = Eigen::Matrix<double, D, 1>::Zero();
  for (const auto& p : pts) c += p;
  c /= static_cast<double>(pts.size());
  double mean = 0;
  for (const auto& p : pts) mean += (p - c).norm();
  mean /= static_cast<double>(pts.size());
  const double s = mean > 0 ? std::sqrt(static_cast<double>(D)) / mean : 1.0;
  Eigen::Matrix<double, D + 1, D + 1> t = Eigen::Matrix<double, D + 1, D + 1>::Identity();
  t.template topLeftCorner<D, D>() *= s;
  t.template topRightCorner<D, 1>() = -s * c;
  return t;
}

/// M = K R with K upper triangular (positive diagonal) and R orthonormal: the RQ decomposition, from the QR of
/// the row-reversed transpose.
void rq(const Eigen::Matrix3d& m, Eigen::Matrix3d& k, Eigen::Matrix3d& r) {
  Eigen::Matrix3d flip;
  flip << 0, 0, 1, 0, 1, 0, 1, 0, 0;
  const Eigen::HouseholderQR<Eigen::Matrix3d> qr((flip * m).transpose());
  const Eigen::Matrix3d q = qr.householderQ();
  const Eigen::Matrix3d upper = qr.matrixQR().triangularView<Eigen::Upper>();
  k = flip * upper.transpose() * flip;
  r = flip * q.transpose();
  for (int i = 0; i < 3; ++i) {
    if (k(i, i) < 0) {
      k.col(i) *= -1;
      r.row(i) *= -1;
    }
  }
}

/// An alignments file's columns, which its optional header names; the eye column holds words.
const CsvColumns kAlignmentColumns{{"eye", "x_mm", "y_mm", "z_mm", "u_px", "v_px"}, {"left", "right"}};

Error bad_line(const std::string& path, int line_no, const std::string& why) {
  return fail(path + ":" + std::to_string(line_no) + ": " + why);
}

}  // namespace

Result<std::array<std::vector<Alignment>, 2>> read_alignments_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) return fail(path + ": cannot open: expected a CSV of SPAAM alignments (eye,x_mm,y_mm,z_mm,u_px,v_px)");
  std::array<std::vector<Alignment>, 2> eyes;
  std::string line;
  int line_no = 0;
  bool first = true;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    if (std::exchange(first, false)) {
      auto header = is_csv_header(line, kAlignmentColumns, path, line_no);
      if (!header) return header.with_context("");
      if (*header) continue;
    }
    std::stringstream fields(line);
    std::string eye, cell;
    std::getline(fields, eye, ',');
    double v[5];
    int got = 0;
    for (; got < 5 && std::getline(fields, cell, ','); ++got) {
      char* end = nullptr;
      v[got] = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || !std::isfinite(v[got])) break;
    }
    if (eye != "left" && eye != "right") return bad_line(path, line_no, "eye: expected left or right, got '" + eye + "'");
    if (got != 5 || std::getline(fields, cell, ','))
      return bad_line(path, line_no, "expected five finite numbers x_mm, y_mm, z_mm, u_px, v_px after the eye");
    eyes[eye == "left" ? 0 : 1].push_back({Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector2d(v[3], v[4])});
  }
  if (eyes[0].empty() && eyes[1].empty()) {
    return fail(path + ": expected alignments (" + kAlignmentColumns.header() + "), got none");
  }
  return eyes;
}

Result<EyeCalibration> decompose_projection(Eigen::Matrix<double, 3, 4> p) {
  const double scale = p.block<1, 3>(2, 0).norm();  // K(2,2) = 1: the third row of M at unit length
  if (!(scale > 0) || !p.allFinite()) return fail("expected a finite projection with a non-zero third row");
  p /= scale;
  EyeCalibration e;
  e.projection = p;
  if (std::abs(p.leftCols<3>().determinant()) < 1e-12) return fail("the projection's left 3x3 is singular");
  rq(p.leftCols<3>(), e.intrinsics, e.rotation);
  if (e.rotation.determinant() < 0) return fail("the alignments fit a mirrored projection: check the eye and pixel axes");
  e.centre_mm = -p.leftCols<3>().inverse() * p.col(3);
  return e;
}

Eigen::Vector2d project(const Eigen::Matrix<double, 3, 4>& p, const Eigen::Vector3d& x) {
  const Eigen::Vector3d h = p * x.homogeneous();
  return h.head<2>() / h.z();
}

Result<EyeCalibration> calibrate_eye(const std::vector<Alignment>& al) {
  const auto n = static_cast<int>(al.size());
  if (n < kMinAlignmentsPerEye) {
    return fail("expected at least " + std::to_string(kMinAlignmentsPerEye) + " alignments, got " + std::to_string(n));
  }
  std::vector<Eigen::Vector3d> xs;
  std::vector<Eigen::Vector2d> us;
  for (const Alignment& a : al) {
    xs.push_back(a.point_mm);
    us.push_back(a.pixel);
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& x : xs) centroid += x / n;
  Eigen::MatrixXd centred(n, 3);
  for (int i = 0; i < n; ++i) centred.row(i) = (xs[static_cast<std::size_t>(i)] - centroid).transpose();
  const Eigen::Vector3d spread = Eigen::JacobiSVD<Eigen::MatrixXd>(centred).singularValues();
  if (!(spread(2) > kMinAlignmentSpreadRatio * spread(0))) {
    char why[200];
    std::snprintf(why, sizeof why,
                  "the %d points lie near a plane or a line (spread %.3g of their largest), expected them spread in "
                  "depth (0.3-0.9 m) and across the view",
                  n, spread(0) > 0 ? spread(2) / spread(0) : 0.0);
    return fail(why);
  }
  const Eigen::Matrix4d t3 = normalising<3>(xs);
  const Eigen::Matrix3d t2 = normalising<2>(us);
  Eigen::MatrixXd a(2 * n, 12);
  for (int i = 0; i < n; ++i) {
    const Eigen::RowVector4d x = (t3 * xs[static_cast<std::size_t>(i)].homogeneous()).transpose();
    const Eigen::Vector3d u = t2 * us[static_cast<std::size_t>(i)].homogeneous();
    a.row(2 * i) << x, Eigen::RowVector4d::Zero(), -u.x() * x;
    a.row(2 * i + 1) << Eigen::RowVector4d::Zero(), x, -u.y() * x;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const Eigen::VectorXd h = svd.matrixV().col(11);
  Eigen::Matrix<double, 3, 4> normalised;
  normalised << h.segment<4>(0).transpose(), h.segment<4>(4).transpose(), h.segment<4>(8).transpose();
  Eigen::Matrix<double, 3, 4> p = t2.inverse() * normalised * t3;
  // Sign: the points lie in front of the eye.
  double depth = 0;
  for (const auto& x : xs) depth += (p * x.homogeneous()).z();
  if (depth < 0) p *= -1;
  auto decomposed = decompose_projection(p);
  if (!decomposed) return decomposed.with_context("");
  EyeCalibration e = *decomposed;
  e.alignments = n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = (project(e.projection, xs[static_cast<std::size_t>(i)]) - us[static_cast<std::size_t>(i)]).norm();
    sum += r * r;
    e.max_px = std::max(e.max_px, r);
  }
  e.rms_px = std::sqrt(sum / n);
  return e;
}

Status write_alignments_csv(const std::string& path, const std::array<std::vector<Alignment>, 2>& eyes) {
  std::string out = "eye,x_mm,y_mm,z_mm,u_px,v_px\n";
  for (int e = 0; e < 2; ++e) {
    for (const Alignment& a : eyes[e]) {
      char row[160];
      std::snprintf(row, sizeof row, "%s,%.3f,%.3f,%.3f,%.2f,%.2f\n", e == 0 ? "left" : "right", a.point_mm.x(),
                    a.point_mm.y(), a.point_mm.z(), a.pixel.x(), a.pixel.y());
      out += row;
    }
  }
  return write_file_atomically(path, out);
}

Status write_display_calibration_toml(const std::string& path, const std::array<EyeCalibration, 2>& eyes) {
  std::string out = "# Written by `lungar calibrate-display` (SPAAM, normalised DLT): reprojection RMS left " +
                    std::to_string(eyes[0].rms_px) + " px, right " + std::to_string(eyes[1].rms_px) +
                    " px. Each 3x4 maps the head sensor's frame (mm) to that eye's viewport pixels (origin top-left),"
                    " row-major.\n[hmd.display_calibration]\n";
  for (int e = 0; e < 2; ++e) {
    out += e == 0 ? "left_projection_3x4 = [" : "right_projection_3x4 = [";
    for (int i = 0; i < 12; ++i) {
      char number[40];
      std::snprintf(number, sizeof number, "%s%.10g", i ? ", " : "", eyes[e].projection(i / 4, i % 4));
      out += number;
    }
    out += "]\n";
  }
  return write_file_atomically(path, out);
}

Status write_display_calibration_json(const std::string& path, const std::array<EyeCalibration, 2>& eyes) {
  nlohmann::ordered_json j;
  for (int e = 0; e < 2; ++e) {
    const EyeCalibration& c = eyes[e];
    j[e == 0 ? "left" : "right"] = {{"alignments", c.alignments},
                                    {"rms_px", c.rms_px},
                                    {"max_px", c.max_px},
                                    {"centre_mm", {c.centre_mm.x(), c.centre_mm.y(), c.centre_mm.z()}},
                                    {"focal_px", {c.intrinsics(0, 0), c.intrinsics(1, 1)}},
                                    {"principal_point_px", {c.intrinsics(0, 2), c.intrinsics(1, 2)}}};
  }
  return write_file_atomically(path, j.dump(2) + "\n");
}

}  // namespace lungar::platform
