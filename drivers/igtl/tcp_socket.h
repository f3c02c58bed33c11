/// @file tcp_socket.h
/// @brief A TCP connection and a listener on POSIX sockets, with timeouts everywhere, for the OpenIGTLink
/// source (client) and `lungar-trk serve-igtl` / the tests (server).
/// @ingroup drivers
///
/// Not libopenigtlink's igtl::Socket: its ConnectToServer blocks as long as the kernel's connect does (minutes
/// to a host that drops packets, so a stop request would wait), prints to stderr on every refused attempt, and
/// its Receive with a timeout drops the bytes of a message cut by the timeout. The message format itself is the
/// library's (drivers/igtl/igtl_decoder.cpp, igtl_server.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <unistd.h>

#include "config/base/result.h"
#include "config/base/unique_handle.h"

namespace lungar::drivers {

/// An owned file descriptor, closed once.
using UniqueFd = UniqueHandle<int, ::close, -1>;

class TcpSocket {
 public:
  TcpSocket() = default;
  explicit TcpSocket(int fd) : fd_(fd) {}

  /// Connects to host:port (a name or an address), giving up after `timeout_ms`. The error names host:port and
  /// the reason ("connection refused", "timed out", "unknown host").
  static Result<TcpSocket> connect(const std::string& host, int port, int timeout_ms);

  /// Reads what has arrived, up to `n` bytes, waiting at most `timeout_ms` for the first: the count (> 0), 0 when
  /// nothing came in time, -1 when the peer closed the connection or it failed. Allocates nothing.
  long read_some(std::uint8_t* out, std::size_t n, int timeout_ms);
  /// Sends all of `bytes` (no SIGPIPE when the peer is gone). False when the connection failed.
  bool write_all(std::span<const std::uint8_t> bytes);

  bool is_open() const { return static_cast<bool>(fd_); }
  void close() { fd_.reset(); }

 private:
  UniqueFd fd_;
};

class TcpListener {
 public:
  /// Listens on address:port (an IPv4 address; "0.0.0.0" for every interface; port 0: one the OS picks, see
  /// port()). The port may be reused at once after a previous listener closed (SO_REUSEADDR).
  static Result<TcpListener> listen(const std::string& address, int port);
  /// The next client, waiting at most `timeout_ms`; nullopt when none came.
  std::optional<TcpSocket> accept(int timeout_ms);
  int port() const { return port_; }
  void close() { fd_.reset(); }

 private:
  UniqueFd fd_;
  int port_ = 0;
};

}  // namespace lungar::drivers
