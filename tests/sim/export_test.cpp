/// @file export_test.cpp
/// @brief `lungar-bake export`'s work: the PLY read back field by field (rest + displacement = position, the
///        triangles, the volume change), postures and --gravity, a breath as a series, the interior points
///        (--interior) and their figures against the bake report's, lesions (--lesion) and how far they move, and
///        refusals that leave no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include "sim/asset/asset_io.h"
#include "sim/bake_tool/export_command.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion.h"
#include "sim/motion/motion_figures.h"
#include "sim_test_support.h"
#include "tests/file_text.h"
#include "tests/partial_files.h"

namespace lungar::sim {
namespace {

using test::sliding_asset;
using test::sliding_bake;
using test::TempDir;

struct Ply {
  std::vector<std::string> properties;
  std::vector<float> xyz, dxyz;
  std::vector<std::uint32_t> triangles;  ///< 3 vertex indices a triangle
};

/// A reader written from the PLY format's definition, independent of the writer.
Ply read_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  Ply p;
  std::string line;
  std::size_t vertices = 0, faces = 0;
  EXPECT_TRUE(std::getline(in, line) && line == "ply");
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream words(line);
    std::string w, kind, name;
    words >> w;
    if (w == "format") {
      EXPECT_EQ(line, "format binary_little_endian 1.0");
    }
    if (w == "element") {
      words >> kind;
      (kind == "vertex" ? words >> vertices : words >> faces);
    }
    if (w == "property" && line.find("list") == std::string::npos) {
      words >> kind >> name;
      p.properties.push_back(name);
    }
  }
  EXPECT_EQ(p.properties.size(), 6u);
  std::vector<float> record(p.properties.size());
  for (std::size_t i = 0; i < vertices; ++i) {
    in.read(reinterpret_cast<char*>(record.data()), static_cast<std::streamsize>(record.size() * 4));
    p.xyz.insert(p.xyz.end(), record.begin(), record.begin() + 3);
    p.dxyz.insert(p.dxyz.end(), record.begin() + 3, record.begin() + 6);
  }
  for (std::size_t t = 0; t < faces; ++t) {
    unsigned char count = 0;
    std::int32_t v[3];
    in.read(reinterpret_cast<char*>(&count), 1);
    EXPECT_EQ(count, 3);
    in.read(reinterpret_cast<char*>(v), 12);
    for (std::int32_t index : v) p.triangles.push_back(static_cast<std::uint32_t>(index));
  }
  EXPECT_TRUE(in.good()) << path << " is shorter than its header says";
  EXPECT_EQ(in.peek(), std::char_traits<char>::eof()) << path << " has bytes after its faces";
  return p;
}

class Export : public ::testing::Test {
 protected:
  void SetUp() override {
    asset_ = dir_.file("lungs.lungbake");
    ASSERT_TRUE(write_asset(sliding_asset(), asset_));
  }
  TempDir dir_;
  std::string asset_;
};

TEST_F(Export, WritesTheDisplacedSurfaceWhoseVolumeChangeIsTheOneAskedFor) {
  const BakedAsset& a = sliding_asset();
  ExportCommand c;
  c.asset = asset_;
  c.posture = "supine";
  c.volume_ml = 500;
  c.out = dir_.file("supine.ply");
  auto written = run_export_command(c);
  ASSERT_TRUE(written) << written.error();
  ASSERT_EQ(written->size(), 1u);
  const Ply p = read_ply(c.out);
  EXPECT_EQ((std::vector<std::string>{"x", "y", "z", "dx", "dy", "dz"}), p.properties);
  ASSERT_EQ(p.xyz.size(), a.positions.size());
  ASSERT_EQ(p.triangles, a.triangles);
  double moved = 0;
  for (std::size_t i = 0; i < p.xyz.size(); ++i) {
    EXPECT_NEAR(p.xyz[i] - p.dxyz[i], a.positions[i], 1e-3) << "x - dx is the rest position";
    moved = std::max<double>(moved, std::abs(p.dxyz[i]));
  }
  EXPECT_GT(moved, 1.0);
  const double rest = enclosed_volume(a.triangles, a.positions.data());
  EXPECT_NEAR((enclosed_volume(p.triangles, p.xyz.data()) - rest) / 1000.0, 500.0, 0.5);

  c.volume_ml = -300;  // below the rest shape
  c.out = dir_.file("below.ply");
  ASSERT_TRUE(run_export_command(c));
  const Ply below = read_ply(c.out);
  EXPECT_NEAR((enclosed_volume(below.triangles, below.xyz.data()) - rest) / 1000.0, -300.0, 0.5)
      << "the enclosed volume, not only its first-order part";
}

