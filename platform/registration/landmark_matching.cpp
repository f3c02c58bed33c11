/// @file landmark_matching.cpp
/// @brief Dwells, their merging, and their matching to the model's landmarks (landmark_matching.h).
#include "platform/registration/landmark_matching.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

namespace lungar::platform {
namespace {

constexpr std::size_t kMaxDwells = 40;  // a session with more pauses than this needs cutting first

/// Repeated touches (dwells within merge_mm of an earlier one) folded into it, weighted by time held.
std::vector<Dwell> merge_repeats(const std::vector<Dwell>& dwells, double merge_mm, int& merged) {
  std::vector<Dwell> kept;
  for (const Dwell& d : dwells) {
    auto same = std::find_if(kept.begin(), kept.end(),
                             [&](const Dwell& k) { return (k.position_mm - d.position_mm).norm() < merge_mm; });
    if (same == kept.end()) {
      kept.push_back(d);
      continue;
    }
    const double w = same->duration_s + d.duration_s;
    if (w > 0) same->position_mm = (same->duration_s * same->position_mm + d.duration_s * d.position_mm) / w;
    same->duration_s = w;
    ++merged;
  }
  return kept;
}

struct Candidate {
  Eigen::Isometry3d model_to_tracked = Eigen::Isometry3d::Identity();
  int matched = 0;
  double residual = 1e300;
};

/// Each landmark's nearest dwell under `t` (-1: none within match_mm, or a closer landmark took it).
std::vector<int> assign(const std::vector<Eigen::Vector3d>& model, const std::vector<Dwell>& dwells,
                        const Eigen::Isometry3d& t, double match_mm, double* residual) {
  std::vector<int> dwell_of(model.size(), -1);
  std::vector<double> best(dwells.size(), 1e300);
  std::vector<int> owner(dwells.size(), -1);
  for (std::size_t m = 0; m < model.size(); ++m) {
    const Eigen::Vector3d p = t * model[m];
    int nearest = -1;
    double d_min = match_mm;
    for (std::size_t d = 0; d < dwells.size(); ++d) {
      const double d_mm = (dwells[d].position_mm - p).norm();
      if (d_mm <= d_min) {
        d_min = d_mm;
        nearest = static_cast<int>(d);
      }
    }
    if (nearest < 0 || d_min >= best[static_cast<std::size_t>(nearest)]) continue;
    const std::size_t slot = static_cast<std::size_t>(nearest);
    if (owner[slot] >= 0) dwell_of[static_cast<std::size_t>(owner[slot])] = -1;
    owner[static_cast<std::size_t>(nearest)] = static_cast<int>(m);
    best[static_cast<std::size_t>(nearest)] = d_min;
    dwell_of[m] = nearest;
  }
  *residual = 0;
  for (std::size_t m = 0; m < model.size(); ++m)
    if (dwell_of[m] >= 0) *residual += best[static_cast<std::size_t>(dwell_of[m])];
  return dwell_of;
}

/// The rigid transform that puts the most landmarks on dwells: every triple of landmarks against every ordered
/// triple of dwells whose three distances agree within 2 match_mm.
Candidate search_by_shape(const std::vector<Eigen::Vector3d>& model, const std::vector<Dwell>& dwells, double tol) {
  Candidate best;
  const std::size_t nm = model.size(), nd = dwells.size();
  const auto dist = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm(); };
  for (std::size_t i = 0; i < nm; ++i)
    for (std::size_t j = i + 1; j < nm; ++j)
      for (std::size_t k = j + 1; k < nm; ++k) {
        const double area = (model[j] - model[i]).cross(model[k] - model[i]).norm();
        if (area < 4 * tol * tol) continue;  // a thin triangle fixes no rotation
        for (std::size_t a = 0; a < nd; ++a)
          for (std::size_t b = 0; b < nd; ++b) {
            if (b == a || std::abs(dist(model[i], model[j]) - dist(dwells[a].position_mm, dwells[b].position_mm)) > 2 * tol)
              continue;
            for (std::size_t c = 0; c < nd; ++c) {
              if (c == a || c == b) continue;
              if (std::abs(dist(model[i], model[k]) - dist(dwells[a].position_mm, dwells[c].position_mm)) > 2 * tol ||
                  std::abs(dist(model[j], model[k]) - dist(dwells[b].position_mm, dwells[c].position_mm)) > 2 * tol)
                continue;
              Eigen::Matrix3d src, dst;
              src << model[i], model[j], model[k];
              dst << dwells[a].position_mm, dwells[b].position_mm, dwells[c].position_mm;
              Candidate cand;
              cand.model_to_tracked = Eigen::Isometry3d(Eigen::umeyama(src, dst, false));
              double residual = 0;
              const std::vector<int> got = assign(model, dwells, cand.model_to_tracked, tol, &residual);
              cand.matched = static_cast<int>(std::count_if(got.begin(), got.end(), [](int d) { return d >= 0; }));
              cand.residual = residual;
              if (cand.matched > best.matched || (cand.matched == best.matched && cand.residual < best.residual))
                best = cand;
            }
          }
      }
  return best;
}

}  // namespace

