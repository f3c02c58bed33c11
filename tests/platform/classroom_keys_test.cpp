/// @file classroom_keys_test.cpp
/// @brief `lungar classroom-keys`: each station's folder complete and checked by openssl itself (the identity
///        against the authority, the documents' signatures), private keys 0600, the instructor alone granted the
///        shared topics; bad requests refused with nothing left behind; an authority reused for a new station.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "drivers/classroom/classroom_keys.h"
#include "tests/file_text.h"

namespace lungar::classroom {
namespace {
namespace fs = std::filesystem;

int sh(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()); }

using ::lungar::testing::file_text;

std::string command_output(const std::string& command) {
  std::string out;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  return out;
}

struct Dir {
  fs::path path = fs::temp_directory_path() / ("lungar_keys_" + std::to_string(::getpid()));
  Dir() { fs::remove_all(path); fs::create_directories(path); }
  ~Dir() { fs::remove_all(path); }
};

TEST(ClassroomKeys, EveryStationGetsAFolderThatOpensslAccepts) {
  Dir d;
  ClassroomKeysOptions o;
  o.classroom = "ward-9";
  o.stations = {"teacher", "hmd-1", "hmd-2"};
  o.out_dir = (d.path / "keys").string();
  auto made = make_classroom_keys(o);
  ASSERT_TRUE(made) << made.error();
  EXPECT_EQ(made->size(), 5u) << "a line per station, one for the console and one for the authority";
  const fs::path ca = d.path / "keys" / "ca" / "ca_cert.pem";
  for (const std::string& s : o.stations) {
    const fs::path f = d.path / "keys" / s;
    for (const char* name : {"identity_ca.pem", "identity_cert.pem", "identity_key.pem", "permissions_ca.pem",
                             "governance.p7s", "permissions.p7s"})
      EXPECT_TRUE(fs::exists(f / name)) << s << "/" << name;
    struct stat st {};
    ASSERT_EQ(::stat((f / "identity_key.pem").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u) << s;
    EXPECT_EQ(sh("openssl verify -CAfile " + ca.string() + " " + (f / "identity_cert.pem").string()), 0) << s;
    for (const char* doc : {"governance.p7s", "permissions.p7s"})
      EXPECT_EQ(sh("openssl smime -verify -in " + (f / doc).string() + " -CAfile " + ca.string() + " -out /dev/null"), 0)
          << s << "/" << doc;
    // The permissions name the station by its certificate's own subject.
    const std::string subject = command_output("openssl x509 -noout -subject -nameopt RFC2253 -in " +
                                               (f / "identity_cert.pem").string());
    ASSERT_EQ(subject.rfind("subject=", 0), 0u) << subject;
    EXPECT_NE(file_text(d.path / "keys" / "permissions.xml")
                  .find("<subject_name>" + subject.substr(8, subject.size() - 9) + "</subject_name>"),
              std::string::npos)
        << subject;
  }
  struct stat st {};
  ASSERT_EQ(::stat((d.path / "keys" / "ca" / "ca_key.pem").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  // The instructor's grant publishes the shared patient pose; a trainee's does not.
  const std::string xml = classroom_permissions_xml(o, "2026-01-01T00:00:00", "2027-01-01T00:00:00");
  const std::size_t teacher = xml.find("ward-9.teacher"), trainee = xml.find("ward-9.hmd-1");
  ASSERT_NE(teacher, std::string::npos);
  ASSERT_NE(trainee, std::string::npos);
  EXPECT_NE(xml.substr(teacher, trainee - teacher).find("<topic>lungar_patient_pose</topic>"), std::string::npos);
  EXPECT_EQ(xml.substr(trainee, xml.find("</grant>", trainee) - trainee).find("lungar_patient_pose"), std::string::npos);
}

TEST(ClassroomKeys, BadRequestsAreRefusedAndLeaveNothing) {
  Dir d;
  ClassroomKeysOptions o;
  o.classroom = "ward-9";
  o.stations = {"a", "b"};
  o.out_dir = (d.path / "keys").string();
  const auto refused = [&](ClassroomKeysOptions bad, const std::string& why) {
    auto r = make_classroom_keys(bad);
    ASSERT_FALSE(r) << why;
    EXPECT_NE(r.error().find(why), std::string::npos) << r.error();
    for (const auto& e : fs::directory_iterator(d.path))
      EXPECT_EQ(e.path().filename(), "taken") << "left behind: " << e.path();
  };
  ClassroomKeysOptions bad = o;
  bad.stations = {"a", "a"};
  refused(bad, "given twice");
  bad = o;
  bad.stations = {"a/b"};
  refused(bad, "--station: expected 1 to 63 letters");
  bad = o;
  bad.instructor = "z";
  refused(bad, "--instructor");
  bad = o;
  bad.openssl = "/nonexistent/openssl";
  refused(bad, "cannot start it");
  fs::create_directories(d.path / "taken");
  std::ofstream(d.path / "taken" / "mine.txt") << "keep me";
  bad = o;
  bad.out_dir = (d.path / "taken").string();
  refused(bad, "expected a new or empty folder");
  EXPECT_EQ(file_text(d.path / "taken" / "mine.txt"), "keep me");
}

// The README's own command ends --out with a slash (as a shell completes a folder): that names the folder. A run
// that fails leaves none of the folders it made, so that a retry is not refused by the leftovers.
TEST(ClassroomKeys, ATrailingSlashNamesTheFolderAndAFailureLeavesNoFolderMade) {
  Dir d;
  ClassroomKeysOptions o;
  o.classroom = "ward-9";
  o.stations = {"teacher", "hmd-1"};
  o.out_dir = (d.path / "keys").string() + "/";
  auto made = make_classroom_keys(o);
  ASSERT_TRUE(made) << made.error();
  EXPECT_TRUE(fs::exists(d.path / "keys" / "hmd-1" / "identity_cert.pem"));
  EXPECT_TRUE(fs::exists(d.path / "keys" / "ca" / "ca_key.pem"));
  for (const auto& e : fs::directory_iterator(d.path))
    EXPECT_EQ(e.path().filename(), "keys") << "left behind: " << e.path();

  ClassroomKeysOptions bad = o;
  bad.openssl = "/nonexistent/openssl";
  bad.out_dir = (d.path / "new" / "deeper" / "keys").string() + "/";
  ASSERT_FALSE(make_classroom_keys(bad));
  EXPECT_FALSE(fs::exists(d.path / "new")) << "the folders this run made stay behind";
  o.out_dir = bad.out_dir;
  made = make_classroom_keys(o);
  ASSERT_TRUE(made) << "a retry after a failure: " << made.error();
  EXPECT_TRUE(fs::exists(d.path / "new" / "deeper" / "keys" / "teacher" / "identity_key.pem"));
}

TEST(ClassroomKeys, AnAuthorityIsReusedForANewStation) {
  Dir d;
  ClassroomKeysOptions o;
  o.classroom = "ward-9";
  o.stations = {"a"};
  o.out_dir = (d.path / "first").string();
  ASSERT_TRUE(make_classroom_keys(o));
  o.stations = {"a", "late"};
  o.ca_dir = (d.path / "first" / "ca").string();
  o.out_dir = (d.path / "second").string();
  auto again = make_classroom_keys(o);
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(sh("openssl verify -CAfile " + (d.path / "first" / "ca" / "ca_cert.pem").string() + " " +
               (d.path / "second" / "late" / "identity_cert.pem").string()),
            0);
}

TEST(ClassroomKeys, RevokingListsTheStationAndRefusesAnotherAuthoritysCertificate) {
  Dir d;
  ClassroomKeysOptions o;
  o.classroom = "ward-9";
  o.stations = {"teacher", "lost-hmd"};
  o.out_dir = (d.path / "keys").string();
  ASSERT_TRUE(make_classroom_keys(o));
  o.stations = {"stranger"};
  o.out_dir = (d.path / "other").string();
  ASSERT_TRUE(make_classroom_keys(o));
  const fs::path ca = d.path / "keys" / "ca";
  ClassroomRevokeOptions r;
  r.ca_dir = ca.string();
  r.certs = {(d.path / "other" / "stranger" / "identity_cert.pem").string()};
  auto refused = revoke_classroom_stations(r);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("not a certificate of this authority"), std::string::npos) << refused.error();
  EXPECT_FALSE(fs::exists(ca / "crl.pem")) << "nothing written for a refused request";
  EXPECT_FALSE(fs::exists(ca / "openssl.err"));

  r.certs = {(d.path / "keys" / "lost-hmd" / "identity_cert.pem").string()};
  auto said = revoke_classroom_stations(r);
  ASSERT_TRUE(said) << said.error();
  EXPECT_NE(said->find("into every station's folder (as crl.pem)"), std::string::npos) << *said;
  // openssl itself: the list is the authority's, and names the lost station's certificate and not the teacher's.
  const std::string crl = (ca / "crl.pem").string(), ca_cert = (ca / "ca_cert.pem").string();
  EXPECT_EQ(sh("openssl crl -in " + crl + " -CAfile " + ca_cert + " -noout"), 0);
  const auto serial = [&](const std::string& station) {
    const std::string s = command_output("openssl x509 -noout -serial -in " +
                                         (d.path / "keys" / station / "identity_cert.pem").string());
    return s.substr(s.find('=') + 1, s.size() - s.find('=') - 2);
  };
  const std::string listed = command_output("openssl crl -noout -text -in " + crl);
  EXPECT_NE(listed.find(serial("lost-hmd")), std::string::npos) << listed;
  EXPECT_EQ(listed.find(serial("teacher")), std::string::npos) << listed;
  EXPECT_TRUE(revoke_classroom_stations(r)) << "revoking it again changes nothing and is no error";
}

}  // namespace
}  // namespace lungar::classroom
