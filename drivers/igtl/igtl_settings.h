/// @file igtl_settings.h
/// @brief [trackers.igtl]: the OpenIGTLink driver's settings, beside it; tracker_config.h composes them into
/// [trackers].
/// @ingroup drivers
#pragma once

#include <string>

namespace lungar::drivers {

/// [trackers.igtl]: an OpenIGTLink server (PlusServer, 3D Slicer's OpenIGTLinkIF) streaming TRANSFORM, TDATA or
/// QTDATA messages.
struct IgtlConfig {
  std::string host = "127.0.0.1";
  int port = 18944;  ///< OpenIGTLink's registered port, PlusServer's and Slicer's default
  /// The device (or tool) name that carries each role, PLUS's naming; "" = the role is not fed.
  std::string head = "HeadToTracker";
  std::string patient = "PatientToTracker";
  std::string stylus = "StylusTipToTracker";
  double scale = 1.0;             ///< mm per unit of the received positions (PLUS and Slicer send mm)
  double rigid_tolerance = 1e-3;  ///< a rotation part whose |R^T R - I| entries exceed this is not rigid: dropped
  double connect_timeout_ms = 1000.0;

  bool operator==(const IgtlConfig&) const = default;
};

}  // namespace lungar::drivers
