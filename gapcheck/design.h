// A withheld case's measurement design, drawn at random from its seed:
// which tool, how many traces and how each is driven and held, what is in
// the jaws, how noisy and coarse the sensors are, and what the real tool
// has beyond its file (in the library, or outside it). Two realities play
// the same designs (reality.h): MuJoCo and ODE, each with its own contact
// and friction. Nothing here or in a reality calls afford's solver, its
// torque terms, its actee law or the gap library to make data.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "jaw_contact.h"
#include "truth.h"

namespace gapcheck {

// How the hand's servo target moves between `high` and `low` (rad).
enum class DriveShape {
  sine,             // a sine of one period
  uneven_triangle,  // straight ramps, closing for `closing_share` of each period
  ramp_and_hold,    // ramp down, hold, ramp up, hold (each a quarter)
  smooth_random,    // a sine whose phase three sines of random phase, up to 3 / period Hz, speed up and slow down (`shape_seed`)
};
const char* drive_shape_name(DriveShape s);

struct Drive {
  DriveShape shape = DriveShape::sine;
  double period = 1;          // s, 0.3 to 5
  double seconds = 4;         // s, the trace's length
  double turned = 0;          // rad, the tool turned about its hinge (gravity turns with it)
  double high = 0, low = 0;   // rad, the servo target's range (high: open)
  double closing_share = 0.5; // uneven_triangle: the share of a period spent closing
  unsigned shape_seed = 0;    // smooth_random
  // closing-only strokes: the target falls from high to low and then jumps
  // back (the hand lets go and the spring reopens the tool unseen): only
  // closing is measured.
  bool closing_only = false;
  // A crack at the end: the last period closes down to this instead of `low`.
  std::optional<double> last_low;
  // The hand's servo on its own hinge, coaxial with the tool's (N*m/rad,
  // N*m*s/rad): a squeezing drive's is as stiff as the actee.
  double servo_stiffness = 10, servo_damping = 0.1;
  bool squeezes = false;      // the drive presses on the actee (else it stays clear of it)
  unsigned noise_seed = 0;    // the sensors' noise of this trace
  // The servo target at time t (rad): starts at `high`, between low and high
  // (last_low in the last period).
  double target(double t) const;
  // Whether the sample at time t is in the trace: not while a closing-only
  // stroke's hand has let go.
  bool measured(double t) const;
};

// What is between the jaws, and what happens to it.
enum class ActeeScenario {
  none,               // no actee: free drives
  light_squeeze,      // squeezed to well below its limit
  crack_first_cycle,  // cracks in the first cycle; the tool goes on opening and closing
  crack_at_end,       // cracks in the last closing of the trace
  closing_only,       // no actee, closing-only strokes
};
const char* actee_scenario_name(ActeeScenario s);

// The sensors: white noise of these deviations, then quantised to these
// steps (0: not quantised).
struct Sensors {
  double effort_noise = 0.02;   // N, 0.02 to 0.2
  double angle_noise = 1e-4;    // rad, 1e-4 to 5e-4
  double actee_noise = 0.1;     // N
  double effort_quantum = 0;    // N
  double angle_quantum = 0;     // rad
  double actee_quantum = 0;     // N
};

// Effects outside afford's library: a diagnosis must say `unexplained`.
struct Outside {
  double backlash = 0;           // rad, free play at the pivot: the arm moves this far before the spring turns
  double detent_torque = 0;      // N*m, a bump of this height ...
  double detent_angle = 0;       // rad, ... centred here ...
  double detent_width = 0;       // rad, ... this wide (a Gaussian's deviation)
  double gain_error = 0;         // the force sensor reads (1 + gain_error) times the force
  double offset_drift = 0;       // N/s, the force sensor's zero drifts by this much a second
  double viscoelastic_share = 0; // of the actee's contact force that relaxes ...
  double viscoelastic_tau = 0;   // s, ... with this time constant (a standard linear solid)
  bool any() const;
  std::string name() const;      // "backlash", "detent", "sensor_gain", "offset_drift", "viscoelastic_actee"; "" if none
};

// The hand: a mass at the emphasis on its own hinge, coaxial with the
// tool's, driven by the drive's servo, pushing the arm through a stiff
// force sensor (a spring with a little damping) whose force is the effort.
struct Hand {
  double mass = 0.05;              // kg, at effort_at
  double sensor_stiffness = 1e4;   // N*m/rad, about the hinge (the sensor's N/m times effort_at^2)
  double sensor_damping = 0.01;    // N*m*s/rad
};

// The real actee's stiffening in MuJoCo's own terms (its contact's solimp:
// the impedance d rises with the depth p from `d0` at contact to `dmax` at
// p >= `width`, along MuJoCo's sigmoid of `midpoint` and `power`). The
// MuJoCo reality sets its solref so that d = dmax gives the specimen's
// stiffness; at a depth p its contact then pushes with the specimen's
// stiffness times p times law(p) (MuJoCo's static force, solref direct:
// k d^2 p / (dmax^2 (1 - d) A) for the solref k, the contact's inverse
// weight A). d0 == dmax (the effect-free specimen): a flat impedance,
// MuJoCo's linear spring.
struct ActeeImpedance {
  double d0 = 0.9, dmax = 0.9;
  double width = 1e-3;  // m
  double midpoint = 0.5, power = 2;
  double at(double depth) const;   // d at a depth (m), as MuJoCo's getimpedance
  double law(double depth) const;  // the force's share of the linear spring's at that depth
};

// One case: a tool (its nominal file's numbers, truth.h), the truth beyond
// the file, the design.
struct Case {
  std::string name;            // unique in a set
  std::string group;           // the design group the scorer reports by: actee_scenario_name, "+turned" if several orientations
  Tool tool;                   // tool.file: the nominal object file the measurement names
  Truth truth;                 // effects of the library (labels: truth.names())
  Outside outside;             // effects outside it (label: unexplained)
  ActeeScenario scenario = ActeeScenario::none;
  std::vector<Drive> drives;   // 1 to 4 traces
  Sensors sensors;
  Hand hand;
  unsigned seed = 0;           // the case's seed: everything above is drawn from it
  // The real actee's stiffness over its shipped file's (a specimen of its
  // own): what the plates measure and the measurement's actee file says.
  double actee_specimen = 1;
  // The real actee's stiffening for the MuJoCo reality (with the library's
  // actee_compliance in the truth; else flat); truth.actee_exponent is the
  // same effect as a power law, for the ODE reality.
  ActeeImpedance actee_impedance;
  // With an actee: the moving jaw's geoms and the actee's as afford's
  // exported scene places them (jaw_contact.h), for the realities' scenes.
  JawScene jaws;
};

// One 1 kHz sample of a played drive, as the sensors read it.
struct Measured {
  double t = 0;        // s
  double angle = 0;    // rad
  double effort = 0;   // N, at the emphasis, closing positive
  double actee = 0;    // N, the load cell under the actee (0 without one)
  bool broken = false; // the actee has given way
};

// One drive of a case played by a reality (Reality::play with any noise
// seed): what a sensor's latency is sized on (design.cpp).
using PlayDrive = std::function<std::vector<Measured>(const Case&, const Drive&)>;

// Draws a case from its seed (std::mt19937): the tool (a shipped one, or a
// new geometry written into `cases_dir` as an object file), the actee and
// its scenario, the drives, the sensors, the hand and the truth. SOURCE is
// the repository (objects/, actees/, agents/). A latency is sized on the
// effort `play` gives for the case's drives, silent and effect-free.
Case draw_case(const std::filesystem::path& source, const std::filesystem::path& cases_dir, unsigned seed,
               const PlayDrive& play);

// N*m/rad: the case's actee specimen's stiffness about the hinge (0
// without an actee).
double actee_rotational_stiffness(const Case& c);

// N: the floor where the jaws press the actee: the effort's noise and the
// angle's, passed into the effort through the specimen's stiffness.
double contact_floor_of(const Case& c);

// N: the RMS change the case's effects of the library (c.truth) make in
// the effort over the samples free of the actee's contact, the case
// played with silent sensors, with them and without. Each effect, and a
// pair together, is drawn at 2 to 10 times the effort's noise there, at
// least twice it where a bound holds it back.
double library_change(const Case& c, const PlayDrive& play);

// N: the RMS change the case's actee law (truth.actee_exponent, and
// actee_impedance in MuJoCo) makes in the effort where the jaws press the
// actee before it cracks, not within 50 ms of the crack, the case played
// with silent sensors and nothing else beyond its file, with the law and
// without. Promised at twice the floor there at least (the effort's noise
// and the angle's through the specimen's stiffness).
double actee_law_change(const Case& c, const PlayDrive& play);

// N: the RMS change the case's viscoelastic actee (c.outside) makes in the
// effort where the jaws press the actee before it cracks, not within 50 ms
// of the crack, the case played with silent sensors and no effect of the
// library, with the viscoelastic actee and without. Each is promised at
// twice the floor there at least.
double viscoelastic_change(const Case& c, const PlayDrive& play);

// The label the scorer reads: the true names joined by '+', sorted;
// "none"; or "outside:NAME".
std::string label_of(const Case& c);

}  // namespace gapcheck
