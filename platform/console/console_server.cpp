/// @file console_server.cpp
/// @brief The console server of console_server.h on Boost.Beast: TLS, HTTP/1.1 with size limits and idle timeouts,
///        the API's checks, the WebSocket's pushes. The one file of lungar that includes Beast or Asio (they are
///        slow to compile: keep them here).
#include "platform/console/console_server.h"

#include <openssl/crypto.h>
#include <openssl/ssl.h>
#include <openssl/x509v3.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>
#include <cctype>
#include <filesystem>
#include <optional>
#include <set>
#include <thread>
#include <utility>

#include "lungar/console/page_files.h"
#include "platform/console/console_logins.h"
#include "platform/console/console_sessions.h"

namespace lungar::console {
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
namespace ssl = net::ssl;
using tcp = net::ip::tcp;
namespace {

constexpr std::uint32_t kHeaderLimit = 8 * 1024;
constexpr std::uint64_t kBodyLimit = 16 * 1024;
constexpr int kMaxConnections = 32;
constexpr auto kIdleTimeout = std::chrono::seconds(30);
constexpr auto kPushPeriod = std::chrono::milliseconds(100);
constexpr const char* kCookie = "lungar_session";

using Request = http::request<http::string_body>;
using Response = http::response<http::string_body>;
using TlsStream = beast::ssl_stream<beast::tcp_stream>;

/// What a route answers, before it becomes an HTTP response.
struct Reply {
  http::status status = http::status::ok;
  std::string type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;
  std::string refused;  ///< why, for a refusal (status >= 400 on /api/): then counted, logged and told the handler
};

Reply json_reply(http::status status, const nlohmann::json& body, std::string refused = "") {
  Reply r;
  r.status = status;
  r.body = body.dump();
  r.refused = std::move(refused);
  return r;
}

Reply refusal(http::status status, const std::string& why) { return json_reply(status, {{"error", why}}, why); }

/// A header's text, made safe for a log line: printable ASCII only, at most `max` characters.
std::string printable(beast::string_view text, std::size_t max = 96) {
  std::string out;
  for (char c : text) {
    if (out.size() >= max) return out + "...";
    out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return out;
}

std::string lower(beast::string_view text) {
  std::string s(text);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// The value of cookie `name` in a Cookie header ("a=1; lungar_session=ab12"), or "".
std::string cookie_value(beast::string_view header, beast::string_view name) {
  while (!header.empty()) {
    const std::size_t end = std::min(header.find(';'), header.size());
    beast::string_view pair = header.substr(0, end);
    header = end < header.size() ? header.substr(end + 1) : beast::string_view{};
    while (!pair.empty() && pair.front() == ' ') pair.remove_prefix(1);
    const std::size_t eq = pair.find('=');
    if (eq != beast::string_view::npos && pair.substr(0, eq) == name) return std::string(pair.substr(eq + 1));
  }
  return "";
}

/// The request's path without its query.
beast::string_view path_of(const Request& req) {
  beast::string_view target = req.target();
  return target.substr(0, std::min(target.find('?'), target.size()));
}

/// The names a certificate is valid for (its subjectAltName's DNS names and IP addresses): the origins a browser
/// that trusts it can come from.
std::vector<std::string> certificate_names(SSL_CTX* ctx) {
  std::vector<std::string> names;
  X509* cert = SSL_CTX_get0_certificate(ctx);
  if (!cert) return names;
  auto* sans = static_cast<GENERAL_NAMES*>(X509_get_ext_d2i(cert, NID_subject_alt_name, nullptr, nullptr));
  if (!sans) return names;
  for (int i = 0; i < sk_GENERAL_NAME_num(sans); ++i) {
    const GENERAL_NAME* n = sk_GENERAL_NAME_value(sans, i);
    if (n->type == GEN_DNS) {
      const ASN1_STRING* s = n->d.dNSName;
      names.emplace_back(reinterpret_cast<const char*>(ASN1_STRING_get0_data(s)), ASN1_STRING_length(s));
    } else if (n->type == GEN_IPADD) {
      const ASN1_OCTET_STRING* s = n->d.iPAddress;
      const unsigned char* b = ASN1_STRING_get0_data(s);
      if (ASN1_STRING_length(s) == 4) {
        names.push_back(net::ip::make_address_v4(net::ip::address_v4::bytes_type{b[0], b[1], b[2], b[3]}).to_string());
      } else if (ASN1_STRING_length(s) == 16) {
        net::ip::address_v6::bytes_type bytes{};
        std::copy(b, b + 16, bytes.begin());
        names.push_back("[" + net::ip::make_address_v6(bytes).to_string() + "]");
      }
    }
  }
  GENERAL_NAMES_free(sans);
  return names;
}

}  // namespace

/// The server's state; everything but the counts is touched on its thread only. Members are destroyed in reverse:
/// the io_context (and with it every connection its handlers hold) before the state they point to.
struct ConsoleServer::Impl {
  Impl(const ConsoleOptions& o, ConsoleHandler& h, std::function<void(const std::string&)> l)
      : options(o), handler(h), log_line(std::move(l)) {}

  ConsoleOptions options;
  ConsoleHandler& handler;
  std::function<void(const std::string&)> log_line;
  ConsoleLogins logins;
  ConsoleSessions sessions;
  LoginThrottle throttle;
  std::set<std::string> origins;  ///< "https://NAME:PORT" for each name of the certificate
  std::string url;
  std::uint16_t port = 0;
  int connections = 0;

  struct AtomicCounts {
    std::atomic<std::uint64_t> requests{0}, logins{0}, logins_refused{0}, refused_401{0}, refused_403{0},
        refused_other{0}, websockets{0};
  } counts;

  ssl::context tls{ssl::context::tls_server};
  net::io_context ioc{1};
  tcp::acceptor acceptor{ioc};
  std::thread thread;

  void log(const std::string& line) {
    if (log_line) log_line(line);
  }

  /// Counts, logs and reports a refusal.
  void refuse(int status, const std::string& method, beast::string_view target, const std::string& peer,
              const std::string& why) {
    if (status == 401) {
      ++counts.refused_401;
    } else if (status == 403) {
      ++counts.refused_403;
    } else {
      ++counts.refused_other;
    }
    const std::string line = "console: refused " + std::to_string(status) + " " + method + " " + printable(target) +
                             " from " + peer + ": " + why;
    log(line);
    try {
      handler.refused(status, line);
    } catch (const std::exception& e) {
      log("console: the handler's refused() threw: " + std::string(e.what()));
    }
  }

  bool origin_allowed(const Request& req) const {
    auto it = req.find(http::field::origin);
    return it == req.end() || origins.count(lower(it->value())) > 0;
  }

  ConsoleSession* session_of(const Request& req) {
    auto it = req.find(http::field::cookie);
    if (it == req.end()) return nullptr;
    const std::string cookie = cookie_value(it->value(), kCookie);
    return cookie.empty() ? nullptr : sessions.find(cookie, ConsoleClock::now());
  }

  Reply route(const Request& req, const std::string& peer);
  Reply login(const Request& req, const std::string& peer);
  Reply control(const Request& req);
  void accept();
};

Reply ConsoleServer::Impl::login(const Request& req, const std::string& peer) {
  const auto now = ConsoleClock::now();
  if (throttle.throttled(peer, now)) {
    ++counts.logins_refused;
    return refusal(http::status::too_many_requests,
                   "more than " + std::to_string(LoginThrottle::kMaxFailures) + " failed logins a minute");
  }
  const nlohmann::json body = nlohmann::json::parse(req.body(), nullptr, false);
  if (!body.is_object() || !body.contains("user") || !body["user"].is_string() || !body.contains("password") ||
      !body["password"].is_string())
    return refusal(http::status::bad_request, "expected a JSON body {\"user\": ..., \"password\": ...}");
  const std::string name = body["user"], password = body["password"];
  std::optional<ConsoleUser> user = logins.verify(name, password);
  if (!user) {
    throttle.failed(peer, now);
    ++counts.logins_refused;
    // The name as given (printable, short), never the password.
    return refusal(http::status::unauthorized, "wrong name or password (user \"" + printable(name, 40) + "\")");
  }
  auto cookie = sessions.open(*user, now);
  if (!cookie) return refusal(http::status::internal_server_error, cookie.error());
  ++counts.logins;
  log("console: login " + user->name + " (" + role_name(user->role) + ") from " + peer);
  Reply r =
      json_reply(http::status::ok,
                 {{"user", user->name}, {"role", role_name(user->role)}, {"csrf", sessions.find(*cookie, now)->csrf}});
  r.headers.emplace_back("Set-Cookie",
                         std::string(kCookie) + "=" + *cookie + "; Secure; HttpOnly; SameSite=Strict; Path=/");
  return r;
}

Reply ConsoleServer::Impl::control(const Request& req) {
  ConsoleSession* session = session_of(req);
  if (!session) return refusal(http::status::unauthorized, "no session (log in first)");
  if (!origin_allowed(req)) return refusal(http::status::forbidden, "foreign Origin");
  if (session->user.role != Role::Instructor)
    return refusal(http::status::forbidden, "user " + session->user.name + " is an observer");
  const std::string type = lower(req[http::field::content_type]);
  if (type.substr(0, type.find(';')) != "application/json")
    return refusal(http::status::unsupported_media_type, "expected Content-Type: application/json");
  const beast::string_view csrf = req["X-CSRF-Token"];
  if (csrf.empty()) return refusal(http::status::forbidden, "no X-CSRF-Token");
  if (csrf.size() != session->csrf.size() ||
      CRYPTO_memcmp(csrf.data(), session->csrf.data(), session->csrf.size()) != 0)
    return refusal(http::status::forbidden, "wrong X-CSRF-Token");
  if (const std::string why = ConsoleSessions::use_nonce(*session, std::string(req["X-Request-Nonce"])); !why.empty())
    return refusal(http::status::forbidden, why);
  const nlohmann::json request = nlohmann::json::parse(req.body(), nullptr, false);
  if (!request.is_object())
    return refusal(http::status::bad_request, "expected a JSON object {\"action\": ...} as the body");
  ControlReply answer = handler.control(session->user, request);
  return json_reply(static_cast<http::status>(answer.status), answer.body);
}

Reply ConsoleServer::Impl::route(const Request& req, const std::string& peer) {
  const beast::string_view path = path_of(req);
  const http::verb method = req.method();
  if (path.substr(0, 5) != "/api/") {
    if (method != http::verb::get) return json_reply(http::status::method_not_allowed, {{"error", "expected GET"}});
    const beast::string_view name = path == "/" ? beast::string_view("index.html") : path.substr(1);
    for (const page::PageFile& f : page::files) {
      if (name == f.name) {
        Reply r;
        r.type = f.type;
        r.body = std::string(f.content);
        return r;
      }
    }
    return json_reply(http::status::not_found, {{"error", "no such page"}});
  }
  const auto only = [&](http::verb allowed) -> std::optional<Reply> {
    if (method == allowed) return std::nullopt;
    return refusal(http::status::method_not_allowed, std::string("expected ") + std::string(http::to_string(allowed)));
  };
  if (path == "/api/login") {
    if (auto r = only(http::verb::post)) return *r;
    if (!origin_allowed(req)) return refusal(http::status::forbidden, "foreign Origin");
    return login(req, peer);
  }
  if (path == "/api/logout") {
    if (auto r = only(http::verb::post)) return *r;
    if (!origin_allowed(req)) return refusal(http::status::forbidden, "foreign Origin");
    if (ConsoleSession* s = session_of(req)) {
      log("console: logout " + s->user.name + " from " + peer);
      sessions.close(cookie_value(req[http::field::cookie], kCookie));
    }
    Reply r = json_reply(http::status::ok, nlohmann::json::object());
    r.headers.emplace_back("Set-Cookie",
                           std::string(kCookie) + "=; Secure; HttpOnly; SameSite=Strict; Path=/; Max-Age=0");
    return r;
  }
  if (path == "/api/state" || path == "/api/timeline.csv") {
    if (auto r = only(http::verb::get)) return *r;
    if (!session_of(req)) return refusal(http::status::unauthorized, "no session (log in first)");
    if (path == "/api/state") {
      Reply r;
      r.body = handler.snapshot_json();
      return r;
    }
    Reply r;
    r.type = "text/csv; charset=utf-8";
    r.body = handler.timeline_csv();
    r.headers.emplace_back("Content-Disposition", "attachment; filename=\"lungar-timeline.csv\"");
    return r;
  }
  if (path == "/api/control") {
    if (auto r = only(http::verb::post)) return *r;
    return control(req);
  }
  if (path == "/api/live") return refusal(http::status::upgrade_required, "expected a WebSocket upgrade");
  return refusal(http::status::not_found, "no such API");
}

namespace {

/// Holds one of the server's kMaxConnections places while a connection lives, whichever object owns it.
class ConnectionSlot {
 public:
  explicit ConnectionSlot(int& count) : count_(&count) { ++*count_; }
  ConnectionSlot(ConnectionSlot&& o) noexcept : count_(std::exchange(o.count_, nullptr)) {}
  ConnectionSlot& operator=(ConnectionSlot&&) = delete;
  ~ConnectionSlot() {
    if (count_) --*count_;
  }

 private:
  int* count_;
};

void set_security_headers(Response& res) {
  res.set(http::field::server, "lungar");
  res.set("Content-Security-Policy", "default-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'self'");
  res.set("X-Frame-Options", "DENY");
  res.set(http::field::cache_control, "no-store");
  res.set("X-Content-Type-Options", "nosniff");
  res.set("Referrer-Policy", "no-referrer");
}

/// A WebSocket on /api/live: the snapshot every kPushPeriod while the session lives. A push is skipped while the
/// previous one is still being written, so a slow client costs one message's memory, never a growing queue.
class LiveSocket : public std::enable_shared_from_this<LiveSocket> {
 public:
  LiveSocket(ConsoleServer::Impl& server, TlsStream&& stream, ConnectionSlot slot, std::string cookie)
      : server_(server),
        ws_(std::move(stream)),
        timer_(server.ioc),
        slot_(std::move(slot)),
        cookie_(std::move(cookie)) {}

  void run(Request req) {
    beast::get_lowest_layer(ws_).expires_never();  // the WebSocket's own timeouts from here
    websocket::stream_base::timeout timeouts = websocket::stream_base::timeout::suggested(beast::role_type::server);
    timeouts.idle_timeout = kIdleTimeout;
    timeouts.keep_alive_pings = true;
    ws_.set_option(timeouts);
    ws_.set_option(websocket::stream_base::decorator(
        [](websocket::response_type& res) { res.set(http::field::server, "lungar"); }));
    ws_.read_message_max(4096);  // the page sends nothing; a client's ping or close is small
    ws_.async_accept(req, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return;
      ++self->server_.counts.websockets;
      self->read();
      self->tick();
    });
  }

 private:
  void read() {
    ws_.async_read(in_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->stop();
      self->in_.consume(self->in_.size());
      self->read();
    });
  }

  void tick() {
    if (stopped_) return;
    if (!server_.sessions.find(cookie_, ConsoleClock::now())) {  // logged out or expired
      stopped_ = true;
      ws_.async_close(websocket::close_code::policy_error, [self = shared_from_this()](beast::error_code) {});
      return;
    }
    if (!writing_) {
      try {
        out_ = server_.handler.snapshot_json();
      } catch (const std::exception& e) {
        server_.log("console: the live view's snapshot failed: " + std::string(e.what()));
        return stop();
      }
      writing_ = true;
      ws_.text(true);
      ws_.async_write(net::buffer(out_), [self = shared_from_this()](beast::error_code ec, std::size_t) {
        self->writing_ = false;
        if (ec) self->stop();
      });
    }
    timer_.expires_after(kPushPeriod);
    timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (!ec) self->tick();
    });
  }

