// A secure classroom (DDS Security) of `lungar` runtimes, each its own process, beside intruders in the same
// classroom name and domain: one with another authority's keys, one with no security (an open classroom's
// station), and a trainee of the right authority that tries to teach. The "done when": the trainee is in
// step with its instructor (breath offset p99 <= 5 ms), the instructor counts one peer, the intruders none, and
// every secure station counts and logs the two participants it refused.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

#include "drivers/classroom/classroom_keys.h"
#include "station_process.h"
#include "stations_test.h"
#include "sync_test_support.h"

using lungar::testing::StationProcess;

namespace {

using lungar::testing::kAsset;
using lungar::testing::kConfig;
using lungar::testing::kLungar;

namespace fs = std::filesystem;

class SecureClassroom : public lungar::testing::StationsTest {
 protected:
  SecureClassroom() : StationsTest("secure") {}

  /// Keys for this test's classroom: an authority with `stations` (the first teaches) into dir/`folder`.
  void make_keys(const std::string& folder, std::vector<std::string> stations) {
    lungar::classroom::ClassroomKeysOptions o;
    o.classroom = room;
    o.stations = std::move(stations);
    o.out_dir = (dir / folder).string();
    auto made = lungar::classroom::make_classroom_keys(o);
    ASSERT_TRUE(made) << made.error();
  }

  /// A station named `name` in this test's classroom; `keys` its folder ("" : an open station).
  std::unique_ptr<StationProcess> start(const std::string& name, const std::string& role, double seconds,
                                        const std::string& keys) {
    std::vector<std::string> a = {"--config",      kConfig,
                                  "--asset",       kAsset,
                                  "--sync",        role,
                                  "--station",     name,
                                  "--classroom",   room,
                                  "--sync-domain", domain,
                                  "--seconds",     std::to_string(seconds),
                                  "--tracker",     "mock",
                                  "--stats-json",  (dir / (name + ".json")).string(),
                                  "--snapshot",    (dir / (name + ".png")).string()};
    if (!keys.empty()) a.insert(a.end(), {"--sync-security", (dir / keys).string()});
    return std::make_unique<StationProcess>(kLungar, a, dir / name);
  }
};

}  // namespace

TEST_F(SecureClassroom, TheInstructorAndTraineeMeetWhileIntrudersGainNoPeerAndAreCountedAsRejected) {
  make_keys("keys", {"instr", "t1"});
  make_keys("other", {"evil"});
  // The intruders were there first, and stay until the class is over.
  auto evil = start("evil", "instructor", 22, "other/evil");
  auto laptop = start("laptop", "instructor", 22, "");
  ASSERT_TRUE(evil->wait_for("running", 30)) << evil->err();
  ASSERT_TRUE(laptop->wait_for("running", 30)) << laptop->err();
  auto instr = start("instr", "instructor", 12, "keys/instr");
  auto t1 = start("t1", "trainee", 10, "keys/t1");
  ASSERT_EQ(t1->wait(60), 0) << t1->err();
  ASSERT_EQ(instr->wait(60), 0) << instr->err();
  ASSERT_EQ(evil->wait(60), 0) << evil->err();
  ASSERT_EQ(laptop->wait(60), 0) << laptop->err();

  const auto ts = json_of("t1"), is = json_of("instr");
  EXPECT_EQ(ts["sync_state"], "in_sync") << ts.dump();
  EXPECT_EQ(ts["sync_instructor"], "instr") << ts.dump();
  EXPECT_LE(ts["sync_breath_offset_ms_p99"].get<double>(), 5.0) << ts.dump();
  EXPECT_EQ(is["sync_peers_max"], 1) << is.dump();
  EXPECT_EQ(ts["sync_secure"], true);
  EXPECT_EQ(is["sync_secure"], true);
  // Both intruders were heard on the domain, neither became a peer: each secure station refused both.
  EXPECT_EQ(is["sync_rejected"], 2) << is.dump();
  EXPECT_EQ(ts["sync_rejected"], 2) << ts.dump();
  const std::string log = instr->err();
  EXPECT_NE(log.find("is secure: DDS Security with"), std::string::npos) << log;
  // The failed handshake is logged by the side that answered it (DDS orders the two by their GUIDs): instr names
  // evil's certificate, or evil names instr's.
  const bool named =
      log.find("refused a peer: Begin handshake reply failed: Certificate not valid") != std::string::npos
          ? log.find("CN=evil") != std::string::npos
          : evil->err().find("CN=instr") != std::string::npos;
  EXPECT_TRUE(named) << "instr:\n" << log << "\nevil:\n" << evil->err();
  EXPECT_NE(log.find("refused DDS participant"), std::string::npos) << log;
  // The intruders' own view: neither ever had a peer, so neither could teach our trainee anything.
  EXPECT_NE(laptop->err().find("is open: any DDS participant on this network can join"), std::string::npos)
      << laptop->err();
  EXPECT_EQ(json_of("evil")["sync_peers_max"], 0) << json_of("evil").dump();
  EXPECT_EQ(json_of("laptop")["sync_peers_max"], 0) << json_of("laptop").dump();
  EXPECT_EQ(json_of("laptop")["sync_secure"], false);
  EXPECT_EQ(t1->err().find("instructor 'evil'"), std::string::npos) << t1->err();
  EXPECT_EQ(t1->err().find("instructor 'laptop'"), std::string::npos) << t1->err();
}

TEST_F(SecureClassroom, ATraineesKeysCannotTeach) {
  make_keys("keys", {"instr", "t1"});
  auto impostor = start("t1", "instructor", 3, "keys/t1");
  EXPECT_EQ(impostor->wait(60), 1);
  const std::string err = impostor->err();
  EXPECT_NE(err.find("station \"t1\" may not publish lungar_"), std::string::npos) << err;
  EXPECT_NE(err.find("its permissions.p7s does not allow it"), std::string::npos) << err;
  EXPECT_EQ(err.find("running"), std::string::npos) << "refused before its first frame: " << err;
}

TEST_F(SecureClassroom, ARevokedTraineeIsRefusedByAnInstructorThatHasTheRevocationList) {
  make_keys("keys", {"instr", "t1"});
  lungar::classroom::ClassroomRevokeOptions r;
  r.ca_dir = (dir / "keys" / "ca").string();
  r.certs = {(dir / "keys" / "t1" / "identity_cert.pem").string()};
  auto said = lungar::classroom::revoke_classroom_stations(r);
  ASSERT_TRUE(said) << said.error();
  fs::copy_file(dir / "keys" / "ca" / "crl.pem", dir / "keys" / "instr" / "crl.pem");  // t1's own folder: none
  auto instr = start("instr", "instructor", 9, "keys/instr");
  ASSERT_TRUE(instr->wait_for("running", 30)) << instr->err();
  auto t1 = start("t1", "trainee", 6, "keys/t1");
  ASSERT_EQ(t1->wait(60), 0) << t1->err();
  ASSERT_EQ(instr->wait(60), 0) << instr->err();
  const auto ts = json_of("t1"), is = json_of("instr");
  EXPECT_NE(ts["sync_state"], "in_sync") << ts.dump();
  EXPECT_EQ(ts["sync_peers_max"], 0) << ts.dump();
  EXPECT_EQ(is["sync_peers_max"], 0) << is.dump();
  EXPECT_EQ(is["sync_rejected"], 1) << is.dump();
  EXPECT_NE((instr->err() + t1->err()).find("certificate revoked; subject: /O=lungar/OU=" + room + "/CN=t1"),
            std::string::npos)
      << instr->err() << t1->err();
}
