#include "core/mesh.h"

#include <sstream>

#include "core/error.h"
#include "core/format.h"

namespace vigil {

std::string MeshObj(const TriangleMesh& mesh) {
  std::string s = "# vigil scene: triangles in the world frame W [m]\no scene\n";
  for (const Eigen::Vector3d& v : mesh.vertices_W)
    s += "v " + FormatDouble(v.x()) + " " + FormatDouble(v.y()) + " " + FormatDouble(v.z()) + "\n";
  for (const auto& t : mesh.triangles)
    s += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) +
         "\n";
  return s;
}

TriangleMesh ReadMeshObj(const std::string& path) { return ReadMeshObj(ReadTextFile(path)); }

TriangleMesh ReadMeshObj(const TextFile& file) {
  TriangleMesh mesh;
  std::istringstream in(file.text);
  std::string row;
  int line = 0;
  std::vector<std::pair<int, std::vector<int64_t>>> faces;  // line, indices as written
  while (std::getline(in, row)) {
    ++line;
    if (!row.empty() && row.back() == '\r') row.pop_back();
    std::istringstream fields(row);
    std::string kind;
    if (!(fields >> kind) || kind[0] == '#') continue;
    if (kind == "v") {
      Eigen::Vector3d v;
      for (int i = 0; i < 3; ++i) {
        std::string tok;
        if (!(fields >> tok) || !ParseDouble(tok, &v[i]))
          throw InputError(Located(file.path, line, "v: expected 3 finite coordinates"));
      }
      mesh.vertices_W.push_back(v);
    } else if (kind == "f") {
      std::vector<int64_t> idx;
      std::string tok;
      while (fields >> tok) {
        int64_t i = 0;
        if (!ParseInt64(tok.substr(0, tok.find('/')), &i))
          throw InputError(Located(file.path, line, "f: expected vertex indices, got '" + tok + "'"));
        idx.push_back(i);
      }
      if (idx.size() < 3) throw InputError(Located(file.path, line, "f: a face needs at least 3 vertices"));
      faces.emplace_back(line, std::move(idx));
    }
  }
  const auto n = static_cast<int64_t>(mesh.vertices_W.size());
  for (const auto& [face_line, idx] : faces) {
    std::vector<int> zero_based;
    for (int64_t i : idx) {
      const int64_t k = i < 0 ? n + i : i - 1;  // negative indices count from the last vertex
      if (i == 0 || k < 0 || k >= n)
        throw InputError(Located(file.path, face_line,
                                 "f: vertex index " + std::to_string(i) + " is out of range (" +
                                     std::to_string(n) + " vertices)"));
      zero_based.push_back(static_cast<int>(k));
    }
    for (std::size_t j = 1; j + 1 < zero_based.size(); ++j)
      mesh.triangles.push_back({zero_based[0], zero_based[j], zero_based[j + 1]});
  }
  return mesh;
}

std::optional<double> RayCast(const TriangleMesh& mesh, const Eigen::Vector3d& origin_W,
                              const Eigen::Vector3d& dir_W, double min_s) {
  std::optional<double> best;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_W[t[0]];
    const Eigen::Vector3d e1 = mesh.vertices_W[t[1]] - a, e2 = mesh.vertices_W[t[2]] - a;
    const Eigen::Vector3d p = dir_W.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-15) continue;  // parallel to the triangle
    const Eigen::Vector3d to_origin = origin_W - a;
    const double u = to_origin.dot(p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Eigen::Vector3d q = to_origin.cross(e1);
    const double v = dir_W.dot(q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double s = e2.dot(q) / det;
    if (s > min_s && (!best || s < *best)) best = s;
  }
  return best;
}

std::optional<Eigen::Vector3d> PixelRayHit(const TriangleMesh& mesh, const CameraModel& camera,
                                           const Eigen::Isometry3d& T_WC, const Eigen::Vector2d& uv_px) {
  const Eigen::Vector2d xy = camera.Normalize(uv_px);
  const Eigen::Vector3d dir_W = T_WC.linear() * Eigen::Vector3d(xy.x(), xy.y(), 1.0);
  const std::optional<double> s = RayCast(mesh, T_WC.translation(), dir_W);
  if (!s) return std::nullopt;
  return Eigen::Vector3d(T_WC.translation() + *s * dir_W);
}

}  // namespace vigil
