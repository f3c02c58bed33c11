/// @file instructor_publisher.h
/// @brief The instructor's FrameListener: each frame's lung pose (after the registration) and breathing time (and
/// dV, when the breath is followed) go to the classroom. It hands them to the sync thread through mailboxes: no allocation, no waiting.
/// @ingroup platform
#pragma once

#include <memory>

#include "drivers/classroom/classroom_station.h"
#include "platform/runtime/frame_listener.h"

namespace lungar::platform::sync {

class InstructorPublisher final : public FrameListener {
 public:
  explicit InstructorPublisher(std::shared_ptr<classroom::ClassroomStation> station) : station_(std::move(station)) {}

  void on_frame(const FrameState& s) override {
    classroom::Instructor& i = *station_->instructor();
    const Eigen::Quaterniond& q = s.lung_in_world;
    i.publish_pose({s.lung_origin_mm.x(), s.lung_origin_mm.y(), s.lung_origin_mm.z()}, {q.w(), q.x(), q.y(), q.z()},
                   s.patient.t_arrival_ns);
    i.frame_breath(s.now_ns, s.breath);
  }

 private:
  std::shared_ptr<classroom::ClassroomStation> station_;
};

}  // namespace lungar::platform::sync
