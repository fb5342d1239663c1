#include "triangle_mesh.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace afford::modelling {

Closure closure(const TriangleMesh& mesh) {
  // Each directed edge once; its reverse must be there exactly once too.
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(mesh.triangles.size() * 3);
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b); };
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[key(t[k], t[(k + 1) % 3])];
  }
  Closure c;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const int forward = directed[key(a, b)];
      const auto back = directed.find(key(b, a));
      const int backward = back == directed.end() ? 0 : back->second;
      if (forward == 1 && backward == 1) continue;
      c.why_not = "edge " + std::to_string(a) + "-" + std::to_string(b) + " is run by " +
                  std::to_string(forward) + " triangle(s) one way and " + std::to_string(backward) +
                  " the other (closed and oriented: 1 and 1)";
      return c;
    }
  }
  c.closed = !mesh.triangles.empty();
  if (!c.closed) c.why_not = "no triangles";
  return c;
}

Eigen::Vector3d box_min(const TriangleMesh& mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (const Eigen::Vector3d& v : mesh.vertices) lo = lo.cwiseMin(v);
  return lo;
}

Eigen::Vector3d box_max(const TriangleMesh& mesh) {
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  for (const Eigen::Vector3d& v : mesh.vertices) hi = hi.cwiseMax(v);
  return hi;
}

}  // namespace afford::modelling
