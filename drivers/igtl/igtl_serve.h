/// @file igtl_serve.h
/// @brief A small PlusServer stand-in: streams a mock trajectory's poses as OpenIGTLink TRANSFORM messages, so
/// that `lungar --tracker igtl:HOST:PORT` can be seen working without a tracker (`lungar-trk serve-igtl`).
/// @ingroup drivers
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "config/base/result.h"

namespace lungar::drivers {

struct ServeIgtlOptions {
  std::string address = "127.0.0.1";             ///< "0.0.0.0": every interface
  int port = 18944;                              ///< 0: one the OS picks (reported through on_listening)
  double rate_hz = 60.0;                         ///< messages per device per second
  std::string trajectory = "upright_to_supine";  ///< static | upright_to_supine | head_orbit (drivers/mock)
  double seconds = 0.0;                          ///< stop after this long; 0: until `stop`
  std::string head = "HeadToTracker";            ///< device names, PLUS's; "" = not sent
  std::string patient = "PatientToTracker";
  std::string stylus;
};

/// Listens, then streams to one client at a time: each device's pose (mm, the mock's world frame) at rate_hz,
/// stamped with the wall clock; the trajectory starts again for each client. Returns when `stop` is set or
/// `seconds` have passed; an error when it cannot listen or the trajectory is unknown.
Status serve_igtl(const ServeIgtlOptions& o, const std::atomic<bool>& stop,
                  const std::function<void(const std::string&)>& log,
                  const std::function<void(int port)>& on_listening);

}  // namespace lungar::drivers
