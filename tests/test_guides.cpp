// The guides (paper Sec. 4.4, Fig. 16) as data: loading rules/guides.yaml
// and its errors, and the guides computed for the shipped nutcracker, tongs
// and pliers (symmetry plane, interaction space and fitting actees, emphasis
// faces, the amplify/decline map).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>
#include <numbers>

#include "derive.h"
#include "rig.h"
#include "guides.h"
#include "lever.h"
#include "load.h"
#include "model.h"
#include "validate.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;


// A small valid guide file; line numbers in the comments.
const std::string kGuides =
    "guides:\n"                                       // 1
    "  - name: plane\n"                               // 2
    "    kind: symmetry_plane\n"                      // 3
    "    description: The plane.\n"                   // 4
    "    colour: [0.2, 0.4, 1]\n"                     // 5
    "    alpha: 0.5\n"                                // 6
    "    margin: 5 mm\n"                              // 7
    "  - name: map\n"                                 // 8
    "    kind: advantage\n"                           // 9
    "    description: The map.\n"                     // 10
    "    colour: [1, 1, 1]\n"                         // 11
    "    step: 10 mm\n"                               // 12
    "    saturate: 4\n"                               // 13
    "    ramp:\n"                                     // 14
    "      decline: [0, 0, 1]\n"                      // 15
    "      neutral: [1, 1, 1]\n"                      // 16
    "      amplify: [1, 0, 0]\n";                     // 17

std::string guides_error(const std::string& text) {
  try {
    (void)read_guides(load_yaml_string(text, "bad.yaml"));
  } catch (const DataError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a DataError, nothing was thrown";
  return "";
}

std::vector<GuideSpec> shipped_guides() { return load_guides(kSource + "/rules/guides.yaml"); }

struct Computed {
  ObjectSpec spec;
  Model model;
  Guides guides;
};

Computed guides_of(const std::string& object) {
  Computed c{load_object(kSource + "/objects/" + object + ".yaml"), {}, {}};
  c.model = compile(c.spec, nullptr, nullptr, ModelOptions{});
  c.guides = compute_guides(c.model, shipped_guides(),
                            fit_actees(c.spec, load_actee_folder(kSource + "/actees")));
  return c;
}

const ActeeFit& fit_named(const Guides& g, const std::string& name) {
  for (const ActeeFit& f : g.facts.actees) {
    if (f.name == name) return f;
  }
  ADD_FAILURE() << "no actee " << name;
  return g.facts.actees.front();
}

// ---------------------------------------------------------------- loading

TEST(GuidesLoad, ReadsEveryField) {
  const std::vector<GuideSpec> g = read_guides(load_yaml_string(kGuides, "good.yaml"));
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].name, "plane");
  EXPECT_EQ(g[0].kind, GuideKind::symmetry_plane);
  EXPECT_DOUBLE_EQ(g[0].colour.g, 0.4);
  EXPECT_DOUBLE_EQ(g[0].colour.a, 0.5);
  EXPECT_DOUBLE_EQ(g[0].margin, 0.005);
  EXPECT_EQ(g[0].gravity, Eigen::Vector3d(0, 0, -1));  // the default
  EXPECT_EQ(g[1].kind, GuideKind::advantage);
  EXPECT_DOUBLE_EQ(g[1].step, 0.010);
  EXPECT_DOUBLE_EQ(g[1].saturate, 4);
  EXPECT_EQ(g[1].load_at, GuideLoadAt::middle);
  EXPECT_DOUBLE_EQ(g[1].amplify.r, 1);
  EXPECT_DOUBLE_EQ(g[1].decline.b, 1);
  EXPECT_EQ(g[1].loc.str(), "good.yaml:8:5");
}

TEST(GuidesLoad, UnknownKeyWithDidYouMean) {
  EXPECT_EQ(guides_error(replace_once(kGuides, "    colour: [0.2, 0.4, 1]", "    colur: [0.2, 0.4, 1]")),
            "bad.yaml:5:5: expected one of the keys of a guide of kind symmetry_plane (name, kind, description, "
            "colour, alpha, lift, margin, gravity), found 'colur' (did you mean 'colour'?)");
  // A key of another kind is unknown here.
  EXPECT_THAT(guides_error(replace_once(kGuides, "    margin: 5 mm", "    step: 5 mm")),
              StartsWith("bad.yaml:7:5: expected one of the keys of a guide of kind symmetry_plane"));
  EXPECT_THAT(guides_error(replace_once(kGuides, "      neutral:", "      nuetral:")),
              StartsWith("bad.yaml:16:7: expected one of the keys of the colour ramp (decline, neutral, amplify), "
                         "found 'nuetral' (did you mean 'neutral'?)"));
  EXPECT_THAT(guides_error(replace_once(kGuides, "guides:", "guide:")),
              StartsWith("bad.yaml:1:1: expected one of the keys of a guides file (guides), found 'guide' "
                         "(did you mean 'guides'?)"));
}

