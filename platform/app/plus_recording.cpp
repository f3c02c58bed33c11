/// @file plus_recording.cpp
/// @brief The session's .trk turned into a PLUS sequence at its end (plus_recording.h).
#include "platform/app/plus_recording.h"

#include <filesystem>
#include <set>

#include "drivers/plus/plus_sequence.h"
#include "drivers/plus/plus_sequence_writer.h"

namespace lungar::platform {

std::string tracker_record_path(const std::string& record_path) {
  return drivers::is_plus_sequence_path(record_path) ? record_path + ".trk" : record_path;
}

Result<std::string> finish_plus_recording(const std::string& record_path, const drivers::TrackerConfig& trackers) {
  const std::string trk = tracker_record_path(record_path);
  auto log = drivers::load_trk(trk);
  if (!log) return fail("recording: " + log.error() + " (kept)");
  int skipped = 0;
  auto seq = drivers::plus_from_trk(*log, trk, trackers, skipped);
  if (!seq) return fail("recording: " + seq.error() + "; " + trk + " kept");
  if (Status w = drivers::write_plus_sequence(record_path, *seq); !w)
    return fail("recording: " + w.error() + "; " + trk + " kept");
  std::error_code ec;
  std::filesystem::remove(trk, ec);
  std::set<std::string> tools;
  for (const drivers::PlusFrame& f : seq->frames)
    for (const drivers::PlusTransform& t : f.transforms) tools.insert(t.name());
  std::string names;
  for (const std::string& t : tools) names += (names.empty() ? "" : ", ") + t;
  return "recording: " + record_path + ": " + std::to_string(seq->frames.size()) + " frames (" + names + ")" +
         (skipped > 0 ? "; " + std::to_string(skipped) + " malformed reports left out" : "");
}

}  // namespace lungar::platform
