// A force sensor that reads late: its readings after a stretch the model
// cannot predict (a rest, a reversal, a limit, the break's snap, before
// the trace) read what happened there, as indeterminate as friction at
// rest, and are left out for every candidate set alike.
#pragma once

#include <functional>
#include <vector>

#include "effects.h"
#include "fit.h"
#include "replay.h"

namespace afford {

// The sensor's delay fitted on `whole` (with friction, an arm's inertia
// and, where the delay comes out under a sampling step, a damping beside
// it, each where `asked`), the fit repeated on the readings the delay
// leaves in until it holds; those late readings are left out of `whole`.
// Returns the delay (s; 0 where none is left out: a delay that would
// leave too few readings for two blocks leaves them all in).
double late_readings_left_out(const Model& model, std::vector<Replay>& whole,
                              const std::function<bool(EffectKind)>& asked);

}  // namespace afford
