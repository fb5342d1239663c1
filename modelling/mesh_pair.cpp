#include "mesh_pair.h"

#include <cmath>
#include <stdexcept>

#include "mesh_file.h"

namespace afford::modelling {

UrdfTool mesh_pair_tool(const std::string& fixed, const std::string& moving, std::optional<double> metres_per_unit,
                        const Eigen::Vector3d& hinge_point, const Eigen::Vector3d& hinge_axis, double lower,
                        double upper) {
  if (!(hinge_axis.norm() > 1e-9) || !hinge_axis.allFinite() || !hinge_point.allFinite()) {
    throw std::invalid_argument("--hinge: a finite point and an axis of some length");
  }
  if (!(lower < upper)) throw std::invalid_argument("--range: MIN below MAX");
  UrdfTool tool;
  tool.file = fixed;
  tool.joint = "--hinge";
  tool.fixed_link = fixed;
  tool.moving_link = moving;
  tool.hinge_point = hinge_point;
  tool.hinge_axis = hinge_axis.normalized();
  tool.limited = true;
  tool.lower = lower;
  tool.upper = upper;
  tool.fixed = read_mesh(fixed, metres_per_unit);  // DataError: a unit for a DAE, none for an STL, ...
  tool.moving = read_mesh(moving, metres_per_unit);
  tool.fixed_pieces.push_back({"fixed", tool.fixed, fixed});
  tool.moving_pieces.push_back({"moving", tool.moving, moving});
  return tool;
}

}  // namespace afford::modelling
