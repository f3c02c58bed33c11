/// @file replay_interface.h
/// @brief Replays a .trk log's raw reports through the configured layout, at the recorded pace or at once.
/// @ingroup drivers
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "drivers/decode/decoder.h"
#include "drivers/tracker/tracker_device.h"
#include "drivers/trk/trk_reader.h"

namespace lungar::drivers {

/// How the records of a device with a protocol of its own are decoded again: those of `source` go through
/// `decode`, the function that device decoded them with live.
struct RecordDecoder {
  TrkSource source = TrkSource::Igtl;
  std::function<DecodedReport(std::span<const std::uint8_t>)> decode;
};

/// A device that feeds `log`'s records in order: a record of a source in `decoders` through its decoder
/// (TrackerCore::feed_decoded()), any other through the configured report layout (TrackerCore::feed()).
/// `realtime`: keep the recorded spacing of arrival times; otherwise as fast as the pipeline takes them. `loop`:
/// start again at the end (else finish and go stale).
std::unique_ptr<TrackerDevice> replay_create(TrkLog log, const std::string& path, bool realtime, bool loop,
                                             std::vector<RecordDecoder> decoders);

}  // namespace lungar::drivers
