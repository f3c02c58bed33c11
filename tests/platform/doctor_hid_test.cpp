// `lungar doctor`'s tracker check against a real hidraw node emulated by umockdev (run under umockdev-wrapper):
// it passes when the configured tracker's node is there and this user can open it, and fails naming the fix when
// the tracker is absent (plug it in) or its node unreadable (the exact udev rule command, or a new seat session when
// a rule exists). The check runs in a child process as an unprivileged user: root opens any node whatever its mode.
#include <gtest/gtest.h>

#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "drivers/tracker/tracker_config.h"
#include "platform/doctor/checks.h"
#include "tests/scratch_dir.h"
#include "umockdev_tracker.h"

namespace fs = std::filesystem;
using namespace lungar::platform::doctor;
using lungar::testing::UmockdevTracker;

namespace {

constexpr uid_t kNobody = 65534;

/// check_tracker() in a child that is not root; its verdict and line come back through a pipe.
Check check_unprivileged(const lungar::drivers::TrackerConfig& t, const DoctorEnv& env) {
  int fds[2];
  if (::pipe(fds) != 0) return failed("test", "pipe", "");
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    if (::geteuid() == 0 && (::setgroups(0, nullptr) != 0 || ::setgid(kNobody) != 0 || ::setuid(kNobody) != 0)) {
      ::_exit(3);
    }
    const Check c = check_tracker(t, env);
    const std::string out = std::to_string(static_cast<int>(c.verdict)) + "\n" + c.detail + "\n" + c.fix;
    const bool written = ::write(fds[1], out.data(), out.size()) == static_cast<ssize_t>(out.size());
    ::_exit(written ? 0 : 4);
  }
  ::close(fds[1]);
  std::string in;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) in.append(buf, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return failed("test", "child failed: " + std::to_string(status), "");
  const std::size_t a = in.find('\n'), b = in.find('\n', a + 1);
  return Check{"tracker", static_cast<Verdict>(std::stoi(in.substr(0, a))), in.substr(a + 1, b - a - 1),
               in.substr(b + 1)};
}

class DoctorHid : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!UmockdevTracker::available()) GTEST_SKIP() << "not under umockdev-wrapper";
    fs::permissions(rules.path(), fs::perms(0755));
    env.udev_rule_dirs = {rules.path().string()};
    tracker.source = lungar::drivers::TrackerSource::Hid;
    tracker.hid.vendor_id = 0x1234;
    tracker.hid.product_id = 0x5678;
  }
  /// Plugs the emulated tracker in and sets its node's mode; the testbed folder is opened to other users so that
  /// only the node's own mode decides.
  void plug_with_mode(fs::perms mode) {
    ASSERT_TRUE(device.plug({})) << device.error();
    const char* testbed = std::getenv("UMOCKDEV_DIR");
    ASSERT_NE(testbed, nullptr);
    // Other users must reach the testbed and its ioctl sockets (umockdev's preload connects to one on open).
    ASSERT_EQ(::chmod(testbed, 0755), 0);
    for (const auto& e : fs::recursive_directory_iterator(testbed)) {
      if (e.is_symlink()) continue;
      if (e.is_directory()) fs::permissions(e.path(), fs::perms(0755));
      if (e.is_socket()) fs::permissions(e.path(), fs::perms(0666));
    }
    // The testbed's node is a link to the pseudo-terminal that stands for the device.
    const fs::path link = fs::path(testbed) / ("." + device.dev_path());
    const fs::path node = fs::is_symlink(link) ? fs::read_symlink(link) : link;
    ASSERT_EQ(::chmod(node.c_str(), static_cast<mode_t>(mode)), 0) << node;
  }

  lungar::testing::ScratchDir rules{"lungar_doctor_rules"};
  DoctorEnv env;
  lungar::drivers::TrackerConfig tracker;
  UmockdevTracker device;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_F(DoctorHid, PassesWhenTheNodeIsReadable) {
  plug_with_mode(fs::perms(0666));
  const Check c = check_unprivileged(tracker, env);
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, device.dev_path()) && contains(c.detail, "1234:5678")) << c.detail;
}

TEST_F(DoctorHid, FailsNamingTheExactUdevCommandWhenTheNodeIsUnreadableAndNoRuleGrantsIt) {
  plug_with_mode(fs::perms::none);
  const Check c = check_unprivileged(tracker, env);
  EXPECT_EQ(c.verdict, Verdict::Fail) << format_check(c);
  EXPECT_TRUE(contains(c.detail, device.dev_path()) && contains(c.detail, "Permission denied")) << c.detail;
  EXPECT_TRUE(contains(c.fix, "ATTRS{idVendor}==\"1234\", ATTRS{idProduct}==\"5678\", TAG+=\"uaccess\"")) << c.fix;
  EXPECT_TRUE(contains(c.fix, "sudo tee /etc/udev/rules.d/70-lungar-1234-5678.rules")) << c.fix;
  EXPECT_TRUE(contains(c.fix, "sudo udevadm control --reload-rules && sudo udevadm trigger")) << c.fix;
}

TEST_F(DoctorHid, WithTheShippedRuleInstalledAnUnreadableNodeAsksForASeatSessionInstead) {
  fs::copy_file(std::string(LUNGAR_SOURCE_DIR) + "/scripts/99-lungar.rules", rules / "99-lungar.rules");
  plug_with_mode(fs::perms::none);
  const Check c = check_unprivileged(tracker, env);
  EXPECT_EQ(c.verdict, Verdict::Fail) << format_check(c);
  EXPECT_TRUE(contains(c.detail, (rules / "99-lungar.rules").string())) << c.detail;
  EXPECT_TRUE(contains(c.fix, "udevadm trigger") && !contains(c.fix, "sudo tee")) << c.fix;
}

TEST_F(DoctorHid, FailsAskingToPlugItInWhenTheTrackerIsAbsent) {
  tracker.hid.product_id = 0x9999;  // the emulated tracker is 1234:5678; nothing else is on the bus
  plug_with_mode(fs::perms(0666));
  const Check c = check_unprivileged(tracker, env);
  EXPECT_EQ(c.verdict, Verdict::Fail) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "1234:9999") && contains(c.detail, "plugged in")) << c.detail;
  EXPECT_TRUE(contains(c.fix, "lsusb")) << c.fix;
}

TEST_F(DoctorHid, FailsWhenTheTrackerWasUnplugged) {
  plug_with_mode(fs::perms(0666));
  device.unplug();
  const Check c = check_unprivileged(tracker, env);
  EXPECT_EQ(c.verdict, Verdict::Fail) << format_check(c);
  EXPECT_TRUE(contains(c.fix, "plug the tracker in")) << c.fix;
}
