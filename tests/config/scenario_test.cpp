// Tests of config/scenario_load: the shipped scenarios, the event kinds and their keys, and one exact message
// per kind of bad scenario (unknown event, negative time, overlapping turns, unknown preset, ...).
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "config/scenario_load.h"

using lungar::config::BreathingSettings;
using lungar::config::load_scenario;
using lungar::config::load_scenario_from_string;
using lungar::config::Scenario;
using lungar::config::ScenarioEventKind;

namespace {

const std::string kScenarios = std::string(LUNGAR_SOURCE_DIR) + "/config/scenarios";

std::string error_of(const std::string& toml) {
  auto r = load_scenario_from_string(toml, "bad.toml");
  EXPECT_FALSE(r) << "expected an error for:\n" << toml;
  return r.error();
}

/// "  name_1 = ..." (a key, not a comment or a table header).
bool is_key_line(const std::string& line) {
  std::size_t k = line.find_first_not_of(" \t");
  const std::size_t start = k;
  while (k < line.size() && (std::islower(static_cast<unsigned char>(line[k])) ||
                             std::isdigit(static_cast<unsigned char>(line[k])) || line[k] == '_')) {
    ++k;
  }
  if (k == start || start == std::string::npos) return false;
  k = line.find_first_not_of(" \t", k);
  return k != std::string::npos && line[k] == '=';
}

Scenario ok(const std::string& toml) {
  auto r = load_scenario_from_string(toml, "ok.toml");
  EXPECT_TRUE(r) << r.error();
  return r ? *r : Scenario{};
}

}  // namespace

TEST(Scenario, TheTeachingScenarioReadsAsTheIssueDescribesIt) {
  auto r = load_scenario(kScenarios + "/teaching.toml");
  ASSERT_TRUE(r) << r.error();
  const Scenario& s = *r;
  EXPECT_EQ(s.start.preset, "normal");
  EXPECT_EQ(s.start_pose, "upright");
  ASSERT_EQ(s.events.size(), 2u);
  EXPECT_EQ(s.events[0].kind, ScenarioEventKind::Turn);
  EXPECT_DOUBLE_EQ(s.events[0].at_s, 20.0);
  EXPECT_DOUBLE_EQ(s.events[0].over_s, 5.0);
  EXPECT_EQ(s.events[0].pose, "supine");
  EXPECT_EQ(s.events[1].kind, ScenarioEventKind::Change);
  EXPECT_DOUBLE_EQ(s.events[1].at_s, 40.0);
  EXPECT_EQ(s.events[1].preset, "fibrosis");
  EXPECT_FALSE(s.events[1].rate_bpm);
}

TEST(Scenario, EveryShippedScenarioLoadsAndDocumentsEveryKey) {
  int files = 0, keys = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenarios)) {
    if (entry.path().extension() != ".toml") continue;
    ++files;
    auto r = load_scenario(entry.path().string());
    EXPECT_TRUE(r) << r.error();
    std::ifstream in(entry.path());
    std::string line;
    while (std::getline(in, line)) {
      if (is_key_line(line)) {
        ++keys;
        EXPECT_NE(line.find('#'), std::string::npos) << entry.path() << ": " << line;
      }
    }
  }
  EXPECT_GE(files, 2);
  EXPECT_GT(keys, 40);
}

TEST(Scenario, StartDefaultsToTheConfigsBreathing) {
  BreathingSettings b;
  b.preset = "emphysema";
  b.rate_bpm = 15.0;
  auto r = load_scenario_from_string("[start]\ntidal_volume_ml = 450\n", "x.toml", b);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->start.preset, "emphysema");
  EXPECT_DOUBLE_EQ(r->start.rate_bpm, 15.0);
  EXPECT_DOUBLE_EQ(r->start.tidal_volume_ml, 450.0);
  EXPECT_TRUE(r->events.empty());
}

