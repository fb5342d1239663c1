// The sim-to-real gap diagnosis: measurement files and traces (every
// mistake located), and the diagnosis on traces made here with a known
// hidden effect. The traces are written by formulas in this file, not by
// the solver; the withheld check against an independent simulator is the
// bench's.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "counted_step.h"
#include "derivatives.h"
#include "diagnose.h"
#include "load.h"
#include "patch.h"
#include "plots.h"
#include "png.h"
#include "probe.h"
#include "state.h"
#include "replay.h"
#include "report.h"
#include "test_util.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;


// A fresh folder for one test's files.
void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

// What the hidden truth adds to the nutcracker's nominal torque, N*m.
struct Hidden {
  double friction = 0;   // N*m, Coulomb (an exact sign)
  double damping = 0;    // N*m*s/rad
  double inertia = 0;    // kg*m^2
  double weight = 0;     // N*m, an unmodelled weight's torque amplitude: -weight * cos(theta + turned)
  double angle_noise = 0;  // rad, the angle sensor's
};

// The shipped nutcracker (2000 N/m at 10 mm, 1.5 N preload, 0.01 N*m
// friction) driven through 10 cycles of a 1 Hz sine between 8 and 28 deg,
// measured at 160 mm at 1 kHz with 0.02 N of sensor noise; the effort by
// moment balance written out here.
std::string lever_trace(const Hidden& h, unsigned seed, double turned = 0) {
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, 0.02), angle_noise(0.0, h.angle_noise > 0 ? h.angle_noise : 1.0);
  std::string csv = "t,angle,effort_force,actee_force\n";
  const double k = 2000, sp = 0.010, rest = 30 * kPi / 180, b = 0.160;
  for (int i = 0; i < 10000; ++i) {
    const double t = i * 1e-3;
    const double w = 2 * kPi;
    const double theta = (18 + 10 * std::sin(w * t)) * kPi / 180;
    const double omega = 10 * kPi / 180 * w * std::cos(w * t);
    const double alpha = -10 * kPi / 180 * w * w * std::sin(w * t);
    const double spring = k * sp * (rest - theta) * sp + 1.5 * sp;
    const double sign = omega > 0 ? 1.0 : (omega < 0 ? -1.0 : 0.0);
    const double torque = spring - (0.01 + h.friction) * sign - h.damping * omega - h.inertia * alpha -
                          h.weight * std::cos(theta + turned);
    const double measured_theta = theta + (h.angle_noise > 0 ? angle_noise(random) : 0.0);
    char row[128];
    std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f,0\n", t, measured_theta, torque / b + noise(random));
    csv += row;
  }
  return csv;
}

fs::path lever_measurement(const std::string& name, const Hidden& h) {
  const fs::path dir = test::fresh_dir("gap", name);
  write(dir / "a.csv", lever_trace(h, 1));
  write(dir / "b.csv", lever_trace(h, 2));
  write(dir / "m.yaml", "measurement: " + name + "\nobject: " + kSource +
                            "/objects/nutcracker.yaml\neffort_at: 160 mm\ntraces: [a.csv, b.csv]\n");
  return dir / "m.yaml";
}

// Two traces, the second with the tool upside down (turned 180 deg).
fs::path turned_measurement(const std::string& name, const Hidden& h) {
  const fs::path dir = test::fresh_dir("gap", name);
  write(dir / "a.csv", lever_trace(h, 1));
  write(dir / "b.csv", lever_trace(h, 2, kPi));
  write(dir / "m.yaml", "measurement: " + name + "\nobject: " + kSource +
                            "/objects/nutcracker.yaml\neffort_at: 160 mm\n"
                            "traces: [a.csv, {file: b.csv, turned: 180 deg}]\n");
  return dir / "m.yaml";
}

const EffectFit* find(const Diagnosis& d, EffectKind k) {
  for (const EffectFit& e : d.effects) {
    if (e.kind == k) return &e;
  }
  return nullptr;
}

// Every effect of the library but `k`.
DiagnoseOptions every_effect_but(EffectKind k) {
  DiagnoseOptions options;
  for (const EffectManifest& e : effect_registry()) {
    if (e.kind != k) options.library.push_back(e.kind);
  }
  return options;
}

// Unexplained over two traces that `effect`, fitted to each alone, takes
// to the floor where their nominal was not: the traces differ.
void expect_two_traces_differ(const Diagnosis& d, EffectKind effect) {
  EXPECT_EQ(d.verdict, Verdict::unexplained) << report_text(d);
  const PerTrace& p = d.per_trace;
  ASSERT_TRUE(p.computed) << report_text(d);
  EXPECT_EQ(p.effect, effect) << report_text(d);
  EXPECT_FALSE(p.nominal_at_floor);
  EXPECT_TRUE(p.each_at_floor) << report_text(d);
  ASSERT_EQ(p.first_parameter.size(), 2u);
  EXPECT_THAT(report_text(d), HasSubstr("the traces differ from one another more than one model allows"));
}

// An effect a verdict must name, its first parameter and how near it must come.
struct Named {
  EffectKind kind;
  double value;
  double tolerance;
};

// `explained` with exactly `truth`, each sized within its tolerance.
void expect_explained_by(const Diagnosis& d, const std::vector<Named>& truth) {
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);
  ASSERT_EQ(d.effects.size(), truth.size()) << report_text(d);
  for (const Named& n : truth) {
    const EffectFit* e = find(d, n.kind);
    ASSERT_NE(e, nullptr) << report_text(d);
    EXPECT_NEAR(e->value[0], n.value, n.tolerance) << report_text(d);
  }
}

TEST(Gap, AnEffectFreeMeasurementIsNone) {
  const Diagnosis d = diagnose(load_measurement(lever_measurement("none", {}).string()));
  EXPECT_EQ(d.verdict, Verdict::none) << report_text(d);
  EXPECT_TRUE(d.effects.empty());
  EXPECT_NEAR(d.noise, 0.02, 0.004);  // estimated from the trace alone
}

TEST(Gap, HiddenFrictionIsNamedAndSized) {
  // 0.3 N*m more friction: the effort loop is 2 * 0.31 / 0.16 = 3.9 N wide.
  const Diagnosis d = diagnose(load_measurement(lever_measurement("friction", {0.3, 0, 0}).string()));
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);
  ASSERT_EQ(d.effects.size(), 1u) << report_text(d);
  const EffectFit* f = find(d, EffectKind::pivot_friction);
  ASSERT_NE(f, nullptr);
  EXPECT_NEAR(f->value[0], 0.31, 0.01);  // the nominal 0.01 plus the hidden 0.3
  EXPECT_GT(d.shrink, 0.8);
  EXPECT_LT(d.rmse_after, 1.3 * 0.02);
  // Where: it changes sign with the direction of motion.
  EXPECT_EQ(d.residual.follows.empty(), false);
  EXPECT_THAT(d.where, HasSubstr("the direction of motion"));
}

// With the nutcracker's linear spring and no inertia, a sensor tau late
// reads -tau k omega more: exactly a damping of tau k. One sine (the
// samples away from its reversals) cannot tell them apart: ambiguous,
// and the report says so.
TEST(Gap, HiddenDampingIsNamedAndNoLateSensorStandsInForIt) {
  // On one sine a late sensor's column is the damping's, but of the other
  // sign: it reads the spring's force of tau ago, k s^2 omega tau over the
  // effort, where a damping adds -c omega. Standing in for 0.05
  // N*m*s/rad it would need a negative delay; its search stops at 0 s.
  const Diagnosis d = diagnose(load_measurement(lever_measurement("damping", {0, 0.05, 0}).string()));
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);
  const EffectFit* f = find(d, EffectKind::viscous_damping);
  ASSERT_NE(f, nullptr) << report_text(d);
  EXPECT_NEAR(f->value[0], 0.05, 0.005);
  ASSERT_EQ(d.look_alikes.size(), 1u) << report_text(d);
  EXPECT_EQ(d.look_alikes[0].alike, EffectKind::sensor_latency);
  EXPECT_GT(d.look_alikes[0].cosine, 0.999);
  EXPECT_THAT(d.look_alikes[0].out_of_range, HasSubstr("sensor_latency")) << report_text(d);
  EXPECT_TRUE(d.ambiguous.empty()) << report_text(d);
}

TEST(Gap, TwoHiddenEffectsAreBothFound) {
  const Diagnosis d = diagnose(load_measurement(lever_measurement("pair", {0.3, 0.05, 0}).string()));
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);  // no late sensor for the damping, as above
  EXPECT_NE(find(d, EffectKind::pivot_friction), nullptr) << report_text(d);
  EXPECT_NE(find(d, EffectKind::viscous_damping), nullptr) << report_text(d);
}

TEST(Gap, WithoutTheTrueEffectInTheLibraryItSaysUnexplained) {
  DiagnoseOptions options;
  options.library = {EffectKind::viscous_damping, EffectKind::spring_preload, EffectKind::progressive_spring,
                     EffectKind::arm_inertia, EffectKind::gravity, EffectKind::sensor_latency};
  const Diagnosis d = diagnose(load_measurement(lever_measurement("withheld", {0.3, 0, 0}).string()), options);
  EXPECT_EQ(d.verdict, Verdict::unexplained) << report_text(d);
  EXPECT_FALSE(d.residual.white);
  const std::string json = report_json(d);
  EXPECT_THAT(json, HasSubstr("\"verdict\":\"unexplained\""));
  // Fitted to each trace alone, no effect left takes up friction's square
  // wave either: the model misses, the traces do not differ.
  ASSERT_TRUE(d.per_trace.computed) << report_text(d);
  EXPECT_FALSE(d.per_trace.nominal_at_floor);
  EXPECT_FALSE(d.per_trace.each_at_floor) << report_text(d);
  EXPECT_GT(d.per_trace.rmse_alone, 1.15 * d.per_trace.floor) << report_text(d);
  EXPECT_THAT(report_text(d), HasSubstr("no one effect of the library explains every trace even alone"));
  EXPECT_THAT(json, HasSubstr("\"nominal_at_floor\":false,\"each_at_floor\":false"));
}

TEST(Gap, ASmallEffectAtTheNoiseButPlainInShapeIsNamed) {
  // 0.0013 N*m more friction: a square wave of 0.0081 N at the effort,
  // which lifts the RMSE to 1.08 times the 0.02 N of noise, within the
  // noise estimate's tolerance (1.15). Over 20,000 samples its shape is
  // plain (the residual is far from white), so it is looked for and named;
  // without friction in the library, nothing explains it.
  const fs::path file = lever_measurement("small", {0.0013, 0, 0});
  const Diagnosis d = diagnose(load_measurement(file.string()));
  EXPECT_GT(d.rmse_before, 0.02);
  EXPECT_LT(d.rmse_before, 1.15 * d.noise_through_model) << report_text(d);
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);
  const EffectFit* f = find(d, EffectKind::pivot_friction);
  ASSERT_NE(f, nullptr) << report_text(d);
  EXPECT_NEAR(f->value[0], 0.0113, 0.0005);  // the nominal 0.01 plus the hidden 0.0013
  DiagnoseOptions options;
  options.library = {EffectKind::viscous_damping, EffectKind::spring_preload, EffectKind::progressive_spring,
                     EffectKind::arm_inertia, EffectKind::gravity, EffectKind::sensor_latency};
  const Diagnosis withheld = diagnose(load_measurement(file.string()), options);
  EXPECT_EQ(withheld.verdict, Verdict::unexplained) << report_text(withheld);
  // Each trace's nominal is within the tolerance already: what is left is
  // a shape the 20,000 samples together show, not traces that differ.
  ASSERT_TRUE(withheld.per_trace.computed) << report_text(withheld);
  EXPECT_TRUE(withheld.per_trace.nominal_at_floor) << report_text(withheld);
  EXPECT_THAT(report_text(withheld), HasSubstr("the gap is a shape only the traces together show"));
}

