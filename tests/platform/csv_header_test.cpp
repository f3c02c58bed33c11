// The calibration CSVs share one header rule: the registration's model points and the display calibration's
// alignments each take an optional first line naming their columns, and refuse a wrong one in one line that names
// the file, the line and the header expected.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "platform/registration/display_calibration.h"
#include "platform/registration/fiducial_registration.h"
#include "tests/scratch_dir.h"

using lungar::platform::read_alignments_csv;
using lungar::platform::read_points_csv;

namespace {

const char kAlignments[] = "left,1,2,300,4,5\nright,6,7,800,9,10\nleft,11,12,500,14,15\n";
const char kPoints[] = "1, 2, 3\n4, 5, 6\n7,8,9\n";

std::string write(const lungar::testing::ScratchDir& root, const std::string& name, const std::string& text) {
  const std::string path = (root / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(CalibrationCsv, BothReadersTakeTheirHeaderOrNone) {
  const lungar::testing::ScratchDir root("lungar_csv_header");
  for (const std::string header : {"", "x_mm,y_mm,z_mm\n", "# model landmarks\n x_mm, y_mm, z_mm\r\n"}) {
    auto points = read_points_csv(write(root, "model.csv", header + kPoints));
    ASSERT_TRUE(points) << points.error();
    ASSERT_EQ(points->size(), 3u) << header;
    EXPECT_EQ(points->front(), Eigen::Vector3d(1, 2, 3)) << header;
  }
  for (const std::string header : {"", "eye,x_mm,y_mm,z_mm,u_px,v_px\n"}) {
    auto eyes = read_alignments_csv(write(root, "alignments.csv", header + kAlignments));
    ASSERT_TRUE(eyes) << eyes.error();
    EXPECT_EQ((*eyes)[0].size(), 2u) << header;
    EXPECT_EQ((*eyes)[1].size(), 1u) << header;
    EXPECT_EQ((*eyes)[1][0].pixel, Eigen::Vector2d(9, 10)) << header;
  }
}

TEST(CalibrationCsv, AWrongHeaderIsOneLineNamingTheFileTheLineAndTheExpectedHeader) {
  const lungar::testing::ScratchDir root("lungar_csv_header");
  std::string path = write(root, "model.csv", "# landmarks\nx,y,z\n1,2,3\n");
  EXPECT_EQ(read_points_csv(path).error(), path + ":2: header: expected 'x_mm,y_mm,z_mm', got 'x,y,z'");
  path = write(root, "model.csv", "x_mm,y_mm,z_mm,label\n1,2,3\n");
  EXPECT_EQ(read_points_csv(path).error(), path + ":1: header: expected 'x_mm,y_mm,z_mm', got 'x_mm,y_mm,z_mm,label'");
  path = write(root, "alignments.csv", std::string("eye,x,y,z,u,v\n") + kAlignments);
  EXPECT_EQ(read_alignments_csv(path).error(),
            path + ":1: header: expected 'eye,x_mm,y_mm,z_mm,u_px,v_px', got 'eye,x,y,z,u,v'");
  // A header is the first line only: a second one is data, and wrong as data.
  path = write(root, "model.csv", "x_mm,y_mm,z_mm\nx_mm,y_mm,z_mm\n");
  EXPECT_EQ(read_points_csv(path).error(),
            path + ":2: expected three finite numbers x, y, z (mm), got 'x_mm y_mm z_mm'");
  path = write(root, "alignments.csv", "eye,x_mm,y_mm,z_mm,u_px,v_px\n");
  EXPECT_EQ(read_alignments_csv(path).error(), path + ": expected alignments (eye,x_mm,y_mm,z_mm,u_px,v_px), got none");
}
