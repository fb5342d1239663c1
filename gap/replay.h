// Kinematic replay: the measured motion drives the nominal model, which
// says what effort (lever) or force (plates) it needs at every sample; the
// difference from the measured one is the gap. Each candidate effect adds a
// torque (or force) along the same samples: its regressor.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "measurement.h"

namespace afford {

// Where a sample lies, from the model's own state along the trace.
// `unresolved`: motion faster than the samples resolve (a ringing, a snap,
// a derivative window across the break, a free sample's window reaching
// into the actee's contact), where the rates are not the motion's.
// `after_break` is the snap as the actee gives way, until the motion
// settles; after it the tool is replayed as a tool without an actee.
enum class Phase { free_closing, free_opening, reversal, loading, unloading, at_rest, at_limit, after_break, unresolved };
inline constexpr int kPhases = 9;
const char* phase_name(Phase p);

// One trace replayed. For a lever the main signal is the torque about the
// fulcrum, N*m (the effort times its lever arm); for plates the force, N.
struct Replay {
  std::string file;
  double turned = 0;             // rad, the tool turned about its hinge (Trace::turned)
  std::vector<double> t;         // s
  std::vector<double> x;         // rad (lever angle) or m (plate displacement)
  std::vector<double> rate;      // rad/s or m/s
  std::vector<double> accel;     // rad/s^2 or m/s^2
  std::vector<double> measured;  // N*m or N
  std::vector<double> nominal;   // the nominal model's prediction, same unit
  std::vector<double> deflection;  // m, the actee's, from the model (0 without contact)
  std::vector<double> actee_measured, actee_nominal;  // N, lever with an actee_force column; else empty
  std::vector<Phase> phase;
  std::vector<bool> fitted;      // used in fits and scores: not at a limit, not in the break's snap, resolved
  // Fitted only as squeezed and all but still: the file's friction band
  // is small there against the noise the actee passes on (release_held()).
  std::vector<bool> held;
  // d nominal / d x at each sample (N*m/rad or N/m): how much of the
  // motion sensor's noise the prediction takes on there (a stiff actee's
  // contact passes it on many times over).
  std::vector<double> slope;
  // Each sample's weight in fits and scores (weigh(); 1 until then): 1
  // where the effort sensor's noise is all the noise, less where the
  // motion's adds to it.
  std::vector<double> weight;
  // The motion sensor's noise (deviation, from x's second differences) and
  // what the differentiation makes of it, sample by sample (each sample's
  // window is the data's choice: smooth_derivative.h), in the rate and in
  // the acceleration.
  double x_noise = 0;
  double step = 0;  // s, the sampling step, time gaps left out (sample_step)
  std::vector<double> rate_noise, accel_noise;
  // kg*m^2: the nominal arm's inertia, through which the acceleration's
  // noise reaches the prediction (0 between plates).
  double inertia = 0;
  // The main signal's printed resolution (trace.h's, in N at the effort):
  // the least noise a measurement can have.
  double resolution = 0;
  size_t break_at = SIZE_MAX;    // the sample at which the actee gave way (SIZE_MAX: it did not)
  // A block of a trace (diagnose.cpp) starts with the samples before it
  // that a late force sensor still reads there: never fitted, judged or
  // counted. 0 for a whole trace.
  size_t history = 0;
  Rig rig = Rig::lever;
  double to_newtons = 1;         // 1 / lever arm (lever) or 1: main signal to N at the effort
};

// s: the longest sensor delay a fit searches; the snap as an actee breaks
// is left out that much longer, since a late sensor reads it then.
inline constexpr double kLongestDelay = 0.1;

// Replays every trace of a lever measurement through `model` (compiled from
// it, with or without candidate effects switched on).
std::vector<Replay> replay_lever(const Model& model, const Measurement& m);

// Replays every trace of a plates measurement: the actee's law at the
// measured displacement (the actee compiled with no tool).
std::vector<Replay> replay_plates(const Model& actee_model, const Measurement& m);

// Weights of generalised least squares: a sample's weight is the effort
// sensor's noise variance over its whole noise variance, the sensor's
// (`noise`, N) plus the motion's through the model's slope. Its unit is
// the effort sensor's: a weighted RMSE of pure noise is `noise` where the
// motion adds nothing. Where a sensor may read `delay` s late, the
// motion's noise is the larger of the model's at the sample and `delay`
// before it, where a late set predicts the reading from.
void weigh(std::vector<Replay>& replays, double noise, double delay = 0);

// A sensor `delay` s late reads at each sample the effort of an earlier
// one. Where that earlier time lies where the model predicts nothing (at
// rest, in a reversal, at a limit, in the snap, before the trace or a time
// gap), the sample is left out of fits and scores too: a late sensor's
// reading there is as indeterminate as friction at rest.
void leave_out_late_readings(std::vector<Replay>& replays, double delay);

// A squeezed sample all but still is fitted where friction's band is a
// small share of the noise the actee's stiffness passes on from the
// angle; the file's friction decides that at the replay. Where the tool's
// friction as the data shows it (`friction`, N*m about the hinge, a fit's)
// is not small there, such a sample is as indeterminate as one at rest,
// and is left out: at the turn of a squeeze the effort may take any value
// within the band.
void release_held(std::vector<Replay>& replays, double friction);

// y (sampled at the increasing times t) at time `at`: linear between
// samples, held before the first and after the last.
double value_at(const std::vector<double>& t, const std::vector<double>& y, double at);

// y as a sensor `delay` s late reads it: value_at(t, y, t[i] - delay) at
// every sample, in linear time. `step` is sample_step(t) (derivatives.h),
// kept with a Replay as its `step`.
std::vector<double> delayed(const std::vector<double>& t, const std::vector<double>& y, double delay, double step);

// The same, for a prediction carrying the angle's noise (a fit's columns):
// between evenly spaced samples by a four-point stencil, exact for a line,
// that passes white noise at its own variance. Linear interpolation
// averages two samples' noise (half its variance at half a sample), so a
// fraction of a sample's delay would cut the noise a stiff actee passes
// from the angle into the prediction, and read as a late sensor.
std::vector<double> delayed_keeping_noise(const std::vector<double>& t, const std::vector<double>& y, double delay,
                                          double step);

// The direction of motion, smoothed over a small speed so that a fit's
// friction term is continuous (rad/s in, -1..1 out).
double smooth_sign(double rate);

// Where the actee sits: its lever arm (m; 1 between plates, where the main
// signal is its force) and its thickness across the jaws or plates (m).
struct ActeeGeometry {
  double arm = 1;
  double thickness = 0;
};
ActeeGeometry actee_geometry(const Model& model, Rig rig);

// The actee's torque (lever) or force (plates) at each sample, with the
// power law of exponent n and reference deflection r (for the
// actee_compliance candidate). `zero_m`: where the law starts, the
// deflection it is taken from (a specimen seated later than its trace's
// zero).
std::vector<double> actee_term(const Model& model, const Replay& r, const ActeeGeometry& g, double exponent,
                               double reference, double zero_m = 0);

}  // namespace afford
