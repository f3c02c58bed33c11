/// @file console_sessions.cpp
/// @brief Sessions, nonces and the failed-login throttle of console_sessions.h.
#include "platform/console/console_sessions.h"

#include "drivers/classroom/console_login_line.h"

#include <openssl/rand.h>

#include <algorithm>
#include <vector>

namespace lungar::console {

Result<std::string> random_hex(std::size_t count) {
  std::vector<unsigned char> bytes(count);
  if (RAND_bytes(bytes.data(), static_cast<int>(bytes.size())) != 1)
    return fail("console: OpenSSL's RAND_bytes gave no random bytes");
  return classroom::to_hex(bytes);
}

Result<std::string> ConsoleSessions::open(const ConsoleUser& user, ConsoleClock::time_point now) {
  auto cookie = random_hex(32), csrf = random_hex(32);
  if (!cookie) return cookie;
  if (!csrf) return csrf;
  // Forget the expired first; if still full, the oldest session ends.
  for (auto it = sessions_.begin(); it != sessions_.end();)
    it = now - it->second.started >= kLifetime ? sessions_.erase(it) : std::next(it);
  if (sessions_.size() >= kMaxSessions) {
    sessions_.erase(std::min_element(sessions_.begin(), sessions_.end(),
                                     [](const auto& a, const auto& b) { return a.second.started < b.second.started; }));
  }
  sessions_[*cookie] = ConsoleSession{user, *csrf, now, {}};
  return cookie;
}

ConsoleSession* ConsoleSessions::find(const std::string& cookie, ConsoleClock::time_point now) {
  auto it = sessions_.find(cookie);
  if (it == sessions_.end()) return nullptr;
  if (now - it->second.started >= kLifetime) {
    sessions_.erase(it);
    return nullptr;
  }
  return &it->second;
}

void ConsoleSessions::close(const std::string& cookie) { sessions_.erase(cookie); }

std::string ConsoleSessions::use_nonce(ConsoleSession& session, const std::string& nonce) {
  const bool hex = std::all_of(nonce.begin(), nonce.end(), [](char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
  });
  if (nonce.empty()) return "no X-Request-Nonce";
  if (!hex || nonce.size() < 16 || nonce.size() > 64) return "X-Request-Nonce: expected 16 to 64 hex digits";
  if (session.nonces.size() >= kMaxNonces) return "this session made its most requests: log in again";
  std::string lower = nonce;  // "AB" and "ab" are one nonce: a replay may not pass by changing the case
  std::transform(lower.begin(), lower.end(), lower.begin(), [](char c) { return c >= 'A' && c <= 'F' ? c + 32 : c; });
  if (!session.nonces.insert(lower).second) return "replayed nonce";
  return "";
}

void LoginThrottle::forget_old(ConsoleClock::time_point now) {
  for (auto it = failures_.begin(); it != failures_.end();) {
    auto& times = it->second;
    while (!times.empty() && now - times.front() >= kWindow) times.pop_front();
    it = times.empty() ? failures_.erase(it) : std::next(it);
  }
}

bool LoginThrottle::throttled(const std::string& address, ConsoleClock::time_point now) {
  forget_old(now);
  auto it = failures_.find(address);
  return it != failures_.end() && it->second.size() >= static_cast<std::size_t>(kMaxFailures);
}

void LoginThrottle::failed(const std::string& address, ConsoleClock::time_point now) {
  forget_old(now);
  auto& times = failures_[address];
  // Bounded: the throttle refuses before a failure is recorded past the limit, but keep it so regardless.
  if (times.size() < static_cast<std::size_t>(kMaxFailures) * 2) times.push_back(now);
}

}  // namespace lungar::console
