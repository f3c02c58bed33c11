// `lungar replay SESSION --console`: a class recorded on a headless instructor serving its console (a pathology added,
// a marker and a breath hold made from the console), then replayed with the console page served read-only, all as
// processes on loopback with a real HTTPS client. /api/state gives the record's events on the cursor's time axis and
// a cursor that moves with the replay; a control request is refused (409) and changes nothing; the timeline CSV is
// the record's debrief sheet.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/classroom/classroom_keys.h"
#include "platform/record/session_record.h"
#include "platform/record/timeline_csv.h"
#include "tests/file_text.h"
#include "tests/platform/console/https_client.h"
#include "tests/platform/sync/station_process.h"
#include "tests/platform/sync/stations_test.h"
#include "tests/shared_folder.h"

namespace fs = std::filesystem;
using lungar::testing::HttpsClient;
using lungar::testing::StationProcess;

namespace {

std::uint16_t console_port(const StationProcess& p) { return lungar::testing::console_port_in(p.err()); }

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

/// One class recorded for every process of the suite (an instructor with its console, a few seconds; shared_
/// folder.h, made again when lungar or this binary is rebuilt), and a replay of it per test.
class ReplayConsole : public ::testing::Test {
 protected:
  static constexpr double kClassS = 8.0;

  static void SetUpTestSuite() {
    dir = lungar::testing::test_dir("replay_console");
    const fs::path made = lungar::testing::shared_folder(
        "replay-console-class", {lungar::testing::kLungar, "/proc/self/exe"}, [](const fs::path& out) {
          record_class(out);
          return setup_error.empty();
        });
    if (made.empty() && setup_error.empty()) setup_error = "no shared folder for the recorded class";
    cls = made;
    record = (cls / "class.lungarsession").string();
  }

  /// An instructor with its console runs the class for kClassS, recorded into `out` with its keys: a pathology,
  /// a marker, a breath hold and its end made from the console. setup_error says what failed.
  static void record_class(const fs::path& out) {
    const std::string session = (out / "class.lungarsession").string();
    lungar::classroom::ClassroomKeysOptions k;
    k.classroom = lungar::testing::test_classroom("replayconsole");
    k.stations = {"instructor"};
    k.out_dir = (out / "keys").string();
    if (auto made = lungar::classroom::make_classroom_keys(k); !made) {
      setup_error = "classroom-keys: " + made.error();
      return;
    }
    StationProcess instructor(lungar::testing::kLungar,
                              {"--config",         lungar::testing::kConfig,
                               "--asset",          lungar::testing::kAsset,
                               "--output",         "headless",
                               "--tracker",        "mock",
                               "--sync",           "instructor",
                               "--station",        "instructor",
                               "--classroom",      k.classroom,
                               "--sync-domain",    std::to_string(lungar::testing::test_domain()),
                               "--seconds",        std::to_string(kClassS),
                               "--console",        "127.0.0.1:0",
                               "--console-keys",   (out / "keys" / "console").string(),
                               "--session-record", session,
                               "--stats-json",     (dir / "class.json").string(),
                               "--snapshot",       (dir / "class.png").string()},
                              dir / "class");
    if (!instructor.wait_for("console: https://", 30)) {
      setup_error = "the instructor's console did not start: " + instructor.err();
      return;
    }
    HttpsClient trainer(client_options(console_port(instructor), out / "keys"));
    const auto in = trainer.login("instructor", first_line(out / "keys" / "console" / "instructor.password"));
    if (in.status != 200) {
      setup_error = "login: " + std::to_string(in.status) + " " + in.body + in.error;
      return;
    }
    for (const char* request : {R"({"action":"pathology_add","spec":"pneumothorax:right:30","over_s":1})",
                                R"({"action":"marker","text":"trainee 2 palpated the apex"})",
                                R"({"action":"breath_pause"})", R"({"action":"breath_resume"})"}) {
      lungar::testing::sleep_s(0.4);
      const auto done = trainer.control(request);
      if (done.status != 200) {
        setup_error = std::string(request) + ": " + std::to_string(done.status) + " " + done.body + done.error;
        return;
      }
    }
    if (const int rc = instructor.wait(60); rc != 0) {
      setup_error = "the instructor exited " + std::to_string(rc) + ": " + instructor.err();
      return;
    }
  }
  static void TearDownTestSuite() { fs::remove_all(dir); }

