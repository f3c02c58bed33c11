/// @file tracker_device.h
/// @brief What every device (drivers/hid, drivers/igtl, drivers/mock, drivers/replay) implements: the body of the
/// thread that feeds the pipeline.
/// @ingroup drivers
#pragma once

#include <stop_token>
#include <string>

#include "drivers/trk/trk_format.h"

namespace lungar::drivers {

class TrackerCore;

class TrackerDevice {
 public:
  virtual ~TrackerDevice() = default;
  /// The thread: read reports and pass each to core.feed() (or, decoded here, to core.feed_decoded()) until
  /// `stop` is requested. Allocates nothing per report. Sets the connection state on `core`.
  virtual void run(TrackerCore& core, std::stop_token stop) = 0;
  /// One line for logs and the .trk header's description ("key=value" lines for the latter).
  virtual std::string describe() const = 0;
  virtual std::string trk_description() const = 0;
  virtual TrkSource trk_source() const = 0;
};

}  // namespace lungar::drivers
