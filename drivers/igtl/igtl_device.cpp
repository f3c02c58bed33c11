/// @file igtl_device.cpp
/// @brief The OpenIGTLink reader thread: connect with back-off, read header then body, decode whole messages and
/// hand their poses, with the bytes, to the pipeline.
#include <algorithm>
#include <array>
#include <chrono>
#include <thread>

#include "drivers/igtl/igtl_decoder.h"
#include "drivers/igtl/igtl_interface.h"
#include "drivers/igtl/tcp_socket.h"
#include "drivers/tracker/reopen_backoff.h"
#include "drivers/tracker/tracker_core.h"
#include "drivers/tracker/tracker_device.h"

namespace lungar::drivers {

namespace {

constexpr int kPollMs = 10;  ///< longest wait on the socket, so that stop and staleness are noticed
/// Bodies of types lungar does not read (images from Slicer) are skipped; beyond this the stream is garbage.
constexpr std::uint64_t kMaxSkip = 1ull << 30;

class IgtlDevice final : public TrackerDevice {
 public:
  IgtlDevice(const IgtlConfig& s, double reopen_backoff_ms, const IgtlLayout& layout)
      : igtl_(s), layout_(layout), backoff_(reopen_backoff_ms) {}

  void run(TrackerCore& core, std::stop_token stop) override {
    bool ever_connected = false, failure_logged = false;
    core.set_state(TrackerState::Disconnected);
    while (!stop.stop_requested()) {
      if (sock_.is_open()) {
        if (!read_step(core)) lose(core);
        core.tick(monotonic_ns());
        continue;
      }
      if (!backoff_.due(monotonic_ns())) {
        std::this_thread::sleep_for(std::chrono::milliseconds(kPollMs));
        core.tick(monotonic_ns());
        continue;
      }
      core.set_state(TrackerState::Opening);
      auto s = TcpSocket::connect(igtl_.host, igtl_.port, static_cast<int>(igtl_.connect_timeout_ms));
      if (!s) {
        if (!failure_logged) {  // once per outage: a server that is not up yet is no flood of lines
          core.log(-1, "igtl: %s; retrying with back-off from %lld ms", s.error().c_str(), backoff_.first_ms());
          failure_logged = true;
        }
        core.set_state(TrackerState::Disconnected);
        backoff_.failed(monotonic_ns());
        continue;
      }
      sock_ = s.take();
      core.log(-1, "igtl: connected to %s:%d", igtl_.host.c_str(), igtl_.port);
      if (ever_connected) core.count_reconnect();
      ever_connected = true;
      failure_logged = false;
      backoff_.opened();
      core.count_open();  // stays "opening" until the first pose
      have_ = 0;
      need_ = kIgtlHeaderBytes;
      skip_ = 0;
    }
    sock_.close();
  }

  std::string describe() const override {
    return "igtl " + igtl_.host + ":" + std::to_string(igtl_.port) + " (head '" + igtl_.head + "', patient '" +
           igtl_.patient + "', stylus '" + igtl_.stylus + "')";
  }
  std::string trk_description() const override {
    return "source=igtl\nhost=" + igtl_.host + "\nport=" + std::to_string(igtl_.port) + "\n";
  }
  TrkSource trk_source() const override { return TrkSource::Igtl; }

 private:
  /// One bounded read: skips an unread body, or fills the header, then the body; a complete message goes to
  /// the pipeline. False when the connection is gone (what arrived of a message is fed first: it is counted).
  bool read_step(TrackerCore& core) {
    if (skip_ > 0) {
      const long n =
          sock_.read_some(buf_.data(), static_cast<std::size_t>(std::min<std::uint64_t>(skip_, buf_.size())), kPollMs);
      if (n > 0) skip_ -= static_cast<std::uint64_t>(n);
      return n >= 0;
    }
    const long n = sock_.read_some(buf_.data() + have_, need_ - have_, kPollMs);
    const std::int64_t t = monotonic_ns();
    if (n < 0) {
      if (have_ > 0) feed(core, t);  // cut short
      core.log(-1, "igtl: %s:%d closed the connection; reconnecting", igtl_.host.c_str(), igtl_.port);
      return false;
    }
    have_ += static_cast<std::size_t>(n);
    if (have_ < need_) return true;
    if (need_ == kIgtlHeaderBytes) {
      const IgtlHeaderInfo info =
          igtl_header_info(std::span<const std::uint8_t, kIgtlHeaderBytes>(buf_.data(), kIgtlHeaderBytes));
      if (info.readable && info.body_size > 0) {
        need_ = kIgtlHeaderBytes + static_cast<std::size_t>(info.body_size);
        return true;
      }
      // A type lungar does not read (or an unsupported header): the header alone is recorded and counted, the
      // body is skipped unread.
      skip_ = info.body_size;
      if (skip_ > kMaxSkip) {
        feed(core, t);
        core.log(-1, "igtl: a header announces %llu bytes: not an OpenIGTLink stream; reconnecting",
                 static_cast<unsigned long long>(skip_));
        return false;
      }
    }
    feed(core, t);
    have_ = 0;
    need_ = kIgtlHeaderBytes;
    return true;
  }

  /// What arrived of the message (all of it, or its header, or the part before the connection closed): decoded
  /// here, recorded as TrkSource::Igtl so that replay decodes it the same way.
  void feed(TrackerCore& core, std::int64_t t_arrival_ns) {
    const std::span<const std::uint8_t> message(buf_.data(), have_);
    core.feed_decoded(TrkSource::Igtl, message, decode_igtl_message(message, layout_), t_arrival_ns);
  }

  void lose(TrackerCore& core) {
    sock_.close();
    core.set_state(TrackerState::Disconnected);
    backoff_.lost(monotonic_ns());
  }

  IgtlConfig igtl_;
  IgtlLayout layout_;
  ReopenBackoff backoff_;
  TcpSocket sock_;
  std::array<std::uint8_t, kIgtlHeaderBytes + kIgtlMaxBody> buf_{};
  std::size_t have_ = 0, need_ = kIgtlHeaderBytes;
  std::uint64_t skip_ = 0;
};

}  // namespace

std::unique_ptr<TrackerDevice> igtl_create(const IgtlConfig& settings, double reopen_backoff_ms,
                                           const IgtlLayout& layout) {
  return std::make_unique<IgtlDevice>(settings, reopen_backoff_ms, layout);
}

}  // namespace lungar::drivers
