/// @file tracker.cpp
/// @brief The Tracker: the thread that runs a device into the pipeline, and what the frame loop reads.
#include "drivers/tracker/tracker.h"

#include <thread>

#include "drivers/tracker/tracker_core.h"
#include "drivers/tracker/tracker_device.h"

namespace lungar::drivers {

const char* to_string(TrackerState s) {
  switch (s) {
    case TrackerState::Disconnected: return "disconnected";
    case TrackerState::Opening: return "opening";
    case TrackerState::Streaming: return "streaming";
    case TrackerState::Stale: return "stale";
  }
  return "?";
}

struct Tracker::Thread {
  std::jthread thread;
};

Tracker::Tracker(std::unique_ptr<TrackerCore> core, std::unique_ptr<TrackerDevice> device)
    : core_(std::move(core)), device_(std::move(device)), thread_(std::make_unique<Thread>()) {
  thread_->thread = std::jthread([this](std::stop_token stop) { device_->run(*core_, stop); });
}

Tracker::~Tracker() { stop(); }

void Tracker::stop() {
  if (thread_ && thread_->thread.joinable()) {
    thread_->thread.request_stop();
    thread_->thread.join();
  }
}

PoseSample Tracker::latest(Role role, std::int64_t now_ns) const { return core_->latest(role, now_ns); }
PoseHistory Tracker::history(Role role) const { return core_->history(role); }
PoseSample Tracker::predicted(Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const {
  PoseSample p = predict(core_->history(role), t_ns, max_ahead_ns);
  if (p.valid() && t_ns - p.t_arrival_ns > core_->stale_ns()) p.flags |= kPoseStale;
  return p;
}
TrackerStats Tracker::stats() const { return core_->stats(); }
TrackerState Tracker::state() const { return core_->state(); }
bool Tracker::finished() const { return core_->finished(); }
std::string Tracker::describe() const { return device_->describe(); }

}  // namespace lungar::drivers