TEST(Gap, TurningTheToolTellsItsWeightFromThePreload) {
  // 0.1 N*m of unmodelled weight (0.6 N at the effort), the tool held one
  // way up and then the other: the weight's torque changes sign, a
  // preload's would not.
  const Hidden weight{0, 0, 0, 0.1, 0};
  const Measurement m = load_measurement(turned_measurement("turned", weight).string());
  ASSERT_EQ(m.traces.size(), 2u);
  EXPECT_DOUBLE_EQ(m.traces[0].turned, 0.0);
  EXPECT_NEAR(m.traces[1].turned, kPi, 1e-12);
  const Diagnosis d = diagnose(m);
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);
  ASSERT_EQ(d.effects.size(), 1u) << report_text(d);
  const EffectFit* g = find(d, EffectKind::gravity);
  ASSERT_NE(g, nullptr) << report_text(d);
  EXPECT_NEAR(g->value[0], 0.1, 0.005);
  // With gravity taken out of the library no preload can stand in for it.
  EXPECT_EQ(diagnose(m, every_effect_but(EffectKind::gravity)).verdict, Verdict::unexplained);
}

TEST(Gap, EachWayUpAWeightIsAPreloadOfItsOwn) {
  // 0.01 N*m of weight (0.06 N at the effort, three times the noise), the
  // tool one way up and then the other, gravity withheld: together no
  // effect cuts the gap (a preload of one sign misses the other trace as
  // far), so the best effect together is none in particular. Fitted to
  // each trace alone, a preload of its own takes each to the noise: about
  // 1.5 - 0.93 N upright and 1.5 + 0.93 N turned (0.01 N*m times a cosine
  // of 0.93 over the 10 mm spring arm).
  const Diagnosis d = diagnose(load_measurement(turned_measurement("small-weight", {0, 0, 0, 0.01, 0}).string()),
                               every_effect_but(EffectKind::gravity));
  ASSERT_NO_FATAL_FAILURE(expect_two_traces_differ(d, EffectKind::spring_preload));
  EXPECT_NEAR(d.per_trace.first_parameter[0], 1.5 - 0.93, 0.05) << report_text(d);
  EXPECT_NEAR(d.per_trace.first_parameter[1], 1.5 + 0.93, 0.05) << report_text(d);
}

TEST(Gap, TracesThatDifferAreToldFromAModelThatMisses) {
  // One nutcracker's two traces, its pivot's friction 0.2 N*m over the
  // model's in one and 0.5 in the other (worn in between): one friction
  // for both misses each by 0.15 N*m (0.94 N at the effort), a square
  // wave of either sign, which no effect takes up. Fitted to each trace
  // alone, friction takes each to the noise: the traces differ.
  const fs::path dir = test::fresh_dir("gap", "differ");
  write(dir / "a.csv", lever_trace({0.2, 0, 0, 0, 0}, 1));
  write(dir / "b.csv", lever_trace({0.5, 0, 0, 0, 0}, 2));
  write(dir / "m.yaml", "measurement: differ\nobject: " + kSource +
                            "/objects/nutcracker.yaml\neffort_at: 160 mm\ntraces: [a.csv, b.csv]\n");
  const Diagnosis d = diagnose(load_measurement((dir / "m.yaml").string()));
  ASSERT_NO_FATAL_FAILURE(expect_two_traces_differ(d, EffectKind::pivot_friction));
  EXPECT_NEAR(d.per_trace.first_parameter[0], 0.21, 0.002);  // the nominal 0.01 and the hidden
  EXPECT_NEAR(d.per_trace.first_parameter[1], 0.51, 0.002);
  EXPECT_NEAR(d.per_trace.rmse_alone, 0.02, 0.002) << report_text(d);
  EXPECT_THAT(report_json(d), HasSubstr("\"nominal_at_floor\":false,\"each_at_floor\":true"));
}

TEST(Gap, TheAnglesNoiseThroughAnInertiaIsPartOfTheNoiseFloor) {
  // 0.002 kg*m^2 hidden, 1e-4 rad of angle noise: the acceleration, from a
  // degree-6 polynomial over +-25 ms at 1 kHz, would carry 1.15 rad/s^2 of
  // it (the filter's gain, worked out from its coefficients), so the
  // inertia would pass 0.002 * 1.15 / 0.16 m = 0.0144 N into the predicted
  // effort, a floor of hypot(0.02, 0.0144) = 0.0246 N. The slow drive lets
  // the same polynomial over +-200 ms take the acceleration
  // (smooth_derivative.h), with a gain of 65.6 s^-2: 0.002 * 6.6e-3 /
  // 0.16 = 8e-5 N, and the floor is the sensor's 0.02 N; the trace's ends,
  // where the narrow window stays, weigh less by as much as they pass.
  Hidden h;
  h.inertia = 0.002;
  h.angle_noise = 1e-4;
  const Diagnosis d = diagnose(load_measurement(lever_measurement("inertia-noise", h).string()));
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);
  const EffectFit* f = find(d, EffectKind::arm_inertia);
  ASSERT_NE(f, nullptr) << report_text(d);
  EXPECT_NEAR(f->value[0], 0.002, 0.0001);
  EXPECT_NEAR(d.noise, 0.02, 0.003);
  EXPECT_NEAR(d.noise_through_model, 0.020, 0.001);
  EXPECT_LT(d.rmse_after, 1.3 * d.noise_through_model);
}

// A fit's delay between samples: a line is read exactly late, and white
// noise keeps its variance at every fraction of a sample (linear
// interpolation halves it at half a sample, which a late sensor of half
// a millisecond would then win on any prediction from a noisy angle).
TEST(GapReplay, ADelayBetweenSamplesKeepsTheNoiseItReads) {
  std::vector<double> t, line, noise;
  std::mt19937 random(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    t.push_back(i * 1e-3);
    line.push_back(3 + 2 * t.back());
    noise.push_back(unit(random));
  }
  for (double fraction : {0.25, 0.5, 0.8}) {
    const double delay = (7 + fraction) * 1e-3;  // s
    const std::vector<double> late = delayed_keeping_noise(t, line, delay, sample_step(t));
    for (size_t i = 10; i < t.size(); ++i) ASSERT_NEAR(late[i], 3 + 2 * (t[i] - delay), 1e-12) << i;
    double kept = 0, linear = 0;
    const std::vector<double> a = delayed_keeping_noise(t, noise, delay, sample_step(t)),
                              b = delayed(t, noise, delay, sample_step(t));
    for (size_t i = 10; i < t.size(); ++i) {
      kept += a[i] * a[i];
      linear += b[i] * b[i];
    }
    const double n = static_cast<double>(t.size() - 10);
    EXPECT_NEAR(kept / n, 1.0, 0.03) << fraction;
    EXPECT_NEAR(linear / n, fraction * fraction + (1 - fraction) * (1 - fraction), 0.03) << fraction;
  }
}

// A latency's delayed signal, worked by hand on uneven samples: held
// before the first sample and after the last, linear between; the same as
// value_at at every shifted time, either way in time.
TEST(GapReplay, ADelayedSignalIsInterpolatedBetweenUnevenSamples) {
  const std::vector<double> t = {0, 0.001, 0.003, 0.004, 0.006}, y = {0, 1, 5, 4, 10};
  const double step = sample_step(t);  // s
  const std::vector<double> late = delayed(t, y, 0.0015, step), early = delayed(t, y, -0.0025, step);
  const std::vector<double> late_by_hand = {0, 0, 2, 4, 5.5}, early_by_hand = {4, 4.5, 8.5, 10, 10};
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(late[i], late_by_hand[i], 1e-12) << i;
    EXPECT_NEAR(early[i], early_by_hand[i], 1e-12) << i;
    EXPECT_EQ(late[i], value_at(t, y, t[i] - 0.0015)) << i;
    EXPECT_EQ(early[i], value_at(t, y, t[i] + 0.0025)) << i;
  }
}

TEST(Gap, APatchKeepsHowEachTraceWasHeld) {
  const fs::path file = turned_measurement("turned-patch", Hidden{0, 0, 0, 0.1, 0});
  const Measurement m = load_measurement(file.string());
  const Diagnosis d = diagnose(m);
  ASSERT_EQ(d.verdict, Verdict::explained) << report_text(d);
  const fs::path dir = file.parent_path() / "patch";
  (void)write_patch(m, d, dir.string());
  const Measurement again = load_measurement((dir / "measurement.yaml").string());
  ASSERT_EQ(again.traces.size(), 2u);
  EXPECT_NEAR(again.traces[1].turned, kPi, 1e-9);
  EXPECT_EQ(diagnose(again).verdict, Verdict::none);
}

TEST(Gap, JsonHasTheReportedFields) {
  const Diagnosis d = diagnose(load_measurement(lever_measurement("json", {0.3, 0, 0}).string()));
  const std::string json = report_json(d);
  for (const char* key : {"\"verdict\":\"explained\"", "\"effects\":[{\"name\":\"pivot_friction\"",
                          "\"torque\":{\"value\":", "\"unit\":\"N*m\"", "\"uncertainty\":", "\"shrink\":",
                          "\"phases\":[", "\"share_before\":", "\"residual\":{\"white\":", "\"events\":"}) {
    EXPECT_THAT(json, HasSubstr(key));
  }
}

// The number after `key` in `text` (NaN if it is not there).
double number_after(const std::string& text, const std::string& key) {
  const size_t at = text.find(key);
  return at == std::string::npos ? NAN : std::strtod(text.c_str() + at + key.size(), nullptr);
}

