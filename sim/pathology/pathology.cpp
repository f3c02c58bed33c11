/// @file pathology.cpp
/// @brief The pathology models of pathology.h, applied to a baked asset's per-vertex response and per-lung figures.
#include "sim/pathology/pathology.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "sim/force/dependent_collapse.h"
#include "sim/motion/surface_regions.h"

namespace lungar::sim {
namespace {

const char* const kExpected =
    "expected pneumothorax:SIDE:PERCENT[:tension], consolidation:SIDE:REGION, emphysema:SEVERITY[:SIDE] or ards:SEVERITY (SIDE "
    "left or right, PERCENT 1 to 90, REGION upper, middle or lower, SEVERITY 0 to 1)";

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(sep, start);
    out.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return out;
    start = end + 1;
  }
}

Error bad(std::string_view spec, const std::string& why) {
  return fail("pathology '" + std::string(spec) + "': " + why);
}

std::size_t find_lung(const BakedAsset& a, const std::string& name) {
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    if (a.lungs[l].name == name) return l;
  return a.lungs.size();
}

Eigen::Vector3d vec(const float* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

/// The lung's first-order swept volume for the unnormalised force SH `f`, mm^3 (unscaled): sum over its vertices
/// of A_I (e_I . n_I) sum_lm T^I_lm f_lm, the sum BakedLung's volume_const and volume_grad are made of.
double swept(const BakedAsset& a, const BakedLung& lung, const std::vector<float>& f) {
  const std::uint32_t c = a.coefficients();
  double sum = 0;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    double d = 0;
    for (std::uint32_t k = 0; k < c; ++k) d += double{a.sh_coeffs[i * c + k]} * f[k];
    sum += a.areas[i] * vec(&a.directions[3 * i]).dot(vec(&a.normals[3 * i])) * d;
  }
  return sum;
}

/// The lung's extent along lung-frame axis `axis` (0 x, 1 y, 2 z).
std::pair<double, double> extent(const BakedAsset& a, const BakedLung& lung, int axis) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    lo = std::min(lo, double{a.positions[3 * i + axis]});
    hi = std::max(hi, double{a.positions[3 * i + axis]});
  }
  return {lo, hi};
}

/// The lung's height extent (z, lung frame: +z superior).
std::pair<double, double> height_range(const BakedAsset& a, const BakedLung& lung) { return extent(a, lung, 2); }

/// The pair's volume-weighted mean x: the body's midline as the lungs give it.
double midline_x(const BakedAsset& a) {
  double x = 0, shares = 0;
  for (const BakedLung& lung : a.lungs) {
    x += lung.volume_share * lung.centre[0];
    shares += lung.volume_share;
  }
  return shares > 0 ? x / shares : 0.0;
}

/// Before a change of the lung's response: its swept volumes as they were, for its weight in the split
/// (breath_share.h), unless an earlier pathology kept them already.
void keep_healthy_volumes(BakedLung& lung) {
  if (!lung.healthy_volumes)
    lung.healthy_volumes = {lung.volume_const, lung.volume_grad[0], lung.volume_grad[1], lung.volume_grad[2]};
}

/// After the lung's response or surface changed: its swept volumes summed again from the arrays, the bake's
/// per-lung factor to the enclosed volume (about 1.03) kept; `before` is the first-order sum from before the
/// change (nothing is done when it is not positive).
void resum_swept_volumes(const BakedAsset& a, BakedLung& lung, double before) {
  if (!(before > 0)) return;
  const double factor = lung.volume_const / before;
  lung.volume_const = factor * swept(a, lung, lung.force_const);
  for (int k = 0; k < 3; ++k) lung.volume_grad[k] = factor * swept(a, lung, lung.force_grad[k]);
}

/// The hilum: the area-weighted centre of the lung's medial face (normals within 60 degrees of the midline) in
/// the middle third of its height, where the bronchus and vessels enter; the lung's centre when it has none.
Eigen::Vector3d hilum(const BakedAsset& a, std::size_t l) {
  const BakedLung& lung = a.lungs[l];
  const Eigen::Vector3d medial = medial_direction(lung.name, lung.centre[0], midline_x(a));
  const auto [lo, hi] = height_range(a, lung);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    const double z = a.positions[3 * i + 2];
    if (z < lo + (hi - lo) / 3 || z > hi - (hi - lo) / 3 || vec(&a.normals[3 * i]).dot(medial) < 0.5) continue;
    sum += a.areas[i] * vec(&a.positions[3 * i]);
    area += a.areas[i];
  }
  return area > 0 ? Eigen::Vector3d(sum / area) : vec(lung.centre.data());
}