TEST(GuidesLoad, WrongKind) {
  EXPECT_EQ(guides_error(replace_once(kGuides, "kind: advantage", "kind: advantag")),
            "bad.yaml:9:11: expected one of symmetry_plane, interaction_space, emphasis, advantage, found "
            "'advantag' (did you mean 'advantage'?)");
  // With an unknown kind, a key no kind has is reported first.
  EXPECT_THAT(guides_error(replace_once(replace_once(kGuides, "kind: advantage", "kind: advantag"), "    step:",
                                        "    stpe:")),
              StartsWith("bad.yaml:12:5: expected one of the keys of a guide ("));
}

TEST(GuidesLoad, ColourOutOfRange) {
  EXPECT_EQ(guides_error(replace_once(kGuides, "[0.2, 0.4, 1]", "[0.2, 1.4, 1]")),
            "bad.yaml:5:19: expected a colour component from 0 to 1, found '1.4'");
  EXPECT_EQ(guides_error(replace_once(kGuides, "      amplify: [1, 0, 0]", "      amplify: [1, 0, -0.1]")),
            "bad.yaml:17:23: expected a colour component from 0 to 1, found '-0.1'");
  EXPECT_THAT(guides_error(replace_once(kGuides, "[0.2, 0.4, 1]", "[0.2, 0.4]")),
              StartsWith("bad.yaml:5:13: expected a colour [r, g, b] of three numbers from 0 to 1"));
  EXPECT_THAT(guides_error(replace_once(kGuides, "alpha: 0.5", "alpha: 2")),
              StartsWith("bad.yaml:6:12: expected an alpha from 0 to 1"));
}

TEST(GuidesLoad, OtherMistakes) {
  EXPECT_THAT(guides_error(replace_once(kGuides, "name: map", "name: plane")),
              StartsWith("bad.yaml:8:11: expected a guide name not used before, found 'plane' again (first at "
                         "bad.yaml:2:5)"));
  EXPECT_THAT(guides_error(replace_once(kGuides, "saturate: 4", "saturate: 1")),
              StartsWith("bad.yaml:13:15: expected a mechanical advantage greater than 1"));
  EXPECT_THAT(guides_error(replace_once(kGuides, "step: 10 mm", "step: 0 mm")), StartsWith("bad.yaml:12:11:"));
  EXPECT_THAT(guides_error(replace_once(kGuides, "step: 10 mm", "step: 10 N")), StartsWith("bad.yaml:12:11:"));
  EXPECT_THAT(guides_error(replace_once(kGuides, "    step: 10 mm\n", "")),
              StartsWith("bad.yaml:8:5: expected key 'step' in a guide of kind advantage"));
  EXPECT_THAT(guides_error("guides: []\n"), StartsWith("bad.yaml:1:9: expected a sequence of guides"));
}

TEST(GuidesLoad, ShippedFileIsValidAndHasTheFourGuides) {
  const std::vector<GuideSpec> g = shipped_guides();
  ASSERT_EQ(g.size(), 4u);
  EXPECT_EQ(g[0].kind, GuideKind::symmetry_plane);
  EXPECT_EQ(g[1].kind, GuideKind::interaction_space);
  EXPECT_EQ(g[2].kind, GuideKind::emphasis);
  EXPECT_EQ(g[3].kind, GuideKind::advantage);
  EXPECT_EQ(validate_file(kSource + "/rules/guides.yaml"), "guides, 4 guides");
}

// ---------------------------------------------------------------- computing