TEST(Gap, AParameterIsReportedAsAChangeOverTheNominalAndAsTheTotal) {
  // The nutcracker's file has 0.01 N*m of friction; the real tool 0.3 more.
  const fs::path file = lever_measurement("change", {0.3, 0, 0});
  const Measurement m = load_measurement(file.string());
  const Diagnosis d = diagnose(m);
  ASSERT_NE(find(d, EffectKind::pivot_friction), nullptr) << report_text(d);
  const Model nominal = nominal_model(m);
  const std::string text = report_text(d, &nominal);
  const double change = number_after(text, "pivot_friction: torque ");
  const double total = number_after(text, "N*m over the nominal 0.01 (");
  EXPECT_NEAR(change, 0.3, 0.01) << text;
  EXPECT_NEAR(total, 0.31, 0.01) << text;
  EXPECT_THAT(text, HasSubstr("pivot_friction: torque +0."));
  const std::string json = report_json(d, &nominal);
  const double value = number_after(json, "\"torque\":{\"value\":");
  EXPECT_NEAR(value, 0.31, 0.01) << json;  // the total, as before
  EXPECT_NEAR(number_after(json, "\"change\":"), 0.3, 0.01) << json;
  EXPECT_NEAR(number_after(json, "\"nominal\":"), 0.01, 1e-12) << json;
  std::printf("friction: change %+.5f N*m, total %.5f N*m (JSON value %.5f)\n", change, total, value);
  // --write-patch writes the total.
  (void)write_patch(m, d, (file.parent_path() / "patch").string());
  const ObjectSpec patched = load_object((file.parent_path() / "patch" / "object.yaml").string());
  for (const EffectSpec& e : patched.effects) {
    if (e.kind == EffectKind::pivot_friction) {
      EXPECT_NEAR(e.param[0], total, 1e-4);
    }
  }
}

// The plots draw the numbers the report gives: the residual curves' RMS
// over the fitted samples are the held-out RMSEs before and after.
TEST(GapPlots, TheCurvesAreTheReportedHeldOutResiduals) {
  const Diagnosis d = diagnose(load_measurement(lever_measurement("plots", {0.3, 0, 0}).string()));
  ASSERT_EQ(d.verdict, Verdict::explained) << report_text(d);
  ASSERT_EQ(d.curves.size(), 4u);  // two traces, each cut into two blocks
  double sq_before = 0, sq_after = 0;
  size_t n = 0;
  for (const HeldOutCurve& c : d.curves) {
    ASSERT_EQ(c.t.size(), c.fitted.size());
    for (size_t s = 0; s < c.t.size(); ++s) {
      if (std::isnan(c.fitted[s])) continue;
      sq_before += (c.measured[s] - c.nominal[s]) * (c.measured[s] - c.nominal[s]);
      sq_after += (c.measured[s] - c.fitted[s]) * (c.measured[s] - c.fitted[s]);
      ++n;
    }
  }
  ASSERT_GT(n, 10000u);
  EXPECT_NEAR(std::sqrt(sq_before / static_cast<double>(n)), d.rmse_before, 1e-9 * d.rmse_before);
  EXPECT_NEAR(std::sqrt(sq_after / static_cast<double>(n)), d.rmse_after, 1e-9 * d.rmse_after);

  // The residual chart shades the phases the sine goes through and shows
  // both residuals; the loop chart the three curves per trace.
  const render::Chart residual = residual_chart(d);
  std::vector<std::string> legend;
  for (const render::ChartLegendBand& b : residual.band_legend) legend.push_back(b.label);
  EXPECT_THAT(legend, ::testing::IsSupersetOf({"free closing", "free opening", "reversals"}));
  EXPECT_EQ(residual.curves.size(), 2u);
  EXPECT_EQ(residual.markers.size(), d.curves.size());  // where each judged block starts
  EXPECT_EQ(loop_chart(d).curves.size(), 3 * d.curves.size());

  const fs::path dir = test::fresh_dir("gap", "plots-out") / "plots";
  const std::vector<std::string> written = write_gap_plots(d, dir.string());
  EXPECT_EQ(written.size(), 4u);
  const render::Image png = render::read_png((dir / "loop.png").string());
  EXPECT_EQ(png.width, render::kChartWidth);
  EXPECT_EQ(png.height, render::kChartHeight);
  std::ifstream svg(dir / "residual.svg");
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("<svg"));
  EXPECT_THAT(text, HasSubstr("<polyline"));
  EXPECT_THAT(text, HasSubstr("fitted, held out"));
  // A folder that cannot be made is an error naming it.
  write(dir / "file", "x");
  try {
    write_gap_plots(d, (dir / "file" / "sub").string());
    ADD_FAILURE() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), HasSubstr("file/sub"));
  }
}

TEST(Gap, APatchAdoptsTheEffectAndLeavesNoGap) {
  const fs::path file = lever_measurement("patch", {0.3, 0, 0});
  const Measurement m = load_measurement(file.string());
  const Diagnosis d = diagnose(m);
  ASSERT_EQ(d.verdict, Verdict::explained) << report_text(d);
  const fs::path dir = file.parent_path() / "patch";
  const std::vector<std::string> written = write_patch(m, d, dir.string());
  ASSERT_EQ(written.size(), 2u);  // object.yaml and measurement.yaml
  const ObjectSpec patched = load_object((dir / "object.yaml").string());
  bool friction = false;
  for (const EffectSpec& e : patched.effects) {
    if (e.kind == EffectKind::pivot_friction) {
      friction = true;
      EXPECT_NEAR(e.param[0], d.effects[0].value[0], 1e-5);
    }
  }
  EXPECT_TRUE(friction);
  const Diagnosis again = diagnose(load_measurement((dir / "measurement.yaml").string()));
  EXPECT_EQ(again.verdict, Verdict::none) << report_text(again);
}

// ------------------------------------------------------------ bad files

std::string measurement_error(const std::string& yaml, const std::string& csv = "") {
  const fs::path dir = test::fresh_dir("gap", "bad");
  if (!csv.empty()) write(dir / "t.csv", csv);
  write(dir / "m.yaml", yaml);
  try {
    (void)load_measurement((dir / "m.yaml").string());
  } catch (const DataError& e) {
    std::string what = e.what();
    const std::string prefix = dir.string() + "/";
    for (size_t at; (at = what.find(prefix)) != std::string::npos;) what.erase(at, prefix.size());
    return what;
  }
  ADD_FAILURE() << "no DataError for:\n" << yaml;
  return "";
}

std::string good_csv(int rows = 60) {
  std::string csv = "t,angle,effort_force,actee_force,extra\n";
  for (int i = 0; i < rows; ++i) csv += std::to_string(i * 1e-3) + ",0.3,5,0,7\n";
  return csv;
}

const std::string kHead = "measurement: m\nobject: " + kSource + "/objects/nutcracker.yaml\n";

TEST(GapErrors, UnknownKeySaysDidYouMean) {
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\ntraec: x\n", good_csv()),
              HasSubstr("m.yaml:5:1: expected one of the keys of a measurement file"));
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\ntraec: x\n", good_csv()),
              HasSubstr("found 'traec' (did you mean 'trace'?)"));
}

TEST(GapErrors, ATraceEntryIsChecked) {
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntraces: [{file: t.csv, turn: 90 deg}]\n", good_csv()),
              HasSubstr("m.yaml:4:24: expected one of the keys of a trace (file, turned), found 'turn' (did you mean 'turned'?)"));
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntraces: [{file: t.csv, turned: 400 deg}]\n", good_csv()),
              HasSubstr("m.yaml:4:32: expected an angle from -360 deg to 360 deg, found '400 deg'"));
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: {turned: 90 deg}\n", good_csv()),
              HasSubstr("m.yaml:4:8: expected key 'file'"));
  EXPECT_THAT(measurement_error("measurement: m\nrig: plates\nactee: {file: " + kSource +
                                    "/actees/walnut.yaml}\ntrace: {file: t.csv, turned: 90 deg}\n",
                                "t,displacement,force\n" + std::string(60 * 6, ' ')),
              HasSubstr("no 'turned' with rig: plates"));
}

TEST(GapErrors, EffortOutsideTheEmphasis) {
  EXPECT_THAT(measurement_error(kHead + "effort_at: 60 mm\ntrace: t.csv\n", good_csv()),
              HasSubstr("m.yaml:3:12: expected a distance in the emphasis region, 110 mm to 180 mm, found '60 mm'"));
}

TEST(GapErrors, ACellThatIsNotANumberNamesItsRowAndColumn) {
  std::string csv = good_csv();
  csv.replace(csv.find("0.3,5"), 5, "0.3,x5");
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\n", csv),
              HasSubstr("t.csv:2:14: expected a number, found 'x5'"));
  csv = good_csv();
  csv.replace(csv.find("0.3,5"), 5, "nan,5");
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\n", csv),
              HasSubstr("t.csv:2:"));
}

TEST(GapErrors, CommentLinesBeforeTheHeaderAreSkippedAndRowsKeepTheirFileLines) {
  // afford's own trace.csv starts with its units as a comment.
  std::string csv = "# units: t s, angle rad\n# a second comment\n" + good_csv();
  csv.replace(csv.find("0.3,5"), 5, "0.3,x5");
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\n", csv),
              HasSubstr("t.csv:4:14: expected a number, found 'x5'"));
}

TEST(GapErrors, TimeMustIncrease) {
  std::string csv = good_csv();
  csv.replace(csv.find("\n0.002000"), 9, "\n0.000500");
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\n", csv),
              HasSubstr("t.csv:4:1: expected a time after 0.001 s, found 0.0005 s"));
}

TEST(GapErrors, TooShortToSplit) {
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\n", good_csv(10)),
              HasSubstr("expected a trace of at least 50 rows (to fit on part and judge on the rest), found 10"));
}

TEST(GapErrors, AMissingColumnAndAWrongUnit) {
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\n", "t,angle\n0,1\n"),
              HasSubstr("t.csv:1:1: expected a column 'effort_force' (effort_force)"));
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\nformat:\n  columns:\n"
                                        "    t: {column: t, unit: s}\n    angle: {column: angle, unit: mm}\n"
                                        "    effort_force: {column: effort_force, unit: N}\n",
                                good_csv()),
              HasSubstr("m.yaml:8:34: expected a unit of an angle (e.g. '30 deg'), found 'mm'"));
}

TEST(GapErrors, PlatesTakeNoTool) {
  EXPECT_THAT(measurement_error("measurement: m\nrig: plates\nobject: x.yaml\nactee: {file: " + kSource +
                                "/actees/walnut.yaml}\ntrace: t.csv\n"),
              HasSubstr("m.yaml:3:1: expected no 'object' with rig: plates (an actee alone), found one"));
}

TEST(GapErrors, AnEffectOfTheMeasurementIsChecked) {
  EXPECT_THAT(measurement_error(kHead + "effort_at: 160 mm\ntrace: t.csv\neffects:\n  sensor_latency: {delay: 5 s}\n",
                                good_csv()),
              HasSubstr("m.yaml:6:27: expected a value from 0 s to 1 s (delay, s), found '5 s'"));
}