/// Scales lung l about its hilum to `volume_factor` of its volume, keeping its shape. The first-order swept
/// volumes scale with the area (s^2): the per-vertex response T is kept, so a unit of force moves the same
/// millimetres over a smaller (or larger) surface.
void scale_about_hilum(BakedAsset& a, std::size_t l, double volume_factor) {
  BakedLung& lung = a.lungs[l];
  const double s = std::cbrt(volume_factor);
  const Eigen::Vector3d h = hilum(a, l);
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    for (int k = 0; k < 3; ++k) a.positions[3 * i + k] = static_cast<float>(h[k] + s * (a.positions[3 * i + k] - h[k]));
    a.areas[i] = static_cast<float>(a.areas[i] * s * s);
  }
  for (int k = 0; k < 3; ++k) lung.centre[k] = static_cast<float>(h[k] + s * (lung.centre[k] - h[k]));
  lung.rest_volume_ml *= s * s * s;
  lung.volume_const *= s * s;
  for (double& v : lung.volume_grad) v *= s * s;
  if (lung.healthy_volumes)
    for (double& v : *lung.healthy_volumes) v *= s * s;
}

/// Collapses lung l to (1 - percent/100) of its volume; its breath weight falls to the collapsed lung's.
void collapse(BakedAsset& a, std::size_t l, double percent) {
  scale_about_hilum(a, l, 1.0 - percent / 100.0);
  a.lungs[l].breath_weight *= kCollapsedLungBreathWeight;
}

/// Tension: the collapsed lung l and the mediastinum move kTensionShiftMm towards the other side, and every other
/// lung is pressed that far from its medial side: scaled along x about its lateral extreme, so that its medial face
/// moves by the shift and its lateral face (on the ribs) stays. Its areas, normals, rest volume and swept volumes
/// follow the scaling; its response per unit of force is its own.
void push_mediastinum(BakedAsset& a, std::size_t l) {
  const double mid = midline_x(a);
  const Eigen::Vector3d towards_other = medial_direction(a.lungs[l].name, a.lungs[l].centre[0], mid);
  const Eigen::Vector3d shift = kTensionShiftMm * towards_other;
  BakedLung& pushed = a.lungs[l];
  for (std::size_t i = pushed.first_vertex; i < std::size_t{pushed.first_vertex} + pushed.vertex_count; ++i)
    for (int k = 0; k < 3; ++k) a.positions[3 * i + k] = static_cast<float>(a.positions[3 * i + k] + shift[k]);
  for (int k = 0; k < 3; ++k) pushed.centre[k] = static_cast<float>(pushed.centre[k] + shift[k]);
  for (std::size_t o = 0; o < a.lungs.size(); ++o) {
    if (o == l) continue;
    BakedLung& lung = a.lungs[o];
    const auto [lo, hi] = extent(a, lung, 0);
    if (!(hi - lo > 2 * kTensionShiftMm)) continue;
    // Its lateral extreme is the one away from the pushed lung.
    const double lateral = towards_other.x() > 0 ? hi : lo;
    const double k = 1.0 - kTensionShiftMm / (hi - lo);
    const double before = swept(a, lung, lung.force_const);
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      a.positions[3 * i] = static_cast<float>(lateral + k * (a.positions[3 * i] - lateral));
      // A surface element under x -> k x: area times sqrt(n_x^2 + k^2 (n_y^2 + n_z^2)), normal along (n_x / k, n_y, n_z).
      Eigen::Vector3d n = vec(&a.normals[3 * i]);
      a.areas[i] = static_cast<float>(a.areas[i] * std::sqrt(n.x() * n.x() + k * k * (n.y() * n.y() + n.z() * n.z())));
      n.x() /= k;
      n.normalize();
      for (int c = 0; c < 3; ++c) a.normals[3 * i + c] = static_cast<float>(n[c]);
    }
    lung.centre[0] = static_cast<float>(lateral + k * (lung.centre[0] - lateral));
    lung.rest_volume_ml *= k;
    resum_swept_volumes(a, lung, before);
  }
}