TEST_F(Export, PosturesAndGravityMoveTheLungsDifferently) {
  ExportCommand c;
  c.asset = asset_;
  c.out = dir_.file("supine.ply");
  ASSERT_TRUE(run_export_command(c));
  c.posture = "left-lateral";
  c.out = dir_.file("left.ply");
  ASSERT_TRUE(run_export_command(c));
  c.gravity = Eigen::Vector3d(0, 1, 0);  // the supine gravity, given directly
  c.out = dir_.file("gravity.ply");
  ASSERT_TRUE(run_export_command(c));
  const Ply supine = read_ply(dir_.file("supine.ply")), left = read_ply(dir_.file("left.ply")),
            gravity = read_ply(dir_.file("gravity.ply"));
  double differ = 0;
  for (std::size_t i = 0; i < supine.dxyz.size(); ++i) {
    differ = std::max<double>(differ, std::abs(supine.dxyz[i] - left.dxyz[i]));
    ASSERT_NEAR(supine.dxyz[i], gravity.dxyz[i], 1e-4) << "--gravity 0,1,0 is supine";
  }
  EXPECT_GT(differ, 0.1);
  EXPECT_TRUE(parse_gravity("0, 1 ,0")) << "spaces after commas are fine";
  EXPECT_FALSE(parse_gravity("0,0,0"));
  EXPECT_FALSE(parse_gravity("1,2"));
  EXPECT_FALSE(parse_gravity("1,2,nan"));
}

TEST_F(Export, ASeriesIsOneBreathFromRest) {
  ExportCommand c;
  c.asset = asset_;
  c.volume_ml = 500;
  c.series = 5;
  c.out = dir_.file("breath.ply");
  auto written = run_export_command(c);
  ASSERT_TRUE(written) << written.error();
  ASSERT_EQ(written->size(), 5u);
  EXPECT_EQ((*written)[2].path, dir_.file("breath_002.ply"));
  EXPECT_NEAR((*written)[0].volume_ml, 0.0, 1.0) << "a breath starts at the end of an expiration";
  double peak = 0;
  for (const ExportedFile& f : *written) {
    EXPECT_EQ(read_ply(f.path).xyz.size(), sliding_asset().positions.size());
    peak = std::max(peak, f.volume_ml);
  }
  EXPECT_GT(peak, 250.0);
  EXPECT_LE(peak, 500.5);
}

TEST_F(Export, RefusalsNameTheFieldAndLeaveNoFile) {
  ExportCommand c;
  c.asset = dir_.file("missing.lungbake");
  c.out = dir_.file("x.ply");
  auto r = run_export_command(c);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("missing.lungbake"), std::string::npos) << r.error();
  c.asset = asset_;
  c.posture = "sideways";
  r = run_export_command(c);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("--posture"), std::string::npos) << r.error();
  EXPECT_EQ(r.error(), "--posture: expected upright, supine, prone, left-lateral or right-lateral, got 'sideways'")
      << "the command line's spelling of the pose names (posture_names())";
  c.posture = "supine";
  c.out = dir_.file("no/such/dir/../../x.ply");
  std::ofstream(dir_.file("no"), std::ios::binary) << "a file where a folder should be";
  EXPECT_FALSE(run_export_command(c));
  EXPECT_FALSE(std::filesystem::exists(dir_.file("x.ply")));
  EXPECT_EQ(lungar::testing::partial_files_beside(dir_.file("x.ply")), std::vector<std::string>{});
}

