/// @file igtl_interface.h
/// @brief The OpenIGTLink source: a client of PlusServer or 3D Slicer's OpenIGTLinkIF (or any OpenIGTLink
/// server) that reads TRANSFORM, TDATA and QTDATA messages and feeds their poses to the tracker pipeline.
/// @ingroup drivers
///
/// disconnected -> opening (connected, no pose yet) -> streaming -> stale (no pose within stale_ms) -> ...; a
/// closed connection goes back to disconnected and is reopened with back-off (reopen_backoff_ms, doubling up to
/// 4 s), without a restart. Each message is decoded here by decode_igtl_message() (igtl_decoder.h) and recorded
/// whole (TrkSource::Igtl), so that replay decodes it with the same function.
#pragma once

#include <memory>

#include "drivers/igtl/igtl_decoder.h"
#include "drivers/tracker/tracker_device.h"

namespace lungar::drivers {

/// A device for [trackers.igtl]'s server, decoding with `layout` (make_igtl_layout()). It never fails to
/// start: an absent server is "disconnected".
std::unique_ptr<TrackerDevice> igtl_create(const IgtlConfig& settings, double reopen_backoff_ms,
                                           const IgtlLayout& layout);

}  // namespace lungar::drivers
