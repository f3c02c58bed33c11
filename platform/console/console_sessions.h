/// @file console_sessions.h
/// @brief The console's logged-in sessions (a random cookie each, with its CSRF token, its user and the nonces its
///        control requests used) and the throttle of failed logins per address: the server's bookkeeping, kept
///        apart from HTTP so that it reads, and is tested, on its own.
/// @ingroup platform
///
/// Not thread-safe: the server calls it on its one thread.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <unordered_set>

#include "config/base/result.h"
#include "platform/console/console_handler.h"

namespace lungar::console {

using ConsoleClock = std::chrono::steady_clock;

/// One login's session.
struct ConsoleSession {
  ConsoleUser user;
  std::string csrf;  ///< sent back in X-CSRF-Token with every control request
  ConsoleClock::time_point started;
  std::unordered_set<std::string> nonces;  ///< X-Request-Nonce values already used
};

class ConsoleSessions {
 public:
  /// A session lasts this long from its login (a class day), then its cookie is refused.
  static constexpr std::chrono::hours kLifetime{12};
  /// At most this many sessions at once: a new login beyond them ends the oldest.
  static constexpr std::size_t kMaxSessions = 64;
  /// At most this many control requests a session: past them it must log in again (bounds its nonce record).
  static constexpr std::size_t kMaxNonces = 100000;

  /// A new session for `user`: its cookie value (32 random bytes, hex). An error if no random bytes came.
  Result<std::string> open(const ConsoleUser& user, ConsoleClock::time_point now);
  /// The live session of this cookie value, or none (unknown, or expired: then it is forgotten).
  ConsoleSession* find(const std::string& cookie, ConsoleClock::time_point now);
  void close(const std::string& cookie);

  /// Why `nonce` is refused for this session ("" when it is fresh: then it is recorded as used).
  static std::string use_nonce(ConsoleSession& session, const std::string& nonce);

  std::size_t size() const { return sessions_.size(); }

 private:
  std::map<std::string, ConsoleSession> sessions_;
};

/// Failed logins from one address: more than kMaxFailures within kWindow and its logins are refused (429) until the
/// window has moved past them.
class LoginThrottle {
 public:
  static constexpr int kMaxFailures = 10;
  static constexpr std::chrono::seconds kWindow{60};

  bool throttled(const std::string& address, ConsoleClock::time_point now);
  void failed(const std::string& address, ConsoleClock::time_point now);

 private:
  void forget_old(ConsoleClock::time_point now);
  std::map<std::string, std::deque<ConsoleClock::time_point>> failures_;
};

/// `count` random bytes as hex (OpenSSL's RAND_bytes), or an error.
Result<std::string> random_hex(std::size_t count);

}  // namespace lungar::console
