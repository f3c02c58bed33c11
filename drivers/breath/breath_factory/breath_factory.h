/// @file breath_factory.h
/// @brief make_breath_source(): the one place that names every breath source (the model, a recorded trace, a live
/// marker, a mannequin's or a ventilator's breath over DDS) and builds the frame's BreathingClock from the one
/// `--breath` or `[breathing] source` picks, as make_tracker() does for the pose sources. The sources never include
/// each other. A classroom trainee's shared breathing wraps whichever clock this makes (platform/sync/).
/// @ingroup breath
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "config/base/result.h"
#include "drivers/breath/marker/marker_feed.h"
#include "drivers/breath/source/breathing_clock.h"
#include "drivers/breath/source/surrogate_feed.h"
#include "drivers/breath/trace/trace_feed.h"
#include "drivers/pose/pose_sample.h"
#include "sim/breathing/script.h"

namespace lungar::breath {

enum class BreathKind { Model, Trace, Marker, Dds };

/// The kind `source` names (config/base/breath_source_names.h): "model" or empty the script, "marker:ROLE" a live
/// marker, "amm..." or "openice..." a source over DDS (even a malformed spec, which opening it names), anything
/// else a trace file.
BreathKind breath_kind(const std::string& source);

/// Opens a source over DDS (`amm[@DOMAIN]`, `openice[:volume|flow|pressure][@DOMAIN]`) and says in the log what it
/// follows, or names what is wrong with the spec: by default their readers' own (physiology/physiology_feed.h);
/// a test hands in a stand-in.
using OpenDdsFeed = std::function<Result<std::shared_ptr<SurrogateFeed>>(const std::string& source)>;

/// A breath source chosen and checked before the tracker starts: a live marker's feed must exist for the tracker
/// to call it with every sample.
struct ChosenBreath {
  std::string source;  ///< as given; empty for the model
  BreathKind kind = BreathKind::Model;
  std::shared_ptr<MarkerFeed> marker;  ///< a live marker's feed

  /// Whether the breath follows a surrogate rather than the script alone.
  bool followed() const { return kind != BreathKind::Model; }
  /// For TrackerOptions::on_sample: a live marker's push; empty for every other source.
  std::function<void(const drivers::PoseSample&)> tracker_tap() const;
};

/// Step one, before the tracker: `source`'s kind, and a live marker's feed; or what is wrong with its ROLE.
Result<ChosenBreath> choose_breath_source(const std::string& source, std::int64_t t0_ns);

struct BreathSourceOptions {
  std::shared_ptr<const sim::BreathingScript> script;  ///< the model: the whole breath, or a followed one's fallback
  TraceSettings trace;
  /// The Cyclone DDS configuration file the sources over DDS join their domain with (the classroom's by default).
  std::string cyclonedds_xml;
  OpenDdsFeed open_dds;  ///< for BreathKind::Dds: a stand-in for the readers (tests); empty, the readers
  std::function<void(const std::string&)> log = [](const std::string&) {};
};

/// Step two, once the tracker runs: the frame's breathing from the chosen source, the run starting at `t0_ns`
/// (monotonic); each followed source says in the log what it follows. An error is the source's one line (a trace
/// that does not read, a DDS spec or reader that fails).
Result<std::unique_ptr<BreathingClock>> make_breath_source(const ChosenBreath& chosen,
                                                           const BreathSourceOptions& options, std::int64_t t0_ns);

}  // namespace lungar::breath