TEST(Scenario, EventsAreSortedByTimeAndKeepTheirFileIndex) {
  const Scenario s = ok("[[event]]\nat_s = 30\nkind = \"sigh\"\n[[event]]\nat_s = 10\nkind = \"hold\"\nduration_s = 2\n"
                        "[[event]]\nat_s = 30\nkind = \"apnoea\"\nduration_s = 3\n");
  ASSERT_EQ(s.events.size(), 3u);
  EXPECT_EQ(s.events[0].kind, ScenarioEventKind::Hold);
  EXPECT_EQ(s.events[0].index, 1);
  EXPECT_EQ(s.events[1].kind, ScenarioEventKind::Sigh);  // equal times keep the file's order
  EXPECT_EQ(s.events[2].kind, ScenarioEventKind::Apnoea);
  EXPECT_EQ(s.events[2].line, 9);
}

TEST(Scenario, KindSpecificKeys) {
  const Scenario s = ok(
      "[[event]]\nat_s = 1\nkind = \"ventilator\"\npeep_cmh2o = 5\ntau_s = 0.4\nrate_bpm = 16\n"
      "[[event]]\nat_s = 2\nkind = \"turn\"\nrotation_wxyz = [0.7071068, -0.7071068, 0, 0]\nover_s = 3\n"
      "[[event]]\nat_s = 9\nkind = \"spontaneous\"\nover_s = 2\n"
      "[[event]]\nat_s = 10\nkind = \"sigh\"\nvolume_ml = 1100\n");
  ASSERT_EQ(s.events.size(), 4u);
  EXPECT_EQ(s.events[0].peep_cmh2o, 5.0);
  EXPECT_EQ(s.events[0].tau_s, 0.4);
  EXPECT_EQ(s.events[0].rate_bpm, 16.0);
  EXPECT_TRUE(s.events[1].pose.empty());
  EXPECT_DOUBLE_EQ(s.events[1].rotation_wxyz[1], -0.7071068);
  EXPECT_DOUBLE_EQ(s.events[2].over_s, 2.0);
  EXPECT_EQ(s.events[3].volume_ml, 1100.0);
}

// --- bad scenarios: each asserts the whole message, naming the file, line, key and what was expected ---

TEST(BadScenario, UnknownEvent) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 5\nkind = \"cough\"\n"),
            "bad.toml:3: key 'event[0].kind': expected one of \"turn\" | \"change\" | \"sigh\" | \"hold\" | "
            "\"apnoea\" | \"ventilator\" | \"spontaneous\" | \"pathology\", got the string \"cough\"");
}

TEST(BadScenario, MissingKind) {
  EXPECT_EQ(error_of("duration_s = 30\n\n[[event]]\nat_s = 5\n"),
            "bad.toml:3: key 'event[0].kind': expected one of \"turn\" | \"change\" | \"sigh\" | \"hold\" | "
            "\"apnoea\" | \"ventilator\" | \"spontaneous\" | \"pathology\", got nothing");
}

TEST(BadScenario, NegativeTime) {
  EXPECT_EQ(error_of("[[event]]\nkind = \"sigh\"\nat_s = -2.5\n"),
            "bad.toml:3: key 'event[0].at_s': expected a number in [0, 86400] s, got the number -2.5");
}

TEST(BadScenario, MissingTime) {
  EXPECT_EQ(error_of("[[event]]\nkind = \"sigh\"\n"),
            "bad.toml:1: key 'event[0].at_s': expected the event's time, a number in [0, 86400] s, got nothing");
}

TEST(BadScenario, TimeAfterTheEnd) {
  EXPECT_EQ(error_of("duration_s = 30\n[[event]]\nkind = \"sigh\"\nat_s = 31\n"),
            "bad.toml:4: key 'event[0].at_s': expected a time within the scenario's duration_s (30 s), got 31 s");
}

TEST(BadScenario, OverlappingTurns) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 20\nkind = \"turn\"\nto = \"supine\"\nover_s = 5\n\n"
                     "[[event]]\nat_s = 22\nkind = \"turn\"\nto = \"left_lateral\"\nover_s = 2\n"),
            "bad.toml:8: key 'event[1].at_s': expected turns that do not overlap, got a turn at 22 s while the turn "
            "of event[0] (line 2) runs from 20 s to 25 s");
}

TEST(BadScenario, OverlappingTurnsAreFoundWhateverTheFileOrder) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 22\nkind = \"turn\"\nto = \"left_lateral\"\nover_s = 2\n\n"
                     "[[event]]\nat_s = 20\nkind = \"turn\"\nto = \"supine\"\nover_s = 5\n"),
            "bad.toml:2: key 'event[0].at_s': expected turns that do not overlap, got a turn at 22 s while the turn "
            "of event[1] (line 8) runs from 20 s to 25 s");
}

