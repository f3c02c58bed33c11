/// @file replay_device.cpp
/// @brief The replay thread: records in order, sleeping to the recorded spacing when real-time.
#include <chrono>
#include <thread>

#include "drivers/replay/replay_interface.h"
#include "drivers/tracker/tracker_core.h"

namespace lungar::drivers {

namespace {

class ReplayDevice final : public TrackerDevice {
 public:
  ReplayDevice(TrkLog log, std::string path, bool realtime, bool loop, std::vector<RecordDecoder> decoders)
      : log_(std::move(log)),
        path_(std::move(path)),
        realtime_(realtime),
        loop_(loop),
        decoders_(std::move(decoders)) {}

  void run(TrackerCore& core, std::stop_token stop) override {
    using clock = std::chrono::steady_clock;
    core.set_state(TrackerState::Opening);
    if (log_.records.empty()) {
      core.log(-1, "replay %s: the log holds no records", path_.c_str());
      core.set_finished();
    }
    core.set_state(TrackerState::Streaming);
    bool first_pass = true;
    while (!stop.stop_requested() && !log_.records.empty() && (first_pass || loop_)) {
      if (!first_pass) core.restart_device_clock();  // the log starts over: its device time too
      first_pass = false;
      const auto start = clock::now();
      const std::int64_t t0 = log_.records.front().t_arrival_ns;
      for (const TrkRecord& r : log_.records) {
        if (stop.stop_requested()) break;
        if (realtime_) {
          // Sleep in short steps so that stop and staleness are noticed during long gaps in the log.
          const auto due = start + std::chrono::nanoseconds(r.t_arrival_ns - t0);
          while (!stop.stop_requested() && clock::now() < due) {
            std::this_thread::sleep_until(std::min(due, clock::now() + std::chrono::milliseconds(10)));
            core.tick(monotonic_ns());
          }
        }
        feed(core, r);
      }
    }
    core.set_finished();
    while (!stop.stop_requested()) {  // nothing more will come: let the pose go stale
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      core.tick(monotonic_ns());
    }
  }

  std::string describe() const override {
    return "replay " + path_ + " (" + std::to_string(log_.records.size()) + " reports" +
           (realtime_ ? ", real time" : ", as fast as possible") + ")";
  }
  std::string trk_description() const override { return "source=replay\nfile=" + path_ + "\n" + log_.header.description; }
  TrkSource trk_source() const override { return TrkSource::Replay; }

 private:
  /// A record of a device with its own protocol (an OpenIGTLink message): the same decoder as live.
  void feed(TrackerCore& core, const TrkRecord& r) const {
    for (const RecordDecoder& d : decoders_) {
      if (d.source == r.source) {
        core.feed_decoded(r.source, r.report, d.decode(r.report), monotonic_ns());
        return;
      }
    }
    core.feed(r.report, monotonic_ns());
  }

  TrkLog log_;
  std::string path_;
  bool realtime_, loop_;
  std::vector<RecordDecoder> decoders_;
};

}  // namespace

std::unique_ptr<TrackerDevice> replay_create(TrkLog log, const std::string& path, bool realtime, bool loop,
                                             std::vector<RecordDecoder> decoders) {
  return std::make_unique<ReplayDevice>(std::move(log), path, realtime, loop, std::move(decoders));
}

}  // namespace lungar::drivers