/// emphysema:SEVERITY[:SIDE] and ards:SEVERITY.
Result<Pathology> parse_severity(std::string_view spec, const std::vector<std::string_view>& parts, Pathology p) {
  if (p.kind == PathologyKind::Ards && parts.size() != 2) return bad(spec, "expected ards:SEVERITY");
  if (parts.size() != 2 && parts.size() != 3)
    return bad(spec, "expected emphysema:SEVERITY or emphysema:SEVERITY:SIDE");
  const std::string number(parts[1]);
  char* end = nullptr;
  p.severity = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !(p.severity >= 0.0 && p.severity <= 1.0))
    return bad(spec, "SEVERITY: expected a number from 0 to 1");
  if (parts.size() == 3) {
    if (parts[2] != "left" && parts[2] != "right") return bad(spec, "SIDE: expected left or right");
    p.side = std::string(parts[2]);
  }
  return p;
}

/// 1 - how much of the region's weight a vertex at height z carries: 1 inside the third, 0 beyond the ramp.
double region_weight(double z, double lo, double hi, LungThird third) {
  const double h = hi - lo, ramp = kConsolidationRamp * h;
  const int index = third == LungThird::Lower ? 0 : third == LungThird::Middle ? 1 : 2;
  const double bottom = lo + index * h / 3, top = lo + (index + 1) * h / 3;
  const double outside = std::max({0.0, bottom - z, z - top});  // distance beyond the third, mm
  return ramp > 0 ? std::clamp(1.0 - outside / ramp, 0.0, 1.0) : (outside > 0 ? 0.0 : 1.0);
}

/// Scales the response of lung l's vertices in the region to kConsolidatedResponse and its swept volumes with it,
/// keeping the healthy ones for its weight in the split (breath_share.h); an error (nothing changed) when its
/// swept volume is not positive.
Status consolidate(BakedAsset& a, std::size_t l, LungThird third, std::string_view spec) {
  BakedLung& lung = a.lungs[l];
  const double before = swept(a, lung, lung.force_const);
  if (!(before > 0)) return bad(spec, "lung '" + lung.name + "' of the asset sweeps no volume to consolidate");
  const auto [lo, hi] = height_range(a, lung);
  const std::uint32_t c = a.coefficients();
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    const double w = region_weight(a.positions[3 * i + 2], lo, hi, third);
    if (w == 0) continue;
    const auto m = static_cast<float>(1.0 - (1.0 - kConsolidatedResponse) * w);
    for (std::uint32_t k = 0; k < c; ++k) a.sh_coeffs[i * c + k] *= m;
    if (!a.linear_coeffs.empty())
      for (int k = 0; k < 4; ++k) a.linear_coeffs[4 * i + k] *= m;
    if (a.has_off_axis())
      for (int k = 0; k < 12; ++k) a.off_axis[12 * i + k] *= m;
  }
  keep_healthy_volumes(lung);
  resum_swept_volumes(a, lung, before);
  return {};
}

/// ARDS: every lung takes the collapsed pattern's force (dependent_collapse.h), its healthy volumes kept for its
/// weight in the split.
Status collapse_dependent(BakedAsset& a, double severity, std::string_view spec) {
  if (std::any_of(a.lungs.begin(), a.lungs.end(), [](const BakedLung& l) { return l.collapse != nullptr; }))
    return bad(spec, "ARDS is given twice; give one severity");
  Result<std::shared_ptr<const DependentCollapse>> pattern = DependentCollapse::build(a, severity);
  if (!pattern) return bad(spec, pattern.error());
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    BakedLung& lung = a.lungs[l];
    keep_healthy_volumes(lung);
    lung.collapse = *pattern;
    lung.collapse_index = l;
  }
  return {};
}

}  // namespace

Result<Pathology> parse_pathology(std::string_view spec) {
  const std::vector<std::string_view> parts = split(spec, ':');
  Pathology p;
  p.spec = std::string(spec);
  const std::optional<PathologyKind> kind = kPathologyKindNames.parse(parts[0]);
  if (!kind) return bad(spec, kExpected);
  p.kind = *kind;
  if (p.kind == PathologyKind::Emphysema || p.kind == PathologyKind::Ards) return parse_severity(spec, parts, p);
  const bool tension = p.kind == PathologyKind::Pneumothorax && parts.size() == 4;
  if (tension && parts[3] != "tension") return bad(spec, "expected pneumothorax:SIDE:PERCENT or pneumothorax:SIDE:PERCENT:tension");
  if (parts.size() != 3 && !tension) return bad(spec, kExpected);
  p.tension = tension;
  if (parts[1] != "left" && parts[1] != "right") return bad(spec, "SIDE: expected left or right");
  p.side = std::string(parts[1]);
  if (p.kind == PathologyKind::Pneumothorax) {
    const std::string number(parts[2]);
    char* end = nullptr;
    p.percent = std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(p.percent) ||
        p.percent < kMinPneumothoraxPercent || p.percent > kMaxPneumothoraxPercent)
      return bad(spec, "PERCENT: expected a number from 1 to 90 (the share of the lung's volume lost)");
    return p;
  }
  const std::optional<LungThird> third = kLungThirdNames.parse(parts[2]);
  if (!third) return bad(spec, "REGION: expected " + kLungThirdNames.expected());
  p.region = *third;
  return p;
}