TEST(Gap, ByForceTheContactAndTheBreakComeWhenMeasured) {
  // The nutcracker closes on the walnut at 60 mm (1 deg/s after 0.2 s):
  // the effort by moment balance written out here, the walnut's force
  // k*d*h/(h-d) along the arc where the jaw touches it (56.38 mm from the
  // hinge, test_util.h), broken at its 378 N. Replayed by force, the
  // nominal model touches and cracks it when the trace says, to a frame.
  const fs::path dir = test::fresh_dir("gap", "events");
  const Measurement probe = [&] {
    write(dir / "x.csv", good_csv());
    write(dir / "m.yaml", kHead + "actee: {file: " + kSource + "/actees/walnut.yaml, at: 60 mm}\n"
                          "effort_at: 160 mm\ntrace: x.csv\n");
    return load_measurement((dir / "m.yaml").string());
  }();
  const Model model = compile_measurement(probe);
  const auto state = make_state(model);
  const double a = test::ellipsoid_under_jaw(0.018, 0.0141, 0.060, 30 * kPi / 180).lever;
  const double h = state->actee_thickness, theta_c = state->contact_angle;
  const double k = 250e3, sp = 0.010, rest = 30 * kPi / 180;
  std::string csv = "t,angle,effort_force,actee_force,broken\n";
  double contact_t = -1, break_t = -1;
  bool broken = false;
  for (int i = 0; i < 3000; ++i) {
    const double t = i * 1e-3;
    const double theta = rest - std::max(0.0, t - 0.2) * kPi / 180 * 2;  // 2 deg/s
    const double d = std::max(0.0, a * (theta_c - theta));
    // The frame the load passes the limit still carries it; then nothing.
    const double force = broken ? 0.0 : k * d * h / (h - d);
    if (!broken && force > 378) {
      broken = true;
      break_t = t;
    }
    if (force > 0.01 * 378 && contact_t < 0) contact_t = t;  // the contact a force sensor sees
    const double torque = 2000 * sp * (rest - theta) * sp + 1.5 * sp + force * a + (theta < rest ? 0.01 : 0.0);
    char row[160];
    std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f,%.6f,%d\n", t, theta, torque / 0.160, force, broken ? 1 : 0);
    csv += row;
  }
  write(dir / "x.csv", csv);
  const Measurement m = load_measurement((dir / "m.yaml").string());
  const std::vector<ForceGap> gaps = replay_force(model, m);
  ASSERT_EQ(gaps.size(), 1u);
  ASSERT_EQ(gaps[0].events.size(), 2u);
  EXPECT_NEAR(gaps[0].events[0].measured_t, contact_t, 1e-9);
  EXPECT_NEAR(gaps[0].events[0].simulated_t, contact_t, 0.0015);
  EXPECT_NEAR(gaps[0].events[1].measured_t, break_t, 1e-9);
  EXPECT_NEAR(gaps[0].events[1].simulated_t, break_t, 0.0015);
  EXPECT_GT(gaps[0].events[1].simulated_force, 378);
  EXPECT_LT(gaps[0].angle_rmse, 1e-3);  // rad, up to the break
}

TEST(GapReplay, EachSampleIsWeighedByTheAnglesNoiseThroughTheModelsSlope) {
  // The nutcracker on the walnut at 60 mm, held open, then 1 mm into the
  // shell. Off the walnut the model's slope is the spring's alone,
  // -2000 N/m * (10 mm)^2 = -0.2 N*m/rad; 1 mm in, the walnut's
  // k h^2 / (h - d)^2 D^2 = 250 N/mm * (28.2 / 27.2)^2 * (56.378 mm)^2
  // = 854.13 N*m/rad adds to it, D where the jaw touches it (test_util.h).
  // With 1e-4 rad of angle noise read at 160 mm, that is 0.5340 N through
  // the model against the effort sensor's 0.02 N: a weight of
  // 0.02^2 / (0.02^2 + 0.5340^2) = 1.401e-3.
  const fs::path dir = test::fresh_dir("gap", "weights");
  write(dir / "x.csv", good_csv());
  write(dir / "m.yaml", kHead + "actee: {file: " + kSource + "/actees/walnut.yaml, at: 60 mm}\n"
                        "effort_at: 160 mm\ntrace: x.csv\n");
  const Model model = compile_measurement(load_measurement((dir / "m.yaml").string()));
  const double theta_c = make_state(model)->contact_angle;
  const double lever = test::ellipsoid_under_jaw(0.018, 0.0141, 0.060, 30 * kPi / 180).lever;
  EXPECT_NEAR(lever, 0.056378, 1e-6);
  std::string csv = "t,angle,effort_force,actee_force\n";
  for (int i = 0; i < 100; ++i) {
    csv += std::to_string(i * 1e-3) + "," + std::to_string(i < 50 ? theta_c + 0.1 : theta_c - 0.001 / lever) + ",1,0\n";
  }
  write(dir / "x.csv", csv);
  std::vector<Replay> replays = replay_lever(model, load_measurement((dir / "m.yaml").string()));
  ASSERT_EQ(replays.size(), 1u);
  Replay& r = replays[0];
  EXPECT_NEAR(r.slope[10], -0.2, 1e-9);
  EXPECT_NEAR(r.deflection[80], 0.001, 1e-6);  // to_string's six decimals of the angle
  EXPECT_NEAR(r.slope[80], -0.2 - 854.13, 0.5);
  EXPECT_EQ(r.weight[80], 1.0);  // until weighed
  r.x_noise = 1e-4;
  weigh(replays, 0.02);
  EXPECT_NEAR(r.weight[10], 1 - 3.9e-5, 1e-6);
  EXPECT_NEAR(r.weight[80], 1.401e-3, 2e-6);
}

// The nutcracker on the walnut at 60 mm, closed onto it and then held
// 1 mm into its shell, the angle read with `angle_noise` rad of noise.
std::vector<Replay> held_on_the_walnut(const std::string& name, double angle_noise, double* theta_c, double* x_noise) {
  const fs::path dir = test::fresh_dir("gap", name);
  write(dir / "x.csv", good_csv());
  write(dir / "m.yaml", kHead + "actee: {file: " + kSource + "/actees/walnut.yaml, at: 60 mm}\n"
                        "effort_at: 160 mm\ntrace: x.csv\n");
  const Model model = compile_measurement(load_measurement((dir / "m.yaml").string()));
  *theta_c = make_state(model)->contact_angle;
  const double lever = test::ellipsoid_under_jaw(0.018, 0.0141, 0.060, 30 * kPi / 180).lever;
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, angle_noise);
  std::string csv = "t,angle,effort_force,actee_force\n";
  for (int i = 0; i < 2000; ++i) {
    // 0.1 rad above the contact, closing onto it in 0.5 s, then held.
    const double clear = std::max(0.0, 1 - i / 500.0) * 0.1;
    const double theta = *theta_c - 0.001 / lever + clear;
    char row[96];
    std::snprintf(row, sizeof row, "%.3f,%.9f,1,0\n", i * 1e-3, theta + noise(random));
    csv += row;
  }
  write(dir / "x.csv", csv);
  std::vector<Replay> replays = replay_lever(model, load_measurement((dir / "m.yaml").string()));
  *x_noise = replays.at(0).x_noise;
  return replays;
}

TEST(GapReplay, SqueezedAndAllButStillIsFittedWhereFrictionIsSmallAgainstItsNoise) {
  // Held 1 mm into the walnut the angle does not move: the rate is the
  // noise's, and friction (0.01 N*m) may take any value up to its limit.
  // The walnut's 854.33 N*m/rad (the test above) passes the angle's noise
  // into the prediction: with 3e-4 rad that is 0.256 N*m, and friction's
  // band is under a tenth of it: the samples tell the walnut's law and
  // are fitted. With 5e-5 rad it is 0.043 N*m, friction's band is not
  // small against it, and they are not.
  double theta_c = 0, x_noise = 0;
  const std::vector<Replay> noisy = held_on_the_walnut("held-noisy", 3e-4, &theta_c, &x_noise);
  EXPECT_NEAR(x_noise, 3e-4, 3e-5);
  const Replay& r = noisy.at(0);
  size_t held = 0, fitted = 0;
  for (size_t s = 1000; s < 1900; ++s) {
    held += r.deflection[s] > 0 ? 1 : 0;
    fitted += r.fitted[s] ? 1 : 0;
    if (r.fitted[s]) {
      EXPECT_TRUE(r.phase[s] == Phase::loading || r.phase[s] == Phase::unloading) << s;
    }
  }
  EXPECT_GT(held, 850u);  // all but where the noise lifts the jaw off
  EXPECT_EQ(fitted, held);
  double quiet_theta_c = 0, quiet_x_noise = 0;
  const std::vector<Replay> quiet = held_on_the_walnut("held-quiet", 5e-5, &quiet_theta_c, &quiet_x_noise);
  for (size_t s = 1000; s < 1900; ++s) EXPECT_FALSE(quiet.at(0).fitted[s]) << s;
  // Within three of the angle's noise above the contact, the noise may put
  // the jaws on the walnut: the slope there is the walnut's, not the
  // spring's -0.2 N*m/rad; farther off, the spring's alone.
  bool near_seen = false, far_seen = false;
  for (size_t s = 0; s < r.t.size(); ++s) {
    if (r.deflection[s] > 0) continue;
    const double above = r.x[s] - theta_c;  // rad
    if (above < 2.5 * x_noise) {
      near_seen = true;
      EXPECT_LT(r.slope[s], -100) << s;
    } else if (above > 3.5 * x_noise) {
      far_seen = true;
      EXPECT_NEAR(r.slope[s], -0.2, 1e-9) << s;
    }
  }
  EXPECT_TRUE(near_seen);
  EXPECT_TRUE(far_seen);
}

// The nutcracker on a hazelnut at 75 mm, driven in four slow triangles
// from 0.06 rad clear of it to 0.6 of its limit's linear deflection in
// it, measured at 160 mm with 1e-4 rad and 0.02 N of noise. The
// hazelnut's law is k r (d / r)^exponent h / (h - d), r its limit's
// deflection 431 N / 270 N/mm: exponent 1 is its nominal law.
fs::path squeezed_hazelnut(const std::string& name, double exponent) {
  const fs::path dir = test::fresh_dir("gap", name);
  write(dir / "x.csv", good_csv());
  const std::string head = kHead + "actee: {file: " + kSource + "/actees/hazelnut.yaml, at: 75 mm}\neffort_at: 160 mm\n";
  write(dir / "m.yaml", head + "trace: x.csv\n");
  const auto state = make_state(compile_measurement(load_measurement((dir / "m.yaml").string())));
  const double a = std::abs(state->load_distance), h = state->actee_thickness, theta_c = state->contact_angle;
  const double k = 270e3, r = 431 / k, sp = 0.010, rest = 30 * kPi / 180, b = 0.160;
  const double deepest = 0.6 * r / a;  // rad past the contact
  std::string traces;
  for (int n = 0; n < 4; ++n) {
    std::mt19937 random(100 + n);
    std::normal_distribution<double> effort_noise(0.0, 0.02), angle_noise(0.0, 1e-4);
    std::string csv = "t,angle,effort_force,actee_force\n";
    for (int i = 0; i < 4000; ++i) {
      const double t = i * 1e-3, phase = std::fmod(t, 2.0);
      const double down = phase < 1 ? phase : 2 - phase;  // 0 to 1 and back, each second
      const double theta = theta_c + 0.06 - (0.06 + deepest) * down;
      const double omega = (phase < 1 ? -1 : 1) * (0.06 + deepest);
      const double d = std::max(0.0, a * (theta_c - theta));
      const double force = d > 0 ? k * r * std::pow(d / r, exponent) * h / (h - d) : 0.0;
      const double torque = 2000 * sp * (rest - theta) * sp + 1.5 * sp + force * a - 0.01 * (omega > 0 ? 1 : -1);
      char row[128];
      std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f,%.6f\n", t, theta + angle_noise(random),
                    torque / b + effort_noise(random), force);
      csv += row;
    }
    write(dir / std::string("s").append(std::to_string(n)).append(".csv"), csv);
    traces += (n ? ", s" : "s") + std::to_string(n) + ".csv";
  }
  write(dir / "m.yaml", head + "traces: [" + traces + "]\n");
  return dir / "m.yaml";
}

