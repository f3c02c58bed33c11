/// @file tcp_socket.cpp
/// @brief Non-blocking connect bounded by poll(), reads bounded by poll(), sends with MSG_NOSIGNAL.
#include "drivers/igtl/tcp_socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace lungar::drivers {

namespace {

/// Waits for `events` on `fd` for at most `timeout_ms`, retrying on signals: > 0 ready, 0 timed out, < 0 failed.
int wait_for(int fd, short events, int timeout_ms) {
  pollfd p{fd, events, 0};
  int r;
  do {
    r = ::poll(&p, 1, timeout_ms);
  } while (r < 0 && errno == EINTR);
  return r;
}

}  // namespace

Result<TcpSocket> TcpSocket::connect(const std::string& host, int port, int timeout_ms) {
  const std::string where = host + ":" + std::to_string(port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int rc = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found); rc != 0) {
    return fail(where + ": unknown host (" + gai_strerror(rc) + ")");
  }
  std::string why = "no address";
  TcpSocket sock;
  for (addrinfo* a = found; a && !sock.is_open(); a = a->ai_next) {
    TcpSocket s(::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol));
    if (!s.is_open()) {
      why = std::strerror(errno);
      continue;
    }
    int rc = ::connect(s.fd_.get(), a->ai_addr, a->ai_addrlen);
    if (rc < 0 && errno == EINPROGRESS) {
      const int ready = wait_for(s.fd_.get(), POLLOUT, timeout_ms);
      int err = 0;
      socklen_t len = sizeof err;
      if (ready == 0) {
        err = ETIMEDOUT;
      } else if (ready < 0 || ::getsockopt(s.fd_.get(), SOL_SOCKET, SO_ERROR, &err, &len) < 0) {
        err = errno;
      }
      rc = err == 0 ? 0 : -1;
      errno = err;
    }
    if (rc < 0) {
      why = std::strerror(errno);
      continue;
    }
    const int one = 1;  // poses are small and late ones are useless: no Nagle delay
    ::setsockopt(s.fd_.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    sock = std::move(s);
  }
  ::freeaddrinfo(found);
  if (!sock.is_open()) return fail(where + ": cannot connect (" + why + ")");
  return sock;
}

long TcpSocket::read_some(std::uint8_t* out, std::size_t n, int timeout_ms) {
  if (!fd_) return -1;
  const int ready = wait_for(fd_.get(), POLLIN, timeout_ms);
  if (ready == 0) return 0;
  if (ready < 0) return -1;
  ssize_t got;
  do {
    got = ::recv(fd_.get(), out, n, 0);
  } while (got < 0 && errno == EINTR);
  if (got < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return 0;
  return got > 0 ? static_cast<long>(got) : -1;  // 0: the peer closed the connection
}

bool TcpSocket::write_all(std::span<const std::uint8_t> bytes) {
  std::size_t done = 0;
  while (fd_ && done < bytes.size()) {
    const ssize_t w = ::send(fd_.get(), bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (wait_for(fd_.get(), POLLOUT, 1000) <= 0) return false;
      continue;
    }
    if (w <= 0) return false;
    done += static_cast<std::size_t>(w);
  }
  return static_cast<bool>(fd_);
}

Result<TcpListener> TcpListener::listen(const std::string& address, int port) {
  const std::string where = address + ":" + std::to_string(port);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  if (port < 0 || port > 65535 || ::inet_pton(AF_INET, address.c_str(), &a.sin_addr) != 1) {
    return fail(where + ": expected an IPv4 address and a port in [0, 65535]");
  }
  TcpListener l;
  l.fd_.reset(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (!l.fd_) return fail(where + ": cannot create a socket (" + std::strerror(errno) + ")");
  const int one = 1;
  ::setsockopt(l.fd_.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(l.fd_.get(), reinterpret_cast<sockaddr*>(&a), sizeof a) < 0 || ::listen(l.fd_.get(), 4) < 0) {
    return fail(where + ": cannot listen (" + std::strerror(errno) + ")");
  }
  socklen_t len = sizeof a;
  ::getsockname(l.fd_.get(), reinterpret_cast<sockaddr*>(&a), &len);
  l.port_ = ntohs(a.sin_port);
  return l;
}

std::optional<TcpSocket> TcpListener::accept(int timeout_ms) {
  if (!fd_ || wait_for(fd_.get(), POLLIN, timeout_ms) <= 0) return std::nullopt;
  const int fd = ::accept4(fd_.get(), nullptr, nullptr, SOCK_CLOEXEC);
  if (fd < 0) return std::nullopt;
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  return TcpSocket(fd);
}

}  // namespace lungar::drivers
