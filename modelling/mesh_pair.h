// A two-part tool from two meshes, the fixed part and the moving part as
// they lie in their files, with the hinge given by hand: what `afford
// model FIXED MOVING --hinge ... --range ...` models when there is no URDF.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "urdf_tool.h"

namespace afford::modelling {

// `hinge_point` in metres in the meshes' frame; `hinge_axis` of any nonzero
// length (std::invalid_argument otherwise); the moving part turns from
// `lower` to `upper` (rad) about it, 0 as it lies in its file. The meshes'
// DataErrors as read_mesh says.
UrdfTool mesh_pair_tool(const std::string& fixed, const std::string& moving, std::optional<double> metres_per_unit,
                        const Eigen::Vector3d& hinge_point, const Eigen::Vector3d& hinge_axis, double lower,
                        double upper);

}  // namespace afford::modelling
