/// @file physiology_spec.h
/// @brief What `--breath amm[@DOMAIN]` and `--breath openice[:volume|flow|pressure][@DOMAIN]` say
///        (physiology_feed.h follows them).
/// @ingroup platform
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "config/base/breath_source_names.h"
#include "config/base/result.h"
#include "drivers/breath/physiology/physiology_sample.h"

namespace lungar::breath::physiology {

struct PhysiologySpec {
  BreathSource source = BreathSource::Amm;  ///< Amm or OpenIce
  Quantity quantity = Quantity::volume_ml;  ///< OpenICE's metric (AMM's are volumes)
  std::uint32_t domain = 0;                 ///< the DDS domain id, [0, 232]
};

/// The spec `breath` names, nullopt when it names no DDS source (a file, a marker), or what is wrong with it.
Result<std::optional<PhysiologySpec>> parse_physiology_spec(const std::string& breath);

}  // namespace lungar::breath::physiology
