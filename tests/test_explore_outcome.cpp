// afford explore's outcome (issue 26, item 7): the function models' own
// order of strength (rules/functions.yaml `strength`), a point's outcome as
// the strongest function reached while the effort was applied, efforts past
// a grasp's cap pushed at the cap and said so, each actee's effort axis
// fitted to its turns, grid values that print short, alike grasps merged.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "effort_axes.h"
#include "grid_axis.h"
#include "outcome.h"
#include "reports.h"
#include "rules.h"
#include "test_util.h"

namespace afford {
namespace {
using test::kSource;

using ::testing::HasSubstr;


// --- the order of strength, as data -------------------------------------

// Three functions a, b, c (in that order in the file) and a `strength` line.
std::string three_functions(const std::string& strength) {
  std::string yaml = "functions:\n";
  for (const char* name : {"a", "b", "c"}) {
    yaml += std::string("  - name: ") + name + "\n    description: test\n    nodes:\n      - when: time > 0 s\n";
  }
  return yaml + strength;  // the strength line is line 14
}

std::string rules_error(const std::string& yaml) {
  return test::thrown([&] { (void)read_rules(yaml, "rules.yaml"); });
}

int strength_of(const RuleSet& rules, const std::string& name) {
  for (int f = 0; f < function_count(rules); ++f) {
    if (function_name(rules, f) == name) return function_strength(rules, f);
  }
  return -1;
}

TEST(FunctionStrength, TheShippedModelsGoFromPinchToCrash) {
  const auto rules = load_rules(kSource + "/rules/functions.yaml");
  EXPECT_EQ(strength_of(*rules, "pinch"), 0);
  EXPECT_EQ(strength_of(*rules, "hold"), 1);
  EXPECT_EQ(strength_of(*rules, "carry"), 2);
  EXPECT_EQ(strength_of(*rules, "crash"), 3);
}

TEST(FunctionStrength, TheListRanksWeakestFirstAndWithoutItTheFileDoes) {
  const auto listed = read_rules(three_functions("strength: [c, a, b]\n"), "rules.yaml");
  EXPECT_EQ(strength_of(*listed, "c"), 0);
  EXPECT_EQ(strength_of(*listed, "a"), 1);
  EXPECT_EQ(strength_of(*listed, "b"), 2);
  const auto unlisted = read_rules(three_functions(""), "rules.yaml");
  EXPECT_EQ(strength_of(*unlisted, "a"), 0);
  EXPECT_EQ(strength_of(*unlisted, "b"), 1);
  EXPECT_EQ(strength_of(*unlisted, "c"), 2);
}

TEST(FunctionStrength, ABadListIsALocatedError) {
  // "strength: [a, bb, c]": bb at line 14, column 15.
  std::string e = rules_error(three_functions("strength: [a, bb, c]\n"));
  EXPECT_THAT(e, HasSubstr("rules.yaml:14:15:"));
  EXPECT_THAT(e, HasSubstr("expected the name of a function in this file, found 'bb' (did you mean 'b'?)"));
  e = rules_error(three_functions("strength: [a, b, a]\n"));
  EXPECT_THAT(e, HasSubstr("rules.yaml:14:18:"));
  EXPECT_THAT(e, HasSubstr("expected each function once, found 'a' again"));
  e = rules_error(three_functions("strength: [a, c]\n"));
  EXPECT_THAT(e, HasSubstr("rules.yaml:14:11:"));
  EXPECT_THAT(e, HasSubstr("expected every function of the file, once, found no 'b'"));
  e = rules_error(three_functions("strength: c\n"));
  EXPECT_THAT(e, HasSubstr("rules.yaml:14:11:"));
  e = rules_error(three_functions("strenght: [a, b, c]\n"));
  EXPECT_THAT(e, HasSubstr("rules.yaml:14:1:"));
  EXPECT_THAT(e, HasSubstr("strength"));
}

// --- the outcome of a point, from its events -----------------------------

// Four functions ranked as the shipped ones: pinch 0, hold 1, carry 2, crash 3.
enum F { pinch, hold, carry, crash };
const std::vector<int> kRanks = {0, 1, 2, 3};

struct Frame {
  double t;
  std::vector<Event> events;
  bool broken = false;
  bool grasped = true;
};

Event inferred(F f, double t) { return {EventKind::inferred, t, f, 0}; }
Event lost(F f, double t) { return {EventKind::node_lost, t, f, 0}; }

OutcomeWatch watch(const std::vector<Frame>& frames, std::vector<int> ranks = kRanks, double applied_at = 1.3) {
  OutcomeWatch w(std::move(ranks), applied_at);
  for (const Frame& f : frames) w.frame(f.t, f.events.data(), f.events.data() + f.events.size(), f.broken, f.grasped);
  return w;
}

TEST(PointOutcome, AHoldLostOnTheWayUpDoesNotCount) {
  // A sponge: pinched at 0.3 s, held at 0.64 s while the squeeze is below its
  // limit, lost at 0.8 s when the squeeze passes it; the effort is applied
  // from 1.3 s on, with only the pinch in force.
  const OutcomeWatch w = watch({{0.3, {inferred(pinch, 0.3)}},
                                {0.64, {inferred(hold, 0.64)}},
                                {0.8, {lost(hold, 0.8)}},
                                {1.3, {}},
                                {3.0, {}}});
  EXPECT_EQ(w.outcome(), pinch);
  EXPECT_DOUBLE_EQ(w.window_from(), 1.3);
}

TEST(PointOutcome, TheStrongestInForceWhileAppliedWinsNotTheLast) {
  // Carried at 2.9 s, then (a user's model) pinch inferred again at 3.0 s:
  // the strongest, carry, not the last.
  const OutcomeWatch w = watch({{0.3, {inferred(pinch, 0.3)}},
                                {0.6, {inferred(hold, 0.6)}},
                                {1.3, {lost(pinch, 1.3)}},
                                {2.9, {inferred(carry, 2.9)}},
                                {3.0, {inferred(pinch, 3.0)}}});
  EXPECT_EQ(w.outcome(), carry);
  // The same events, the order of strength reversed (crash 0 ... pinch 3).
  const OutcomeWatch reversed = watch({{0.3, {inferred(pinch, 0.3)}},
                                       {0.6, {inferred(hold, 0.6)}},
                                       {1.3, {lost(pinch, 1.3)}},
                                       {2.9, {inferred(carry, 2.9)}},
                                       {3.0, {inferred(pinch, 3.0)}}},
                                      {3, 2, 1, 0});
  EXPECT_EQ(reversed.outcome(), pinch);
}

TEST(PointOutcome, ABreakOnTheWayUpOpensTheWindow) {
  // A walnut cracks at 0.9 s, before the push reaches the effort (1.3 s):
  // crash is inferred in that frame and lost 1 ms later (the jaws pass
  // through); the break is for good, so the window opens at 0.9 s.
  const OutcomeWatch w = watch({{0.3, {inferred(pinch, 0.3)}},
                                {0.6, {inferred(hold, 0.6)}},
                                {0.9, {lost(hold, 0.9), inferred(crash, 0.9)}, true},
                                {0.901, {lost(crash, 0.901), lost(pinch, 0.901)}, true},
                                {1.3, {}, true}});
  EXPECT_EQ(w.outcome(), crash);
  EXPECT_DOUBLE_EQ(w.window_from(), 0.9);
}

TEST(PointOutcome, MomentsWhileTheToolIsReleasedDoNotCount) {
  // Carry inferred at 2.0 s in a frame where the hand has let go of the
  // tool, lost at once: only the hold (in force while grasped) counts.
  const OutcomeWatch w = watch({{0.6, {inferred(hold, 0.6)}},
                                {1.3, {}},
                                {2.0, {inferred(carry, 2.0)}, false, false},
                                {2.001, {lost(carry, 2.001)}}});
  EXPECT_EQ(w.outcome(), hold);
  EXPECT_EQ(watch({{0.5, {}}}).outcome(), -1);
  EXPECT_EQ(watch({{0.5, {}}}).window_from(), -1);
}

// --- grid values -----------------------------------------------------------

TEST(GridAxis, ValuesAreTheDoubleNearestAShortDecimal) {
  // The 21st of 41 steps from 30 to 52.5 mm, 0.03 + (0.0525 - 0.03) * 20 /
  // 40, is 0.041249999999999995 in doubles (printed so by points.csv
  // before); 0.08 + 0.07 / 2 is 0.11499999999999999.
  const double step20 = 0.03 + (0.0525 - 0.03) * 20 / 40;
  EXPECT_NE(step20, 0.04125);
  EXPECT_EQ(tidy(step20), 0.04125);
  const std::vector<double> thumbs = spread(0.08, 0.15, 3);
  ASSERT_EQ(thumbs.size(), 3u);
  EXPECT_EQ(thumbs[0], 0.08);
  EXPECT_EQ(thumbs[1], 0.115);
  EXPECT_EQ(thumbs[2], 0.15);
  EXPECT_EQ(spread(0.185, 0.24, 1), std::vector<double>{0.2125});
  EXPECT_EQ(tidy(-1.0), -1.0);
  EXPECT_EQ(tidy(0.0), 0.0);
}

TEST(GridAxis, TheEffortAxisEndsALittleAboveTheLastTurnOnANiceStep) {
  // 9 efforts (8 steps): a turn at 23.5 N wants a step of 1.1 * 23.5 / 8 =
  // 3.23 N, so 4 N, and the axis ends at 32 N.
  EXPECT_DOUBLE_EQ(effort_axis_top(23.5, 9, 400, 0.5), 32);
  // 107.3 N: 1.1 * 107.3 / 8 = 14.75 N, so 15 N, to 120 N.
  EXPECT_DOUBLE_EQ(effort_axis_top(107.3, 9, 400, 0.5), 120);
  // 3 efforts: a turn at 160.3 N wants 1.1 * 160.3 / 2 = 88.2 N, so 100 N, to 200 N.
  EXPECT_DOUBLE_EQ(effort_axis_top(160.3, 3, 400, 0.5), 200);
  // 380 N: 52.25 N, so 60 N, 480 N: the hand's 400 N instead.
  EXPECT_DOUBLE_EQ(effort_axis_top(380, 9, 400, 0.5), 400);
  // A turn at 0.5 N wants 0.069 N, finer than the 0.5 N the thresholds are
  // found to: a step of 0.5 N, to 4 N.
  EXPECT_DOUBLE_EQ(effort_axis_top(0.5, 9, 400, 0.5), 4);
  // No turn: the whole axis.
  EXPECT_DOUBLE_EQ(effort_axis_top(-1, 9, 400, 0.5), 400);
}

// --- a grid on the shipped tongs ---------------------------------------------

ExploreFiles tongs_with(const std::vector<std::string>& actees) {
  ExploreFiles f;
  f.object = kSource + "/objects/tongs.yaml";
  f.agent = kSource + "/agents/hand.yaml";
  f.rules = kSource + "/rules/functions.yaml";
  f.grasps = kSource + "/rules/grasps.yaml";
  for (const std::string& a : actees) f.actees.push_back(kSource + "/actees/" + a);
  return f;
}


TEST(ExploreOutcome, ASpongeSqueezedPastItsLimitIsPinchedNotHeld) {
  GridOptions grid;
  grid.placements = 1;  // 212.5 mm
  grid.thumbs = 2;      // 80 and 150 mm
  grid.efforts = 2;
  grid.grasps = {"medium_wrap"};
  const Explorer e = make_explorer(tongs_with({"sponge.yaml"}), grid);
  const int hold = test::index_of(e.grid.functions, "hold"), pinch = test::index_of(e.grid.functions, "pinch");
  const int carry = test::index_of(e.grid.functions, "carry");
  // 40 N at the thumb, 80 mm from the hinge: 3.2 N*m, less at most the
  // spring's 10.2 N * 40 mm = 0.41 N*m fully closed, over a jaw at most
  // 240 mm long: at least 2.79 / 0.24 = 11.6 N at the sponge, past its 8 N.
  // On the way up (1 s) the squeeze is below 8 N long enough (300 ms) for a
  // hold, lost before the push gets to 40 N at 1.3 s.
  const PointResult r = run_point(e, {0, 0, 0, 0, 0}, 40.0);
  EXPECT_GT(r.peak_actee_force, 11.6);
  EXPECT_GT(r.first[static_cast<size_t>(hold)], 0.3);
  EXPECT_LT(r.first[static_cast<size_t>(hold)], 1.3);
  EXPECT_DOUBLE_EQ(r.applied_from, 1.3);
  EXPECT_EQ(r.outcome, pinch);
  // 4 N at the thumb: 0.32 N*m, over at least 165 mm (the sponge, 95 mm
  // long, reaches from 212.5 - 47.5 mm), is at most 1.94 N at the sponge
  // (the spring only takes from it), below 8 N: held, then carried when lifted.
  const PointResult light = run_point(e, {0, 0, 0, 0, 0}, 4.0);
  EXPECT_LT(light.peak_actee_force, 1.94);
  EXPECT_EQ(light.outcome, carry);
}

TEST(ExploreOutcome, NoSpongePointEndsInAHold) {
  // Held and below its limit when the push arrives, the sponge is carried
  // when the hand lifts; past its limit it is only pinched. A hold is never
  // the strongest (the "hold above carry" of issue 26).
  GridOptions grid;
  grid.placements = 2;
  grid.thumbs = 2;
  grid.efforts = 5;
  grid.grasps = {"medium_wrap"};
  Explorer e = make_explorer(tongs_with({"sponge.yaml"}), grid);
  fit_effort_axes(e, 2);
  const ExploreResult r = explore(e, Shard{}, 2);
  const int hold = test::index_of(e.grid.functions, "hold");
  for (const SeriesResult& s : r.series) {
    for (const PointResult& p : s.points) EXPECT_NE(p.outcome, hold);
    for (const Threshold& t : s.thresholds) EXPECT_NE(t.to, hold);
  }
  EXPECT_THAT(summary_text(e.grid, r), ::testing::Not(HasSubstr("ends in hold")));
}

TEST(ExploreOutcome, EffortsPastAGraspsCapArePushedAtTheCap) {
  GridOptions grid;
  grid.placements = 1;
  grid.thumbs = 1;
  grid.efforts = 5;  // 0, 100, 200, 300, 400 N
  grid.grasps = {"tip_pinch"};
  grid.scale_efforts = false;
  const Explorer e = make_explorer(tongs_with({"egg.yaml"}), grid);
  // tip_pinch pushes at most 65 N (rules/grasps.yaml).
  ASSERT_DOUBLE_EQ(e.grid.grasp_limit[0], 65);
  EXPECT_DOUBLE_EQ(applied_effort(e.grid, 0, 100), 65);
  EXPECT_DOUBLE_EQ(applied_effort(e.grid, 0, 40), 40);
  const ExploreResult r = explore(e, Shard{}, 2);
  const SeriesResult& s = r.series.at(0);
  // 100 to 400 N are one run at 65 N.
  for (size_t i = 2; i < 5; ++i) EXPECT_EQ(s.points[i].peak_effort, s.points[1].peak_effort);
  EXPECT_LT(s.points[1].peak_effort, 65.5);
  // Every turn lies below the cap.
  for (const Threshold& t : s.thresholds) EXPECT_LE(t.effort, 65);
  const std::string csv = points_csv(e.grid, r);
  EXPECT_THAT(csv, HasSubstr(",tip_pinch,400,65,"));
  EXPECT_THAT(csv, HasSubstr(",tip_pinch,0,0,"));
  EXPECT_THAT(summary_text(e.grid, r), HasSubstr("tip_pinch pushes at most 65 N: efforts above it are pushed at it"));
}

TEST(ExploreOutcome, TheEggsAxisEndsAboveItsCrackAndTheWrapsShareARow) {
  GridOptions grid;
  grid.placements = 1;  // 212.5 mm
  grid.thumbs = 1;      // 115 mm
  grid.efforts = 9;
  grid.grasps = {"small_wrap", "medium_wrap", "tip_pinch"};
  Explorer e = make_explorer(tongs_with({"egg.yaml"}), grid);
  fit_effort_axes(e, 2);
  const ExploreResult r = explore(e, Shard{}, 2);
  const GridInfo& g = e.grid;
  // The egg (radii 28.5, 21.5 mm) at 212.5 mm under the moving jaw (tongs
  // rest at 18 deg): pushed with the lever arm D of test_util.h. Its 35 N
  // need 35 D / 0.115 at the thumb, plus the spring (4 N preload, 500 N/m at
  // 40 mm: at most 10.2 N * 40 / 115 = 3.55 N) and the pivot's friction
  // (0.005 N*m / 0.115 m = 0.04 N).
  const test::JawTouch touch = test::ellipsoid_under_jaw(0.0285, 0.0215, 0.2125, 18 * std::numbers::pi / 180);
  const double needed = 35 * touch.lever / 0.115;  // N
  // D = 209.3 mm (theta_c = 11.64 deg): needed = 63.70 N.
  EXPECT_NEAR(needed, 63.70, 0.01);
  const SeriesResult& wrap = r.series.at(0);
  ASSERT_FALSE(wrap.thresholds.empty());
  const Threshold& last = wrap.thresholds.back();
  EXPECT_EQ(last.to, test::index_of(g.functions, "crash"));
  EXPECT_GE(last.effort, needed);
  // The hand's push when the shell cracked (the effort asked for, which the
  // generated squeeze reaches only to within a newton or so).
  EXPECT_GE(last.at.peak_effort, needed);
  EXPECT_LE(last.at.peak_effort, needed + 3.55 + 0.04 + g.tolerance);
  // The axis: 9 efforts from 0 N to effort_axis_top of the last turn.
  const std::vector<double>& efforts = g.actees[0].efforts;
  ASSERT_EQ(efforts.size(), 9u);
  EXPECT_EQ(efforts.front(), 0);
  EXPECT_GT(efforts.back(), last.effort);
  EXPECT_DOUBLE_EQ(efforts.back(), effort_axis_top(last.effort, 9, 400, g.tolerance));
  // The two wraps (430 N, above the axis) are alike; the tip pinch is cut at 65 N.
  const std::vector<std::vector<int>> groups = alike_grasps(g, r, 0);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], (std::vector<int>{0, 1}));
  EXPECT_EQ(groups[1], (std::vector<int>{2}));
  EXPECT_THAT(summary_text(g, r), HasSubstr("alike everywhere (one row of the map): small_wrap, medium_wrap"));
}

