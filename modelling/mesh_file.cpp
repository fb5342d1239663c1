#include "mesh_file.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <unordered_map>

#include "errors.h"

namespace afford::modelling {
namespace {

namespace fs = std::filesystem;

std::string extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

bool unitless_format(const std::string& e) { return e == ".obj" || e == ".stl" || e == ".ply"; }
bool unit_format(const std::string& e) { return e == ".dae" || e == ".gltf" || e == ".glb"; }

[[noreturn]] void file_error(const std::string& path, const std::string& expected, const std::string& found) {
  fail(SourceLoc{path, 0, 0}, expected, found);
}

void check_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) file_error(path, "a mesh file", "no such file");
  if (!fs::is_regular_file(st)) {
    file_error(path, "a mesh file", fs::is_directory(st) ? "a directory" : "something that is not a regular file");
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) file_error(path, "a readable mesh file", ec.message());
  if (size > kMaxMeshFileBytes) {
    file_error(path, "a mesh file of at most 100 MiB", std::to_string(size >> 20) + " MiB");
  }
  const std::string e = extension(path);
  if (!unitless_format(e) && !unit_format(e)) {
    file_error(path, "an OBJ, STL, PLY, DAE or glTF (.gltf, .glb) file", "the extension '" + e + "'");
  }
}

// Vertices that coincide exactly become one, so that a closed surface
// written per triangle (STL) is seen as closed.
struct Welder {
  std::unordered_map<std::string, int> index;
  std::vector<Eigen::Vector3d>* out;
  int add(const Eigen::Vector3d& v) {
    Eigen::Vector3d w = v;
    for (int k = 0; k < 3; ++k) w[k] += 0.0;  // -0 and +0 alike
    std::string key(sizeof w[0] * 3, '\0');
    std::memcpy(key.data(), w.data(), key.size());
    const auto [it, fresh] = index.emplace(std::move(key), static_cast<int>(out->size()));
    if (fresh) out->push_back(w);
    return it->second;
  }
};

}  // namespace

bool format_says_unit(const std::string& path) { return unit_format(extension(path)); }

TriangleMesh read_mesh(const std::string& path, std::optional<double> metres_per_unit) {
  check_file(path);
  const bool says = format_says_unit(path);
  if (says && metres_per_unit) {
    file_error(path, "no --unit for a DAE or glTF file (it says its own unit)", "--unit");
  }
  if (!says && !metres_per_unit) {
    file_error(path, "--unit mm or --unit m (OBJ, STL and PLY do not say their unit)", "no --unit");
  }
  const double scale = says ? 1.0 : *metres_per_unit;

  Assimp::Importer importer;
  // Every node's transform applied (a DAE's <unit> with it); polygons cut
  // into triangles; points and lines dropped.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (scene == nullptr) file_error(path, "a mesh Assimp can read", shorten(importer.GetErrorString()));

  TriangleMesh mesh;
  mesh.file = path;
  Welder welder{{}, &mesh.vertices};
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* m = scene->mMeshes[i];
    for (unsigned f = 0; f < m->mNumFaces; ++f) {
      const aiFace& face = m->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines: no surface
      std::array<int, 3> t{};
      for (int k = 0; k < 3; ++k) {
        const aiVector3D& p = m->mVertices[face.mIndices[k]];
        const Eigen::Vector3d v = scale * Eigen::Vector3d(p.x, p.y, p.z);
        if (!v.allFinite()) {
          file_error(path, "finite vertex coordinates", "vertex " + std::to_string(face.mIndices[k]) + " of mesh " +
                                                            std::to_string(i) + " at (" + std::to_string(p.x) + ", " +
                                                            std::to_string(p.y) + ", " + std::to_string(p.z) + ")");
        }
        t[k] = welder.add(v);
      }
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // no area: no surface
      mesh.triangles.push_back(t);
      if (mesh.triangles.size() > kMaxMeshTriangles) {
        file_error(path, "at most 5,000,000 triangles", "more");
      }
    }
  }
  if (mesh.triangles.empty()) file_error(path, "a mesh with triangles", "none");
  return mesh;
}

}  // namespace afford::modelling
