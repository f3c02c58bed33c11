/// @file surface_simplify.cpp
/// @brief TriMesh -> OpenMesh -> quadric decimation with normal-flip and aspect-ratio guards -> TriMesh.
#include "sim/bake_tool/surface_simplify.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

namespace lungar::sim {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

}  // namespace

lungar::Result<TriMesh> simplify_surface(const TriMesh& in, std::uint32_t target) {
  if (in.positions.size() <= target) return in;
  Mesh mesh;
  std::vector<Mesh::VertexHandle> handle;
  handle.reserve(in.positions.size());
  for (const Eigen::Vector3d& p : in.positions) handle.push_back(mesh.add_vertex(Mesh::Point(p.x(), p.y(), p.z())));
  for (const Triangle& t : in.triangles)
    if (!mesh.add_face(handle[t[0]], handle[t[1]], handle[t[2]]).is_valid())
      return fail("simplification: the surface is not a 2-manifold (a triangle could not be added)");
  mesh.request_face_normals();
  mesh.update_face_normals();
  OpenMesh::Decimater::DecimaterT<Mesh> decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<Mesh>::Handle flipping;
  OpenMesh::Decimater::ModAspectRatioT<Mesh>::Handle aspect;
  decimater.add(quadric);
  decimater.add(flipping);
  decimater.add(aspect);
  decimater.module(flipping).set_max_normal_deviation(60.0);  // a collapse may turn a face by at most 60 degrees
  decimater.module(aspect).set_aspect_ratio(10.0f);          // and may not leave a face thinner than 1:10
  if (!decimater.initialize()) return fail("simplification: OpenMesh's decimater could not start");
  decimater.decimate_to(target);
  mesh.garbage_collection();
  TriMesh out;
  out.positions.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const Mesh::Point& p = mesh.point(v);
    out.positions.emplace_back(p[0], p[1], p[2]);
  }
  out.triangles.reserve(mesh.n_faces());
  for (const auto f : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (const auto v : mesh.fv_range(f)) t[k++] = static_cast<std::uint32_t>(v.idx());
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace lungar::sim
