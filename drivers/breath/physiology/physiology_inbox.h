/// @file physiology_inbox.h
/// @brief Where a DDS reader's thread leaves the physiology samples it checked, for the frame thread to take:
///        a fixed ring (no lock, no allocation on either side) and the drops counted by reason. The first drop of
///        each reason is logged once, so that a misconfigured publisher (a wrong unit) is seen at once without
///        a line per sample.
/// @ingroup platform
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>

#include "config/base/log_line.h"
#include "config/base/spsc_ring.h"
#include "drivers/breath/physiology/physiology_sample.h"

namespace lungar::breath::physiology {

class PhysiologyInbox {
 public:
  struct Item {
    Sample sample;
    std::int64_t arrival_ns = 0;  ///< monotonic: when the reader took it
  };

  /// `source` names the source in the log ("amm", "openice").
  explicit PhysiologyInbox(std::string source) : source_(std::move(source)) {}

  /// The reader's thread.
  void push(const Sample& s, std::int64_t arrival_ns) { ring_.push({s, arrival_ns}); }
  void drop(Drop why) {
    if (drops_[static_cast<std::size_t>(why)].fetch_add(1, std::memory_order_relaxed) == 0) {
      ::lungar::log_line("lungar", "breath: " + source_ + ": dropped a sample (" + kDropNames.name(why) +
                                       "); each such is counted in the stats JSON's breath_dropped");
    }
  }
  /// The frame thread: `on(item)` for each sample pushed since the last call, oldest first.
  template <class F>
  void drain(F&& on) {
    ring_.drain(on);
  }
  /// Any thread.
  std::uint64_t dropped(Drop why) const {
    return drops_[static_cast<std::size_t>(why)].load(std::memory_order_relaxed);
  }
  /// Samples lost because the frame thread did not take them in time (a full ring), not because they were bad.
  std::uint64_t overflowed() const { return ring_.dropped(); }

 private:
  std::string source_;
  SpscRing<Item, 4096> ring_;
  std::array<std::atomic<std::uint64_t>, kDropReasons> drops_{};
};

}  // namespace lungar::breath::physiology
