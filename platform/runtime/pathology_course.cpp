/// @file pathology_course.cpp
/// @brief The course's states, built once at load, and the blend in the frame.
#include "platform/runtime/pathology_course.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "sim/pathology/pathology.h"

namespace lungar::platform {

namespace {

/// Eased in and out, so that a lung starts and stops moving gently (smoothstep).
double ease(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

/// Each lung of `drawn` as a map to `healthy` with `present` applied; `where` names what asked for it.
Result<std::vector<sim::LungShape>> state_of(const sim::BakedAsset& healthy, const sim::BakedAsset& drawn,
                                             const std::vector<std::string>& present, const std::string& where) {
  sim::BakedAsset state = healthy;
  sim::PatientState patient = sim::PatientState::of(healthy);
  if (Status s = sim::apply_pathologies(state, patient, present); !s) return s.with_context(where);
  Result<std::vector<sim::LungShape>> shapes = sim::lung_shapes(drawn, state, patient);
  if (!shapes) {
    return fail(where + shapes.error() +
                ": only what reshapes a lung (a collapse, a larger rest) can come or go while the lungs are drawn; a "
                "change of a lung's response (a consolidation) must be the drawn lungs' own (give it in the pathology "
                "list, or --pathology, of every station)");
  }
  return shapes;
}

/// "a, b" ("none" for no pathology), with " (coming)" after `coming` and " (going)" after `going`.
std::string label_of(std::vector<std::string> present, const std::string& coming, const std::string& going) {
  if (!coming.empty()) present.push_back(coming);
  std::string out;
  for (const std::string& spec : present) {
    out += (out.empty() ? "" : ", ") + spec;
    if (!coming.empty() && spec == coming) out += " (coming)";
    if (!going.empty() && spec == going) out += " (going)";
  }
  return out.empty() ? "none" : out;
}

}  // namespace

sim::PathologyTimeline timeline_of(const std::vector<std::string>& start, const config::Scenario* scenario) {
  sim::PathologyTimeline timeline{start, {}};
  if (scenario == nullptr) return timeline;
  for (const config::ScenarioEvent& e : scenario->events) {
    if (e.kind != config::ScenarioEventKind::Pathology) continue;
    timeline.events.push_back({e.at_s, e.over_s, e.pathology_add, e.pathology_remove});
  }
  return timeline;
}

Result<std::shared_ptr<PathologyCourse>> PathologyCourse::create(const sim::BakedAsset& healthy,
                                                                 const sim::BakedAsset& drawn,
                                                                 const sim::PathologyTimeline& timeline) {
  if (Status s = sim::check_timeline(timeline); !s) return Error{s.error()};
  auto course = std::make_shared<PathologyCourse>();
  course->timeline_ = timeline;
  auto start = state_of(healthy, drawn, timeline.start, "pathology at the start: ");
  if (!start) return start.with_context("");
  course->start_ = start.take();
  for (std::size_t k = 0; k < timeline.events.size(); ++k) {
    const sim::PathologyEvent& e = timeline.events[k];
    const std::string where = "pathology event " + std::to_string(k + 1) + " (" +
                              (e.add.empty() ? "remove " + e.remove : "add " + e.add) + "): ";
    if (auto p = sim::parse_pathology(e.add.empty() ? e.remove : e.add); p && !(*p)->model().may_change_in_a_run()) {
      return fail(where + "'" + std::string((*p)->model().name()) + "' cannot come or go during a run (its change "
                  "would switch at once); give it in the pathology list for the whole run");
    }
    auto to = state_of(healthy, drawn, sim::present_after(timeline, k + 1), where);
    if (!to) return to.with_context("");
    const std::vector<std::string> before = sim::present_after(timeline, k);
    course->steps_.push_back({e.at_s, e.over_s, to.take(), e.add.empty() ? e.remove : e.add,
                              label_of(before, e.add, e.remove),
                              label_of(sim::present_after(timeline, k + 1), "", "")});
  }
  course->now_ = course->start_;
  course->start_label_ = label_of(timeline.start, "", "");
  return course;
}

const std::vector<sim::LungShape>& PathologyCourse::at(std::int64_t now_ns) {
  return at_seconds(static_cast<double>(now_ns - t0_ns_) * 1e-9);
}

const std::vector<sim::LungShape>& PathologyCourse::at_seconds(double t_s) {
  std::size_t begun = 0;  // steps under way or done at t_s; they are in time order
  while (begun < steps_.size() && t_s > steps_[begun].at_s) ++begun;
  under_way_ = begun > 0 && t_s < steps_[begun - 1].at_s + steps_[begun - 1].over_s;
  done_ = under_way_ ? begun - 1 : begun;
  now_ = state_at(t_s, begun);
  return now_;
}

std::vector<sim::LungShape> PathologyCourse::state_at(double t_s, std::size_t begun) const {
  if (begun == 0) return start_;
  const Step& step = steps_[begun - 1];
  if (t_s >= step.at_s + step.over_s) return step.to;
  // Under way: from where the lungs were when it began, which is the step before still changing when an instructor
  // adds a change before the last one ended; so the lungs never jump, however the changes overlap.
  return sim::blend(state_at(step.at_s, begun - 1), step.to, ease((t_s - step.at_s) / step.over_s));
}

const std::string& PathologyCourse::label_now() const {
  if (under_way_) return steps_[done_].label_under_way;
  return done_ == 0 ? start_label_ : steps_[done_ - 1].label_done;
}

void PathologyCourse::add_stats(nlohmann::json& stats) const {
  std::vector<std::string> present = sim::present_after(timeline_, done_);
  std::vector<std::string> changing;
  if (under_way_) {
    changing.push_back(steps_[done_].changing);
    if (!timeline_.events[done_].add.empty()) present.push_back(steps_[done_].changing);  // it shows already
  }
  stats["pathologies"] = present;
  stats["pathologies_changing"] = changing;
}

}  // namespace lungar::platform
