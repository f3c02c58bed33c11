/// @file lesion.cpp
/// @brief Parsing, placing and measuring lesions (lesion.h).
#include "sim/motion/lesion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace lungar::sim {

namespace {

std::string point_text(const Eigen::Vector3d& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.1f, %.1f, %.1f)", p.x(), p.y(), p.z());
  return text;
}

}  // namespace

Result<Lesion> parse_lesion(const std::string& spec, std::string_view what) {
  const std::string expected = std::string(what) +
                               ": expected NAME=x,y,z,radius_mm (LPS, mm; NAME of letters, digits, '_' or '-'), got '" +
                               spec + "'";
  const std::size_t eq = spec.find('=');
  if (eq == std::string::npos) return fail(expected);
  Lesion l;
  l.name = spec.substr(0, eq);
  if (!lesion_name_ok(l.name)) return fail(expected);
  std::istringstream in(spec.substr(eq + 1));
  char c1 = 0, c2 = 0, c3 = 0;
  in >> l.centre_mm.x() >> c1 >> l.centre_mm.y() >> c2 >> l.centre_mm.z() >> c3 >> l.radius_mm;
  if (!in || c1 != ',' || c2 != ',' || c3 != ',' || !(in >> std::ws).eof() || !l.centre_mm.allFinite() ||
      !std::isfinite(l.radius_mm))
    return fail(expected);
  if (!(l.radius_mm > 0 && l.radius_mm <= kMaxLesionRadiusMm)) {
    char text[200];
    std::snprintf(text, sizeof text, "%.*s %s: expected a radius above 0 and at most %.0f mm, got %g mm",
                  static_cast<int>(what.size()), what.data(), l.name.c_str(), kMaxLesionRadiusMm, l.radius_mm);
    return fail(text);
  }
  return l;
}

Result<std::vector<PlacedLesion>> place_lesions(const InteriorDisplacement& field, const std::vector<Lesion>& lesions,
                                                std::string_view what) {
  const std::string named = std::string(what) + " ";
  std::vector<PlacedLesion> placed;
  for (const Lesion& l : lesions) {
    for (const PlacedLesion& p : placed)
      if (p.lesion.name == l.name) return fail(named + l.name + ": expected each name once, got it twice");
    const int lung = field.lung_containing(l.centre_mm);
    if (lung < 0)
      return fail(named + l.name + ": its centre " + point_text(l.centre_mm) +
                  " (LPS, mm) lies outside every lung; expected a point inside the left or right lung");
    for (int d = 0; d < 27 && !l.from_label; ++d) {
      const int dx = d % 3 - 1, dy = d / 3 % 3 - 1, dz = d / 9 - 1;
      if (dx == 0 && dy == 0 && dz == 0) continue;
      const Eigen::Vector3d p = l.centre_mm + l.radius_mm * Eigen::Vector3d(dx, dy, dz).normalized();
      if (field.lung_containing(p) != lung) {
        char text[64];
        std::snprintf(text, sizeof text, "%.1f mm", l.radius_mm);
        return fail(named + l.name + ": a ball of radius " + text + " around " + point_text(l.centre_mm) +
                    " reaches out of its lung at " + point_text(p) +
                    "; expected the whole lesion inside one lung (a smaller radius, or a centre further in)");
      }
    }
    placed.push_back({l, static_cast<std::size_t>(lung)});
  }
  return placed;
}

BakedLesion baked_lesion(const PlacedLesion& p) {
  const Eigen::Vector3d& c = p.lesion.centre_mm;
  return {p.lesion.name, static_cast<std::uint32_t>(p.lung), {c.x(), c.y(), c.z()}, p.lesion.radius_mm,
          p.lesion.from_label};
}

Lesion lesion_of(const BakedLesion& b) {
  return {b.name, Eigen::Vector3d(b.centre_mm[0], b.centre_mm[1], b.centre_mm[2]), b.radius_mm, b.from_label};
}

std::string describe_lesion(const PlacedLesion& p, const BakedAsset& asset) {
  char radius[48];
  std::snprintf(radius, sizeof radius, "%.1f mm radius", p.lesion.radius_mm);
  return "lesion " + p.lesion.name + ": " + asset.lungs.at(p.lung).name + " lung, " + radius + " at " +
         point_text(p.lesion.centre_mm) + " mm (LPS)" +
         (p.lesion.from_label ? ", the ball of its segmented volume at its centroid" : "");
}

InteriorPoints lesion_centres(const std::vector<PlacedLesion>& lesions) {
  InteriorPoints points;
  for (const PlacedLesion& p : lesions) {
    for (int c = 0; c < 3; ++c) points.positions.push_back(static_cast<float>(p.lesion.centre_mm[c]));
    points.lung_of_point.push_back(static_cast<std::uint8_t>(p.lung));
  }
  return points;
}

double peak_to_peak_mm(const std::vector<Eigen::Vector3d>& displacements, double& si_mm) {
  double most = 0, z_lo = 0, z_hi = 0;
  for (std::size_t i = 0; i < displacements.size(); ++i) {
    z_lo = i == 0 ? displacements[i].z() : std::min(z_lo, displacements[i].z());
    z_hi = i == 0 ? displacements[i].z() : std::max(z_hi, displacements[i].z());
    for (std::size_t j = 0; j < i; ++j) most = std::max(most, (displacements[i] - displacements[j]).norm());
  }
  si_mm = z_hi - z_lo;
  return most;
}

}  // namespace lungar::sim
