/// @file label_map_files_support.cpp
/// @brief ITK writes and reads the tests' label maps.
#include "label_map_files_support.h"

#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>

#include "sim/bake_tool/itk_label_reader.h"

namespace lungar::sim::test {
namespace {

using Image3 = itk::Image<std::uint16_t, 3>;
using itk_io::register_formats;  // the bake tool's: the same three formats

template <class Image>
bool write(const std::string& path, const typename Image::Pointer& image) {
  register_formats();
  auto writer = itk::ImageFileWriter<Image>::New();
  writer->SetFileName(path);
  writer->SetInput(image);
  writer->SetUseCompression(true);
  try {
    writer->Update();
  } catch (const itk::ExceptionObject&) {
    return false;
  }
  return true;
}

}  // namespace

bool write_label_volume(const std::string& path, const LabelVolume& v) {
  auto image = Image3::New();
  Image3::RegionType region;
  Image3::SpacingType spacing;
  Image3::PointType origin;
  Image3::DirectionType direction;
  for (unsigned a = 0; a < 3; ++a) {
    region.SetSize(a, static_cast<itk::SizeValueType>(v.size[a]));
    spacing[a] = v.spacing[a];
    origin[a] = v.origin[a];
    for (unsigned b = 0; b < 3; ++b) direction(a, b) = v.direction[3 * a + b];
  }
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  std::copy(v.labels.begin(), v.labels.end(), image->GetBufferPointer());
  return write<Image3>(path, image);
}

LabelVolume stored_in_ras_order(const LabelVolume& v) {
  LabelVolume r = v;
  const int n0 = v.size[0], n1 = v.size[1];
  for (int k = 0; k < v.size[2]; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i)
        r.labels[static_cast<std::size_t>(i + n0 * (j + n1 * k))] =
            v.labels[static_cast<std::size_t>((n0 - 1 - i) + n0 * ((n1 - 1 - j) + n1 * k))];
  // New voxel (0, 0, 0) is old voxel (n0 - 1, n1 - 1, 0); the i and j steps turn round.
  for (int b = 0; b < 3; ++b) {
    r.origin[b] = v.origin[b] + v.direction[3 * b + 0] * v.spacing[0] * (n0 - 1) +
                  v.direction[3 * b + 1] * v.spacing[1] * (n1 - 1);
    r.direction[3 * b + 0] = -v.direction[3 * b + 0];
    r.direction[3 * b + 1] = -v.direction[3 * b + 1];
  }
  return r;
}

bool read_subsampled(const std::string& path, int step, LabelVolume& out) {
  register_formats();
  auto reader = itk::ImageFileReader<Image3>::New();
  reader->SetFileName(path);
  try {
    reader->Update();
  } catch (const itk::ExceptionObject&) {
    return false;
  }
  const Image3::Pointer in = reader->GetOutput();
  const auto size = in->GetLargestPossibleRegion().GetSize();
  for (unsigned a = 0; a < 3; ++a) {
    out.size[a] = static_cast<int>((size[a] + static_cast<unsigned>(step) - 1) / static_cast<unsigned>(step));
    out.spacing[a] = in->GetSpacing()[a] * step;
    out.origin[a] = in->GetOrigin()[a];
    for (unsigned b = 0; b < 3; ++b) out.direction[3 * a + b] = in->GetDirection()(a, b);
  }
  out.labels.resize(static_cast<std::size_t>(out.size[0]) * out.size[1] * out.size[2]);
  const std::uint16_t* voxel = in->GetBufferPointer();
  std::size_t n = 0;
  for (int k = 0; k < out.size[2]; ++k)
    for (int j = 0; j < out.size[1]; ++j)
      for (int i = 0; i < out.size[0]; ++i)
        out.labels[n++] = voxel[static_cast<std::size_t>(i * step) +
                                size[0] * (static_cast<std::size_t>(j * step) + size[1] * static_cast<std::size_t>(k * step))];
  return true;
}

bool write_2d_image(const std::string& path) {
  using Image2 = itk::Image<std::uint16_t, 2>;
  auto image = Image2::New();
  Image2::RegionType region;
  region.SetSize(0, 8);
  region.SetSize(1, 8);
  image->SetRegions(region);
  image->Allocate();
  image->FillBuffer(2);
  return write<Image2>(path, image);
}

}  // namespace lungar::sim::test
