/// @file trainee.cpp
/// @brief The trainee's endpoints and sync thread: shared breathing in, poses in, clock exchanges, state.
#include "drivers/classroom/trainee.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "config/base/clock.h"

namespace lungar::classroom {

namespace {
constexpr std::int64_t kMaxWaitNs = 20'000'000;

}  // namespace

Trainee::Trainee(std::unique_ptr<ClassroomLink> link) : link_(std::move(link)) { transitions_.reserve(256); }

Result<std::unique_ptr<Trainee>> Trainee::create(const SyncOptions& options) {
  auto link = ClassroomLink::open(options, kWireTrainee);
  if (!link) return Error{link.error()};
  std::unique_ptr<Trainee> self(new Trainee(link.take()));
  if (Status s = self->open_endpoints(); !s) return fail("sync: " + s.error());
  if (Status a = self->link_->announce(); !a) return fail("sync: " + a.error());
  self->link_->log("sync: trainee '" + self->link_->name() + "' of classroom '" + options.classroom + "' (domain " +
                   std::to_string(options.domain) + "); waiting for the instructor");
  self->transition(SyncState::Lost);
  self->thread_.start(self->link_->waitset(), [s = self.get()] { s->run(); });
  return self;
}

Trainee::~Trainee() { thread_.stop(); }

Status Trainee::open_endpoints() {
  auto w = link_->writer<lungar_sync_TimeRequest>();
  if (!w) return Error{w.error()};
  request_writer_.emplace(w.take());
  auto status = link_->writer<lungar_sync_StationStatus>();
  if (!status) return Error{status.error()};
  status_writer_.emplace(status.take());
  // Each reader wakes the sync thread on data from the moment it is made.
  return readers_.open([this](auto type) { return link_->reader<typename decltype(type)::type>(); },
                       [this](const auto& reader) { return link_->waitset().attach_reader(reader.get()); });
}

drivers::PoseSample Trainee::patient_pose() const {
  drivers::PoseSample p = pose_box_.read();
  if (p.valid() && state() == SyncState::Lost) p.flags |= drivers::kPoseStale;
  return p;
}

bool Trainee::breathing(std::int64_t now_ns, sim::BreathingSample& out) const {
  if (!breathing_.sample_at(link_->clock().from_monotonic(now_ns), out)) return false;
  followed_.apply(out);
  return true;
}

bool Trainee::breath_time(std::int64_t now_ns, double& t_s) const {
  return breathing_.time_at(link_->clock().from_monotonic(now_ns), t_s);
}

bool Trainee::lungs_since(std::uint64_t& version, sim::PathologyTimeline& out) const {
  if (lungs_version_.load(std::memory_order_acquire) == version) return false;
  std::lock_guard lock(lungs_mutex_);
  out = lungs_;
  version = lungs_version_.load(std::memory_order_acquire);
  return true;
}

void Trainee::run() {
  while (!thread_.stopping()) {
    std::int64_t now = lungar::monotonic_ns();
    const std::int64_t wait = std::clamp<std::int64_t>(next_request_mono_ - now, 0, kMaxWaitNs);
    link_->waitset().wait(heard_session_ != 0 ? wait : kMaxWaitNs);
    now = lungar::monotonic_ns();
    if (link_->poll_roster() > 0) {
      peers_.store(link_->peers());
      peers_max_.store(link_->peers_max());
    }
    take_breathing();
    take_events();
    install_if_complete();
    take_heartbeats(now);
    take_poses();
    take_replies();
    request_time(now);
    update_state(lungar::monotonic_ns());
    send_status(now);
  }
}

void Trainee::take_breathing() {
  const auto& reader = readers_.get<lungar_sync_BreathingState>();
  reader.take_each<4>([&](const lungar_sync_BreathingState& s, const dds_sample_info_t& info) {
    if (!info.valid_data) return;
    auto params = from_wire(s);
    if (!params) {
      link_->malformed(params.error());
      return;
    }
    hear(s.session, lungar::monotonic_ns());  // a durable sample arrives from a live writer only
    pending_state_ = PendingState{s.session, s.revision, s.time_base_ns, s.station, *params};
  });
}

void Trainee::take_events() {
  const auto& reader = readers_.get<lungar_sync_ScenarioEvents>();
  reader.take_loaned([&](const lungar_sync_ScenarioEvents& s, const dds_sample_info_t& info) {
    if (!info.valid_data) return;
    auto events = from_wire(s);
    if (!events) {
      link_->malformed(events.error());
      return;
    }
    auto lungs = pathologies_from_wire(s);
    if (!lungs) {
      link_->malformed(lungs.error());
      return;
    }
    auto ventilation_map = ventilation_map_from_wire(s);
    if (!ventilation_map) {
      link_->malformed(ventilation_map.error());
      return;
    }
    pending_events_ = PendingEvents{s.session, s.revision, events.take(), lungs.take(), *ventilation_map};
  });
}

void Trainee::install_if_complete() {
  if (!pending_state_ || !pending_events_) return;
  const PendingState& st = *pending_state_;
  if (st.session != pending_events_->session || st.revision != pending_events_->revision) return;
  if (st.session == installed_session_ && st.revision == installed_revision_) return;
  auto driver = SharedBreathing::build(st.params, pending_events_->events);
  installed_session_ = st.session;  // a bad pair is not retried until the instructor sends another
  installed_revision_ = st.revision;
  if (!driver) {
    link_->malformed(driver.error());
    return;
  }
  breathing_.install(driver.take(), st.time_base_ns);
  {
    std::lock_guard lock(report_mutex_);
    instructor_ = st.station;
  }
  {
    std::lock_guard lock(lungs_mutex_);
    lungs_ = pending_events_->lungs;
    lungs_version_.fetch_add(1, std::memory_order_release);
  }
  char line[200];
  std::snprintf(line, sizeof line, "sync: breathing of instructor '%s': %s, %.1f/min, %.0f mL, %zu events",
                st.station.c_str(), std::string(sim::to_string(st.params.preset)).c_str(), st.params.rate_bpm,
                st.params.tidal_volume_ml, pending_events_->events.size());
  link_->log(line);
  link_->log("sync: lungs of instructor '" + st.station + "': " + sim::describe(pending_events_->lungs));
  const std::optional<bool> map = pending_events_->ventilation_map;
  if (map && map != display_applied_) {
    display_applied_ = map;
    ventilation_map_.set(*map);
    link_->log(std::string("sync: the instructor's console asks for the ventilation map ") + (*map ? "on" : "off"));
  }
}

bool Trainee::ventilation_map_since(std::uint64_t& version, bool& on) const {
  return ventilation_map_.since(version, on);
}

void Trainee::take_heartbeats(std::int64_t now_mono) {
  const auto& reader = readers_.get<lungar_sync_Heartbeat>();
  reader.take_each<8>([&](const lungar_sync_Heartbeat& hb, const dds_sample_info_t& info) {
    if (!info.valid_data) return;
    if (Status c = check(hb); !c) {
      link_->malformed(c.error());
      return;
    }
    hear(hb.session, now_mono);
    provisional_offset(info.source_timestamp, link_->clock().now_ns());
    heartbeats_.fetch_add(1, std::memory_order_relaxed);
    if (hb.session == installed_session_ && state() == SyncState::InSync) compare_breath(hb);
    if (hb.session == installed_session_ && hb.followed) {
      followed_.push({hb.breath_t_s, hb.dv_ml, {hb.left_dv_ml, hb.right_dv_ml}});
      followed_points_.fetch_add(1, std::memory_order_relaxed);
    }
  });
}

/// The breathing time this station's last frame drew minus the instructor's at the same instant: the instructor's
/// frame time mapped onto this clock by the estimated offset, its breathing time carried forward to the frame.
void Trainee::compare_breath(const lungar_sync_Heartbeat& hb) {
  if (!estimate_ || frame_box_.published() == 0) return;
  const FrameBreath f = frame_box_.read();
  if (f.now_mono_ns < in_sync_since_mono_) return;  // drawn before this station was in step
  const std::int64_t frame_on_instructor_clock = link_->clock().from_monotonic(f.now_mono_ns) + estimate_->offset_ns;
  const double instructor_t = hb.breath_t_s + static_cast<double>(frame_on_instructor_clock - hb.frame_ns) * 1e-9;
  record(breath_offset_ms_, std::abs(f.t_s - instructor_t) * 1e3);
  status_offset_ms_ = std::max(status_offset_ms_, std::abs(f.t_s - instructor_t) * 1e3);
}

void Trainee::take_poses() {
  std::int64_t arrival = 0, here_ns = 0;
  auto taken = [&] {  // a batch of poses shares its receipt time
    arrival = lungar::monotonic_ns();
    here_ns = link_->clock().from_monotonic(arrival);
  };
  const auto& reader = readers_.get<lungar_sync_PatientPose>();
  reader.take_each<8>(taken, [&](const lungar_sync_PatientPose& s, const dds_sample_info_t& info) {
    if (!info.valid_data) return;
    auto pose = from_wire(s);
    if (!pose) {
      link_->malformed(pose.error());
      return;
    }
    hear(s.session, arrival);
    provisional_offset(info.source_timestamp, here_ns);
    drivers::PoseSample p;
    p.role = drivers::Role::Patient;
    p.flags = drivers::kPoseValid;
    p.t_arrival_ns = arrival;
    p.t_device_ns = arrival;
    p.position_mm = pose->position_mm;
    p.orientation_wxyz = pose->orientation_wxyz;
    if (estimate_) {  // publication -> receipt, both on the instructor's clock
      p.t_device_ns = link_->clock().to_monotonic(pose->measured_ns - estimate_->offset_ns);
      const double age_ms = static_cast<double>(here_ns + estimate_->offset_ns - info.source_timestamp) * 1e-6;
      record(pose_age_ms_, age_ms);
      status_pose_age_ms_ = std::max(status_pose_age_ms_, age_ms);
    }
    pose_box_.publish(p);
    poses_.fetch_add(1, std::memory_order_relaxed);
    std::lock_guard lock(report_mutex_);
    last_orientation_ = p.orientation_wxyz;
  });
}

void Trainee::hear(std::uint64_t session, std::int64_t now_mono) {
  if (session != heard_session_) {  // a new instructor (or the first): its clock is learnt afresh
    heard_session_ = session;
    estimator_.reset();
    exchanges_ = 0;
    next_request_mono_ = now_mono;
    if (join_mono_ == 0) join_mono_ = now_mono;
    std::lock_guard lock(report_mutex_);
    estimate_.reset();
    provisional_ = false;
  }
  last_heard_mono_ = now_mono;
}

void Trainee::provisional_offset(std::int64_t source_ns, std::int64_t here_ns) {
  if (estimate_ && !provisional_) return;
  const std::int64_t candidate = source_ns - here_ns;  // offset - delay: the largest has the least delay
  if (estimate_ && candidate <= estimate_->offset_ns) return;
  breathing_.update_offset(candidate);
  std::lock_guard lock(report_mutex_);
  estimate_ = ClockEstimate{candidate, 0, 0.0, 0};
  provisional_ = true;
}

void Trainee::take_replies() {
  std::int64_t t4 = 0;
  auto taken = [&] { t4 = link_->clock().now_ns(); };  // a batch of replies shares its receipt time
  const auto& reader = readers_.get<lungar_sync_TimeReply>();
  reader.take_each<8>(taken, [&](const lungar_sync_TimeReply& s, const dds_sample_info_t& info) {
    if (!info.valid_data || s.requester != link_->session()) return;
    const ClockExchange x{s.t1_ns, s.t2_ns, info.source_timestamp, t4};
    if (!estimator_.add(x)) return;  // a stalled or impossible exchange: the next one will do
    ++exchanges_;
    const auto e = estimator_.estimate();
    breathing_.update_offset(e->offset_ns);
    std::lock_guard lock(report_mutex_);
    estimate_ = e;
    provisional_ = false;
  });
}

void Trainee::request_time(std::int64_t now_mono) {
  if (heard_session_ == 0 || now_mono < next_request_mono_ || request_writer_->matched() <= 0) return;
  lungar_sync_TimeRequest req{link_->session(), ++request_seq_};
  (void)request_writer_->write(req, link_->clock().now_ns());  // its source timestamp is t1
  next_request_mono_ = now_mono + (exchanges_ < kBurstExchanges ? kBurstPeriodNs : kRequestPeriodNs);
}

void Trainee::update_state(std::int64_t now_mono) {
  const bool heard = heard_session_ != 0 && now_mono - last_heard_mono_ <= link_->options().lost_after_ns;
  const bool ready = heard && installed_session_ == heard_session_ && breathing_.ready() && estimate_;
  const SyncState was = state();
  if (ready && was != SyncState::InSync) {
    char line[240];
    const double join_ms = join_mono_ != 0 ? static_cast<double>(now_mono - join_mono_) * 1e-6 : -1.0;
    std::snprintf(line, sizeof line,
                  "sync: in step with instructor '%s' %.1f ms after joining (clock offset %.3f ms, %s)",
                  instructor_.c_str(), join_ms, static_cast<double>(estimate_->offset_ns) * 1e-6,
                  provisional_ ? "one-way until the first clock exchange" : "from a clock exchange");
    link_->log(line);
    {
      std::lock_guard lock(report_mutex_);
      join_to_in_sync_ms_ = join_ms;
    }
    join_mono_ = 0;
    in_sync_since_mono_ = now_mono;
    transition(SyncState::InSync);
  } else if (!heard && was == SyncState::InSync) {
    link_->log("sync lost: no word from instructor '" + instructor_ + "' for " +
               std::to_string((now_mono - last_heard_mono_) / 1'000'000) +
               " ms; breathing goes on on the shared time base");
    heard_session_ = 0;  // whoever speaks next is followed as a new instructor
    transition(SyncState::Lost);
  }
}

void Trainee::transition(SyncState to) {
  state_.store(to, std::memory_order_release);
  std::lock_guard lock(report_mutex_);
  if (transitions_.size() < transitions_.capacity())
    transitions_.push_back({to, StationClock().now_ns()});  // the machine's clock, unskewed
}

void Trainee::send_status(std::int64_t now_mono) {
  constexpr std::int64_t kStatusPeriodNs = 500'000'000;
  if (now_mono < next_status_mono_) return;
  const double interval_s =
      next_status_mono_ == 0 ? 0.0 : 1e-9 * static_cast<double>(now_mono - next_status_mono_ + kStatusPeriodNs);
  next_status_mono_ = now_mono + kStatusPeriodNs;
  const std::uint64_t frames = frame_box_.published();
  lungar_sync_StationStatus s{};
  std::snprintf(s.name, sizeof s.name, "%s", link_->name().c_str());
  s.session = link_->session();
  s.state = static_cast<std::uint8_t>(state());
  s.breath_offset_ms = status_offset_ms_;
  s.pose_age_ms = status_pose_age_ms_;
  s.fps = interval_s > 0 ? static_cast<double>(frames - status_frames_) / interval_s : 0.0;
  s.secure = link_->secure();
  status_frames_ = frames;
  status_offset_ms_ = status_pose_age_ms_ = 0;
  (void)status_writer_->write(s, link_->clock().now_ns());  // best effort: the next one comes in half a second
}

void Trainee::record(LogHistogram& values, double v) {
  std::lock_guard lock(report_mutex_);
  values.add(v);
}

SyncReport Trainee::report() const {
  SyncReport r = link_->report(SyncRole::Trainee);
  r.state = state();
  r.peers = peers_.load();
  r.peers_max = peers_max_.load();
  r.poses = poses_.load();
  r.heartbeats = heartbeats_.load();
  r.followed_breath_points = followed_points_.load();
  std::lock_guard lock(report_mutex_);
  r.instructor = instructor_;
  r.patient_orientation_wxyz = last_orientation_;
  r.breath_offset_ms_p50 = breath_offset_ms_.percentile(50);
  r.breath_offset_ms_p99 = breath_offset_ms_.percentile(99);
  r.patient_pose_age_ms_p50 = pose_age_ms_.percentile(50);
  r.patient_pose_age_ms_p99 = pose_age_ms_.percentile(99);
  if (estimate_) {
    r.clock_offset_ms = static_cast<double>(estimate_->offset_ns) * 1e-6;
    r.clock_offset_spread_ms = estimate_->spread_ns * 1e-6;
    r.clock_delay_ms = static_cast<double>(estimate_->delay_ns) * 1e-6;
  }
  r.join_to_in_sync_ms = join_to_in_sync_ms_;
  r.transitions = transitions_;
  return r;
}

}  // namespace lungar::classroom
