// When one model does not fit the traces together: the best effect fitted
// to each trace alone (in sample), to tell specimens that differ from one
// another (each alone at the floor) from a model that misses (not even
// every trace alone is), and both from a shape only the traces together
// show (each trace's nominal at the floor already).
#pragma once

#include <functional>
#include <vector>

#include "effects.h"
#include "fit.h"
#include "replay.h"

namespace afford {

struct PerTrace {
  bool computed = false;
  EffectKind effect = EffectKind::pivot_friction;
  double rmse_nominal = 0, rmse_alone = 0;  // N, every trace, each under its own fit
  double floor = 0;                         // N, the noise with the motion's through the effect
  bool nominal_at_floor = false;            // every trace's nominal within the noise's tolerance of the floor
  bool each_at_floor = false;               // every trace under its own fit within it
  std::vector<double> first_parameter;      // SI, per trace
};

// Each of `whole`'s traces fitted alone, with nothing and with each single
// effect of `library`. `on_blocks` fits the blocks of every trace;
// `floor_of` is the floor (N) of a set it fitted, `noise` (N) the floor
// where that fit fails. `computed` stays false where no effect fits.
PerTrace per_trace_fits(const Model& model, const std::vector<Replay>& whole, const std::vector<EffectKind>& library,
                        const Fitter& on_blocks, const std::function<double(const SetFit&)>& floor_of, double noise);

}  // namespace afford
