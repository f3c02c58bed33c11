/// @file label_map_test.cpp
/// @brief lungar-bake's label-map input: the same map as NRRD (LPS) and as a NIfTI stored in RAS order gives the
///        same lungs (volume within 1 %, centroid within 2 mm), on a synthetic pair with a tunnel and on a
///        subsampled copy of the shared CT map; the right lung lands at -x; tunnels are closed (voxels reported);
///        bad maps (missing label, empty mask, wrong dimension, corrupt gzip, bad --label) are one clear line
///        and leave no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "label_map_files_support.h"
#include "sim/asset/asset_io.h"
#include "sim/bake_tool/bake_command.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

using test::LabelVolume;
using test::TempDir;

const Eigen::Vector3d kRightCentre(-35, -100, -210), kLeftCentre(35, -100, -210);
const Eigen::Vector3d kRightHalf(28, 40, 70), kLeftHalf(24, 38, 65);
constexpr double kTunnelMm = 6;  ///< radius of the tunnel bored through the left lung along y, at z = -200

bool in_left(const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = p - kLeftCentre;
  const bool tunnel = std::hypot(q.x(), q.z() - 10) < kTunnelMm;
  return q.cwiseQuotient(kLeftHalf).squaredNorm() < 1 && !tunnel;
}

/// Two lungs in LPS on a 1.5 x 1.5 x 2 mm grid: the right (label 2) at -x, the left (label 3) at +x, with a tunnel.
LabelVolume synthetic_pair() {
  LabelVolume v;
  v.size = {100, 70, 90};
  v.spacing = {1.5, 1.5, 2.0};
  v.origin = {-74.25, -152, -300};
  v.labels.resize(static_cast<std::size_t>(v.size[0]) * v.size[1] * v.size[2]);
  std::size_t n = 0;
  for (int k = 0; k < v.size[2]; ++k)
    for (int j = 0; j < v.size[1]; ++j)
      for (int i = 0; i < v.size[0]; ++i, ++n) {
        const Eigen::Vector3d p(v.origin[0] + 1.5 * i, v.origin[1] + 1.5 * j, v.origin[2] + 2.0 * k);
        if ((p - kRightCentre).cwiseQuotient(kRightHalf).squaredNorm() < 1) v.labels[n] = 2;
        if (in_left(p)) v.labels[n] = 3;
      }
  return v;
}

BakeCommand label_command(const std::string& map, const std::string& out, std::uint32_t nodes) {
  BakeCommand c;
  c.labelmap = map;
  c.labels = {"right=2", "left=3"};
  c.nodes = nodes;
  c.out = out;
  c.options.threads = 2;
  c.options.bands = 4;
  c.options.evaluate = false;  // volumes, centroids and folds are reported without the accuracy figures
  c.options.transfer_rows = false;
  return c;
}

const LungReport& lung_named(const BakeReport& r, const std::string& name) {
  for (const LungReport& l : r.per_lung)
    if (l.name == name) return l;
  throw std::runtime_error("no lung " + name);
}

/// Bakes the map written as NRRD and as NIfTI in RAS order and compares the lungs.
void expect_same_lungs_from_both_formats(const LabelVolume& v, std::uint32_t nodes) {
  TempDir dir;
  ASSERT_TRUE(test::write_label_volume(dir.file("map.nrrd"), v));
  ASSERT_TRUE(test::write_label_volume(dir.file("map.nii.gz"), test::stored_in_ras_order(v)));
  std::vector<std::string> notes;
  const auto a = run_bake_command(label_command(dir.file("map.nrrd"), dir.file("a.lungbake"), nodes), nullptr, notes);
  const auto b = run_bake_command(label_command(dir.file("map.nii.gz"), dir.file("b.lungbake"), nodes), nullptr, notes);
  ASSERT_TRUE(a) << a.error();
  ASSERT_TRUE(b) << b.error();
  for (const char* name : {"right", "left"}) {
    const LungReport& la = lung_named(*a, name);
    const LungReport& lb = lung_named(*b, name);
    EXPECT_NEAR(lb.volume_ml / la.volume_ml, 1.0, 0.01) << name;
    EXPECT_LT((lb.centroid_mm - la.centroid_mm).norm(), 2.0) << name << ": " << la.centroid_mm.transpose() << " vs "
                                                               << lb.centroid_mm.transpose();
    EXPECT_EQ(la.folded_triangles, 0u) << name;
    EXPECT_EQ(lb.folded_triangles, 0u) << name;
  }
  EXPECT_LT(lung_named(*a, "right").centroid_mm.x(), 0) << "LPS: the right lung at -x";
  EXPECT_GT(lung_named(*b, "left").centroid_mm.x(), 0);
  EXPECT_NEAR(a->nodes, nodes, 0.05 * nodes);
}

