/// @file tracker_config.h
/// @brief [trackers], composed from the settings each driver declares beside itself: the source, the mock's and
/// the replay's keys, the decoder's layout and world frame, and the HID, OpenIGTLink and PLUS tables.
/// @ingroup drivers
///
/// Only the files that choose or configure a device include this (the factory, the TOML reader, the program's
/// settings loader and commands); a driver includes its own settings header. The values are the defaults;
/// `config/default.toml` documents each key and its unit, and tracker_config_toml.h reads and writes the TOML form
/// from one field list.
#pragma once

#include <string>

#include "config/base/enum_names.h"
#include "drivers/decode/report_settings.h"
#include "drivers/hid/hid_settings.h"
#include "drivers/igtl/igtl_settings.h"
#include "drivers/mock/mock_settings.h"
#include "drivers/plus/plus_settings.h"

namespace lungar::drivers {

/// Where the poses come from.
enum class TrackerSource { Mock, Hid, Replay, Igtl };
inline constexpr EnumNames<TrackerSource, 4> kTrackerSourceNames{{{{TrackerSource::Mock, "mock"},
                                                                   {TrackerSource::Hid, "hid"},
                                                                   {TrackerSource::Replay, "replay"},
                                                                   {TrackerSource::Igtl, "igtl"}}}};
inline const char* to_string(TrackerSource v) { return kTrackerSourceNames.name(v); }

/// [trackers]: everything make_tracker() needs. The layout part (report, sensors, world frame) is the base.
struct TrackerConfig : LayoutConfig {
  TrackerSource source = TrackerSource::Mock;
  MockConfig mock;
  std::string replay_file;
  bool replay_realtime = true;
  bool replay_loop = false;         ///< start the log again at its end
  bool replay_truncated = false;    ///< replay a log whose last record stops partway (refused otherwise)
  double stale_ms = 100.0;          ///< a pose older than this is marked stale
  double reopen_backoff_ms = 250.0;
  HidConfig hid;
  IgtlConfig igtl;
  PlusConfig plus;

  bool operator==(const TrackerConfig&) const = default;
};

}  // namespace lungar::drivers
