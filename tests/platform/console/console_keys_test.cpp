/// @file console_keys_test.cpp
/// @brief `lungar classroom-keys` makes the console's folder: a server certificate that openssl verifies against
///        the classroom's authority, naming localhost, 127.0.0.1 and each --console-host; its key and the passwords
///        0600; logins that console_logins.h reads and that take those passwords (and no station's key); a bad
///        --console-host refused with nothing left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>

#include "drivers/classroom/classroom_keys.h"
#include "platform/console/console_logins.h"
#include "tests/file_text.h"
#include "tests/scratch_dir.h"

namespace lungar::console {
namespace {
namespace fs = std::filesystem;
using ::lungar::testing::file_text;
using ::lungar::testing::ScratchDir;

std::string output_of(const std::string& command) {
  std::string out;
  if (FILE* p = popen((command + " 2>&1").c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  return out;
}

unsigned mode_of(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 ? (st.st_mode & 0777) : 0;
}

TEST(ConsoleKeys, ClassroomKeysWritesTheConsolesFolder) {
  ScratchDir d("lungar_console_keys");
  classroom::ClassroomKeysOptions o;
  o.classroom = "ward-9";
  o.stations = {"teacher", "hmd-1"};
  o.console_hosts = {"console.ward-9.lan", "192.168.4.20", "fe80::1"};
  o.out_dir = (d / "keys").string();
  auto made = classroom::make_classroom_keys(o);
  ASSERT_TRUE(made) << made.error();
  const fs::path c = d / "keys" / "console";
  bool said = false;
  for (const std::string& line : *made) said = said || line.find(c.string() + "/") != std::string::npos;
  EXPECT_TRUE(said) << "a line says where the console's folder goes";
  for (const char* f :
       {"server_cert.pem", "server_key.pem", "ca.pem", "logins", "instructor.password", "observer.password"})
    EXPECT_TRUE(fs::exists(c / f)) << f;
  EXPECT_EQ(std::distance(fs::directory_iterator(c), fs::directory_iterator()), 6) << "nothing else (no CSR)";
  for (const char* f : {"server_key.pem", "instructor.password", "observer.password", "logins"})
    EXPECT_EQ(mode_of(c / f), 0600u) << f;
  EXPECT_EQ(file_text(c / "ca.pem"), file_text(d / "keys" / "ca" / "ca_cert.pem"));
  const std::string verify = output_of("openssl verify -CAfile " + (c / "ca.pem").string() + " -purpose sslserver " +
                                       (c / "server_cert.pem").string());
  EXPECT_NE(verify.find(": OK"), std::string::npos) << verify;
  const std::string text = output_of("openssl x509 -noout -ext subjectAltName,extendedKeyUsage,basicConstraints -in " +
                                     (c / "server_cert.pem").string());
  for (const char* name : {"DNS:localhost", "IP Address:127.0.0.1", "DNS:console.ward-9.lan", "IP Address:192.168.4.20",
                           "IP Address:FE80:0:0:0:0:0:0:1", "TLS Web Server Authentication", "CA:FALSE"})
    EXPECT_NE(text.find(name), std::string::npos) << name << " in\n" << text;

  auto logins = ConsoleLogins::read((c / "logins").string());
  ASSERT_TRUE(logins) << logins.error();
  std::string instructor = file_text(c / "instructor.password"), observer = file_text(c / "observer.password");
  ASSERT_EQ(instructor.back(), '\n');
  instructor.pop_back();
  observer.pop_back();
  EXPECT_EQ(instructor.size(), 20u);
  EXPECT_NE(instructor, observer);
  auto i = logins->verify("instructor", instructor);
  ASSERT_TRUE(i);
  EXPECT_EQ(i->role, Role::Instructor);
  auto w = logins->verify("observer", observer);
  ASSERT_TRUE(w);
  EXPECT_EQ(w->role, Role::Observer);
  EXPECT_FALSE(logins->verify("instructor", observer));
  // No station is a login, whatever it offers as a password.
  for (const std::string& station : o.stations) {
    const std::string key = file_text(d / "keys" / station / "identity_key.pem");
    EXPECT_FALSE(logins->verify(station, key)) << station;
    EXPECT_FALSE(logins->verify("instructor", key)) << station;
  }
}

TEST(ConsoleKeys, ABadConsoleHostIsRefusedWithNothingLeft) {
  ScratchDir d("lungar_console_keys");
  classroom::ClassroomKeysOptions o;
  o.classroom = "ward-9";
  o.stations = {"teacher"};
  o.out_dir = (d / "keys").string();
  for (const char* bad : {"evil.example, DNS:*.com", "a..b", "-lead.example", "", "host\nsubjectAltName=x"}) {
    o.console_hosts = {bad};
    auto made = classroom::make_classroom_keys(o);
    ASSERT_FALSE(made) << bad;
    EXPECT_EQ(made.error().rfind("--console-host: expected an IP address or a DNS name", 0), 0u) << made.error();
    EXPECT_FALSE(fs::exists(d / "keys")) << bad;
  }
  o.console_hosts = {};
  o.stations = {"teacher", "console"};
  auto named = classroom::make_classroom_keys(o);
  ASSERT_FALSE(named);
  EXPECT_NE(named.error().find("\"console\" is the console's folder"), std::string::npos) << named.error();
}

}  // namespace
}  // namespace lungar::console
