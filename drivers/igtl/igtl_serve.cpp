/// @file igtl_serve.cpp
/// @brief The serve loop: accept, then send on absolute deadlines until the client leaves.
#include "drivers/igtl/igtl_serve.h"

#include <chrono>
#include <ctime>
#include <thread>
#include <utility>
#include <vector>

#include "drivers/igtl/igtl_messages.h"
#include "drivers/igtl/tcp_socket.h"
#include "drivers/mock/mock_trajectory.h"

namespace lungar::drivers {

namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t unix_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::uint64_t>(ts.tv_sec) * 1'000'000'000u + static_cast<std::uint64_t>(ts.tv_nsec);
}

/// Streams to `client` until it leaves, `stop` is set or `end` passes. False when the client left.
bool stream(TcpSocket& client, const ServeIgtlOptions& o, const std::vector<std::pair<Role, std::string>>& devices,
            const std::atomic<bool>& stop, Clock::time_point end) {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / o.rate_hz));
  const auto start = Clock::now();
  auto next = start;
  for (std::int64_t k = 0; !stop.load() && Clock::now() < end; ++k) {
    const double t_s = std::chrono::duration<double>(next - start).count();
    const IgtlTime time = IgtlTime::from_ns(unix_ns());
    for (const auto& [role, name] : devices) {
      const PoseSample p = *mock_pose(o.trajectory, role, t_s);
      if (!client.write_all(igtl_transform_message(name, p.transform().matrix(), time))) return false;
    }
    next += period;
    std::this_thread::sleep_until(next);
  }
  return true;
}

}  // namespace

Status serve_igtl(const ServeIgtlOptions& o, const std::atomic<bool>& stop,
                  const std::function<void(const std::string&)>& log,
                  const std::function<void(int port)>& on_listening) {
  if (!mock_pose(o.trajectory, Role::Patient, 0.0)) {
    return fail(unknown_trajectory("--trajectory", o.trajectory));
  }
  if (!(o.rate_hz > 0)) return fail("--rate-hz: expected a positive rate, got " + std::to_string(o.rate_hz));
  std::vector<std::pair<Role, std::string>> devices;
  for (const auto& [role, name] :
       {std::pair{Role::Head, o.head}, {Role::Patient, o.patient}, {Role::Stylus, o.stylus}}) {
    if (!name.empty()) devices.emplace_back(role, name);
  }
  auto listener = TcpListener::listen(o.address, o.port);
  if (!listener) return Error{listener.error()};
  if (on_listening) on_listening(listener->port());
  const auto end =
      o.seconds > 0
          ? Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds))
          : Clock::time_point::max();
  while (!stop.load() && Clock::now() < end) {
    auto client = listener->accept(100);
    if (!client) continue;
    log("client connected; streaming " + std::to_string(devices.size()) + " device(s) at " +
        std::to_string(static_cast<int>(o.rate_hz)) + " Hz");
    if (!stream(*client, o, devices, stop, end)) log("client left; waiting for the next");
  }
  return ok();
}

}  // namespace lungar::drivers
