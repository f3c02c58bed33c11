/// @file quat.h
/// @brief The few quaternion and 3x3 operations the drivers need, on std::array (drivers use no math library).
/// @ingroup drivers
///
/// Quaternions are (w, x, y, z), Hamilton convention; a unit quaternion q rotates v as q v q*.
#pragma once

#include <array>
#include <cmath>

namespace lungar::drivers::quat {

using Q = std::array<double, 4>;
using V = std::array<double, 3>;
using M = std::array<std::array<double, 3>, 3>;  ///< row-major

inline Q mul(const Q& a, const Q& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
inline Q conj(const Q& q) { return {q[0], -q[1], -q[2], -q[3]}; }
inline double norm(const Q& q) { return std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]); }
inline Q normalized(const Q& q) {
  const double n = norm(q);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}
/// Rotation by `angle_rad` about the unit `axis`.
inline Q from_axis_angle(const V& axis, double angle_rad) {
  const double s = std::sin(angle_rad / 2);
  return {std::cos(angle_rad / 2), axis[0] * s, axis[1] * s, axis[2] * s};
}
/// Rotation about coordinate axis 0, 1 or 2.
inline Q about(int axis, double angle_rad) {
  V a = {0, 0, 0};
  a[axis] = 1;
  return from_axis_angle(a, angle_rad);
}
inline V rotate(const Q& q, const V& v) {
  const Q r = mul(mul(q, Q{0, v[0], v[1], v[2]}), conj(q));
  return {r[1], r[2], r[3]};
}
inline M to_matrix(const Q& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return M{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}
/// The unit quaternion of a proper rotation matrix (Shepperd's method, stable for every angle).
inline Q from_matrix(const M& m) {
  const double tr = m[0][0] + m[1][1] + m[2][2];
  Q q;
  if (tr > 0) {
    const double s = std::sqrt(tr + 1.0) * 2;
    q = {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
  } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    const double s = std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2;
    q = {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
  } else if (m[1][1] > m[2][2]) {
    const double s = std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2;
    q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
  } else {
    const double s = std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2;
    q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
  }
  return normalized(q);
}
/// Angle between two rotations, radians in [0, pi] (q and -q are the same rotation).
inline double angle_between(const Q& a, const Q& b) {
  const double d = std::abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  return 2 * std::acos(std::fmin(1.0, d));
}
/// Spherical interpolation from a (t = 0) to b (t = 1), the short way.
inline Q slerp(const Q& a, Q b, double t) {
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  if (d < 0) {
    d = -d;
    b = {-b[0], -b[1], -b[2], -b[3]};
  }
  if (d > 0.9995) {
    return normalized({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]),
                       a[3] + t * (b[3] - a[3])});
  }
  const double th = std::acos(d);
  const double sa = std::sin((1 - t) * th) / std::sin(th), sb = std::sin(t * th) / std::sin(th);
  return {sa * a[0] + sb * b[0], sa * a[1] + sb * b[1], sa * a[2] + sb * b[2], sa * a[3] + sb * b[3]};
}

}  // namespace lungar::drivers::quat
