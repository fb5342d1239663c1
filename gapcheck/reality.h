// A reality plays a case's drives: a physics engine other than afford
// (MuJoCo, ODE), with its own joint friction that sticks, a hand with mass
// pushing through a force sensor at the emphasis, and the actee as the
// engine's own contact. Each engine also measures an actee as an
// experimenter would, squeezed between two plates, so that the nominal
// actee file the diagnosis reads holds the law that engine's contact has.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "design.h"

namespace gapcheck {

// An actee as measured between plates: the curve of force against the
// crosshead's travel since the plates touched it, up to its limit, and
// the law an experimenter fits to it (plates_fit.h). Where `deflection`
// is empty the reality gives only `stiffness`, the linear law's K, and
// the actee file takes that.
struct PlatesLaw {
  std::vector<double> deflection;  // m
  std::vector<double> force;       // N
  double stiffness = 0;  // N/m, the law fitted (plates_fit.h's K where the curve is given)
  double rms_misfit = 0; // N, of that law over the measured points
};

class Reality {
 public:
  virtual ~Reality() = default;
  virtual const char* name() const = 0;  // "mujoco", "ode"
  // One drive of a case at 1 kHz, with the case's sensors' noise from
  // `noise_seed` (fixed seed: the same samples every time).
  virtual std::vector<Measured> play(const Case& c, const Drive& drive, unsigned noise_seed) const = 0;
  // The case's actee (its shape from tool.actee->file, scaled by the
  // engine's own contact parameters for this case) squeezed between
  // plates in this engine, read as a testing machine would.
  virtual PlatesLaw plates(const Case& c) const = 0;
};

// mujoco_reality.cpp and ode_reality.cpp.
std::unique_ptr<Reality> make_mujoco_reality();
std::unique_ptr<Reality> make_ode_reality();

}  // namespace gapcheck