TEST(BadScenario, OverlappingHoldAndApnoea) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 10\nkind = \"apnoea\"\nduration_s = 10\n"
                     "[[event]]\nat_s = 15\nkind = \"hold\"\nduration_s = 2\n"),
            "bad.toml:6: key 'event[1].at_s': expected holds and apnoeas that do not overlap, got a hold at 15 s while "
            "the apnoea of event[0] (line 2) lasts from 10 s to 20 s");
}

TEST(BadScenario, UnknownPreset) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 40\nkind = \"change\"\npreset = \"asthma\"\n"),
            "bad.toml:4: key 'event[0].preset': expected one of \"normal\" | \"emphysema\" | \"fibrosis\", got the "
            "string \"asthma\"");
  EXPECT_EQ(error_of("[start]\npreset = \"copd\"\n"),
            "bad.toml:2: key 'start.preset': expected one of \"normal\" | \"emphysema\" | \"fibrosis\", got the string "
            "\"copd\"");
}

TEST(BadScenario, UnknownPose) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 1\nkind = \"turn\"\nto = \"sitting\"\nover_s = 1\n"),
            "bad.toml:4: key 'event[0].to': expected one of \"upright\" | \"supine\" | \"prone\" | \"left_lateral\" | "
            "\"right_lateral\", got the string \"sitting\"");
}

TEST(BadScenario, KeyThatDoesNotBelongToTheKind) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 1\nkind = \"sigh\"\npreset = \"normal\"\n"),
            "bad.toml:4: unknown key 'event[0].preset'; expected one of: at_s, kind, volume_ml");
}

TEST(BadScenario, TurnWithoutDurationOrTarget) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 1\nkind = \"turn\"\nto = \"supine\"\n"),
            "bad.toml:1: key 'event[0].over_s': expected the duration of the turn, a number in [0.01, 600] s, got "
            "nothing");
  EXPECT_EQ(error_of("[[event]]\nat_s = 1\nkind = \"turn\"\nover_s = 2\n"),
            "bad.toml:1: key 'event[0].to': expected the pose to turn to (upright, supine, prone, left_lateral or "
            "right_lateral) or rotation_wxyz, got nothing");
  EXPECT_EQ(error_of("[[event]]\nat_s = 1\nkind = \"turn\"\nover_s = 2\nrotation_wxyz = [1, 1, 0, 0]\n"),
            "bad.toml:5: key 'event[0].rotation_wxyz': expected a unit quaternion [w, x, y, z] (norm 1 within 1e-3), "
            "got norm 1.41421");
}

TEST(BadScenario, ChangeThatChangesNothing) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 1\nkind = \"change\"\n"),
            "bad.toml:3: key 'event[0].kind': expected at least one of preset, rate_bpm, ie_ratio, tidal_volume_ml "
            "with kind = \"change\", got none");
}

TEST(BadScenario, SighOnTheVentilator) {
  EXPECT_EQ(error_of("[[event]]\nat_s = 1\nkind = \"ventilator\"\n[[event]]\nat_s = 5\nkind = \"sigh\"\n"),
            "bad.toml:5: key 'event[1].kind': expected a sigh during spontaneous breathing, got one while on the "
            "ventilator");
}

TEST(BadScenario, EventIsNotAnArrayOfTables) {
  EXPECT_EQ(error_of("event = 3\n"), "bad.toml:1: key 'event': expected [[event]] tables, got the integer 3");
}

