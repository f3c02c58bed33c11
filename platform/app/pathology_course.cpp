/// @file pathology_course.cpp
/// @brief The course's states, built once at load, and the blend in the frame.
#include "platform/app/pathology_course.h"

#include <algorithm>
#include <cstdio>

#include "sim/pathology/pathology.h"

namespace lungar::platform {

namespace {

/// Eased in and out, so that a lung starts and stops moving gently (smoothstep).
double ease(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace

Result<std::shared_ptr<PathologyCourse>> PathologyCourse::create(
    const sim::BakedAsset& healthy, const sim::BakedAsset& drawn, const std::vector<std::string>& start,
    const config::Scenario& scenario, const std::function<void(const std::string&)>& log) {
  auto course = std::make_shared<PathologyCourse>();
  std::vector<std::string> present = start;
  for (const sim::BakedLung& lung : drawn.lungs)
    course->start_.push_back({Eigen::Affine3d::Identity(), sim::LungFigures::of(lung)});
  for (const config::ScenarioEvent& e : scenario.events) {
    if (e.kind != config::ScenarioEventKind::Pathology) continue;
    const std::string where = scenario.where(e, e.pathology_add.empty() ? "remove" : "add") + ": ";
    if (!e.pathology_add.empty()) {
      Result<sim::Pathology> p = sim::parse_pathology(e.pathology_add);
      if (!p) return p.with_context(where);
      present.push_back(e.pathology_add);
    } else {
      const auto it = std::find(present.begin(), present.end(), e.pathology_remove);
      if (it == present.end())
        return fail(where + "'" + e.pathology_remove + "' is not present then (the scenario's pathology list and the "
                    "events before add what can be removed)");
      present.erase(it);
    }
    sim::BakedAsset state = healthy;
    if (Status s = sim::apply_pathologies(state, present); !s) return s.with_context(where);
    Result<std::vector<sim::LungShape>> shapes = sim::lung_shapes(drawn, state);
    if (!shapes) {
      return fail(where + shapes.error() +
                  ": only a pneumothorax (tension too) or an emphysema can come or go during a scenario; give a "
                  "consolidation or ARDS in its pathology list");
    }
    course->steps_.push_back({e.at_s, e.over_s, shapes.take()});
    if (log) {
      char when[96];
      std::snprintf(when, sizeof when, ": at %.1f s %s over %.1f s", e.at_s,
                    e.pathology_add.empty() ? "goes" : "comes", e.over_s);
      log("scenario " + (scenario.name.empty() ? scenario.source : scenario.name) + ": " +
          (e.pathology_add.empty() ? e.pathology_remove : e.pathology_add) + when);
    }
  }
  if (course->steps_.empty()) return std::shared_ptr<PathologyCourse>{};
  course->now_ = course->start_;
  return course;
}

const std::vector<sim::LungShape>& PathologyCourse::at(std::int64_t now_ns) {
  return at_seconds(static_cast<double>(now_ns - t0_ns_) * 1e-9);
}

const std::vector<sim::LungShape>& PathologyCourse::at_seconds(double t_s) {
  const std::vector<sim::LungShape>* done = &start_;
  for (const Step& step : steps_) {
    if (t_s >= step.at_s + step.over_s) {
      done = &step.to;
      continue;
    }
    if (t_s > step.at_s) {  // under way: from where the steps before left the lungs
      now_ = sim::blend(*done, step.to, ease((t_s - step.at_s) / step.over_s));
      return now_;
    }
    break;
  }
  now_ = *done;
  return now_;
}

}  // namespace lungar::platform
