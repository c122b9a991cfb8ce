// A triangle mesh of the scene in the world frame W, its Wavefront OBJ text (scene.obj of a dataset
// rendered with images) and the ray cast that gives the true 3-D point seen at a pixel.
//
// scene.obj holds only "v x y z" (metres, W) and "f i j k" (1-based vertex indices, triangles) lines, plus
// "#" comments and "o name" lines; what the renderer drew is exactly these triangles.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/camera.h"
#include "core/output.h"

namespace vigil {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices_W;
  std::vector<std::array<int, 3>> triangles;  // 0-based vertex indices
};

inline constexpr const char* kSceneObjFile = "scene.obj";

// OBJ text of `mesh` (shortest round-trip numbers: reads back bit for bit).
std::string MeshObj(const TriangleMesh& mesh);
// Reads OBJ text: v and f lines (f with 3 indices, "i", "i/t" or "i/t/n" forms; polygons of more vertices
// are fanned into triangles); other lines (vt, vn, o, g, s, usemtl, mtllib, comments) are ignored. Errors are
// "file:line: reason" (bad number, index out of range).
TriangleMesh ReadMeshObj(const TextFile& file);
TriangleMesh ReadMeshObj(const std::string& path);

// Distance along the ray origin_W + s dir_W (dir_W need not be unit; s in units of |dir_W|) to the first
// triangle it hits with s > min_s; nothing on a miss. Brute force over the triangles (Moeller-Trumbore).
std::optional<double> RayCast(const TriangleMesh& mesh, const Eigen::Vector3d& origin_W,
                              const Eigen::Vector3d& dir_W, double min_s = 1e-9);

// The first point of the mesh seen at pinhole (undistorted) pixel `uv_px` by a camera at pose T_WC (camera
// -> world); nothing when the ray misses.
std::optional<Eigen::Vector3d> PixelRayHit(const TriangleMesh& mesh, const CameraModel& camera,
                                           const Eigen::Isometry3d& T_WC, const Eigen::Vector2d& uv_px);

}  // namespace vigil
