/// @file session_recorder.cpp
/// @brief The frame's side (a copy into the ring), the notes' queue, and the writer thread's lines.
#include "platform/record/session_recorder.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "config/base/clock.h"

namespace lungar::platform::record {

namespace {

/// `x` as JSON: printed with `format`, or null when it is not a number (a lung the asset lacks).
void append_number(std::string& out, const char* format, double x) {
  if (!std::isfinite(x)) {
    out += "null";
    return;
  }
  char text[48];
  std::snprintf(text, sizeof text, format, x);
  out += text;
}

template <std::size_t N>
void append_numbers(std::string& out, const char* key, const char* format, const std::array<double, N>& xs) {
  out += ",\"";
  out += key;
  out += "\":[";
  for (std::size_t k = 0; k < N; ++k) {
    if (k > 0) out += ',';
    append_number(out, format, xs[k]);
  }
  out += ']';
}

void append_field(std::string& out, const char* key, const char* format, double x) {
  out += ",\"";
  out += key;
  out += "\":";
  append_number(out, format, x);
}

/// `text` as a JSON string (quotes, backslashes and control characters escaped; UTF-8 passed through).
void append_json_string(std::string& out, const char* text) {
  out += '"';
  for (const char* c = text; *c != '\0'; ++c) {
    const auto u = static_cast<unsigned char>(*c);
    if (*c == '"' || *c == '\\') {
      out += '\\';
      out += *c;
    } else if (u < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", u);
      out += escaped;
    } else {
      out += *c;
    }
  }
  out += '"';
}

/// One JSON text on one line; text that is not UTF-8 (a login typed oddly) is replaced, never thrown on.
template <class Json>
std::string one_line(const Json& j) {
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace

Result<std::shared_ptr<SessionRecorder>> SessionRecorder::create(const std::string& path, const SessionHeader& header,
                                                                 std::int64_t t0_ns,
                                                                 std::shared_ptr<const LungCourse> course,
                                                                 std::function<void(const std::string&)> log) {
  // O_EXCL: a record is never overwritten, not even one another station is writing.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) {
    const std::string why = std::strerror(errno);
    return fail(path + ": cannot create the session record: " + why +
                (errno == EEXIST ? " (a record is never overwritten: give a new file or a folder)" : ""));
  }
  std::shared_ptr<SessionRecorder> r(new SessionRecorder(path, fd, t0_ns, std::move(course), std::move(log)));
  // The header is on the disk before the first frame: a record cut at once is still one, of no frame.
  if (!r->write_all(session_line(one_line(header_json(header)))) || ::fdatasync(fd) != 0) {
    const std::string why = r->error_.empty() ? std::strerror(errno) : r->error_;
    ::close(fd);
    r->fd_ = -1;
    ::unlink(path.c_str());
    return fail(path + ": cannot write the session record's header: " + why);
  }
  r->writer_ = std::thread([raw = r.get()] { raw->write_loop(); });
  return r;
}

SessionRecorder::SessionRecorder(std::string path, int fd, std::int64_t t0_ns, std::shared_ptr<const LungCourse> course,
                                 std::function<void(const std::string&)> log)
    : path_(std::move(path)),
      fd_(fd),
      t0_ns_(t0_ns),
      course_(std::move(course)),
      log_(std::move(log)),
      ring_(std::make_unique<SpscRing<FrameItem, kRingFrames>>()) {}

SessionRecorder::~SessionRecorder() { (void)close(); }

double SessionRecorder::session_s(std::int64_t now_ns) const { return seconds_between(t0_ns_, now_ns); }

void SessionRecorder::on_frame(const FrameState& state) {
  FrameItem f;
  f.index = frames_++;
  f.now_ns = state.now_ns;
  f.breath = state.breath;
  f.lung_dv_ml = state.lung_dv_ml;
  f.patient_mm = state.patient.position_mm;
  f.patient_wxyz = state.patient.orientation_wxyz;
  f.patient_flags = state.patient.flags;
  f.lung_origin_mm = {state.lung_origin_mm.x(), state.lung_origin_mm.y(), state.lung_origin_mm.z()};
  const Eigen::Quaterniond& q = state.lung_in_world;
  f.lung_wxyz = {q.w(), q.x(), q.y(), q.z()};
  if (const std::string* label = course_ ? course_->pathologies_now() : nullptr) {
    std::size_t n = std::min(label->size(), kLabelChars - 1);
    if (n < label->size()) {  // cut before a character, not inside one: the line stays UTF-8
      while (n > 0 && (static_cast<unsigned char>((*label)[n]) & 0xC0) == 0x80) --n;
    }
    std::memcpy(f.pathologies, label->data(), n);
    f.pathologies[n] = '\0';
    f.has_pathologies = true;
  }
  ring_->push(f);
}

void SessionRecorder::note_timeline(const sim::PathologyTimeline& timeline) {
  queue(one_line(timeline_json(session_s(monotonic_ns()), timeline)));
}

void SessionRecorder::note_event(double t_s, std::string kind, std::string user, std::string text) {
  nlohmann::ordered_json j;
  j["type"] = "event";
  j["s"] = session_s(monotonic_ns());
  j["t_s"] = std::isfinite(t_s) ? t_s : 0.0;
  j["kind"] = std::move(kind);
  j["user"] = std::move(user);
  j["text"] = std::move(text);
  queue(one_line(j));
}

void SessionRecorder::note_stations(nlohmann::json stations) {
  nlohmann::ordered_json j;
  j["type"] = "stations";
  j["s"] = session_s(monotonic_ns());
  j["stations"] = std::move(stations);
  queue(one_line(j));
}

void SessionRecorder::queue(std::string json) {
  std::lock_guard lock(mutex_);
  if (closing_) return;
  notes_.push_back(std::move(json));
}

void SessionRecorder::write_loop() {
  std::string lines;
  std::int64_t synced_ns = monotonic_ns();
  bool closing = false;
  while (!closing) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, std::chrono::duration<double>(kFlushS), [&] { return closing_; });
      closing = closing_;
    }
    lines.clear();
    take_lines(lines);
    if (!lines.empty()) write_all(lines);
    if (const std::int64_t now = monotonic_ns(); seconds_between(synced_ns, now) >= kSyncS) {
      ::fdatasync(fd_);
      synced_ns = now;
    }
  }
  // The frames handed over before close() are taken above; the end line says the record is whole.
  nlohmann::ordered_json end;
  end["type"] = "end";
  end["s"] = session_s(monotonic_ns());
  end["frames"] = frames_written_;
  end["dropped_frames"] = ring_->dropped();
  write_all(session_line(one_line(end)));
  if (::fdatasync(fd_) != 0 || ::close(fd_) != 0) {
    std::lock_guard lock(mutex_);
    if (error_.empty()) error_ = path_ + ": cannot sync the session record: " + std::strerror(errno);
  }
  fd_ = -1;
}

