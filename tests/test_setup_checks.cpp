// Setups that cannot work as meant: an actee off the application region and
// a part off its arm are located errors; a spring the hand can never beat is
// a warning with the numbers (setup_warnings.h). Numbers worked by hand.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rig.h"
#include "setup_warnings.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;

// t2: arm 0-180 mm, spring 500 N/m at 30 mm, rest and theta_max 50 deg,
// emphasis 110-170 mm, application 20-70 mm; the nut (radius 10 mm) at 40 mm.
std::string t2(double spring_k, double preload_n) {
  return tool_yaml("t2", "type2", 0, 180, 50, spring_k, 30, preload_n, 110, 170, 20, 70);
}

std::string compile_error(const std::string& tool, double load) {
  const std::string nut = nut_yaml();
  try {
    (void)model_of(tool, &nut, load);
  } catch (const DataError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SetupChecks, AnActeeOutsideTheApplicationRegionIsAnError) {
  // On the arm (0-180 mm) but past the jaws (20-70 mm).
  EXPECT_THAT(compile_error(t2(500, 2), 0.100),
              HasSubstr("expected a distance in the application region, between 20 mm and 70 mm, found 100 mm"));
  EXPECT_THAT(compile_error(t2(500, 2), 0.015), HasSubstr("found 15 mm"));
  EXPECT_EQ(compile_error(t2(500, 2), 0.040), "no error");
}

TEST(SetupChecks, APartOffItsArmIsAnErrorAtItsPosition) {
  // tool_yaml's line 20 is the fixed jaw's position, [90 mm, -5 mm, 0 mm].
  std::string tool = t2(500, 2);
  const std::string from = "position: [90.000000 mm, -5";
  ASSERT_NE(tool.find(from), std::string::npos);
  tool.replace(tool.find(from), from.size(), "position: [400 mm, -5");
  try {
    (void)object_from(tool);
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_THAT(e.what(), HasSubstr("tool.yaml:20:15: expected a part on its arm: a position along it (x) between "
                                    "0 mm and 180 mm, found 400 mm"));
  }
}

std::vector<Warning> warnings_of(const std::string& tool) {
  const std::string nut = nut_yaml();
  const Model m = model_of(tool, &nut, 0.040);
  return setup_warnings(m, SourceLoc{"tool.yaml", 13, 9});
}

TEST(SetupChecks, ASpringTheHandCannotMoveIsAWarningWithTheNumbers) {
  // At rest the spring pushes its preload; moment balance at the far end of
  // the emphasis, 170 mm: F = P * 30 mm / 170 mm. 2000 N takes 352.9 N (the
  // hand gives 400 N); 3000 N takes 529.4 N.
  EXPECT_TRUE(warnings_of(t2(500, 2000)).empty());
  const std::vector<Warning> w = warnings_of(t2(500, 3000));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].str(),
            "tool.yaml:13:9: warning: the agent (test_hand, at most 400 N) can never move the arm: the spring pushes "
            "3000 N at rest (50 deg), which takes 529.4 N at 170 mm, the far end of the emphasis region");
}

TEST(SetupChecks, ASpringTooStiffToCloseOnTheActeeIsAWarning) {
  // The jaws touch the nut at 2 atan(10/40) = 28.07 deg, 0.3827 rad before
  // the rest angle: the spring's end has moved 30 mm * 0.3827 = 11.48 mm.
  // At 300 N/mm it pushes 3444 N + 2 N = 3446 N there, which takes
  // 3446 N * 30 mm / 170 mm = 608.2 N; at rest only 2 N * 30 / 170 = 0.35 N.
  const double d = 0.030 * (50 * std::numbers::pi / 180 - 2 * std::atan(0.25));
  ASSERT_NEAR(d, 0.011481, 1e-6);
  ASSERT_NEAR((3e5 * d + 2) * 0.030 / 0.170, 608.18, 0.01);
  const std::vector<Warning> w = warnings_of(t2(3e5, 2));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_THAT(w[0].message, HasSubstr("can never close the jaws on the nut: at 28.07 deg, where they touch it, the "
                                      "spring pushes 3446 N, which takes 608.2 N at 170 mm"));
  EXPECT_TRUE(warnings_of(t2(1e5, 2)).empty());  // 1150 N there: 203 N
}

}  // namespace
}  // namespace afford::test
