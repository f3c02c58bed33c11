/// @file console_logins.cpp
/// @brief The logins file of console_logins.h: reading it, checking a password, making a line.
#include "platform/console/console_logins.h"

#include "drivers/classroom/console_login_line.h"

#include <openssl/crypto.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace lungar::console {
namespace {

constexpr std::size_t kHashBytes = 32;  // SHA-256's output

std::optional<std::vector<unsigned char>> from_hex(const std::string& s) {
  if (s.size() % 2 != 0) return std::nullopt;
  std::vector<unsigned char> out;
  for (std::size_t i = 0; i < s.size(); i += 2) {
    const auto nibble = [](char c) -> int {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      if (c >= 'A' && c <= 'F') return c - 'A' + 10;
      return -1;
    };
    const int hi = nibble(s[i]), lo = nibble(s[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out.push_back(static_cast<unsigned char>(hi * 16 + lo));
  }
  return out;
}

bool good_name(const std::string& name) {
  return !name.empty() && name.size() <= 63 && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
  });
}

}  // namespace

const char* role_name(Role role) { return role == Role::Instructor ? "instructor" : "observer"; }

Result<ConsoleLogins> ConsoleLogins::read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path + ": cannot read it (the console's logins, made by lungar classroom-keys)");
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

Result<ConsoleLogins> ConsoleLogins::parse(const std::string& text, const std::string& path) {
  ConsoleLogins out;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string where = path + ":" + std::to_string(number) + ": ";
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string w; fields >> w;) f.push_back(w);
    if (f.empty() || f[0][0] == '#') continue;
    if (f.size() != 6)
      return fail(where + "expected 6 fields, NAME ROLE pbkdf2-sha256 ITERATIONS SALT_HEX HASH_HEX, got " +
                  std::to_string(f.size()));
    ConsoleLogin login;
    login.name = f[0];
    if (!good_name(login.name))
      return fail(where + "NAME: expected 1 to 63 letters, digits, '-', '_' or '.', got \"" + f[0] + "\"");
    if (std::any_of(out.logins_.begin(), out.logins_.end(), [&](const ConsoleLogin& l) { return l.name == f[0]; }))
      return fail(where + "NAME: \"" + f[0] + "\" is given twice");
    if (f[1] == "instructor") {
      login.role = Role::Instructor;
    } else if (f[1] == "observer") {
      login.role = Role::Observer;
    } else {
      return fail(where + "ROLE: expected instructor or observer, got \"" + f[1] + "\"");
    }
    if (f[2] != "pbkdf2-sha256") return fail(where + "scheme: expected pbkdf2-sha256, got \"" + f[2] + "\"");
    std::size_t used = 0;
    long iterations = 0;
    try {
      iterations = std::stol(f[3], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != f[3].size() || iterations < 1000 || iterations > 10000000)
      return fail(where + "ITERATIONS: expected a whole number in [1000, 10000000], got \"" + f[3] + "\"");
    login.iterations = static_cast<int>(iterations);
    auto salt = from_hex(f[4]);
    if (!salt || salt->size() < 8 || salt->size() > 64)
      return fail(where + "SALT_HEX: expected 16 to 128 hex digits, got \"" + f[4] + "\"");
    login.salt = *salt;
    auto hash = from_hex(f[5]);
    if (!hash || hash->size() != kHashBytes)
      return fail(where + "HASH_HEX: expected 64 hex digits (SHA-256), got \"" + f[5] + "\"");
    login.hash = *hash;
    out.logins_.push_back(std::move(login));
  }
  if (out.logins_.empty()) return fail(path + ": expected at least one login, found none");
  return out;
}

std::optional<ConsoleUser> ConsoleLogins::verify(const std::string& name, const std::string& password) const {
  const auto found =
      std::find_if(logins_.begin(), logins_.end(), [&](const ConsoleLogin& l) { return l.name == name; });
  // An unknown name is hashed against the first login's salt all the same: its answer takes as long as a wrong
  // password's, so the time does not say which names exist.
  const ConsoleLogin& against = found != logins_.end() ? *found : logins_.front();
  const auto hash = classroom::login_hash(password, against.salt, against.iterations);
  if (!hash) return std::nullopt;
  const bool same = CRYPTO_memcmp(hash->data(), against.hash.data(), kHashBytes) == 0;
  if (found == logins_.end() || !same) return std::nullopt;
  return ConsoleUser{found->name, found->role};
}

Result<std::string> make_login_line(const std::string& name, Role role, const std::string& password, int iterations) {
  if (!good_name(name))
    return fail("login name: expected 1 to 63 letters, digits, '-', '_' or '.', got \"" + name + "\"");
  return classroom::make_login_line(name, role_name(role), password, iterations);
}

}  // namespace lungar::console
