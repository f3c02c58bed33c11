/// @file console_login_line.h
/// @brief A line of the instructor's console's logins file, `NAME ROLE pbkdf2-sha256 ITERATIONS SALT_HEX HASH_HEX`,
///        and the random passwords behind them: written here, where `lungar classroom-keys` makes the console's
///        folder, and read by the console (platform/console/console_logins.h), which checks a password with the
///        same hash.
/// @ingroup platform
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::classroom {

/// The PBKDF2 iterations a new login gets. Generated passwords (20 characters, ~119 bits) need few; a password a
/// trainer sets by hand gets this many so that a stolen logins file costs a guesser ~0.1 s per try and core.
inline constexpr int kConsoleLoginIterations = 200000;

/// PBKDF2-HMAC-SHA256 of `password` (32 bytes), through OpenSSL; none when OpenSSL fails.
std::optional<std::vector<unsigned char>> login_hash(const std::string& password,
                                                     const std::vector<unsigned char>& salt, int iterations);

/// Lower-case hex of `bytes`.
std::string to_hex(const std::vector<unsigned char>& bytes);

/// A logins-file line (no newline) for `name` with role `role` ("instructor" or "observer") and `password`: a fresh
/// random salt (16 bytes).
Result<std::string> make_login_line(const std::string& name, const std::string& role, const std::string& password,
                                    int iterations = kConsoleLoginIterations);

/// A random password of `length` characters from letters and digits (OpenSSL's RAND_bytes, unbiased; no 0/O, 1/l/I).
Result<std::string> random_password(std::size_t length = 20);

}  // namespace lungar::classroom
