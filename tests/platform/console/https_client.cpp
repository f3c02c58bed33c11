/// @file https_client.cpp
/// @brief The test client of https_client.h on Boost.Beast: each step an asynchronous operation run to completion
///        under the stream's own timeout, so that a silent server fails a test instead of hanging it.
#include "tests/platform/console/https_client.h"

#include <openssl/rand.h>
#include <openssl/ssl.h>

#include <algorithm>
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>
#include <cctype>

namespace lungar::testing {
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
namespace ssl = net::ssl;
using tcp = net::ip::tcp;
namespace {

using TlsStream = beast::ssl_stream<beast::tcp_stream>;

/// Runs one asynchronous operation to its end; its error (a timeout shows as beast::error::timeout).
template <class Start>
beast::error_code run_one(net::io_context& ioc, Start start) {
  beast::error_code result = net::error::would_block;
  start([&result](beast::error_code ec, auto&&...) { result = ec; });
  ioc.restart();
  ioc.run();
  return result;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// A TLS connection made as the options say, or the error of the step that failed.
struct Connection {
  net::io_context ioc;
  ssl::context tls{ssl::context::tls_client};
  std::unique_ptr<TlsStream> stream;
  std::string error;

  explicit Connection(const HttpsClientOptions& o) {
    beast::error_code ec;
    if (!o.ca_file.empty()) {
      tls.load_verify_file(o.ca_file, ec);
      if (ec) {
        error = o.ca_file + ": " + ec.message();
        return;
      }
      tls.set_verify_mode(ssl::verify_peer);
    } else {
      tls.set_verify_mode(ssl::verify_none);
    }
    if (!o.client_cert.empty()) {
      tls.use_certificate_file(o.client_cert, ssl::context::pem, ec);
      if (!ec) tls.use_private_key_file(o.client_key, ssl::context::pem, ec);
      if (ec) {
        error = o.client_cert + ": " + ec.message();
        return;
      }
    }
    stream = std::make_unique<TlsStream>(ioc, tls);
    if (!o.ca_file.empty()) stream->set_verify_callback(ssl::host_name_verification(o.host));
    SSL_set_tlsext_host_name(stream->native_handle(), o.host.c_str());
    tcp::endpoint endpoint(net::ip::make_address(o.address, ec), o.port);
    if (ec) {
      error = o.address + ": " + ec.message();
      return;
    }
    auto& tcp_stream = beast::get_lowest_layer(*stream);
    tcp_stream.expires_after(o.timeout);
    if ((ec = run_one(ioc, [&](auto h) { tcp_stream.async_connect(endpoint, h); }))) {
      error = "connect: " + ec.message();
      return;
    }
    tcp_stream.expires_after(o.timeout);
    if ((ec = run_one(ioc, [&](auto h) { stream->async_handshake(ssl::stream_base::client, h); }))) {
      error = "TLS handshake: " + ec.message();
      return;
    }
  }
  bool ok() const { return error.empty(); }
};

class LiveClient : public WebSocketClient {
 public:
  LiveClient(const HttpsClientOptions& o, const std::string& cookie, const HttpHeaders& headers,
             const std::string& target)
      : connection_(o), timeout_(o.timeout) {
    if (!connection_.ok()) {
      error_ = connection_.error;
      return;
    }
    ws_ = std::make_unique<websocket::stream<TlsStream&>>(*connection_.stream);
    ws_->set_option(websocket::stream_base::decorator([cookie, headers](websocket::request_type& req) {
      if (!cookie.empty()) req.set(http::field::cookie, "lungar_session=" + cookie);
      for (const auto& [name, value] : headers) req.set(name, value);
    }));
    websocket::response_type res;
    beast::get_lowest_layer(*connection_.stream).expires_after(o.timeout);
    const std::string host = o.host + ":" + std::to_string(o.port);
    const beast::error_code ec = run_one(connection_.ioc, [&](auto h) { ws_->async_handshake(res, host, target, h); });
    status_ = static_cast<int>(res.result_int());
    if (ec) error_ = "WebSocket upgrade: " + ec.message();
  }

  int status() const override { return status_; }
  const std::string& error() const override { return error_; }

  bool read(std::string& message, std::chrono::milliseconds timeout) override {
    if (!ws_ || status_ != 101) return false;
    beast::flat_buffer buffer;
    beast::get_lowest_layer(*connection_.stream).expires_after(timeout);
    const beast::error_code ec = run_one(connection_.ioc, [&](auto h) { ws_->async_read(buffer, h); });
    if (ec) {
      error_ = "WebSocket read: " + ec.message();
      return false;
    }
    message = beast::buffers_to_string(buffer.data());
    return true;
  }

 private:
  Connection connection_;
  std::chrono::milliseconds timeout_;
  std::unique_ptr<websocket::stream<TlsStream&>> ws_;
  int status_ = 0;
  std::string error_;
};

}  // namespace

std::string HttpsReply::header(const std::string& name) const {
  for (const auto& [n, v] : headers)
    if (n == name) return v;
  return "";
}

HttpsClient::HttpsClient(HttpsClientOptions options) : options_(std::move(options)) {}

std::string HttpsClient::origin() const { return "https://" + options_.host + ":" + std::to_string(options_.port); }

std::string HttpsClient::fresh_nonce() {
  unsigned char bytes[16];
  RAND_bytes(bytes, sizeof bytes);
  static const char* digits = "0123456789abcdef";
  std::string s;
  for (unsigned char b : bytes) (s += digits[b >> 4]) += digits[b & 15];
  return s;
}

HttpsReply HttpsClient::request(const std::string& method, const std::string& target, const std::string& body,
                                const HttpHeaders& headers) {
  HttpsReply reply;
  Connection c(options_);
  if (!c.ok()) {
    reply.error = c.error;
    return reply;
  }
  http::request<http::string_body> req(http::string_to_verb(method), target, 11);
  req.set(http::field::host, options_.host + ":" + std::to_string(options_.port));
  if (!cookie_.empty()) req.set(http::field::cookie, "lungar_session=" + cookie_);
  for (const auto& [name, value] : headers) req.set(name, value);
  req.body() = body;
  req.keep_alive(false);
  req.prepare_payload();
  auto& tcp_stream = beast::get_lowest_layer(*c.stream);
  tcp_stream.expires_after(options_.timeout);
  if (beast::error_code ec = run_one(c.ioc, [&](auto h) { http::async_write(*c.stream, req, h); })) {
    reply.error = "write: " + ec.message();  // the server may have answered before it read everything: read on
  }
  beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.body_limit(16 * 1024 * 1024);
  tcp_stream.expires_after(options_.timeout);
  if (beast::error_code ec = run_one(c.ioc, [&](auto h) { http::async_read(*c.stream, buffer, parser, h); })) {
    reply.error += (reply.error.empty() ? "" : "; ") + std::string("read: ") + ec.message();
    return reply;
  }
  reply.error.clear();
  const auto& res = parser.get();
  reply.status = static_cast<int>(res.result_int());
  for (const auto& field : res)
    reply.headers.emplace_back(lower(std::string(field.name_string())), std::string(field.value()));
  reply.body = res.body();
  tcp_stream.expires_after(std::chrono::milliseconds(500));
  run_one(c.ioc, [&](auto h) { c.stream->async_shutdown(h); });
  return reply;
}

HttpsReply HttpsClient::login(const std::string& user, const std::string& password) {
  // Built by hand, which keeps the client free of a JSON library: quotes, backslashes and newlines escaped, other
  // control characters left out.
  const auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
      if (c == '"' || c == '\\') q += '\\';
      if (c == '\n') {
        q += "\\n";
        continue;
      }
      if (static_cast<unsigned char>(c) < 0x20) continue;
      q += c;
    }
    return q + "\"";
  };
  HttpsReply r = post("/api/login", "{\"user\":" + quoted(user) + ",\"password\":" + quoted(password) + "}",
                      {{"Content-Type", "application/json"}});
  if (r.status != 200) return r;
  const std::string set_cookie = r.header("set-cookie");
  const std::string prefix = "lungar_session=";
  if (set_cookie.rfind(prefix, 0) == 0)
    cookie_ = set_cookie.substr(prefix.size(), set_cookie.find(';') - prefix.size());
  const std::size_t at = r.body.find("\"csrf\":\"");
  if (at != std::string::npos) {
    const std::size_t start = at + 8;
    csrf_ = r.body.substr(start, r.body.find('"', start) - start);
  }
  return r;
}

HttpsReply HttpsClient::control(const std::string& json, const std::string& nonce, const HttpHeaders& extra) {
  HttpHeaders headers{{"Content-Type", "application/json"},
                      {"X-CSRF-Token", csrf_},
                      {"X-Request-Nonce", nonce.empty() ? fresh_nonce() : nonce}};
  headers.insert(headers.end(), extra.begin(), extra.end());
  return post("/api/control", json, headers);
}

std::unique_ptr<WebSocketClient> HttpsClient::websocket(const HttpHeaders& headers, const std::string& target) {
  return std::make_unique<LiveClient>(options_, cookie_, headers, target);
}

}  // namespace lungar::testing
