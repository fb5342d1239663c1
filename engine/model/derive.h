// What a model implies without running it: the interaction space, the
// mechanical advantage along the arm, which actees fit, spring forces.
// Used by `afford describe` and by the guides.
#pragma once

#include <string>
#include <vector>

#include "model.h"
#include "terms.h"

namespace afford {

// The interaction space L_is: where between the jaws an actee of which size
// fits. From the object's interaction_space table when it has one (the
// real shape, afford model): the gap fully open at each distance, linear
// between them. Else the wedge of flat jaw faces through the pivot over the
// application region, |r| sin(theta_max) wide.
struct InteractionSpace {
  double from = 0, to = 0;          // m, signed distances along the fixed arm
  double gap_from = 0, gap_to = 0;  // m, jaw opening (perpendicular) at theta_max at each end
  bool from_shape = false;          // the object's table (true) or the wedge
  std::vector<double> distances;    // m, the table's distances (from_shape)
  std::vector<double> gaps;         // m, its gaps at theta_max (from_shape)
};
InteractionSpace interaction_space(const Model& m);

// The jaws' gap fully open (m) at signed distance r (m) in [s.from, s.to]:
// the table's, linear between its distances, or the wedge's |r| sin(theta_max).
double gap_at(const Model& m, const InteractionSpace& s, double r);

// The thickest actee (m, across the jaws) that rests on the fixed jaw's face
// at r and clears the jaws fully open. The moving jaw there is taken as the
// straight face g from the face's point at r that tilts by alpha to it,
// sin alpha = |dg/dr| (the table's slope there): a ball resting at r clears
// it while its diameter is at most 2 g / (1 + cos alpha). For flat faces
// through the pivot that is the wedge's inscribed ball, 2 |r| tan(theta_max / 2).
double clearance_at(const Model& m, const InteractionSpace& s, double r);

// Effort force (N) at signed emphasis distance effort_m that holds the lever
// at theta with a load of load_n newtons at load_m (moment balance, no
// friction or motion terms).
double effort_for_load(const Model& m, double theta_rad, double effort_m, double load_m, double load_n);

// How an actee fits the jaws: resting on the fixed jaw anywhere in the
// interaction space, can the moving jaw close on it? With a table from the
// shape an actee thicker across the jaws than clearance_at a distance does
// not fit there; where it fits, the parts say where the jaws touch it.
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
