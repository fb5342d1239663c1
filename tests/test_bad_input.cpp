// Every kind of mistake a user can make in an object, actee or agent file is
// reported as "file:line:col: expected X, found Y", at the offending token.
// Each test starts from a valid document (the content of a shipped example,
// without its comments, fixed here so that line numbers stay put) and
// changes one thing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_util.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <unistd.h>

#include "errors.h"
#include "load.h"
#include "model.h"
#include "validate.h"

namespace afford {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using test::replace_once;

// objects/nutcracker.yaml. Line numbers are given in the comments.
const std::string kNutcracker =
    "object: nutcracker\n"                                                   // 1
    "description: Hinged nutcracker, 185 mm, jaws near the hinge.\n"         // 2
    "mass: 190 g\n"                                                          // 3
    "centre_of_gravity: [80 mm, 0 mm, 0 mm]\n"                               // 4
    "functional_pose:\n"                                                     // 5
    "  position: [0 mm, 0 mm, 100 mm]\n"                                     // 6
    "  rotation: [0 deg, 0 deg, 0 deg]\n"                                    // 7
    "symmetry_plane:\n"                                                      // 8
    "  point: [0 mm, 0 mm, 0 mm]\n"                                          // 9
    "  normal: [0, 0, 1]\n"                                                  // 10
    "lever:\n"                                                               // 11
    "  pattern: type2\n"                                                     // 12
    "  arm: {from: 0 mm, to: 185 mm}\n"                                      // 13
    "  theta_min: 0 deg\n"                                                   // 14
    "  theta_max: 60 deg\n"                                                  // 15
    "  rest: 60 deg\n"                                                       // 16
    "spring:\n"                                                              // 17
    "  constant: 600 N/m\n"                                                  // 18
    "  position: 25 mm\n"                                                    // 19
    "  preload: 1.5 N\n"                                                     // 20
    "emphasis: {from: 110 mm, to: 180 mm}\n"                                 // 21
    "application: {from: 20 mm, to: 75 mm}\n"                                // 22
    "parts:\n"                                                               // 23
    "  - name: fixed_arm\n"                                                  // 24
    "    arm: fixed\n"                                                       // 25
    "    shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n"                     // 26
    "    position: [92.5 mm, -6 mm, 0 mm]\n"                                 // 27
    "  - name: moving_arm\n"                                                 // 28
    "    arm: moving\n"                                                      // 29
    "    shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n"                     // 30
    "    position: [92.5 mm, 6 mm, 0 mm]\n"                                  // 31
    "effects:\n"                                                             // 32
    "  pivot_friction: {torque: 0.01 N*m}\n"                                 // 33
    "  viscous_damping: {coefficient: 0.0005 N*m*s/rad, enabled: false}\n";  // 34

// actees/walnut.yaml.
const std::string kWalnut =
    "actee: walnut\n"                                                  // 1
    "description: Walnut in shell, 36 x 28 mm.\n"                      // 2
    "shape: {ellipsoid: {radii: [18 mm, 14.1 mm, 14.1 mm]}}\n"         // 3
    "mass: 9 g\n"                                                      // 4
    "force_direction: [0, 1, 0]\n"                                     // 5
    "limit: 378 N\n"                                                   // 6
    "stiffness: 250 N/mm\n"                                            // 7
    "breaks: true\n"                                                   // 8
    "friction: {coefficient: 0.35, source: walnut.yaml}\n";            // 9

// agents/hand.yaml.
const std::string kHand =
    "agent: hand\n"                                                    // 1
    "description: Adult right hand, power grip up to 400 N.\n"         // 2
    "force_gain: 5 N/mm\n"                                             // 3
    "max_force: 400 N\n"                                               // 4
    "fingers:\n"                                                       // 5
    "  thumb:\n"                                                       // 6
    "    tip_radius: 10.5 mm\n"                                        // 7
    "    distal: [-20 deg, 80 deg]\n"                                  // 8
    "    proximal: [0 deg, 50 deg]\n"                                  // 9
    "    metacarpal: [0 deg, 70 deg]\n"                                // 10
    "  index:\n"                                                       // 11
    "    tip_radius: 9 mm\n"                                           // 12
    "    distal: [0 deg, 90 deg]\n"                                    // 13
    "    proximal: [0 deg, 100 deg]\n"                                 // 14
    "    metacarpal: [-45 deg, 90 deg]\n"                              // 15
    "  middle:\n"                                                      // 16
    "    tip_radius: 9 mm\n"                                           // 17
    "    distal: [0 deg, 90 deg]\n"                                    // 18
    "    proximal: [0 deg, 100 deg]\n"                                 // 19
    "    metacarpal: [-45 deg, 90 deg]\n"                              // 20
    "  ring:\n"                                                        // 21
    "    tip_radius: 8.5 mm\n"                                         // 22
    "    distal: [0 deg, 90 deg]\n"                                    // 23
    "    proximal: [0 deg, 100 deg]\n"                                 // 24
    "    metacarpal: [-45 deg, 90 deg]\n"                              // 25
    "  little:\n"                                                      // 26
    "    tip_radius: 8 mm\n"                                           // 27
    "    distal: [0 deg, 90 deg]\n"                                    // 28
    "    proximal: [0 deg, 100 deg]\n"                                 // 29
    "    metacarpal: [-45 deg, 90 deg]\n";                             // 30


// The message of the DataError that `run` throws; fails the test when it
// throws nothing or anything else.
std::string data_error(const std::function<void()>& run) {
  try {
    run();
  } catch (const DataError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected a DataError, got another exception: " << e.what();
    return "";
  } catch (...) {
    ADD_FAILURE() << "expected a DataError, got a non-standard exception";
    return "";
  }
  ADD_FAILURE() << "expected a DataError, nothing was thrown";
  return "";
}

std::string object_error(const std::string& text) {
  return data_error([&] { (void)read_object(load_yaml_string(text, "bad.yaml")); });
}
std::string actee_error(const std::string& text) {
  return data_error([&] { (void)read_actee(load_yaml_string(text, "bad.yaml")); });
}
std::string agent_error(const std::string& text) {
  return data_error([&] { (void)read_agent(load_yaml_string(text, "bad.yaml")); });
}
// Objects whose mistake only compiling the shapes finds.
std::string compile_error(const std::string& text) {
  return data_error([&] {
    const ObjectSpec o = read_object(load_yaml_string(text, "bad.yaml"));
    (void)compile(o, nullptr, nullptr, ModelOptions{});
  });
}

// A file in the temporary directory, removed at the end of the test.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& text)
      : path_(std::filesystem::temp_directory_path() /
              ("afford_bad_input_" + std::to_string(::getpid()) + "_" + name)) {
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

std::string validate_error(const std::string& path) {
  return data_error([&] { (void)validate_file(path); });
}

// ---------------------------------------------------------------- the base documents

TEST(BadInputBase, NutcrackerIsValid) {
  const ObjectSpec o = read_object(load_yaml_string(kNutcracker, "good.yaml"));
  EXPECT_EQ(o.name, "nutcracker");
  EXPECT_DOUBLE_EQ(o.mass, 0.19);
  EXPECT_DOUBLE_EQ(o.spring.constant, 600.0);
  EXPECT_DOUBLE_EQ(o.spring.position, 0.025);
  EXPECT_EQ(o.lever.pattern, LeverPattern::type2);
  EXPECT_EQ(o.parts.size(), 2u);
  EXPECT_EQ(o.effects.size(), 3u);  // pivot_friction, viscous_damping and the spring's preload
  EXPECT_EQ(o.effects.back().kind, EffectKind::spring_preload);
  (void)compile(o, nullptr, nullptr, ModelOptions{});
}

TEST(BadInputBase, WalnutIsValid) {
  const ActeeSpec a = read_actee(load_yaml_string(kWalnut, "good.yaml"));
  EXPECT_EQ(a.name, "walnut");
  EXPECT_DOUBLE_EQ(a.limit, 378.0);
  EXPECT_DOUBLE_EQ(a.stiffness, 250e3);
  EXPECT_TRUE(a.breaks);
}

TEST(BadInputBase, HandIsValid) {
  const AgentSpec a = read_agent(load_yaml_string(kHand, "good.yaml"));
  EXPECT_EQ(a.name, "hand");
  EXPECT_DOUBLE_EQ(a.force_gain, 5e3);
  EXPECT_DOUBLE_EQ(a.fingers[4].tip_radius, 0.008);
  EXPECT_DOUBLE_EQ(a.fingers[0].joint_min[0], -20.0 * std::numbers::pi / 180.0);
}

// ---------------------------------------------------------------- unknown keys

// A misspelt required key is reported where it is written, with the key it
// is closest to: unknown keys are found before any key counts as missing.
TEST(BadInputObject, MisspeltRequiredKeySaysDidYouMean) {
  const std::string e =
      object_error(replace_once(kNutcracker, "  constant: 600 N/m", "  constnat: 600 N/m"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:3:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the spring (constant, position, rest_length, preload), "
                           "found 'constnat' (did you mean 'constant'?)"));
}

// A key simply left out is missing, reported at its mapping.
TEST(BadInputObject, MissingRequiredKey) {
  const std::string e = object_error(replace_once(kNutcracker, "  constant: 600 N/m\n", ""));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:3:"));
  EXPECT_THAT(e, HasSubstr("expected key 'constant' in the spring, found no such key"));
}

// With 'constant' there, 'constnat' is an unknown key, named with the key
// it is closest to.
TEST(BadInputObject, UnknownKeySaysDidYouMean) {
  const std::string e =
      object_error(replace_once(kNutcracker, "  constant: 600 N/m\n", "  constant: 600 N/m\n  constnat: 600 N/m\n"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:19:3:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the spring (constant, position, rest_length, preload)"));
  EXPECT_THAT(e, HasSubstr("found 'constnat' (did you mean 'constant'?)"));
}

TEST(BadInputObject, MisspeltPreloadSaysDidYouMean) {
  const std::string e = object_error(replace_once(kNutcracker, "  preload: 1.5 N", "  prelaod: 1.5 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:20:3:"));
  EXPECT_THAT(e, HasSubstr("found 'prelaod' (did you mean 'preload'?)"));
}

TEST(BadInputObject, MisspeltOptionalKeySaysDidYouMean) {
  const std::string e = object_error(
      replace_once(kNutcracker, "  rotation: [0 deg", "  rotaton: [0 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:7:3:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the functional pose (position, rotation)"));
  EXPECT_THAT(e, HasSubstr("found 'rotaton' (did you mean 'rotation'?)"));
}

TEST(BadInputObject, ExtraKeyAtTheEnd) {
  const std::string e = object_error(kNutcracker + "colour: red\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:35:1:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of an object file (object, description"));
  EXPECT_THAT(e, HasSubstr("found 'colour'"));
}

TEST(BadInputObject, UnknownEffectParameter) {
  const std::string e =
      object_error(replace_once(kNutcracker, "0.0005 N*m*s/rad, enabled:", "0.0005 N*m*s/rad, enable:"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:34:52:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the effect viscous_damping (enabled, coefficient)"));
  EXPECT_THAT(e, HasSubstr("found 'enable' (did you mean 'enabled'?)"));
}

TEST(BadInputActee, MisspeltKeySaysDidYouMean) {
  const std::string e = actee_error(replace_once(kWalnut, "stiffness: 250", "stifness: 250"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:7:1:"));
  EXPECT_THAT(e, HasSubstr("found 'stifness' (did you mean 'stiffness'?)"));
}

TEST(BadInputActee, UnknownKeySaysDidYouMean) {
  const std::string e = actee_error(kWalnut + "stifness: 250 N/mm\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:10:1:"));
  EXPECT_THAT(e, HasSubstr("found 'stifness' (did you mean 'stiffness'?)"));
}

TEST(BadInputActee, ExtraKey) {
  const std::string e = actee_error(kWalnut + "colour: brown\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:10:1:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of an actee file (actee, description, shape, "
                           "mass, force_direction, limit, stiffness, breaks, friction, effects, look), found 'colour'"));
}

TEST(BadInputAgent, MisspeltFingerSaysDidYouMean) {
  const std::string e = agent_error(replace_once(kHand, "  middle:", "  midle:"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:16:3:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the fingers (thumb, index, middle, ring, little), "
                           "found 'midle' (did you mean 'middle'?)"));
}

TEST(BadInputAgent, SixthFinger) {
  const std::string e = agent_error(kHand + "  sixth:\n    tip_radius: 8 mm\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:31:3:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the fingers (thumb, index, middle, ring, "
                           "little), found 'sixth'"));
}

TEST(BadInputAgent, ExtraJointSaysDidYouMean) {
  const std::string e = agent_error(replace_once(kHand, "    proximal: [0 deg, 50 deg]\n",
                                                 "    proximal: [0 deg, 50 deg]\n    proximl: [0 deg, 50 deg]\n"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:10:5:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the thumb (tip_radius, distal, proximal, metacarpal), "
                           "found 'proximl' (did you mean 'proximal'?)"));
}

// ---------------------------------------------------------------- duplicate keys

TEST(BadInputObject, DuplicateKey) {
  const std::string e = object_error(replace_once(kNutcracker, "mass: 190 g\n", "mass: 190 g\nmass: 200 g\n"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:4:1:"));
  EXPECT_THAT(e, HasSubstr("expected each key once in an object file, found 'mass' again"));
}

TEST(BadInputObject, DuplicateKeyInFlowMapping) {
  const std::string e = object_error(
      replace_once(kNutcracker, "emphasis: {from: 110 mm, to: 180 mm}", "emphasis: {from: 110 mm, from: 120 mm}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:21:26:"));
  EXPECT_THAT(e, HasSubstr("expected each key once in the emphasis region, found 'from' again"));
}

TEST(BadInputActee, DuplicateKey) {
  const std::string e = actee_error(kWalnut + "limit: 400 N\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:10:1:"));
  EXPECT_THAT(e, HasSubstr("expected each key once in an actee file, found 'limit' again"));
}

TEST(BadInputAgent, DuplicateFinger) {
  const std::string e = agent_error(kHand + "  index:\n    tip_radius: 8 mm\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:31:3:"));
  EXPECT_THAT(e, HasSubstr("expected each key once in the fingers, found 'index' again"));
}

// ---------------------------------------------------------------- wrong types

TEST(BadInputObject, SequenceWhereQuantityExpected) {
  const std::string e = object_error(replace_once(kNutcracker, "mass: 190 g", "mass: [190 g]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:7:"));
  EXPECT_THAT(e, HasSubstr("expected a mass (e.g. '120 g'), found a sequence of 1"));
}

TEST(BadInputObject, MappingWhereNameExpected) {
  const std::string e =
      object_error(replace_once(kNutcracker, "object: nutcracker", "object: {name: nutcracker}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:1:9:"));
  EXPECT_THAT(e, HasSubstr("expected a text, found a mapping"));
}

TEST(BadInputObject, NameWithASpace) {
  const std::string e = object_error(replace_once(kNutcracker, "name: fixed_arm", "name: fixed arm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:24:11:"));
  EXPECT_THAT(e, HasSubstr("expected a name of letters, digits, '_' and '-', found 'fixed arm'"));
}

TEST(BadInputObject, VectorOfTwo) {
  const std::string e = object_error(
      replace_once(kNutcracker, "centre_of_gravity: [80 mm, 0 mm, 0 mm]", "centre_of_gravity: [80 mm, 0 mm]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:4:20:"));
  EXPECT_THAT(e, HasSubstr("expected a sequence of three, each a length (e.g. '18 mm'), found a sequence of 2"));
}

TEST(BadInputObject, ScalarWhereMappingExpected) {
  const std::string e = object_error(
      replace_once(kNutcracker, "emphasis: {from: 110 mm, to: 180 mm}", "emphasis: 110 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:21:11:"));
  EXPECT_THAT(e, HasSubstr("expected a mapping for the emphasis region, found '110 mm'"));
}

TEST(BadInputObject, PartsNotASequence) {
  const size_t parts = kNutcracker.find("parts:");
  const size_t effects = kNutcracker.find("effects:");
  ASSERT_LT(parts, effects);
  const std::string e =
      object_error(kNutcracker.substr(0, parts) + "parts: fixed_arm\n" + kNutcracker.substr(effects));
  EXPECT_THAT(e, HasSubstr("bad.yaml:23:8:"));
  EXPECT_THAT(e, HasSubstr("expected a sequence of parts, found 'fixed_arm'"));
}

TEST(BadInputObject, EnabledNotABool) {
  const std::string e = object_error(replace_once(kNutcracker, "enabled: false", "enabled: no"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:34:61:"));
  EXPECT_THAT(e, HasSubstr("expected true or false, found 'no'"));
}

TEST(BadInputActee, BreaksNotABool) {
  const std::string e = actee_error(replace_once(kWalnut, "breaks: true", "breaks: yes"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:8:9:"));
  EXPECT_THAT(e, HasSubstr("expected true or false, found 'yes'"));
}

TEST(BadInputActee, SequenceWhereQuantityExpected) {
  const std::string e = actee_error(replace_once(kWalnut, "limit: 378 N", "limit: [378 N]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:6:8:"));
  EXPECT_THAT(e, HasSubstr("expected a force (e.g. '30 N'), found a sequence of 1"));
}

TEST(BadInputActee, MappingWhereNameExpected) {
  const std::string e = actee_error(replace_once(kWalnut, "actee: walnut", "actee: {walnut: 1}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:1:8:"));
  EXPECT_THAT(e, HasSubstr("expected a text, found a mapping"));
}

TEST(BadInputActee, DirectionWithUnits) {
  const std::string e = actee_error(replace_once(kWalnut, "[0, 1, 0]", "[0, 1 mm, 0]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:5:22:"));
  EXPECT_THAT(e, HasSubstr("expected a finite number, found '1 mm'"));
}

TEST(BadInputAgent, FingersAsASequence) {
  const std::string e = agent_error(kHand.substr(0, kHand.find("fingers:")) + "fingers: [thumb, index]\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:5:10:"));
  EXPECT_THAT(e, HasSubstr("expected a mapping for the fingers, found a sequence of 2"));
}

TEST(BadInputAgent, JointNotAPair) {
  const std::string e = agent_error(replace_once(kHand, "distal: [-20 deg, 80 deg]", "distal: [-20 deg]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:8:13:"));
  EXPECT_THAT(e, HasSubstr("expected a pair [min, max] of angles, found a sequence of 1"));
}

// ---------------------------------------------------------------- missing keys and values

TEST(BadInputObject, MissingKeyReportedAtTheFile) {
  const std::string e = object_error(replace_once(kNutcracker, "mass: 190 g\n", ""));
  EXPECT_THAT(e, HasSubstr("bad.yaml:1:1:"));
  EXPECT_THAT(e, HasSubstr("expected key 'mass' in an object file, found no such key"));
}

TEST(BadInputObject, MissingKeyReportedAtItsMapping) {
  const std::string e = object_error(replace_once(kNutcracker, "  rest: 60 deg\n", ""));
  EXPECT_THAT(e, HasSubstr("bad.yaml:12:3:"));
  EXPECT_THAT(e, HasSubstr("expected key 'rest' in the lever, found no such key"));
}

TEST(BadInputObject, MissingKeyInFlowMapping) {
  const std::string e = object_error(replace_once(kNutcracker, "{from: 0 mm, to: 185 mm}", "{from: 0 mm}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:13:8:"));
  EXPECT_THAT(e, HasSubstr("expected key 'to' in the arm's extent, found no such key"));
}

TEST(BadInputObject, KeyWithoutValue) {
  const std::string e = object_error(replace_once(kNutcracker, "mass: 190 g", "mass:"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:1:"));
  EXPECT_THAT(e, HasSubstr("expected a value for 'mass', found nothing"));
}

TEST(BadInputObject, NeitherRestLengthNorPreload) {
  const std::string e = object_error(replace_once(kNutcracker, "  preload: 1.5 N\n", ""));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:3:"));
  EXPECT_THAT(e, HasSubstr("expected exactly one of rest_length and preload, found neither"));
}

TEST(BadInputActee, MissingKey) {
  const std::string e = actee_error(replace_once(kWalnut, "breaks: true\n", ""));
  EXPECT_THAT(e, HasSubstr("bad.yaml:1:1:"));
  EXPECT_THAT(e, HasSubstr("expected key 'breaks' in an actee file, found no such key"));
}

TEST(BadInputActee, MissingShapeKey) {
  const std::string e = actee_error(replace_once(kWalnut, "{radii: [18 mm, 14.1 mm, 14.1 mm]}", "{}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:20:"));
  EXPECT_THAT(e, HasSubstr("expected key 'radii' in a ellipsoid, found no such key"));
}

TEST(BadInputAgent, MissingFinger) {
  const std::string e = agent_error(kHand.substr(0, kHand.find("  little:")));
  EXPECT_THAT(e, HasSubstr("bad.yaml:6:3:"));
  EXPECT_THAT(e, HasSubstr("expected key 'little' in the fingers, found no such key"));
}

TEST(BadInputAgent, MissingTipRadius) {
  const std::string e = agent_error(replace_once(kHand, "    tip_radius: 8.5 mm\n", ""));
  EXPECT_THAT(e, HasSubstr("bad.yaml:22:5:"));
  EXPECT_THAT(e, HasSubstr("expected key 'tip_radius' in the ring, found no such key"));
}

// ---------------------------------------------------------------- values that are not finite

TEST(BadInputObject, InfiniteMass) {
  const std::string e = object_error(replace_once(kNutcracker, "mass: 190 g", "mass: .inf"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:7:"));
  EXPECT_THAT(e, HasSubstr("expected a mass (e.g. '120 g') (a finite number followed by a unit), found '.inf'"));
}

TEST(BadInputObject, NanSpringConstant) {
  const std::string e = object_error(replace_once(kNutcracker, "constant: 600 N/m", "constant: nan N/m"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:13:"));
  EXPECT_THAT(e, HasSubstr("expected a stiffness (e.g. '800 N/m') (a finite number followed by a unit), "
                           "found 'nan N/m'"));
}

TEST(BadInputObject, OverflowingPreload) {
  const std::string e = object_error(replace_once(kNutcracker, "preload: 1.5 N", "preload: 1e999 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:20:12:"));
  EXPECT_THAT(e, HasSubstr("expected a force (e.g. '30 N') (a finite number followed by a unit), found '1e999 N'"));
}

TEST(BadInputObject, FiniteNumberThatOverflowsInSI) {
  const std::string e = object_error(replace_once(kNutcracker, "preload: 1.5 N", "preload: 1e308 kN"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:20:12:"));
  EXPECT_THAT(e, HasSubstr("expected a finite value, found '1e308 kN'"));
}

TEST(BadInputObject, NanInPlainVector) {
  const std::string e = object_error(replace_once(kNutcracker, "normal: [0, 0, 1]", "normal: [0, .nan, 1]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:10:15:"));
  EXPECT_THAT(e, HasSubstr("expected a finite number, found '.nan'"));
}

TEST(BadInputActee, InfiniteLimit) {
  const std::string e = actee_error(replace_once(kWalnut, "limit: 378 N", "limit: .inf"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:6:8:"));
  EXPECT_THAT(e, HasSubstr("expected a force (e.g. '30 N') (a finite number followed by a unit), found '.inf'"));
}

TEST(BadInputActee, NanMass) {
  const std::string e = actee_error(replace_once(kWalnut, "mass: 9 g", "mass: nan g"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:4:7:"));
  EXPECT_THAT(e, HasSubstr("expected a mass (e.g. '120 g') (a finite number followed by a unit), found 'nan g'"));
}

TEST(BadInputActee, OverflowingStiffness) {
  const std::string e = actee_error(replace_once(kWalnut, "stiffness: 250 N/mm", "stiffness: 1e999 N/mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:7:12:"));
  EXPECT_THAT(e, HasSubstr("(a finite number followed by a unit), found '1e999 N/mm'"));
}

TEST(BadInputAgent, InfiniteMaxForce) {
  const std::string e = agent_error(replace_once(kHand, "max_force: 400 N", "max_force: inf N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:4:12:"));
  EXPECT_THAT(e, HasSubstr("expected a force (e.g. '30 N') (a finite number followed by a unit), found 'inf N'"));
}

// ---------------------------------------------------------------- units

TEST(BadInputObject, BareNumberWhereLengthExpected) {
  const std::string e = object_error(replace_once(kNutcracker, "position: 25 mm", "position: 25"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:19:13:"));
  EXPECT_THAT(e, HasSubstr("expected a length (e.g. '18 mm'), found '25', a number without a unit"));
}

TEST(BadInputObject, ForceWhereAngleExpected) {
  const std::string e = object_error(replace_once(kNutcracker, "theta_max: 60 deg", "theta_max: 30 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:15:14:"));
  EXPECT_THAT(e, HasSubstr("expected an angle (e.g. '30 deg'), found '30 N', a force (e.g. '30 N')"));
}

TEST(BadInputObject, UnknownUnit) {
  const std::string e = object_error(replace_once(kNutcracker, "position: 25 mm", "position: 30 furlongs"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:19:13:"));
  EXPECT_THAT(e, HasSubstr("expected a length (e.g. '18 mm') (unknown unit 'furlongs'), found '30 furlongs'"));
}

TEST(BadInputObject, StiffnessGivenAsTorque) {
  const std::string e = object_error(replace_once(kNutcracker, "constant: 600 N/m", "constant: 600 N*m"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:13:"));
  EXPECT_THAT(e, HasSubstr("expected a stiffness (e.g. '800 N/m'), found '600 N*m', a torque (e.g. '0.02 N*m')"));
}

TEST(BadInputObject, EffectParameterInTheWrongUnit) {
  const std::string e = object_error(replace_once(kNutcracker, "torque: 0.01 N*m", "torque: 0.01 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:33:28:"));
  EXPECT_THAT(e, HasSubstr("expected a torque (e.g. '0.02 N*m'), found '0.01 N', a force (e.g. '30 N')"));
}

TEST(BadInputObject, DampingWithoutPerRadian) {
  const std::string e = object_error(replace_once(kNutcracker, "0.0005 N*m*s/rad", "0.0005 N*m*s"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:34:34:"));
  EXPECT_THAT(e, HasSubstr("expected a rotational damping (e.g. '0.001 N*m*s/rad'), found '0.0005 N*m*s', "
                           "a quantity in m^2*kg/s"));
}

TEST(BadInputObject, ConvexUnitNotALength) {
  const std::string e = object_error(replace_once(
      kNutcracker, "shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n    position: [92.5 mm, 6 mm",
      "shape: {convex: {unit: N, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]}}\n"
      "    position: [92.5 mm, 6 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:30:28:"));
  EXPECT_THAT(e, HasSubstr("expected a length unit such as mm, found 'N'"));
}

TEST(BadInputActee, BareNumberWhereForceExpected) {
  const std::string e = actee_error(replace_once(kWalnut, "limit: 378 N", "limit: 378"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:6:8:"));
  EXPECT_THAT(e, HasSubstr("expected a force (e.g. '30 N'), found '378', a number without a unit"));
}

TEST(BadInputActee, StiffnessGivenAsTorque) {
  const std::string e = actee_error(replace_once(kWalnut, "stiffness: 250 N/mm", "stiffness: 250 N*mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:7:12:"));
  EXPECT_THAT(e, HasSubstr("expected a stiffness (e.g. '800 N/m'), found '250 N*mm', a torque (e.g. '0.02 N*m')"));
}

TEST(BadInputActee, PressureWhereForceExpected) {
  const std::string e = actee_error(replace_once(kWalnut, "limit: 378 N", "limit: 378 kPa"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:6:8:"));
  EXPECT_THAT(e, HasSubstr("expected a force (e.g. '30 N'), found '378 kPa', a quantity in kg/m/s^2"));
}

TEST(BadInputActee, UnknownUnitInRadii) {
  const std::string e = actee_error(replace_once(kWalnut, "14.1 mm, 14.1 mm]", "14.1 mm, 14.1 furlongs]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:45:"));
  EXPECT_THAT(e, HasSubstr("(unknown unit 'furlongs'), found '14.1 furlongs'"));
}

TEST(BadInputAgent, LengthWhereAngleExpected) {
  const std::string e = agent_error(replace_once(kHand, "distal: [-20 deg, 80 deg]", "distal: [-20 mm, 80 mm]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:8:14:"));
  EXPECT_THAT(e, HasSubstr("expected an angle (e.g. '30 deg'), found '-20 mm', a length (e.g. '18 mm')"));
}

TEST(BadInputAgent, ForceGainGivenAsForce) {
  const std::string e = agent_error(replace_once(kHand, "force_gain: 5 N/mm", "force_gain: 5 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:13:"));
  EXPECT_THAT(e, HasSubstr("expected a stiffness (e.g. '800 N/m'), found '5 N', a force (e.g. '30 N')"));
}

// ---------------------------------------------------------------- physical nonsense: objects

TEST(BadInputObject, ZeroSpringConstant) {
  const std::string e = object_error(replace_once(kNutcracker, "constant: 600 N/m", "constant: 0 N/m"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:13:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 N/m'"));
}

TEST(BadInputObject, NegativeSpringConstant) {
  const std::string e = object_error(replace_once(kNutcracker, "constant: 600 N/m", "constant: -600 N/m"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:13:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '-600 N/m'"));
}

TEST(BadInputObject, ZeroMass) {
  const std::string e = object_error(replace_once(kNutcracker, "mass: 190 g", "mass: 0 g"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:7:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 g'"));
}

TEST(BadInputObject, ThetaMaxEqualToThetaMin) {
  const std::string e = object_error(replace_once(kNutcracker, "theta_max: 60 deg", "theta_max: 0 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:15:14:"));
  EXPECT_THAT(e, HasSubstr("expected theta_max greater than theta_min (0 deg), found '0 deg'"));
}

TEST(BadInputObject, ThetaMinAboveThetaMax) {
  const std::string e = object_error(replace_once(kNutcracker, "theta_min: 0 deg", "theta_min: 70 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:15:14:"));
  EXPECT_THAT(e, HasSubstr("expected theta_max greater than theta_min (70 deg), found '60 deg'"));
}

TEST(BadInputObject, NegativeThetaMin) {
  const std::string e = object_error(replace_once(kNutcracker, "theta_min: 0 deg", "theta_min: -5 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:14:14:"));
  EXPECT_THAT(e, HasSubstr("expected an opening angle of 0 deg or more, found '-5 deg'"));
}

TEST(BadInputObject, ThetaMaxOfHalfATurn) {
  const std::string e = object_error(replace_once(kNutcracker, "theta_max: 60 deg", "theta_max: 180 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:15:14:"));
  EXPECT_THAT(e, HasSubstr("expected an opening angle below 180 deg, found '180 deg'"));
}

TEST(BadInputObject, RestAboveThetaMax) {
  const std::string e = object_error(replace_once(kNutcracker, "rest: 60 deg", "rest: 70 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:16:9:"));
  EXPECT_THAT(e, HasSubstr("expected a rest angle between theta_min and theta_max, found '70 deg'"));
}

TEST(BadInputObject, RestBelowThetaMin) {
  const std::string e = object_error(replace_once(kNutcracker, "rest: 60 deg", "rest: -1 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:16:9:"));
  EXPECT_THAT(e, HasSubstr("expected a rest angle between theta_min and theta_max, found '-1 deg'"));
}

TEST(BadInputObject, ArmToNotAboveFrom) {
  const std::string e = object_error(replace_once(kNutcracker, "{from: 0 mm, to: 185 mm}", "{from: 0 mm, to: -185 mm}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:13:25:"));
  EXPECT_THAT(e, HasSubstr("expected 'to' greater than 'from' (0 mm), found '-185 mm'"));
}

TEST(BadInputObject, SpringBeyondTheArm) {
  const std::string e = object_error(replace_once(kNutcracker, "position: 25 mm", "position: 200 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:19:13:"));
  EXPECT_THAT(e, HasSubstr("expected a distance on the arm, between 0 mm and 185 mm, found '200 mm'"));
}

TEST(BadInputObject, SpringAtTheFulcrum) {
  const std::string e = object_error(replace_once(kNutcracker, "position: 25 mm", "position: 0 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:19:13:"));
  EXPECT_THAT(e, HasSubstr("expected a spring away from the fulcrum, found '0 mm'"));
}

TEST(BadInputObject, EmphasisBeyondTheArm) {
  const std::string e = object_error(
      replace_once(kNutcracker, "emphasis: {from: 110 mm, to: 180 mm}", "emphasis: {from: 110 mm, to: 190 mm}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:21:30:"));
  EXPECT_THAT(e, HasSubstr("expected a distance on the arm, between 0 mm and 185 mm, found '190 mm'"));
}

TEST(BadInputObject, ApplicationBeforeTheArm) {
  const std::string e = object_error(
      replace_once(kNutcracker, "application: {from: 20 mm, to: 75 mm}", "application: {from: -5 mm, to: 75 mm}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:22:21:"));
  EXPECT_THAT(e, HasSubstr("expected a distance on the arm, between 0 mm and 185 mm, found '-5 mm'"));
}

TEST(BadInputObject, EmphasisToNotAboveFrom) {
  const std::string e = object_error(
      replace_once(kNutcracker, "emphasis: {from: 110 mm, to: 180 mm}", "emphasis: {from: 110 mm, to: 110 mm}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:21:30:"));
  EXPECT_THAT(e, HasSubstr("expected 'to' greater than 'from' (110 mm), found '110 mm'"));
}

TEST(BadInputObject, PatternThatTheRegionsDoNotMake) {
  const std::string e = object_error(replace_once(kNutcracker, "pattern: type2", "pattern: type3"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:12:12:"));
  EXPECT_THAT(e, HasSubstr("expected the pattern that the emphasis and application regions make, type2, "
                           "found 'type3'"));
}

TEST(BadInputObject, UnknownPatternSaysDidYouMean) {
  const std::string e = object_error(replace_once(kNutcracker, "pattern: type2", "pattern: typ2"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:12:12:"));
  EXPECT_THAT(e, HasSubstr("expected one of type1-power, type1-distance, type1-balance, type2, type3, "
                           "found 'typ2' (did you mean 'type2'?)"));
}

TEST(BadInputObject, OverlappingRegions) {
  const std::string e = object_error(
      replace_once(kNutcracker, "application: {from: 20 mm, to: 75 mm}", "application: {from: 20 mm, to: 120 mm}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:22:14:"));
  EXPECT_THAT(e, HasSubstr("expected emphasis and application regions that do not overlap, "
                           "found regions that make no lever pattern"));
}

TEST(BadInputObject, BothRestLengthAndPreload) {
  const std::string e =
      object_error(replace_once(kNutcracker, "  preload: 1.5 N\n", "  preload: 1.5 N\n  rest_length: 30 mm\n"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:18:3:"));
  EXPECT_THAT(e, HasSubstr("expected exactly one of rest_length and preload, found both"));
}

TEST(BadInputObject, NegativePreload) {
  const std::string e = object_error(replace_once(kNutcracker, "preload: 1.5 N", "preload: -1.5 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:20:12:"));
  EXPECT_THAT(e, HasSubstr("expected a value of zero or more, found '-1.5 N'"));
}

TEST(BadInputObject, CompressedSpringAtRestBelowThetaMax) {
  // 1.5 N / 600 N/m = 2.5 mm of compression, but the tool rests at 30 deg,
  // not against theta_max: the spring would move it.
  const std::string e = object_error(replace_once(kNutcracker, "rest: 60 deg", "rest: 30 deg"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:20:12:"));
  EXPECT_THAT(e, HasSubstr("expected a spring free at the rest angle, or the rest angle at theta_max, "
                           "found a spring compressed by 2.5 mm at a rest angle below theta_max"));
}

TEST(BadInputObject, StretchedSpringAtRestAboveThetaMin) {
  // The gap at rest is 25 mm * 60 deg = 26.18 mm; a 20 mm spring is stretched.
  const std::string e = object_error(replace_once(kNutcracker, "preload: 1.5 N", "rest_length: 20 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:20:16:"));
  EXPECT_THAT(e, HasSubstr("expected a spring free at the rest angle, or the rest angle at theta_min, "
                           "found a spring stretched by 6.18 mm at a rest angle above theta_min"));
}

TEST(BadInputObject, ZeroSizeBox) {
  const std::string e = object_error(replace_once(
      kNutcracker, "{size: [185 mm, 12 mm, 16 mm]}}\n    position: [92.5 mm, -6 mm",
      "{size: [185 mm, 0 mm, 16 mm]}}\n    position: [92.5 mm, -6 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:26:34:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 mm'"));
}

TEST(BadInputObject, NoMovingArm) {
  const std::string e = object_error(replace_once(kNutcracker, "arm: moving", "arm: fixed"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:24:3:"));
  EXPECT_THAT(e, HasSubstr("expected parts on both arms, fixed and moving, found a sequence of 2"));
}

TEST(BadInputObject, NoParts) {
  const std::string e = object_error(replace_once(
      kNutcracker, kNutcracker.substr(kNutcracker.find("parts:"), kNutcracker.find("effects:") - kNutcracker.find("parts:")),
      "parts: []\n"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:23:8:"));
  EXPECT_THAT(e, HasSubstr("expected a sequence of parts, found a sequence of 0"));
}

TEST(BadInputObject, DuplicatePartNames) {
  const std::string e = object_error(replace_once(kNutcracker, "name: moving_arm", "name: fixed_arm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:28:5:"));
  EXPECT_THAT(e, HasSubstr("expected a part name used once, found 'fixed_arm' again"));
}

TEST(BadInputObject, UnknownArmSaysDidYouMean) {
  const std::string e = object_error(replace_once(kNutcracker, "arm: moving", "arm: movng"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:29:10:"));
  EXPECT_THAT(e, HasSubstr("expected one of fixed, moving, found 'movng' (did you mean 'moving'?)"));
}

TEST(BadInputObject, UnknownEffectSaysDidYouMean) {
  const std::string e = object_error(replace_once(kNutcracker, "pivot_friction:", "pivot_fricton:"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:33:3:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of the effects (pivot_friction, viscous_damping, "
                           "spring_preload, progressive_spring, arm_inertia, gravity), found 'pivot_fricton' "
                           "(did you mean 'pivot_friction'?)"));
}

TEST(BadInputObject, NegativeEffectParameter) {
  const std::string e = object_error(replace_once(kNutcracker, "torque: 0.01 N*m", "torque: -0.01 N*m"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:33:28:"));
  EXPECT_THAT(e, HasSubstr("expected a value from 0 N*m to 100 N*m (friction torque, N*m), found '-0.01 N*m'"));
}

TEST(BadInputObject, ZeroArmInertia) {
  const std::string e = object_error(kNutcracker + "  arm_inertia: {inertia: 0 kg*m^2}\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:35:26:"));
  EXPECT_THAT(e, HasSubstr("expected a value above 0 kg*m^2 to 10 kg*m^2 (moment of inertia about the pivot, "
                           "kg*m^2), found '0 kg*m^2'"));
}

TEST(BadInputObject, EffectWithoutValue) {
  const std::string e = object_error(kNutcracker + "  arm_inertia:\n");
  EXPECT_THAT(e, HasSubstr("bad.yaml:35:3:"));
  EXPECT_THAT(e, HasSubstr("expected a value for 'arm_inertia', found nothing"));
}

TEST(BadInputObject, UnknownShapeKindSaysDidYouMean) {
  const std::string e = object_error(replace_once(
      kNutcracker, "shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n    position: [92.5 mm, -6 mm",
      "shape: {sphre: {radius: 6 mm}}\n    position: [92.5 mm, -6 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:26:13:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of a shape (sphere, box, capsule, cylinder, ellipsoid, "
                           "convex), found 'sphre' (did you mean 'sphere'?)"));
}

TEST(BadInputObject, ShapeWithTwoKinds) {
  const std::string e = object_error(replace_once(
      kNutcracker, "shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n    position: [92.5 mm, -6 mm",
      "shape: {sphere: {radius: 6 mm}, box: {size: [1 mm, 1 mm, 1 mm]}}\n    position: [92.5 mm, -6 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:26:12:"));
  EXPECT_THAT(e, HasSubstr("expected exactly one of sphere, box, capsule, cylinder, ellipsoid, convex, "
                           "found 2 keys"));
}

// A convex hull needs four points that span a volume. The loader cannot see
// that; compiling the shape does, and still names the shape's line.
TEST(BadInputObject, ConvexWithThreePoints) {
  const std::string e = compile_error(replace_once(
      kNutcracker, "shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n    position: [92.5 mm, 6 mm",
      "shape: {convex: {unit: mm, vertices: [[0, 0, 0], [10, 0, 0], [0, 10, 0]]}}\n"
      "    position: [92.5 mm, 6 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:30:12:"));
  EXPECT_THAT(e, HasSubstr("expected at least 4 vertices that span a volume, found 3 vertices"));
}

TEST(BadInputObject, ConvexWithCoplanarPoints) {
  const std::string e = compile_error(replace_once(
      kNutcracker, "shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n    position: [92.5 mm, 6 mm",
      "shape: {convex: {unit: mm, vertices: [[0, 0, 0], [10, 0, 0], [0, 10, 0], [10, 10, 0]]}}\n"
      "    position: [92.5 mm, 6 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:30:12:"));
  EXPECT_THAT(e, HasSubstr("expected at least 4 vertices that span a volume, found coplanar vertices"));
}

TEST(BadInputObject, ConvexVertexNotAPoint) {
  const std::string e = object_error(replace_once(
      kNutcracker, "shape: {box: {size: [185 mm, 12 mm, 16 mm]}}\n    position: [92.5 mm, 6 mm",
      "shape: {convex: {unit: mm, vertices: [[0, 0, 0], [10, 0]]}}\n"
      "    position: [92.5 mm, 6 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:30:54:"));
  EXPECT_THAT(e, HasSubstr("expected a sequence of three numbers, found a sequence of 2"));
}

// ---------------------------------------------------------------- physical nonsense: actees

TEST(BadInputActee, ZeroLimit) {
  const std::string e = actee_error(replace_once(kWalnut, "limit: 378 N", "limit: 0 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:6:8:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 N'"));
}

TEST(BadInputActee, NegativeLimit) {
  const std::string e = actee_error(replace_once(kWalnut, "limit: 378 N", "limit: -378 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:6:8:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '-378 N'"));
}

TEST(BadInputActee, NegativeStiffness) {
  const std::string e = actee_error(replace_once(kWalnut, "stiffness: 250 N/mm", "stiffness: -250 N/mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:7:12:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '-250 N/mm'"));
}

TEST(BadInputActee, ZeroDirection) {
  const std::string e = actee_error(replace_once(kWalnut, "[0, 1, 0]", "[0, 0, 0]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:5:18:"));
  EXPECT_THAT(e, HasSubstr("expected a direction, not all zeros, found a sequence of 3"));
}

TEST(BadInputActee, ZeroRadius) {
  const std::string e = actee_error(replace_once(kWalnut, "[18 mm, 14.1 mm, 14.1 mm]", "[18 mm, 0 mm, 14.1 mm]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:36:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 mm'"));
}

TEST(BadInputActee, ZeroSizeBox) {
  const std::string e = actee_error(replace_once(
      kWalnut, "{ellipsoid: {radii: [18 mm, 14.1 mm, 14.1 mm]}}", "{box: {size: [28 mm, 28 mm, 0 mm]}}"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:36:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 mm'"));
}

TEST(BadInputActee, UnknownShapeKindSaysDidYouMean) {
  const std::string e = actee_error(replace_once(kWalnut, "{ellipsoid:", "{elipsoid:"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:9:"));
  EXPECT_THAT(e, HasSubstr("found 'elipsoid' (did you mean 'ellipsoid'?)"));
}

TEST(BadInputActee, ConvexWithTwoPoints) {
  const TempFile file("convex2.yaml",
                      replace_once(kWalnut, "{ellipsoid: {radii: [18 mm, 14.1 mm, 14.1 mm]}}",
                                   "{convex: {unit: mm, vertices: [[0, 0, 0], [1, 1, 1]]}}"));
  const std::string e = validate_error(file.path());
  EXPECT_THAT(e, HasSubstr(file.path() + ":3:8:"));
  EXPECT_THAT(e, HasSubstr("expected at least 4 vertices that span a volume, found 2 vertices"));
}

TEST(BadInputActee, ConvexWithCoplanarPoints) {
  const TempFile file("coplanar.yaml",
                      replace_once(kWalnut, "shape: {ellipsoid: {radii: [18 mm, 14.1 mm, 14.1 mm]}}",
                                   "shape:\n  convex:\n    unit: cm\n"
                                   "    vertices: [[0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1], [0.5, 0.5, 1]]"));
  const std::string e = validate_error(file.path());
  EXPECT_THAT(e, HasSubstr(file.path() + ":4:3:"));
  EXPECT_THAT(e, HasSubstr("expected at least 4 vertices that span a volume, found coplanar vertices"));
}

// ---------------------------------------------------------------- physical nonsense: agents

TEST(BadInputAgent, JointMaxBelowMin) {
  const std::string e = agent_error(replace_once(kHand, "    distal: [0 deg, 90 deg]\n    proximal: [0 deg, 100 deg]\n    metacarpal: [-45 deg, 90 deg]\n  middle",
                                                 "    distal: [90 deg, 0 deg]\n    proximal: [0 deg, 100 deg]\n    metacarpal: [-45 deg, 90 deg]\n  middle"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:13:22:"));
  EXPECT_THAT(e, HasSubstr("expected a maximum above the minimum, found '0 deg'"));
}

TEST(BadInputAgent, JointMaxEqualToMin) {
  const std::string e = agent_error(replace_once(kHand, "metacarpal: [0 deg, 70 deg]", "metacarpal: [70 deg, 70 deg]"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:10:26:"));
  EXPECT_THAT(e, HasSubstr("expected a maximum above the minimum, found '70 deg'"));
}

TEST(BadInputAgent, NegativeForceGain) {
  const std::string e = agent_error(replace_once(kHand, "force_gain: 5 N/mm", "force_gain: -5 N/mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:3:13:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '-5 N/mm'"));
}

TEST(BadInputAgent, ZeroMaxForce) {
  const std::string e = agent_error(replace_once(kHand, "max_force: 400 N", "max_force: 0 N"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:4:12:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 N'"));
}

TEST(BadInputAgent, ZeroTipRadius) {
  const std::string e = agent_error(replace_once(kHand, "tip_radius: 8 mm", "tip_radius: 0 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:27:17:"));
  EXPECT_THAT(e, HasSubstr("expected a value greater than zero, found '0 mm'"));
}

// ---------------------------------------------------------------- the file itself

TEST(BadInputFile, UnclosedFlowSequence) {
  const std::string e = object_error(
      replace_once(kNutcracker, "centre_of_gravity: [80 mm, 0 mm, 0 mm]", "centre_of_gravity: [80 mm, 0 mm, 0 mm"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:5:16:"));
  EXPECT_THAT(e, HasSubstr("expected valid YAML, found a syntax error: end of sequence flow not found"));
}

TEST(BadInputFile, BadIndentation) {
  const std::string e = actee_error(replace_once(kWalnut, "mass: 9 g", "  mass: 9 g"));
  EXPECT_THAT(e, HasSubstr("bad.yaml:4:3:"));
  EXPECT_THAT(e, HasSubstr("expected valid YAML, found a syntax error: end of map not found"));
}

TEST(BadInputFile, EmptyText) {
  const std::string e = object_error("");
  EXPECT_THAT(e, StartsWith("bad.yaml:1:1:"));
  EXPECT_THAT(e, HasSubstr("expected a YAML mapping, found an empty file"));
}

TEST(BadInputFile, OnlyComments) {
  const std::string e = actee_error("# nothing here yet\n\n");
  EXPECT_THAT(e, StartsWith("bad.yaml:1:1:"));
  EXPECT_THAT(e, HasSubstr("expected a YAML mapping, found an empty file"));
}

TEST(BadInputFile, EmptyFileOnDisk) {
  const TempFile file("empty.yaml", "");
  const std::string e = validate_error(file.path());
  EXPECT_EQ(e, file.path() + ":1:1: expected a YAML mapping, found an empty file");
}

TEST(BadInputFile, MissingFile) {
  const std::string path = "/nonexistent/afford/nothing.yaml";
  const std::string e = validate_error(path);
  EXPECT_EQ(e, path + ": expected a readable file, found none");
}

TEST(BadInputFile, DirectoryIsNotAnEmptyFile) {
  const std::string path = std::filesystem::temp_directory_path().string();
  const std::string e = validate_error(path);
  EXPECT_EQ(e, path + ": expected a readable file, found a directory");
}

TEST(BadInputFile, UnknownKindSaysDidYouMean) {
  const TempFile file("objcet.yaml", replace_once(kNutcracker, "object: nutcracker", "objcet: nutcracker"));
  const std::string e = validate_error(file.path());
  std::string kinds;  // object, actee, agent and the kinds added since
  for (const std::string& k : file_kinds()) kinds += (kinds.empty() ? "" : ", ") + k;
  EXPECT_THAT(kinds, StartsWith("object, actee, agent"));
  EXPECT_EQ(e, file.path() + ":1:1: expected a file whose first key names its kind (" + kinds +
                   "), found 'objcet' (did you mean 'object'?)");
}

TEST(BadInputFile, FirstKeyNotAKind) {
  // The kind must come first: a file starting with its description is not read.
  const TempFile file("description_first.yaml", "description: a walnut\n" + kWalnut);
  const std::string e = validate_error(file.path());
  EXPECT_THAT(e, HasSubstr(file.path() + ":1:1:"));
  EXPECT_THAT(e, HasSubstr("found 'description'"));
  EXPECT_THAT(e, ::testing::Not(HasSubstr("did you mean")));
}

TEST(BadInputFile, SequenceAtTheTop) {
  const TempFile file("sequence.yaml", "- object\n- nutcracker\n");
  const std::string e = validate_error(file.path());
  EXPECT_EQ(e, file.path() +
                   ":1:1: expected a mapping whose first key names the kind of file, found a sequence of 2");
}

TEST(BadInputFile, ReadObjectOnAnActee) {
  const std::string e = object_error(kWalnut);
  EXPECT_THAT(e, HasSubstr("bad.yaml:1:1:"));
  EXPECT_THAT(e, HasSubstr("expected one of the keys of an object file (object, "));
  EXPECT_THAT(e, HasSubstr("found 'actee'"));
}

TEST(BadInputFile, ValidateReportsKindAndName) {
  const TempFile object("object.yaml", kNutcracker);
  const TempFile actee("actee.yaml", kWalnut);
  const TempFile agent("agent.yaml", kHand);
  EXPECT_EQ(validate_file(object.path()), "object nutcracker");
  EXPECT_EQ(validate_file(actee.path()), "actee walnut");
  EXPECT_EQ(validate_file(agent.path()), "agent hand");
}

// ---------------------------------------------------------------- the shipped files

// Every file shipped under `dir` validates and is named after its file.
void expect_shipped_files_valid(const std::string& dir, const std::string& kind) {
  const std::filesystem::path root = std::filesystem::path(AFFORD_SOURCE_DIR) / dir;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root)) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    try {
      EXPECT_EQ(validate_file(entry.path().string()), kind + " " + entry.path().stem().string());
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GT(count, 0) << "no .yaml files in " << root;
}

TEST(BadInputShipped, ObjectsValidate) { expect_shipped_files_valid("objects", "object"); }
TEST(BadInputShipped, ActeesValidate) { expect_shipped_files_valid("actees", "actee"); }
TEST(BadInputShipped, AgentsValidate) { expect_shipped_files_valid("agents", "agent"); }

}  // namespace
}  // namespace afford