TEST(GuidesCompute, SymmetryPlaneAndFunctionalPose) {
  for (const char* object : {"nutcracker", "tongs", "pliers"}) {
    SCOPED_TRACE(object);
    const Computed c = guides_of(object);
    const int index = c.guides.find("stable_orientation");
    ASSERT_GE(index, 0);
    int planes = 0;
    for (const GuideRect& r : c.guides.rects) {
      if (r.guide != index) continue;
      ++planes;
      EXPECT_TRUE(r.normal.isApprox(c.spec.symmetry_plane.normal));
      EXPECT_NEAR((r.centre - c.spec.symmetry_plane.point).dot(r.normal), 0, 1e-12);  // on the plane
      EXPECT_NEAR(r.u.dot(r.normal), 0, 1e-12);
      EXPECT_TRUE(r.u.cross(r.v).isApprox(r.normal));
      // It covers the arms with the margin to spare.
      EXPECT_GE(r.half_u, 0.5 * (c.model.arm_to - c.model.arm_from));
      EXPECT_DOUBLE_EQ(r.colour.a, 0.25);
    }
    EXPECT_EQ(planes, 1);
    EXPECT_TRUE(c.guides.facts.functional_pose.isApprox(c.model.object_start));
    // The tongs and the pliers stand on edge, the moving arm above: the
    // paper's stable orientation (Sec. 4.4), exactly (no turn left to
    // find). The nutcracker's weight outdoes its spring, so its file lays
    // it flat, the pivot axis (the plane's normal) vertical.
    const bool on_edge = std::string(object) != "nutcracker";
    EXPECT_EQ(c.guides.facts.plane_to_gravity, on_edge ? 0.0 : std::numbers::pi / 2);
    if (on_edge) {
      EXPECT_TRUE(c.guides.facts.stable_turn_found);
      EXPECT_EQ(c.guides.facts.stable_turn, 0.0);
    }
  }
}

TEST(GuidesCompute, TheStableOrientationsWeightWorkedByHand) {
  // A type 2 tool of two equal boxes, 180 x 10 x 16 mm, the fixed one at
  // y = -5 mm and the moving one at y = +5 mm, 100 g in all: the moving arm
  // has 50 g at (90, 5) mm of its frame. At rest (50 deg) that is (90 cos 50
  // - 5 sin 50, 90 sin 50 + 5 cos 50) = (54.02, 72.16) mm. Turned 90 deg
  // about x, the moving arm above, gravity is -y of the object frame: the
  // weight's torque about the pivot is x * (-m g) = -0.05402 * 0.05 * 9.81
  // = -0.02650 N*m (closing), +0.02650 below. The spring's preload, 2 N at
  // 30 mm, holds 0.06 N*m: the arm rests open both ways.
  const std::string yaml = test::tool_yaml("t2", "type2", 0, 180, 50, 500, 30, 2, 110, 170, 20, 70);
  const Model m = compile(read_object(load_yaml_string(yaml, "tool.yaml")), nullptr, nullptr, ModelOptions{});
  const GuideFacts f = compute_guides(m, shipped_guides()).facts;
  ASSERT_TRUE(f.stable_turn_found);
  EXPECT_NEAR(std::abs(std::remainder(f.stable_turn, 2 * std::numbers::pi)), std::numbers::pi / 2, 1e-9);
  const double x = 0.090 * std::cos(50 * test::kDeg) - 0.005 * std::sin(50 * test::kDeg);
  EXPECT_NEAR(f.weight_above, -x * 0.05 * 9.81, 2e-4);
  EXPECT_NEAR(f.weight_below, x * 0.05 * 9.81, 2e-4);
  EXPECT_NEAR(f.spring_at_rest, 0.06, 1e-12);
  EXPECT_EQ(f.friction_at_rest, 0);
}

TEST(GuidesCompute, InteractionSpaceMatchesDerive) {
  for (const char* object : {"nutcracker", "tongs", "pliers"}) {
    SCOPED_TRACE(object);
    const Computed c = guides_of(object);
    const InteractionSpace s = interaction_space(c.model);
    EXPECT_EQ(c.guides.facts.space.from, s.from);
    EXPECT_EQ(c.guides.facts.space.to, s.to);
    EXPECT_EQ(c.guides.facts.space.gap_to, s.gap_to);
    ASSERT_EQ(c.guides.meshes.size(), 1u);
    const GuideMesh& mesh = c.guides.meshes[0];
    ASSERT_EQ(mesh.vertices.size(), 8u);
    ASSERT_EQ(mesh.triangles.size(), 12u);
    // Over the application region on the fixed jaw, opened to theta_max.
    EXPECT_DOUBLE_EQ(mesh.vertices[0].x(), s.from);
    EXPECT_DOUBLE_EQ(mesh.vertices[1].x(), s.to);
    EXPECT_NEAR(mesh.vertices[2].y(), s.gap_to, 1e-12);
    EXPECT_NEAR(mesh.vertices[3].y(), s.gap_from, 1e-12);
    // Closed and wound outward: positive volume.
    double volume = 0;
    for (const auto& t : mesh.triangles) {
      volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6;
    }
    const double z = mesh.vertices[4].z() - mesh.vertices[0].z();
    const double area = 0.5 * std::sin(c.model.theta_max) * (s.to * s.to - s.from * s.from);
    EXPECT_NEAR(volume, area * z, 1e-12);
  }
}

