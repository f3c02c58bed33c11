/// @file mesh_import.cpp
/// @brief assimp reads the triangles; sim/mesh/mesh_repair.h decides what is a lung.
#include "sim/bake_tool/mesh_import.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <filesystem>

#include "sim/mesh/mesh_repair.h"

namespace lungar::sim {

double units_to_mm(const std::string& units) {
  if (units == "mm") return 1.0;
  if (units == "cm") return 10.0;
  if (units == "m") return 1000.0;
  return 0.0;
}

namespace {

Result<TriMesh> read_soup(const std::string& path, double mm_per_unit, std::vector<std::string>& notes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return fail(path + ": cannot open: " + (std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  Assimp::Importer importer;
  // No normal generation and no "invalid data" clean-up: NaN coordinates must reach our check and be named.
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices);
  if (scene == nullptr) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unknown reason";
    return fail(path + ": cannot read the mesh: " + why + "; expected a closed surface in STL, OBJ or PLY");
  }
  TriMesh soup;
  std::size_t skipped = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const auto base = static_cast<std::uint32_t>(soup.positions.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      soup.positions.emplace_back(p.x * mm_per_unit, p.y * mm_per_unit, p.z * mm_per_unit);
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) {
        ++skipped;
        continue;
      }
      soup.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  if (skipped > 0) notes.push_back(path + ": ignored " + std::to_string(skipped) + " point and line primitives");
  if (soup.triangles.empty()) return fail(path + ": no triangles; expected a closed lung surface");
  return soup;
}

}  // namespace

Result<std::vector<LungMesh>> import_lungs(const std::vector<std::string>& files, double mm_per_unit,
                                           std::vector<std::string>& notes) {
  if (files.empty() || files.size() > 2) return fail("--mesh: expected one or two files");
  if (!(mm_per_unit > 0)) return fail("--units: expected mm, cm or m");
  std::vector<LungMesh> lungs;
  for (const std::string& path : files) {
    Result<TriMesh> soup = read_soup(path, mm_per_unit, notes);
    if (!soup) return fail(soup.error());
    Result<std::vector<TriMesh>> parts = repair_surface(*soup, path, notes);
    if (!parts) return fail(parts.error());
    for (TriMesh& m : *parts) {
      LungMesh lung;
      lung.mesh = std::move(m);
      lungs.push_back(std::move(lung));
    }
  }
  if (lungs.size() > 2)
    return fail(files.back() + ": " + std::to_string(lungs.size()) +
                   " closed components in all; expected one or two lungs");
  std::vector<double> x;
  for (const LungMesh& l : lungs) x.push_back(volume_centroid(l.mesh).x());
  if (lungs.size() == 2) {
    if (x[0] > x[1]) {
      std::swap(lungs[0], lungs[1]);
      std::swap(x[0], x[1]);
    }
    lungs[0].name = "right";
    lungs[1].name = "left";
  } else {
    lungs[0].name = x[0] < 0 ? "right" : "left";
    notes.push_back(files.front() + ": one lung, named '" + lungs[0].name + "' from its centroid's side (x " +
                    (x[0] < 0 ? "< 0" : ">= 0") + ", LPS)");
  }
  return lungs;
}

}  // namespace lungar::sim
