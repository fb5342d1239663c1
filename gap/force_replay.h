// Replay by force: the measured effort drives the model, which predicts the
// angle, when the jaws first touch the actee and when (and at what force)
// it breaks; set against what was measured.
#pragma once

#include <string>
#include <vector>

#include "measurement.h"

namespace afford {

// One event, measured and simulated; a time < 0: it did not happen.
struct EventGap {
  std::string event;          // "contact", "break"
  double measured_t = -1;     // s
  double simulated_t = -1;    // s
  double measured_force = 0;  // N, at the break (actee_force), if measured
  double simulated_force = 0;
};

struct ForceGap {
  std::string file;
  double angle_rmse = 0;          // rad, predicted against measured angle, up to the first break
  std::vector<EventGap> events;
};

// Every trace of a lever measurement, by force, through `model`.
std::vector<ForceGap> replay_force(const Model& model, const Measurement& m);

}  // namespace afford
