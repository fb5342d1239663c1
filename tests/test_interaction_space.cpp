// The interaction space L_is from the shape (issue 28): the object key
// `interaction_space` (the jaws' gap fully open along the arm), read with
// located errors, used by derive's interaction_space and fit_actee instead
// of the wedge of flat jaw faces through the pivot, and written by afford
// model from the gap between a PartNet tool's jaws.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <unistd.h>

#include "derive.h"
#include "errors.h"
#include "explore.h"
#include "guides.h"
#include "load.h"
#include "model.h"
#include "terms.h"
#include "test_util.h"
#include "tool_model.h"
#include "urdf_tool.h"
#include "yaml_reader.h"

namespace afford::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;


std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The shipped nutcracker (type 2, application 25 to 75 mm, theta_max 30 deg,
// flat jaw faces through the pivot) with `block` after its application
// line; `line` is set to the line of the block's first line.
const std::string kApplication = "application: {from: 25 mm, to: 75 mm}\n";
std::string nutcracker_with(const std::string& block, int* line = nullptr) {
  const std::string text = read_text(kSource + "/objects/nutcracker.yaml");
  const size_t at = text.find(kApplication);
  if (line != nullptr) *line = static_cast<int>(std::count(text.begin(), text.begin() + at, '\n')) + 2;
  return replace_once(text, kApplication, kApplication + block);
}

ObjectSpec object_of(const std::string& text) { return read_object(load_yaml_string(text, "bad.yaml")); }

// A table that differs from the wedge (r/2 at 30 deg: 12.5, 25, 37.5 mm):
// the gap grows by 0.2 mm per mm, then by 0.6.
const std::string kTable =
    "interaction_space:\n"
    "  distances: [25 mm, 50 mm, 75 mm]\n"
    "  gap_at_theta_max: [5 mm, 10 mm, 25 mm]\n";

std::string load_error(const std::string& block, int* line) {
  const std::string text = nutcracker_with(block, line);
  return thrown<DataError>([&] { (void)object_of(text); });
}

TEST(InteractionSpaceLoad, ReadsTheTableInMetres) {
  const ObjectSpec o = object_of(nutcracker_with(kTable));
  EXPECT_THAT(o.interaction_space.distances, ::testing::ElementsAre(0.025, 0.050, 0.075));
  EXPECT_THAT(o.interaction_space.gaps, ::testing::ElementsAre(0.005, 0.010, 0.025));
  // Without the key: no table, the wedge.
  EXPECT_TRUE(object_of(nutcracker_with("")).interaction_space.distances.empty());
}

TEST(InteractionSpaceLoad, EachMistakeIsLocated) {
  int line = 0;
  auto at = [&line](int below, int column) {
    return "bad.yaml:" + std::to_string(line + below) + ":" + std::to_string(column) + ": ";
  };
  // An unknown key, with a hint.
  std::string e = load_error(
      "interaction_space:\n  distances: [25 mm, 75 mm]\n  gaps: [5 mm, 40 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(2, 3)));
  EXPECT_THAT(e, HasSubstr("gap_at_theta_max"));
  // Lengths that differ: at the gaps' sequence.
  e = load_error("interaction_space:\n  distances: [25 mm, 50 mm, 75 mm]\n  gap_at_theta_max: [5 mm, 10 mm]\n",
                 &line);
  EXPECT_THAT(e, HasSubstr(at(2, 21) + "expected as many gaps as distances (3), found 2"));
  // Distances that do not increase: at the one that goes back.
  e = load_error(
      "interaction_space:\n  distances: [25 mm, 60 mm, 50 mm]\n  gap_at_theta_max: [5 mm, 10 mm, 40 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(1, 29) + "expected a distance greater than the one before (60 mm), found '50 mm'"));
  e = load_error(
      "interaction_space:\n  distances: [25 mm, 25 mm, 50 mm]\n  gap_at_theta_max: [5 mm, 10 mm, 40 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(1, 22) + "expected a distance greater than the one before (25 mm)"));
  // A negative gap.
  e = load_error(
      "interaction_space:\n  distances: [25 mm, 50 mm, 75 mm]\n  gap_at_theta_max: [5 mm, -1 mm, 40 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(2, 28) + "expected a value of zero or more"));
  // A distance outside the application region (25 to 75 mm).
  e = load_error(
      "interaction_space:\n  distances: [25 mm, 50 mm, 80 mm]\n  gap_at_theta_max: [5 mm, 10 mm, 40 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(1, 29) + "expected a distance in the application region, between 25 mm and 75 mm"));
  e = load_error(
      "interaction_space:\n  distances: [20 mm, 50 mm, 75 mm]\n  gap_at_theta_max: [5 mm, 10 mm, 40 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(1, 15) + "expected a distance in the application region"));
  // A gap that changes faster than the distance: the moving jaw's nearest
  // point to one place is at most 25 mm farther from the next.
  e = load_error(
      "interaction_space:\n  distances: [25 mm, 50 mm, 75 mm]\n  gap_at_theta_max: [5 mm, 10 mm, 36 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(2, 35) + "expected a gap within 25 mm of the one before (10 mm)"));
  // Fewer than two, a wrong unit, a missing key.
  e = load_error("interaction_space:\n  distances: [50 mm]\n  gap_at_theta_max: [10 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(1, 14) + "expected a sequence of at least 2 distances"));
  e = load_error("interaction_space:\n  distances: [25 mm, 75 mm]\n  gap_at_theta_max: [5 mm, 40 N]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(2, 28)));
  e = load_error("interaction_space:\n  distances: [25 mm, 75 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(1, 3) + "expected key 'gap_at_theta_max' in the interaction space"));
  // Not a mapping.
  e = load_error("interaction_space: [25 mm, 75 mm]\n", &line);
  EXPECT_THAT(e, HasSubstr(at(0, 20)));
}

// A ball of radius `radius` (m): the actee the fits below are worked with.
ActeeSpec ball(double radius) {
  const std::string mm = std::to_string(radius * 1e3);
  return read_actee(load_yaml_string("actee: ball\n"
                                     "description: A ball.\n"
                                     "shape: {sphere: {radius: " + mm + " mm}}\n"
                                     "mass: 2 g\n"
                                     "force_direction: [0, 1, 0]\n"
                                     "limit: 50 N\n"
                                     "stiffness: 50 N/mm\n"
                                     "breaks: true\n"
                                     "friction: {coefficient: 0.4, source: a test}\n",
                                     "ball.yaml"));
}

ActeeFit fit_of(const ObjectSpec& o, const ActeeSpec& a) {
  ModelOptions options;
  options.actee.in_jaws = false;
  return fit_actee(compile(o, &a, nullptr, options));
}

TEST(InteractionSpaceDerive, TheTableReplacesTheWedge) {
  const ObjectSpec o = object_of(nutcracker_with(kTable));
  const Model m = compile(o, nullptr, nullptr, ModelOptions{});
  const InteractionSpace s = interaction_space(m);
  EXPECT_TRUE(s.from_shape);
  EXPECT_EQ(s.from, 0.025);
  EXPECT_EQ(s.to, 0.075);
  EXPECT_EQ(s.gap_from, 0.005);
  EXPECT_EQ(s.gap_to, 0.025);
  // Linear between the distances: 37.5 mm is halfway from 5 to 10 mm,
  // 60 mm two fifths from 10 to 25 mm.
  EXPECT_NEAR(gap_at(m, s, 0.0375), 0.0075, 1e-15);
  EXPECT_NEAR(gap_at(m, s, 0.060), 0.016, 1e-15);
  EXPECT_EQ(gap_at(m, s, 0.050), 0.010);
  // The thickest actee that clears the jaw there: the jaw's face tilts by
  // asin 0.6 from 50 mm on (cos 0.8), so 2 * 16 mm / 1.8 at 60 mm; by
  // asin 0.2 before (cos sqrt 0.96).
  EXPECT_NEAR(clearance_at(m, s, 0.060), 0.032 / 1.8, 1e-15);
  EXPECT_NEAR(clearance_at(m, s, 0.0375), 0.015 / (1 + std::sqrt(0.96)), 1e-15);

  // The wedge without the table: |r| sin 30 deg = r / 2 apart, and the
  // inscribed ball 2 r tan 15 deg.
  const Model wedge = compile(object_of(nutcracker_with("")), nullptr, nullptr, ModelOptions{});
  const InteractionSpace w = interaction_space(wedge);
  EXPECT_FALSE(w.from_shape);
  EXPECT_EQ(w.from, 0.025);
  EXPECT_NEAR(w.gap_from, 0.0125, 1e-15);
  EXPECT_NEAR(w.gap_to, 0.0375, 1e-15);
  EXPECT_NEAR(gap_at(wedge, w, 0.060), 0.030, 1e-15);
  EXPECT_NEAR(clearance_at(wedge, w, 0.060), 0.120 * std::tan(15 * kDeg), 1e-15);
}

TEST(InteractionSpaceDerive, AnActeeFitsWhereTheTableClearsIt) {
  // A 12 mm ball. Before 50 mm the table clears at most 2 * 10 mm / 1.98;
  // beyond, 2 g / 1.8 >= 12 mm where g >= 10.8 mm, from 50 + 0.8 / 0.6 =
  // 51.33 mm. The placements are 25 + 1.25 i mm: the first beyond it is
  // 52.5 mm. There the flat moving jaw through the pivot touches the ball
  // at the opening whose half-angle has tan = 6 / 52.5, and pushes it at
  // 52.5 mm from the pivot (equal tangents).
  const ObjectSpec o = object_of(nutcracker_with(kTable));
  const ActeeFit fit = fit_of(o, ball(0.006));
  ASSERT_TRUE(fit.fits) << fit.why;
  EXPECT_NEAR(fit.from, 0.0525, 1e-12);
  EXPECT_NEAR(fit.to, 0.075, 1e-12);
  const double theta_c = 2 * std::atan(0.006 / 0.0525);
  EXPECT_NEAR(fit.contact_angle, theta_c, 1e-6);
  const Model m = compile(o, nullptr, nullptr, ModelOptions{});
  // The effort at the handle's far end (180 mm) that reaches the ball's
  // 50 N limit: the spring's moment (at 10 mm) and the load's, over 180 mm.
  const double effort = (spring_force(m, theta_c) * 0.010 + 50 * 0.0525) / 0.180;
  EXPECT_NEAR(fit.effort_to_limit, effort, 1e-4 * effort);

  // The wedge clears it wherever the inscribed ball, 2 r tan 15 deg, is
  // 12 mm or more (r >= 22.4 mm): over the whole application region.
  const ActeeFit wedge = fit_of(object_of(nutcracker_with("")), ball(0.006));
  ASSERT_TRUE(wedge.fits);
  EXPECT_NEAR(wedge.from, 0.025, 1e-12);

  // A 30 mm ball is thicker than the table ever clears, 2 * 25 mm / 1.8 =
  // 27.8 mm; the wedge would take it from 15 mm / tan 15 deg = 56 mm on.
  const ActeeFit large = fit_of(o, ball(0.015));
  EXPECT_FALSE(large.fits);
  EXPECT_THAT(large.why, HasSubstr("the jaws fully open (5 mm to 25 mm apart"));
  EXPECT_THAT(large.why, HasSubstr("30 mm across"));
  EXPECT_TRUE(fit_of(object_of(nutcracker_with("")), ball(0.015)).fits);
}

TEST(InteractionSpaceGuide, DrawsTheTablesStrip) {
  // The strip over the fixed jaw's face up to the gap at each distance:
  // (5 + 10) / 2 * 25 + (10 + 25) / 2 * 25 = 625 mm^2, through the
  // nutcracker's 16 mm (its parts' extent along the pivot), closed and
  // wound outward: 10,000 mm^3.
  const Model m = compile(object_of(nutcracker_with(kTable)), nullptr, nullptr, ModelOptions{});
  const Guides g = compute_guides(m, load_guides(kSource + "/rules/guides.yaml"), {});
  ASSERT_EQ(g.meshes.size(), 1u);
  const GuideMesh& mesh = g.meshes[0];
  ASSERT_EQ(mesh.vertices.size(), 12u);
  EXPECT_EQ(mesh.triangles.size(), 2u * (2 * 4 + 2));
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    volume += mesh.vertices[static_cast<size_t>(t[0])].dot(
                  mesh.vertices[static_cast<size_t>(t[1])].cross(mesh.vertices[static_cast<size_t>(t[2])])) /
              6;
  }
  EXPECT_NEAR(volume, 625e-6 * 0.016, 1e-15);
  EXPECT_EQ(mesh.vertices[5], Eigen::Vector3d(0.050, 0.010, -0.008));
  EXPECT_TRUE(g.facts.space.from_shape);
}

// tests/data/partnet's stapler modelled, with a spring so that it runs.
ObjectSpec modelled_stapler(const std::string& dir) {
  modelling::ToolModelOptions o;
  o.name = "stapler";
  o.density = 7850;
  o.spring = modelling::SpringGiven{0.5, 40 * kDeg, std::nullopt};
  const modelling::ToolModel m =
      modelling::model_tool(modelling::read_urdf_tool(kSource + "/tests/data/partnet/stapler/mobility.urdf"), o);
  const std::string file = dir + "/stapler.yaml";
  std::ofstream(file) << modelling::object_yaml(m);
  return load_object(file);
}

TEST(InteractionSpaceModel, AStaplersActeeIsPlacedFromItsShape) {
  const fs::path dir = fs::temp_directory_path() / ("afford_space_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const ObjectSpec o = modelled_stapler(dir.string());
  // The head (120 to 150 mm of the top) reaches the base; the rest of the
  // top stands 3 mm above it. Opened 25 deg the head's inner corner is at
  // (120 cos 25, 120 sin 25) deg = (108.76, 50.71) mm: where the foot of
  // the perpendicular from the base misses the head (r cos 25 deg < 120
  // mm) the gap runs to that corner, wider than the wedge's r sin 25 deg;
  // beyond, it is the wedge's.
  const InteractionSpaceSpec& s = o.interaction_space;
  ASSERT_EQ(s.distances.size(), 9u);
  EXPECT_NEAR(s.distances.front(), o.application.from, 1e-9);
  EXPECT_NEAR(s.distances.back(), 0.150, 1e-6);
  const double cx = 0.120 * std::cos(25 * kDeg), cy = 0.120 * std::sin(25 * kDeg);
  const double r0 = s.distances.front();
  EXPECT_NEAR(s.gaps.front(), std::hypot(r0 - cx, cy), 1e-6);
  EXPECT_GT(s.gaps.front(), r0 * std::sin(25 * kDeg) + 1e-3);
  EXPECT_NEAR(s.gaps.back(), 0.150 * std::sin(25 * kDeg), 1e-6);

  // A 53 mm ball: resting at r its centre is 26.5 mm up, clear of the
  // corner while r >= 108.76 + sqrt(26.5^2 - 24.21^2) = 119.54 mm, where
  // the parts alone (without the table) let it fit. The table, which
  // sees the jaw as a straight face, is stricter there: on its first piece
  // (the gaps at its first two places, 3.8 mm apart, by the corner) the
  // face tilts by alpha, sin alpha = the slope, and clears 53 mm where
  // 2 g / (1 + cos alpha) = 53 mm. Each fits from the first of the 41
  // placements (0.77 mm apart) beyond.
  const double step = (s.distances.back() - s.distances.front()) / 40;
  const double r1 = s.distances[1];
  const double g0 = std::hypot(r0 - cx, cy), g1 = std::hypot(r1 - cx, cy);
  const double slope = (g1 - g0) / (r1 - r0);
  const double by_table = r0 + (0.053 * (1 + std::sqrt(1 - slope * slope)) / 2 - g0) / slope;
  ASSERT_LT(by_table, r1);
  const ActeeFit fit = fit_actees(o, {ball(0.0265)}).front();
  ASSERT_TRUE(fit.fits) << fit.why;
  EXPECT_GT(fit.from, by_table - 1e-6);
  EXPECT_LT(fit.from, by_table + step);
  EXPECT_NEAR(fit.to, s.distances.back(), 1e-9);

  // explore spreads its placements over where it fits.
  std::ofstream(dir / "ball.yaml") << "actee: ball\ndescription: A ball.\nshape: {sphere: {radius: 26.5 mm}}\n"
                                      "mass: 2 g\nforce_direction: [0, 1, 0]\nlimit: 50 N\nstiffness: 50 N/mm\n"
                                      "breaks: true\nfriction: {coefficient: 0.4, source: a test}\n";
  ExploreFiles files;
  files.object = (dir / "stapler.yaml").string();
  files.agent = kSource + "/agents/hand.yaml";
  files.rules = kSource + "/rules/functions.yaml";
  files.grasps = kSource + "/rules/grasps.yaml";
  files.actees = {(dir / "ball.yaml").string()};
  GridOptions grid;
  grid.placements = 3;
  const Explorer e = make_explorer(files, grid);
  fs::remove_all(dir);
  ASSERT_EQ(e.grid.actees.size(), 1u);
  const std::vector<double>& at = e.grid.actees[0].placements;
  ASSERT_EQ(at.size(), 3u);
  EXPECT_NEAR(at[0], fit.from, 1e-12);
  EXPECT_NEAR(at[1], 0.5 * (fit.from + fit.to), 1e-12);
  EXPECT_NEAR(at[2], fit.to, 1e-12);

  ObjectSpec without = o;
  without.interaction_space = {};
  const ActeeFit by_parts = fit_actees(without, {ball(0.0265)}).front();
  ASSERT_TRUE(by_parts.fits);
  const double by_corner = cx + std::sqrt(0.0265 * 0.0265 - std::pow(cy - 0.0265, 2));
  EXPECT_GT(by_parts.from, by_corner - 1e-4);
  EXPECT_LT(by_parts.from, by_corner + step);
}

}  // namespace
}  // namespace afford::test