TEST(Gap, AnActeesLawIsJudgedWhereTheJawsDeflectIt) {
  const Diagnosis hertz = diagnose(load_measurement(squeezed_hazelnut("hertz", 1.5).string()));
  EXPECT_EQ(hertz.verdict, Verdict::explained) << report_text(hertz);
  ASSERT_EQ(hertz.effects.size(), 1u) << report_text(hertz);
  EXPECT_EQ(hertz.effects[0].kind, EffectKind::actee_compliance);
  EXPECT_NEAR(hertz.effects[0].value[0], 1.5, 0.05);
  // The contact's samples weigh little (the hazelnut passes the angle's
  // noise on): its gap, scaled to the sensor's noise, is the larger, and
  // the shrink is the contact's.
  EXPECT_GT(hertz.contact_samples, 1000u);
  EXPECT_GT(hertz.contact_before, hertz.rmse_before);
  EXPECT_TRUE(hertz.shrink_in_contact);
  EXPECT_DOUBLE_EQ(hertz.shrink, 1 - hertz.contact_after / hertz.contact_before);
  EXPECT_LT(hertz.contact_after, 1.15 * hertz.noise_through_model);
  // Its nominal law: nothing to find, in the contact either.
  const Diagnosis linear = diagnose(load_measurement(squeezed_hazelnut("linear", 1.0).string()));
  EXPECT_EQ(linear.verdict, Verdict::none) << report_text(linear);
  EXPECT_LT(linear.contact_before, 1.15 * linear.noise_through_model) << report_text(linear);
}

TEST(Gap, AProbeFindsTheLeverAndTheSpring) {
  // A robot pushes at 160 mm on a tool like the nutcracker but opening to
  // 40 deg, with a 3000 N/m spring at 10 mm (0.3 N*m/rad) preloaded with
  // 10 N (0.1 N*m: enough to open it against the friction) and 0.05 N*m of
  // pivot friction, closed to 5 deg: 0.5 s untouched, 2 s closing, pressed
  // on at the stop, 2 s opening. The effort by moment balance, written out
  // here; 0.01 N of noise.
  const double deg = kPi / 180, b = 0.160, k = 0.3, preload = 0.1, friction = 0.05;
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::string csv = "t,angle,effort_force\n";
  for (int i = 0; i < 6000; ++i) {
    const double t = i * 1e-3;
    double theta = 40 * deg, torque = 0;
    if (t >= 0.5 && t < 2.5) {
      theta = (40 - 35 * (t - 0.5) / 2) * deg;
      torque = k * (40 * deg - theta) + preload + friction;
    } else if (t >= 2.5 && t < 3.5) {
      theta = 5 * deg;  // on the closed stop, pressed harder
      torque = k * 35 * deg + preload + friction + 2.0 * (t - 2.5);
    } else if (t >= 3.5 && t < 5.5) {
      theta = (5 + 35 * (t - 3.5) / 2) * deg;
      torque = k * (40 * deg - theta) + preload - friction;
    }
    char row[96];
    std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f\n", t, theta, std::max(0.0, torque / b + (torque > 0 ? noise(random) : 0)));
    csv += row;
  }
  const fs::path dir = test::fresh_dir("gap", "probe");
  write(dir / "p.csv", csv);
  write(dir / "m.yaml", kHead + "effort_at: 160 mm\ntrace: p.csv\n");
  const ProbeResult p = probe_lever(load_measurement((dir / "m.yaml").string()));
  // Both stops: pressed harder on the closed one, let go on the open one,
  // where the spring's 0.05 N*m past friction holds it.
  EXPECT_TRUE(p.min_found);
  EXPECT_TRUE(p.max_found);
  EXPECT_NEAR(p.theta_min, 5 * deg, 1e-9);
  EXPECT_NEAR(p.theta_max, 40 * deg, 1e-9);
  EXPECT_TRUE(p.rest_seen);
  EXPECT_NEAR(p.theta_rest, 40 * deg, 1e-9);
  EXPECT_TRUE(p.told_apart);
  EXPECT_NEAR(p.torsion, k, 0.003);
  EXPECT_NEAR(p.spring_constant, 3000, 30);  // at the nominal file's 10 mm
  EXPECT_NEAR(p.preload_torque, preload, 0.002);
  EXPECT_NEAR(p.preload, 10.0, 0.2);
  EXPECT_NEAR(p.friction, friction, 0.002);
  write_probed_object(p, (dir / "object.yaml").string());
  const ObjectSpec o = load_object((dir / "object.yaml").string());
  EXPECT_NEAR(o.lever.theta_max, 40 * deg, 1e-6);
  EXPECT_NEAR(o.spring.constant, p.spring_constant, 1e-3 * p.spring_constant);
}

// A robot's probe of a tool like the shipped nutcracker (2000 N/m at
// 10 mm, rest 30 deg on its open stop), pushing at 160 mm: legs one after
// another, the angle linear in time over each; the effort by moment
// balance written out here, with noise. The nominal file is the shipped
// nutcracker's (limits 0 and 30 deg, 1.5 N preload, 0.01 N*m friction).
struct ProbeLeg {
  double seconds, from_deg, to_deg;
  enum How { move, press, hold, untouched } how = move;
};
struct ProbeTruth {
  double preload = 1.5;        // N at 10 mm
  double friction = 0.01;      // N*m
  double effort_noise = 0.02;  // N
  double angle_noise = 1e-4;   // rad
};
fs::path probe_measurement(const std::string& name, const std::vector<ProbeLeg>& legs, const ProbeTruth& truth) {
  const double k = 2000, sp = 0.010, rest = 30 * kPi / 180, b = 0.160;
  std::mt19937 random(7);
  std::normal_distribution<double> force_noise(0.0, truth.effort_noise), angle_noise(0.0, truth.angle_noise);
  std::string csv = "t,angle,effort_force\n";
  int i = 0;
  for (const ProbeLeg& leg : legs) {
    const int n = static_cast<int>(std::lround(leg.seconds * 1000));
    const double closing = leg.to_deg < leg.from_deg ? 1.0 : -1.0;  // friction adds to the effort closing
    for (int s = 0; s < n; ++s, ++i) {
      const double into = s * 1e-3;
      const double theta = (leg.from_deg + (leg.to_deg - leg.from_deg) * into / leg.seconds) * kPi / 180;
      const double spring = k * sp * sp * (rest - theta) + truth.preload * sp;
      double torque = 0;
      switch (leg.how) {
        case ProbeLeg::move: torque = spring + closing * truth.friction; break;
        case ProbeLeg::press: torque = spring + truth.friction + 0.3 * into; break;  // harder on the closed stop
        case ProbeLeg::hold: torque = spring + truth.friction; break;  // stopped closing, held by the hand
        case ProbeLeg::untouched: torque = 0; break;
      }
      char row[96];
      std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f\n", i * 1e-3, theta + angle_noise(random),
                    torque / b + force_noise(random));
      csv += row;
    }
  }
  const fs::path dir = test::fresh_dir("gap", name);
  write(dir / "p.csv", csv);
  write(dir / "m.yaml", kHead + "effort_at: 160 mm\ntrace: p.csv\n");
  return dir / "m.yaml";
}

// The number after "  key " on a line of the probe's text.
double printed(const std::string& text, const std::string& key) {
  const size_t at = text.find("\n  " + key + " ");
  if (at == std::string::npos) {
    ADD_FAILURE() << "no " << key << " in\n" << text;
    return NAN;
  }
  return std::strtod(text.c_str() + at + 4 + key.size(), nullptr);
}

// What --probe prints is what it writes: each value in the text against
// the object file written, read back.
void expect_printed_is_written(const ProbeResult& p, const fs::path& dir) {
  const std::string text = probe_text(p);
  write_probed_object(p, (dir / "object.yaml").string());
  const ObjectSpec o = load_object((dir / "object.yaml").string());
  const double deg = kPi / 180;
  auto same = [](double a, double b) { return std::abs(a - b) <= 1e-5 * std::max(1.0, std::abs(b)); };
  EXPECT_PRED2(same, printed(text, "theta_min") * deg, o.lever.theta_min) << text;
  EXPECT_PRED2(same, printed(text, "theta_max") * deg, o.lever.theta_max) << text;
  EXPECT_PRED2(same, printed(text, "rest") * deg, o.lever.theta_rest) << text;
  EXPECT_PRED2(same, printed(text, "spring constant"), o.spring.constant) << text;
  EXPECT_PRED2(same, printed(text, "preload"), o.spring.preload) << text;
  double friction = 0;
  for (const EffectSpec& e : o.effects) {
    if (e.kind == EffectKind::pivot_friction && e.enabled) friction = e.param[0];
  }
  EXPECT_PRED2(same, printed(text, "pivot_friction"), friction) << text;
}

TEST(Gap, AProbeThatReachesNoLimitKeepsTheFilesLimits) {
  // Back and forth between 12 and 26 deg, never let go: no stop reached,
  // the untouched arm never seen.
  std::vector<ProbeLeg> legs;
  for (int n = 0; n < 3; ++n) {
    legs.push_back({1.4, 26, 12});
    legs.push_back({1.4, 12, 26});
  }
  const fs::path file = probe_measurement("probe-no-limit", legs, {});
  const ProbeResult p = probe_lever(load_measurement(file.string()));
  const double deg = kPi / 180;
  EXPECT_FALSE(p.min_found);
  EXPECT_FALSE(p.max_found);
  EXPECT_EQ(p.theta_min, 0.0);        // the file's, not the 12 deg visited
  EXPECT_EQ(p.theta_max, 30 * deg);   // the file's
  EXPECT_FALSE(p.rest_seen);
  EXPECT_EQ(p.theta_rest, 30 * deg);  // the file's, on its open stop
  EXPECT_TRUE(p.told_apart);
  EXPECT_NEAR(p.preload, 1.5, 0.1);
  EXPECT_NEAR(p.friction, 0.01, 0.002);
  EXPECT_NEAR(p.spring_constant, 2000, 40);
  const std::string text = probe_text(p);
  EXPECT_THAT(text, HasSubstr("theta_min 0 deg: not reached"));
  EXPECT_THAT(text, HasSubstr("rest 30 deg: not observed"));
  expect_printed_is_written(p, file.parent_path());
  const ObjectSpec o = load_object((file.parent_path() / "object.yaml").string());
  EXPECT_EQ(o.lever.theta_min, 0.0);
  EXPECT_EQ(o.lever.theta_max, 30 * deg);
}

