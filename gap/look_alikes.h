// Before an effect is named: can the fitted samples tell it from the
// other candidates at all? Two effects whose columns (as the fit weighs
// them, with the other named effects' taken out) are all but parallel fit
// any data equally well: closing-only strokes make friction a constant
// torque, as a preload is; one orientation makes the arm's weight all but
// one; one sine at one speed makes a late sensor read as damping.
#pragma once

#include <string>
#include <vector>

#include "fit.h"

namespace afford {

struct LookAlike {
  EffectKind chosen = EffectKind::pivot_friction;  // named by the selection
  EffectKind alike = EffectKind::pivot_friction;   // a candidate the data cannot tell from it
  double cosine = 0;                               // of their columns, 0..1
  std::string separate;                            // the measurement that would tell them apart
  std::string out_of_range;  // where physics tells them apart: the value the look-alike would need ("" if none)
  // Where the held-out samples tell them apart, though their columns are
  // all but parallel: how the look-alike in the chosen effect's place
  // predicts them ("" where they do not).
  std::string told_apart;
};

// Every candidate of `library` outside `chosen` whose column, and the
// chosen one's, the other chosen effects leave at a cosine of at least
// kLookAlike (look_alikes.cpp).
std::vector<LookAlike> look_alikes(const Fitter& fitter, const std::vector<EffectKind>& chosen,
                                   const std::vector<EffectKind>& library);

// Whether effect k's column lies, at a cosine of at least kLookAlike, in
// the span of `others`' columns: added to them it can only trade large
// opposite values with them (a weight and a preload one way up), never
// tell the data anything they do not. False for the actee's law, which has
// no column over every sample.
bool adds_nothing_to(const Fitter& fitter, EffectKind k, const std::vector<EffectKind>& others);

// Physics tells what the data cannot. `swapped` is the fit with the
// look-alike in the chosen effect's place: it stands in alone only where
// every value lies within its physical range by `sigmas` standard errors
// and its own change lies clear of zero by as many (a search stopped at
// its range's edge, a delay at 0 s, takes no part). Where it cannot, a
// share of it beside the chosen effect still may where its file value has
// room to move its way. Sets l.out_of_range to what it would need.
struct Standing {
  bool alone = true;   // it may stand in for the chosen effect
  bool beside = true;  // a share of it beside the chosen effect may
};
Standing standing_in(LookAlike& l, const SetFit& swapped, const Model& nominal, double sigmas);

// "the data cannot tell gravity from spring_preload[, nor from both]
// (cosine 0.9997); to tell them apart: turn the tool ...", or where
// physics rules the look-alike out, ", but spring_preload would need
// ...", or where the held-out samples tell them apart, "the held-out
// samples tell gravity from spring_preload (cosine 0.9993; ...)[, not
// from both; ...]": one line of the report and of the selection's steps.
std::string look_alike_text(const LookAlike& l, bool both);

}  // namespace afford
