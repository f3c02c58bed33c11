/// @file mock_interface.h
/// @brief The mock tracker: scripted trajectories turned into raw reports through the configured layout, so
/// that the decoder, recording and everything downstream see the same bytes a device would send.
/// @ingroup drivers
#pragma once

#include <memory>

#include "drivers/decode/report_layout.h"
#include "drivers/mock/mock_settings.h"
#include "drivers/tracker/tracker_device.h"

namespace lungar::drivers {

/// A source producing mock_rate_hz reports per sensor (one report each with a station byte, else one report
/// for all), with optional Gaussian position noise and dropouts. Precondition: the trajectory name is valid.
std::unique_ptr<TrackerDevice> mock_create(const MockConfig& settings, const ReportLayout& layout);

}  // namespace lungar::drivers