TEST(ExploreOutcome, AGrapesAxisShowsItsBurstAndNothingWeakerSitsAboveAStronger) {
  ExploreFiles files = tongs_with({});
  files.actees = {kSource + "/tests/data/explore/grape.yaml"};
  GridOptions grid;
  grid.placements = 1;  // 212.5 mm
  grid.thumbs = 1;      // 115 mm
  grid.efforts = 9;
  grid.grasps = {"medium_wrap"};
  Explorer e = make_explorer(files, grid);
  fit_effort_axes(e, 2);
  const ExploreResult r = explore(e, Shard{}, 2);
  const GridInfo& g = e.grid;
  // The grape (radii 11, 9.5 mm) bursts at 12 N: 12 D / 0.115 at the thumb
  // with D its lever arm under the jaw (test_util.h), plus at most 3.55 N
  // for the spring and 0.04 N for the pivot (as for the egg above).
  const test::JawTouch touch = test::ellipsoid_under_jaw(0.011, 0.0095, 0.2125, 18 * std::numbers::pi / 180);
  const double needed = 12 * touch.lever / 0.115;  // N
  // D = 212.2 mm (theta_c = 5.12 deg): needed = 22.14 N.
  EXPECT_NEAR(needed, 22.14, 0.01);
  const SeriesResult& s = r.series.at(0);
  ASSERT_FALSE(s.thresholds.empty());
  const Threshold& burst = s.thresholds.back();
  EXPECT_EQ(burst.to, test::index_of(g.functions, "crash"));
  EXPECT_GE(burst.effort, needed);
  EXPECT_GE(burst.at.peak_effort, needed);
  EXPECT_LE(burst.at.peak_effort, needed + 3.55 + 0.04 + g.tolerance);
  // The axis: a burst asked for with 21.8 to 29.1 N wants a step of 1.1 *
  // burst / 8 = 3.0 to 4.0 N: 4 N, to 32 N (on the common axis the burst
  // sat in the lowest 7 % of 0-400 N).
  ASSERT_GE(burst.effort, 21.8);
  ASSERT_LE(burst.effort, 29.1);
  EXPECT_DOUBLE_EQ(g.actees[0].efforts.back(), 32);
  EXPECT_DOUBLE_EQ(g.actees[0].efforts[1], 4);
  // Up the axis the outcome only grows stronger (none, ..., carry, crash):
  // no hold above a carry.
  auto rank = [&](int o) { return o < 0 ? -1 : g.strength[static_cast<size_t>(o)]; };
  for (size_t i = 1; i < s.points.size(); ++i) {
    EXPECT_GE(rank(s.points[i].outcome), rank(s.points[i - 1].outcome)) << "effort " << g.actees[0].efforts[i];
  }
  EXPECT_EQ(s.points.back().outcome, test::index_of(g.functions, "crash"));
}

TEST(ExploreOutcome, TheAxesDoNotDependOnTheThreads) {
  GridOptions grid;
  grid.placements = 2;
  grid.thumbs = 1;
  grid.efforts = 4;
  grid.grasps = {"medium_wrap", "tip_pinch"};
  Explorer one = make_explorer(tongs_with({"egg.yaml", "sponge.yaml"}), grid);
  Explorer three = make_explorer(tongs_with({"egg.yaml", "sponge.yaml"}), grid);
  fit_effort_axes(one, 1);
  fit_effort_axes(three, 3);
  EXPECT_TRUE(one.grid == three.grid);
  EXPECT_EQ(points_csv(one.grid, explore(one, Shard{}, 1)), points_csv(three.grid, explore(three, Shard{}, 3)));
}

}  // namespace
}  // namespace afford
