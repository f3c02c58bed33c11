/// @file dds.cpp
/// @brief The RAII layer's non-template half: deleting entities, the domain from an XML file, the waitset.
#include "drivers/dds/dds.h"

#include <fstream>
#include <mutex>
#include <set>
#include <sstream>

namespace lungar::dds {

namespace {

/// Cyclone reports what it dislikes in a configuration, and DDS Security what it refuses, through its log, not
/// its return codes: the log sink keeps the first error line of the current domain and participant creation
/// so it can go into our one error line, and each distinct security warning once for
/// take_security_complaints().
struct CycloneLog {
  std::mutex mutex;
  bool capturing = false;
  std::string first;
  std::set<std::string> complaints_seen;  ///< bounded: a station logs each at most once per run
  std::vector<std::string> complaints_new;
};
CycloneLog g_log;

bool about_security(const std::string& line) {
  for (const char* word : {"handshake", "not allowed", "ertificate", "ermission", "ecurity", "uthenticat"}) {
    if (line.find(word) != std::string::npos) return true;
  }
  return false;
}

void log_sink(void*, const dds_log_data_t* data) {
  if (data->message == nullptr) return;
  const bool error = (data->priority & (DDS_LC_ERROR | DDS_LC_FATAL)) != 0;
  if (!error && (data->priority & DDS_LC_WARNING) == 0) return;
  // Cyclone 0.10 hands the log sink the text after its header (hdrsize is that header's length before it).
  std::string line(data->message, data->size);
  while (!line.empty() && (line.back() == '\n' || line.back() == ' ')) line.pop_back();
  std::lock_guard lock(g_log.mutex);
  if (error && g_log.capturing && g_log.first.empty()) g_log.first = line;
  if (!error && about_security(line) && g_log.complaints_seen.size() < 256 &&
      g_log.complaints_seen.insert(line).second) {
    g_log.complaints_new.push_back(line);
  }
}

void capture_errors(bool on) {
  std::lock_guard lock(g_log.mutex);
  g_log.capturing = on;
  if (on) g_log.first.clear();
}

std::string captured_error() {
  std::lock_guard lock(g_log.mutex);
  return g_log.first;
}

}  // namespace

std::vector<std::string> take_security_complaints() {
  std::lock_guard lock(g_log.mutex);
  std::vector<std::string> taken;
  taken.swap(g_log.complaints_new);
  return taken;
}

std::string describe(const char* call, dds_return_t rc) { return std::string(call) + ": " + dds_strretcode(rc); }

void Entity::reset() {
  if (handle_ > 0) dds_delete(handle_);
  handle_ = 0;
}

Result<Entity> own(const char* call, dds_entity_t handle) {
  if (handle < 0) return fail(describe(call, handle));
  return Entity(handle);
}

Result<Domain> Domain::create(std::uint32_t domain_id, const std::string& config_path, const Qos* participant_qos) {
  if (domain_id > 232) {  // 7400 + 250 * id must stay a port number (DDSI's default port mapping)
    return fail("sync.domain: expected a DDS domain id in [0, 232], got " + std::to_string(domain_id));
  }
  std::ifstream in(config_path);
  if (!in) return fail(config_path + ": cannot read the Cyclone DDS configuration (sync.cyclonedds_xml)");
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  if (xml.find("<CycloneDDS") == std::string::npos) {
    return fail(config_path + ": expected a Cyclone DDS XML configuration (a <CycloneDDS> element), got none");
  }
  Domain d;
  d.id_ = domain_id;
  dds_set_log_sink(log_sink, nullptr);  // also keeps Cyclone's multi-line complaints off stderr
  capture_errors(true);
  const dds_entity_t domain = dds_create_domain(domain_id, xml.c_str());
  capture_errors(false);
  if (domain == DDS_RETCODE_PRECONDITION_NOT_MET) {
    // This process made the domain already (two stations in one test process): its participants share it.
  } else if (domain < 0) {
    const std::string complaint = captured_error();
    return fail(config_path + ": Cyclone DDS refused the configuration (" +
                (complaint.empty() ? describe("dds_create_domain", domain) : complaint) + ")");
  } else {
    d.domain_ = Entity(domain);
  }
  capture_errors(true);
  auto participant =
      own("dds_create_participant",
          dds_create_participant(domain_id, participant_qos ? participant_qos->get() : nullptr, nullptr));
  capture_errors(false);
  if (!participant) {
    const std::string complaint = captured_error();
    if (participant_qos != nullptr && !complaint.empty())
      return fail("DDS Security refused this station (" + complaint + ")");
    return fail(config_path + ": " + participant.error() + (complaint.empty() ? "" : " (" + complaint + ")"));
  }
  d.participant_ = participant.take();
  return d;
}

Result<WaitSet> WaitSet::create(dds_entity_t participant) {
  WaitSet w;
  auto ws = own("dds_create_waitset", dds_create_waitset(participant));
  if (!ws) return Error{ws.error()};
  w.waitset_ = ws.take();
  auto guard = own("dds_create_guardcondition", dds_create_guardcondition(participant));
  if (!guard) return Error{guard.error()};
  w.guard_ = guard.take();
  if (const dds_return_t rc = dds_waitset_attach(w.waitset_.get(), w.guard_.get(), 0); rc < 0) {
    return fail(describe("dds_waitset_attach", rc));
  }
  return w;
}

Status WaitSet::attach_reader(dds_entity_t reader) {
  if (condition_count_ == conditions_.size()) return fail("dds waitset: more readers than it holds");
  auto cond = own("dds_create_readcondition", dds_create_readcondition(reader, DDS_ANY_STATE));
  if (!cond) return Error{cond.error()};
  if (const dds_return_t rc = dds_waitset_attach(waitset_.get(), cond->get(), 0); rc < 0) {
    return fail(describe("dds_waitset_attach", rc));
  }
  conditions_[condition_count_++] = cond.take();
  return ok();
}

Status WaitSet::attach_publication_matched(dds_entity_t writer) {
  if (const dds_return_t rc = dds_set_status_mask(writer, DDS_PUBLICATION_MATCHED_STATUS); rc < 0) {
    return fail(describe("dds_set_status_mask", rc));
  }
  if (const dds_return_t rc = dds_waitset_attach(waitset_.get(), writer, 0); rc < 0) {
    return fail(describe("dds_waitset_attach", rc));
  }
  return ok();
}

bool WaitSet::wait(std::int64_t timeout_ns) {
  const dds_return_t rc = dds_waitset_wait(waitset_.get(), nullptr, 0, timeout_ns);
  bool triggered = false;
  dds_take_guardcondition(guard_.get(), &triggered);
  return rc >= 0;
}

}  // namespace lungar::dds
