/// @file trk_reader.cpp
/// @brief Bounds-checked parsing of .trk headers and records; nothing here trusts a length it has not checked.
#include "drivers/trk/trk_reader.h"

#include <cstring>
#include <fstream>
#include <iterator>

#include "config/base/crc32.h"

namespace lungar::drivers {

namespace {

std::uint64_t get_le(const std::uint8_t* p, int bytes) {
  std::uint64_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | p[k];
  return v;
}

}  // namespace

const char* to_string(TrkSource s) {
  switch (s) {
    case TrkSource::Hid: return "hid";
    case TrkSource::Mock: return "mock";
    case TrkSource::Synth: return "synth";
    case TrkSource::Replay: return "replay";
    case TrkSource::Igtl: return "igtl";
  }
  return "?";
}

std::string TrkHeader::field(const std::string& key) const {
  std::size_t pos = 0;
  while (pos < description.size()) {
    std::size_t end = description.find('\n', pos);
    if (end == std::string::npos) end = description.size();
    const std::string line = description.substr(pos, end - pos);
    if (line.size() > key.size() && line.compare(0, key.size(), key) == 0 && line[key.size()] == '=') {
      return line.substr(key.size() + 1);
    }
    pos = end + 1;
  }
  return {};
}

Result<TrkHeader> parse_trk_header(std::span<const std::uint8_t> d) {
  auto fail = [](const std::string& what, std::size_t at) {
    return lungar::fail(what + ", at byte " + std::to_string(at));
  };
  if (d.size() < 16) return fail("expected a .trk header (magic, version, lengths), got only " + std::to_string(d.size()) + " bytes", 0);
  if (std::memcmp(d.data(), kTrkMagic, 8) != 0) return fail("expected the magic \"LUNGATRK\": not a .trk log", 0);
  TrkHeader h;
  h.version = static_cast<std::uint32_t>(get_le(d.data() + 8, 4));
  if (h.version != kTrkVersion) {
    return fail("expected version " + std::to_string(kTrkVersion) + ", got " + std::to_string(h.version), 8);
  }
  std::size_t off = 12;
  std::string* texts[] = {&h.description, &h.layout_toml};
  for (std::string* text : texts) {
    if (d.size() - off < 4) return fail("expected a text length, got the end of the file", off);
    const std::uint64_t n = get_le(d.data() + off, 4);
    off += 4;
    if (n > kTrkMaxText || n > d.size() - off) {
      return fail("expected a text of at most " + std::to_string(std::min<std::size_t>(kTrkMaxText, d.size() - off)) +
                      " bytes, got a length of " + std::to_string(n),
                  off - 4);
    }
    text->assign(reinterpret_cast<const char*>(d.data() + off), static_cast<std::size_t>(n));
    off += static_cast<std::size_t>(n);
  }
  if (d.size() - off < 4) return fail("expected the header CRC, got the end of the file", off);
  const std::uint32_t stored = static_cast<std::uint32_t>(get_le(d.data() + off, 4));
  const std::uint32_t actual = crc32(d.first(off));
  if (stored != actual) return fail("header CRC mismatch: the header is damaged", off);
  h.size = off + 4;
  return h;
}

TrkNext read_trk_record(std::span<const std::uint8_t> d, std::size_t off) {
  TrkNext n;
  n.next_offset = off;
  if (off >= d.size()) {
    n.status = TrkStatus::End;
    return n;
  }
  const std::size_t left = d.size() - off;
  const std::uint8_t* p = d.data() + off;
  if (left < 2 || get_le(p, 2) != kTrkSync) {
    if (left >= 2 || p[0] != (kTrkSync & 0xFF)) {
      n.status = TrkStatus::Corrupt;
      n.error = "expected a record sync 0x4B52, at byte " + std::to_string(off);
      return n;
    }
  }
  if (left < kTrkRecordOverhead - 4) {
    n.status = TrkStatus::TruncatedTail;
    return n;
  }
  const std::size_t len = static_cast<std::size_t>(get_le(p + 4, 2));
  if (len == 0 || len > kTrkMaxReport) {
    n.status = TrkStatus::Corrupt;
    n.error = "expected a report length in [1, " + std::to_string(kTrkMaxReport) + "], got " + std::to_string(len) +
              ", at byte " + std::to_string(off + 4);
    return n;
  }
  if (left < kTrkRecordOverhead + len) {
    n.status = TrkStatus::TruncatedTail;
    return n;
  }
  const std::size_t body = kTrkRecordOverhead - 4 - 2 + len;  // source .. report bytes
  const std::uint32_t stored = static_cast<std::uint32_t>(get_le(p + 2 + body, 4));
  if (crc32(std::span<const std::uint8_t>(p + 2, body)) != stored) {
    n.status = TrkStatus::Corrupt;
    n.error = "record CRC mismatch, at byte " + std::to_string(off);
    return n;
  }
  if (p[2] > static_cast<std::uint8_t>(TrkSource::Igtl)) {
    n.status = TrkStatus::Corrupt;
    n.error = "expected a record source 0 to 4, got " + std::to_string(p[2]) + ", at byte " + std::to_string(off + 2);
    return n;
  }
  n.status = TrkStatus::Ok;
  n.record.source = static_cast<TrkSource>(p[2]);
  n.record.t_arrival_ns = static_cast<std::int64_t>(get_le(p + 6, 8));
  n.record.report = std::span<const std::uint8_t>(p + 14, len);
  n.next_offset = off + kTrkRecordOverhead + len;
  return n;
}

Result<TrkLog> parse_trk(std::vector<std::uint8_t> bytes, const std::string& name) {
  TrkLog log;
  log.bytes = std::move(bytes);
  const std::span<const std::uint8_t> d(log.bytes);
  Result<TrkHeader> h = parse_trk_header(d);
  if (!h) return h.with_context(name + ": ");
  log.header = h.take();
  std::size_t off = log.header.size;
  for (;;) {
    TrkNext n = read_trk_record(d, off);
    if (n.status == TrkStatus::End) break;
    if (n.status == TrkStatus::TruncatedTail) {
      log.truncated_tail = true;
      break;
    }
    if (n.status == TrkStatus::Corrupt)
      return fail(name + ": record " + std::to_string(log.records.size()) + ": " + n.error);
    log.records.push_back(n.record);
    off = n.next_offset;
  }
  return log;  // the records' spans stay valid: moving a vector keeps its buffer
}

Result<TrkLog> load_trk(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path + ": cannot open the tracker log: expected a readable .trk file");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return fail(path + ": read error");
  return parse_trk(std::move(bytes), path);
}

}  // namespace lungar::drivers