TEST(Scenario, APathologyEventSaysWhatComesOrGoesAndOverHowLong) {
  auto s = load_scenario_from_string(
      "pathology = [\"ards:0.6\"]\n[[event]]\nat_s = 3.0\nkind = \"pathology\"\nadd = \"pneumothorax:right:30\"\n"
      "over_s = 5.0\n",
      "p.toml");
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(s->pathologies, std::vector<std::string>{"ards:0.6"});
  ASSERT_EQ(s->events.size(), 1u);
  EXPECT_EQ(s->events[0].kind, ScenarioEventKind::Pathology);
  EXPECT_EQ(s->events[0].pathology_add, "pneumothorax:right:30");
  EXPECT_EQ(s->events[0].over_s, 5.0);
  EXPECT_EQ(error_of("[[event]]\nat_s = 3.0\nkind = \"pathology\"\nover_s = 5.0\n"),
            "bad.toml:1: key 'event[0].add': expected one of add = SPEC (the pathology comes) or remove = SPEC (it "
            "goes: a needle decompression), got neither");
  EXPECT_NE(error_of("[[event]]\nat_s = 3.0\nkind = \"pathology\"\nremove = \"x\"\n").find("over_s"),
            std::string::npos);
}

TEST(BadScenario, UnknownTopLevelKey) {
  EXPECT_EQ(error_of("duration = 30\n"),
            "bad.toml:1: unknown key 'duration'; expected one of: description, duration_s, name, pathology, start");
}

TEST(BadScenario, SyntaxErrorAndMissingFile) {
  EXPECT_EQ(error_of("[[event]\n").rfind("bad.toml:1:", 0), 0u);
  EXPECT_EQ(load_scenario("/nonexistent/s.toml").error(),
            "/nonexistent/s.toml: cannot read the scenario: expected a TOML file, got no such file");
}

// An empty scenario was accepted, and the log still said it breathes and turns the patient: it is refused in one
// line naming the file; a scenario with only a start, only a pathology or only an event is one.
TEST(Scenario, AnEmptyScenarioIsRefusedNamingTheFile) {
  for (const std::string toml : {"", "name = \"nothing\"\nduration_s = 30.0\n", "# only comments\n"}) {
    const std::string e = error_of(toml);
    EXPECT_EQ(e.rfind("bad.toml: ", 0), 0u) << e;
    EXPECT_NE(e.find("expected a scenario: at least one [[event]], a [start] table or a pathology list"),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  ok("[start]\n");
  ok("pathology = [\"ards:0.6\"]\n");
  ok("[[event]]\nat_s = 1.0\nkind = \"sigh\"\n");
}

// The README's ARDS-proning command stopped at 10 s (lungar's default), before the turn at 20 s: every command
// that runs a shipped scenario, in the README or in a scenario's own comments, gives --seconds for the whole of it.
TEST(Scenario, EveryDocumentedCommandRunsTheWholeScenario) {
  const std::string root = std::string(LUNGAR_SOURCE_DIR) + "/";
  std::vector<std::string> files = {root + "README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(kScenarios)) files.push_back(entry.path().string());
  int commands = 0;
  for (const std::string& file : files) {
    std::ifstream in(file);
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_no;
      // The commands of a line: its `code` spans, else the whole line (an indented block, a comment).
      std::vector<std::string> spans;
      for (std::size_t open = line.find('`'); open != std::string::npos; open = line.find('`', open)) {
        const std::size_t close = line.find('`', open + 1);
        if (close == std::string::npos) break;
        spans.push_back(line.substr(open + 1, close - open - 1));
        open = close + 1;
      }
      if (spans.empty()) spans.push_back(line);
      for (const std::string& span : spans) {
        std::istringstream words(span);
        std::vector<std::string> w{std::istream_iterator<std::string>(words), {}};
        std::string scenario;
        double seconds = 10.0;  // lungar's default run
        for (std::size_t k = 0; k + 1 < w.size(); ++k) {
          if (w[k] == "--scenario") scenario = w[k + 1];
          if (w[k] == "--seconds" && std::isdigit(static_cast<unsigned char>(w[k + 1][0])))
            seconds = std::stod(w[k + 1]);  // "--seconds S" in a synopsis is no command
        }
        if (scenario.empty() || !std::filesystem::exists(root + scenario)) continue;  // "--scenario FILE"
        ++commands;
        const auto sc = load_scenario(root + scenario);
        ASSERT_TRUE(sc) << sc.error();
        EXPECT_GE(seconds, sc->duration_s) << file << ":" << line_no << ": `" << span << "` stops at " << seconds
                                           << " s, the scenario lasts " << sc->duration_s << " s";
      }
    }
  }
  EXPECT_GE(commands, 4) << "the README's and the scenarios' own commands";
}
