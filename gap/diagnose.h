// The sim-to-real gap diagnosis of one measurement: where the nominal model
// misses (phases), which effect of the library explains it (forward
// selection on held-out error and AICc), how far the gap shrinks on data
// the fit never saw, and whether what is left has structure.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "fit.h"
#include "look_alikes.h"
#include "force_replay.h"
#include "measurement.h"
#include "per_trace.h"
#include "phases.h"
#include "replay.h"
#include "residual_tests.h"
#include "specimens.h"
#include "turn_impulse.h"

namespace afford {

enum class Verdict { none, explained, ambiguous, unexplained };
const char* verdict_name(Verdict v);

// Whether two sets hold the same effects, whatever their order.
bool same_effects(std::vector<EffectKind> a, std::vector<EffectKind> b);

// One judged trace as the plots draw it: the main signal measured, as the
// nominal model predicts it, and as the effects fitted on the other traces
// predict it (held out), in N at the effort (lever) or between the plates;
// NaN where a sample is not fitted (at a limit, after the break, ...).
struct HeldOutCurve {
  std::string file;
  std::vector<double> t;  // s
  std::vector<double> x;  // rad (lever angle) or m (plate displacement)
  std::vector<double> measured, nominal, fitted;  // N
  std::vector<Phase> phase;
};

// One fold of the cross-validation: how many blocks of the traces it
// judges, and how many fitted samples they hold.
struct FoldSize {
  size_t blocks = 0, fitted = 0;
};

struct Diagnosis {
  std::string measurement;
  Verdict verdict = Verdict::none;
  std::vector<EffectFit> effects;                  // the effects adopted
  std::vector<std::vector<EffectKind>> ambiguous;  // sets that fit as well, when ambiguous
  std::vector<LookAlike> look_alikes;              // what the data cannot tell the named effects from
  // The force sensor's gain error (outside the library) that explains the
  // gap as well as the effects fitted, which are then not named: the
  // relative error of its reading (+0.06: 6 % high); NaN when told apart.
  double gain_alike = std::numeric_limits<double>::quiet_NaN();
  // With gain_alike: whether the effects fitted would have explained the
  // gap (to the noise's tolerance, or white, ...) but for the gain. Then
  // what is unexplained is which of the two, not what is left.
  bool gain_alike_explains = false;
  double noise = 0;                                // N, the measurement's own noise, estimated
  double noise_through_model = 0;                  // N, with the motion's noise through the adopted model
  double rmse_before = 0, rmse_after = 0;          // N, on the held-out traces
  double shrink = 0;                               // 1 - after / before, held out, where the gap is the larger (below)
  // In the actee's contact, where there is one: the held-out RMSE with each
  // sample's error scaled to the effort sensor's noise (times the root of
  // its weight: pure noise gives the sensor's noise), N, before and after.
  size_t contact_samples = 0;
  double contact_before = 0, contact_after = 0;
  // `shrink` is measured where the gap is the larger against the noise
  // (both in the sensor's units): over every sample, or in the contact.
  bool shrink_in_contact = false;
  std::vector<PhaseShare> phases;
  std::string where;                               // one sentence
  ResidualTest residual;
  // The residual out of the actee's contact, where it was asked whether a
  // shape lies in the contact only (`computed` false where it was not).
  struct OutOfContact {
    bool computed = false;
    ResidualTest test;
  } out_of_contact;
  // Lever: what the turns, left out of every fit, say of an arm's inertia
  // beyond the adopted model's (turn_impulse.h), named where the fits saw none.
  TurnImpulse turns;
  PerTrace per_trace;                              // with an unexplained verdict over several traces
  SpecimenShape specimens;                         // and there, when each trace alone wants the actee's power law
  std::vector<ForceGap> by_force_before, by_force_after;  // lever: replayed by force, nominal and fitted
  std::vector<std::string> judged_on;              // the blocks of the traces (gap/README.md), each judged
  size_t folds = 0;                                // by a fit on the blocks outside its fold
  std::vector<FoldSize> fold_sizes;                // per fold
  size_t traces = 0;                               // the measurement's
  std::vector<std::string> steps;                  // the selection, step by step
  Rig rig = Rig::lever;
  std::vector<HeldOutCurve> curves;                // every judged trace, for the plots
};

struct DiagnoseOptions {
  std::vector<EffectKind> library;  // the candidates; empty: every one that applies
};

Diagnosis diagnose(const Measurement& m, const DiagnoseOptions& options = {});

// The measurement with the fitted effects among its own, and its model.
Measurement with_effects(const Measurement& m, const std::vector<EffectFit>& effects);
Model compile_with(const Measurement& m, const std::vector<EffectFit>& effects);

}  // namespace afford
