/// @file recorded_trackers.cpp
/// @brief A log's own [trackers], and its OpenIGTLink records' decoder (recorded_trackers.h).
#include "drivers/replay/recorded_trackers.h"

#include "drivers/tracker/tracker_config_toml.h"

namespace lungar::drivers {

Result<TrackerConfig> recorded_trackers(const TrkLog& log, const std::string& path, const TrackerConfig& otherwise) {
  if (log.header.layout_toml.empty()) return otherwise;
  return tracker_config_from_toml(log.header.layout_toml, path + " (header layout)");
}

RecordDecoder igtl_record_decoder(IgtlLayout layout) {
  return {TrkSource::Igtl,
          [layout](std::span<const std::uint8_t> message) { return decode_igtl_message(message, layout); }};
}

}  // namespace lungar::drivers
