/// @file bench_console.h
/// @brief What a frame costs with the instructor's console open and a browser watching it: a real instructor station
///        (DDS on loopback), its class control as a frame listener, the console's HTTPS server, and a watcher that
///        logs in and reads the live view's WebSocket pushes (10 a second) while the frames it is watching run.
/// @ingroup platform
///
/// The watcher is a plain OpenSSL client: it reads and drops what comes, as a browser's socket does, and costs the
/// frame what the server's work for one watching page costs (the snapshot, its JSON, TLS), not what a browser does.
/// It connects while watch(true) and disconnects on watch(false), so that the frames measured without the console
/// bear none of that work.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "config/base/result.h"
#include "platform/runtime/frame_listener.h"

namespace lungar::platform::bench {

class BenchConsole {
 public:
  /// Keys in a temporary folder, an instructor on a loopback classroom of its own, the control and its server on
  /// 127.0.0.1 (a free port), and the watcher's thread (idle until watch(true)).
  static Result<std::unique_ptr<BenchConsole>> start();
  ~BenchConsole();
  BenchConsole(const BenchConsole&) = delete;
  BenchConsole& operator=(const BenchConsole&) = delete;

  /// The class control: a frame listener for the Runtime of the frames with the console.
  std::shared_ptr<FrameListener> listener() const;
  /// Whether a browser watches now (its WebSocket open, pushes read). Cheap: a flag the watcher follows.
  void watch(bool on) { watching_.store(on, std::memory_order_relaxed); }
  /// WebSocket bytes the watcher has read (a check that it watched).
  std::uint64_t bytes_read() const { return bytes_.load(); }

  struct Parts;

 private:
  BenchConsole() = default;
  void run_watcher();

  std::unique_ptr<Parts> parts_;
  std::atomic<bool> watching_{false}, stop_{false};
  std::atomic<std::uint64_t> bytes_{0};
  std::thread watcher_;
};

}  // namespace lungar::platform::bench
