// The withheld check's MuJoCo reality (gapcheck/mujoco_reality.cpp): what
// it plays is the effect-free tool its files describe, where no effect is
// drawn; and cases it played that the diagnosis once read wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "case_files.h"
#include "design.h"
#include "diagnose.h"
#include "effects.h"
#include "reality.h"

namespace fs = std::filesystem;

namespace {

// Each drive played by `reality` with its own noise seed, as the generator plays it.
gapcheck::PlayDrive playing(const gapcheck::Reality& reality) {
  return [&reality](const gapcheck::Case& k, const gapcheck::Drive& d) { return reality.play(k, d, d.noise_seed); };
}

}  // namespace

// Each test draws its cases into its own folder and plays them in one
// MuJoCo reality, as the generator does.
class GapcheckMujocoReality : public testing::Test {
 protected:
  static fs::path cases_in(const std::string& folder) {
    const fs::path cases = fs::path(testing::TempDir()) / folder;
    fs::create_directories(cases);
    return cases;
  }
  const std::unique_ptr<gapcheck::Reality> reality = gapcheck::make_mujoco_reality();
  const gapcheck::PlayDrive play = playing(*reality);
};

// An actee in the jaws is pressed as the plates press it: its force at a
// depth is the specimen's law there (MuJoCo's linear spring, k p, for the
// effect-free specimen), the depth being the lever's, lever * (contact
// angle - angle). A pecan is long (22.35 mm along the jaw, 11.65 mm
// across): pressed whole by the turning jaw it rolls, and its depth grows
// by a^2 delta^2 / (2 b) beyond the lever's, which afford's lever does not
// model. Before, this pecan's force was up to 0.48 % over the lever's
// depth (now 0.036 %), and effect-free pecans (development seeds 3082,
// 3094) read as an actee's law.
TEST_F(GapcheckMujocoReality, AnActeeInTheJawsTakesTheDepthTheLeverGives) {
  const fs::path cases = cases_in("gapcheck-mujoco-reality");
  const gapcheck::Case drawn = gapcheck::draw_case(AFFORD_SOURCE_DIR, cases, 3094, play);
  ASSERT_TRUE(drawn.tool.actee.has_value());
  ASSERT_NE(drawn.tool.actee->file.find("pecan"), std::string::npos);
  gapcheck::Case silent = drawn;
  silent.sensors = gapcheck::Sensors{.effort_noise = 0, .angle_noise = 0, .actee_noise = 0};
  const gapcheck::ToolActee& a = *silent.tool.actee;
  const double stiffness = a.stiffness * silent.actee_specimen;  // N/m
  int judged = 0;
  for (const gapcheck::Drive& d : silent.drives) {
    if (!d.squeezes) continue;
    for (const gapcheck::Measured& m : reality->play(silent, d, d.noise_seed)) {
      // From a third of the limit, where the rolling has grown; never past
      // the break.
      if (m.broken || m.actee < a.limit / 3) continue;
      const double depth = a.lever * (a.contact_angle - m.angle);  // m
      EXPECT_NEAR(m.actee / (stiffness * depth), 1.0, 1e-3) << "t " << m.t << " s, " << m.actee << " N";
      ++judged;
    }
  }
  EXPECT_GE(judged, 50);
}

// A viscoelastic actee, outside the library, is promised as every effect
// is: at twice the floor at least where the jaws press it (the effort's
// noise and the angle's through the specimen's stiffness). Before, its
// share was drawn at 15 to 40 % whatever it showed: development seeds
// 3034, 3213 and 3238 drew one that changed the contact by 0.3 to 0.8 N
// against 3 to 19 N (twice the floor), and 3213 read `none` in ODE. Now
// 3238 draws another effect outside the library, and 3197 keeps a
// viscoelastic actee sized on the floor.
TEST_F(GapcheckMujocoReality, AViscoelasticActeeIsDrawnOnlyWhereItShowsAtTwiceTheFloor) {
  const fs::path cases = cases_in("gapcheck-mujoco-viscoelastic");
  int relaxing = 0;
  for (unsigned seed : {3197u, 3238u}) {
    const gapcheck::Case c = gapcheck::draw_case(AFFORD_SOURCE_DIR, cases, seed, play);
    if (c.outside.viscoelastic_share == 0) continue;
    ++relaxing;
    EXPECT_GE(gapcheck::viscoelastic_change(c, play), 2 * gapcheck::contact_floor_of(c)) << "seed " << seed;
  }
  EXPECT_GE(relaxing, 1);
}

