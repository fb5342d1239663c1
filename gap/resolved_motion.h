// Which samples' rates are the motion's. The narrow polynomial
// (derivatives.h) cannot follow a ringing, a snap or a kink of the
// motion; there the rates are not the motion's, and the samples are left
// out of every fit (Phase::unresolved), unless a plainer window follows
// the motion where the narrow one cannot.
#pragma once

#include <vector>

#include "derivatives.h"
#include "replay.h"

namespace afford {

// The samples whose rates are not the motion's: the narrow window
// leaves more than twice what the noise alone would over it, in the angle
// or in the effort (`effort_left`: the measured effort less what the
// nominal model predicts from the angle alone, N; `effort_variance`: its
// noise, N^2, sample by sample), each misfit spread over its window; its
// window reaches across the break; or a free sample's window reaches
// into the actee's contact (resolved_motion.cpp says why). `d` is the
// narrow window's fit of r.x, whose rates r holds.
// Where the narrow window misfits, a plainer one may follow: strokes
// that start and stop every 0.1 s put a kink of the angle within 25 ms
// of every sample, each misfit spread over its window, and no sample was
// left (development seed 8920, a press stroking between its stops after
// the crack, ODE). A line's bend (degree 2) over +-10 ms passes about as
// much of the angle's noise as the narrow window and follows even speeds
// and accelerations between the kinks. Where it follows the motion, its
// rates replace r's (and their noise), but only where its rate is no
// noisier than the one it replaces: beside a slow turn, where the rate
// had taken the +-200 ms window, twenty times as wide, the plain window's
// rate passed 0.2 N of the angle's noise on through a damping the file
// lacked, ten times the sensor's, and a late sensor was named to dodge it
// (tested).
std::vector<bool> unresolved(const Derivatives& d, Replay& r, const std::vector<double>& effort_left,
                             const std::vector<double>& effort_variance);

}  // namespace afford
