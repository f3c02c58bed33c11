/// @file console_server_test.cpp
/// @brief The console server (console_server.h) over real TLS on loopback, with keys from make_classroom_keys and a
///        fake handler: logins and their refusals; every check of a control request (session, role, CSRF, nonce,
///        Origin, Content-Type, size), each refusal counted, logged, told to the handler and never reaching
///        handler.control(); the state, the timeline and the WebSocket's pushes; the page and its headers; the
///        certificate verified through the classroom's authority; the connection limit; one error line when it
///        cannot start.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "drivers/classroom/classroom_keys.h"
#include "platform/console/console_server.h"
#include "tests/file_text.h"
#include "tests/platform/console/fake_console_handler.h"
#include "tests/platform/console/https_client.h"
#include "tests/shared_folder.h"

namespace lungar::console {
namespace {
namespace fs = std::filesystem;
using ::lungar::testing::FakeConsoleHandler;
using ::lungar::testing::file_text;
using ::lungar::testing::HttpsClient;
using ::lungar::testing::HttpsClientOptions;
using ::lungar::testing::HttpsReply;

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

/// A classroom's keys (teacher, hmd-1; the console also named console.ward-9.lan), made once for every process of
/// the suite (shared_folder.h): the tests only read them.
class ConsoleServerTest : public ::testing::Test {
 protected:
  static fs::path& keys() {
    static fs::path path;
    return path;
  }
  static void SetUpTestSuite() {
    std::string error;
    keys() = lungar::testing::shared_folder("console-keys", {"/proc/self/exe"}, [&](const fs::path& out) {
      classroom::ClassroomKeysOptions o;
      o.classroom = "ward-9";
      o.stations = {"teacher", "hmd-1"};
      o.console_hosts = {"console.ward-9.lan", "10.1.2.3"};
      o.out_dir = (out / "keys").string();
      auto made = classroom::make_classroom_keys(o);
      if (!made) error = made.error();
      return bool(made);
    });
    ASSERT_FALSE(keys().empty()) << error;
    keys() /= "keys";
  }

  void SetUp() override {
    ConsoleOptions o;
    o.address = "127.0.0.1";
    o.port = 0;
    o.keys_dir = (keys() / "console").string();
    auto started = ConsoleServer::start(o, handler, [this](const std::string& line) {
      std::lock_guard lock(log_mutex);
      log.push_back(line);
    });
    ASSERT_TRUE(started) << started.error();
    server = started.take();
  }

  HttpsClientOptions client_options() const {
    HttpsClientOptions c;
    c.port = server->port();
    c.ca_file = (keys() / "console" / "ca.pem").string();
    return c;
  }
  std::string password(const std::string& who) const {
    return trimmed(file_text(keys() / "console" / (who + ".password")));
  }
  /// A client logged in as `who` (instructor or observer).
  HttpsClient logged_in(const std::string& who) {
    HttpsClient c(client_options());
    HttpsReply r = c.login(who, password(who));
    EXPECT_EQ(r.status, 200) << r.error << r.body;
    return c;
  }
  std::vector<std::string> log_lines() {
    std::lock_guard lock(log_mutex);
    return log;
  }