TEST(LabelMap, NrrdAndRasNiftiGiveTheSameSyntheticLungs) {
  expect_same_lungs_from_both_formats(synthetic_pair(), 6000);
}

TEST(LabelMap, SyntheticLungsComeOutAtTheirPlaceAndSizeWithTheTunnelClosed) {
  TempDir dir;
  ASSERT_TRUE(test::write_label_volume(dir.file("map.nrrd"), synthetic_pair()));
  std::vector<std::string> notes;
  const auto r = run_bake_command(label_command(dir.file("map.nrrd"), dir.file("a.lungbake"), 6000), nullptr, notes);
  ASSERT_TRUE(r) << r.error();
  const LungReport& right = lung_named(*r, "right");
  const LungReport& left = lung_named(*r, "left");
  EXPECT_NEAR(right.volume_ml, 4.0 / 3.0 * std::numbers::pi * kRightHalf.prod() / 1000, 0.03 * right.volume_ml);
  EXPECT_LT((right.centroid_mm - kRightCentre).norm(), 1.5);
  EXPECT_LT((left.centroid_mm - kLeftCentre).norm(), 3.0);
  EXPECT_TRUE(right.source.from_label_map);
  EXPECT_EQ(right.source.label, 2);
  EXPECT_EQ(right.source.filled_voxels, 0) << "no hole in the right lung";
  EXPECT_GT(left.source.filled_voxels, 0) << "the tunnel through the left lung is closed";
  const double bore_ml = std::numbers::pi * kTunnelMm * kTunnelMm * 2 * 37.5 / 1000;  // 75 mm through the lung
  EXPECT_GT(left.source.filled_ml, 0.2 * bore_ml);
  EXPECT_LT(left.source.filled_ml, 1.1 * bore_ml) << "the tunnel is filled, nothing beyond it";
  EXPECT_EQ(r->folded_triangles, 0u) << "genus 0 after the closing: the conformal map takes it";
  EXPECT_TRUE(load_asset(dir.file("a.lungbake")));
}

TEST(LabelMap, NrrdAndRasNiftiGiveTheSameRealLungs) {
  // The demo's shipped copy (sim/data/lungs/), so that this runs wherever the source is, CI's clean clone included.
  const std::string path = std::string(LUNGAR_SOURCE_DIR) + "/sim/data/lungs/10002K_INSP_STD_BWH_COPD_leftLungRightLung.nrrd";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  LabelVolume v;
  ASSERT_TRUE(test::read_subsampled(path, 3, v));  // 171 x 171 x 210 voxels of about 1.5 mm: a quick test
  expect_same_lungs_from_both_formats(v, 8000);
}

/// The synthetic pair with a 9 mm tumour (label 7) cut out of the right lung against its lateral surface, which it
/// just breaks through (into the chest wall), as a segmentation gives it; and a small blob (label 9) outside both
/// lungs.
const Eigen::Vector3d kTumourCentre = kRightCentre + Eigen::Vector3d(-19, 0, -20);
constexpr double kTumourRadius = 9;
LabelVolume pair_with_a_tumour() {
  LabelVolume v = synthetic_pair();
  std::size_t n = 0;
  for (int k = 0; k < v.size[2]; ++k)
    for (int j = 0; j < v.size[1]; ++j)
      for (int i = 0; i < v.size[0]; ++i, ++n) {
        const Eigen::Vector3d p(v.origin[0] + 1.5 * i, v.origin[1] + 1.5 * j, v.origin[2] + 2.0 * k);
        if ((p - kTumourCentre).norm() < kTumourRadius) v.labels[n] = 7;
        if ((p - Eigen::Vector3d(0, -60, -140)).norm() < 4) v.labels[n] = 9;
      }
  return v;
}