  void SetUp() override {
    ASSERT_TRUE(setup_error.empty()) << setup_error;
    auto read = lungar::platform::record::read_session_record(record);
    ASSERT_TRUE(read) << read.error();
    recorded = read.take();
    ASSERT_GE(recorded.events.size(), 4u) << "the console's actions are in the record";
  }

  static std::string keys() { return (cls / "keys" / "console").string(); }
  static std::string password(const std::string& login) {
    return first_line(cls / "keys" / "console" / (login + ".password"));
  }
  static lungar::testing::HttpsClientOptions client_options(std::uint16_t port, const fs::path& keys = cls / "keys") {
    lungar::testing::HttpsClientOptions o;
    o.port = port;
    o.ca_file = (keys / "console" / "ca.pem").string();
    return o;
  }

  /// `lungar replay` of the record, in real time, serving its console on a free port.
  std::unique_ptr<StationProcess> replay(const std::string& name, std::vector<std::string> extra = {}) {
    std::vector<std::string> a = {"--config",       lungar::testing::kConfig,
                                  "replay",         record,
                                  "--output",       "headless",
                                  "--stats-json",   (dir / (name + ".json")).string(),
                                  "--snapshot",     (dir / (name + ".png")).string(),
                                  "--console",      "127.0.0.1:0",
                                  "--console-keys", keys()};
    a.insert(a.end(), extra.begin(), extra.end());
    return std::make_unique<StationProcess>(lungar::testing::kLungar, a, dir / name);
  }

  /// GET /api/state as JSON (null when it fails: `why` says so).
  static nlohmann::json state(HttpsClient& c, std::string& why) {
    const auto r = c.get("/api/state");
    why = std::to_string(r.status) + " " + r.body + r.error;
    if (r.status != 200) return nullptr;
    return nlohmann::json::parse(r.body, nullptr, false);
  }

  /// The view's events are the record's, each on the session-time axis (when it was noted).
  void expect_the_records_events(const nlohmann::json& events) const {
    ASSERT_TRUE(events.is_array()) << events.dump();
    ASSERT_EQ(events.size(), recorded.events.size()) << events.dump();
    for (std::size_t k = 0; k < recorded.events.size(); ++k) {
      SCOPED_TRACE(k);
      const auto& e = recorded.events[k];
      EXPECT_NEAR(events[k]["t_s"].get<double>(), e.s, 1e-6) << "the cursor's axis: session time";
      EXPECT_NEAR(events[k]["breath_s"].get<double>(), e.t_s, 1e-6);
      EXPECT_EQ(events[k]["kind"], e.kind);
      EXPECT_EQ(events[k]["user"], e.user);
      EXPECT_EQ(events[k]["text"], e.text);
    }
  }

  static inline fs::path dir, cls;  // this process's outputs; the shared recorded class
  static inline std::string record, setup_error;
  lungar::platform::record::SessionRecord recorded;
};

}  // namespace

TEST_F(ReplayConsole, ItsStateIsTheRecordsEventsWithACursorThatMovesWithTheReplay) {
  auto played = replay("state");
  ASSERT_TRUE(played->wait_for("console: https://", 30)) << played->err();
  HttpsClient watcher(client_options(console_port(*played)));
  ASSERT_EQ(watcher.login("observer", password("observer")).status, 200);
  std::string why;
  const nlohmann::json first = state(watcher, why);
  ASSERT_TRUE(first.is_object()) << why;
  lungar::testing::sleep_s(1.0);
  const nlohmann::json second = state(watcher, why);
  ASSERT_TRUE(second.is_object()) << why;

  expect_the_records_events(first["events"]);
  bool marked = false;
  for (const auto& e : first["events"]) marked = marked || (e["kind"] == "marker" && e["user"] == "instructor");
  EXPECT_TRUE(marked) << first["events"].dump();
  const nlohmann::json& replay = first["replay"];
  ASSERT_TRUE(replay.is_object()) << first.dump();
  EXPECT_EQ(replay["file"], "class.lungarsession");
  EXPECT_NEAR(replay["duration_s"].get<double>(), recorded.frames.back().s, 1e-6);
  EXPECT_DOUBLE_EQ(first["t_s"].get<double>(), replay["session_s"].get<double>()) << "the page's cursor";
  const double s1 = replay["session_s"], s2 = second["replay"]["session_s"];
  EXPECT_GE(s1, recorded.frames.front().s);
  EXPECT_GT(s2 - s1, 0.5) << "a second later the replay is further on: " << s1 << " then " << s2;
  EXPECT_LT(s2 - s1, 1.5);
  EXPECT_EQ(first["station"], recorded.header.station);
  ASSERT_FALSE(second["samples"].empty()) << "the last half second of recorded frames";
  EXPECT_NEAR(second["samples"].back()[0].get<double>(), s2, 0.1);
  EXPECT_EQ(played->wait(60), 0) << played->err();
  const nlohmann::json stats = nlohmann::json::parse(lungar::testing::file_text(dir / "state.json"));
  EXPECT_EQ(stats["console_logins"], 1) << stats.dump();
}