TEST(Gap, AProbeFindsTheClosedStopWithinTheAnglesNoise) {
  // The real tool closes to 3 deg (its file says 0): let go at 30 deg,
  // closed onto the stop and pressed harder there, opened and let go.
  const fs::path file = probe_measurement("probe-stop",
                                          {{0.5, 30, 30, ProbeLeg::untouched},
                                           {2.0, 30, 3},
                                           {1.0, 3, 3, ProbeLeg::press},
                                           {2.0, 3, 30},
                                           {0.5, 30, 30, ProbeLeg::untouched}},
                                          {});
  const ProbeResult p = probe_lever(load_measurement(file.string()));
  const double deg = kPi / 180;
  EXPECT_TRUE(p.min_found);
  EXPECT_NEAR(p.theta_min, 3 * deg, 1e-4);  // the angle's noise
  // At the open stop the spring pushes 0.005 N*m past friction, 0.03 N at
  // the effort, within the effort's noise: friction alone might hold it.
  EXPECT_FALSE(p.max_found);
  EXPECT_EQ(p.theta_max, 30 * deg);
  EXPECT_TRUE(p.rest_seen);
  EXPECT_EQ(p.theta_rest, p.theta_max);
  EXPECT_NEAR(p.preload, 1.5, 0.1);
  std::printf("closed stop %.5f deg (true 3), preload %.4f N (1.5), friction %.5f N*m (0.01)\n", p.theta_min / deg,
              p.preload, p.friction);
  expect_printed_is_written(p, file.parent_path());
}

TEST(Gap, AProbeTellsThePreloadFromFrictionByMotionBothWays) {
  // 0.1 and 0.5 N of friction at the 160 mm effort (0.016 and 0.08 N*m;
  // at 0.08 the spring cannot open the tool alone and the probe pulls):
  // the preload at the rest angle, 1.5 N, is not pulled up by it.
  const double deg = kPi / 180;
  for (double friction_force : {0.1, 0.5}) {
    ProbeTruth truth;
    truth.friction = friction_force * 0.160;
    std::vector<ProbeLeg> legs;
    for (int n = 0; n < 2; ++n) {
      legs.push_back({0.5, 30, 30, ProbeLeg::untouched});
      legs.push_back({2.0, 30, 10});
      legs.push_back({2.0, 10, 30});
    }
    legs.push_back({0.5, 30, 30, ProbeLeg::untouched});
    const fs::path file = probe_measurement("probe-friction", legs, truth);
    const ProbeResult p = probe_lever(load_measurement(file.string()));
    EXPECT_TRUE(p.told_apart);
    EXPECT_EQ(p.theta_rest, 30 * deg);
    EXPECT_NEAR(p.preload, 1.5, 0.1) << friction_force;
    EXPECT_NEAR(p.friction, truth.friction, 0.002) << friction_force;
    std::printf("friction %.1f N at the effort: preload %.4f N (1.5), friction %.5f N*m (%.3f)\n", friction_force,
                p.preload, p.friction, truth.friction);
    expect_printed_is_written(p, file.parent_path());
  }
  // Closing only (then held): friction adds to the preload's torque and
  // cannot be told from it; the file's preload and friction stay.
  ProbeTruth truth;
  truth.friction = 0.08;
  const fs::path file = probe_measurement("probe-one-way",
                                          {{0.5, 30, 30, ProbeLeg::untouched},
                                           {2.0, 30, 10},
                                           {1.0, 10, 10, ProbeLeg::hold}},
                                          truth);
  const ProbeResult p = probe_lever(load_measurement(file.string()));
  EXPECT_FALSE(p.told_apart);
  EXPECT_EQ(p.preload, 1.5);   // the file's
  EXPECT_EQ(p.friction_written, 0.01);
  EXPECT_NEAR(p.spring_constant, 2000, 40);
  EXPECT_THAT(probe_text(p), HasSubstr("cannot be told apart"));
  expect_printed_is_written(p, file.parent_path());
}

// Three nuts between plates, each F = a k r ((d - z) / r)^n h / (h - (d - z))
// past its zero z (0 before), with the macadamia's k = 1950 N/mm and
// h = 23.8 mm, r = 1 mm, written here; `scale` (a) and `zero` (m) per nut,
// the deflection to `most` (m), 0.5 N of noise. Returns the measurement.
fs::path formula_nuts(const std::string& name, double exponent, const double (&scale)[3], const double (&zero)[3],
                      double most, unsigned seed) {
  const fs::path dir = test::fresh_dir("gap", name);
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, 0.5);  // N
  for (int n = 0; n < 3; ++n) {
    std::string csv = "t,displacement,force\n";
    for (int i = 0; i <= 200; ++i) {
      const double d = most * i / 200, k = 1950e3, r = 1e-3, h = 23.8e-3;  // m, N/m
      const double x = d - zero[n];
      const double force = x > 0 ? scale[n] * k * r * std::pow(x / r, exponent) * h / (h - x) : 0.0;
      char row[96];
      std::snprintf(row, sizeof row, "%.3f,%.9g,%.6f\n", 0.025 * i, d, force + noise(random));
      csv += row;
    }
    write(dir / std::string("n").append(std::to_string(n)).append(".csv"), csv);
  }
  write(dir / "m.yaml", "measurement: nuts\nrig: plates\nactee: {file: " + kSource +
                            "/actees/macadamia.yaml}\ntraces: [n0.csv, n1.csv, n2.csv]\n");
  return dir / "m.yaml";
}

TEST(Gap, SpecimensOfOneShapeAndTheirOwnStiffness) {
  // Three Hertzian nuts (exponent 1.5), 0.8, 1.0 and 1.3 times as stiff.
  // No one law fits them together (unexplained); each with a stiffness of
  // its own, the exponent fitted on the other two is the shape's.
  const double scale[] = {0.8, 1.0, 1.3}, zero[] = {0, 0, 0};
  const fs::path file = formula_nuts("specimens", 1.5, scale, zero, 0.8e-3, 7);
  const Diagnosis d = diagnose(load_measurement(file.string()));
  EXPECT_EQ(d.verdict, Verdict::unexplained) << report_text(d);
  ASSERT_TRUE(d.specimens.computed) << report_text(d);
  const ShapeJudged& s = d.specimens.own_stiffness;
  EXPECT_NEAR(s.exponent, 1.5, 1e-3);
  EXPECT_LT(s.exponent_sigma, 1e-3);
  EXPECT_GT(s.shrink, 0.99) << report_text(d);
  // Least squares is linear in the measurement: each nut's own stiffness
  // is in the ratio of its scale, whatever the nominal law's shape.
  ASSERT_EQ(s.stiffness_factor.size(), 3u);
  EXPECT_NEAR(s.stiffness_factor[0] / s.stiffness_factor[1], 0.8, 1e-3);
  EXPECT_NEAR(s.stiffness_factor[2] / s.stiffness_factor[1], 1.3, 1e-3);
  // A power above 1 against a line: below it first, above it last.
  EXPECT_LT(d.specimens.first_third, 0);
  EXPECT_GT(d.specimens.last_third, 0);
  EXPECT_THAT(report_text(d), HasSubstr("(a soft toe)"));
  EXPECT_THAT(report_json(d), HasSubstr("\"specimens\":{\"effect\":\"actee_compliance\",\"exponent\":{\"value\":"));
}

TEST(Gap, SpecimensSeatedPastTheirZero) {
  // Three nuts of exponent 1.3, 0.8, 1.0 and 1.3 times as stiff, bearing
  // only from 0, 0.1 and 0.25 mm past their traces' zero. Judged with its
  // own zero, each nut's is found and the exponent is the law's; judged
  // without, the toe reads as a larger exponent.
  const double scale[] = {0.8, 1.0, 1.3}, zero[] = {0.0, 0.1e-3, 0.25e-3};
  const Diagnosis d = diagnose(load_measurement(formula_nuts("seated", 1.3, scale, zero, 0.9e-3, 11).string()));
  ASSERT_TRUE(d.specimens.computed) << report_text(d);
  const ShapeJudged& seated = d.specimens.own_zero;
  EXPECT_NEAR(seated.exponent, 1.3, 5e-3) << report_text(d);
  EXPECT_GT(seated.shrink, 0.95) << report_text(d);
  ASSERT_EQ(seated.zero.size(), 3u);
  for (size_t n = 0; n < 3; ++n) EXPECT_NEAR(seated.zero[n], zero[n], 5e-6) << report_text(d);
  // Without their zeros the toe reads as a steeper law, which fits worse.
  EXPECT_GT(d.specimens.own_stiffness.exponent, 1.4) << report_text(d);
  EXPECT_GT(d.specimens.own_stiffness.rmse_after, 5 * seated.rmse_after) << report_text(d);
  EXPECT_THAT(report_text(d), HasSubstr("if the soft toe is seating instead"));
  EXPECT_THAT(report_json(d), HasSubstr("\"own_zero\":{\"exponent\":{\"value\":"));
}

// ------------------------------------------------------------ real data

TEST(GapReal, MacadamiaCurvesArePowerLawsWithASoftToe) {
  // Five nuts between plates (../shared/data/real/macadamia, read in
  // place). Each nut alone: the power law fitted on its first half and
  // judged on its second, against the nominal linear 1950 N/mm.
  const std::string dir = std::string(AFFORD_SHARED_DIR) + "/data/real/macadamia";
  if (!fs::is_directory(dir)) GTEST_SKIP() << dir << " is absent: the real macadamia curves are not here";
  const Measurement m = load_measurement(kSource + "/measurements/macadamia-plates.yaml");
  ASSERT_EQ(m.traces.size(), 5u);
  const Model model = compile_actee_only(*m.actee, m.options);
  const std::vector<Replay> replays = replay_plates(model, m);
  for (size_t k = 0; k < replays.size(); ++k) {
    const Fitter own(model, replays, {k}, {k});
    const SetFit linear = own.fit({});
    const SetFit law = own.fit({EffectKind::actee_compliance});
    // The toe is soft and the curve stiffens: an exponent above 1.
    EXPECT_GT(law.effects[0].value[0], 1.1) << k;
    EXPECT_LT(law.effects[0].value[0], 2.5) << k;
    EXPECT_LT(law.rmse_test, 0.5 * linear.rmse_test) << k;
  }
  // Across nuts (cross-validated), one law for all explains nothing: the
  // nuts differ in stiffness more than in shape.
  const Diagnosis d = diagnose(m);
  EXPECT_EQ(d.folds, 5u);
  EXPECT_GT(d.rmse_before, 100.0);
  EXPECT_EQ(d.verdict, Verdict::unexplained) << report_text(d);
  // Each nut with a stiffness of its own, the shape is shared: a soft toe
  // and a stiffening, a power near Hertz's 1.5 fitted on the other nuts.
  // Measured: 1.47 +/- 0.13, shrink 0.45, stiffness 0.65 to 1.30 times the
  // nominal.
  ASSERT_TRUE(d.specimens.computed) << report_text(d);
  EXPECT_GT(d.specimens.own_stiffness.exponent, 1.2);
  EXPECT_LT(d.specimens.own_stiffness.exponent, 1.8);
  EXPECT_GT(d.specimens.own_stiffness.shrink, 0.3);
  EXPECT_LT(d.specimens.first_third, 0);
  EXPECT_GT(d.specimens.last_third, 0);
  // Read as seating (each nut its own zero too), the nuts agree on a
  // flatter power more closely. Measured: 1.23 +/- 0.03, shrink 0.53.
  const ShapeJudged& seated = d.specimens.own_zero;
  EXPECT_GT(seated.exponent, 1.1);
  EXPECT_LT(seated.exponent, 1.4);
  EXPECT_LT(seated.exponent_sigma, d.specimens.own_stiffness.exponent_sigma);
  EXPECT_GT(seated.shrink, 0.4);
}


