/// @file session_recorder.h
/// @brief Writes a session record (session_record.h) while the class runs: each frame from the frame loop, the
///        pathology timeline, the events and console actions and the stations' status from the console's threads,
///        all by a writer thread of its own into one append-only file.
/// @ingroup platform
///
/// Crash-safe: every line is `CRC32HEX JSON\n` and is written whole or not at all as far as a reader goes (a torn
/// last line is cut off); the writer hands its lines to the kernel at least every kFlushS (a SIGKILL of the station
/// loses what the frame handed over since, a fraction of a second) and fsyncs at least every kSyncS (a power cut
/// loses at most that). The file is created exclusively: a record is never overwritten.
///
/// Threads. on_frame() runs on the frame loop: it copies the frame into a fixed ring (SpscRing), no lock, no
/// allocation; a full ring drops the frame and counts it (the end line says how many). The note_* calls come from any
/// other thread, may allocate, and go through a queue under a mutex.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/base/result.h"
#include "config/base/spsc_ring.h"
#include "platform/record/session_record.h"
#include "platform/runtime/frame_listener.h"
#include "platform/runtime/lung_course.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::platform::record {

class SessionRecorder final : public FrameListener {
 public:
  static constexpr double kFlushS = 0.05;          ///< lines go to the kernel at least this often
  static constexpr double kSyncS = 1.0;            ///< and to the disk (fdatasync) at least this often
  static constexpr std::size_t kRingFrames = 512;  ///< frames the writer may fall behind by (2 s at 250 Hz)
  static constexpr std::size_t kLabelChars = 256;  ///< a frame's pathologies, longer ones cut there

  /// Creates `path` (never over an existing file), writes and syncs the header, and starts the writer. `t0_ns`: the
  /// session's time zero (monotonic), which every line's `s` counts from; `course`: the lungs' course whose
  /// pathologies_now() each frame keeps (null: none); `log`: a write error, said once. An error names the path.
  static Result<std::shared_ptr<SessionRecorder>> create(const std::string& path, const SessionHeader& header,
                                                         std::int64_t t0_ns,
                                                         std::shared_ptr<const LungCourse> course = nullptr,
                                                         std::function<void(const std::string&)> log = nullptr);
  /// close().
  ~SessionRecorder() override;
  SessionRecorder(const SessionRecorder&) = delete;
  SessionRecorder& operator=(const SessionRecorder&) = delete;

  /// The frame loop: the frame into the ring. Allocates nothing, never waits.
  void on_frame(const FrameState& state) override;
  /// The pathology timeline as it stands from now on (the start's, then each time it changes).
  void note_timeline(const sim::PathologyTimeline& timeline);
  /// An event of the class or a console action at breathing time `t_s`: its kind ("pathology add", "marker"...),
  /// who made it (a console login; empty: the class itself) and its text.
  void note_event(double t_s, std::string kind, std::string user, std::string text);
  /// Each station's status now (name, in step or lost, breath offset, pose age, frames per second...), about once a
  /// second.
  void note_stations(nlohmann::json stations);

  /// Writes what is queued and the end line, syncs and closes the file, and stops the writer. The first error the
  /// writer met, if any (the record then stops there). Later calls return the same; later notes are dropped.
  Status close();

  const std::string& path() const { return path_; }
  /// Frames dropped because the writer fell a whole ring behind.
  std::uint64_t dropped_frames() const { return ring_->dropped(); }
  /// Seconds since the session's time zero, as every line's `s` counts them.
  double session_s(std::int64_t now_ns) const;

 private:
  /// A frame as the ring carries it: fixed size, copied without allocating.
  struct FrameItem {
    std::int64_t index = 0;
    std::int64_t now_ns = 0;
    sim::BreathingSample breath;
    std::array<double, 2> lung_dv_ml{};
    std::array<double, 3> patient_mm{}, lung_origin_mm{};
    std::array<double, 4> patient_wxyz{}, lung_wxyz{};
    std::uint32_t patient_flags = 0;
    bool has_pathologies = false;
    char pathologies[kLabelChars] = {};
  };

  SessionRecorder(std::string path, int fd, std::int64_t t0_ns, std::shared_ptr<const LungCourse> course,
                  std::function<void(const std::string&)> log);
  void queue(std::string json);
  void write_loop();
  /// Frames and notes queued so far as lines into `out`.
  void take_lines(std::string& out);
  void frame_line(const FrameItem& f, std::string& out);
  /// `bytes` to the file, every one (EINTR, short writes); false and said once on an error.
  bool write_all(const std::string& bytes);

  const std::string path_;
  int fd_ = -1;
  const std::int64_t t0_ns_;
  std::shared_ptr<const LungCourse> course_;
  std::function<void(const std::string&)> log_;
  std::unique_ptr<SpscRing<FrameItem, kRingFrames>> ring_;  ///< on the heap: half a megabyte
  std::int64_t frames_ = 0;                                 ///< the frame loop's count

  std::mutex mutex_;  ///< guards notes_, closing_, error_
  std::condition_variable wake_;
  std::vector<std::string> notes_;  ///< the note_* lines' JSON, in the order noted
  bool closing_ = false;
  std::string error_;

  std::string last_label_;  ///< the writer's: the pathologies of the last frame written
  std::int64_t frames_written_ = 0;
  std::thread writer_;
  std::once_flag closed_;
  Status close_status_;
};

}  // namespace lungar::platform::record
