/// @file classroom_link.cpp
/// @brief Opening a classroom (domain, topics, Station), the roster of the other stations, dropped samples.
#include "drivers/classroom/classroom_link.h"

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <random>

#include "config/base/log_line.h"
#include "drivers/classroom/wire.h"
#include "drivers/dds/dds_security.h"

namespace lungar::classroom {

std::uint64_t new_session_id() {
  std::random_device rd;
  std::uint64_t id = 0;
  while (id == 0) id = (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
  return id;
}

std::string default_station_name() {
  char host[64] = {};
  if (gethostname(host, sizeof host - 1) != 0 || host[0] == '\0') std::strcpy(host, "station");
  return std::string(host) + "/" + std::to_string(getpid());
}

namespace {
std::string folder_name(const std::string& dir) {
  const std::filesystem::path p = std::filesystem::path(dir).lexically_normal();
  return p.has_filename() ? p.filename().string() : p.parent_path().filename().string();
}
}  // namespace

ClassroomLink::ClassroomLink(const SyncOptions& options, dds::Domain domain)
    : options_(options), clock_(options.clock_skew_ns), domain_(std::move(domain)) {}

Result<std::unique_ptr<ClassroomLink>> ClassroomLink::open(const SyncOptions& options, std::uint8_t wire_role) {
  if (options.classroom.empty() || options.classroom.size() > 63 ||
      options.classroom.find_first_of("*?[]\\") != std::string::npos) {
    return fail("sync.classroom: expected a name of 1 to 63 characters without * ? [ ] \\, got \"" + options.classroom +
                "\"");
  }
  // A secure station's folder is named after it (DIR/STATION/ of classroom-keys): that name, unless told another.
  const std::string name = !options.station.empty()        ? options.station
                           : !options.security_dir.empty() ? folder_name(options.security_dir)
                                                           : default_station_name();
  if (name.size() > 63) return fail("sync.station: expected at most 63 characters, got \"" + name + "\"");
  dds::Qos participant_qos;
  if (!options.security_dir.empty()) {
    auto files = dds::find_security_files(options.security_dir);
    if (!files) return Error{files.error()};
    if (Status s = dds::add_security_properties(*files, options.domain, participant_qos); !s) return Error{s.error()};
  }
  auto domain = dds::Domain::create(options.domain, options.cyclonedds_xml,
                                    options.security_dir.empty() ? nullptr : &participant_qos);
  if (!domain) {
    if (options.security_dir.empty()) return Error{domain.error()};
    return fail("sync.security " + options.security_dir + ": " + domain.error());
  }
  std::unique_ptr<ClassroomLink> link(new ClassroomLink(options, domain.take()));
  link->name_ = name;
  link->session_ = new_session_id();
  link->started_ns_ = link->clock_.now_ns();
  link->wire_role_ = wire_role;
  const dds_entity_t p = link->domain_.participant();
  Status topics = link->topics_.open([p](auto type) {
    using T = typename decltype(type)::type;
    return dds::Topic<T>::create(p, TopicInfo<T>::descriptor(), TopicInfo<T>::name);
  });
  if (!topics) return fail("sync: " + topics.error());
  auto writer = link->writer<lungar_sync_Station>();
  auto reader = link->reader<lungar_sync_Station>();
  auto waitset = dds::WaitSet::create(p);
  if (!writer || !reader || !waitset) {
    return fail("sync: " + (!writer ? writer.error() : !reader ? reader.error() : waitset.error()));
  }
  link->station_writer_.emplace(writer.take());
  link->station_reader_.emplace(reader.take());
  link->waitset_.emplace(waitset.take());
  if (!options.security_dir.empty()) {
    auto refused = dds::RefusedPeers::create(p, options.refuse_after_ns);
    if (!refused) return fail("sync: " + refused.error());
    link->refused_ = refused.take();
    link->log("sync: classroom \"" + options.classroom + "\" is secure: DDS Security with " + options.security_dir +
              " (authenticated, access-controlled, encrypted)");
  } else {
    link->log("sync: classroom \"" + options.classroom +
              "\" is open: any DDS participant on this network can join "
              "it and publish to it (--sync-security DIR closes it; see lungar classroom-keys)");
  }
  if (Status a = link->waitset_->attach_reader(link->station_reader_->get()); !a) return fail("sync: " + a.error());
  return link;
}

Status ClassroomLink::announce() {
  lungar_sync_Station s{};
  std::strncpy(s.name, name_.c_str(), sizeof s.name - 1);
  s.role = wire_role_;
  s.session = session_;
  s.started_ns = started_ns_;
  return station_writer_->write(s, clock_.now_ns());
}

int ClassroomLink::poll_roster() {
  const int total = station_reader_->take_each<8>([this](const lungar_sync_Station& s, const dds_sample_info_t& info) {
    RosterEntry* entry = nullptr;
    for (std::size_t k = 0; k < roster_size_; ++k) {
      if (roster_[k].instance == info.instance_handle) entry = &roster_[k];
    }
    if (!info.valid_data) {  // the instance's writer went away (lease expired or deleted)
      if (entry) entry->alive = info.instance_state == DDS_IST_ALIVE;
      return;
    }
    if (Status c = check(s); !c) {
      malformed(c.error());
      return;
    }
    if (s.session == session_) return;  // ourselves
    if (!entry) {
      if (roster_size_ == roster_.size()) return;
      entry = &roster_[roster_size_++];
    }
    *entry = RosterEntry{s.name, s.role, s.session, s.started_ns, info.instance_handle, true};
  });
  peers_max_ = std::max(peers_max_, peers());
  const std::int64_t now = clock_.now_ns();
  if (refused_ && now - refused_polled_ns_ >= 200'000'000) {  // discovery changes slowly: five looks a second
    refused_polled_ns_ = now;
    refused_->poll(station_reader_->get(), now, [this](const std::string& line) { log(line); });
  }
  return total;
}

int ClassroomLink::peers() const {
  int n = 0;
  for (std::size_t k = 0; k < roster_size_; ++k) n += roster_[k].alive ? 1 : 0;
  return n;
}

std::optional<RosterEntry> ClassroomLink::senior_instructor() const {
  for (std::size_t k = 0; k < roster_size_; ++k) {
    const RosterEntry& e = roster_[k];
    if (!e.alive || e.role != kWireInstructor) continue;
    if (e.started_ns < started_ns_ || (e.started_ns == started_ns_ && e.name < name_)) return e;
  }
  return std::nullopt;
}

void ClassroomLink::log(const std::string& line) const {
  if (options_.log) {
    options_.log(line);
  } else {
    log_line("lungar", line);
  }
}

std::string ClassroomLink::not_permitted(const char* topic, const char* what, const std::string& cyclone) const {
  return "sync.security " + options_.security_dir + ": station \"" + name_ + "\" may not " + what + " " + topic +
         " in classroom \"" + options_.classroom +
         "\": its permissions.p7s does not allow it (only the instructor's "
         "allow the shared patient, breath and scenario, and each station's only the classroom its keys were made "
         "for; " +
         cyclone + ")";
}

void ClassroomLink::malformed(const std::string& why) {
  const std::uint64_t n = malformed_.fetch_add(1, std::memory_order_relaxed) + 1;
  if (n <= 5 || n % 100 == 0) log("sync: dropped a malformed sample (" + std::to_string(n) + " so far): " + why);
}

}  // namespace lungar::classroom
