/// @file mock_settings.h
/// @brief The mock tracker's settings, beside it: the `mock_*` keys of [trackers] (tracker_config.h composes them).
/// @ingroup drivers
#pragma once

#include <string>

namespace lungar::drivers {

/// [trackers] mock_trajectory, mock_rate_hz, mock_noise_mm and mock_dropout: what the mock tracker plays.
struct MockConfig {
  std::string trajectory = "upright_to_supine";  ///< static | upright_to_supine | head_orbit
  double rate_hz = 62.5;
  double noise_mm = 0.0;  ///< Gaussian position noise of the mock, mm (1 sigma)
  double dropout = 0.0;   ///< probability that the mock drops a report

  bool operator==(const MockConfig&) const = default;
};

}  // namespace lungar::drivers
