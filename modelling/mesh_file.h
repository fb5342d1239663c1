// Meshes read from OBJ, STL, PLY, DAE and glTF files through Assimp, in
// metres. OBJ, STL and PLY do not say their unit: the caller gives it. DAE
// (its <unit>) and glTF (metres by its specification) do, and a unit given
// for them is an error rather than a second scaling.
#pragma once

#include <optional>
#include <string>

#include "triangle_mesh.h"

namespace afford::modelling {

inline constexpr std::uintmax_t kMaxMeshFileBytes = 100u << 20;  // 100 MiB: a scan of a few million triangles
inline constexpr size_t kMaxMeshTriangles = 5'000'000;

// The file's triangles, its vertices welded where they coincide exactly
// (STL repeats them per triangle), in metres. Assimp reads coordinates in
// single precision: a vertex is good to about 6e-8 of its distance from
// the file's origin. `metres_per_unit` is the
// length of one of the file's units (0.001 for mm) for OBJ, STL and PLY,
// and must be empty for DAE and glTF. DataError (at the file) when the file
// is missing, not a regular file, too large, of another format, unreadable
// by Assimp, empty, or has a vertex that is not finite.
TriangleMesh read_mesh(const std::string& path, std::optional<double> metres_per_unit);

// Whether the format says its own unit (DAE, glTF), by the file's extension.
bool format_says_unit(const std::string& path);

}  // namespace afford::modelling