TEST(GuidesCompute, WhichActeesFit) {
  const Computed nut = guides_of("nutcracker");
  EXPECT_EQ(nut.guides.facts.actees.size(), 9u);
  EXPECT_TRUE(fit_named(nut.guides, "walnut").fits);
  EXPECT_TRUE(fit_named(nut.guides, "hazelnut").fits);
  EXPECT_FALSE(fit_named(nut.guides, "coconut").fits);
  EXPECT_FALSE(fit_named(nut.guides, "egg").fits);
  const Computed tongs = guides_of("tongs");
  EXPECT_TRUE(fit_named(tongs.guides, "egg").fits);
  EXPECT_TRUE(fit_named(tongs.guides, "sponge").fits);
  EXPECT_FALSE(fit_named(tongs.guides, "coconut").fits);
  const Computed pliers = guides_of("pliers");
  EXPECT_TRUE(fit_named(pliers.guides, "peanut").fits);
  EXPECT_FALSE(fit_named(pliers.guides, "walnut").fits);
  // The same as derive.h's fit_actee on a model compiled with the actee.
  ModelOptions options;
  options.actee.in_jaws = false;
  const ActeeSpec walnut = load_actee(kSource + "/actees/walnut.yaml");
  const ActeeFit direct = fit_actee(compile(nut.spec, &walnut, nullptr, options));
  EXPECT_EQ(fit_named(nut.guides, "walnut").from, direct.from);
  EXPECT_EQ(fit_named(nut.guides, "walnut").effort_to_limit, direct.effort_to_limit);
  // Each fitting actee has a bar over where it fits, and every actee a label.
  int labels = 0;
  for (const GuideLabel& l : nut.guides.labels) labels += l.text.starts_with("walnut fits");
  EXPECT_EQ(labels, 1);
}

// The emphasis rectangles lie on the arms' outer faces (the faces the agent
// presses to close the jaws), over the emphasis range.
TEST(GuidesCompute, EmphasisOnTheOuterFaces) {
  for (const char* object : {"nutcracker", "tongs", "pliers"}) {
    SCOPED_TRACE(object);
    const Computed c = guides_of(object);
    const int index = c.guides.find("emphasis");
    const double lift = c.guides.guides[index].lift;
    int faces = 0;
    for (const GuideRect& r : c.guides.rects) {
      if (r.guide != index) continue;
      ++faces;
      EXPECT_NEAR(r.centre.x() - r.half_u, c.model.emphasis_from, 1e-12);
      EXPECT_NEAR(r.centre.x() + r.half_u, c.model.emphasis_to, 1e-12);
      EXPECT_NEAR(std::abs(r.normal.y()), 1, 1e-12);
      // On the outermost face of the arm's parts there, away from the other arm.
      double outer = -1;
      for (const PartSpec& p : c.spec.parts) {
        if (p.arm != r.frame) continue;
        const double x0 = p.pose.position.x() - 0.5 * p.shape.size.x(), x1 = x0 + p.shape.size.x();
        if (x1 <= c.model.emphasis_from || x0 >= c.model.emphasis_to) continue;
        outer = std::max(outer, r.normal.y() * p.pose.position.y() + 0.5 * p.shape.size.y());
        EXPECT_GT(r.normal.y() * p.pose.position.y(), 0);  // the normal points away from the other arm
      }
      EXPECT_NEAR(r.centre.y() * r.normal.y(), outer + lift, 1e-12);
    }
    EXPECT_EQ(faces, 2);
  }
  // The nutcracker's, in numbers: the fixed arm's bottom and the moving arm's top.
  const Computed nut = guides_of("nutcracker");
  const GuideRect& fixed = nut.guides.rects[1];
  EXPECT_EQ(fixed.frame, Arm::fixed);
  EXPECT_TRUE(fixed.centre.isApprox(Eigen::Vector3d(0.145, -0.0125, 0)));
  EXPECT_TRUE(fixed.normal.isApprox(-Eigen::Vector3d::UnitY()));
  EXPECT_EQ(nut.guides.rects[2].frame, Arm::moving);
  EXPECT_TRUE(nut.guides.rects[2].normal.isApprox(Eigen::Vector3d::UnitY()));
  // Posed at an angle, the moving arm's face turns with it.
  const Guides posed = posed_guides(nut.guides, 0.2);
  EXPECT_EQ(posed.rects[2].frame, Arm::fixed);
  EXPECT_TRUE(posed.rects[2].centre.isApprox(moving_arm_pose(0.2) * nut.guides.rects[2].centre));
  EXPECT_TRUE(posed.rects[1].centre.isApprox(fixed.centre));
  // And into the world at the object's pose.
  const Guides world = posed_guides(nut.guides, 0.2, nut.model.object_start);
  EXPECT_TRUE(world.rects[2].centre.isApprox(nut.model.object_start * posed.rects[2].centre));
  EXPECT_TRUE(world.meshes[0].vertices[5].isApprox(nut.model.object_start * nut.guides.meshes[0].vertices[5]));
  EXPECT_TRUE(world.labels[0].anchor.isApprox(nut.model.object_start * nut.guides.labels[0].anchor));
}