std::vector<Dwell> find_dwells(const std::vector<StylusSample>& samples, double radius_mm, double dwell_s) {
  std::vector<Dwell> out;
  std::size_t start = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const auto close_run = [&](std::size_t end) {  // samples [start, end) form a run
    if (end > start && samples[end - 1].t_s - samples[start].t_s >= dwell_s)
      out.push_back({sum / static_cast<double>(end - start), samples[start].t_s, samples[end - 1].t_s - samples[start].t_s});
  };
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (k > start && (samples[k].position_mm - sum / static_cast<double>(k - start)).norm() > radius_mm) {
      close_run(k);
      start = k;
      sum.setZero();
    }
    sum += samples[k].position_mm;
  }
  close_run(samples.size());
  return out;
}

Result<LandmarkMatch> match_landmarks(const std::vector<Eigen::Vector3d>& model, std::vector<Dwell> dwells,
                                      const LandmarkRules& rules) {
  LandmarkMatch out;
  std::sort(dwells.begin(), dwells.end(), [](const Dwell& a, const Dwell& b) { return a.start_s < b.start_s; });
  const std::vector<Dwell> kept = merge_repeats(dwells, rules.merge_mm, out.merged);
  if (model.size() < 3) return fail("landmarks: expected at least 3 model landmarks, got " + std::to_string(model.size()));
  if (kept.size() < model.size()) {
    return fail("landmarks: expected a dwell of the stylus on each of the " + std::to_string(model.size()) +
                " landmarks, got " + std::to_string(kept.size()) + " distinct dwells: was a landmark missed?");
  }
  if (kept.size() > kMaxDwells) {
    return fail("landmarks: expected at most " + std::to_string(kMaxDwells) + " distinct dwells, got " +
                std::to_string(kept.size()) + ": cut the log to the landmark touches first (lungar-trk cut)");
  }
  std::vector<int> dwell_of(model.size());
  // In touching order when it fits: as many dwells as landmarks, each within match_mm after the fit.
  bool ordered = false;
  if (kept.size() == model.size()) {
    std::vector<Eigen::Vector3d> tracked;
    for (const Dwell& d : kept) tracked.push_back(d.position_mm);
    if (auto r = register_fiducials(model, tracked); r && r->fre_max_mm <= rules.match_mm) {
      for (std::size_t m = 0; m < model.size(); ++m) dwell_of[m] = static_cast<int>(m);
      ordered = true;
    }
  }
  if (!ordered) {
    const Candidate best = search_by_shape(model, kept, rules.match_mm);
    double residual = 0;
    dwell_of = assign(model, kept, best.model_to_tracked, rules.match_mm, &residual);
    for (std::size_t m = 0; m < model.size(); ++m) {
      if (dwell_of[m] >= 0) continue;
      char line[240];
      std::snprintf(line, sizeof line,
                    "landmarks: landmark %zu (%.1f, %.1f, %.1f) has no dwell within %.1f mm of where the others put "
                    "it: was it missed, or touched off its mark?",
                    m + 1, model[m].x(), model[m].y(), model[m].z(), rules.match_mm);
      return fail(line);
    }
  }
  for (int d : dwell_of) out.tracked.push_back(kept[static_cast<std::size_t>(d)].position_mm);
  auto fitted = register_fiducials(model, out.tracked);
  if (!fitted) return fitted.with_context("");
  out.registration = *fitted;
  for (std::size_t m = 0; m < model.size(); ++m)
    out.fre_mm.push_back((fitted->apply(model[m]) - out.tracked[m]).norm());
  out.in_order = std::is_sorted(dwell_of.begin(), dwell_of.end());
  out.dropped = static_cast<int>(kept.size() - model.size());
  if (out.merged > 0)
    out.warnings.push_back(std::to_string(out.merged) + " repeated touches merged into the landmark touched before");
  if (out.dropped > 0)
    out.warnings.push_back(std::to_string(out.dropped) + " dwells fit no landmark and were dropped (rests, pauses)");
  if (!out.in_order) {
    std::string order;
    for (int d : dwell_of) order += (order.empty() ? "" : ", ") + std::to_string(d + 1);
    out.warnings.push_back("matched by shape, not in the touching order: landmark k was touched in dwell " + order +
                           " (check the landmark file's order)");
  }
  return out;
}

}  // namespace lungar::platform
