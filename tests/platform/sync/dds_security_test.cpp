// A secure station's folder: the checks before DDS is touched (each file there, the key private, the domain one
// a governance can name), and Cyclone's own verdict on real keys from `lungar classroom-keys`: a station with a
// complete folder joins, one whose permissions expired or whose governance was tampered with is refused with
// Cyclone's reason in the one error line.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "drivers/classroom/classroom_keys.h"
#include "drivers/dds/dds_security.h"
#include "sync_test_support.h"

using namespace lungar;
using namespace lungar::platform;
using namespace lungar::classroom;
namespace fs = std::filesystem;

namespace {

class DdsSecurity : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = lungar::testing::test_dir("dds_security");
    keys.classroom = "ward-" + std::to_string(::getpid());
    keys.stations = {"instr", "t1"};
    keys.out_dir = (dir / "keys").string();
    auto made = make_classroom_keys(keys);
    ASSERT_TRUE(made) << made.error();
    station = dir / "keys" / "t1";
  }
  void TearDown() override { fs::remove_all(dir); }

  /// Joins the test domain as `folder`'s station: the error line, or "" when Cyclone let it in.
  std::string join(const fs::path& folder) const {
    auto files = dds::find_security_files(folder.string());
    if (!files) return files.error();
    dds::Qos qos;
    if (Status s = dds::add_security_properties(*files, lungar::testing::test_domain(), qos); !s) return s.error();
    auto d = dds::Domain::create(lungar::testing::test_domain(), lungar::testing::kLoopbackXml, &qos);
    return d ? "" : d.error();
  }

  /// Signs `xml` as the classroom's authority into `out` (S/MIME, as classroom-keys does).
  void sign(const std::string& xml, const fs::path& out) const {
    const fs::path in = dir / "doc.xml", ca = dir / "keys" / "ca";
    std::ofstream(in) << xml;
    const std::string cmd = "openssl smime -sign -text -in " + in.string() + " -out " + out.string() + " -signer " +
                            (ca / "ca_cert.pem").string() + " -inkey " + (ca / "ca_key.pem").string() + " 2>/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  }

  fs::path dir, station;
  ClassroomKeysOptions keys;
};

}  // namespace

TEST_F(DdsSecurity, ACompleteFolderJoins) {
  EXPECT_EQ(join(station), "");
  auto files = dds::find_security_files(station.string());
  ASSERT_TRUE(files);
  EXPECT_EQ(files->identity_key, (station / "identity_key.pem").string());
  EXPECT_EQ(fs::path(files->dir).filename(), "t1");
}

TEST_F(DdsSecurity, AMissingFileOrFolderIsNamed) {
  EXPECT_NE(join(dir / "nowhere").find("expected a station folder written by `lungar classroom-keys`"),
            std::string::npos);
  fs::remove(station / "permissions.p7s");
  const std::string e = join(station);
  EXPECT_NE(e.find("sync.security " + station.string() + ": expected permissions.p7s there"), std::string::npos) << e;
}

TEST_F(DdsSecurity, AKeyOthersCanReadIsRefusedWithTheCommandThatMendsIt) {
  fs::permissions(station / "identity_key.pem", fs::perms::group_read, fs::perm_options::add);
  const std::string e = join(station);
  EXPECT_NE(e.find("identity_key.pem is readable by others than its owner; expected mode 0600 (chmod 600 "),
            std::string::npos)
      << e;
}

TEST_F(DdsSecurity, ADomainNoGovernanceCanNameIsRefused) {
  auto files = dds::find_security_files(station.string());
  ASSERT_TRUE(files);
  dds::Qos qos;
  Status s = dds::add_security_properties(*files, 231, qos);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("a secure classroom needs a DDS domain id in [0, 230]"), std::string::npos) << s.error();
  EXPECT_TRUE(dds::add_security_properties(*files, 230, qos));
}

TEST_F(DdsSecurity, ExpiredPermissionsAreRefusedByCyclone) {
  sign(classroom_permissions_xml(keys, "2020-01-01T00:00:00", "2020-01-02T00:00:00"), station / "permissions.p7s");
  const std::string e = join(station);
  EXPECT_NE(e.find("DDS Security refused this station ("), std::string::npos) << e;
  EXPECT_NE(e.find("xpired"), std::string::npos) << "Cyclone's reason: " << e;
}

TEST_F(DdsSecurity, ATamperedGovernanceIsRefusedByCyclone) {
  std::string gov;
  {
    std::ifstream in(station / "governance.p7s");
    gov.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = gov.find("<allow_unauthenticated_participants>false");
  ASSERT_NE(at, std::string::npos);
  gov.replace(at, 41, "<allow_unauthenticated_participants>true ");  // same length, signature now wrong
  std::ofstream(station / "governance.p7s") << gov;
  const std::string e = join(station);
  EXPECT_NE(e.find("DDS Security refused this station ("), std::string::npos) << e;
}

TEST_F(DdsSecurity, ARevokedIdentityIsRefusedWhereTheRevocationListIs) {
  ClassroomRevokeOptions r;
  r.ca_dir = (dir / "keys" / "ca").string();
  r.certs = {(station / "identity_cert.pem").string()};
  auto said = revoke_classroom_stations(r);
  ASSERT_TRUE(said) << said.error();
  EXPECT_EQ(join(dir / "keys" / "instr"), "") << "no list in its folder yet: nothing changes for the others";
  fs::copy_file(dir / "keys" / "ca" / "crl.pem", dir / "keys" / "instr" / "crl.pem");
  EXPECT_EQ(join(dir / "keys" / "instr"), "") << "instr is not on the list";
  fs::copy_file(dir / "keys" / "ca" / "crl.pem", station / "crl.pem");
  auto files = dds::find_security_files(station.string());
  ASSERT_TRUE(files);
  EXPECT_EQ(files->crl, (station / "crl.pem").string());
  const std::string e = join(station);
  EXPECT_NE(e.find("DDS Security refused this station ("), std::string::npos) << e;
  EXPECT_NE(e.find("revoked"), std::string::npos) << "Cyclone's reason: " << e;
}
