#include "lever_geometry.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "errors.h"
#include "lever.h"
#include "units.h"
#include "surface_distance.h"

namespace afford::modelling {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

constexpr int kSamplesPerPart = 20000;  // points spread over each part's surface
constexpr int kBins = 200;              // stretches along the arm
constexpr double kNearHinge = 0.1;      // of the arm's reach: angles this near the pivot say little
constexpr double kTypeOneReach = 0.2;   // both ends reach this share of the longer one: type 1
constexpr double kUniformShare = 0.8;   // jaws over this share of the arm: no jaws told apart
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
constexpr double kRounding = 1e-9;      // rad: an angle this small is the sums' rounding

// The object axes, written in the tool's frame.
struct Frame {
  Vector3d origin, u, v, z;
};

Isometry3d to_object(const Frame& f) {
  Isometry3d t = Isometry3d::Identity();
  t.linear().row(0) = f.u.transpose();
  t.linear().row(1) = f.v.transpose();
  t.linear().row(2) = f.z.transpose();
  t.translation() = -(t.linear() * f.origin);
  return t;
}

Frame turned(const Frame& f, double angle) {  // the axes turned about z by angle (rad)
  Frame g = f;
  g.u = std::cos(angle) * f.u + std::sin(angle) * f.v;
  g.v = f.z.cross(g.u);
  return g;
}

// A surface point: its distance along its arm (in the arm's own frame) and
// its angle from the arm's line at joint 0, counter-clockwise about z, on
// its side of the pivot.
struct Point {
  double x = 0, beta = 0;
};

std::vector<Point> points_of(const std::vector<Vector3d>& samples, const Frame& f, double theta0) {
  const Isometry3d t = to_object(f);
  std::vector<Point> out;
  out.reserve(samples.size());
  for (const Vector3d& p : samples) {
    const Vector3d q = t * p;
    const double x_arm = std::cos(theta0) * q.x() + std::sin(theta0) * q.y();
    const double s = x_arm >= 0 ? 1 : -1;
    out.push_back({x_arm, std::atan2(s * q.y(), s * q.x())});
  }
  return out;
}

// Both parts' points in stretches along the arm: the fixed part's largest
// angle and the moving part's smallest, where each has points.
struct Profile {
  double lo = 0, hi = 0, reach = 0;  // m
  std::vector<double> fixed_max, moving_min, gap;  // rad per bin; NaN where not both (or near the pivot)
  double width() const { return (hi - lo) / kBins; }
  double centre(int b) const { return lo + (b + 0.5) * width(); }
};

// `only`: +1 or -1 keeps the gap on that side of the pivot alone (a tool
// whose parts lie on one side: behind it is the hinge's knuckle), 0 both.
Profile profile_of(const std::vector<Point>& fixed, const std::vector<Point>& moving, double only) {
  Profile p;
  p.lo = std::numeric_limits<double>::infinity();
  p.hi = -p.lo;
  for (const auto* pts : {&fixed, &moving}) {
    for (const Point& q : *pts) {
      p.lo = std::min(p.lo, q.x);
      p.hi = std::max(p.hi, q.x);
    }
  }
  p.reach = std::max(std::abs(p.lo), std::abs(p.hi));
  p.fixed_max.assign(kBins, kNone);
  p.moving_min.assign(kBins, kNone);
  p.gap.assign(kBins, kNone);
  auto bin = [&](double x) { return std::clamp(static_cast<int>((x - p.lo) / p.width()), 0, kBins - 1); };
  for (const Point& q : fixed) {
    double& m = p.fixed_max[bin(q.x)];
    if (std::isnan(m) || q.beta > m) m = q.beta;
  }
  for (const Point& q : moving) {
    double& m = p.moving_min[bin(q.x)];
    if (std::isnan(m) || q.beta < m) m = q.beta;
  }
  for (int b = 0; b < kBins; ++b) {
    if (std::abs(p.centre(b)) < kNearHinge * p.reach || only * p.centre(b) < 0) continue;
    if (!std::isnan(p.fixed_max[b]) && !std::isnan(p.moving_min[b])) p.gap[b] = p.moving_min[b] - p.fixed_max[b];
  }
  return p;
}

double median_beta(const std::vector<Point>& pts, double reach) {
  std::vector<double> b;
  for (const Point& q : pts) {
    if (std::abs(q.x) >= kNearHinge * reach) b.push_back(q.beta);
  }
  if (b.empty()) return 0;
  std::nth_element(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(b.size() / 2), b.end());
  return b[b.size() / 2];
}

// The smallest gap over the bins whose centres `keep` says yes to; NaN where none.
template <typename Keep>
double smallest_gap(const Profile& p, Keep keep) {
  double g = kNone;
  for (int b = 0; b < kBins; ++b) {
    if (!std::isnan(p.gap[b]) && keep(p.centre(b)) && (std::isnan(g) || p.gap[b] < g)) g = p.gap[b];
  }
  return g;
}

std::string deg(double rad) { return format_quantity(rad, dim::angle); }
std::string mm(double m) { return format_quantity(m, dim::length); }

// The jaws: the run of bins around the smallest gap (on the jaws' side)
// whose gap is within the tolerance of it; its extent from the points in it.
RangeSpec jaws_of(const Profile& p, const std::vector<Point>& fixed, const std::vector<Point>& moving,
                  bool positive_only) {
  int best = -1;
  for (int b = 0; b < kBins; ++b) {
    if (std::isnan(p.gap[b]) || (positive_only && p.centre(b) < 0)) continue;
    if (best < 0 || p.gap[b] < p.gap[best]) best = b;
  }
  const double limit = p.gap[best] + kJawGapTolerance;
  auto in_run = [&](int b) {
    return b >= 0 && b < kBins && !std::isnan(p.gap[b]) && p.gap[b] <= limit && (!positive_only || p.centre(b) >= 0);
  };
  int first = best, last = best;
  while (in_run(first - 1)) --first;
  while (in_run(last + 1)) ++last;
  const double lo = p.lo + first * p.width(), hi = p.lo + (last + 1) * p.width();
  RangeSpec r{hi, lo, {}};
  for (const auto* pts : {&fixed, &moving}) {
    for (const Point& q : *pts) {
      if (q.x >= lo && q.x <= hi) {
        r.from = std::min(r.from, q.x);
        r.to = std::max(r.to, q.x);
      }
    }
  }
  return r;
}

double share_with_gap(const Profile& p, const RangeSpec& r) {
  int with_gap = 0, inside = 0;
  for (int b = 0; b < kBins; ++b) {
    if (std::isnan(p.gap[b])) continue;
    ++with_gap;
    if (p.centre(b) >= r.from && p.centre(b) <= r.to) ++inside;
  }
  return with_gap == 0 ? 0 : static_cast<double>(inside) / with_gap;
}

}  // namespace

