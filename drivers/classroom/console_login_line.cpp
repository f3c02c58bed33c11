/// @file console_login_line.cpp
/// @brief The console's login lines and passwords, on OpenSSL's PBKDF2 and RAND_bytes.
#include "drivers/classroom/console_login_line.h"

#include <openssl/evp.h>
#include <openssl/rand.h>

namespace lungar::classroom {

std::optional<std::vector<unsigned char>> login_hash(const std::string& password,
                                                     const std::vector<unsigned char>& salt, int iterations) {
  std::vector<unsigned char> out(32);  // SHA-256's output
  if (PKCS5_PBKDF2_HMAC(password.data(), static_cast<int>(password.size()), salt.data(), static_cast<int>(salt.size()),
                        iterations, EVP_sha256(), static_cast<int>(out.size()), out.data()) != 1)
    return std::nullopt;
  return out;
}

std::string to_hex(const std::vector<unsigned char>& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  for (unsigned char b : bytes) {
    s += digits[b >> 4];
    s += digits[b & 15];
  }
  return s;
}

Result<std::string> make_login_line(const std::string& name, const std::string& role, const std::string& password,
                                    int iterations) {
  if (password.empty()) return fail("login " + name + ": expected a password, got an empty one");
  std::vector<unsigned char> salt(16);
  if (RAND_bytes(salt.data(), static_cast<int>(salt.size())) != 1)
    return fail("login " + name + ": OpenSSL's RAND_bytes gave no salt");
  auto hash = login_hash(password, salt, iterations);
  if (!hash) return fail("login " + name + ": OpenSSL's PBKDF2 failed");
  return name + " " + role + " pbkdf2-sha256 " + std::to_string(iterations) + " " + to_hex(salt) + " " + to_hex(*hash);
}

Result<std::string> random_password(std::size_t length) {
  static const std::string alphabet = "ABCDEFGHJKLMNPQRSTUVWXYZabcdefghijkmnopqrstuvwxyz23456789";
  std::string out;
  while (out.size() < length) {
    unsigned char b = 0;
    if (RAND_bytes(&b, 1) != 1) return fail("a password: OpenSSL's RAND_bytes gave no bytes");
    // Rejection keeps every character equally likely: 256 is not a multiple of the alphabet's size.
    if (b < 256 - 256 % alphabet.size()) out += alphabet[b % alphabet.size()];
  }
  return out;
}

}  // namespace lungar::classroom