// Every effect of the library is drawn at 2 to 10 times the effort's
// noise as it shows in the effort played, not as a torque at the
// emphasis. Drawn as a torque before, a snips' progressive spring on
// closing-only strokes (development seed 3072) changed the effort by
// 0.92 times the noise, and a tongs' weight with a progressive spring
// (3366) by 0.78 times (now 2.4 and 2.2 times).
TEST_F(GapcheckMujocoReality, AnEffectOfTheLibraryShowsInTheEffortAtTwiceTheNoise) {
  const fs::path cases = cases_in("gapcheck-mujoco-library");
  for (unsigned seed : {3072u, 3366u}) {
    const gapcheck::Case c = gapcheck::draw_case(AFFORD_SOURCE_DIR, cases, seed, play);
    ASSERT_FALSE(c.truth.names().empty()) << "seed " << seed;
    EXPECT_GE(gapcheck::library_change(c, play), 2 * c.sensors.effort_noise) << "seed " << seed;
  }
}

// Each effect of the tool is promised at twice the noise as it shows
// played alone at the size drawn, not as a line through a first play at
// another size predicts. An arm's inertia is not linear in that way:
// played first at the torque over the drive's acceleration, many times the
// bound, it turns the hand's servo about. Before, development seed 6098 drew
// a snips' inertia at the bound that the line promised at 2.22 times the
// noise and that showed 1.86 times.
TEST_F(GapcheckMujocoReality, EachEffectShowsAtTwiceTheNoiseAtTheSizeItIsDrawn) {
  const fs::path cases = cases_in("gapcheck-mujoco-sized");
  const gapcheck::Case c = gapcheck::draw_case(AFFORD_SOURCE_DIR, cases, 6098, play);
  ASSERT_FALSE(c.truth.names().empty());
  int effects = 0;
  for (double gapcheck::Truth::*field : {&gapcheck::Truth::friction, &gapcheck::Truth::damping, &gapcheck::Truth::preload,
                                         &gapcheck::Truth::cubic, &gapcheck::Truth::inertia, &gapcheck::Truth::weight}) {
    if (c.truth.*field == 0) continue;
    ++effects;
    gapcheck::Case alone = c;
    alone.truth = gapcheck::Truth{};
    alone.truth.*field = c.truth.*field;
    EXPECT_GE(gapcheck::library_change(alone, play), 2 * c.sensors.effort_noise) << alone.truth.names().front();
  }
  EXPECT_GE(effects, 1);
}

// An actee's law is promised as every effect is: at twice the floor at
// least where the jaws press the actee, as played. Its bounds (an exponent
// of 4 for ODE, a toe's impedance of 0.5 for MuJoCo) held it back where
// the jaws press little: development seeds 3032 and 3451 (tongs) drew the
// exponent at 4 whatever it showed, as did 8 of the 12 actee laws of
// report seeds 1,002,900 to 1,003,199. Now those take the library's next
// effect, and 3443 (a press) keeps a law that shows.
TEST_F(GapcheckMujocoReality, AnActeesLawIsDrawnOnlyWhereItShowsAtTwiceTheFloor) {
  const fs::path cases = cases_in("gapcheck-mujoco-actee-law");
  {
    const gapcheck::Case c = gapcheck::draw_case(AFFORD_SOURCE_DIR, cases, 3451, play);
    EXPECT_EQ(c.truth.actee_exponent, 0.0);
  }
  {
    const unsigned seed = 3443;
    const gapcheck::Case c = gapcheck::draw_case(AFFORD_SOURCE_DIR, cases, seed, play);
    ASSERT_GT(c.truth.actee_exponent, 0.0) << "seed " << seed;
    EXPECT_GE(gapcheck::actee_law_change(c, play), 2 * gapcheck::contact_floor_of(c)) << "seed " << seed;  // 12.9 N against 3.6 N
  }
}

// The smallest set that explains is judged as the verdict judges it: it
// may leave a slight shape, as the verdict accepts for one or two effects.
// Development seed 6976 (a press, turned; gravity and a progressive
// spring): the forward selection took a preload, the weight and the
// spring, the preload 1.7 standard errors from zero; the true pair left a
// shape of 3 % of its residual, and the smallest set that explains was
// looked for among those with a white residual only. It read
// `unexplained`.
TEST_F(GapcheckMujocoReality, TheSmallestSetThatExplainsMayLeaveASlightShape) {
  const fs::path out = cases_in("gapcheck-mujoco-slight");
  fs::create_directories(out / "cases");
  fs::create_directories(out / "labels");
  const gapcheck::Case c = gapcheck::draw_case(AFFORD_SOURCE_DIR, out / "cases", 6976, play);
  const fs::path measurement = gapcheck::play_and_write(out, c, *reality).measurement;
  const afford::Diagnosis d = afford::diagnose(afford::load_measurement(measurement.string()));
  std::vector<std::string> named;
  for (const afford::EffectFit& e : d.effects) named.emplace_back(afford::manifest_of(e.kind).name);
  std::sort(named.begin(), named.end());
  std::vector<std::string> truth = c.truth.names();
  std::sort(truth.begin(), truth.end());
  ASSERT_EQ(truth, (std::vector<std::string>{"gravity", "progressive_spring"}));
  EXPECT_EQ(afford::verdict_name(d.verdict), std::string("explained"));
  EXPECT_EQ(named, truth);
}
