#include "contact_planes.h"

#include <cmath>
#include <vector>

#include "outline.h"

namespace afford::modelling {
namespace {

constexpr int kPlaces = 9;

// The places along a stretch, each in the middle of its ninth (off the ends,
// where a part's corner would count on both of its faces).
double place(const RangeSpec& r, int k) { return r.from + (r.to - r.from) * (k + 0.5) / kPlaces; }

// The middle of the outline's extent across the stretch (y), NaN where none.
double middle_y(const Outline& o, const RangeSpec& r) {
  double sum = 0;
  int n = 0;
  for (int k = 0; k < kPlaces; ++k) {
    const double hi = edge_at(o, place(r, k), +1), lo = edge_at(o, place(r, k), -1);
    if (std::isnan(hi)) continue;
    sum += 0.5 * (hi + lo);
    ++n;
  }
  return n == 0 ? std::nan("") : sum / n;
}

// The face on `side` (+1 the top edge, -1 the bottom) over the stretch.
FacePlane face_of(const Outline& o, const RangeSpec& r, int side, double z) {
  FacePlane f;
  f.from = r.from;
  f.to = r.to;
  std::vector<Eigen::Vector2d> pts;
  for (int k = 0; k < kPlaces; ++k) {
    const double y = edge_at(o, place(r, k), side);
    if (!std::isnan(y)) pts.emplace_back(place(r, k), y);
  }
  if (pts.size() < 2) return f;
  // y = a + b x by least squares.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p / static_cast<double>(pts.size());
  double sxx = 0, sxy = 0;
  for (const auto& p : pts) sxx += (p.x() - mean.x()) * (p.x() - mean.x()), sxy += (p.x() - mean.x()) * (p.y() - mean.y());
  const double b = sxy / sxx;
  double sum = 0;
  for (const auto& p : pts) {
    const double e = p.y() - (mean.y() + b * (p.x() - mean.x()));
    sum += e * e;
  }
  const double x_mid = 0.5 * (r.from + r.to);
  f.point = Eigen::Vector3d(x_mid, mean.y() + b * (x_mid - mean.x()), z);
  f.normal = Eigen::Vector3d(-b * side, side, 0).normalized();
  f.rms = std::sqrt(sum / static_cast<double>(pts.size()));
  f.found = true;
  return f;
}

}  // namespace

ContactPlanes contact_planes(const TriangleMesh& fixed, const TriangleMesh& moving, const LeverGeometry& lever) {
  const Outline f = outline_of(fixed), m = outline_of(moving);
  const double fz = 0.5 * (box_min(fixed).z() + box_max(fixed).z());
  const double mz = 0.5 * (box_min(moving).z() + box_max(moving).z());
  ContactPlanes out;
  // Closed, the moving arm's frame is the object frame: the parts' middles compare.
  const double handle_side = middle_y(f, lever.emphasis) >= middle_y(m, lever.emphasis) ? +1 : -1;
  out.fixed_contact = face_of(f, lever.emphasis, static_cast<int>(handle_side), fz);
  out.moving_contact = face_of(m, lever.emphasis, static_cast<int>(-handle_side), mz);
  const double jaw_side = middle_y(f, lever.application) >= middle_y(m, lever.application) ? -1 : +1;
  out.support = face_of(f, lever.application, static_cast<int>(jaw_side), fz);
  return out;
}

}  // namespace afford::modelling
