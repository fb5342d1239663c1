#include "derive.h"

#include <algorithm>
#include <cmath>

#include "stages.h"

namespace afford {

InteractionSpace interaction_space(const Model& m) {
  InteractionSpace s;
  if (!m.space_distances.empty()) {
    s.from_shape = true;
    s.distances = m.space_distances;
    s.gaps = m.space_gaps;
    s.from = s.distances.front();
    s.to = s.distances.back();
    s.gap_from = s.gaps.front();
    s.gap_to = s.gaps.back();
    return s;
  }
  s.from = m.application_from;
  s.to = m.application_to;
  s.gap_from = std::abs(s.from) * std::sin(m.theta_max);
  s.gap_to = std::abs(s.to) * std::sin(m.theta_max);
  return s;
}

namespace {

// The table's piece [i - 1, i] that holds r (the last piece from its end on).
size_t piece_of(const InteractionSpace& s, double r) {
  const auto above = std::upper_bound(s.distances.begin(), s.distances.end(), r);
  return std::clamp<size_t>(static_cast<size_t>(above - s.distances.begin()), 1, s.distances.size() - 1);
}

}  // namespace

double gap_at(const Model& m, const InteractionSpace& s, double r) {
  if (!s.from_shape) return std::abs(r) * std::sin(m.theta_max);
  const size_t i = piece_of(s, r);
  const double t = std::clamp((r - s.distances[i - 1]) / (s.distances[i] - s.distances[i - 1]), 0.0, 1.0);
  return s.gaps[i - 1] + t * (s.gaps[i] - s.gaps[i - 1]);
}

double clearance_at(const Model& m, const InteractionSpace& s, double r) {
  if (!s.from_shape) return 2 * std::abs(r) * std::tan(0.5 * m.theta_max);
  const size_t i = piece_of(s, r);
  // The loader keeps |slope| <= 1: a gap changes no faster than the distance.
  const double slope = std::min(1.0, std::abs((s.gaps[i] - s.gaps[i - 1]) / (s.distances[i] - s.distances[i - 1])));
  return 2 * gap_at(m, s, r) / (1 + std::sqrt(1 - slope * slope));
}

double effort_for_load(const Model& m, double theta_rad, double effort_m, double load_m, double load_n) {
  return (spring_force(m, theta_rad) * std::abs(m.spring_position) + load_n * std::abs(load_m)) /
         std::abs(effort_m);
}

ActeeFit fit_actee(const Model& m) {
  ActeeFit fit;
  fit.name = m.actee_name;
  ContactQuery query;
  const double lift = m.actee().support(-Eigen::Vector3d::UnitY());
  constexpr int kSteps = 40;  // placements tried across the application region
  // Where it does not fit, by reason: the first and last distance of each.
  struct Span {
    bool seen = false;
    double from = 0, to = 0;  // m
  };
  Span too_large, out_of_reach, off_jaw;
  bool found = false;
  const InteractionSpace space = interaction_space(m);
  for (int i = 0; i <= kSteps; ++i) {
    const double r = space.from + (space.to - space.from) * i / kSteps;
    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
    at.translation() = Eigen::Vector3d(r, lift, 0);
    double theta_c = 0, load_distance = 0;
    const bool too_thick = space.from_shape && thickness_across_jaws(m, at) > clearance_at(m, space, r);
    const JawFit jaw =
        too_thick ? JawFit::too_large : find_contact_angle(m, at, query, &theta_c, &load_distance, nullptr);
    if (jaw != JawFit::fits) {
      Span& span = jaw == JawFit::too_large ? too_large : jaw == JawFit::out_of_reach ? out_of_reach : off_jaw;
      if (!span.seen) span.from = r;
      span.seen = true;
      span.to = r;
      continue;
    }
    if (!found) {
      found = true;
      fit.from = r;
      fit.contact_angle = theta_c;
      const double far = std::abs(m.emphasis_to) > std::abs(m.emphasis_from) ? m.emphasis_to : m.emphasis_from;
      fit.effort_to_limit = effort_for_load(m, theta_c, far, load_distance, m.actee_limit);
    }
    fit.to = r;
  }
  fit.fits = found;
  if (found) return fit;
  // Every reason, with where along the application region it holds.
  auto where = [](const Span& s) {
    return s.from == s.to ? "at " + format_quantity(s.from, dim::length)
                          : "from " + format_quantity(s.from, dim::length) + " to " + format_quantity(s.to, dim::length);
  };
  std::string why;
  auto add = [&why](const std::string& reason) { why += (why.empty() ? "" : "; ") + reason; };
  if (too_large.seen) {
    const InteractionSpace& s = space;
    // Too large: fully open, the moving jaw already overlaps it somewhere
    // along its length (the wedge narrows toward the fulcrum).
    const double across = m.actee().support(Eigen::Vector3d::UnitY()) + lift;
    const double along = m.actee().support(Eigen::Vector3d::UnitX()) + m.actee().support(-Eigen::Vector3d::UnitX());
    add("the jaws fully open (" + format_quantity(s.gap_from, dim::length) + " to " +
        format_quantity(s.gap_to, dim::length) + " apart along the application region) do not clear it (" +
        format_quantity(across, dim::length) + " across, " + format_quantity(along, dim::length) +
        " along the jaws) " + where(too_large));
  }
  if (out_of_reach.seen) add("the moving jaw never reaches it, even closed, " + where(out_of_reach));
  if (off_jaw.seen) add("it does not rest on the fixed jaw's face " + where(off_jaw));
  fit.why = why;
  return fit;
}

}  // namespace afford