LeverGeometry lever_geometry(const UrdfTool& tool, const RegionsGiven& given) {
  const SourceLoc at{tool.file, 0, 0};
  if (!tool.limited) {
    fail(at, "limits on the joint (a revolute joint, or --range MIN,MAX)", "a continuous joint");
  }
  const std::vector<Vector3d> fixed_samples = surface_samples(tool.fixed, kSamplesPerPart);
  const std::vector<Vector3d> moving_samples = surface_samples(tool.moving, kSamplesPerPart);

  // The first axes: z along the hinge, x along the fixed part's longest
  // extent across it, the origin on the hinge level with the parts.
  Frame f;
  f.z = tool.hinge_axis.normalized();
  double low = std::numeric_limits<double>::infinity(), high = -low;  // the parts' extent along the hinge
  for (const auto* m : {&tool.fixed, &tool.moving}) {
    for (const Vector3d& p : m->vertices) {
      low = std::min(low, f.z.dot(p - tool.hinge_point));
      high = std::max(high, f.z.dot(p - tool.hinge_point));
    }
  }
  f.origin = tool.hinge_point + f.z * (0.5 * (low + high));
  const Vector3d e1 = f.z.unitOrthogonal(), e2 = f.z.cross(e1);
  Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Vector3d& p : fixed_samples) {
    const Eigen::Vector2d d((p - f.origin).dot(e1), (p - f.origin).dot(e2));
    spread += d * d.transpose();
    mean += d;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(spread);
  Eigen::Vector2d along = eig.eigenvectors().col(1);
  if (along.dot(mean) < 0) along = -along;
  f.u = (along.x() * e1 + along.y() * e2).normalized();
  f.v = f.z.cross(f.u);

  // The moving part on the side of positive angles (it opens counter-
  // clockwise about z): else z turns over and the joint's angle with it.
  LeverGeometry g;
  std::vector<Point> fixed = points_of(fixed_samples, f, 0), moving = points_of(moving_samples, f, 0);
  Profile p = profile_of(fixed, moving, 0);
  if (median_beta(moving, p.reach) < median_beta(fixed, p.reach)) {
    f.z = -f.z;
    f.v = -f.v;
    g.joint_sign = -1;
  }
  // Type 1 where both ends reach across the pivot; else the gap is
  // measured on the long side only.
  const double pos = std::max(p.hi, 0.0), neg = std::max(-p.lo, 0.0);
  const bool type1 = std::min(pos, neg) >= kTypeOneReach * std::max(pos, neg);
  double only = type1 ? 0 : pos >= neg ? 1 : -1;
  // The opening at joint 0: the smallest gap, measured again with the
  // moving part's distances along its own arm.
  for (int pass = 0; pass < 2; ++pass) {
    fixed = points_of(fixed_samples, f, 0);
    moving = points_of(moving_samples, f, g.theta_at_zero);
    p = profile_of(fixed, moving, only);
    const double smallest = smallest_gap(p, [](double) { return true; });
    if (std::isnan(smallest)) {
      fail(at, "two parts side by side along the arm, away from the hinge", "no stretch of the arm where both are");
    }
    g.theta_at_zero = std::abs(smallest) < kRounding ? 0 : smallest;
  }

  // Which way the arm runs: a type 1 tool's jaws at positive distances,
  // other tools' parts at positive distances.
  bool turn = neg > pos;
  if (type1) {
    const double gp = smallest_gap(p, [](double x) { return x > 0; });
    const double gn = smallest_gap(p, [](double x) { return x < 0; });
    if (std::isnan(gp) || std::isnan(gn) || std::abs(gp - gn) > kJawGapTolerance) {
      turn = std::isnan(gp) || (!std::isnan(gn) && gn < gp);
    } else {
      turn = neg < pos;  // a tie: the jaws are the shorter end
    }
  }
  if (turn) {
    f.u = -f.u;
    f.v = -f.v;
    only = -only;
    fixed = points_of(fixed_samples, f, 0);
    moving = points_of(moving_samples, f, g.theta_at_zero);
    p = profile_of(fixed, moving, only);
  }

  // The jaws and the handle, then the fixed jaw's face turned into y = 0;
  // found again in the turned frame, where distances along the arm are
  // the object frame's.
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      fixed = points_of(fixed_samples, f, 0);
      moving = points_of(moving_samples, f, g.theta_at_zero);
      p = profile_of(fixed, moving, only);
    }
    g.application_found = !given.application;
    g.emphasis_found = !given.emphasis;
    if (given.application) {
      g.application = *given.application;
    } else {
      g.application = jaws_of(p, fixed, moving, type1);
      if (!type1 && share_with_gap(p, g.application) >= kUniformShare) {
        fail(at, "jaws told apart from the handle by the gap between the parts (smallest where the jaws meet)",
             "a gap the same within " + deg(kJawGapTolerance) + " from " + mm(g.application.from) + " to " +
                 mm(g.application.to) + ": give --application FROM,TO and --emphasis FROM,TO (mm)");
      }
    }
    if (given.emphasis) {
      g.emphasis = *given.emphasis;
    } else if (type1) {
      g.emphasis = {p.lo, 0.5 * p.lo, {}};  // the handles' far half, where a hand closes on them
    } else {
      double start = p.hi;  // the part nearest the pivot
      for (const auto* pts : {&fixed, &moving}) {
        for (const Point& q : *pts) start = std::min(start, std::max(q.x, 0.0));
      }
      if (g.application.middle() < 0.5 * (start + p.hi)) {  // jaws near the pivot: the hand beyond them
        g.emphasis = {0.5 * (g.application.to + p.hi), p.hi, {}};
      } else {  // jaws at the far end: the hand between the pivot and them
        const double w = g.application.from - start;
        g.emphasis = {start + 0.25 * w, start + 0.75 * w, {}};
      }
    }
    std::string why;
    const std::optional<LeverPattern> pattern = derive_pattern(g.emphasis, g.application, &why);
    if (!pattern) {
      fail(at, why, "the handle at " + mm(g.emphasis.from) + " to " + mm(g.emphasis.to) + " and the jaws at " +
                        mm(g.application.from) + " to " + mm(g.application.to));
    }
    g.pattern = *pattern;

    // The fixed jaw's gripping face in y = 0.
    double face = kNone;
    for (const Point& q : fixed) {
      if (q.x >= g.application.from && q.x <= g.application.to && std::abs(q.x) >= kNearHinge * p.reach &&
          (std::isnan(face) || q.beta > face)) {
        face = q.beta;
      }
    }
    if (std::isnan(face)) {
      fail(at, "the fixed part along the jaws (" + mm(g.application.from) + " to " + mm(g.application.to) + ")", "none of it there");
    }
    f = turned(f, face);
  }
  g.fixed_to_object = to_object(f);
  g.moving_to_arm = Eigen::AngleAxisd(-g.theta_at_zero, Vector3d::UnitZ()) * g.fixed_to_object;

  // The gap along the closed tool, for the report.
  for (int b = 0; b < kBins; ++b) {
    if (std::isnan(p.gap[b])) continue;
    g.gap.push_back({p.lo + b * p.width(), p.lo + (b + 1) * p.width(), p.gap[b] - g.theta_at_zero});
  }

  // The opening angle at the joint's limits; closed where the parts meet.
  const double a = g.theta_at_zero + g.joint_sign * tool.lower, b = g.theta_at_zero + g.joint_sign * tool.upper;
  g.theta_min = std::min(a, b);
  g.theta_max = std::max(a, b);
  if (!(g.theta_max > 1e-6)) {
    fail(at, "a joint range that opens the tool", "openings of " + deg(g.theta_min) + " to " + deg(g.theta_max) +
                                                      " (0 deg where the parts meet)");
  }
  if (g.theta_min < 0) {
    g.closes_on_contact = g.theta_min < -kRounding;
    g.theta_min = 0;
  }
  if (g.theta_max >= std::numbers::pi) fail(at, "an opening below 180 deg", deg(g.theta_max));

  // The arm's extent, from every vertex in its own arm's frame.
  g.arm = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), {}};
  for (const Vector3d& v : tool.fixed.vertices) {
    const double x = (g.fixed_to_object * v).x();
    g.arm.from = std::min(g.arm.from, x);
    g.arm.to = std::max(g.arm.to, x);
  }
  for (const Vector3d& v : tool.moving.vertices) {
    const double x = (g.moving_to_arm * v).x();
    g.arm.from = std::min(g.arm.from, x);
    g.arm.to = std::max(g.arm.to, x);
  }
  return g;
}

}  // namespace afford::modelling
