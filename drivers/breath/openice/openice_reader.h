/// @file openice_reader.h
/// @brief A ventilator's waveform from OpenICE (ice::SampleArray, openice.idl) read over Cyclone DDS: one metric
///        (the tidal volume, the airway flow or the airway pressure), its arrays checked (physiology_sample.h) and
///        their samples left in an inbox for the frame, by a thread of the reader's own.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "config/base/result.h"
#include "drivers/breath/physiology/physiology_inbox.h"
#include "drivers/dds/dds.h"
#include "drivers/dds/wait_thread.h"

struct ice_SampleArray;

namespace lungar::breath::physiology {

/// OpenICE's topic of sampled waveforms.
inline constexpr const char* kOpenIceTopic = "SampleArray";

class OpenIceReader {
 public:
  /// Joins domain `domain` with `cyclonedds_xml` and reads the arrays of `followed` into `inbox` (which must
  /// outlive the reader); best effort and volatile, so that it matches any ventilator's writer.
  static Result<std::unique_ptr<OpenIceReader>> open(std::uint32_t domain, const std::string& cyclonedds_xml,
                                                     Quantity followed, PhysiologyInbox& inbox);
  ~OpenIceReader();
  /// Publishers matched now.
  int matched() const { return reader_->matched(); }

 private:
  OpenIceReader(dds::Domain domain, Quantity followed, PhysiologyInbox& inbox)
      : domain_(std::move(domain)), checks_(followed), inbox_(inbox) {}
  void take();

  dds::Domain domain_;  ///< deleted last
  std::optional<dds::Topic<ice_SampleArray>> topic_;
  std::optional<dds::Reader<ice_SampleArray>> reader_;
  std::optional<dds::WaitSet> waitset_;
  OpenIceChecks checks_;  ///< the reader's thread only
  PhysiologyInbox& inbox_;
  dds::WaitThread thread_;  ///< stopped first
};

}  // namespace lungar::breath::physiology
