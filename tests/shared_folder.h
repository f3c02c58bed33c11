/// @file shared_folder.h
/// @brief Test helper: a folder made once and shared by the test processes of one build tree, for what several
/// tests only read and is slow to make (a classroom's keys: some openssl runs, 2.7 s under the sanitizers; a
/// recorded class: an instructor run for seconds). ctest runs every test in a process of its own, so a suite's
/// SetUpTestSuite made it again for each of its tests.
///
/// The folder lives under the build tree's `test-cache/`, named by `name` and by the size and modification time of
/// each file in `made_by` (the programs that make it: a rebuilt one makes it afresh). It is made under a name of
/// this process's own and renamed into place once whole, with a `whole` marker written last, so a process killed
/// while making it leaves nothing another process takes as made. A folder older than `max_age` is made again
/// (certificates expire).
#pragma once

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace lungar::testing {

/// The shared folder for `name`, made by `make` (which fills the folder it is given; false or an exception: no
/// folder, and the error is `make`'s to report) when it is not there whole. Empty on failure.
inline std::filesystem::path shared_folder(const std::string& name, const std::vector<std::filesystem::path>& made_by,
                                           const std::function<bool(const std::filesystem::path&)>& make,
                                           std::chrono::hours max_age = std::chrono::hours(24 * 7)) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::string key = name;
  for (const fs::path& p : made_by) {
    const auto size = fs::file_size(p, ec);
    const auto mtime = fs::last_write_time(p, ec).time_since_epoch().count();
    if (ec) return {};
    key += "-" + std::to_string(size) + "-" + std::to_string(static_cast<long long>(mtime));
  }
  const fs::path root = fs::path(LUNGAR_BINARY_DIR) / "test-cache";
  const fs::path dir = root / key;
  const auto whole = fs::last_write_time(dir / "whole", ec);
  if (!ec && fs::file_time_type::clock::now() - whole < max_age) return dir;
  fs::create_directories(root, ec);
  const fs::path mine = root / (key + "." + std::to_string(::getpid()) + ".part");
  fs::remove_all(mine, ec);
  fs::create_directories(mine, ec);
  if (ec || !make(mine)) {
    fs::remove_all(mine, ec);
    return {};
  }
  std::ofstream(mine / "whole") << "made whole by process " << ::getpid() << "\n";
  // One another process made meanwhile is as good as ours (and may be in use): only a stale one is replaced.
  const auto theirs = fs::last_write_time(dir / "whole", ec);
  if (ec || fs::file_time_type::clock::now() - theirs >= max_age) {
    fs::remove_all(dir, ec);
    fs::rename(mine, dir, ec);
  }
  fs::remove_all(mine, ec);
  return fs::exists(dir / "whole") ? dir : fs::path();
}

}  // namespace lungar::testing
