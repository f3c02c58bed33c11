/// @file instructor.cpp
/// @brief The instructor's probe for another instructor, its writers, and its sync thread.
#include "drivers/classroom/instructor.h"

#include <algorithm>
#include <cstring>
#include <ctime>

#include "config/base/clock.h"
#include "drivers/classroom/wire.h"

namespace lungar::classroom {

namespace {

/// "12:00:01" local time of a station-clock stamp, for the refusal line.
std::string clock_time(std::int64_t ns) {
  const std::time_t s = static_cast<std::time_t>(ns / 1'000'000'000);
  std::tm tm{};
  localtime_r(&s, &tm);
  char text[16];
  std::strftime(text, sizeof text, "%H:%M:%S", &tm);
  return text;
}

std::string refusal(const ClassroomLink& link, const RosterEntry& other) {
  return "sync: classroom '" + link.options().classroom + "' (domain " + std::to_string(link.options().domain) +
         ") already has an instructor: station '" + other.name + "' (started " + clock_time(other.started_ns) +
         "); start this station with --sync trainee, or give it another classroom";
}

}  // namespace

Instructor::Instructor(std::unique_ptr<ClassroomLink> link) : link_(std::move(link)) {}

Result<std::unique_ptr<Instructor>> Instructor::create(const SyncOptions& options) {
  auto link = ClassroomLink::open(options, kWireInstructor);
  if (!link) return Error{link.error()};
  std::unique_ptr<Instructor> self(new Instructor(link.take()));
  ClassroomLink& l = *self->link_;
  if (Status a = l.announce(); !a) return fail("sync: " + a.error());
  // Listen for an instructor already there: its Station sample is transient-local, so it arrives on matching.
  const std::int64_t until = lungar::monotonic_ns() + options.probe_ns;
  for (std::int64_t now = lungar::monotonic_ns(); now < until; now = lungar::monotonic_ns()) {
    l.waitset().wait(until - now);
    l.poll_roster();
    if (auto other = l.senior_instructor()) return fail(refusal(l, *other));
  }
  if (Status w = self->open_writers(); !w) return fail("sync: " + w.error());
  l.log("sync: instructor '" + l.name() + "' of classroom '" + options.classroom + "' (domain " +
        std::to_string(options.domain) + "), " + std::to_string(l.peers()) + " other stations");
  self->thread_.start(l.waitset(), [s = self.get()] { s->run(); });
  return self;
}

Instructor::~Instructor() { thread_.stop(); }

Status Instructor::open_writers() {
  Status writers = writers_.open([this](auto type) { return link_->writer<typename decltype(type)::type>(); });
  if (!writers) return writers;
  auto request = link_->reader<lungar_sync_TimeRequest>();
  if (!request) return Error{request.error()};
  request_reader_.emplace(request.take());
  auto status = link_->reader<lungar_sync_StationStatus>();
  if (!status) return Error{status.error()};
  status_reader_.emplace(status.take());
  if (Status s = link_->waitset().attach_reader(status_reader_->get()); !s) return s;
  for (dds_entity_t durable :
       {writers_.get<lungar_sync_BreathingState>().get(), writers_.get<lungar_sync_ScenarioEvents>().get()}) {
    if (Status s = link_->waitset().attach_publication_matched(durable); !s) return s;
  }
  return link_->waitset().attach_reader(request_reader_->get());
}

Status Instructor::share_breathing(const sim::BreathingParams& start, std::span<const sim::Event> events,
                                   const sim::PathologyTimeline& lungs, std::int64_t t0_mono_ns) {
  const std::int64_t time_base = link_->clock().from_monotonic(t0_mono_ns);
  state_.session = link_->session();
  std::strncpy(state_.station, link_->name().c_str(), sizeof state_.station - 1);
  state_.time_base_ns = time_base;
  state_.revision = 1;
  to_wire(start, state_);
  events_.session = link_->session();
  events_.revision = 1;
  if (Status s = to_wire(events, event_storage_, events_); !s) return s;
  if (Status s = to_wire(lungs, pathology_storage_, events_); !s) return s;
  const std::int64_t now = link_->clock().now_ns();
  const auto& events_writer = writers_.get<lungar_sync_ScenarioEvents>();
  const auto& state_writer = writers_.get<lungar_sync_BreathingState>();
  if (Status s = events_writer.write(events_, now); !s) return fail("sync: " + s.error());
  if (Status s = state_writer.write(state_, now); !s) return fail("sync: " + s.error());
  time_base_ns_.store(time_base);
  shared_.store(true);  // from here on the sync thread owns state_ and events_
  link_->waitset().trigger();
  return ok();
}

Status Instructor::reshare(const sim::BreathingParams& start, std::span<const sim::Event> events,
                           const sim::PathologyTimeline& lungs, std::optional<bool> ventilation_map) {
  if (!shared_.load()) return fail("sync: the class changed before its breathing was shared");
  std::lock_guard lock(share_mutex_);
  // Built in copies first: a change the wire refuses leaves the shared revision as it was.
  lungar_sync_BreathingState state = state_;
  lungar_sync_ScenarioEvents sample = events_;
  std::vector<lungar_sync_ScenarioEvent> event_storage;
  std::vector<lungar_sync_PathologyEvent> pathology_storage;
  to_wire(start, state);
  if (Status s = to_wire(events, event_storage, sample); !s) return s;
  if (Status s = to_wire(lungs, pathology_storage, sample); !s) return s;
  ventilation_map_to_wire(ventilation_map, sample);
  state.revision = sample.revision = state_.revision + 1;
  const std::int64_t now = link_->clock().now_ns();
  // The events first: a trainee installs a revision once both halves of it have come.
  if (Status s = writers_.get<lungar_sync_ScenarioEvents>().write(sample, now); !s) return fail("sync: " + s.error());
  if (Status s = writers_.get<lungar_sync_BreathingState>().write(state, now); !s) return fail("sync: " + s.error());
  state_ = state;
  events_ = sample;
  event_storage_ = std::move(event_storage);  // the sample's sequences point into these buffers, which moved whole
  pathology_storage_ = std::move(pathology_storage);
  return ok();
}

std::uint32_t Instructor::revision() const {
  std::lock_guard lock(share_mutex_);
  return state_.revision;
}

void Instructor::push_to_new_readers() {
  const auto& state_writer = writers_.get<lungar_sync_BreathingState>();
  const auto& events_writer = writers_.get<lungar_sync_ScenarioEvents>();
  const int state_readers = state_writer.matched();  // reading the status clears the waitset's trigger
  const int event_readers = events_writer.matched();
  if (shared_.load() && (state_readers > state_readers_ || event_readers > event_readers_)) {
    std::lock_guard lock(share_mutex_);
    const std::int64_t now = link_->clock().now_ns();
    (void)events_writer.write(events_, now);  // reliable: a failure here is Cyclone's to retry
    (void)state_writer.write(state_, now);
  }
  state_readers_ = state_readers;
  event_readers_ = event_readers;
}

void Instructor::publish_pose(const std::array<double, 3>& position_mm, const std::array<double, 4>& orientation_wxyz,
                              std::int64_t measured_mono_ns) {
  if (measured_mono_ns == last_measured_) return;
  last_measured_ = measured_mono_ns;
  pose_box_.publish(PoseMsg{position_mm, orientation_wxyz, measured_mono_ns});
  link_->waitset().trigger();
}

void Instructor::frame_breath(std::int64_t frame_mono_ns, const sim::BreathingSample& breath) {
  breath_box_.publish(BreathMsg{frame_mono_ns, breath.t_s, breath.dv_ml, breath.lung_dv_ml});
  if (followed_.load(std::memory_order_relaxed)) link_->waitset().trigger();
}

void Instructor::run() {
  std::int64_t next_heartbeat = lungar::monotonic_ns();
  while (!thread_.stopping()) {
    const std::int64_t now = lungar::monotonic_ns();
    if (now >= next_heartbeat) {
      send_heartbeat();
      next_heartbeat = now + kHeartbeatPeriodNs;
    }
    link_->waitset().wait(next_heartbeat - lungar::monotonic_ns());
    if (link_->poll_roster() > 0) check_roster();
    answer_requests();
    take_statuses();
    push_to_new_readers();
    send_pose();
    if (followed_.load(std::memory_order_relaxed) && breath_box_.published() != sent_breath_) send_heartbeat();
  }
}

void Instructor::send_pose() {
  const std::uint64_t n = pose_box_.published();
  if (n == sent_pose_ || !shared_.load()) return;
  sent_pose_ = n;
  const PoseMsg m = pose_box_.read();
  SharedPose pose{m.position_mm, m.orientation_wxyz, link_->clock().from_monotonic(m.measured_mono_ns)};
  lungar_sync_PatientPose sample{};
  to_wire(pose, link_->session(), ++pose_seq_, sample);
  if (!writers_.get<lungar_sync_PatientPose>().write(sample, link_->clock().now_ns())) return;
  poses_.fetch_add(1, std::memory_order_relaxed);
  std::lock_guard lock(fatal_mutex_);
  last_orientation_ = m.orientation_wxyz;
}

void Instructor::send_heartbeat() {
  if (!shared_.load()) return;
  lungar_sync_Heartbeat hb{};
  hb.session = link_->session();
  hb.seq = ++heartbeat_seq_;
  if (breath_box_.published() > 0) {
    sent_breath_ = breath_box_.published();
    const BreathMsg m = breath_box_.read();
    hb.frame_ns = link_->clock().from_monotonic(m.frame_mono_ns);
    hb.breath_t_s = m.breath_t_s;
    hb.followed = followed_.load(std::memory_order_relaxed);
    hb.dv_ml = m.dv_ml;
    hb.left_dv_ml = m.lung_dv_ml[0];
    hb.right_dv_ml = m.lung_dv_ml[1];
  } else {  // no frame yet: breathing time 0 is the time base itself
    hb.frame_ns = time_base_ns_.load();
    hb.breath_t_s = 0.0;
  }
  const auto& heartbeat_writer = writers_.get<lungar_sync_Heartbeat>();
  if (heartbeat_writer.write(hb, link_->clock().now_ns())) heartbeats_.fetch_add(1, std::memory_order_relaxed);
}

void Instructor::answer_requests() {
  std::int64_t t2 = 0;
  auto taken = [&] { t2 = link_->clock().now_ns(); };  // a batch of requests shares its receipt time
  request_reader_->take_each<8>(taken, [&](const lungar_sync_TimeRequest& request, const dds_sample_info_t& info) {
    if (!info.valid_data) return;
    lungar_sync_TimeReply reply{};
    reply.requester = request.requester;
    reply.seq = request.seq;
    reply.t1_ns = info.source_timestamp;
    reply.t2_ns = t2;
    // A lost reply is a lost exchange: the trainee's next request makes another.
    (void)writers_.get<lungar_sync_TimeReply>().write(reply, link_->clock().now_ns());
  });
}

void Instructor::take_statuses() {
  const std::int64_t now = lungar::monotonic_ns();
  status_reader_->take_each<8>([&](const lungar_sync_StationStatus& s, const dds_sample_info_t& info) {
    if (!info.valid_data) return;
    if (Status c = check(s); !c) {
      link_->malformed(c.error());
      return;
    }
    StationStatus st;
    st.name = s.name;
    st.state = s.state == static_cast<std::uint8_t>(SyncState::InSync) ? "in step" : "joining";
    st.breath_offset_ms = s.breath_offset_ms;
    st.pose_age_ms = s.pose_age_ms;
    st.fps = s.fps;
    st.secure = s.secure;
    std::lock_guard lock(stations_mutex_);
    auto it = std::find_if(stations_.begin(), stations_.end(),
                           [&](const HeardStatus& h) { return h.status.name == st.name; });
    if (it == stations_.end()) {
      stations_.push_back({std::move(st), now});
    } else {
      *it = {std::move(st), now};
    }
  });
}

std::vector<StationStatus> Instructor::stations() const {
  const std::int64_t now = lungar::monotonic_ns();
  std::vector<StationStatus> out;
  std::lock_guard lock(stations_mutex_);
  for (const HeardStatus& h : stations_) {
    StationStatus st = h.status;
    st.heard_s_ago = 1e-9 * static_cast<double>(now - h.heard_mono_ns);
    if (now - h.heard_mono_ns > kStationLostNs) st.state = "lost";
    out.push_back(std::move(st));
  }
  return out;
}

void Instructor::check_roster() {
  peers_.store(link_->peers());
  peers_max_.store(link_->peers_max());
  auto other = link_->senior_instructor();
  if (!other) return;
  std::lock_guard lock(fatal_mutex_);
  if (fatal_.empty()) {
    fatal_ = refusal(*link_, *other);
    link_->log(fatal_);
  }
}

std::string Instructor::fatal_error() const {
  std::lock_guard lock(fatal_mutex_);
  return fatal_;
}

SyncReport Instructor::report() const {
  SyncReport r = link_->report(SyncRole::Instructor);
  r.state = SyncState::InSync;
  r.peers = peers_.load();
  r.peers_max = peers_max_.load();
  r.instructor = link_->name();
  r.poses = poses_.load();
  r.heartbeats = heartbeats_.load();
  std::lock_guard lock(fatal_mutex_);
  r.patient_orientation_wxyz = last_orientation_;
  return r;
}

}  // namespace lungar::classroom
