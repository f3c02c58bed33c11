/// @file console_logins.h
/// @brief The console's logins file (DIR/console/logins of `lungar classroom-keys`): one line per login,
///        `NAME ROLE pbkdf2-sha256 ITERATIONS SALT_HEX HASH_HEX`, read with one error line naming the file, the line
///        and the field; a password checked through OpenSSL's PBKDF2-HMAC-SHA256 and a constant-time compare.
/// @ingroup platform
///
/// Only a hash is stored: the passwords themselves go to the trainer (instructor.password, observer.password). A
/// classroom station's DDS identity is never a login: nothing here reads a certificate.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "drivers/classroom/console_login_line.h"
#include "platform/console/console_handler.h"

namespace lungar::console {

/// One line of the logins file.
struct ConsoleLogin {
  std::string name;
  Role role = Role::Observer;
  int iterations = 0;
  std::vector<unsigned char> salt;
  std::vector<unsigned char> hash;  ///< PBKDF2-HMAC-SHA256(password, salt, iterations), 32 bytes
};

using classroom::kConsoleLoginIterations;
using classroom::random_password;

/// "instructor" or "observer".
const char* role_name(Role role);

class ConsoleLogins {
 public:
  /// Reads `path`; an error names the file, the line and the field ("logins:3: ITERATIONS: expected ...").
  static Result<ConsoleLogins> read(const std::string& path);
  /// Parses a whole file's text; `path` names it in errors.
  static Result<ConsoleLogins> parse(const std::string& text, const std::string& path);

  /// The user with this name and password, or none. Takes the same time for an unknown name as for a wrong
  /// password (a hash is computed either way).
  std::optional<ConsoleUser> verify(const std::string& name, const std::string& password) const;

  const std::vector<ConsoleLogin>& logins() const { return logins_; }

 private:
  std::vector<ConsoleLogin> logins_;
};

/// A logins-file line (no newline) for `name` with this role and password: a fresh random salt (16 bytes).
Result<std::string> make_login_line(const std::string& name, Role role, const std::string& password,
                                    int iterations = kConsoleLoginIterations);

}  // namespace lungar::console
