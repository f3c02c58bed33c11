/// @file https_client.h
/// @brief Test helper: a small HTTPS and WebSocket client for the instructor's console (Boost.Beast behind it, in
///        https_client.cpp alone): log in, GET, POST with headers, send a control request with the session's CSRF
///        token and a fresh nonce, open /api/live and read its messages. Every call has a timeout and returns what
///        came back (or an error line); nothing throws. For the console's own tests and the whole program's.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lungar::testing {

using HttpHeaders = std::vector<std::pair<std::string, std::string>>;

struct HttpsReply {
  int status = 0;       ///< 0: no answer (then `error` says why)
  HttpHeaders headers;  ///< as received; names in lower case
  std::string body;
  std::string error;
  /// The first header of this name (lower case), or "".
  std::string header(const std::string& name) const;
};

struct HttpsClientOptions {
  std::string address = "127.0.0.1";  ///< where to connect
  std::uint16_t port = 0;
  std::string host = "localhost";  ///< the name sent as SNI and Host, and checked against the server's certificate
  std::string ca_file;             ///< verify the server against this authority; empty: accept any certificate
  std::string client_cert;         ///< present this certificate (PEM) and key as a TLS client, if given
  std::string client_key;
  std::chrono::milliseconds timeout{5000};  ///< for each step (connect, handshake, write, read)
};

/// A WebSocket to the console: its upgrade's answer, then one message per read().
class WebSocketClient {
 public:
  virtual ~WebSocketClient() = default;
  /// 101 when upgraded, else the HTTP status the server refused it with (0: no answer).
  virtual int status() const = 0;
  virtual const std::string& error() const = 0;
  /// The next message, or nothing (closed, timed out: error() says which).
  virtual bool read(std::string& message, std::chrono::milliseconds timeout) = 0;
};

/// The port of the first "console: https://HOST:PORT/" line of a `lungar` log (what a run with --console ADDR:0
/// says it serves on); 0 until it is there.
inline std::uint16_t console_port_in(const std::string& log) {
  const auto at = log.find("console: https://");
  if (at == std::string::npos) return 0;
  const auto slash = log.find('/', at + 17);
  const auto colon = log.rfind(':', slash);
  return static_cast<std::uint16_t>(std::stoi(log.substr(colon + 1, slash - colon - 1)));
}

class HttpsClient {
 public:
  explicit HttpsClient(HttpsClientOptions options);

  /// One request on a connection of its own. Adds Host, the session cookie once logged in, Content-Length.
  HttpsReply request(const std::string& method, const std::string& target, const std::string& body = "",
                     const HttpHeaders& headers = {});
  HttpsReply get(const std::string& target, const HttpHeaders& headers = {}) {
    return request("GET", target, "", headers);
  }
  HttpsReply post(const std::string& target, const std::string& body, const HttpHeaders& headers = {}) {
    return request("POST", target, body, headers);
  }

  /// POST /api/login; on 200 keeps the session cookie and the CSRF token for the calls that follow.
  HttpsReply login(const std::string& user, const std::string& password);
  /// POST /api/control with Content-Type JSON, the session's X-CSRF-Token and a fresh X-Request-Nonce (or `nonce`),
  /// and `extra` headers besides (an Origin, say). To leave one of the three out, post() it by hand.
  HttpsReply control(const std::string& json, const std::string& nonce = "", const HttpHeaders& extra = {});

  /// Opens /api/live (or `target`) with the session cookie and these headers (an Origin, say).
  std::unique_ptr<WebSocketClient> websocket(const HttpHeaders& headers = {}, const std::string& target = "/api/live");

  const std::string& cookie() const { return cookie_; }
  const std::string& csrf() const { return csrf_; }
  void set_session(std::string cookie, std::string csrf) {
    cookie_ = std::move(cookie);
    csrf_ = std::move(csrf);
  }
  /// "https://HOST:PORT": the server's own origin as a browser sends it.
  std::string origin() const;

  /// 32 hex digits of fresh randomness.
  static std::string fresh_nonce();

 private:
  HttpsClientOptions options_;
  std::string cookie_;  ///< the session cookie's value
  std::string csrf_;
};

}  // namespace lungar::testing