  void stop() {
    stopped_ = true;
    timer_.cancel();
  }

  ConsoleServer::Impl& server_;
  websocket::stream<TlsStream> ws_;
  net::steady_timer timer_;
  ConnectionSlot slot_;
  std::string cookie_;
  beast::flat_buffer in_;
  std::string out_;
  bool writing_ = false;
  bool stopped_ = false;
};

/// One TLS connection: requests read one at a time, each within the limits, answered in order.
class Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(ConsoleServer::Impl& server, tcp::socket&& socket, std::string peer)
      : server_(server), stream_(std::move(socket), server.tls), slot_(server.connections), peer_(std::move(peer)) {}

  void run() {
    beast::get_lowest_layer(stream_).expires_after(kIdleTimeout);
    stream_.async_handshake(ssl::stream_base::server, [self = shared_from_this()](beast::error_code ec) {
      if (!ec) self->read();
    });
  }

 private:
  void read() {
    parser_.emplace();
    parser_->header_limit(kHeaderLimit);
    parser_->body_limit(kBodyLimit);
    beast::get_lowest_layer(stream_).expires_after(kIdleTimeout);
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }

  void on_read(beast::error_code ec) {
    if (ec == http::error::body_limit || ec == http::error::header_limit) {
      ++server_.counts.requests;
      const bool body = ec == http::error::body_limit;
      const Request& req = parser_->get();
      Reply r = refusal(body ? http::status::payload_too_large : http::status::request_header_fields_too_large,
                        body ? "body over 16 KiB" : "header over 8 KiB");
      server_.refuse(static_cast<int>(r.status), body ? std::string(req.method_string()) : "?",
                     body ? req.target() : beast::string_view("?"), peer_, r.refused);
      return write(std::move(r), 11, false, true);
    }
    if (ec) return shutdown();  // end of stream, timeout, reset, garbage: nothing to answer
    ++server_.counts.requests;
    Request req = parser_->release();
    if (websocket::is_upgrade(req)) return upgrade(std::move(req));
    Reply r;
    try {
      r = server_.route(req, peer_);
    } catch (const std::exception& e) {
      server_.log("console: " + std::string(req.method_string()) + " " + printable(req.target()) + ": " + e.what());
      r = json_reply(http::status::internal_server_error, {{"error", "the console failed: " + std::string(e.what())}});
    }
    if (!r.refused.empty())
      server_.refuse(static_cast<int>(r.status), std::string(req.method_string()), req.target(), peer_, r.refused);
    write(std::move(r), req.version(), req.keep_alive(), false);
  }

  void upgrade(Request req) {
    const auto refused = [&](http::status status, const std::string& why) {
      server_.refuse(static_cast<int>(status), "GET", req.target(), peer_, why);
      write(refusal(status, why), req.version(), false, false);
    };
    if (path_of(req) != "/api/live") return refused(http::status::not_found, "no WebSocket here");
    if (!server_.session_of(req)) return refused(http::status::unauthorized, "no session (log in first)");
    if (!server_.origin_allowed(req)) return refused(http::status::forbidden, "foreign Origin");
    const std::string cookie = cookie_value(req[http::field::cookie], kCookie);
    std::make_shared<LiveSocket>(server_, std::move(stream_), std::move(slot_), cookie)->run(std::move(req));
  }

  /// Writes `r`; then reads the next request, or ends the connection. After a request that was too big the rest of
  /// it is drained first, so that the client reads the answer rather than a reset.
  void write(Reply r, unsigned version, bool keep_alive, bool drain) {
    auto res = std::make_shared<Response>(r.status, version);
    set_security_headers(*res);
    res->set(http::field::content_type, r.type);
    for (const auto& [name, value] : r.headers) res->insert(name, value);
    res->body() = std::move(r.body);
    res->keep_alive(keep_alive);
    res->prepare_payload();
    beast::get_lowest_layer(stream_).expires_after(kIdleTimeout);
    http::async_write(stream_, *res, [self = shared_from_this(), res, drain](beast::error_code ec, std::size_t) {
      if (ec) return;
      if (drain) return self->drain(0);
      if (res->need_eof()) return self->shutdown();
      self->read();
    });
  }

  void drain(std::size_t drained) {
    if (drained > 4 * kBodyLimit * 16) return shutdown();
    beast::get_lowest_layer(stream_).expires_after(std::chrono::seconds(2));
    stream_.async_read_some(net::buffer(scratch_),
                            [self = shared_from_this(), drained](beast::error_code ec, std::size_t n) {
                              if (ec) return self->shutdown();
                              self->drain(drained + n);
                            });
  }

  void shutdown() {
    beast::get_lowest_layer(stream_).expires_after(std::chrono::seconds(5));
    stream_.async_shutdown([self = shared_from_this()](beast::error_code) {});
  }

  ConsoleServer::Impl& server_;
  TlsStream stream_;
  ConnectionSlot slot_;
  std::string peer_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::array<char, 4096> scratch_{};
};

}  // namespace

