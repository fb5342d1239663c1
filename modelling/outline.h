// A part's outline seen along the pivot axis (the x-y plane the tool turns
// in): its triangles flattened, what an actee between the jaws or a hand on
// the arm meets whatever the part's thickness in z.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "triangle_mesh.h"

namespace afford::modelling {

using Outline = std::vector<std::array<Eigen::Vector2d, 3>>;

Outline outline_of(const TriangleMesh& mesh);

// m, from p to the outline: 0 inside it.
double distance_to(const Outline& outline, const Eigen::Vector2d& p);

// m, the outline's highest (side +1) or lowest (side -1) y on the line
// x = r; NaN where it has none there.
double edge_at(const Outline& outline, double r, int side);

}  // namespace afford::modelling
