/// @file plus_settings.h
/// @brief [trackers.plus]: the PLUS sequence driver's tool names, beside it; tracker_config.h composes them into
/// [trackers].
/// @ingroup drivers
#pragma once

#include <string>

namespace lungar::drivers {

/// [trackers.plus]: the PLUS sequence tool that feeds each role (`<Tool>To<Frame>Transform`), read by a replayed or
/// calibrating `.igs.mha` and written by `--record FILE.igs.mha`. PLUS's own names by default; at the defaults
/// `StylusTip` also reads as the stylus and `Head` as the head.
struct PlusConfig {
  std::string head = "HMD";
  std::string patient = "Reference";
  std::string stylus = "Stylus";

  bool operator==(const PlusConfig&) const = default;
};

}  // namespace lungar::drivers
