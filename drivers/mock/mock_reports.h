/// @file mock_reports.h
/// @brief The raw reports of a mock trajectory, tick by tick: shared by the mock source and `lungar-trk synth`.
/// @ingroup drivers
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <span>
#include <string>

#include "drivers/decode/encoder.h"
#include "drivers/mock/mock_settings.h"
#include "drivers/mock/mock_trajectory.h"
#include "drivers/trk/trk_format.h"

namespace lungar::drivers {

class MockReports {
 public:
  /// Precondition: settings.trajectory is a known trajectory.
  MockReports(const MockConfig& settings, const ReportLayout& layout)
      : trajectory_(settings.trajectory),
        rate_hz_(settings.rate_hz),
        noise_mm_(settings.noise_mm),
        dropout_(settings.dropout),
        layout_(layout),
        noise_(0.0, noise_mm_ > 0 ? noise_mm_ : 1.0) {}

  double rate_hz() const { return rate_hz_; }
  const std::string& trajectory() const { return trajectory_; }

  /// Calls emit(bytes) for each report of tick `k` (time k / rate): one per sensor with a station byte, one for
  /// all without; a dropped report is not emitted. Allocates nothing.
  template <typename Emit>
  void tick(std::int64_t k, Emit&& emit) {
    const double t_s = static_cast<double>(k) / rate_hz_;
    const auto ticks = static_cast<std::uint32_t>(static_cast<std::uint64_t>(t_s * 1e9 / layout_.time_tick_ns));
    int n = 0;
    for (int s = 0; s < layout_.sensor_count; ++s) {
      PoseSample p = *mock_pose(trajectory_, layout_.sensors[s].role, t_s);
      if (noise_mm_ > 0) {
        for (double& v : p.position_mm) v += noise_(rng_);
      }
      poses_[n++] = p;
    }
    const std::span<const std::uint8_t> out(buf_.data(), static_cast<std::size_t>(layout_.length));
    if (layout_.station_offset >= 0) {
      for (int s = 0; s < n; ++s) {
        if (dropped()) continue;
        encode_report(layout_, std::span<const PoseSample>(&poses_[s], 1), ticks, buf_);
        emit(out);
      }
    } else if (!dropped()) {
      encode_report(layout_, std::span<const PoseSample>(poses_.data(), n), ticks, buf_);
      emit(out);
    }
  }

 private:
  bool dropped() { return dropout_ > 0 && uniform_(rng_) < dropout_; }

  std::string trajectory_;
  double rate_hz_, noise_mm_, dropout_;
  ReportLayout layout_;
  std::mt19937 rng_{12345};  // fixed seed: runs are reproducible
  std::normal_distribution<double> noise_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::array<PoseSample, kRoleCount> poses_{};
  std::array<std::uint8_t, kTrkMaxReport> buf_{};
};

}  // namespace lungar::drivers
