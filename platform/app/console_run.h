/// @file console_run.h
/// @brief The instructor's console for a run: `--console [ADDR:]PORT` (or [console] listen) read, the server started
///        on the class control, and its counts in the stats JSON.
/// @ingroup platform
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <nlohmann/json_fwd.hpp>

#include "config/base/result.h"
#include "platform/app/settings.h"

namespace lungar::console {
class ConsoleHandler;
class ConsoleServer;
}  // namespace lungar::console

namespace lungar::platform {

namespace sync {
class ClassControl;
class ClassScenario;
}
namespace record {
class SessionRecorder;
}

struct ListenAddress {
  std::string address = "0.0.0.0";  ///< every interface: the classroom's network
  std::uint16_t port = 0;
};

/// "8443", "127.0.0.1:8443", "[::1]:8443" -> the address and port (0: any free one); the error says what was
/// expected.
Result<ListenAddress> parse_listen(const std::string& text);

/// The console's folder: [console] keys, else `console` beside [sync] security's station folder; an error when
/// neither is there.
Result<std::string> console_keys_dir(const Settings& s);

/// The scenarios the console offers, from [console] scenarios (an error when that is not a folder) or the shipped
/// ones. A file that does not load (or does not build) is one line in `log` and left out: the others are offered.
Result<std::vector<sync::ClassScenario>> console_scenarios(const Settings& s,
                                                           const std::function<void(const std::string&)>& log);

/// The console server on `handler` at `listen` with the keys of `keys_dir` (DIR/console of `lungar
/// classroom-keys`); `log` gets "console: URL (logins: DIR/logins)" once it listens, and the server's lines. Shared by
/// a live class (ConsoleRun) and a replay (`lungar replay --console`). `handler` must outlive the server.
Result<std::unique_ptr<console::ConsoleServer>> serve_console(const ListenAddress& listen, const std::string& keys_dir,
                                                              console::ConsoleHandler& handler,
                                                              std::function<void(const std::string&)> log);

/// A console server's `console_*` keys for the stats JSON: where it was served, the requests, logins and those
/// refused.
void add_console_stats(const console::ConsoleServer& server, nlohmann::json& stats);

/// The console served while it lives; stopped (its thread joined) when it goes, before the class control. With a
/// session record, the console's actions go into it, and each trainee's status once a second.
class ConsoleRun {
 public:
  static Result<std::unique_ptr<ConsoleRun>> start(const Settings& s, std::shared_ptr<sync::ClassControl> control,
                                                   std::shared_ptr<record::SessionRecorder> recorder,
                                                   std::function<void(const std::string&)> log);
  ~ConsoleRun();
  ConsoleRun(const ConsoleRun&) = delete;
  ConsoleRun& operator=(const ConsoleRun&) = delete;
  /// `console_*` keys: where it was served, the requests, logins and those refused.
  void add_stats(nlohmann::json& stats) const;

 private:
  ConsoleRun() = default;
  /// The statuses' thread: each trainee's status into the record once a second, until stopped.
  void record_stations();

  std::shared_ptr<sync::ClassControl> control_;
  std::shared_ptr<record::SessionRecorder> recorder_;
  std::unique_ptr<console::ConsoleServer> server_;
  std::mutex stop_mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread stations_;
};

}  // namespace lungar::platform