TEST(Gap, APressesFrictionBesideItsProgressiveSpringInAStiffNutIsNamed) {
  // Most judged samples squeeze a stiff nut, whose contact passes the
  // angle's noise on (2828 samples). With the rate from its widest window
  // the floor is 0.225 N, and a progressive spring alone leaves 0.64 N:
  // the friction earns its place beside it. (With the narrow rate the
  // floor was 0.72 N, the spring alone reached it, and only a rule that
  // searched on past a set at the floor with a plain shape found the
  // friction; that rule is gone.)
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/press-friction-spring/measurement.yaml"));
  std::vector<EffectKind> named;
  for (const EffectFit& e : d.effects) named.push_back(e.kind);
  ASSERT_THAT(named, testing::UnorderedElementsAre(EffectKind::pivot_friction, EffectKind::progressive_spring))
      << report_text(d);
  for (const EffectFit& e : d.effects) {
    if (e.kind == EffectKind::pivot_friction) {
      EXPECT_NEAR(e.value[0], 0.03 + 0.139, 0.01) << report_text(d);  // N*m, the file's and the more, in all
    }
    if (e.kind == EffectKind::progressive_spring) {
      EXPECT_NEAR(e.value[0], 2.305e8, 0.1e8) << report_text(d);
    }
  }
}

TEST(Gap, APreloadToTheNoiseIsNotTakenForAGainErrorThatLeavesMore) {
  // The press turned on its side (development seed 6172, ODE), its spring
  // preloaded 1.554 N less than its file says. One gain on the effort
  // (-5.7 %) cuts 94 % of what the preload cuts held out, and the paired
  // test's batches tell them apart by only 2 standard errors, for the
  // gain's misfit gathers in a few strokes; yet it leaves 1.45 times the
  // noise's floor where the preload leaves the floor. That is not a gain
  // explaining the gap as well: the preload is named.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/press-preload-turned/measurement.yaml"));
  EXPECT_EQ(d.verdict, Verdict::explained) << report_text(d);
  ASSERT_EQ(d.effects.size(), 1u) << report_text(d);
  EXPECT_EQ(d.effects[0].kind, EffectKind::spring_preload) << report_text(d);
  EXPECT_NEAR(d.effects[0].value[0], 4 - 1.554, 0.05) << report_text(d);  // N, the file's 4 N and the change
  EXPECT_TRUE(std::isnan(d.gain_alike)) << report_text(d);
}

TEST(Gap, APairThatALookAlikePairFitsAsWellIsNotNamedAlone) {
  // The snips' progressive spring and lower preload, on one trace of
  // closing-only strokes one way up (development seed 6560, ODE): neither
  // alone cuts as much as a weight, whose cosine over the travel stands in
  // for both, and a late sensor then takes the gap to the noise. The pair
  // of truth was never compared with it step by step; held out, it fits
  // as well. Named alone, the weight and the late sensor were a confident
  // look-alike.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/snips-spring-preload-closing/measurement.yaml"));
  EXPECT_EQ(d.verdict, Verdict::ambiguous) << report_text(d);
  const std::vector<EffectKind> truth = {EffectKind::spring_preload, EffectKind::progressive_spring};
  const std::vector<EffectKind> alike = {EffectKind::gravity, EffectKind::sensor_latency};
  EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(truth))) << report_text(d);
  EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(alike))) << report_text(d);
  EXPECT_LE(d.ambiguous.size(), 3u) << report_text(d);
  EXPECT_THAT(report_text(d), testing::HasSubstr("among every pair that explains")) << report_text(d);
}

TEST(Gap, ASetALookAlikeMakesAgainIsListedOnce) {
  // The heavy press turned, its preload and progressive spring both more
  // than its file's, cracking a walnut in the first cycle (development
  // seed 9079, ODE). A weight one way up stands in for either; the
  // search among every pair listed the spring with the weight, and the
  // weight put in the preload's place made that pair again in the other
  // order: four sets listed, three of them different.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/press-preload-spring-walnut/measurement.yaml"));
  EXPECT_EQ(d.verdict, Verdict::ambiguous) << report_text(d);
  const std::vector<EffectKind> truth = {EffectKind::spring_preload, EffectKind::progressive_spring};
  EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(truth))) << report_text(d);
  std::vector<std::vector<EffectKind>> sorted = d.ambiguous;
  for (auto& set : sorted) std::sort(set.begin(), set.end());
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << report_text(d);
  EXPECT_EQ(d.ambiguous.size(), 3u) << report_text(d);
  // The text lists the sets as good as the named one, not the named one
  // again; and the weight stands in for one effect at a time here (the
  // three at once are not listed), so the text does not say "nor from
  // both" of the weight and the preload a listed pair happens to hold.
  const std::string text = report_text(d);
  EXPECT_THAT(text, testing::Not(testing::HasSubstr("as good: spring_preload + progressive_spring"))) << text;
  EXPECT_THAT(text, testing::HasSubstr("cannot tell spring_preload from gravity (cosine")) << text;
  EXPECT_THAT(text, testing::HasSubstr("over 4 folds of 4 blocks of 1 trace (fitted samples")) << text;
}

TEST(Gap, AProgressiveSpringReadByALateSensorIsFoundWithTheDelayFittedBesideADamping) {
  // The snips' progressive spring (7.347e4 N/m^3) and force sensor 50 ms
  // late (development seed 6293, ODE). The delay that decides which late
  // readings are left out, fitted with friction and an inertia beside it,
  // came out at 0: nothing was left out, and the pair left 1.37 times the
  // floor held out (`unexplained`, in both engines). A delay at the
  // search's end says nothing of the delay; fitted again with a damping
  // beside it (on a spring a late sensor reads as a negative one) it
  // comes out at 62 ms, the readings after each turn are left out, and
  // the pair is fitted to the floor.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/snips-spring-late-sensor/measurement.yaml"));
  expect_explained_by(d, {{EffectKind::progressive_spring, 7.347e4, 0.05 * 7.347e4},  // N/m^3
                          {EffectKind::sensor_latency, 0.050, 0.002}});                 // s
}

TEST(Gap, AWeightReadByALateSensorIsFoundWhereTheFirstDelayIsUnderOneSample) {
  // The snips turned 90 deg, a weight of 0.07709 N*m and a force sensor
  // 50 ms late (development seed 7062, ODE). The first delay came out at
  // 0.85 ms: under the 1 ms sampling step, it leaves out only the first
  // reading of each stretch, and says as little of the delay as 0. Fitted
  // again beside a damping it comes out at 40 ms and earns its place by
  // the training AICc (by 165), though the RMSE it cuts is only what lies
  // over the noise (2.1 %); the pair is then fitted to the floor.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/snips-weight-late-sensor/measurement.yaml"));
  expect_explained_by(d, {{EffectKind::gravity, 0.07709, 0.05 * 0.07709},  // N*m
                          {EffectKind::sensor_latency, 0.050, 0.002}});       // s
}

TEST(Gap, ADelayThatWouldLeaveNothingToJudgeLeavesNoReadingOut) {
  // The press cracks its walnut at once and strokes quickly between turns
  // (57 ms of free motion between them), with a damping and a weight its
  // file lacks and a sensor that is not late (development seed 6404,
  // MuJoCo). At one speed a damping reads as a late sensor: the delay
  // fitted to decide which readings are left out came out at 80 ms, longer
  // than each stretch of free motion, and left none (`unexplained`, nothing
  // to judge). Such a delay cannot be judged itself; the readings stay, and
  // the pair is among the sets named.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/press-damping-weight-quick-strokes/measurement.yaml"));
  ASSERT_TRUE(d.verdict == Verdict::explained || d.verdict == Verdict::ambiguous) << report_text(d);
  const std::vector<EffectKind> truth = {EffectKind::gravity, EffectKind::viscous_damping};
  if (d.verdict == Verdict::ambiguous) {
    EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(truth))) << report_text(d);
    EXPECT_LE(d.ambiguous.size(), 3u) << report_text(d);
  } else {
    expect_explained_by(d, {{EffectKind::gravity, 0.24, 0.05 * 0.24},                  // N*m
                            {EffectKind::viscous_damping, 0.302, 0.05 * 0.302}});     // N*m*s/rad
  }
}

TEST(Gap, AnArmInertiaIsNotJudgedWorseForTheNoiseItsOwnPredictionCarries) {
  // The nutcracker squeezing a pecan lightly on a quick sine of 3 deg
  // (development seed 9356, ODE), with an arm inertia of 0.002 kg*m^2 its
  // file lacks. The inertia passes the angle's noise on, differentiated
  // twice: alone it leaves 0.084 N held out, at its floor of 0.085 N,
  // white. A progressive spring takes the part that follows the angle and
  // leaves 0.070 N, nearer the sensor's 0.048 N but with a shape (Ljung-Box
  // Q 203), and nothing earns a place beside it. Judged by what each
  // leaves beyond its own prediction's noise, the inertia is not worse,
  // and it is named where the diagnosis read `unexplained`.
  const Diagnosis d = diagnose(load_measurement(kSource + "/tests/data/gap/nutcracker-inertia-pecan/measurement.yaml"));
  expect_explained_by(d, {{EffectKind::arm_inertia, 0.002, 0.05 * 0.002}});  // kg*m^2
  EXPECT_TRUE(d.residual.white) << report_text(d);
}

TEST(Gap, ADampingIsNotJudgedWorseAtAStepForTheNoiseItsOwnPredictionCarries) {
  // The tongs cracking an egg in the first cycle and going on, on an
  // uneven triangle (development seed 9434, ODE), with a friction and a
  // damping their file lacks. At one speed closing and another opening a
  // damping reads as a friction and a constant torque, so after the
  // friction a weight (0.0789 N held out, at its floor of 0.0798 N) and
  // the true damping (0.0823 N, at its floor of 0.0826 N: the angle's rate
  // noise it passes on) fit alike. Judged by the raw held-out errors, the
  // damping was worse by that noise alone, and the truth was left out of
  // the sets as good.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/tongs-friction-damping-uneven-strokes/measurement.yaml"));
  EXPECT_EQ(d.verdict, Verdict::ambiguous) << report_text(d);
  const std::vector<EffectKind> truth = {EffectKind::pivot_friction, EffectKind::viscous_damping};
  EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(truth))) << report_text(d);
  EXPECT_LE(d.ambiguous.size(), 3u) << report_text(d);
}

