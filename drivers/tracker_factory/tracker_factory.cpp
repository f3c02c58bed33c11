/// @file tracker_factory.cpp
/// @brief make_tracker(): layouts, the device, optional recording, and the Tracker that runs them.
#include "drivers/tracker_factory/tracker_factory.h"

#include <hidapi/hidapi.h>

#include <mutex>

#include "drivers/hid/hid_interface.h"
#include "drivers/igtl/igtl_interface.h"
#include "drivers/mock/mock_interface.h"
#include "drivers/mock/mock_trajectory.h"
#include "drivers/plus/plus_replay.h"
#include "drivers/replay/recorded_trackers.h"
#include "drivers/replay/replay_interface.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/tracker/tracker_core.h"

namespace lungar::drivers {

namespace {

/// Whether `a` and `b` decode the same bytes to the same poses: the report layout, the sensors, the world frame,
/// the OpenIGTLink names and units; not the source, how it is reached, or its timing.
bool decodes_alike(const TrackerConfig& a, const TrackerConfig& b) {
  return a.report == b.report && a.head == b.head && a.patient == b.patient && a.stylus == b.stylus &&
         a.axis_remap == b.axis_remap && a.world_offset_mm == b.world_offset_mm &&
         a.workspace_min_mm == b.workspace_min_mm && a.workspace_max_mm == b.workspace_max_mm &&
         a.quat_norm_tolerance == b.quat_norm_tolerance && a.igtl.head == b.igtl.head &&
         a.igtl.patient == b.igtl.patient && a.igtl.stylus == b.igtl.stylus && a.igtl.scale == b.igtl.scale &&
         a.igtl.rigid_tolerance == b.igtl.rigid_tolerance;
}

/// Whether a log's header names a layout other than the config's (a header that does not load counts as one).
bool recorded_with_another_layout(const TrkLog& log, const TrackerConfig& settings) {
  if (log.header.layout_toml.empty()) return false;
  auto recorded = tracker_config_from_toml(log.header.layout_toml, settings.replay_file + " (header layout)");
  return !recorded || !decodes_alike(*recorded, settings);
}

/// A PLUS tracked sequence replayed as the OpenIGTLink messages of a PlusServer (drivers/plus/plus_replay.h).
Result<std::unique_ptr<TrackerDevice>> plus_device(const TrackerConfig& settings) {
  Result<PlusSequence> seq = read_plus_sequence(settings.replay_file);
  if (!seq) return fail(seq.error());
  Result<PlusReplay> replay = plus_replay(*seq, settings, settings.replay_file);
  if (!replay) return fail(replay.error());
  RecordDecoder igtl = igtl_record_decoder(replay->layout);
  const std::string what = settings.replay_file + " (PLUS sequence: " + replay->describe + ")";
  return replay_create(std::move(replay->log), what, settings.replay_realtime, settings.replay_loop, {std::move(igtl)});
}

/// The device settings.source names; `layout_differs` is set for a replayed log made with another layout.
Result<std::unique_ptr<TrackerDevice>> make_device(const TrackerConfig& settings, const ReportLayout& layout,
                                                   const IgtlLayout& igtl_layout, bool& layout_differs) {
  switch (settings.source) {
    case TrackerSource::Mock:
      if (!mock_pose(settings.mock.trajectory, Role::Head, 0.0)) {
        return fail(unknown_trajectory("trackers.mock_trajectory", settings.mock.trajectory));
      }
      return mock_create(settings.mock, layout);
    case TrackerSource::Replay: {
      if (is_plus_sequence_path(settings.replay_file)) return plus_device(settings);
      Result<TrkLog> log = load_trk(settings.replay_file);
      if (!log) return fail(log.error());
      // A log cut short (a crash or a full disk while recording) replays what it holds only when asked: else the
      // replay ends early without a word, and a lesson or a test runs on less than the recording.
      if (log->truncated_tail && !settings.replay_truncated) {
        return fail(settings.replay_file + ": the log is truncated (its last record stops partway: the recording " +
                    "was cut short; lungar-trk info says so); expected a whole log, or --replay-truncated " +
                    "(trackers.replay_truncated = true) to replay the " + std::to_string(log->records.size()) +
                    " records it holds");
      }
      // The bytes are decoded with the configured layout, as the live device would; a log made with another
      // layout says so in its header, and the mismatch is worth a line.
      layout_differs = recorded_with_another_layout(*log, settings);
      RecordDecoder igtl = igtl_record_decoder(igtl_layout);
      return replay_create(log.take(), settings.replay_file, settings.replay_realtime, settings.replay_loop,
                           {std::move(igtl)});
    }
    case TrackerSource::Hid: {
      static std::once_flag init;  // hid_init is not thread-safe; once per process
      std::call_once(init, [] { hid_init(); });
      return hid_create(settings.hid, settings.reopen_backoff_ms);
    }
    case TrackerSource::Igtl:
      return igtl_create(settings.igtl, settings.reopen_backoff_ms, igtl_layout);
  }
  return fail("trackers.source: expected " + kTrackerSourceNames.expected());
}

}  // namespace

Result<std::unique_ptr<Tracker>> make_tracker(const TrackerConfig& settings, const TrackerOptions& options) {
  Result<ReportLayout> layout = make_layout(settings);
  if (!layout) return layout.with_context("tracker report layout: ");
  auto igtl_layout = make_igtl_layout(settings.igtl, settings);  // for replay too: a log may hold OpenIGTLink messages
  if (!igtl_layout) return igtl_layout.with_context("tracker: ");
  bool layout_differs = false;
  auto device = make_device(settings, *layout, *igtl_layout, layout_differs);
  if (!device) return device.with_context("");
  TrackerOptions opts = options;
  opts.record_layout_toml = tracker_config_to_toml(settings);
  auto core = std::make_unique<TrackerCore>(*layout, settings.stale_ms, opts);
  if (!options.record_path.empty()) {
    Status recording =
        core->start_recording(options.record_path, (*device)->trk_description(), (*device)->trk_source());
    if (!recording) return fail(recording.error());
  }
  core->log(-1, "tracker: %s", (*device)->describe().c_str());
  if (!options.record_path.empty()) core->log(-1, "recording the tracker's reports into %s", options.record_path.c_str());
  if (settings.source == TrackerSource::Replay && settings.replay_truncated) {
    core->log(-1, "replay %s: a truncated log is replayed as far as it goes (--replay-truncated)",
              settings.replay_file.c_str());
  }
  if (layout_differs) {
    core->log(-1,
              "replay %s: the log was recorded with another report layout than the config's; decoding with "
              "the config's (lungar-trk dump uses the log's own)",
              settings.replay_file.c_str());
  }
  return std::make_unique<Tracker>(std::move(core), device.take());
}

}  // namespace lungar::drivers
