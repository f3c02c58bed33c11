/// @file mesh_import_test.cpp
/// @brief lungar-bake's input side: STL (binary, ASCII), OBJ and PLY surfaces bake; empty, truncated,
///        over-claiming, NaN-bearing and open meshes are refused with one clear line and no output file; the
///        real right lung from ../shared bakes under 1 % at the default 36 coefficients, without folds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "sim/asset/asset_io.h"
#include "sim/bake_tool/bake_command.h"
#include "sim/bake_tool/mesh_import.h"
#include "sim/mesh/procedural_lungs.h"
#include "sim/mesh/spherical_map.h"
#include "sim_test_support.h"
#include "test_meshes.h"

namespace lungar::sim {
namespace {

using test::TempDir;

/// Binary STL with `claimed` in the header and the given triangles (corner positions, 9 floats each).
void write_binary_stl(const std::string& path, const std::vector<std::array<float, 9>>& tris, std::uint32_t claimed) {
  std::ofstream out(path, std::ios::binary);
  char header[80] = "binary STL written by lungar's tests";
  out.write(header, 80);
  out.write(reinterpret_cast<const char*>(&claimed), 4);
  for (const auto& t : tris) {
    const float normal[3] = {0, 0, 0};
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(normal), 12);
    out.write(reinterpret_cast<const char*>(t.data()), 36);
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

std::vector<std::array<float, 9>> corners(const TriMesh& m, const Eigen::Vector3d& shift = Eigen::Vector3d::Zero()) {
  std::vector<std::array<float, 9>> out;
  for (const Triangle& t : m.triangles) {
    std::array<float, 9> c{};
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) c[3 * k + j] = static_cast<float>(m.positions[t[k]][j] + shift[j]);
    out.push_back(c);
  }
  return out;
}

const TriMesh& small_lung() {
  static const TriMesh m = procedural_lungs(1600, 5)[0].mesh;  // the right lung, ~830 vertices
  return m;
}

BakeCommand command(const std::vector<std::string>& meshes, const std::string& out) {
  BakeCommand c;
  c.meshes = meshes;
  c.out = out;
  c.options.threads = 2;
  c.options.bands_sweep = false;
  return c;
}

/// command() for the import's own figures: one mesh at `nodes`, without the accuracy figures or the rows.
BakeCommand import_command(const std::string& mesh, const std::string& out, std::uint32_t nodes) {
  BakeCommand c = command({mesh}, out);
  c.nodes = nodes;
  c.options.evaluate = false;
  c.options.transfer_rows = false;
  return c;
}

class BadMesh : public ::testing::Test {
 protected:
  /// Runs the bake on `mesh` and checks the refusal: one line naming the file, no asset left behind.
  std::string refusal(const std::string& mesh) {
    std::vector<std::string> notes;
    const Result<BakeReport> r = run_bake_command(command({mesh}, dir_.file("out.lungbake")), nullptr, notes);
    test::expect_refused_cleanly(r, dir_, "out.lungbake");
    if (r) return {};
    EXPECT_NE(r.error().find(mesh), std::string::npos) << r.error();
    return r.error();
  }
  TempDir dir_;
};

TEST_F(BadMesh, MissingFile) { EXPECT_NE(refusal(dir_.file("none.stl")).find("no such file"), std::string::npos); }

TEST_F(BadMesh, EmptyFile) {
  std::ofstream(dir_.file("empty.stl")).flush();
  refusal(dir_.file("empty.stl"));
}

TEST_F(BadMesh, TruncatedBinaryStl) {
  write_binary_stl(dir_.file("cut.stl"), corners(small_lung()), static_cast<std::uint32_t>(small_lung().triangles.size()));
  std::filesystem::resize_file(dir_.file("cut.stl"), 84 + 50 * 100 + 17);
  refusal(dir_.file("cut.stl"));
}

TEST_F(BadMesh, HeaderClaimsMoreTrianglesThanTheFileHolds) {
  auto tris = corners(small_lung());
  write_binary_stl(dir_.file("claims.stl"), tris, static_cast<std::uint32_t>(tris.size() + 1000));
  refusal(dir_.file("claims.stl"));
}

TEST_F(BadMesh, NanCoordinates) {
  auto tris = corners(small_lung());
  tris[10][4] = std::numeric_limits<float>::quiet_NaN();
  write_binary_stl(dir_.file("nan.stl"), tris, static_cast<std::uint32_t>(tris.size()));
  EXPECT_NE(refusal(dir_.file("nan.stl")).find("not finite"), std::string::npos);
}

TEST_F(BadMesh, TwoTriangles) {
  write_binary_stl(dir_.file("two.stl"), {{0, 0, 0, 10, 0, 0, 0, 10, 0}, {10, 0, 0, 10, 10, 0, 0, 10, 0}}, 2);
  EXPECT_NE(refusal(dir_.file("two.stl")).find("open"), std::string::npos);
}

TEST_F(BadMesh, OpenSurface) {
  auto tris = corners(small_lung());
  tris.resize(tris.size() - 7);
  write_binary_stl(dir_.file("open.stl"), tris, static_cast<std::uint32_t>(tris.size()));
  EXPECT_NE(refusal(dir_.file("open.stl")).find("open"), std::string::npos);
}

TEST_F(BadMesh, NotAMesh) {
  std::ofstream(dir_.file("text.obj")) << "this is not a mesh\n";
  refusal(dir_.file("text.obj"));
}

TEST(MeshImport, BinaryStlInCentimetresWithBothLungsInOneFile) {
  TempDir dir;
  const auto lungs = procedural_lungs(1600, 5);
  auto tris = corners(lungs[1].mesh, Eigen::Vector3d::Zero());
  const auto right = corners(lungs[0].mesh);
  tris.insert(tris.end(), right.begin(), right.end());
  for (auto& t : tris)
    for (float& v : t) v /= 10;  // the file is in cm
  write_binary_stl(dir.file("pair.stl"), tris, static_cast<std::uint32_t>(tris.size()));
  std::vector<std::string> notes;
  const auto imported = import_lungs({dir.file("pair.stl")}, units_to_mm("cm"), notes);
  ASSERT_TRUE(imported) << imported.error();
  ASSERT_EQ(imported->size(), 2u);
  EXPECT_EQ((*imported)[0].name, "right");
  EXPECT_EQ((*imported)[1].name, "left");
  EXPECT_EQ((*imported)[0].mesh.positions.size(), lungs[0].mesh.positions.size()) << "equal corners welded";
  EXPECT_NEAR(enclosed_volume((*imported)[0].mesh), enclosed_volume(lungs[0].mesh), 1e-3 * enclosed_volume(lungs[0].mesh));
}

TEST(MeshImport, AsciiStlObjAndPlyOneLungPerFileBake) {
  TempDir dir;
  const auto lungs = procedural_lungs(1600, 5);
  {  // right lung as ASCII STL, with its triangles reversed (inward): the import turns them outward
    std::ofstream out(dir.file("right.stl"));
    out << "solid right\n";
    for (const auto& c : corners(lungs[0].mesh)) {
      out << " facet normal 0 0 0\n  outer loop\n";
      for (int k : {0, 2, 1}) out << "   vertex " << c[3 * k] << ' ' << c[3 * k + 1] << ' ' << c[3 * k + 2] << '\n';
      out << "  endloop\n endfacet\n";
    }
    out << "endsolid right\n";
  }
  {
    std::ofstream out(dir.file("left.obj"));
    for (const auto& p : lungs[1].mesh.positions) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const auto& t : lungs[1].mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  {
    std::ofstream out(dir.file("left.ply"));
    out << "ply\nformat ascii 1.0\nelement vertex " << lungs[1].mesh.positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << lungs[1].mesh.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& p : lungs[1].mesh.positions) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const auto& t : lungs[1].mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  for (const char* left : {"left.obj", "left.ply"}) {
    std::vector<std::string> notes;
    BakeCommand c = command({dir.file("right.stl"), dir.file(left)}, dir.file("pair.lungbake"));
    c.report_json = dir.file("report.json");
    const Result<BakeReport> r = run_bake_command(c, nullptr, notes);
    ASSERT_TRUE(r) << r.error();
    EXPECT_EQ(r->lungs, 2u);
    EXPECT_LT(r->eq7_rms_rel_error, 0.03);
    bool flipped = false;
    for (const auto& n : notes) flipped |= n.find("flipped") != std::string::npos;
    EXPECT_TRUE(flipped) << "the inward ASCII STL was said to be turned outward";
    const Result<BakedAsset> a = load_asset(dir.file("pair.lungbake"));
    ASSERT_TRUE(a) << a.error();
    EXPECT_EQ(a->lungs[0].name, "right");
    EXPECT_TRUE(std::filesystem::exists(dir.file("report.json")));
  }
}

TEST(MeshImport, RealRightLungBakesUnderOnePercentWithoutFolds) {
  const std::string path = std::string(LUNGAR_SHARED_DIR) + "/data/lungs/copdgene10002K_right_lung.stl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no real lung data at " << path << " (../shared is absent)";
  std::vector<std::string> notes;
  const auto lungs = import_lungs({path}, 1.0, notes);
  ASSERT_TRUE(lungs) << lungs.error();
  ASSERT_EQ(lungs->size(), 1u);
  EXPECT_EQ((*lungs)[0].name, "right");
  EXPECT_EQ((*lungs)[0].mesh.positions.size(), 65754u) << "the README's vertex count after welding";
  EXPECT_NEAR(enclosed_volume((*lungs)[0].mesh) / 1000, 2428.2, 0.5) << "the README's volume";
  const TriMesh& m = (*lungs)[0].mesh;
  const auto radial = map_to_sphere(m, volume_centroid(m), {SphereMap::radial});
  ASSERT_TRUE(radial);
  EXPECT_EQ(radial->folded, 7844u) << "the hilar surface is not star-shaped (docs/bake-measurements.md)";
  BakeOptions options;
  options.threads = 2;
  options.transfer_rows = false;  // the rows are covered on the procedural pair; keep this test quick
  const Result<BakeOutput> baked = bake_lungs(*lungs, options, nullptr);
  ASSERT_TRUE(baked) << baked.error();
  const BakeReport& r = baked->report;
  EXPECT_LE(r.eq7_rms_rel_error, 0.01) << "why the default is 36 coefficients (sim/bake/bake.h)";
  EXPECT_EQ(r.folded_triangles, 0u) << "the conformal map is one-to-one";
  ASSERT_EQ(r.maps.size(), 2u);
  EXPECT_EQ(r.maps[1].map, SphereMap::radial);
  EXPECT_EQ(r.maps[1].folded_triangles, 7844u);
  for (const BandsSweepEntry& e : r.bands_sweep)
    if (e.bands >= 4) {
      EXPECT_LT(e.by_map[0].eq7_rms_rel_error, e.by_map[1].eq7_rms_rel_error) << e.coefficients;
    }
  EXPECT_NEAR(r.alpha, 1.0, 0.03);
  EXPECT_LT(r.linear_basis_rms_rel_error, 1e-6);
  EXPECT_GE(r.base_apex_displacement_ratio, 2.0);
  EXPECT_GT(r.posterior_anterior_displacement_ratio, 1.0);
  EXPECT_LT(std::abs(r.tidal_volume_rel_error), 0.02);
}

// A mesh in mm baked with --units m became a 2.4e12 mL lung without a word: a lung outside 30-8000 mL is refused
// in one line naming the file, the volume, what was expected and --any-volume, which bakes it anyway.
TEST(MeshImport, ALungVolumeNoHumanLungHasIsRefusedUnlessAnyVolume) {
  TempDir dir;
  const auto lung = corners(small_lung());
  write_binary_stl(dir.file("lung.stl"), lung, static_cast<std::uint32_t>(lung.size()));
  BakeCommand c = import_command(dir.file("lung.stl"), dir.file("out.lungbake"), 0);
  std::vector<std::string> notes;
  ASSERT_TRUE(run_bake_command(c, nullptr, notes)) << "in mm, as written: a lung's volume";
  std::filesystem::remove(dir.file("out.lungbake"));
  for (const char* units : {"m", "cm"}) {
    c.units = units;
    const Result<BakeReport> r = run_bake_command(c, nullptr, notes);
    test::expect_refused_cleanly(r, dir, "out.lungbake");
    if (r) continue;
    const std::string& e = r.error();
    EXPECT_EQ(e.rfind(dir.file("lung.stl") + ": lung '", 0), 0u) << e;
    EXPECT_NE(e.find(" mL; expected 30 to 8000 mL a lung"), std::string::npos) << e;
    EXPECT_NE(e.find(std::string("check --units (the mesh was read in ") + units + ")"), std::string::npos) << e;
    EXPECT_NE(e.find("--any-volume"), std::string::npos) << e;
  }
  c.units = "cm";
  c.any_volume = true;
  const Result<BakeReport> anyway = run_bake_command(c, nullptr, notes);
  ASSERT_TRUE(anyway) << anyway.error();
  EXPECT_GT(anyway->per_lung[0].volume_ml, 8000.0);
}

TEST(MeshImport, NodesSimplifiesALargerSurfaceAndMeasuresHowFarItMoved) {
  TempDir dir;
  const auto lung = corners(procedural_lungs(12000, 5)[0].mesh);
  write_binary_stl(dir.file("lung.stl"), lung, static_cast<std::uint32_t>(lung.size()));
  BakeCommand c = import_command(dir.file("lung.stl"), dir.file("out.lungbake"), 2000);
  std::vector<std::string> notes;
  const Result<BakeReport> r = run_bake_command(c, nullptr, notes);
  ASSERT_TRUE(r) << r.error();
  EXPECT_NEAR(r->nodes, 2000, 100) << "N +- 5 %";
  const LungSource& s = r->per_lung[0].source;
  EXPECT_TRUE(s.simplified);
  EXPECT_GT(s.input_vertices, 5000u);
  EXPECT_GT(s.hausdorff_mm, 0.01);
  EXPECT_LT(s.hausdorff_mm, 3.0) << "a 2000-vertex lung stays within a few mm of the 6000-vertex one";
  EXPECT_EQ(r->folded_triangles, 0u) << "still closed, manifold and genus 0: the conformal map takes it";

  c.nodes = 50000;  // more than the surface has: kept as it is, and said
  notes.clear();
  const Result<BakeReport> kept = run_bake_command(c, nullptr, notes);
  ASSERT_TRUE(kept) << kept.error();
  EXPECT_EQ(kept->nodes, s.input_vertices);
  EXPECT_FALSE(kept->per_lung[0].source.simplified);
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes.back().find("kept all"), std::string::npos) << notes.back();
}

TEST(MeshImport, ASurfaceWithAHandleIsRebuiltFromItsVoxelsForTheConformalMap) {
  TempDir dir;
  TriMesh ring = test::torus(48, 24);
  for (Eigen::Vector3d& p : ring.positions) p = 20.0 * p + Eigen::Vector3d(-70, 0, 0);  // a 40 mm ring at -x
  write_binary_stl(dir.file("ring.stl"), corners(ring), static_cast<std::uint32_t>(ring.triangles.size()));
  BakeCommand c = import_command(dir.file("ring.stl"), dir.file("out.lungbake"), 3000);
  std::vector<std::string> notes;
  const Result<BakeReport> r = run_bake_command(c, nullptr, notes);
  ASSERT_TRUE(r) << r.error();
  const LungSource& s = r->per_lung[0].source;
  EXPECT_TRUE(s.rebuilt_from_voxels);
  EXPECT_EQ(s.handles, 1);
  EXPECT_GT(s.filled_voxels, 0) << "the hole is closed by a membrane";
  EXPECT_GT(s.hausdorff_mm, 5.0) << "the membrane's middle lies far from the ring";
  EXPECT_EQ(r->folded_triangles, 0u);
  EXPECT_NEAR(r->nodes, 3000, 150);
  bool said = false;
  for (const std::string& n : notes) said = said || n.find("had 1 handle (") != std::string::npos;
  EXPECT_TRUE(said) << "the rebuild is said in the notes";

  c.options.sphere.map = SphereMap::radial;  // the radial map takes a surface with handles as it is
  notes.clear();
  const Result<BakeReport> radial = run_bake_command(c, nullptr, notes);
  ASSERT_TRUE(radial) << radial.error();
  EXPECT_FALSE(radial->per_lung[0].source.rebuilt_from_voxels);
  EXPECT_GT(radial->folded_triangles, 0u);
}

}  // namespace
}  // namespace lungar::sim
