/// @file trk_reader.h
/// @brief Parses .trk logs from memory (what the fuzz target calls) or from a file, with errors as values.
/// @ingroup drivers
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "drivers/trk/trk_format.h"

namespace lungar::drivers {

/// The header, or what is wrong with it, with the byte offset.
Result<TrkHeader> parse_trk_header(std::span<const std::uint8_t> data);

enum class TrkStatus { Ok, End, TruncatedTail, Corrupt };

struct TrkNext {
  TrkStatus status = TrkStatus::End;
  TrkRecord record;
  std::size_t next_offset = 0;
  std::string error;  ///< for Corrupt: what, at which offset
};
/// The record at `offset` (just after the header for the first). End at the end of the data; TruncatedTail
/// when the data stops inside a record (a crash while writing); Corrupt for a bad sync, length or CRC.
TrkNext read_trk_record(std::span<const std::uint8_t> data, std::size_t offset);

/// A whole log in memory. Move-only: the records' spans point into `bytes`.
struct TrkLog {
  TrkLog() = default;
  TrkLog(TrkLog&&) = default;
  TrkLog& operator=(TrkLog&&) = default;
  TrkLog(const TrkLog&) = delete;
  TrkLog& operator=(const TrkLog&) = delete;
  TrkHeader header;
  std::vector<std::uint8_t> bytes;        ///< the file
  std::vector<TrkRecord> records;         ///< spans into `bytes`
  bool truncated_tail = false;            ///< the last record was incomplete and is left out
};

/// Reads and checks a whole log. A corrupt record is an error ("FILE: record N: what, at byte M").
Result<TrkLog> load_trk(const std::string& path);
/// The same from bytes; `name` stands for the file in messages.
Result<TrkLog> parse_trk(std::vector<std::uint8_t> bytes, const std::string& name);

}  // namespace lungar::drivers