  FakeConsoleHandler handler;
  std::unique_ptr<ConsoleServer> server;
  std::mutex log_mutex;
  std::vector<std::string> log;
};

TEST_F(ConsoleServerTest, AnInstructorLogsInWithASecureCookieAndACsrfToken) {
  HttpsClient c(client_options());
  HttpsReply r = c.login("instructor", password("instructor"));
  ASSERT_EQ(r.status, 200) << r.error << r.body;
  const nlohmann::json body = nlohmann::json::parse(r.body);
  EXPECT_EQ(body["user"], "instructor");
  EXPECT_EQ(body["role"], "instructor");
  EXPECT_EQ(body["csrf"].get<std::string>().size(), 64u);
  const std::string cookie = r.header("set-cookie");
  EXPECT_EQ(cookie.rfind("lungar_session=", 0), 0u) << cookie;
  for (const char* attribute : {"; Secure", "; HttpOnly", "; SameSite=Strict", "; Path=/"})
    EXPECT_NE(cookie.find(attribute), std::string::npos) << cookie << " lacks " << attribute;
  EXPECT_EQ(c.cookie().size(), 64u) << "32 random bytes, hex";
  EXPECT_EQ(server->counts().logins, 1u);
  HttpsClient o(client_options());
  HttpsReply obs = o.login("observer", password("observer"));
  ASSERT_EQ(obs.status, 200) << obs.body;
  EXPECT_EQ(nlohmann::json::parse(obs.body)["role"], "observer");
  EXPECT_NE(o.cookie(), c.cookie());
}

TEST_F(ConsoleServerTest, AWrongPasswordOrAnUnknownUserIs401CountedLoggedWithoutThePasswordAndReported) {
  HttpsClient c(client_options());
  HttpsReply wrong = c.login("instructor", "not-the-password-42");
  EXPECT_EQ(wrong.status, 401) << wrong.body;
  EXPECT_TRUE(c.cookie().empty());
  EXPECT_TRUE(wrong.header("set-cookie").empty());
  HttpsReply unknown = c.login("principal", password("instructor"));
  EXPECT_EQ(unknown.status, 401) << unknown.body;
  const ConsoleCounts n = server->counts();
  EXPECT_EQ(n.logins, 0u);
  EXPECT_EQ(n.logins_refused, 2u);
  EXPECT_EQ(n.refused_401, 2u);
  const auto refusals = handler.refusals();
  ASSERT_EQ(refusals.size(), 2u);
  EXPECT_EQ(refusals[0].first, 401);
  EXPECT_EQ(refusals[0].second.rfind("console: refused 401 POST /api/login from 127.0.0.1: wrong name or password", 0),
            0u)
      << refusals[0].second;
  for (const std::string& line : log_lines()) {
    EXPECT_EQ(line.find("not-the-password-42"), std::string::npos) << line;
    EXPECT_EQ(line.find(password("instructor")), std::string::npos) << line;
  }
}

TEST_F(ConsoleServerTest, MoreThanTenFailedLoginsAMinuteAre429EvenWithTheRightPassword) {
  HttpsClient c(client_options());
  for (int i = 0; i < 10; ++i) EXPECT_EQ(c.login("instructor", "guess" + std::to_string(i)).status, 401) << i;
  HttpsReply r = c.login("instructor", password("instructor"));
  EXPECT_EQ(r.status, 429) << r.body;
  EXPECT_EQ(server->counts().logins_refused, 11u);
  EXPECT_EQ(server->counts().refused_other, 1u);
}

TEST_F(ConsoleServerTest, AControlWithoutASessionIs401AndNeverReachesTheHandler) {
  HttpsClient c(client_options());
  HttpsReply r = c.control(R"({"action":"breath_pause"})");
  EXPECT_EQ(r.status, 401) << r.body;
  c.set_session(std::string(64, 'a'), std::string(64, 'b'));  // a made-up cookie
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})").status, 401);
  EXPECT_TRUE(handler.controls().empty());
  EXPECT_EQ(server->counts().refused_401, 2u);
  ASSERT_EQ(handler.refusals().size(), 2u);
  EXPECT_EQ(handler.refusals()[0].second,
            "console: refused 401 POST /api/control from 127.0.0.1: no session (log in first)");
}

TEST_F(ConsoleServerTest, AnObserversControlIs403) {
  HttpsClient c = logged_in("observer");
  HttpsReply r = c.control(R"({"action":"breath_pause"})");
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_NE(r.body.find("observer"), std::string::npos) << r.body;
  EXPECT_TRUE(handler.controls().empty());
  EXPECT_EQ(server->counts().refused_403, 1u);
}

TEST_F(ConsoleServerTest, AMissingOrWrongCsrfTokenIs403) {
  HttpsClient c = logged_in("instructor");
  HttpsReply none = c.post("/api/control", R"({"action":"breath_pause"})",
                           {{"Content-Type", "application/json"}, {"X-Request-Nonce", HttpsClient::fresh_nonce()}});
  EXPECT_EQ(none.status, 403) << none.body;
  const std::string csrf = c.csrf();
  c.set_session(c.cookie(), std::string(64, '0'));
  HttpsReply wrong = c.control(R"({"action":"breath_pause"})");
  EXPECT_EQ(wrong.status, 403) << wrong.body;
  c.set_session(c.cookie(), csrf.substr(0, 63));
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})").status, 403) << "a prefix of the token";
  EXPECT_TRUE(handler.controls().empty());
  EXPECT_EQ(server->counts().refused_403, 3u);
  c.set_session(c.cookie(), csrf);
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})").status, 200);
}