void ConsoleServer::Impl::accept() {
  acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
    if (ec == net::error::operation_aborted) return;
    if (!ec) {
      beast::error_code peer_ec;
      const std::string peer = socket.remote_endpoint(peer_ec).address().to_string();
      if (connections >= kMaxConnections) {
        refuse(503, "connect", "", peer, std::to_string(kMaxConnections) + " connections open already");
        socket.close(peer_ec);
      } else {
        std::make_shared<Connection>(*this, std::move(socket), peer)->run();
      }
    }
    accept();
  });
}

ConsoleServer::ConsoleServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ConsoleServer::~ConsoleServer() {
  impl_->ioc.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

std::uint16_t ConsoleServer::port() const { return impl_->port; }
std::string ConsoleServer::url() const { return impl_->url; }

ConsoleCounts ConsoleServer::counts() const {
  const Impl::AtomicCounts& c = impl_->counts;
  return {c.requests, c.logins, c.logins_refused, c.refused_401, c.refused_403, c.refused_other, c.websockets};
}

Result<std::unique_ptr<ConsoleServer>> ConsoleServer::start(const ConsoleOptions& o, ConsoleHandler& handler,
                                                            std::function<void(const std::string&)> log) {
  namespace fs = std::filesystem;
  std::error_code fs_ec;
  if (o.keys_dir.empty() || !fs::is_directory(o.keys_dir, fs_ec))
    return fail("console keys \"" + o.keys_dir +
                "\": expected the console folder of lungar classroom-keys (server_cert.pem, server_key.pem, logins)");
  auto impl = std::make_unique<Impl>(o, handler, std::move(log));
  const std::string cert = (fs::path(o.keys_dir) / "server_cert.pem").string(),
                    key = (fs::path(o.keys_dir) / "server_key.pem").string(),
                    logins = (fs::path(o.keys_dir) / "logins").string();
  auto read = ConsoleLogins::read(logins);
  if (!read) return read.with_context("");
  impl->logins = read.take();

  SSL_CTX* ctx = impl->tls.native_handle();
  SSL_CTX_set_min_proto_version(ctx, TLS1_2_VERSION);
  // TLS 1.2's forward-secret AEAD suites only (TLS 1.3's are all such).
  SSL_CTX_set_cipher_list(ctx, "ECDHE+AESGCM:ECDHE+CHACHA20");
  impl->tls.set_options(ssl::context::default_workarounds | ssl::context::no_compression);
  beast::error_code ec;
  impl->tls.use_certificate_chain_file(cert, ec);
  if (ec) return fail(cert + ": cannot use it as the console's certificate (PEM): " + ec.message());
  impl->tls.use_private_key_file(key, ssl::context::pem, ec);
  if (ec) return fail(key + ": cannot use it as the console's private key (PEM): " + ec.message());
  if (SSL_CTX_check_private_key(ctx) != 1) return fail(key + ": is not the key of " + cert);

  const net::ip::address address = net::ip::make_address(o.address, ec);
  if (ec) return fail("console address \"" + o.address + "\": expected an IPv4 or IPv6 address");
  const std::string where = o.address + ":" + std::to_string(o.port);
  const tcp::endpoint endpoint(address, o.port);
  impl->acceptor.open(endpoint.protocol(), ec);
  if (!ec) impl->acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) impl->acceptor.bind(endpoint, ec);
  if (!ec) impl->acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) return fail("console: cannot listen on " + where + ": " + ec.message());
  impl->port = impl->acceptor.local_endpoint().port();

  const std::string port = std::to_string(impl->port);
  for (const std::string& name : certificate_names(ctx)) {
    impl->origins.insert("https://" + lower(name) + ":" + port);
    if (impl->port == 443) impl->origins.insert("https://" + lower(name));
  }
  const std::string host = address.is_unspecified() ? "localhost"
                           : address.is_v6()        ? "[" + address.to_string() + "]"
                                                    : address.to_string();
  impl->url = "https://" + host + ":" + port + "/";

  impl->accept();
  Impl* raw = impl.get();
  impl->thread = std::thread([raw] {
    // A handler that throws must not end the console: log and carry on.
    for (;;) {
      try {
        raw->ioc.run();
        return;
      } catch (const std::exception& e) {
        raw->log(std::string("console: ") + e.what());
      }
    }
  });
  return std::unique_ptr<ConsoleServer>(new ConsoleServer(std::move(impl)));
}

}  // namespace lungar::console
