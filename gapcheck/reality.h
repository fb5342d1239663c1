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

// An actee's law as measured between plates: the linear stiffness that
// fits force against deflection up to its limit, least squares through 0.
struct PlatesLaw {
  double stiffness = 0;  // N/m
  double rms_misfit = 0; // N, of the straight line over the measured points
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
