/// @file amm_reader.h
/// @brief The Advanced Modular Manikin's physiology waveforms (amm.idl) read over DDS: the mannequin's own lung
///        volumes, checked (physiology_sample.h) and left in an inbox for the frame.
///
/// Read with eProsima Fast DDS, AMM's own stack, not Cyclone: AMM's topic is named "Physiology Waveform", and
/// Cyclone DDS (0.10 and later) refuses a topic name with a space. The participant takes Fast DDS's default
/// profile, so FASTRTPS_DEFAULT_PROFILES_FILE sets its network as it does for AMM's modules
/// (config/fastdds/loopback-tests.xml: one machine, no multicast).
/// @ingroup platform
#pragma once

#include <cstdint>
#include <memory>

#include "config/base/result.h"
#include "drivers/breath/physiology/physiology_inbox.h"

namespace lungar::breath::physiology {

/// AMM's topic, reliable, transient-local (a late joiner gets the last samples), exclusive ownership (one
/// physiology engine drives a mannequin).
inline constexpr const char* kAmmTopic = "Physiology Waveform";

class AmmReader {
 public:
  /// Joins DDS domain `domain` and reads kAmmTopic into `inbox` (which must outlive the reader) on Fast DDS's
  /// own thread; an error line when this build has no Fast DDS or the participant cannot be made.
  static Result<std::unique_ptr<AmmReader>> open(std::uint32_t domain, PhysiologyInbox& inbox);
  virtual ~AmmReader() = default;
  /// Publishers matched now.
  virtual int matched() const = 0;
};

}  // namespace lungar::breath::physiology