TEST_F(ReplayConsole, AControlRequestIsRefusedAndChangesNothing) {
  const fs::path timeline = dir / "refused-timeline.csv";
  auto played = replay("refused", {"--timeline-csv", timeline.string()});
  ASSERT_TRUE(played->wait_for("console: https://", 30)) << played->err();
  const auto options = client_options(console_port(*played));
  HttpsClient trainer(options);
  ASSERT_EQ(trainer.login("instructor", password("instructor")).status, 200);
  for (const char* request : {R"({"action":"pathology_add","spec":"pneumothorax:left:30","over_s":1})",
                              R"({"action":"marker","text":"not in the record"})", R"({"action":"breath_pause"})",
                              R"({"action":"seek","session_s":1.0})"}) {
    SCOPED_TRACE(request);
    const auto refused = trainer.control(request);
    EXPECT_EQ(refused.status, 409) << refused.body << refused.error;
    EXPECT_EQ(refused.body.rfind(R"({"error":"a replay is read-only: )", 0), 0u) << refused.body;
  }
  HttpsClient stranger(options);  // no login: the server refuses it, and the replay counts it
  EXPECT_EQ(
      stranger.post("/api/control", R"({"action":"marker","text":"x"})", {{"Content-Type", "application/json"}}).status,
      401);
  std::string why;
  const nlohmann::json after = state(trainer, why);
  ASSERT_TRUE(after.is_object()) << why;
  expect_the_records_events(after["events"]);
  EXPECT_GE(after["refused"].get<int>(), 1) << "the refused request is counted";
  for (const auto& p : after["pathologies"]) EXPECT_NE(p, "pneumothorax:left:30");
  EXPECT_EQ(played->wait(60), 0) << played->err();
  const nlohmann::json stats = nlohmann::json::parse(lungar::testing::file_text(dir / "refused.json"));
  for (const auto& p : stats["pathologies"]) EXPECT_NE(p, "pneumothorax:left:30") << stats["pathologies"].dump();
  EXPECT_EQ(lungar::testing::file_text(timeline), lungar::platform::record::timeline_csv(recorded))
      << "the debrief sheet is the record's: the refused requests added nothing";
}

TEST_F(ReplayConsole, ItsTimelineCsvIsTheRecordsDebriefSheet) {
  auto played = replay("csv");
  ASSERT_TRUE(played->wait_for("console: https://", 30)) << played->err();
  HttpsClient watcher(client_options(console_port(*played)));
  ASSERT_EQ(watcher.login("observer", password("observer")).status, 200);
  const auto csv = watcher.get("/api/timeline.csv");
  ASSERT_EQ(csv.status, 200) << csv.body << csv.error;
  EXPECT_EQ(csv.body, lungar::platform::record::timeline_csv(recorded));
  EXPECT_NE(csv.body.find(",marker,instructor,trainee 2 palpated the apex,"), std::string::npos) << csv.body;
  EXPECT_NE(csv.body.find(",pathology add,instructor,pneumothorax:right:30"), std::string::npos) << csv.body;
  EXPECT_EQ(played->wait(60), 0) << played->err();
}
