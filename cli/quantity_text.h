// A vector printed as the commands print quantities: "[x, y, z]", each in
// the dimension's display unit (units.h).
#pragma once

#include <Eigen/Core>
#include <string>

#include "units.h"

namespace afford::cli {

inline std::string format_vector(const Eigen::Vector3d& v, const Dimension& d) {
  return "[" + format_quantity(v.x(), d) + ", " + format_quantity(v.y(), d) + ", " + format_quantity(v.z(), d) + "]";
}

}  // namespace afford::cli
