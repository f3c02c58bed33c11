/// @file bake_cli_test.cpp
/// @brief `lungar-bake` as a user runs it: --help and --version exit 0; a missing mesh or a bad option exits
///        non-zero below 128 with one line on stderr and writes nothing; a small procedural bake writes the
///        asset and every key of the report; Ctrl-C stops a bake with 130 and leaves no file.
#include <gtest/gtest.h>

#include <algorithm>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "label_map_files_support.h"
#include "sim/asset/asset_io.h"
#include "sim_test_support.h"
#include "tests/file_text.h"

namespace lungar::sim {
namespace {

const std::string kBake = std::string(LUNGAR_BINARY_DIR) + "/sim/lungar-bake";

/// Runs lungar-bake with `args`, stderr to `err` (and stdout to `out`); returns the exit status.
int run(const std::string& args, const std::string& err, const std::string& out = "/dev/null") {
  const int status = std::system((kBake + " " + args + " >" + out + " 2>" + err).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

using ::lungar::testing::file_text;

TEST(BakeCli, HelpAndVersion) {
  test::TempDir dir;
  EXPECT_EQ(run("--help", dir.file("err"), dir.file("help")), 0);
  const std::string help = file_text(dir.file("help"));
  EXPECT_EQ(help.find("->"), std::string::npos) << "CLI11's enum-map garbage:\n" << help;
  EXPECT_NE(help.find("--map TEXT:{radial,conformal}=conformal"), std::string::npos) << help;
  EXPECT_EQ(run("--version", dir.file("err")), 0);
}

TEST(BakeCli, MapNamesAnyCaseAndRefusesOthers) {
  test::TempDir dir;
  const std::string args = "--procedural --nodes 600 --no-evaluate --no-transfer-rows --out " + dir.file("r.lungbake") +
                           " --report-json " + dir.file("r.json") + " --map ";
  ASSERT_EQ(run(args + "RADIAL", dir.file("err")), 0) << file_text(dir.file("err"));
  EXPECT_EQ(nlohmann::json::parse(file_text(dir.file("r.json")))["map"], "radial");
  EXPECT_EQ(run(args + "spherical", dir.file("err")), 2);
  EXPECT_NE(file_text(dir.file("err")).find("spherical not in {radial,conformal}"), std::string::npos)
      << file_text(dir.file("err"));
}

/// Starts lungar-bake with `args` (stdout to /dev/null, stderr to `err`); its process id.
pid_t spawn_bake(const std::vector<std::string>& args, const std::string& err) {
  std::vector<std::string> all{kBake};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  if (posix_spawn(&pid, kBake.c_str(), &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

TEST(BakeCli, CtrlCStopsTheBakeSoonAndLeavesNoFile) {
  using namespace std::chrono_literals;
  using Clock = std::chrono::steady_clock;
  test::TempDir dir;
  const std::string err = dir.file("err");
  const pid_t pid = spawn_bake({"--procedural", "--nodes", "100000", "--threads", "2", "--out",
                                dir.file("big.lungbake"), "--report-json", dir.file("big.json")}, err);
  ASSERT_GT(pid, 0);
  const auto started = Clock::now();
  while (file_text(err).find("baking") == std::string::npos && Clock::now() - started < 30s)
    std::this_thread::sleep_for(10ms);
  std::this_thread::sleep_for(1s);  // into the bake, which takes far longer at 100,000 nodes
  const auto sent = Clock::now();
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (Clock::now() - sent > 120s) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      FAIL() << "still baking 120 s after Ctrl-C";
    }
    std::this_thread::sleep_for(10ms);
  }
  const double stop_s = std::chrono::duration<double>(Clock::now() - sent).count();
  ASSERT_TRUE(WIFEXITED(status)) << "the signal ended it instead of the bake stopping";
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << file_text(err);
  EXPECT_NE(file_text(err).find("interrupted; nothing was written"), std::string::npos) << file_text(err);
  EXPECT_EQ(dir.entries(), 1u) << "only the captured stderr: no asset, report or .partial file";
  // A parallel step stops within a body; a serial one (the conformal map's solve, the factorisation) runs to its end.
  EXPECT_LT(stop_s, 60.0);
}

TEST(BakeCli, MissingMeshIsOneCleanErrorAndNoFile) {
  test::TempDir dir;
  const int rc = run("--mesh " + dir.file("none.stl") + " --out " + dir.file("x.lungbake"), dir.file("err"));
  EXPECT_GE(rc, 1);
  EXPECT_LT(rc, 128);
  const std::string err = file_text(dir.file("err"));
  EXPECT_NE(err.find("none.stl: cannot open"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.lungbake")));
}

// An output that can never be written is found before the bake, not after its minutes: and a report that cannot be
// written does not leave the asset written beside a failed command.
TEST(BakeCli, AnOutputThatCannotBeWrittenIsRefusedBeforeBaking) {
  test::TempDir dir;
  std::ofstream(dir.file("plain")) << "a file, not a folder\n";
  const std::string bake = "--procedural --nodes 600 --no-evaluate --no-transfer-rows ";
  EXPECT_EQ(run(bake + "--out " + dir.file("plain") + "/x.lungbake", dir.file("err")), 1);
  std::string err = file_text(dir.file("err"));
  EXPECT_NE(err.find("lungar-bake: --out: " + dir.file("plain") + "/x.lungbake: cannot open for writing"),
            std::string::npos)
      << err;

  EXPECT_EQ(run(bake + "--out " + dir.file("x.lungbake") + " --report-json " + dir.file("plain") + "/r.json",
                dir.file("err")),
            1);
  err = file_text(dir.file("err"));
  EXPECT_NE(err.find("lungar-bake: --report-json: " + dir.file("plain") + "/r.json"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.lungbake"))) << "the asset of a command that failed";
  EXPECT_EQ(dir.entries(), 2u) << "only the plain file and the captured stderr: no .partial file";
}

TEST(BakeCli, BadOptionsAreRefused) {
  test::TempDir dir;
  for (const std::string args : {"", "--procedural", "--procedural --out a.lungbake --bands 9",
                                 "--procedural --out a.lungbake --units inch", "--mesh a.stl --procedural --out a"}) {
    const int rc = run(args, dir.file("err"));
    EXPECT_GE(rc, 1) << args;
    EXPECT_LT(rc, 128) << args;
    EXPECT_FALSE(file_text(dir.file("err")).empty()) << args;
  }
}

TEST(BakeCli, ProceduralBakeWritesTheAssetAndEveryReportKey) {
  test::TempDir dir;
  const std::string args = "--procedural --nodes 2000 --seed 3 --threads 2 --out " + dir.file("p.lungbake") +
                           " --report-json " + dir.file("p.json");
  ASSERT_EQ(run(args, dir.file("err")), 0) << file_text(dir.file("err"));
  const Result<BakedAsset> a = load_asset(dir.file("p.lungbake"));
  ASSERT_TRUE(a) << a.error();
  const nlohmann::json r = nlohmann::json::parse(file_text(dir.file("p.json")));
  for (const char* key : {"nodes", "triangles", "lungs", "bands", "coefficients", "transfer_nnz_per_row_mean",
                          "bake_s", "folded_triangles", "eq7_rms_rel_error", "alpha", "paper_interp_rms_rel_error",
                          "linear_basis_rms_rel_error", "displacement_max_mm_at_tidal", "tidal_volume_rel_error",
                          "base_apex_displacement_ratio", "posterior_anterior_displacement_ratio", "bands_sweep"})
    EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_EQ(r["nodes"].get<std::uint32_t>(), a->vertex_count());
  EXPECT_EQ(r["bands_sweep"].size(), 7u);
  EXPECT_EQ(r["bands_sweep"][2]["coefficients"].get<int>(), 16);
  EXPECT_EQ(r["model"], "sliding");
  const nlohmann::json& m = r["motion"];
  for (const char* key : {"si_share", "apex_base_ratio", "dorsal_ventral_ratio", "mean_displacement_mm", "regions",
                          "prone", "upright", "compared", "interior_si_share", "interior_apex_base_ratio",
                          "interior_dorsal_ventral_ratio", "interior_mean_displacement_mm", "interior_points"})
    EXPECT_TRUE(m.contains(key)) << "motion." << key;
  EXPECT_EQ(m["interior_points"].get<int>(), 5000);
  EXPECT_GT(m["interior_mean_displacement_mm"].get<double>(), 0.0);
  EXPECT_EQ(m["compared"]["model"], "paper");
  EXPECT_GT(m["si_share"].get<double>(), m["compared"]["supine"]["si_share"].get<double>());
  for (const char* face : {"diaphragmatic", "costal", "mediastinal", "apical"})
    EXPECT_TRUE(m["regions"][face].contains("volume_share")) << face;
}

TEST(BakeCli, ThePapersModelIsOneOptionAway) {
  test::TempDir dir;
  const std::string args = "--procedural --nodes 2000 --no-transfer-rows --out " + dir.file("p.lungbake") +
                           " --report-json " + dir.file("p.json") + " --model ";
  ASSERT_EQ(run(args + "paper", dir.file("err")), 0) << file_text(dir.file("err"));
  const nlohmann::json r = nlohmann::json::parse(file_text(dir.file("p.json")));
  EXPECT_EQ(r["model"], "paper");
  EXPECT_EQ(r["motion"]["compared"]["model"], "sliding");
  EXPECT_LT(r["motion"]["si_share"].get<double>(), 0.5) << "the paper's balloon";
  EXPECT_EQ(run(args + "balloon", dir.file("err")), 2);
}

TEST(BakeCli, ExportWritesPlyAndRefusesBadInputWithOneLine) {
  test::TempDir dir;
  ASSERT_EQ(run("--procedural --nodes 2000 --no-evaluate --no-transfer-rows --out " + dir.file("p.lungbake"),
                dir.file("err")),
            0)
      << file_text(dir.file("err"));
  EXPECT_EQ(run("export --help", dir.file("err"), dir.file("help")), 0);
  EXPECT_NE(file_text(dir.file("help")).find("--posture"), std::string::npos);
  const std::string args = "export --asset " + dir.file("p.lungbake") + " --out " + dir.file("e.ply");
  ASSERT_EQ(run(args + " --posture prone --volume-ml 400", dir.file("err")), 0) << file_text(dir.file("err"));
  const std::string ply = file_text(dir.file("e.ply"));
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  for (const char* line : {"property float dx\n", "property float dz\n", "element face "})
    EXPECT_NE(ply.find(line), std::string::npos) << line;
  EXPECT_NE(file_text(dir.file("err")).find("wrote " + dir.file("e.ply")), std::string::npos)
      << file_text(dir.file("err"));
  std::filesystem::remove(dir.file("e.ply"));
  EXPECT_EQ(run(args + " --gravity 0,0", dir.file("err")), 2);
  EXPECT_NE(file_text(dir.file("err")).find("--gravity"), std::string::npos) << file_text(dir.file("err"));
  EXPECT_EQ(run(args + " --posture sideways", dir.file("err")), 2);
  EXPECT_EQ(run("export --asset " + dir.file("none.lungbake") + " --out " + dir.file("e.ply"), dir.file("err")), 1);
  EXPECT_NE(file_text(dir.file("err")).find("none.lungbake"), std::string::npos) << file_text(dir.file("err"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("e.ply")));
  ASSERT_EQ(run(args + " --series 4", dir.file("err")), 0) << file_text(dir.file("err"));
  EXPECT_TRUE(std::filesystem::exists(dir.file("e_003.ply")));
  // Pathologies: two in one export, then a bad one refused in one line naming it, writing nothing.
  ASSERT_EQ(run(args + " --pathology pneumothorax:left:20 --pathology consolidation:right:upper", dir.file("err")), 0)
      << file_text(dir.file("err"));
  EXPECT_NE(file_text(dir.file("e.ply")).find("with pneumothorax:left:20 with consolidation:right:upper"),
            std::string::npos);
  std::filesystem::remove(dir.file("e.ply"));
  ASSERT_EQ(run(args + " --pathology emphysema:0.4", dir.file("err")), 0) << file_text(dir.file("err"));
  std::filesystem::remove(dir.file("e.ply"));
  ASSERT_EQ(run(args + " --pathology ards:0.4", dir.file("err")), 0) << file_text(dir.file("err"));
  std::filesystem::remove(dir.file("e.ply"));
  EXPECT_EQ(run(args + " --pathology ards:1.4", dir.file("err")), 1);
  const std::string err = file_text(dir.file("err"));
  EXPECT_NE(err.find("'ards:1.4'"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("e.ply")));
}

TEST(BakeCli, ExportWritesInteriorPointsAndRefusesTheirBadOptionsAsUsageErrors) {
  test::TempDir dir;
  ASSERT_EQ(run("--procedural --nodes 2000 --no-evaluate --no-transfer-rows --out " + dir.file("p.lungbake"),
                dir.file("err")),
            0)
      << file_text(dir.file("err"));
  const std::string args = "export --asset " + dir.file("p.lungbake") + " --out " + dir.file("e.ply");
  const std::string inside = " --interior-out " + dir.file("i.ply");
  ASSERT_EQ(run(args + " --interior 200" + inside, dir.file("err")), 0) << file_text(dir.file("err"));
  const std::string ply = file_text(dir.file("i.ply"));
  EXPECT_NE(ply.find("element vertex 200\n"), std::string::npos);
  EXPECT_EQ(ply.find("element face"), std::string::npos) << "vertices only";
  EXPECT_NE(file_text(dir.file("err")).find("wrote " + dir.file("i.ply") + ": 200 interior points; SI share"),
            std::string::npos)
      << file_text(dir.file("err"));
  std::filesystem::remove(dir.file("e.ply"));
  std::filesystem::remove(dir.file("i.ply"));
  // Each refusal: exit 2 as the tool's other usage errors, one line naming the option, no file.
  for (const auto& [options, expected] :
       {std::pair{" --interior 0" + inside, "lungar-bake export: --interior: expected a positive number of points"},
        std::pair{std::string(" --interior -3") + inside, "lungar-bake export: --interior: expected a positive"},
        std::pair{std::string(" --interior 50"), "lungar-bake export: --interior: expected --interior-out FILE"},
        std::pair{inside, "lungar-bake export: --interior-out: expected --interior N"}}) {
    EXPECT_EQ(run(args + options, dir.file("err")), 2) << options;
    const std::string err = file_text(dir.file("err"));
    EXPECT_EQ(err.rfind(expected, 0), 0u) << options << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("e.ply"))) << options;
    EXPECT_FALSE(std::filesystem::exists(dir.file("i.ply"))) << options;
  }
  // A file that cannot be written fails the work, exit 1 as an unwritable --out does.
  std::ofstream(dir.file("no"), std::ios::binary) << "a file where a folder should be";
  EXPECT_EQ(run(args + " --interior 50 --interior-out " + dir.file("no/i.ply"), dir.file("err")), 1);
  EXPECT_EQ(file_text(dir.file("err")).rfind("lungar-bake export: --interior-out: " + dir.file("no/i.ply"), 0), 0u)
      << file_text(dir.file("err"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("e.ply")));
}

/// Two balls of 30 mm radius on a 2 mm grid: label 2 at x = -40 mm (the right lung, LPS), label 3 at x = +40 mm.
test::LabelVolume two_balls() {
  test::LabelVolume v;
  v.size = {70, 40, 40};
  v.spacing = {2, 2, 2};
  v.origin = {-69, -39, -39};
  for (int k = 0; k < 40; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 70; ++i) {
        const double x = -69 + 2 * i, y = -39 + 2 * j, z = -39 + 2 * k;
        const double r2 = y * y + z * z;
        v.labels.push_back((x + 40) * (x + 40) + r2 < 900 ? 2 : (x - 40) * (x - 40) + r2 < 900 ? 3 : 0);
      }
  return v;
}

TEST(BakeCli, LabelMapBakeWritesThePerLungReport) {
  test::TempDir dir;
  ASSERT_TRUE(test::write_label_volume(dir.file("m.nii.gz"), two_balls()));
  const std::string args = "--labelmap " + dir.file("m.nii.gz") + " --label right=2 --label left=3 --nodes 8000 " +
                           "--bands 3 --no-transfer-rows --threads 2 --out " + dir.file("m.lungbake") +
                           " --report-json " + dir.file("m.json");
  ASSERT_EQ(run(args, dir.file("err")), 0) << file_text(dir.file("err"));
  const nlohmann::json r = nlohmann::json::parse(file_text(dir.file("m.json")));
  EXPECT_EQ(r["map"], "conformal");
  ASSERT_EQ(r["per_lung"].size(), 2u);
  for (const auto& lung : r["per_lung"]) {
    for (const char* key : {"name", "nodes", "volume_ml", "centroid_mm", "folded_triangles", "eq7_rms_rel_error",
                            "map", "maps", "bands_sweep", "input_nodes", "label_map"})
      EXPECT_TRUE(lung.contains(key)) << key;
    EXPECT_EQ(lung["folded_triangles"], 0);
    EXPECT_NEAR(lung["volume_ml"].get<double>(), 113.1, 3.0) << "a ball of 30 mm";
    EXPECT_NEAR(std::abs(lung["centroid_mm"][0].get<double>()), 40, 1.0);
  }
  EXPECT_EQ(r["per_lung"][0]["name"], "right");
  EXPECT_LT(r["per_lung"][0]["centroid_mm"][0].get<double>(), 0);
  ASSERT_EQ(r["bands_sweep"].size(), 7u);
  EXPECT_TRUE(r["bands_sweep"][1]["by_map"].contains("radial"));
  EXPECT_TRUE(r["bands_sweep"][1]["by_map"].contains("conformal"));
}

TEST(BakeCli, BadLabelOptionsAreRefused) {
  test::TempDir dir;
  ASSERT_TRUE(test::write_label_volume(dir.file("m.nrrd"), two_balls()));
  const std::string map = dir.file("m.nrrd");
  for (const std::string& args : std::vector<std::string>{"--labelmap " + map + " --label right --out a.lungbake",
                                 std::string("--label right=2 --out a.lungbake"),
                                 "--labelmap " + map + " --mesh x.stl --label right=2 --out a.lungbake",
                                 "--labelmap " + map + " --label right=9 --out " + dir.file("a.lungbake")}) {
    const int rc = run(args, dir.file("err"));
    EXPECT_GE(rc, 1) << args;
    EXPECT_LT(rc, 128) << args;
    EXPECT_FALSE(file_text(dir.file("err")).empty()) << args;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.lungbake"))) << args;
  }
}

}  // namespace
}  // namespace lungar::sim
