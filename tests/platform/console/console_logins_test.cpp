/// @file console_logins_test.cpp
/// @brief The console's logins file (console_logins.h): a made line verifies its password and no other; each bad
///        line is refused with one error naming the file, the line and the field. And the sessions' bookkeeping
///        (console_sessions.h): a session ends after its lifetime, a nonce is used once, failed logins throttle.
#include <gtest/gtest.h>

#include "platform/console/console_logins.h"
#include "platform/console/console_sessions.h"

namespace lungar::console {
namespace {

TEST(ConsoleLogins, AMadeLineVerifiesItsPasswordAndNoOther) {
  auto line = make_login_line("instructor", Role::Instructor, "correct horse", 1000);
  ASSERT_TRUE(line) << line.error();
  auto obs = make_login_line("observer", Role::Observer, "battery staple", 1000);
  ASSERT_TRUE(obs) << obs.error();
  auto logins = ConsoleLogins::parse("# a comment\n\n" + *line + "\n" + *obs + "\n", "logins");
  ASSERT_TRUE(logins) << logins.error();
  ASSERT_EQ(logins->logins().size(), 2u);
  auto who = logins->verify("instructor", "correct horse");
  ASSERT_TRUE(who);
  EXPECT_EQ(who->name, "instructor");
  EXPECT_EQ(who->role, Role::Instructor);
  auto watcher = logins->verify("observer", "battery staple");
  ASSERT_TRUE(watcher);
  EXPECT_EQ(watcher->role, Role::Observer);
  EXPECT_FALSE(logins->verify("instructor", "correct horse "));
  EXPECT_FALSE(logins->verify("instructor", "battery staple")) << "another login's password";
  EXPECT_FALSE(logins->verify("nobody", "correct horse"));
  EXPECT_FALSE(logins->verify("", ""));
}

TEST(ConsoleLogins, EachBadLineNamesTheFileTheLineAndTheField) {
  auto good = make_login_line("instructor", Role::Instructor, "pw", 1000);
  ASSERT_TRUE(good);
  const std::string salt(32, 'a'), hash(64, 'b');
  struct Case {
    std::string line, expected;
  };
  const Case cases[] = {
      {"instructor instructor pbkdf2-sha256 1000 " + salt, "logins:2: expected 6 fields"},
      {"in/structor instructor pbkdf2-sha256 1000 " + salt + " " + hash, "logins:2: NAME:"},
      {"boss admin pbkdf2-sha256 1000 " + salt + " " + hash, "logins:2: ROLE: expected instructor or observer"},
      {"boss observer md5 1000 " + salt + " " + hash, "logins:2: scheme: expected pbkdf2-sha256"},
      {"boss observer pbkdf2-sha256 10x " + salt + " " + hash, "logins:2: ITERATIONS:"},
      {"boss observer pbkdf2-sha256 10 " + salt + " " + hash, "logins:2: ITERATIONS:"},
      {"boss observer pbkdf2-sha256 1000 xyz " + hash, "logins:2: SALT_HEX:"},
      {"boss observer pbkdf2-sha256 1000 " + salt + " " + hash.substr(2), "logins:2: HASH_HEX:"},
      {"instructor observer pbkdf2-sha256 1000 " + salt + " " + hash, "logins:2: NAME: \"instructor\" is given twice"},
  };
  for (const Case& c : cases) {
    auto read = ConsoleLogins::parse(*good + "\n" + c.line + "\n", "logins");
    ASSERT_FALSE(read) << c.line;
    EXPECT_EQ(read.error().rfind(c.expected, 0), 0u) << read.error();
    EXPECT_EQ(read.error().find('\n'), std::string::npos) << "one line";
  }
  auto none = ConsoleLogins::parse("# nothing\n", "logins");
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().find("logins: expected at least one login"), std::string::npos) << none.error();
  auto missing = ConsoleLogins::read("/nonexistent/console/logins");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().rfind("/nonexistent/console/logins: cannot read it", 0), 0u) << missing.error();
}

TEST(ConsoleLogins, RandomPasswordsAreLongAndDiffer) {
  auto a = random_password(20), b = random_password(20);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->size(), 20u);
  EXPECT_NE(*a, *b);
}

TEST(ConsoleSessions, ASessionEndsAfterItsLifetimeAndLogoutEndsItAtOnce) {
  ConsoleSessions sessions;
  const auto t0 = ConsoleClock::now();
  auto cookie = sessions.open({"instructor", Role::Instructor}, t0);
  ASSERT_TRUE(cookie);
  EXPECT_EQ(cookie->size(), 64u) << "32 random bytes, hex";
  ASSERT_NE(sessions.find(*cookie, t0 + std::chrono::hours(11)), nullptr);
  EXPECT_EQ(sessions.find(*cookie, t0 + ConsoleSessions::kLifetime), nullptr);
  EXPECT_EQ(sessions.find(*cookie, t0), nullptr) << "forgotten once expired";
  auto other = sessions.open({"observer", Role::Observer}, t0);
  ASSERT_TRUE(other);
  EXPECT_EQ(sessions.find(*other, t0)->user.name, "observer");
  sessions.close(*other);
  EXPECT_EQ(sessions.find(*other, t0), nullptr);
  EXPECT_EQ(sessions.find("", t0), nullptr);
}

TEST(ConsoleSessions, ANonceIsUsedOnceAndMustBeHex) {
  ConsoleSession s;
  EXPECT_EQ(ConsoleSessions::use_nonce(s, "0123456789abcdef"), "");
  EXPECT_EQ(ConsoleSessions::use_nonce(s, "0123456789abcdef"), "replayed nonce");
  EXPECT_EQ(ConsoleSessions::use_nonce(s, "0123456789ABCDEF"), "replayed nonce") << "case is no new nonce";
  EXPECT_EQ(ConsoleSessions::use_nonce(s, ""), "no X-Request-Nonce");
  EXPECT_NE(ConsoleSessions::use_nonce(s, "0123456789abcde"), "") << "15 digits";
  EXPECT_NE(ConsoleSessions::use_nonce(s, std::string(65, 'a')), "");
  EXPECT_NE(ConsoleSessions::use_nonce(s, "0123456789abcdeg"), "");
  EXPECT_EQ(ConsoleSessions::use_nonce(s, std::string(64, 'a')), "");
}

TEST(ConsoleSessions, MoreThanTenFailedLoginsAMinuteThrottleThatAddressOnly) {
  LoginThrottle throttle;
  const auto t0 = ConsoleClock::now();
  for (int i = 0; i < LoginThrottle::kMaxFailures; ++i) {
    EXPECT_FALSE(throttle.throttled("10.0.0.7", t0)) << i;
    throttle.failed("10.0.0.7", t0);
  }
  EXPECT_TRUE(throttle.throttled("10.0.0.7", t0 + std::chrono::seconds(59)));
  EXPECT_FALSE(throttle.throttled("10.0.0.8", t0));
  EXPECT_FALSE(throttle.throttled("10.0.0.7", t0 + LoginThrottle::kWindow));
}

}  // namespace
}  // namespace lungar::console
