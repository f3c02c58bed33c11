/// @file tri_mesh.cpp
/// @brief Per-vertex areas and normals, enclosed volume and centroid of a triangle surface.
#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

VertexGeometry vertex_geometry(const TriMesh& mesh) {
  VertexGeometry g;
  g.areas.assign(mesh.positions.size(), 0.0);
  g.normals.assign(mesh.positions.size(), Eigen::Vector3d::Zero());
  for (const Triangle& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.positions[t[0]];
    const Eigen::Vector3d& b = mesh.positions[t[1]];
    const Eigen::Vector3d& c = mesh.positions[t[2]];
    const Eigen::Vector3d cross = (b - a).cross(c - a);  // twice the area along the face normal
    const double third_area = cross.norm() / 6.0;
    for (std::uint32_t v : t) {
      g.areas[v] += third_area;
      g.normals[v] += cross;  // area weighting comes for free
    }
  }
  for (Eigen::Vector3d& n : g.normals) {
    const double len = n.norm();
    n = len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::UnitZ();
  }
  return g;
}

double enclosed_volume(const TriMesh& mesh) {
  double six_v = 0;
  for (const Triangle& t : mesh.triangles)
    six_v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]]));
  return six_v / 6.0;
}

double enclosed_volume(std::span<const std::uint32_t> indices, const float* xyz) {
  double six_v = 0;
  for (std::size_t k = 0; k + 2 < indices.size(); k += 3) {
    const std::uint32_t* t = &indices[k];
    const Eigen::Vector3d a(xyz[3 * t[0]], xyz[3 * t[0] + 1], xyz[3 * t[0] + 2]);
    const Eigen::Vector3d b(xyz[3 * t[1]], xyz[3 * t[1] + 1], xyz[3 * t[1] + 2]);
    const Eigen::Vector3d c(xyz[3 * t[2]], xyz[3 * t[2] + 1], xyz[3 * t[2] + 2]);
    six_v += a.dot(b.cross(c));
  }
  return six_v / 6.0;
}

Eigen::Vector3d volume_centroid(const TriMesh& mesh) {
  // Each triangle with the origin spans a tetrahedron; the solid's centroid is their volume-weighted mean.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double six_v = 0;
  for (const Triangle& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.positions[t[0]];
    const Eigen::Vector3d& b = mesh.positions[t[1]];
    const Eigen::Vector3d& c = mesh.positions[t[2]];
    const double w = a.dot(b.cross(c));
    six_v += w;
    sum += w * (a + b + c) / 4.0;
  }
  return six_v != 0 ? Eigen::Vector3d(sum / six_v) : Eigen::Vector3d::Zero();
}

double surface_area(const TriMesh& mesh) {
  double s = 0;
  for (const Triangle& t : mesh.triangles)
    s += (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm();
  return s / 2.0;
}

std::optional<double> x_crossing(const TriMesh& mesh, std::uint32_t t, double y, double z) {
  const Eigen::Vector3d& a = mesh.positions[mesh.triangles[t][0]];
  const Eigen::Vector3d& b = mesh.positions[mesh.triangles[t][1]];
  const Eigen::Vector3d& c = mesh.positions[mesh.triangles[t][2]];
  // Barycentric coordinates of (y, z) in the triangle's (y, z) projection.
  const double det = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
  if (det == 0) return std::nullopt;
  const double u = ((y - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (z - a.z())) / det;
  const double v = ((b.y() - a.y()) * (z - a.z()) - (y - a.y()) * (b.z() - a.z())) / det;
  if (u < 0 || v < 0 || u + v > 1) return std::nullopt;
  return a.x() + u * (b.x() - a.x()) + v * (c.x() - a.x());
}

}  // namespace lungar::sim
