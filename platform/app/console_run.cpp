/// @file console_run.cpp
/// @brief [console] -> the server on the class control.
#include "platform/app/console_run.h"

#include <algorithm>
#include <charconv>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "config/scenario_load.h"
#include "platform/app/scenario_adapter.h"
#include "platform/app/shipped_data.h"
#include "platform/console/console_server.h"
#include "platform/record/session_recorder.h"
#include "platform/sync/class_control.h"

namespace lungar::platform {

Result<ListenAddress> parse_listen(const std::string& text) {
  const std::string expected = "expected [ADDR:]PORT (e.g. 8443, 127.0.0.1:8443 or [::1]:8443), not '" + text + "'";
  ListenAddress out;
  std::string port = text;
  if (const auto colon = text.rfind(':'); colon != std::string::npos) {
    out.address = text.substr(0, colon);
    port = text.substr(colon + 1);
    if (out.address.size() >= 2 && out.address.front() == '[' && out.address.back() == ']')
      out.address = out.address.substr(1, out.address.size() - 2);
    if (out.address.empty()) return fail(expected);
  }
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size() || value > 65535)
    return fail(expected + ": the port is 0 (any free one, said in the log) to 65535");
  out.port = static_cast<std::uint16_t>(value);
  return out;
}

Result<std::string> console_keys_dir(const Settings& s) {
  if (!s.console.keys.empty()) return s.console.keys;
  if (!s.sync.security.empty()) {
    const auto beside = std::filesystem::path(s.sync.security).lexically_normal().parent_path() / "console";
    if (std::filesystem::is_directory(beside)) return beside.string();
  }
  return fail(
      "console.keys: expected the console's folder of `lungar classroom-keys` (DIR/console), which holds "
      "its certificate and logins; none given, and none beside sync.security");
}

namespace {

/// The shipped scenarios' folder (shipped_data.h); empty when none is there.
std::filesystem::path shipped_scenarios() {
  std::error_code ec;
  for (const std::filesystem::path& p : shipped_data_places("scenarios", "config/scenarios"))
    if (std::filesystem::is_directory(p, ec)) return p.lexically_normal();
  return {};
}

}  // namespace

Result<std::vector<sync::ClassScenario>> console_scenarios(const Settings& s,
                                                           const std::function<void(const std::string&)>& log) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!s.console.scenarios.empty() && !fs::is_directory(s.console.scenarios, ec))
    return fail("console.scenarios: expected a folder of scenario TOML files; '" + s.console.scenarios +
                "' is not one");
  const fs::path dir = s.console.scenarios.empty() ? shipped_scenarios() : fs::path(s.console.scenarios);
  std::vector<fs::path> files;
  if (!dir.empty())
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<sync::ClassScenario> out;
  for (const fs::path& f : files) {
    auto made = [&]() -> Result<sync::ClassScenario> {
      auto scenario = config::load_scenario(f.string(), s.breathing);
      if (!scenario) return Error{scenario.error()};
      auto script = make_breathing_script(*scenario);
      if (!script) return Error{script.error()};
      return sync::ClassScenario::create(*scenario, *script);
    }();
    if (made)
      out.push_back(made.take());
    else if (log)
      log("console: scenario left out: " + made.error());
  }
  if (log)
    log("console: " + std::to_string(out.size()) + " scenarios from " + (dir.empty() ? "nowhere" : dir.string()));
  return out;
}

Result<std::unique_ptr<console::ConsoleServer>> serve_console(const ListenAddress& listen, const std::string& keys_dir,
                                                              console::ConsoleHandler& handler,
                                                              std::function<void(const std::string&)> log) {
  auto server = console::ConsoleServer::start({listen.address, listen.port, keys_dir}, handler, log);
  if (!server) return server.with_context("console: ");
  if (log) log("console: " + (*server)->url() + " (logins: " + keys_dir + "/logins)");
  return server;
}

void add_console_stats(const console::ConsoleServer& server, nlohmann::json& stats) {
  const console::ConsoleCounts c = server.counts();
  stats["console_url"] = server.url();
  stats["console_requests"] = c.requests;
  stats["console_logins"] = c.logins;
  stats["console_logins_refused"] = c.logins_refused;
  stats["console_refused"] = c.refused_401 + c.refused_403 + c.refused_other;
  stats["console_refused_401"] = c.refused_401;
  stats["console_refused_403"] = c.refused_403;
  stats["console_websockets"] = c.websockets;
}

Result<std::unique_ptr<ConsoleRun>> ConsoleRun::start(const Settings& s, std::shared_ptr<sync::ClassControl> control,
                                                      std::shared_ptr<record::SessionRecorder> recorder,
                                                      std::function<void(const std::string&)> log) {
  auto listen = parse_listen(s.console.listen);
  if (!listen) return listen.with_context("console.listen (--console): ");
  auto keys = console_keys_dir(s);
  if (!keys) return Error{keys.error()};
  auto scenarios = console_scenarios(s, log);
  if (!scenarios) return Error{scenarios.error()};
  std::unique_ptr<ConsoleRun> run(new ConsoleRun());
  run->control_ = std::move(control);
  run->control_->scenarios = scenarios.take();
  if (recorder) {  // before the server starts: its thread makes the events
    run->recorder_ = std::move(recorder);
    run->control_->on_event = [r = run->recorder_](const sync::ClassEvent& e) {
      r->note_event(e.t_s, e.kind, e.user, e.text);
    };
    run->control_->on_timeline = [r = run->recorder_](const sim::PathologyTimeline& t) { r->note_timeline(t); };
    run->stations_ = std::thread([r = run.get()] { r->record_stations(); });
  }
  auto server = serve_console(*listen, *keys, *run->control_, std::move(log));
  if (!server) return Error{server.error()};
  run->server_ = server.take();
  return run;
}

ConsoleRun::~ConsoleRun() {
  server_.reset();  // the server's thread calls the control: it stops first
  {
    std::lock_guard lock(stop_mutex_);
    stopping_ = true;
  }
  stop_.notify_all();
  if (stations_.joinable()) stations_.join();
}

void ConsoleRun::record_stations() {
  std::unique_lock lock(stop_mutex_);
  while (!stop_.wait_for(lock, std::chrono::seconds(1), [this] { return stopping_; }))
    recorder_->note_stations(control_->stations_json());
}

void ConsoleRun::add_stats(nlohmann::json& stats) const { add_console_stats(*server_, stats); }

}  // namespace lungar::platform
