/// @file trk_writer.cpp
/// @brief POSIX writes for .trk logs: temp-then-rename for the header or whole file, one write() per record.
#include "drivers/trk/trk_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "config/base/atomic_file.h"
#include "config/base/crc32.h"

namespace lungar::drivers {

namespace {

void put_le(std::string& out, std::uint64_t v, int bytes) {
  for (int k = 0; k < bytes; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}

void put_le(std::uint8_t* p, std::uint64_t v, int bytes) {
  for (int k = 0; k < bytes; ++k) p[k] = static_cast<std::uint8_t>((v >> (8 * k)) & 0xFF);
}

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace

std::string encode_trk_header(const TrkHeader& h) {
  std::string out(kTrkMagic, 8);
  put_le(out, kTrkVersion, 4);
  put_le(out, h.description.size(), 4);
  out += h.description;
  put_le(out, h.layout_toml.size(), 4);
  out += h.layout_toml;
  const std::uint32_t crc = crc32(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(out.data()), out.size()));
  put_le(out, crc, 4);
  return out;
}

TrkWriter::~TrkWriter() {
  if (fd_ >= 0) {
    ::close(fd_);
    if (mode_ == Mode::Atomic) ::unlink(temp_path_.c_str());  // never committed: leave nothing half-written
  }
}

Status TrkWriter::fail(const std::string& what) const {
  return lungar::fail(path_ + ": " + what + (errno ? std::string(": ") + std::strerror(errno) : std::string()));
}

Status TrkWriter::open(const std::string& path, const TrkHeader& header, Mode mode) {
  path_ = path;
  mode_ = mode;
  errno = 0;
  if (header.description.size() > kTrkMaxText || header.layout_toml.size() > kTrkMaxText) {
    return fail("cannot write the tracker log: header texts longer than 1 MiB");
  }
  const int fd = create_partial_file(path, temp_path_);
  if (fd < 0) return fail("cannot create the tracker log");
  const std::string bytes = encode_trk_header(header);
  if (!write_all(fd, bytes.data(), bytes.size())) {
    ::close(fd);
    ::unlink(temp_path_.c_str());
    return fail("cannot write the tracker log's header");
  }
  if (mode == Mode::Atomic) {
    fd_ = fd;
    return ok();
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0 || ::rename(temp_path_.c_str(), path.c_str()) != 0) {
    ::unlink(temp_path_.c_str());
    return fail("cannot put the tracker log in place");
  }
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) return fail("cannot reopen the tracker log for appending");
  return ok();
}

Status TrkWriter::append(TrkSource source, std::int64_t t_arrival_ns, std::span<const std::uint8_t> report) {
  errno = 0;
  if (fd_ < 0) return fail("the tracker log is not open");
  if (report.empty() || report.size() > kTrkMaxReport) return fail("report length out of [1, 4096]");
  std::array<std::uint8_t, kTrkMaxReport + kTrkRecordOverhead> rec;
  std::uint8_t* p = rec.data();
  put_le(p, kTrkSync, 2);
  p[2] = static_cast<std::uint8_t>(source);
  p[3] = 0;
  put_le(p + 4, report.size(), 2);
  put_le(p + 6, static_cast<std::uint64_t>(t_arrival_ns), 8);
  std::memcpy(p + 14, report.data(), report.size());
  const std::size_t body = 12 + report.size();
  put_le(p + 2 + body, crc32(std::span<const std::uint8_t>(p + 2, body)), 4);
  if (!write_all(fd_, p, kTrkRecordOverhead + report.size())) return fail("cannot append a record");
  ++records_;
  return ok();
}

Status TrkWriter::commit() {
  errno = 0;
  if (fd_ < 0) return fail("the tracker log is not open");
  const int fd = fd_;
  fd_ = -1;
  if (::fsync(fd) != 0) {
    ::close(fd);
    if (mode_ == Mode::Atomic) ::unlink(temp_path_.c_str());
    return fail("cannot flush the tracker log");
  }
  if (::close(fd) != 0) {
    if (mode_ == Mode::Atomic) ::unlink(temp_path_.c_str());
    return fail("cannot close the tracker log");
  }
  if (mode_ == Mode::Atomic && ::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    ::unlink(temp_path_.c_str());
    return fail("cannot put the tracker log in place");
  }
  return ok();
}

}  // namespace lungar::drivers
