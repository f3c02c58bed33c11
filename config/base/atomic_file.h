/// @file atomic_file.h
/// @brief The one way lungar writes an output file (asset, report, stats, PNG, registration, .trk cut): whole or
/// not at all. Everything goes to a partial file beside it, "<path>.partial-XXXXXX", is flushed to disk, and is
/// renamed into place on commit(); a failure or a destructor before commit() removes the partial file, so nothing
/// half-written is ever left under the final name or beside it. Each writer's partial file has a name of its own:
/// two processes writing the same path (two stations on one PC, each saving its stats) never write into one
/// another's, and the last to commit wins whole.
/// @ingroup base
#pragma once

#include <fcntl.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <unistd.h>

#include "config/base/result.h"

namespace lungar {

/// Creates a new, empty file beside `path` for writing, named "<path>.partial-XXXXXX" with X's no other file there
/// has, readable by all (0644); its name goes to `partial`. The descriptor (close-on-exec), or -1 with errno set.
inline int create_partial_file(const std::string& path, std::string& partial) {
  partial = path + ".partial-XXXXXX";
  const int fd = ::mkostemp(partial.data(), O_CLOEXEC);
  if (fd >= 0 && ::fchmod(fd, 0644) != 0) {
    const int saved_errno = errno;
    ::close(fd);
    ::unlink(partial.c_str());
    errno = saved_errno;
    return -1;
  }
  return fd;
}

class AtomicFile {
 public:
  AtomicFile() = default;
  ~AtomicFile() { abandon(); }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Creates the parent folder if needed and a partial file beside `path` to write into.
  Status open(const std::string& path) {
    abandon();
    path_ = path;
    const std::filesystem::path p(path);
    std::error_code ec;
    if (p.has_parent_path() && !std::filesystem::exists(p.parent_path(), ec)) {
      std::filesystem::create_directories(p.parent_path(), ec);
      if (ec) return fail(path + ": cannot create its folder: " + ec.message());
    }
    const int fd = create_partial_file(path, partial_);
    if (fd < 0) return fail(path + ": cannot open for writing: " + std::strerror(errno));
    file_ = ::fdopen(fd, "wb");
    if (file_ == nullptr) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      std::remove(partial_.c_str());
      return fail(path + ": cannot open for writing: " + why);
    }
    return ok();
  }
  /// The open stream, for writers that take a FILE* (libpng).
  std::FILE* stream() const { return file_; }
  const std::string& path() const { return path_; }
  /// Appends bytes; a failure is reported by commit().
  void write(const void* data, std::size_t size) {
    if (file_ != nullptr && size > 0 && std::fwrite(data, 1, size, file_) != size) write_failed_ = true;
  }
  void write(std::string_view text) { write(text.data(), text.size()); }
  /// Flushes, syncs and renames into place.
  Status commit() {
    if (file_ == nullptr) return fail(path_ + ": not open for writing");
    const bool flushed = !write_failed_ && std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
    const int saved_errno = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!flushed || !closed) {
      std::remove(partial_.c_str());
      return fail(path_ + ": write failed (" + std::strerror(saved_errno) + "); nothing was written under this name");
    }
    if (std::rename(partial_.c_str(), path_.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      std::remove(partial_.c_str());
      return fail(path_ + ": cannot rename the finished file into place: " + why);
    }
    return ok();
  }
  /// Drops what was written (also done by the destructor).
  void abandon() {
    if (file_ == nullptr) return;
    std::fclose(file_);
    file_ = nullptr;
    std::remove(partial_.c_str());
  }

 private:
  std::FILE* file_ = nullptr;
  bool write_failed_ = false;
  std::string path_, partial_;
};

/// Whether `path` can be written as AtomicFile writes it (its folder made if missing, a partial file created and
/// removed): long work (a bake of minutes) asks first, so that an output it could never write fails at once.
inline Status check_writable(const std::string& path) {
  AtomicFile probe;
  return probe.open(path);  // the destructor removes the empty partial file
}

/// Writes `bytes` to `path` whole or not at all.
inline Status write_file_atomically(const std::string& path, std::string_view bytes) {
  AtomicFile file;
  if (Status opened = file.open(path); !opened) return opened;
  file.write(bytes);
  return file.commit();
}

}  // namespace lungar
