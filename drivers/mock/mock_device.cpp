/// @file mock_device.cpp
/// @brief The mock's thread: at each tick, MockReports -> bytes -> TrackerCore::feed(), on absolute deadlines.
#include <chrono>
#include <thread>

#include "drivers/mock/mock_interface.h"
#include "drivers/mock/mock_reports.h"
#include "drivers/tracker/tracker_core.h"

namespace lungar::drivers {

namespace {

class MockDevice final : public TrackerDevice {
 public:
  MockDevice(const MockConfig& s, const ReportLayout& l) : reports_(s, l) {}

  void run(TrackerCore& core, std::stop_token stop) override {
    using clock = std::chrono::steady_clock;
    const auto period = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 / reports_.rate_hz()));
    core.set_state(TrackerState::Opening);
    core.set_state(TrackerState::Streaming);
    auto next = clock::now();
    for (std::int64_t k = 0; !stop.stop_requested(); ++k) {
      reports_.tick(k, [&](std::span<const std::uint8_t> bytes) { core.feed(bytes, monotonic_ns()); });
      next += period;
      std::this_thread::sleep_until(next);
      core.tick(monotonic_ns());
    }
  }

  std::string describe() const override { return "mock " + reports_.trajectory(); }
  std::string trk_description() const override {
    return "source=mock\ntrajectory=" + reports_.trajectory() + "\nrate_hz=" + std::to_string(reports_.rate_hz()) +
           "\n";
  }
  TrkSource trk_source() const override { return TrkSource::Mock; }

 private:
  MockReports reports_;
};

}  // namespace

std::unique_ptr<TrackerDevice> mock_create(const MockConfig& settings, const ReportLayout& layout) {
  return std::make_unique<MockDevice>(settings, layout);
}

}  // namespace lungar::drivers
