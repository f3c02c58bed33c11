/// @file tracker_core.cpp
/// @brief Validation, publication, counters, staleness and rate-limited logging for every source.
#include "drivers/tracker/tracker_core.h"

#include <cstdarg>
#include <cstdio>

#include "config/base/log_line.h"

namespace lungar::drivers {

namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

/// Without a log of the caller's, the one log-line format (config/base), as the runtime prints the tracker's lines.
void default_log(const std::string& line) { log_line("lungar", "drivers: " + line); }

}  // namespace

TrackerCore::TrackerCore(const ReportLayout& layout, double stale_ms, TrackerOptions options)
    : layout_(layout), stale_ns_(static_cast<std::int64_t>(stale_ms * 1e6)), options_(std::move(options)) {
  if (!options_.log) options_.log = default_log;
}

Status TrackerCore::start_recording(const std::string& path, const std::string& description, TrkSource source) {
  TrkHeader h;
  h.description = description;
  h.layout_toml = options_.record_layout_toml;
  if (Status opened = recorder_.open(path, h, TrkWriter::Mode::AppendLog); !opened) return opened;
  record_source = source;
  recording_ = true;
  return ok();
}

void TrackerCore::log(int key, const char* fmt, ...) {
  const std::int64_t now = monotonic_ns();
  if (key >= 0 && key < static_cast<int>(log_last_ns_.size())) {
    // At most one line per key and second: a flood of malformed reports must not become a flood of lines.
    if (log_last_ns_[key] != 0 && now - log_last_ns_[key] < kSecond) {
      ++log_suppressed_[key];
      return;
    }
    log_last_ns_[key] = now;
  }
  char buf[512];
  int n = std::snprintf(buf, sizeof buf, "drivers: ");
  va_list args;
  va_start(args, fmt);
  n += std::vsnprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), fmt, args);
  va_end(args);
  if (key >= 0 && key < static_cast<int>(log_suppressed_.size()) && log_suppressed_[key] > 0 &&
      n < static_cast<int>(sizeof buf)) {
    std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), " (%llu more like it not shown)",
                  static_cast<unsigned long long>(log_suppressed_[key]));
    log_suppressed_[key] = 0;
  }
  options_.log(buf);
}

DecodeError TrackerCore::feed(std::span<const std::uint8_t> report, std::int64_t t_arrival_ns) {
  record(record_source, report, t_arrival_ns);
  return accept(decode_report(report, layout_), report.size(), t_arrival_ns);
}

DecodeError TrackerCore::feed_decoded(TrkSource source, std::span<const std::uint8_t> bytes,
                                      const DecodedReport& decoded, std::int64_t t_arrival_ns) {
  record(source, bytes, t_arrival_ns);  // the record's source says how to decode it again
  return accept(decoded, bytes.size(), t_arrival_ns);
}

void TrackerCore::record(TrkSource source, std::span<const std::uint8_t> bytes, std::int64_t t_arrival_ns) {
  reports_.fetch_add(1, std::memory_order_relaxed);
  if (!recording_) return;
  if (Status appended = recorder_.append(source, t_arrival_ns, bytes)) {
    recorded_.fetch_add(1, std::memory_order_relaxed);
  } else {
    log(-1, "recording stopped: %s", appended.error().c_str());
    recording_ = false;
  }
}