TEST_F(ConsoleServerTest, AReplayedNonceIs403AndTheRequestRunsOnce) {
  HttpsClient c = logged_in("instructor");
  const std::string nonce = HttpsClient::fresh_nonce();
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})", nonce).status, 200);
  HttpsReply again = c.control(R"({"action":"breath_pause"})", nonce);
  EXPECT_EQ(again.status, 403) << again.body;
  EXPECT_EQ(handler.controls().size(), 1u);
  ASSERT_FALSE(handler.refusals().empty());
  EXPECT_EQ(handler.refusals().back().second, "console: refused 403 POST /api/control from 127.0.0.1: replayed nonce");
  const auto lines = log_lines();
  EXPECT_NE(
      std::find(lines.begin(), lines.end(), "console: refused 403 POST /api/control from 127.0.0.1: replayed nonce"),
      lines.end());
  // No nonce, or one that is not 16 to 64 hex digits: refused too.
  EXPECT_EQ(c.post("/api/control", "{}", {{"Content-Type", "application/json"}, {"X-CSRF-Token", c.csrf()}}).status,
            403);
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})", "abc").status, 403);
  EXPECT_EQ(handler.controls().size(), 1u);
}

TEST_F(ConsoleServerTest, AForeignOriginIs403ForControlAndWebSocket) {
  HttpsClient c = logged_in("instructor");
  HttpsReply r = c.control(R"({"action":"breath_pause"})", "", {{"Origin", "https://evil.example:8443"}});
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})", "", {{"Origin", "null"}}).status, 403);
  EXPECT_TRUE(handler.controls().empty());
  auto ws = c.websocket({{"Origin", "https://evil.example:8443"}});
  EXPECT_EQ(ws->status(), 403) << ws->error();
  EXPECT_EQ(server->counts().refused_403, 3u);
  EXPECT_EQ(server->counts().websockets, 0u);
  // The server's own origins (each name of its certificate, with its port) pass.
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})", "", {{"Origin", c.origin()}}).status, 200);
  const std::string port = std::to_string(server->port());
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})", "", {{"Origin", "https://console.ward-9.lan:" + port}}).status,
            200);
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})", "", {{"Origin", "https://10.1.2.3:" + port}}).status, 200);
  EXPECT_EQ(handler.controls().size(), 3u);
}

TEST_F(ConsoleServerTest, ABodyOver16KiBIs413AndAHeaderOver8KiBIs431) {
  HttpsClient c = logged_in("instructor");
  const std::string big = R"({"action":"marker","text":")" + std::string(17 * 1024, 'x') + "\"}";
  HttpsReply r = c.control(big);
  EXPECT_EQ(r.status, 413) << r.error;
  HttpsReply h = c.get("/api/state", {{"X-Padding", std::string(9 * 1024, 'p')}});
  EXPECT_EQ(h.status, 431) << h.error;
  EXPECT_TRUE(handler.controls().empty());
  EXPECT_EQ(server->counts().refused_other, 2u);
  // Just under the limit passes.
  const std::string fits = R"({"action":"marker","text":")" + std::string(15 * 1024, 'x') + "\"}";
  EXPECT_EQ(c.control(fits).status, 200);
}

TEST_F(ConsoleServerTest, AGoodControlReachesTheHandlerWithTheUserAndItsAnswerComesBack) {
  HttpsClient c = logged_in("instructor");
  HttpsReply r = c.control(R"({"action":"pathology_add","spec":"pneumothorax:right:30","over_s":5})", "",
                           {{"Origin", c.origin()}});
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(nlohmann::json::parse(r.body)["done"], "ok");
  auto controls = handler.controls();
  ASSERT_EQ(controls.size(), 1u);
  EXPECT_EQ(controls[0].user.name, "instructor");
  EXPECT_EQ(controls[0].user.role, Role::Instructor);
  EXPECT_EQ(controls[0].request["spec"], "pneumothorax:right:30");
  handler.set_reply({409, {{"error", "pathology_add: pneumothorax:right is there already"}}});
  HttpsReply conflict = c.control(R"({"action":"pathology_add","spec":"pneumothorax:right:30"})");
  EXPECT_EQ(conflict.status, 409);
  EXPECT_EQ(nlohmann::json::parse(conflict.body)["error"], "pathology_add: pneumothorax:right is there already");
  EXPECT_EQ(server->counts().refused_other, 0u) << "the handler's own answers are no refusals";
  // Not JSON, or not an object, or the wrong type: refused before the handler.
  EXPECT_EQ(c.control("not json").status, 400);
  EXPECT_EQ(c.post("/api/control", "{}",
                   {{"Content-Type", "text/plain"},
                    {"X-CSRF-Token", c.csrf()},
                    {"X-Request-Nonce", HttpsClient::fresh_nonce()}})
                .status,
            415);
  EXPECT_EQ(handler.controls().size(), 2u);
}

