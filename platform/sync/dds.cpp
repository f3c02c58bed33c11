/// @file dds.cpp
/// @brief The RAII layer's non-template half: deleting entities, the domain from an XML file, the waitset.
#include "platform/sync/dds.h"

#include <fstream>
#include <mutex>
#include <sstream>

namespace lungar::platform::dds {

namespace {

/// Cyclone reports what it dislikes in a configuration through its log, not its return code: the log sink
/// keeps the first error line of the current domain creation so it can go into our one error line.
struct ConfigComplaint {
  std::mutex mutex;
  bool capturing = false;
  std::string first;
};
ConfigComplaint g_complaint;

void log_sink(void*, const dds_log_data_t* data) {
  if ((data->priority & (DDS_LC_ERROR | DDS_LC_FATAL)) == 0 || data->message == nullptr) return;
  std::lock_guard lock(g_complaint.mutex);
  if (!g_complaint.capturing || !g_complaint.first.empty()) return;
  std::string line(data->message + data->hdrsize, data->size > data->hdrsize ? data->size - data->hdrsize : 0);
  while (!line.empty() && (line.back() == '\n' || line.back() == ' ')) line.pop_back();
  g_complaint.first = line;
}

}  // namespace

std::string describe(const char* call, dds_return_t rc) {
  return std::string(call) + ": " + dds_strretcode(rc);
}

void Entity::reset() {
  if (handle_ > 0) dds_delete(handle_);
  handle_ = 0;
}

Result<Entity> own(const char* call, dds_entity_t handle) {
  if (handle < 0) return fail(describe(call, handle));
  return Entity(handle);
}

Result<Domain> Domain::create(std::uint32_t domain_id, const std::string& config_path) {
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
  {
    std::lock_guard lock(g_complaint.mutex);
    g_complaint.capturing = true;
    g_complaint.first.clear();
  }
  dds_set_log_sink(log_sink, nullptr);  // also keeps Cyclone's multi-line complaints off stderr
  const dds_entity_t domain = dds_create_domain(domain_id, xml.c_str());
  std::string complaint;
  {
    std::lock_guard lock(g_complaint.mutex);
    g_complaint.capturing = false;
    complaint = g_complaint.first;
  }
  if (domain == DDS_RETCODE_PRECONDITION_NOT_MET) {
    // This process made the domain already (two stations in one test process): its participants share it.
  } else if (domain < 0) {
    return fail(config_path + ": Cyclone DDS refused the configuration (" +
                (complaint.empty() ? describe("dds_create_domain", domain) : complaint) + ")");
  } else {
    d.domain_ = Entity(domain);
  }
  auto participant = own("dds_create_participant", dds_create_participant(domain_id, nullptr, nullptr));
  if (!participant) return fail(config_path + ": " + participant.error());
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

}  // namespace lungar::platform::dds