// Mechanical advantage along the arms for a load in the application
// region's middle: > 1 over the handles of the nutcracker and pliers, < 1
// over the tongs' effort region.
TEST(GuidesCompute, AmplifyOrDecline) {
  struct Case {
    const char* object;
    bool amplifies;
  };
  for (const Case& k : {Case{"nutcracker", true}, Case{"pliers", true}, Case{"tongs", false}}) {
    SCOPED_TRACE(k.object);
    const Computed c = guides_of(k.object);
    const int index = c.guides.find("amplify_decline");
    const GuideSpec& spec = c.guides.guides[index];
    const double load = 0.5 * (c.model.application_from + c.model.application_to);
    EXPECT_DOUBLE_EQ(c.guides.facts.load_at, load);
    int in_emphasis = 0;
    for (const GuideSegment& s : c.guides.segments) {
      if (s.guide != index) continue;
      EXPECT_NEAR(s.value, mechanical_advantage(s.distance, load), 1e-12);
      EXPECT_LE(std::abs(s.b.x() - s.a.x()), spec.step + 1e-12);
      if (s.distance < c.model.emphasis_from || s.distance > c.model.emphasis_to) continue;
      ++in_emphasis;
      EXPECT_EQ(s.value > 1, k.amplifies) << "at " << s.distance;
      // Coloured towards amplify (red) or decline (blue).
      EXPECT_EQ(s.colour.r > s.colour.b, k.amplifies);
    }
    EXPECT_GT(in_emphasis, 10);
    EXPECT_EQ(c.guides.facts.ma_min > 1, k.amplifies);
    EXPECT_EQ(c.guides.facts.ma_max < 1, !k.amplifies);
  }
  const Computed nut = guides_of("nutcracker");
  EXPECT_DOUBLE_EQ(nut.guides.facts.ma_min, 0.110 / 0.050);
  EXPECT_DOUBLE_EQ(nut.guides.facts.ma_max, 0.180 / 0.050);
}

TEST(GuidesCompute, ColourRamp) {
  const std::vector<GuideSpec> g = read_guides(load_yaml_string(kGuides, "good.yaml"));
  const GuideSpec& map = g[1];
  EXPECT_DOUBLE_EQ(advantage_colour(map, 1).g, 1);                   // neutral
  EXPECT_DOUBLE_EQ(advantage_colour(map, 4).g, 0);                   // amplify
  EXPECT_DOUBLE_EQ(advantage_colour(map, 40).r, 1);                  // clamped
  EXPECT_DOUBLE_EQ(advantage_colour(map, 0.25).r, 0);                // decline
  EXPECT_DOUBLE_EQ(advantage_colour(map, 2).g, 0.5);                 // half way, log scale
  EXPECT_DOUBLE_EQ(advantage_colour(map, 0.5).b, 1);
  EXPECT_DOUBLE_EQ(advantage_colour(map, 0.5).r, 0.5);
}

}  // namespace
}  // namespace afford::test
