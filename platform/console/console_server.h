/// @file console_server.h
/// @brief The instructor's console server: the page and a JSON API over HTTPS (TLS 1.2 or newer), the live view
///        over a WebSocket, logins with roles, and every check a control request passes (session, role, CSRF
///        token, Origin, fresh nonce) before the ConsoleHandler sees it. Boost.Beast on one thread of its own; all
///        of Beast stays in console_server.cpp.
/// @ingroup platform
///
/// The API: GET / and the page's files; POST /api/login {"user","password"} -> {"user","role","csrf"}
/// and the session cookie; POST /api/logout; GET /api/state (snapshot_json); GET /api/timeline.csv; GET /api/live
/// (a WebSocket pushing snapshot_json every 100 ms); POST /api/control (an instructor's request to the handler).
/// Refused requests are counted, logged as one line and passed to ConsoleHandler::refused.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "config/base/result.h"
#include "platform/console/console_handler.h"

namespace lungar::console {

struct ConsoleOptions {
  std::string address = "0.0.0.0";
  std::uint16_t port = 8443;  ///< 0: any free port (port() says which)
  /// DIR/console of `lungar classroom-keys`: server_cert.pem, server_key.pem, logins.
  std::string keys_dir;
};

/// What the server has seen since it started. A request refused is counted once, under its status (401, 403, or
/// other: 404 on /api/, 405, 413, 429, 431, 503); a refused login is also counted in logins_refused.
struct ConsoleCounts {
  std::uint64_t requests = 0;  ///< HTTP requests read (a WebSocket's upgrade included)
  std::uint64_t logins = 0;
  std::uint64_t logins_refused = 0;  ///< wrong name or password, or throttled
  std::uint64_t refused_401 = 0;
  std::uint64_t refused_403 = 0;
  std::uint64_t refused_other = 0;
  std::uint64_t websockets = 0;  ///< WebSockets opened
};

class ConsoleServer {
 public:
  /// Listens on options.address:port with the keys of options.keys_dir; `log` gets one line per login, logout and
  /// refusal (from the server's thread). One error line naming the file or the address when it cannot start.
  /// `handler` must outlive the server.
  static Result<std::unique_ptr<ConsoleServer>> start(const ConsoleOptions& options, ConsoleHandler& handler,
                                                      std::function<void(const std::string&)> log);
  /// Stops the server (open connections are dropped) and joins its thread.
  ~ConsoleServer();
  ConsoleServer(const ConsoleServer&) = delete;
  ConsoleServer& operator=(const ConsoleServer&) = delete;

  std::uint16_t port() const;
  ConsoleCounts counts() const;
  /// "https://HOST:PORT/": the certificate's first name (localhost when it listens on every address).
  std::string url() const;

  struct Impl;

 private:
  explicit ConsoleServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace lungar::console