void SessionRecorder::take_lines(std::string& out) {
  std::vector<std::string> notes;
  {
    std::lock_guard lock(mutex_);
    notes.swap(notes_);
  }
  for (const std::string& json : notes) out += session_line(json);
  ring_->drain([&](const FrameItem& f) { frame_line(f, out); });
}

void SessionRecorder::frame_line(const FrameItem& f, std::string& out) {
  std::string json;
  json.reserve(640);
  json += "{\"type\":\"frame\",\"i\":";
  json += std::to_string(f.index);
  append_field(json, "s", "%.6f", session_s(f.now_ns));
  append_field(json, "t_s", "%.6f", f.breath.t_s);
  append_field(json, "dv_ml", "%.6f", f.breath.dv_ml);
  append_numbers(json, "lung_dv_ml", "%.6f", f.lung_dv_ml);
  append_field(json, "v_ml", "%.6f", f.breath.v_ml);
  append_field(json, "v_frc_ml", "%.6f", f.breath.v_frc_ml);
  append_field(json, "p_cmh2o", "%.6f", f.breath.p_cmh2o);
  append_field(json, "p_applied_cmh2o", "%.6f", f.breath.p_applied_cmh2o);
  json += ",\"phase\":\"";
  json += sim::to_string(f.breath.phase);
  json += "\",\"breath\":";
  json += std::to_string(f.breath.breath);
  append_numbers(json, "source_lung_dv_ml", "%.6f", f.breath.lung_dv_ml);
  append_numbers(json, "patient_mm", "%.4f", f.patient_mm);
  append_numbers(json, "patient_wxyz", "%.9f", f.patient_wxyz);
  json += ",\"patient_flags\":";
  json += std::to_string(f.patient_flags);
  append_numbers(json, "lung_origin_mm", "%.4f", f.lung_origin_mm);
  append_numbers(json, "lung_in_world_wxyz", "%.9f", f.lung_wxyz);
  // The pathologies only when they change (and on the first frame): the reader carries them forward.
  if (f.has_pathologies && (frames_written_ == 0 || last_label_ != f.pathologies)) {
    json += ",\"pathologies\":";
    append_json_string(json, f.pathologies);
    last_label_ = f.pathologies;
  }
  json += '}';
  out += session_line(json);
  ++frames_written_;
}

bool SessionRecorder::write_all(const std::string& bytes) {
  {
    std::lock_guard lock(mutex_);
    if (!error_.empty()) return false;  // the record stops at its first failed write: no line after a hole
  }
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = path_ + ": cannot write the session record: " + std::strerror(errno) +
                              "; it stops here (everything before stands)";
      {
        std::lock_guard lock(mutex_);
        error_ = why;
      }
      if (log_) log_("error: " + why);
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

Status SessionRecorder::close() {
  std::call_once(closed_, [this] {
    {
      std::lock_guard lock(mutex_);
      closing_ = true;
    }
    wake_.notify_all();
    if (writer_.joinable()) writer_.join();
    std::lock_guard lock(mutex_);
    if (!error_.empty()) close_status_ = fail(error_);
  });
  return close_status_;
}

}  // namespace lungar::platform::record
