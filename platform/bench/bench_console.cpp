/// @file bench_console.cpp
/// @brief The bench's instructor with its console, and a watcher reading the live view over plain OpenSSL.
#include "platform/bench/bench_console.h"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <openssl/bio.h>
#include <openssl/err.h>
#include <openssl/ssl.h>

#include "config/base/clock.h"
#include "drivers/classroom/classroom_keys.h"
#include "drivers/classroom/classroom_station.h"
#include "platform/console/console_server.h"
#include "platform/sync/class_control.h"
#include "sim/breathing/script.h"

namespace lungar::platform::bench {

struct BenchConsole::Parts {
  std::filesystem::path dir;
  std::shared_ptr<classroom::ClassroomStation> station;
  std::shared_ptr<sync::ClassControl> control;
  std::unique_ptr<console::ConsoleServer> server;
  std::string password;
  ~Parts() {
    server.reset();  // its thread calls the control
    std::error_code ec;
    if (!dir.empty()) std::filesystem::remove_all(dir, ec);
  }
};

namespace {

/// One TLS connection to the console, the certificate not checked (the bench's own server on loopback).
class TlsLink {
 public:
  explicit TlsLink(std::uint16_t port) {
    ctx_ = SSL_CTX_new(TLS_client_method());
    if (ctx_ == nullptr) return;
    bio_ = BIO_new_ssl_connect(ctx_);
    if (bio_ == nullptr) return;
    BIO_set_conn_hostname(bio_, ("127.0.0.1:" + std::to_string(port)).c_str());
    if (BIO_do_connect(bio_) <= 0 || BIO_do_handshake(bio_) <= 0) {
      BIO_free_all(bio_);
      bio_ = nullptr;
    }
  }
  ~TlsLink() {
    if (bio_ != nullptr) BIO_free_all(bio_);
    if (ctx_ != nullptr) SSL_CTX_free(ctx_);
  }
  TlsLink(const TlsLink&) = delete;
  TlsLink& operator=(const TlsLink&) = delete;

  bool ok() const { return bio_ != nullptr; }
  bool send(const std::string& text) { return BIO_write(bio_, text.data(), static_cast<int>(text.size())) > 0; }
  /// What came, at most `size` bytes; <= 0 when the connection ended.
  int read(char* into, int size) { return BIO_read(bio_, into, size); }
  /// Reads until the end of the HTTP head (the body, if any, follows in later reads).
  std::string head() {
    std::string text;
    char c = 0;
    while (text.size() < 16384 && text.find("\r\n\r\n") == std::string::npos && read(&c, 1) == 1) text += c;
    return text;
  }

 private:
  SSL_CTX* ctx_ = nullptr;
  BIO* bio_ = nullptr;
};

/// Logs in as the instructor; the session cookie's value, or "" on failure.
std::string log_in(std::uint16_t port, const std::string& password) {
  TlsLink link(port);
  if (!link.ok()) return "";
  const std::string body = R"({"user":"instructor","password":")" + password + "\"}";
  link.send("POST /api/login HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\nContent-Length: " +
            std::to_string(body.size()) + "\r\nConnection: close\r\n\r\n" + body);
  const std::string head = link.head();
  const auto at = head.find("lungar_session=");
  if (head.rfind("HTTP/1.1 200", 0) != 0 || at == std::string::npos) return "";
  const auto end = head.find(';', at);
  return head.substr(at + 15, end - at - 15);
}

}  // namespace

Result<std::unique_ptr<BenchConsole>> BenchConsole::start() {
  std::unique_ptr<BenchConsole> b(new BenchConsole());
  b->parts_ = std::make_unique<Parts>();
  Parts& p = *b->parts_;
  char dir[] = "/tmp/lungar-bench-console-XXXXXX";
  if (mkdtemp(dir) == nullptr) return fail("bench console: cannot make a temporary folder");
  p.dir = dir;
  const std::string room = "bench-" + std::to_string(getpid());
  classroom::ClassroomKeysOptions keys;
  keys.classroom = room;
  keys.stations = {"instructor"};
  keys.out_dir = (p.dir / "keys").string();
  if (auto made = classroom::make_classroom_keys(keys); !made) return made.with_context("bench console: ");
  std::ifstream(p.dir / "keys" / "console" / "instructor.password") >> p.password;

  classroom::SyncSettings s;
  s.role = classroom::SyncRole::Instructor;
  s.classroom = room;
  s.domain = 200 + static_cast<int>(getpid() % 30);
  const auto loopback = std::filesystem::path(classroom::default_cyclonedds_xml()).parent_path() / "loopback-tests.xml";
  if (std::filesystem::exists(loopback)) s.cyclonedds_xml = loopback.string();
  s.station = "instructor";
  auto station = classroom::ClassroomStation::open(s, nullptr);
  if (!station) return station.with_context("bench console: ");
  p.station = std::make_shared<classroom::ClassroomStation>(station.take());
  const sim::BreathingParams start;
  const std::int64_t t0 = monotonic_ns();
  if (Status shared = p.station->instructor()->share_breathing(start, {}, {}, t0); !shared)
    return shared.with_context("bench console: ");
  auto control = sync::ClassControl::create({start, {}, {}, t0, "", std::nullopt}, p.station, nullptr);
  if (!control) return control.with_context("bench console: ");
  p.control = control.take();
  auto server =
      console::ConsoleServer::start({"127.0.0.1", 0, (p.dir / "keys" / "console").string()}, *p.control, nullptr);
  if (!server) return server.with_context("bench console: ");
  p.server = server.take();
  b->watcher_ = std::thread([w = b.get()] { w->run_watcher(); });
  return b;
}

BenchConsole::~BenchConsole() {
  stop_.store(true);
  if (watcher_.joinable()) watcher_.join();
}

std::shared_ptr<FrameListener> BenchConsole::listener() const { return parts_->control; }

void BenchConsole::run_watcher() {
  const std::uint16_t port = parts_->server->port();
  const std::string cookie = log_in(port, parts_->password);
  std::unique_ptr<TlsLink> live;
  char buffer[16384];
  while (!stop_.load()) {
    if (!watching_.load(std::memory_order_relaxed)) {
      live.reset();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    if (!live) {
      live = std::make_unique<TlsLink>(port);
      if (!live->ok() || cookie.empty()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        live.reset();
        continue;
      }
      live->send(
          "GET /api/live HTTP/1.1\r\nHost: localhost\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
          "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\nCookie: lungar_session=" +
          cookie + "\r\n\r\n");
      if (live->head().rfind("HTTP/1.1 101", 0) != 0) {
        live.reset();
        continue;
      }
    }
    // The pushes come 10 a second; a read blocks until one does, which the next flag check follows.
    const int n = live->read(buffer, sizeof buffer);
    if (n <= 0) {
      live.reset();
      continue;
    }
    bytes_.fetch_add(static_cast<std::uint64_t>(n));
  }
}

}  // namespace lungar::platform::bench
