// The squeeze a grip needs for a force: keyframes written as "squeeze
// until the actee's force is F" or "until the effort is F" (script.h), and
// explore's points. The lever is settled under the effort with every term
// a frame has (forced_lever.h: spring, actee, friction, gravity, limits);
// the hand pushes force_gain times the thumb's travel past the arm, so the
// thumb goes effort / force_gain further than the arm.
#pragma once

#include <string>

#include "forced_lever.h"
#include "model.h"

namespace afford {

// The lever as the model starts: its actee between the jaws if it is one,
// the tool's pose for gravity. The effort's distance is set per grip.
ForcedLever lever_at_start(const Model& m);

// Where the arm comes to rest under `effort_n` at the thumb's distance.
ForcedStep settle_under_effort(const Model& m, const ForcedLever& lever, double thumb_m, double effort_n);

// The thumb's advance past the rest angle (m) at which the hand pushes
// `effort_n` once the arm has settled.
double squeeze_for_effort(const Model& m, const ForcedLever& lever, double thumb_m, double effort_n);

// The inverse: the effort (N) the hand settles at for a squeeze of
// `squeeze_m`, at most `cap_n` (where the hand can push no harder).
double effort_for_squeeze(const Model& m, const ForcedLever& lever, double thumb_m, double squeeze_m, double cap_n);

// The effort (N) under which the actee's force settles at `force_n`, at
// most `cap_n` (the hand's, or its grasp's, largest). False, with `why`
// naming the numbers, when no effort up to the cap reaches it, when the
// actee breaks first, or when no actee lies between the jaws.
bool effort_for_actee_force(const Model& m, const ForcedLever& lever, double thumb_m, double force_n, double cap_n,
                            double* effort_n, std::string* why);

}  // namespace afford
