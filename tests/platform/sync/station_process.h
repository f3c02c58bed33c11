/// @file station_process.h
/// @brief Test support: a classroom station as a separate process (fork + exec), its stderr and stdout in
/// files, stopped by SIGTERM or SIGKILL when the test says, by SIGKILL when the object goes.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace lungar::testing {

class StationProcess {
 public:
  /// Starts `program` with `args`; stdout and stderr go to `log_prefix`.out and .err.
  StationProcess(const std::string& program, const std::vector<std::string>& args, const std::filesystem::path& log_prefix);
  ~StationProcess();
  StationProcess(const StationProcess&) = delete;
  StationProcess& operator=(const StationProcess&) = delete;

  /// Waits at most `timeout_s` for the exit; the exit code, or -1 when it did not end (then it is killed).
  int wait(double timeout_s);
  /// Waits at most `timeout_s` for `text` on its stderr (a log line): true when it came. Stations start slowly
  /// under load or a sanitizer, so a test waits for what it needs instead of sleeping a guessed time.
  bool wait_for(const std::string& text, double timeout_s) const;
  /// SIGKILL now: the station goes away without a word, as a crashed or unplugged PC does.
  void kill_now();
  /// SIGTERM, as a user's Ctrl-C or `systemctl stop`: the station ends its frame and writes its outputs. The exit
  /// code, as wait() gives it.
  int stop(double timeout_s);
  std::string err() const;
  std::string out() const;

 private:
  pid_t pid_ = -1;
  std::filesystem::path out_, err_;
};

}  // namespace lungar::testing