TEST_F(Export, InteriorPointsAreVerticesInsideTheLungsWhoseFiguresAreTheReports) {
  const BakeOutput& bake = sliding_bake();
  ExportCommand c;
  c.asset = asset_;
  c.out = dir_.file("supine.ply");
  c.interior = static_cast<int>(kInteriorReportPoints);
  c.interior_out = dir_.file("inside.ply");
  auto written = run_export_command(c);
  ASSERT_TRUE(written) << written.error();
  ASSERT_EQ(written->size(), 1u);
  EXPECT_EQ((*written)[0].interior_path, c.interior_out);
  const Ply p = read_ply(c.interior_out);
  EXPECT_EQ((std::vector<std::string>{"x", "y", "z", "dx", "dy", "dz"}), p.properties);
  ASSERT_EQ(p.xyz.size(), 3 * kInteriorReportPoints);
  EXPECT_TRUE(p.triangles.empty());
  EXPECT_EQ(lungar::testing::file_text(c.interior_out).find("element face"), std::string::npos) << "vertices only";
  std::vector<float> rest(p.xyz.size());
  for (std::size_t i = 0; i < rest.size(); ++i) rest[i] = p.xyz[i] - p.dxyz[i];
  const InteriorDisplacement field(bake.asset);
  for (std::size_t k = 0; k < kInteriorReportPoints; k += 50)
    EXPECT_GE(field.lung_containing({rest[3 * k], rest[3 * k + 1], rest[3 * k + 2]}), 0) << "point " << k;
  // The export's volume is exact and the report's first-order: the same field times a factor near 1, so the
  // ratios agree and the mean within the report's tidal volume error.
  const MotionFigures f = point_motion_figures(rest, p.dxyz);
  const MotionFigures& r = bake.report.interior_supine;
  EXPECT_EQ(bake.report.interior_points, kInteriorReportPoints);
  EXPECT_NEAR(f.si_share, r.si_share, 1e-3);
  EXPECT_NEAR(f.apex_base_ratio, r.apex_base_ratio, 1e-3 * r.apex_base_ratio);
  EXPECT_NEAR(f.dorsal_ventral_ratio, r.dorsal_ventral_ratio, 1e-3 * r.dorsal_ventral_ratio);
  EXPECT_NEAR(f.mean_displacement_mm, r.mean_displacement_mm, 0.03 * r.mean_displacement_mm);
  EXPECT_NEAR((*written)[0].interior.si_share, f.si_share, 1e-4) << "what the tool logs is what it wrote";
  // Supine, the interior moves as the surface does: mostly cranio-caudally, the base and the back more.
  EXPECT_GT(r.si_share, 0.5);
  EXPECT_LT(r.apex_base_ratio, 1.0);
  EXPECT_GT(r.dorsal_ventral_ratio, 1.0);
  EXPECT_LT(r.mean_displacement_mm, bake.report.motion_supine.mean_displacement_mm * 1.5);
}

TEST_F(Export, InteriorRefusalsNameTheOptionAndLeaveNoFile) {
  ExportCommand c;
  c.asset = asset_;
  c.out = dir_.file("supine.ply");
  c.interior_out = dir_.file("inside.ply");
  auto refused = [&](const std::string& option, const std::string& expected) {
    auto r = run_export_command(c);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().rfind(option + ":", 0), 0u) << r.error();
    EXPECT_NE(r.error().find(expected), std::string::npos) << r.error();
    EXPECT_FALSE(std::filesystem::exists(c.out)) << r.error();
    EXPECT_FALSE(std::filesystem::exists(dir_.file("inside.ply"))) << r.error();
  };
  c.interior = 0;
  refused("--interior", "expected a positive number of points, got 0");
  c.interior = -5;
  refused("--interior", "got -5");
  EXPECT_FALSE(check_export_command(c)) << "the command line's own check, before the asset is read";
  c.interior = 100;
  c.interior_out.clear();
  refused("--interior", "--interior-out FILE");
  c.interior.reset();
  c.interior_out = dir_.file("inside.ply");
  refused("--interior-out", "--interior N");
  c.interior = 100;
  c.interior_out = c.out;
  refused("--interior-out", "other than --out");
  // A folder that cannot be made (a file in its place): nothing of the export is left.
  std::ofstream(dir_.file("no"), std::ios::binary) << "a file where a folder should be";
  c.interior_out = dir_.file("no/inside.ply");
  refused("--interior-out", "no/inside.ply");
  EXPECT_EQ(lungar::testing::partial_files_beside(c.out), std::vector<std::string>{});
  // The surface's file failing after the interior's was written takes the interior's away too.
  c.interior_out = dir_.file("inside.ply");
  c.out = dir_.file("no/supine.ply");
  EXPECT_FALSE(run_export_command(c));
  EXPECT_FALSE(std::filesystem::exists(c.interior_out));
  EXPECT_EQ(lungar::testing::partial_files_beside(c.interior_out), std::vector<std::string>{});
}