TEST_F(ConsoleServerTest, TheStateAndTheTimelineNeedASessionAndLogoutEndsIt) {
  HttpsClient anonymous(client_options());
  EXPECT_EQ(anonymous.get("/api/state").status, 401);
  EXPECT_EQ(anonymous.get("/api/timeline.csv").status, 401);
  HttpsClient c = logged_in("observer");
  HttpsReply state = c.get("/api/state");
  ASSERT_EQ(state.status, 200);
  EXPECT_EQ(nlohmann::json::parse(state.body)["station"], "teacher");
  EXPECT_EQ(state.header("content-type"), "application/json");
  HttpsReply csv = c.get("/api/timeline.csv");
  ASSERT_EQ(csv.status, 200);
  EXPECT_EQ(csv.body.rfind("t_s,kind,text,user\n", 0), 0u);
  EXPECT_EQ(csv.header("content-type").rfind("text/csv", 0), 0u);
  EXPECT_EQ(csv.header("content-disposition").rfind("attachment", 0), 0u);
  EXPECT_EQ(c.post("/api/logout", "").status, 200);
  EXPECT_EQ(c.get("/api/state").status, 401) << "the cookie is no session any more";
}

TEST_F(ConsoleServerTest, TheWebSocketPushesTheSnapshotEvery100Ms) {
  HttpsClient anonymous(client_options());
  EXPECT_EQ(anonymous.websocket()->status(), 401);
  HttpsClient c = logged_in("observer");
  auto ws = c.websocket({{"Origin", c.origin()}});
  ASSERT_EQ(ws->status(), 101) << ws->error();
  std::string message;
  ASSERT_TRUE(ws->read(message, std::chrono::seconds(2))) << ws->error();
  EXPECT_EQ(nlohmann::json::parse(message)["station"], "teacher");
  handler.set_snapshot(R"({"station":"teacher","t_s":2.0})");
  const auto t0 = std::chrono::steady_clock::now();
  bool changed = false;
  for (int i = 0; i < 10 && !changed; ++i) {
    ASSERT_TRUE(ws->read(message, std::chrono::seconds(2))) << ws->error();
    changed = nlohmann::json::parse(message)["t_s"] == 2.0;
  }
  EXPECT_TRUE(changed);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(600));
  EXPECT_EQ(server->counts().websockets, 1u);
  // Logging out closes it.
  EXPECT_EQ(c.post("/api/logout", "").status, 200);
  bool closed = false;
  for (int i = 0; i < 5 && !closed; ++i) closed = !ws->read(message, std::chrono::seconds(2));
  EXPECT_TRUE(closed);
}

TEST_F(ConsoleServerTest, TheClassroomAuthorityVerifiesTheCertificateForEachOfItsNames) {
  for (const char* name : {"localhost", "console.ward-9.lan"}) {
    HttpsClientOptions o = client_options();
    o.host = name;
    EXPECT_EQ(HttpsClient(o).get("/").status, 200) << name;
  }
  HttpsClientOptions o = client_options();
  o.host = "evil.example";
  HttpsReply r = HttpsClient(o).get("/");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.error.find("TLS handshake"), std::string::npos) << r.error;
  // Another authority (a station's own certificate taken for one) does not vouch for it.
  o = client_options();
  o.ca_file = (keys() / "hmd-1" / "identity_cert.pem").string();
  EXPECT_EQ(HttpsClient(o).get("/").status, 0);
}

TEST_F(ConsoleServerTest, ThePageIsServedWithItsSecurityHeaders) {
  HttpsClient c(client_options());
  HttpsReply index = c.get("/");
  ASSERT_EQ(index.status, 200);
  EXPECT_EQ(index.header("content-type").rfind("text/html", 0), 0u);
  EXPECT_NE(index.body.find("id=\"login-user\""), std::string::npos);
  EXPECT_NE(index.header("content-security-policy").find("default-src 'self'"), std::string::npos);
  EXPECT_EQ(index.header("x-frame-options"), "DENY");
  EXPECT_EQ(index.header("cache-control"), "no-store");
  for (const char* file : {"/console.js", "/console.css", "/index.html"}) {
    HttpsReply r = c.get(file);
    EXPECT_EQ(r.status, 200) << file;
    EXPECT_FALSE(r.body.empty()) << file;
    EXPECT_EQ(r.header("x-frame-options"), "DENY") << file;
  }
  EXPECT_EQ(c.get("/console.js").header("content-type").rfind("text/javascript", 0), 0u);
  EXPECT_EQ(c.get("/nothing-here").status, 404);
  EXPECT_EQ(c.get("/../logins").status, 404);
  EXPECT_EQ(server->counts().refused_other, 0u) << "a page's 404 is no refusal";
  EXPECT_EQ(c.get("/api/nothing").status, 404);
  EXPECT_EQ(c.get("/api/control").status, 405);
  EXPECT_EQ(server->counts().refused_other, 2u);
}

