/// @file trk_writer.h
/// @brief Writes .trk logs: as a crash-tolerant append log (recording), or atomically (cut, synth).
/// @ingroup drivers
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "config/base/result.h"
#include "drivers/trk/trk_format.h"

namespace lungar::drivers {

class TrkWriter {
 public:
  enum class Mode {
    /// The header lands under the final name at once (written beside it, then renamed); every record is one
    /// write() appended to it, so whatever is on disk after a crash reads back, short the last record.
    AppendLog,
    /// Everything goes to a partial file beside it (config/base/atomic_file.h) and becomes `path` only on
    /// commit(): no half file under the final name.
    Atomic,
  };

  TrkWriter() = default;
  ~TrkWriter();
  TrkWriter(const TrkWriter&) = delete;
  TrkWriter& operator=(const TrkWriter&) = delete;

  /// Creates the log; an error reads "FILE: what".
  Status open(const std::string& path, const TrkHeader& header, Mode mode);
  /// Appends one record; allocates nothing unless it fails (then the record is lost).
  Status append(TrkSource source, std::int64_t t_arrival_ns, std::span<const std::uint8_t> report);
  /// Atomic mode: flushes and renames into place. AppendLog: flushes and closes.
  Status commit();
  bool is_open() const { return fd_ >= 0; }
  std::uint64_t records() const { return records_; }

 private:
  Status fail(const std::string& what) const;
  int fd_ = -1;
  Mode mode_ = Mode::AppendLog;
  std::string path_, temp_path_;
  std::uint64_t records_ = 0;
};

/// The header bytes as they go to disk (magic .. CRC).
std::string encode_trk_header(const TrkHeader& header);

}  // namespace lungar::drivers
