/// @file openice_samples_fuzz.cpp
/// @brief libFuzzer target: an OpenICE sample array from arbitrary bytes on the wire to the samples lungar keeps.
/// The first byte picks the CDR version, the byte order and the followed metric; the rest is the payload, taken as
/// Cyclone takes a received one (dds_stream_normalize_data checks it; only what it accepts is deserialised) and
/// then checked as the reader checks it. It must never crash, hang or read out of bounds; every sample kept must
/// be finite, in time order within its array, and a volume never negative.
#include <dds/ddsi/ddsi_cdrstream.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "drivers/breath/physiology/physiology_sample.h"
#include "lungar/physiology/openice.h"

namespace ph = lungar::breath::physiology;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t pick = data[0];
  const std::uint32_t xcdr = (pick & 0x10) ? 2u : 1u;
  const bool bswap = (pick & 0x20) != 0;
  const auto followed = static_cast<ph::Quantity>(pick % 3);
  ++data;
  --size;
  std::vector<std::uint64_t> aligned((size + 7) / 8 + 1);  // CDR is read 8-byte aligned, as Cyclone's buffers are
  std::memcpy(aligned.data(), data, size);
  char* bytes = reinterpret_cast<char*>(aligned.data());
  std::uint32_t off = 0;
  if (dds_stream_normalize_data(bytes, &off, static_cast<std::uint32_t>(size), bswap, xcdr,
                                ice_SampleArray_desc.m_ops) == nullptr)
    return 0;
  dds_istream_t is;
  dds_istream_init(&is, static_cast<std::uint32_t>(size), bytes, xcdr);
  ice_SampleArray a{};
  dds_stream_read(&is, reinterpret_cast<char*>(&a), ice_SampleArray_desc.m_ops);
  ph::OpenIceChecks checks(followed);
  double last_t = -INFINITY;
  const double end = static_cast<double>(a.device_time.sec) + 1e-9 * static_cast<double>(a.device_time.nanosec);
  checks.check(
      {a.metric_id, a.unit_id, a.frequency, {a.values._buffer, a.values._length}, end},
      [&](const ph::Sample& s) {
        if (!std::isfinite(s.value) || !std::isfinite(s.t_s) || s.t_s < last_t) std::abort();
        if (followed == ph::Quantity::volume_ml && s.value < 0) std::abort();
        last_t = s.t_s;
      },
      [](ph::Drop) {});
  dds_stream_free_sample(&a, ice_SampleArray_desc.m_ops);
  dds_istream_fini(&is);
  return 0;
}