TEST_F(ConsoleServerTest, AStationsIdentityIsNoLogin) {
  // hmd-1's DDS identity as the TLS client certificate, and its key as a password for its name and the
  // instructor's: no session.
  HttpsClientOptions o = client_options();
  o.client_cert = (keys() / "hmd-1" / "identity_cert.pem").string();
  o.client_key = (keys() / "hmd-1" / "identity_key.pem").string();
  HttpsClient c(o);
  const std::string key = file_text(keys() / "hmd-1" / "identity_key.pem");
  EXPECT_EQ(c.control(R"({"action":"breath_pause"})").status, 401) << "a certificate is no session";
  EXPECT_EQ(c.login("hmd-1", key).status, 401);
  EXPECT_EQ(c.login("instructor", key).status, 401);
  EXPECT_EQ(c.login("hmd-1", trimmed(key)).status, 401);
  EXPECT_TRUE(c.cookie().empty());
  EXPECT_EQ(c.get("/api/state").status, 401);
  EXPECT_TRUE(handler.controls().empty());
}

TEST_F(ConsoleServerTest, ConnectionsBeyond32AreRefusedUntilOneCloses) {
  std::vector<int> sockets;
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(server->port());
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  for (int i = 0; i < 32; ++i) {
    const int s = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_EQ(::connect(s, reinterpret_cast<sockaddr*>(&to), sizeof to), 0);
    sockets.push_back(s);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  HttpsReply refused = HttpsClient(client_options()).get("/");
  EXPECT_EQ(refused.status, 0) << "the 33rd connection is closed at once";
  EXPECT_EQ(server->counts().refused_other, 1u);
  ASSERT_FALSE(handler.refusals().empty());
  EXPECT_EQ(handler.refusals().back().first, 503);
  for (int s : sockets) ::close(s);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(HttpsClient(client_options()).get("/").status, 200);
}

TEST_F(ConsoleServerTest, BadKeysOrABusyPortGiveOneLineNamingTheFileOrAddress) {
  const fs::path dir = fs::temp_directory_path() / ("lungar_console_bad_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ConsoleOptions o;
  o.address = "127.0.0.1";
  o.port = 0;
  o.keys_dir = (dir / "missing").string();
  auto missing = ConsoleServer::start(o, handler, nullptr);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find(o.keys_dir), std::string::npos) << missing.error();

  o.keys_dir = dir.string();
  fs::copy_file(keys() / "console" / "logins", dir / "logins");
  std::ofstream(dir / "server_cert.pem") << "not a certificate\n";
  fs::copy_file(keys() / "console" / "server_key.pem", dir / "server_key.pem");
  auto garbage = ConsoleServer::start(o, handler, nullptr);
  ASSERT_FALSE(garbage);
  EXPECT_EQ(garbage.error().rfind((dir / "server_cert.pem").string() + ":", 0), 0u) << garbage.error();

  fs::copy_file(keys() / "console" / "server_cert.pem", dir / "server_cert.pem", fs::copy_options::overwrite_existing);
  fs::copy_file(keys() / "hmd-1" / "identity_key.pem", dir / "server_key.pem", fs::copy_options::overwrite_existing);
  auto mismatched = ConsoleServer::start(o, handler, nullptr);
  ASSERT_FALSE(mismatched);
  EXPECT_EQ(mismatched.error().rfind((dir / "server_key.pem").string() + ":", 0), 0u) << mismatched.error();

  fs::copy_file(keys() / "console" / "server_key.pem", dir / "server_key.pem", fs::copy_options::overwrite_existing);
  o.port = server->port();
  auto busy = ConsoleServer::start(o, handler, nullptr);
  ASSERT_FALSE(busy);
  EXPECT_EQ(busy.error(),
            "console: cannot listen on 127.0.0.1:" + std::to_string(server->port()) + ": Address already in use");
  o.address = "console.local";
  auto bad_address = ConsoleServer::start(o, handler, nullptr);
  ASSERT_FALSE(bad_address);
  EXPECT_NE(bad_address.error().find("\"console.local\""), std::string::npos) << bad_address.error();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lungar::console
