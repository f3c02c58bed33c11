/// @file itk_label_reader.cpp
/// @brief ITK reads the header and the voxels; the labels are cropped here in one pass over the voxels.
#include "sim/bake_tool/itk_label_reader.h"

#include <itkImageIOBase.h>
#include <itkImageIOFactory.h>
#include <itkMetaImageIOFactory.h>
#include <itkNiftiImageIOFactory.h>
#include <itkNrrdImageIOFactory.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>

namespace lungar::sim::itk_io {

void register_formats() {
  static std::once_flag once;
  std::call_once(once, [] {
    itk::NrrdImageIOFactory::RegisterOneFactory();
    itk::NiftiImageIOFactory::RegisterOneFactory();
    itk::MetaImageIOFactory::RegisterOneFactory();
  });
}

namespace {

/// ITK's exception text on one line, without its source location.
std::string itk_reason(const itk::ExceptionObject& e) {
  std::string why = e.GetDescription();
  std::replace(why.begin(), why.end(), '\n', ' ');
  while (!why.empty() && why.back() == ' ') why.pop_back();
  return why.empty() ? "unknown reason" : why;
}

struct Box {
  std::array<int, 3> lo{INT32_MAX, INT32_MAX, INT32_MAX}, hi{-1, -1, -1};
  std::int64_t count = 0;
};

/// The grid's placement: origin and the voxel steps (direction cosines times spacing), LPS mm.
lungar::Status place(const std::string& path, const itk::ImageIOBase& io, LabelImage& out) {
  for (unsigned a = 0; a < 3; ++a) {
    out.size[a] = static_cast<int>(io.GetDimensions(a));
    out.origin[a] = io.GetOrigin(a);
    const std::vector<double> cosines = io.GetDirection(a);  // axis a's direction, one entry per LPS row
    for (unsigned b = 0; b < 3; ++b) out.axes[3 * b + a] = (b < cosines.size() ? cosines[b] : 0.0) * io.GetSpacing(a);
  }
  const auto& m = out.axes;
  const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                     m[2] * (m[3] * m[7] - m[4] * m[6]);
  bool finite = std::isfinite(det);
  for (double o : out.origin) finite = finite && std::isfinite(o);
  if (!finite || !(std::abs(det) > 1e-9))
    return fail(path + ": space directions: expected a non-singular voxel frame (spacing and direction cosines)");
  return ok();
}

/// Reads the voxels as T straight through the file's ImageIO (no itk::Image: its reader's templates cost the build
/// more than the rest of the bake tool), finds each value's bounding box in one pass, then copies the boxes out.
template <class T>
lungar::Result<LabelImage> crop_labels(const std::string& path, itk::ImageIOBase& io,
                                       const std::vector<std::int64_t>& values) {
  LabelImage out;
  if (lungar::Status s = place(path, io, out); !s) return fail(s.error());
  std::vector<T> voxels;
  try {
    itk::ImageIORegion region(3);
    for (unsigned a = 0; a < 3; ++a) {
      region.SetIndex(a, 0);
      region.SetSize(a, io.GetDimensions(a));
    }
    io.SetIORegion(region);
    voxels.resize(static_cast<std::size_t>(std::int64_t{out.size[0]} * out.size[1] * out.size[2]));
    io.Read(voxels.data());
  } catch (const itk::ExceptionObject& e) {
    return fail(path + ": voxels: cannot read them: " + itk_reason(e) + "; expected an intact label map");
  } catch (const std::bad_alloc&) {
    return fail(path + ": voxels: not enough memory for " + std::to_string(out.size[0]) + " x " +
                std::to_string(out.size[1]) + " x " + std::to_string(out.size[2]) + " voxels");
  }
  const T* voxel = voxels.data();
  const auto at = [&](int i, int j, int k) {
    return static_cast<std::int64_t>(voxel[(std::int64_t{k} * out.size[1] + j) * out.size[0] + i]);
  };
  std::vector<Box> box(values.size());
  std::set<std::int64_t> seen;
  for (int k = 0; k < out.size[2]; ++k)
    for (int j = 0; j < out.size[1]; ++j)
      for (int i = 0; i < out.size[0]; ++i) {
        const std::int64_t value = at(i, j, k);
        if (seen.size() <= 16) seen.insert(value);
        for (std::size_t l = 0; l < values.size(); ++l)
          if (value == values[l]) {
            Box& b = box[l];
            ++b.count;
            const std::array<int, 3> p{i, j, k};
            for (int a = 0; a < 3; ++a) b.lo[a] = std::min(b.lo[a], p[a]), b.hi[a] = std::max(b.hi[a], p[a]);
          }
      }
  out.more_values = seen.size() > 16;
  out.values_seen.assign(seen.begin(), seen.end());
  if (out.more_values) out.values_seen.pop_back();
  for (std::size_t l = 0; l < values.size(); ++l) {
    CroppedLabel c{values[l], box[l].count, box[l].lo, {0, 0, 0}, {}};
    if (c.voxels > 0) {
      for (int a = 0; a < 3; ++a) c.size[a] = box[l].hi[a] - box[l].lo[a] + 1;
      c.inside.resize(static_cast<std::size_t>(std::int64_t{c.size[0]} * c.size[1] * c.size[2]));
      std::size_t v = 0;
      for (int k = 0; k < c.size[2]; ++k)
        for (int j = 0; j < c.size[1]; ++j)
          for (int i = 0; i < c.size[0]; ++i) c.inside[v++] = at(i + c.lo[0], j + c.lo[1], k + c.lo[2]) == values[l];
    }
    out.labels.push_back(std::move(c));
  }
  return out;
}

}  // namespace

lungar::Result<LabelImage> read_label_image(const std::string& path, const std::vector<std::int64_t>& values) {
  register_formats();
  itk::ImageIOBase::Pointer io = itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::IOFileModeEnum::ReadMode);
  if (!io) return fail(path + ": cannot read: expected a label map in NRRD, NIfTI (.nii, .nii.gz) or MetaImage (.mha, .mhd)");
  try {
    io->SetFileName(path);
    io->ReadImageInformation();
  } catch (const itk::ExceptionObject& e) {
    return fail(path + ": header: cannot read it: " + itk_reason(e));
  }
  if (io->GetNumberOfDimensions() != 3)
    return fail(path + ": dimension: expected a 3-D label map, got " + std::to_string(io->GetNumberOfDimensions()) + "-D");
  if (io->GetNumberOfComponents() != 1)
    return fail(path + ": components: expected one label per voxel, got " + std::to_string(io->GetNumberOfComponents()));
  for (unsigned a = 0; a < 3; ++a)
    if (io->GetDimensions(a) < 2) return fail(path + ": sizes: expected at least 2 voxels along each axis");
  using C = itk::IOComponentEnum;
  switch (io->GetComponentType()) {
    case C::UCHAR: return crop_labels<std::uint8_t>(path, *io, values);
    case C::CHAR: return crop_labels<std::int8_t>(path, *io, values);
    case C::USHORT: return crop_labels<std::uint16_t>(path, *io, values);
    case C::SHORT: return crop_labels<std::int16_t>(path, *io, values);
    case C::UINT: return crop_labels<std::uint32_t>(path, *io, values);
    case C::INT: return crop_labels<std::int32_t>(path, *io, values);
    case C::ULONG: case C::LONG: case C::ULONGLONG: case C::LONGLONG: return crop_labels<std::int64_t>(path, *io, values);
    default:
      return fail(path + ": voxel type: expected integer labels, got " +
                  itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType()));
  }
}

}  // namespace lungar::sim::itk_io
