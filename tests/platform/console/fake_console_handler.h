/// @file fake_console_handler.h
/// @brief Test helper: a ConsoleHandler that records every call (from the server's thread) and answers as told.
#pragma once

#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "platform/console/console_handler.h"

namespace lungar::testing {

class FakeConsoleHandler : public console::ConsoleHandler {
 public:
  struct Control {
    console::ConsoleUser user;
    nlohmann::json request;
  };

  std::string snapshot_json() override {
    std::lock_guard lock(mutex_);
    ++snapshots_;
    return snapshot_;
  }
  console::ControlReply control(const console::ConsoleUser& user, const nlohmann::json& request) override {
    std::lock_guard lock(mutex_);
    controls_.push_back({user, request});
    return reply_;
  }
  std::string timeline_csv() override { return "t_s,kind,text,user\n5.0,marker,apex,instructor\n"; }
  void refused(int status, const std::string& line) override {
    std::lock_guard lock(mutex_);
    refusals_.emplace_back(status, line);
  }

  void set_snapshot(std::string s) {
    std::lock_guard lock(mutex_);
    snapshot_ = std::move(s);
  }
  void set_reply(console::ControlReply r) {
    std::lock_guard lock(mutex_);
    reply_ = std::move(r);
  }
  std::vector<Control> controls() const {
    std::lock_guard lock(mutex_);
    return controls_;
  }
  std::vector<std::pair<int, std::string>> refusals() const {
    std::lock_guard lock(mutex_);
    return refusals_;
  }
  int snapshots() const {
    std::lock_guard lock(mutex_);
    return snapshots_;
  }

 private:
  mutable std::mutex mutex_;
  std::string snapshot_ = R"({"station":"teacher","t_s":1.5,"breath":{"state":"breathing"}})";
  console::ControlReply reply_{200, {{"done", "ok"}}};
  std::vector<Control> controls_;
  std::vector<std::pair<int, std::string>> refusals_;
  int snapshots_ = 0;
};

}  // namespace lungar::testing
