/// @file classroom_course.cpp
/// @brief The instructor's course built off the frame, and the frame's choice between it and this station's own.
#include "platform/sync/classroom_course.h"

#include <nlohmann/json.hpp>

namespace lungar::platform {

ClassroomCourse::ClassroomCourse(std::shared_ptr<LungCourse> own, std::shared_ptr<const TimelineFeed> feed,
                                 LoadedLungs lungs, std::function<void(const std::string&)> log)
    : own_(std::move(own)), feed_(std::move(feed)), lungs_(std::move(lungs)), log_(std::move(log)) {
  // A station that loaded no pathologies may leave the drawn patient out: it is then the drawn asset's healthy one.
  if (lungs_.drawn_patient.lungs.size() != lungs_.drawn->lungs.size())
    lungs_.drawn_patient = sim::PatientState::of(*lungs_.drawn);
  for (const sim::LungState& lung : lungs_.drawn_patient.lungs)
    as_loaded_.push_back({Eigen::Affine3d::Identity(), lung});
}

ClassroomCourse::~ClassroomCourse() {
  if (builder_.joinable()) builder_.join();
}

void ClassroomCourse::take_new_timeline() {
  if (building_.load(std::memory_order_acquire)) return;
  sim::PathologyTimeline timeline;
  if (!feed_->lungs_since(seen_version_, timeline)) return;
  if (followed_ && followed_->timeline() == timeline) return;  // a restarted instructor with the same patient
  if (builder_.joinable()) builder_.join();                   // done: building_ is false
  building_.store(true, std::memory_order_release);
  builder_ = std::thread([this, timeline = std::move(timeline)]() mutable { build(std::move(timeline)); });
}

void ClassroomCourse::build(sim::PathologyTimeline timeline) {
  auto course = PathologyCourse::create(*lungs_.healthy, *lungs_.drawn, timeline);
  if (!course) {
    if (log_) log_("classroom: this station cannot draw the instructor's lungs (" + course.error() + "); it keeps its own");
  } else {
    if (log_) log_("classroom: drawing the instructor's lungs: " + sim::describe(timeline));
    std::lock_guard lock(built_mutex_);
    built_ = course.take();
    ready_.store(true, std::memory_order_release);
  }
  building_.store(false, std::memory_order_release);
}

const std::vector<sim::LungShape>& ClassroomCourse::at(std::int64_t now_ns) {
  take_new_timeline();
  if (ready_.load(std::memory_order_acquire)) {
    std::lock_guard lock(built_mutex_);
    followed_ = std::move(built_);
    ready_.store(false, std::memory_order_relaxed);
  }
  double t_s = 0;
  if (followed_ && feed_->breath_time(now_ns, t_s)) return followed_->at_seconds(t_s);
  return own_ ? own_->at(now_ns) : as_loaded_;
}

void ClassroomCourse::add_stats(nlohmann::json& stats) const {
  if (followed_) {
    followed_->add_stats(stats);
  } else if (own_) {
    own_->add_stats(stats);
  } else {
    stats["pathologies"] = lungs_.own.start;
  }
  stats["sync_lungs"] = followed_ ? "instructor" : "own";
}

}  // namespace lungar::platform