TEST(LabelMap, ASegmentedTumourIsBakedAsTheBallOfItsVolumeInsideItsLungWithNoNotch) {
  TempDir dir;
  ASSERT_TRUE(test::write_label_volume(dir.file("map.nrrd"), pair_with_a_tumour()));
  BakeCommand c = label_command(dir.file("map.nrrd"), dir.file("a.lungbake"), 6000);
  c.lesions = {"tumour=7", "dot=-35,-100,-170,4"};
  std::vector<std::string> notes;
  const auto r = run_bake_command(c, nullptr, notes);
  ASSERT_TRUE(r) << r.error();
  const Result<BakedAsset> a = load_asset(dir.file("a.lungbake"));
  ASSERT_TRUE(a) << a.error();
  ASSERT_EQ(a->lesions.size(), 2u);
  const BakedLesion& tumour = a->lesions[0];
  EXPECT_EQ(tumour.name, "tumour");
  EXPECT_EQ(a->lungs[tumour.lung].name, "right");
  EXPECT_TRUE(tumour.from_label);
  EXPECT_LT((Eigen::Vector3d(tumour.centre_mm[0], tumour.centre_mm[1], tumour.centre_mm[2]) - kTumourCentre).norm(),
            1.0);
  EXPECT_NEAR(tumour.radius_mm, kTumourRadius, 0.05 * kTumourRadius) << "the ball of its voxels' volume";
  EXPECT_EQ(a->lesions[1].name, "dot");
  EXPECT_FALSE(a->lesions[1].from_label);
  // The tumour's voxels count in the right lung: its surface goes round them, no notch where the label cut it out
  // (the tumour's centre would lie in it, outside the lung).
  const LungReport& right = lung_named(*r, "right");
  EXPECT_NEAR(right.volume_ml, 4.0 / 3.0 * std::numbers::pi * kRightHalf.prod() / 1000, 0.03 * right.volume_ml);
  bool said = false;
  for (const std::string& note : notes) said = said || note.find("lesion tumour: right lung") != std::string::npos;
  EXPECT_TRUE(said) << "the bake says where the lesion went";
}

class BadLabelMap : public ::testing::Test {
 protected:
  /// Bakes `map` (with --label values `labels`) and checks the refusal: one line, no asset, no partial file.
  std::string refusal(const std::string& map, std::vector<std::string> labels = {"right=2", "left=3"}) {
    BakeCommand c = label_command(map, dir_.file("out.lungbake"), 3000);
    c.labels = std::move(labels);
    std::vector<std::string> notes;
    const auto r = run_bake_command(c, nullptr, notes);
    test::expect_refused_cleanly(r, dir_, "out.lungbake");
    return r ? std::string() : r.error();
  }
  TempDir dir_;
};

TEST_F(BadLabelMap, MissingLabel) {
  ASSERT_TRUE(test::write_label_volume(dir_.file("m.nrrd"), synthetic_pair()));
  const std::string e = refusal(dir_.file("m.nrrd"), {"right=2", "left=7"});
  EXPECT_NE(e.find("m.nrrd: --label left=7: no voxel has this value (the map holds 0, 2, 3)"), std::string::npos) << e;
}

TEST_F(BadLabelMap, EmptyMask) {
  LabelVolume v = synthetic_pair();
  std::fill(v.labels.begin(), v.labels.end(), 0);
  ASSERT_TRUE(test::write_label_volume(dir_.file("empty.nii"), v));
  const std::string e = refusal(dir_.file("empty.nii"));
  EXPECT_NE(e.find("--label right=2: no voxel has this value (the map holds 0)"), std::string::npos) << e;
}

TEST_F(BadLabelMap, WrongDimension) {
  ASSERT_TRUE(test::write_2d_image(dir_.file("flat.nrrd")));
  const std::string e = refusal(dir_.file("flat.nrrd"));
  EXPECT_NE(e.find("flat.nrrd: dimension: expected a 3-D label map, got 2-D"), std::string::npos) << e;
}

