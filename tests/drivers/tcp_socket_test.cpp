/// @file tcp_socket_test.cpp
/// @brief TcpSocket on loopback: a read with nothing to read times out and a closed peer reads as closed, whatever
///        errno an earlier call left behind; write_all waits for a reader and gives up on a peer that never reads.
#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "drivers/igtl/tcp_socket.h"

namespace lungar::drivers {
namespace {

/// The third field (the maximum, bytes) of /proc/sys/net/ipv4/`name`, or 64 MiB where it cannot be read.
std::size_t kernel_max(const std::string& name) {
  std::ifstream in("/proc/sys/net/ipv4/" + name);
  std::size_t low = 0, initial = 0, most = 0;
  return in >> low >> initial >> most ? most : std::size_t{64} << 20;
}

/// A connected pair on 127.0.0.1: `near` from connect() (non-blocking), `far` from accept().
struct Pair {
  TcpListener listener;
  TcpSocket near, far;
  Pair() {
    auto l = TcpListener::listen("127.0.0.1", 0);
    EXPECT_TRUE(l) << l.error();
    if (!l) return;
    listener = l.take();
    auto c = TcpSocket::connect("127.0.0.1", listener.port(), 1000);
    EXPECT_TRUE(c) << c.error();
    if (c) near = c.take();
    auto a = listener.accept(1000);
    EXPECT_TRUE(a.has_value());
    if (a) far = std::move(*a);
  }
};

// errno means something only after a failed call: a poll that timed out, or a recv that read the peer's close,
// is not an interrupted or a would-block call because an earlier one left EINTR or EAGAIN behind.
TEST(TcpSocket, ATimeoutAndAClosedPeerAreSeenWhateverErrnoWasLeft) {
  Pair p;
  std::uint8_t buf[16];
  errno = EINTR;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(p.near.read_some(buf, sizeof buf, 50), 0) << "nothing was sent: timed out";
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
  p.far.close();
  errno = EAGAIN;
  EXPECT_EQ(p.near.read_some(buf, sizeof buf, 1000), -1) << "the peer closed";
}

// A message far larger than the socket buffers: write_all waits for room while the peer reads, and gives up (after
// a second without room) on a peer that stopped reading instead of blocking for ever.
TEST(TcpSocket, WriteAllWaitsForAReaderAndGivesUpOnOneThatNeverReads) {
  Pair p;
  const std::vector<std::uint8_t> big(32u << 20, 0x5a);
  std::size_t received = 0;
  std::thread reader([&] {
    std::vector<std::uint8_t> buf(1u << 16);
    for (long n = 1; received < big.size() && n > 0;) {
      n = p.far.read_some(buf.data(), buf.size(), 2000);
      if (n > 0) received += static_cast<std::size_t>(n);
    }
  });
  EXPECT_TRUE(p.near.write_all(big));
  reader.join();
  EXPECT_EQ(received, big.size());
  // Nobody reads any more: the write must outgrow what both sockets' buffers can hold, and the first transfer has
  // let the kernel autotune the reader's buffer up to its maximum (tcp_rmem's third field: 32 MiB on Debian 12's
  // defaults here, so 32 MiB could fit whole and the write succeed), plus the writer's (tcp_wmem's).
  const std::vector<std::uint8_t> more(2 * (kernel_max("tcp_rmem") + kernel_max("tcp_wmem")) + (1u << 20), 0x5a);
  EXPECT_FALSE(p.near.write_all(more)) << "nobody reads any more";
}

}  // namespace
}  // namespace lungar::drivers
