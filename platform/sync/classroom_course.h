/// @file classroom_course.h
/// @brief A trainee's lungs: its own (its scenario's course, or as loaded) until the instructor's pathologies
///        arrive, then the instructor's course on the instructor's breathing time, so that a tension pneumothorax
///        drops and a needle decompression re-expands the lung on every station at once, and a trainee joining
///        late draws what the instructor draws.
/// @ingroup platform
///
/// The instructor's course is built off the frame, on a thread of its own (a second or so on the CT demo's 400k
/// points: each state is the healthy asset with its pathologies applied); the lungs change when it is ready. A
/// course this station cannot draw (a consolidation its lungs were not loaded with: it changes the baked response
/// on the GPU) is said once, and the station keeps its own lungs.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "drivers/classroom/classroom_station.h"
#include "platform/runtime/lung_course.h"
#include "platform/runtime/pathology_course.h"
#include "sim/asset/baked_asset.h"
#include "sim/pathology/pathology_timeline.h"
#include "sim/patient/patient_state.h"

namespace lungar::platform {

/// The lungs a station loaded: the healthy asset (every state of a course is built from it) and the drawn one
/// (the asset on the GPU, with this station's own pathologies), and what this station's own timeline is.
struct LoadedLungs {
  std::shared_ptr<const sim::BakedAsset> healthy;
  std::shared_ptr<const sim::BakedAsset> drawn;
  sim::PatientState drawn_patient;  ///< the patient as `drawn` was loaded (its pathologies at load)
  sim::PathologyTimeline own;
};

/// Where the course followed comes from: a trainee's instructor, or the instructor's own console changing the
/// class while it runs.
class TimelineFeed {
 public:
  virtual ~TimelineFeed() = default;
  /// A timeline newer than `version` (which it then updates): true.
  virtual bool lungs_since(std::uint64_t& version, sim::PathologyTimeline& out) const = 0;
  /// The breathing time the timeline's events are on, at `now_ns`; false before there is one.
  virtual bool breath_time(std::int64_t now_ns, double& t_s) const = 0;
};

/// A trainee's feed: its instructor's timeline, on the instructor's breathing time.
class TraineeFeed final : public TimelineFeed {
 public:
  explicit TraineeFeed(std::shared_ptr<classroom::ClassroomStation> station) : station_(std::move(station)) {}
  bool lungs_since(std::uint64_t& version, sim::PathologyTimeline& out) const override {
    return station_->trainee() != nullptr && station_->trainee()->lungs_since(version, out);
  }
  bool breath_time(std::int64_t now_ns, double& t_s) const override {
    return station_->trainee() != nullptr && station_->trainee()->breath_time(now_ns, t_s);
  }

 private:
  std::shared_ptr<classroom::ClassroomStation> station_;
};

class ClassroomCourse final : public LungCourse {
 public:
  /// `own`: this station's course (none: its lungs as loaded); `feed` the timeline it follows once one comes.
  ClassroomCourse(std::shared_ptr<LungCourse> own, std::shared_ptr<const TimelineFeed> feed, LoadedLungs lungs,
                  std::function<void(const std::string&)> log);
  /// A trainee's: its instructor's timeline.
  ClassroomCourse(std::shared_ptr<LungCourse> own, std::shared_ptr<classroom::ClassroomStation> station,
                  LoadedLungs lungs, std::function<void(const std::string&)> log)
      : ClassroomCourse(std::move(own), std::make_shared<TraineeFeed>(std::move(station)), std::move(lungs),
                        std::move(log)) {}
  ~ClassroomCourse() override;
  ClassroomCourse(const ClassroomCourse&) = delete;
  ClassroomCourse& operator=(const ClassroomCourse&) = delete;

  const std::vector<sim::LungShape>& at(std::int64_t now_ns) override;
  /// `pathologies` (the instructor's when followed) and `sync_lungs` ("instructor" or "own").
  void add_stats(nlohmann::json& stats) const override;
  /// The instructor's pathologies once followed, else the station's own.
  const std::string* pathologies_now() const override {
    if (followed_) return followed_->pathologies_now();
    return own_ ? own_->pathologies_now() : nullptr;
  }

 private:
  /// A new timeline from the feed: builds its course unless it is the one drawn (or the builder is busy:
  /// the next frame asks again).
  void take_new_timeline();
  void build(sim::PathologyTimeline timeline);  ///< the builder thread

  std::shared_ptr<LungCourse> own_;
  std::shared_ptr<const TimelineFeed> feed_;
  LoadedLungs lungs_;
  std::function<void(const std::string&)> log_;
  std::vector<sim::LungShape> as_loaded_;
  std::shared_ptr<PathologyCourse> followed_;  ///< frame thread: the instructor's course, once built
  std::uint64_t seen_version_ = 0;             ///< frame thread: the trainee's timeline version taken

  std::thread builder_;
  std::atomic<bool> building_{false};
  std::mutex built_mutex_;  ///< guards built_ between the builder and the frame
  std::shared_ptr<PathologyCourse> built_;
  std::atomic<bool> ready_{false};
};

}  // namespace lungar::platform
