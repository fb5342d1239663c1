// An object file's tool as a robot description (`afford export --urdf`):
// a URDF with a link per arm, the hinge as a revolute joint with the
// opening angles as its limits and the pivot's friction and damping as its
// dynamics, each part meshed (modelling/primitive_meshes) into an STL file
// named from the part. Each link's <inertial> has the tool's mass shared by
// volume, centred so that the tool's centre of gravity at rest is the
// file's. URDF has no spring: a comment says it, as the `afford model
// --spring` that gives it back.
#pragma once

#include <string>
#include <vector>

#include "spec.h"

namespace afford::modelling {

struct ExportedFile {
  std::string path;  // relative to the folder written into: "NAME.urdf", "meshes/PART.stl"
  std::string text;
};

// The URDF first, then one mesh per part. Deterministic text.
std::vector<ExportedFile> urdf_export(const ObjectSpec& object);

}  // namespace afford::modelling