TEST_F(BadLabelMap, CorruptGzip) {
  ASSERT_TRUE(test::write_label_volume(dir_.file("c.nrrd"), synthetic_pair()));
  std::fstream f(dir_.file("c.nrrd"), std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(0, std::ios::end);
  const auto size = static_cast<std::streamoff>(f.tellg());
  for (std::streamoff at = size / 2; at < size / 2 + 64; ++at) {  // scribble over the middle of the deflate stream
    f.seekp(at);
    f.put(static_cast<char>(0xA5 ^ at));
  }
  f.close();
  const std::string e = refusal(dir_.file("c.nrrd"));
  EXPECT_NE(e.find("c.nrrd: voxels: the compressed data is damaged (zlib: "), std::string::npos) << e;
  // A .nii.gz cut short: the gzip stream ends before its trailer.
  ASSERT_TRUE(test::write_label_volume(dir_.file("t.nii.gz"), synthetic_pair()));
  std::filesystem::resize_file(dir_.file("t.nii.gz"), std::filesystem::file_size(dir_.file("t.nii.gz")) / 2);
  const std::string t = refusal(dir_.file("t.nii.gz"));
  EXPECT_NE(t.find("t.nii.gz: "), std::string::npos) << t;
}

TEST_F(BadLabelMap, NotALabelMapAndBadLabelOptions) {
  std::ofstream(dir_.file("notes.txt")) << "not an image";
  EXPECT_NE(refusal(dir_.file("notes.txt")).find("notes.txt: cannot read: expected a label map in NRRD"), std::string::npos);
  EXPECT_NE(refusal(dir_.file("none.nrrd")).find("none.nrrd: cannot open: no such file"), std::string::npos);
  ASSERT_TRUE(test::write_label_volume(dir_.file("m.nrrd"), synthetic_pair()));
  EXPECT_NE(refusal(dir_.file("m.nrrd"), {"right"}).find("--label: expected NAME=VALUE"), std::string::npos);
  EXPECT_NE(refusal(dir_.file("m.nrrd"), {"right=two"}).find("got 'right=two'"), std::string::npos);
  EXPECT_NE(refusal(dir_.file("m.nrrd"), {"right=2", "right=3"}).find("given twice"), std::string::npos);
  EXPECT_NE(refusal(dir_.file("m.nrrd"), {}).find("--label: expected at least one"), std::string::npos);
}

TEST_F(BadLabelMap, ALesionLabelThatIsMissingOutsideTheLungsOrWithoutAMapIsOneLine) {
  ASSERT_TRUE(test::write_label_volume(dir_.file("t.nrrd"), pair_with_a_tumour()));
  auto refused = [&](const std::string& lesion, bool procedural = false) {
    BakeCommand c = label_command(dir_.file("t.nrrd"), dir_.file("out.lungbake"), 3000);
    if (procedural) c.labelmap.clear(), c.labels.clear(), c.procedural = true, c.nodes = 2000;
    c.lesions = {lesion};
    std::vector<std::string> notes;
    const auto r = run_bake_command(c, nullptr, notes);
    test::expect_refused_cleanly(r, dir_, "out.lungbake");
    return r ? std::string() : r.error();
  };
  EXPECT_NE(refused("stray=8").find("t.nrrd: --lesion stray=8: no voxel has this value (the map holds 0, 2, 3, 7, 9)"),
            std::string::npos);
  EXPECT_NE(
      refused("blob=9").find("t.nrrd: --lesion blob=9: no lung's voxels touch it; expected a lesion inside a lung"),
      std::string::npos);
  EXPECT_NE(refused("tumour=7", true).find("--lesion tumour=7: a label needs --labelmap"), std::string::npos);
  EXPECT_NE(
      refused("far=0,0,500,5").find("--lesion far: its centre (0.0, 0.0, 500.0) (LPS, mm) lies outside every lung"),
      std::string::npos);
}

}  // namespace
}  // namespace lungar::sim
