// How the commands print quantities, shortened because their reports use
// them on every line: q(si, dim) is format_quantity (units.h), in the
// dimension's display unit; qv a vector as "[x, y, z]".
#pragma once

#include <Eigen/Core>
#include <string>

#include "units.h"

namespace afford::cli {

inline std::string q(double si, const Dimension& d) { return format_quantity(si, d); }

inline std::string qv(const Eigen::Vector3d& v, const Dimension& d) {
  return "[" + q(v.x(), d) + ", " + q(v.y(), d) + ", " + q(v.z(), d) + "]";
}

}  // namespace afford::cli