/// A point of `lung` at a fraction of its height (0 its bottom, 1 its top) with room for a lesion of `radius`
/// around it (place_lesions() accepts it): the interior sample nearest that height that has the room.
Eigen::Vector3d deep_point(const InteriorDisplacement& field, std::size_t lung, double height, double radius) {
  const InteriorPoints points = field.sample(4000, 7);
  double lo = 1e300, hi = -1e300;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (points.lung_of_point[k] != lung) continue;
    lo = std::min<double>(lo, points.positions[3 * k + 2]);
    hi = std::max<double>(hi, points.positions[3 * k + 2]);
  }
  const double z = lo + height * (hi - lo);
  std::vector<Eigen::Vector3d> candidates;  // this lung's samples, nearest the height first
  for (std::size_t k = 0; k < points.size(); ++k)
    if (points.lung_of_point[k] == lung)
      candidates.emplace_back(points.positions[3 * k], points.positions[3 * k + 1], points.positions[3 * k + 2]);
  std::sort(candidates.begin(), candidates.end(), [z](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::abs(a.z() - z) < std::abs(b.z() - z);
  });
  for (const Eigen::Vector3d& p : candidates) {
    if (std::abs(p.z() - z) > 0.08 * (hi - lo)) break;
    if (place_lesions(field, {{"probe", p, radius}})) return p;
  }
  ADD_FAILURE() << "no room for a " << radius << " mm lesion at " << height << " of the lung's height";
  return Eigen::Vector3d::Zero();
}

std::string lesion_spec(const std::string& name, const Eigen::Vector3d& c, double radius) {
  std::ostringstream text;
  text << name << '=' << c.x() << ',' << c.y() << ',' << c.z() << ',' << radius;
  return text.str();
}

// Lower-lobe tumours move cranio-caudally two to three times as far as upper-lobe ones (13.5-14.4 mm against
// 5.1-6.3 mm in one published series; 12 +- 2 mm for lower lobes in Seppenwoolde et al. 2002): the interior field
// carries that from the diaphragm's motion. A lesion's displacement is its centre's (lesion.h: the mean value
// property), in the lung the spec places it in.
TEST_F(Export, ALowerLesionMovesCranioCaudallyMoreThanTwiceAnUpperOne) {
  const BakedAsset& a = sliding_asset();
  const InteriorDisplacement field(a);
  std::size_t right = a.lungs.size();
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    if (a.lungs[l].name == "right") right = l;
  ASSERT_LT(right, a.lungs.size());
  ExportCommand c;
  c.asset = asset_;
  c.out = dir_.file("breath.ply");
  c.series = 6;
  c.lesions = {lesion_spec("lower", deep_point(field, right, 0.2, 2.0), 2.0),
               lesion_spec("upper", deep_point(field, right, 0.8, 2.0), 2.0)};
  c.lesions_out = dir_.file("lesions.csv");
  auto written = run_export_command(c);
  ASSERT_TRUE(written) << written.error();
  // The CSV: a header, then each lesion in each phase, displaced position = rest + displacement.
  std::istringstream csv(lungar::testing::file_text(c.lesions_out));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "phase,volume_ml,name,lung,x_mm,y_mm,z_mm,dx_mm,dy_mm,dz_mm");
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    const ExportedFile& f = (*written)[rows / 2];
    const LesionAt& l = f.lesions[rows % 2];
    std::ostringstream want;
    want.setf(std::ios::fixed);
    want.precision(4);
    want << f.phase << ',';
    want.precision(3);
    want << f.volume_ml << ',' << l.name << ',' << l.lung << ',';
    want.precision(4);
    want << l.centre_mm.x() + l.displacement_mm.x();
    EXPECT_EQ(line.rfind(want.str(), 0), 0u) << line << " | " << want.str();
    ++rows;
  }
  EXPECT_EQ(rows, 2u * 6u);
  ASSERT_EQ((*written)[0].lesions.size(), 2u);
  EXPECT_EQ((*written)[0].lesions[0].lung, "right");
  const std::vector<LesionExcursion> e = lesion_excursions(*written);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].name, "lower");
  EXPECT_GT(e[0].si_mm, 2.0 * e[1].si_mm) << "lower " << e[0].si_mm << " mm, upper " << e[1].si_mm << " mm";
  EXPECT_GT(e[0].si_mm, 0.5 * e[0].peak_to_peak_mm) << "mostly cranio-caudal";
  EXPECT_LE(e[0].si_mm, e[0].peak_to_peak_mm + 1e-9);
  // Over a breath from rest the largest excursion is the one at the tidal volume's peak: the same lesion exported
  // at that volume alone moves as far.
  double peak_ml = 0;
  for (const ExportedFile& f : *written) peak_ml = std::max(peak_ml, f.volume_ml);
  c.series = 0;
  c.volume_ml = peak_ml;
  auto once = run_export_command(c);
  ASSERT_TRUE(once) << once.error();
  EXPECT_NEAR(lesion_excursions(*once)[0].peak_to_peak_mm, e[0].peak_to_peak_mm, 1e-3 * e[0].peak_to_peak_mm);
}