DecodeError TrackerCore::accept(const DecodedReport& d, std::size_t bytes, std::int64_t t_arrival_ns) {
  DecodeError error = d.error;
  std::int64_t t_device = t_arrival_ns;
  if (error == DecodeError::None && d.has_time) {
    const std::int64_t t = clock_.advance(d.device_ticks, d.time_bits, d.time_tick_ns);
    if (t < 0) {
      error = DecodeError::TimeBackwards;
    } else {
      if (rebase_) {  // first report after a reconnect: continue from where the old clock stopped
        device_base_ns_ = (last_device_ns_ < 0 ? 0 : last_device_ns_) - t + (t_arrival_ns - last_arrival_ns_);
        rebase_ = false;
      }
      t_device = device_base_ns_ + t;
    }
  }
  if (error != DecodeError::None) {
    malformed_[static_cast<std::size_t>(error)].fetch_add(1, std::memory_order_relaxed);
    log(static_cast<int>(error), "malformed report dropped (%zu bytes): %s", bytes, to_string(error));
    return error;
  }
  if (d.ignored > 0 && ignored_.fetch_add(static_cast<std::uint64_t>(d.ignored), std::memory_order_relaxed) == 0) {
    // Once: a server that also streams other tools (a probe, a needle) is normal, not worth a line a second.
    log(-1, "device '%s' feeds no role (no role of [trackers] names it); data of devices no role names is ignored",
        d.ignored_name.data());
  }
  if (d.count == 0) {  // nothing for any role (only ignored devices): no pose, no change of state
    tick(t_arrival_ns);
    return DecodeError::None;
  }
  last_device_ns_ = t_device;
  last_arrival_ns_ = t_arrival_ns;
  for (int k = 0; k < d.count; ++k) {
    PoseSample s = d.poses[k];
    s.flags = kPoseValid | (d.has_time ? 0u : static_cast<std::uint32_t>(kPoseNoDeviceTime));
    s.t_device_ns = t_device;
    s.t_arrival_ns = t_arrival_ns;
    const auto r = static_cast<std::size_t>(s.role);
    ++role_window_count_[r];
    latest_[r].publish(s);
    history_[r].push(s);
    history_mail_[r].publish(history_[r]);
    if (options_.on_sample) options_.on_sample(s);
  }
  accepted_.fetch_add(1, std::memory_order_relaxed);
  last_accepted_ns_.store(t_arrival_ns, std::memory_order_release);
  if (state() != TrackerState::Streaming) set_state(TrackerState::Streaming);
  ++rate_window_count_;
  tick(t_arrival_ns);
  return DecodeError::None;
}

void TrackerCore::tick(std::int64_t now_ns) {
  if (rate_window_start_ns_ == 0) rate_window_start_ns_ = now_ns;
  const std::int64_t span = now_ns - rate_window_start_ns_;
  if (span >= kSecond) {
    rate_hz_.store(static_cast<double>(rate_window_count_) * 1e9 / static_cast<double>(span),
                   std::memory_order_relaxed);
    for (std::size_t r = 0; r < kRoleCount; ++r) {
      role_rate_hz_[r].store(static_cast<double>(role_window_count_[r]) * 1e9 / static_cast<double>(span),
                             std::memory_order_relaxed);
      role_window_count_[r] = 0;
    }
    rate_window_start_ns_ = now_ns;
    rate_window_count_ = 0;
  }
  if (state() == TrackerState::Streaming && now_ns - last_accepted_ns_.load(std::memory_order_acquire) > stale_ns_) {
    set_state(TrackerState::Stale);
  }
}

void TrackerCore::set_state(TrackerState s) {
  const TrackerState old = state_.exchange(s, std::memory_order_acq_rel);
  if (old != s) log(-1, "tracker %s -> %s", to_string(old), to_string(s));
}

void TrackerCore::count_reconnect() {
  reconnects_.fetch_add(1, std::memory_order_relaxed);
  restart_device_clock();
}

void TrackerCore::restart_device_clock() {
  clock_.reset();
  rebase_ = true;
}

PoseSample TrackerCore::latest(Role role, std::int64_t now_ns) const {
  PoseSample s = latest_[static_cast<std::size_t>(role)].read();
  if (s.valid() && now_ns - s.t_arrival_ns > stale_ns_) s.flags |= kPoseStale;
  return s;
}

TrackerStats TrackerCore::stats() const {
  TrackerStats t;
  t.reports = reports_.load(std::memory_order_relaxed);
  t.accepted = accepted_.load(std::memory_order_relaxed);
  for (int k = 0; k < kDecodeErrorCount; ++k) {
    t.malformed_by_reason[k] = malformed_[k].load(std::memory_order_relaxed);
    t.malformed += t.malformed_by_reason[k];
  }
  t.opens = opens_.load(std::memory_order_relaxed);
  t.reconnects = reconnects_.load(std::memory_order_relaxed);
  t.recorded = recorded_.load(std::memory_order_relaxed);
  t.ignored = ignored_.load(std::memory_order_relaxed);
  t.rate_hz = rate_hz_.load(std::memory_order_relaxed);
  for (std::size_t r = 0; r < kRoleCount; ++r) t.role_rate_hz[r] = role_rate_hz_[r].load(std::memory_order_relaxed);
  t.state = state();
  return t;
}

}  // namespace lungar::drivers
