/// @file console_handler.h
/// @brief What the instructor's console server asks of the class it serves: the live view as JSON, and the
///        control requests a logged-in instructor makes. The server (console_server.h) owns HTTPS, WebSocket,
///        logins, roles, CSRF and replay checks; the handler (the class control) owns what a request does.
/// @ingroup platform
///
/// Both calls come on the server's thread, never on the frame loop's: a handler hands the frame what it needs
/// through a queue or a mailbox, so the frame never waits for the console.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace lungar::console {

/// A console login's role: an observer watches; an instructor also controls the class.
enum class Role { Observer, Instructor };

/// Who made a request (the login's name and role), for the session record.
struct ConsoleUser {
  std::string name;
  Role role = Role::Observer;
};

/// A control request's answer: `status` 200 with what was done (`body`), or 400/409 with `body` {"error": one
/// line saying what is wrong and what was expected}.
struct ControlReply {
  int status = 200;
  nlohmann::json body = nlohmann::json::object();
};

class ConsoleHandler {
 public:
  virtual ~ConsoleHandler() = default;
  /// The live view as JSON text (stations, breath, orientation, pathologies, events): for GET /api/state and each
  /// WebSocket push.
  virtual std::string snapshot_json() = 0;
  /// A request from a logged-in instructor, after the server checked its login, role, CSRF token and nonce.
  virtual ControlReply control(const ConsoleUser& user, const nlohmann::json& request) = 0;
  /// The session's timeline as CSV (GET /api/timeline.csv): a header line, then one line per event.
  virtual std::string timeline_csv() = 0;
  /// A request the server refused (status, and one line saying who, what and why), for the record.
  virtual void refused(int status, const std::string& line) = 0;
};

}  // namespace lungar::console