TEST_F(Export, ALesionOutsideItsLungIsOneLineAndNoFile) {
  const BakedAsset& a = sliding_asset();
  const InteriorDisplacement field(a);
  const Eigen::Vector3d inside = deep_point(field, 0, 0.5, 1.0);
  ExportCommand c;
  c.asset = asset_;
  c.out = dir_.file("supine.ply");
  auto refused = [&](const std::string& spec, const std::string& expected) {
    c.lesions = {spec};
    auto r = run_export_command(c);
    ASSERT_FALSE(r) << spec;
    EXPECT_NE(r.error().find(expected), std::string::npos) << r.error();
    EXPECT_EQ(r.error().find('\n'), std::string::npos) << "one line";
    EXPECT_FALSE(std::filesystem::exists(c.out)) << r.error();
  };
  refused("far=5000,5000,5000,5",
          "--lesion far: its centre (5000.0, 5000.0, 5000.0) (LPS, mm) lies outside every lung");
  refused(lesion_spec("huge", inside, 49), "--lesion huge: a ball of radius 49.0 mm");
  refused(lesion_spec("huge", inside, 49), "expected the whole lesion inside one lung");
  refused("tumour=1,2,3", "--lesion: expected NAME=x,y,z,radius_mm");
  refused("=1,2,3,4", "--lesion: expected NAME=x,y,z,radius_mm");
  refused("a b=1,2,3,4", "got 'a b=1,2,3,4'");
  refused("t=1,2,3,0", "--lesion t: expected a radius above 0 and at most 50 mm, got 0 mm");
  refused("t=1,2,3,51", "got 51 mm");
  refused("t=1,2,nan,4", "--lesion: expected NAME=x,y,z,radius_mm");
  c.lesions = {lesion_spec("twice", inside, 1), lesion_spec("twice", inside, 1)};
  auto twice = run_export_command(c);
  ASSERT_FALSE(twice);
  EXPECT_NE(twice.error().find("--lesion twice: expected each name once"), std::string::npos) << twice.error();
  c.lesions.clear();
  c.lesions_out = dir_.file("lesions.csv");
  auto alone = run_export_command(c);
  ASSERT_FALSE(alone);
  EXPECT_EQ(alone.error(), "--lesions-out: expected --lesion NAME=x,y,z,radius_mm (the lesions to write) with it");
  EXPECT_FALSE(check_export_command(c)) << "the command line's own check";
  EXPECT_FALSE(std::filesystem::exists(c.out));
  c.lesions = {lesion_spec("ok", inside, 1)};
  c.lesions_out = c.out;
  auto same = run_export_command(c);
  ASSERT_FALSE(same);
  EXPECT_NE(same.error().find("--lesions-out: expected a file other than --out's"), std::string::npos);
  c.lesions_out.clear();
  EXPECT_TRUE(run_export_command(c)) << "the same point and a small radius are accepted";
}

}  // namespace
}  // namespace lungar::sim
