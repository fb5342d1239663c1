#include "derive.h"

#include <cmath>

#include "stages.h"

namespace afford {

InteractionSpace interaction_space(const Model& m) {
  InteractionSpace s;
  s.from = m.application_from;
  s.to = m.application_to;
  s.gap_from = std::abs(s.from) * std::sin(m.theta_max);
  s.gap_to = std::abs(s.to) * std::sin(m.theta_max);
  return s;
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
  bool found = false;
  for (int i = 0; i <= kSteps; ++i) {
    const double r = m.application_from + (m.application_to - m.application_from) * i / kSteps;
    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
    at.translation() = Eigen::Vector3d(r, lift, 0);
    double theta_c = 0;
    if (find_contact_angle(m, at, query, &theta_c, nullptr) != JawFit::fits) continue;
    if (!found) {
      found = true;
      fit.from = r;
      fit.contact_angle = theta_c;
      const double far = std::abs(m.emphasis_to) > std::abs(m.emphasis_from) ? m.emphasis_to : m.emphasis_from;
      fit.effort_to_limit = effort_for_load(m, theta_c, far, r, m.actee_limit);
    }
    fit.to = r;
  }
  fit.fits = found;
  if (!found) {
    const InteractionSpace s = interaction_space(m);
    fit.why = "its thickness across the jaws (" +
              format_quantity(m.actee().support(Eigen::Vector3d::UnitY()) +
                                  m.actee().support(-Eigen::Vector3d::UnitY()),
                              dim::length) +
              ") exceeds the opening (" + format_quantity(s.gap_from, dim::length) + " to " +
              format_quantity(s.gap_to, dim::length) + ")";
  }
  return fit;
}

}  // namespace afford
