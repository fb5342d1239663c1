// What a model implies without running it: the interaction space, the
// mechanical advantage along the arm, which actees fit, spring forces.
// Used by `afford describe` and by the guides.
#pragma once

#include <string>
#include <vector>

#include "model.h"
#include "terms.h"

namespace afford {

// The interaction space L_is: the wedge between the jaws over the
// application region, opened to theta_max.
struct InteractionSpace {
  double from = 0, to = 0;          // m, signed distances along the fixed arm
  double gap_from = 0, gap_to = 0;  // m, jaw opening (perpendicular) at theta_max at each end
};
InteractionSpace interaction_space(const Model& m);

// Effort force (N) at signed emphasis distance effort_m that holds the lever
// at theta with a load of load_n newtons at load_m (moment balance, no
// friction or motion terms).
double effort_for_load(const Model& m, double theta_rad, double effort_m, double load_m, double load_n);

// How an actee fits the jaws: resting on the fixed jaw anywhere in the
// application region, can the moving jaw close on it?
struct ActeeFit {
  std::string name;
  bool fits = false;
  double from = 0, to = 0;        // m, the part of the application region where it fits
  double contact_angle = 0;       // rad, where the jaws touch it, at `from`
  double effort_to_limit = 0;     // N, effort at the far end of the emphasis to reach its limit, at `from`
  std::string why;                // when it does not fit
};
// `model` must be compiled with this actee (placement irrelevant).
ActeeFit fit_actee(const Model& model);

}  // namespace afford
