/// @file sync_samples_fuzz.cpp
/// @brief libFuzzer target: a classroom sample from arbitrary bytes on the wire to what a station applies. The
/// first byte picks the topic and the CDR version; the rest is the payload, taken as Cyclone takes a received one
/// (dds_stream_normalize_data checks and byte-swaps it; only a payload it accepts is deserialised, with
/// dds_stream_read) and then handled as the stations handle it (check() or from_wire()). It must never crash,
/// hang or read out of bounds; whatever from_wire() accepts must be finite and in range.
#include <dds/ddsi/ddsi_cdrstream.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "drivers/classroom/classroom_topics.h"
#include "drivers/classroom/wire.h"

namespace ls = lungar::classroom;

namespace {

template <class T, class Handle>
void receive(const std::uint8_t* data, std::size_t size, std::uint32_t xcdr, bool bswap, Handle&& handle) {
  const dds_topic_descriptor_t& desc = ls::TopicInfo<T>::descriptor();
  std::vector<std::uint64_t> aligned((size + 7) / 8 + 1);  // CDR is read 8-byte aligned, as Cyclone's buffers are
  std::memcpy(aligned.data(), data, size);
  char* bytes = reinterpret_cast<char*>(aligned.data());
  std::uint32_t off = 0;
  if (dds_stream_normalize_data(bytes, &off, static_cast<std::uint32_t>(size), bswap, xcdr, desc.m_ops) == nullptr)
    return;  // Cyclone drops it before any reader sees it
  dds_istream_t is;
  dds_istream_init(&is, static_cast<std::uint32_t>(size), bytes, xcdr);
  T sample{};
  dds_stream_read(&is, reinterpret_cast<char*>(&sample), desc.m_ops);
  handle(sample);
  dds_stream_free_sample(&sample, desc.m_ops);
  dds_istream_fini(&is);
}

void finite_or_abort(double v) {
  if (!std::isfinite(v)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t pick = data[0];
  const std::uint32_t xcdr = (pick & 0x10) ? 2u : 1u;  // CDR_ENC_VERSION_2 / _1 (q_protocol.h)
  const bool bswap = (pick & 0x20) != 0;
  ++data;
  --size;
  switch (pick & 0x7) {
    case 0:
      receive<lungar_sync_Station>(data, size, xcdr, bswap, [](const lungar_sync_Station& s) {
        if (ls::check(s) && std::strlen(s.name) == 0) std::abort();
      });
      break;
    case 1:
      receive<lungar_sync_PatientPose>(data, size, xcdr, bswap, [](const lungar_sync_PatientPose& s) {
        auto p = ls::from_wire(s);
        if (!p) return;
        double n = 0;
        for (double q : p->orientation_wxyz) n += q * q;
        if (std::abs(std::sqrt(n) - 1.0) > 1e-2) std::abort();
        for (double x : p->position_mm)
          if (!(std::abs(x) <= ls::kMaxPositionMm)) std::abort();
      });
      break;
    case 2:
      receive<lungar_sync_BreathingState>(data, size, xcdr, bswap, [](const lungar_sync_BreathingState& s) {
        auto p = ls::from_wire(s);
        if (!p) return;
        finite_or_abort(p->rate_bpm);
        finite_or_abort(p->tidal_volume_ml);
        if (!(p->rate_bpm > 0)) std::abort();
      });
      break;
    case 3:
      receive<lungar_sync_ScenarioEvents>(data, size, xcdr, bswap, [](const lungar_sync_ScenarioEvents& s) {
        auto events = ls::from_wire(s);
        if (events) {
          if (events->size() > ls::kMaxScenarioEvents) std::abort();
          for (std::size_t k = 1; k < events->size(); ++k)
            if ((*events)[k].t_s < (*events)[k - 1].t_s) std::abort();  // promised: in time order
        }
        auto lungs = ls::pathologies_from_wire(s);
        if (!lungs) return;
        if (lungs->events.size() > ls::kMaxPathologyEvents) std::abort();
        for (const auto& e : lungs->events) {  // promised: real times, in order, one spec an event
          finite_or_abort(e.at_s);
          finite_or_abort(e.over_s);
          if (e.add.empty() == e.remove.empty()) std::abort();
        }
      });
      break;
    case 4:
      receive<lungar_sync_Heartbeat>(data, size, xcdr, bswap, [](const lungar_sync_Heartbeat& s) {
        if (!ls::check(s)) return;
        finite_or_abort(s.breath_t_s);
        if (s.followed) finite_or_abort(s.dv_ml);
      });
      break;
    default:
      receive<lungar_sync_TimeReply>(data, size, xcdr, bswap, [](const lungar_sync_TimeReply&) {});
      break;
  }
  return 0;
}