TEST(Gap, AnEffectWhoseLookAlikesCannotTakeItsPartAloneIsListedWithEachBesideIt) {
  // The snips on closing-only strokes one way up (development seed 9374,
  // ODE), with a weight and a weaker preload their file lacks: a weight
  // of 0.146 N*m takes both. Friction and a preload each look like it,
  // but alone would need a negative friction or a preload that pulls the
  // snips shut, outside their ranges; a share of either beside the weight
  // fits as well. Where the weight had one look-alike that pair was
  // listed; with two, the weight was named alone, a confident half.
  const Diagnosis d =
      diagnose(load_measurement(kSource + "/tests/data/gap/snips-weight-weaker-preload-closing/measurement.yaml"));
  EXPECT_EQ(d.verdict, Verdict::ambiguous) << report_text(d);
  const std::vector<std::vector<EffectKind>> sets = {
      {EffectKind::gravity},
      {EffectKind::gravity, EffectKind::pivot_friction},
      {EffectKind::gravity, EffectKind::spring_preload},
  };
  ASSERT_EQ(d.ambiguous.size(), sets.size()) << report_text(d);
  for (const std::vector<EffectKind>& set : sets) {
    EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(set))) << report_text(d);
  }
}

TEST(Gap, AThirdEffectThatLeavesTheHeldOutSamplesOverTheNoiseHasNotExplainedTheGap) {
  // The same snips with the damping withheld from the library: the delay
  // that leaves readings out stays at 0 (no damping to fit it again
  // beside), and the pair leaves 1.37 times the noise's floor held out, an arm's
  // inertia added to it 1.29 times, its residual white in sample. A
  // third effect is asked for only where a pair fell short; white on the
  // samples it was fitted to, it has chased what the pair left, and does
  // not explain samples it predicts this far off (that verdict named the
  // inertia with the pair).
  const Diagnosis d = diagnose(load_measurement(kSource + "/tests/data/gap/snips-spring-late-sensor/measurement.yaml"),
                               every_effect_but(EffectKind::viscous_damping));
  EXPECT_EQ(d.verdict, Verdict::unexplained) << report_text(d);
  EXPECT_EQ(d.effects.size(), 3u) << report_text(d);  // fitted, not enough
  EXPECT_GT(d.rmse_after, 1.15 * d.noise_through_model) << report_text(d);
  EXPECT_TRUE(d.residual.white) << report_text(d);
  EXPECT_GT(d.shrink, 0.8) << report_text(d);
}

TEST(Gap, ASecondEffectThatTheShapeLeftBesideAMatchedFirstAsksForIsFound) {
  // The tongs squeezing an egg, turned 90 deg (development seed 6531,
  // ODE): a preload 3.2 N higher and a weight of 0.24 N*m. The preload
  // alone left 1.1 times the floor held out, within the tolerance, with a
  // shape just over the whiteness test's point (Q 63 against 37.6) that
  // follows the angle: the weight, whose cosine over the travel is not
  // quite the preload's constant. Named alone, the preload was a confident
  // half of the truth; the search goes on while the residual keeps a
  // shape, and the weight earns its place.
  const Diagnosis d = diagnose(load_measurement(kSource + "/tests/data/gap/tongs-weight-preload-egg/measurement.yaml"));
  EXPECT_EQ(d.verdict, Verdict::ambiguous) << report_text(d);
  const std::vector<EffectKind> truth = {EffectKind::spring_preload, EffectKind::gravity};
  EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(truth))) << report_text(d);
  EXPECT_LE(d.ambiguous.size(), 3u) << report_text(d);
  const EffectFit* weight = find(d, EffectKind::gravity);
  ASSERT_NE(weight, nullptr) << report_text(d);
  EXPECT_NEAR(weight->value[0], 0.24, 0.03) << report_text(d);  // N*m
  EXPECT_TRUE(d.residual.white) << report_text(d);
}

TEST(Gap, ARunnerUpThatLeavesTheGapUnexplainedWhereTheBestExplainsItIsNotAsGood) {
  // The tongs squeezing an egg lightly on a sine, one way up (development
  // seed 6039, ODE): a preload 0.038 N*m lower and a damping of 0.169
  // N*m*s/rad. A weight and a progressive spring are look-alikes of the
  // preload here, so three pairs with the damping explain the gap alike.
  // A friction in the damping's place cut nearly as much and the paired
  // test's batches did not tell it apart, but it leaves 1.5 times the
  // floor held out: it was listed as well, five sets in all.
  const Measurement m = load_measurement(kSource + "/tests/data/gap/tongs-preload-damping-egg/measurement.yaml");
  const Diagnosis d = diagnose(m);
  EXPECT_EQ(d.verdict, Verdict::ambiguous) << report_text(d);
  const std::vector<EffectKind> truth = {EffectKind::spring_preload, EffectKind::viscous_damping};
  EXPECT_THAT(d.ambiguous, testing::Contains(testing::UnorderedElementsAreArray(truth))) << report_text(d);
  EXPECT_LE(d.ambiguous.size(), 3u) << report_text(d);
  for (const std::vector<EffectKind>& set : d.ambiguous) {
    EXPECT_THAT(set, testing::Not(testing::Contains(EffectKind::pivot_friction))) << report_text(d);
  }
  const EffectFit* damping = find(d, EffectKind::viscous_damping);
  ASSERT_NE(damping, nullptr) << report_text(d);
  EXPECT_NEAR(damping->value[0], 0.169, 0.01) << report_text(d);  // N*m*s/rad

  // On its own, the friction's pair is unexplained: the runner-up the
  // search no longer lists.
  DiagnoseOptions friction_pair;
  friction_pair.library = {EffectKind::spring_preload, EffectKind::pivot_friction};
  const Diagnosis f = diagnose(m, friction_pair);
  EXPECT_EQ(f.verdict, Verdict::unexplained) << report_text(f);
  EXPECT_GT(f.rmse_after, 1.3 * f.noise_through_model) << report_text(f);
}

TEST(Gap, APairWhiteInSampleThatMissesTheHeldOutSamplesFarHasNotExplainedTheGap) {
  // The nutcracker cracking a hazelnut in its first cycle and going on,
  // its friction 0.076 N*m over its file's (development seed 6291, ODE),
  // with friction left out of the library. A damping and a late sensor,
  // fitted to three blocks of 250 samples, leave a residual white in
  // sample and twice the floor held out: they have not explained the gap.
  const Measurement m = load_measurement(kSource + "/tests/data/gap/nutcracker-friction-hazelnut/measurement.yaml");
  const Diagnosis all = diagnose(m);
  EXPECT_EQ(all.verdict, Verdict::explained) << report_text(all);
  ASSERT_EQ(all.effects.size(), 1u) << report_text(all);
  EXPECT_EQ(all.effects[0].kind, EffectKind::pivot_friction) << report_text(all);

  DiagnoseOptions without_friction;
  without_friction.library = {EffectKind::viscous_damping, EffectKind::spring_preload, EffectKind::progressive_spring,
                              EffectKind::arm_inertia,     EffectKind::gravity,        EffectKind::sensor_latency,
                              EffectKind::actee_compliance};
  const Diagnosis d = diagnose(m, without_friction);
  EXPECT_EQ(d.verdict, Verdict::unexplained) << report_text(d);
  EXPECT_TRUE(d.residual.white) << report_text(d);
  EXPECT_GT(d.rmse_after, 1.5 * d.noise_through_model) << report_text(d);
}

// The step a measured column is counted in, worked by hand: an encoder's
// count of 2 pi / 34925 rad = 1.799e-4 rad, printed to 1e-7 rad; a
// converter's bit of 0.110328 N printed to 1e-6 N.

// Counts of `step` from `offset` at each of `counts`, printed to `printed`.
std::vector<double> counted(double offset, double step, double printed, const std::vector<long>& counts) {
  std::vector<double> out;
  for (long k : counts) out.push_back(std::round((offset + static_cast<double>(k) * step) / printed) * printed);
  return out;
}

TEST(CountedStep, AnEncodersCountIsFoundFromTheChangesBetweenSamples) {
  // A slow sine of 40 counts about count 1340, 1 s at 1 kHz: the count
  // stays for samples on end, then moves by one.
  const double count = 2 * kPi / 34925;  // rad
  std::vector<long> counts;
  for (int i = 0; i < 1000; ++i) counts.push_back(std::lround(1340 + 40 * std::sin(2 * kPi * i / 1000.0)));
  EXPECT_NEAR(counted_step(counted(0.3, count, 1e-7, counts), 1e-7), count, 2e-8);
}

TEST(CountedStep, AConvertersBitIsFoundUnderNoiseOfManyBits) {
  // 0.178 N of noise read in bits of 0.110328 N, printed to 1e-6 N: most
  // changes are several bits; the least, one.
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.178 / 0.110328);
  std::vector<long> counts;
  for (int i = 0; i < 2000; ++i) counts.push_back(std::lround(30 + noise(random)));
  EXPECT_NEAR(counted_step(counted(0.0, 0.110328, 1e-6, counts), 1e-6), 0.110328, 2e-6);
}

TEST(CountedStep, ValuesFreeOfAnyCountHaveNone) {
  std::mt19937 random(4);
  std::normal_distribution<double> noise(0.0, 1e-4);
  std::vector<double> values;
  for (int i = 0; i < 5000; ++i) values.push_back(std::round((0.3 + noise(random)) / 1e-9) * 1e-9);
  EXPECT_EQ(counted_step(values, 1e-9), 0.0);
}

// 100 samples from `start`, each changed from the last by the next of
// `changes` in turn, up and down by turns so the column stays near `start`.
std::vector<double> changed_by(double start, const std::vector<double>& changes) {
  std::vector<double> out = {start};
  for (size_t i = 0; out.size() < 100; ++i) out.push_back(out.back() + (i % 2 ? -1 : 1) * changes[i % changes.size()]);
  return out;
}

TEST(CountedStep, AStepTheDigitsAloneMakeIsNoCount) {
  // Printed to 1e-4 and changing by 1e-4 or 2e-4: the printing's step.
  EXPECT_EQ(counted_step(changed_by(0.1, {1e-4, 2e-4, 1e-4}), 1e-4), 0.0);
  // 5e-4 is only five printed steps: too few to tell a count from them.
  EXPECT_EQ(counted_step(changed_by(0.1, {5e-4, 1e-3, 5e-4}), 1e-4), 0.0);
  // As a check on the two: 2e-3 is twenty, and is a count.
  EXPECT_NEAR(counted_step(changed_by(0.1, {2e-3, 4e-3, 2e-3}), 1e-4), 2e-3, 1e-5);
}

TEST(CountedStep, ChangesNoOneStepDividesHaveNone) {
  // 1, 1.5 and 2.7 thousandths: the least change is no count.
  EXPECT_EQ(counted_step(changed_by(0.0, {1e-3, 1.5e-3, 2.7e-3}), 1e-7), 0.0);
  // A still column, one too short to change, one that changes once, and
  // one with too few single steps (one of 1e-3, the rest two or three).
  EXPECT_EQ(counted_step(std::vector<double>(100, 0.5), 1e-7), 0.0);
  EXPECT_EQ(counted_step({0.5}, 1e-7), 0.0);
  std::vector<double> once(100, 0.5);
  std::fill(once.begin() + 50, once.end(), 0.4);
  EXPECT_EQ(counted_step(once, 1e-7), 0.0);
  std::vector<double> rare = changed_by(0.0, {2e-3, 3e-3});
  rare.push_back(rare.back() + 1e-3);
  EXPECT_EQ(counted_step(rare, 1e-7), 0.0);
}

}  // namespace
}  // namespace afford::test