bool same_pathology(const Pathology& a, const Pathology& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case PathologyKind::Pneumothorax:
      return a.side == b.side;
    case PathologyKind::Consolidation:
      return a.side == b.side && a.region == b.region;
    case PathologyKind::Emphysema:
      return a.side.empty() || b.side.empty() || a.side == b.side;
    case PathologyKind::Ards:
      return true;
  }
  return false;
}

Status check_pathologies(const std::vector<std::string>& specs) {
  std::vector<Pathology> seen;
  for (const std::string& spec : specs) {
    Result<Pathology> p = parse_pathology(spec);
    if (!p) return p.with_context("");
    for (const Pathology& before : seen) {
      if (!same_pathology(before, *p)) continue;
      const char* expected = "";
      switch (p->kind) {
        case PathologyKind::Pneumothorax:
          expected = "one pneumothorax a lung (give its size once; a second one would collapse the lung again)";
          break;
        case PathologyKind::Consolidation:
          expected = "each third of a lung consolidated once";
          break;
        case PathologyKind::Emphysema:
          expected = "one emphysema a lung (emphysema:SEVERITY without SIDE is both lungs')";
          break;
        case PathologyKind::Ards:
          expected = "one ARDS (it is given twice: give its severity once)";
          break;
      }
      return bad(spec, "repeats '" + before.spec + "': expected " + expected);
    }
    seen.push_back(p.take());
  }
  return {};
}

Status apply_pathology(BakedAsset& asset, const Pathology& p) {
  if (p.kind == PathologyKind::Ards) return collapse_dependent(asset, p.severity, p.spec);
  if (p.kind == PathologyKind::Emphysema) {
    const std::size_t only = p.side.empty() ? asset.lungs.size() : find_lung(asset, p.side);
    if (!p.side.empty() && only == asset.lungs.size())
      return bad(p.spec, "the asset has no lung named '" + p.side + "'");
    for (std::size_t l = 0; l < asset.lungs.size(); ++l)
      if (p.side.empty() || l == only) scale_about_hilum(asset, l, 1.0 + kEmphysemaFrcGain * p.severity);
    return {};
  }
  const std::size_t l = find_lung(asset, p.side);
  if (l == asset.lungs.size()) return bad(p.spec, "the asset has no lung named '" + p.side + "'");
  if (p.kind == PathologyKind::Pneumothorax) {
    collapse(asset, l, p.percent);
    if (p.tension) push_mediastinum(asset, l);
    return {};
  }
  return consolidate(asset, l, p.region, p.spec);
}

bool has_emphysema(const std::vector<std::string>& specs) {
  for (const std::string& spec : specs) {
    Result<Pathology> p = parse_pathology(spec);
    if (p && p->kind == PathologyKind::Emphysema) return true;
  }
  return false;
}

Status apply_pathologies(BakedAsset& asset, const std::vector<std::string>& specs) {
  if (specs.empty()) return {};
  BakedAsset changed = asset;
  if (Status distinct = check_pathologies(specs); !distinct) return distinct;
  std::vector<Pathology> parsed;
  for (const std::string& spec : specs) {
    Result<Pathology> p = parse_pathology(spec);
    if (!p) return p.with_context("");
    parsed.push_back(p.take());
  }
  // ARDS's pattern is fitted to the response and geometry the others leave, so it goes last.
  std::stable_partition(parsed.begin(), parsed.end(), [](const Pathology& p) { return p.kind != PathologyKind::Ards; });
  for (const Pathology& p : parsed)
    if (Status s = apply_pathology(changed, p); !s) return s;
  asset = std::move(changed);
  return {};
}

}  // namespace lungar::sim
