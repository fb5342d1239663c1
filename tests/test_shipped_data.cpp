// The shipped tools, actees and hand: they load, and their figures agree
// with the real measurements in shared/data.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "derive.h"
#include "load.h"
#include "model.h"
#include "test_util.h"

namespace afford {
namespace {
using test::kSource;


// One compression test: load (N) against plate displacement (m).
struct Curve {
  std::vector<double> force, displacement;
};

Curve read_macadamia(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 10 && std::getline(in, line); ++i) {}  // nine header lines and the column names
  Curve c;
  int index = 0;
  double load_kn = 0, defor_mm = 0, stroke = 0, time = 0;
  while (in >> index >> load_kn >> defor_mm >> stroke >> time) {
    c.force.push_back(load_kn * 1e3);
    c.displacement.push_back(defor_mm * 1e-3);
  }
  return c;
}

// Rupture: the peak before the first drop of more than 10 %, once loaded
// past the toe (sensor noise at a few newtons is not a rupture).
size_t rupture_index(const Curve& c) {
  size_t peak = 0;
  for (size_t i = 0; i < c.force.size(); ++i) {
    if (c.force[i] > c.force[peak]) peak = i;
    if (c.force[peak] > 500 && c.force[i] < 0.9 * c.force[peak]) break;
  }
  return peak;
}

TEST(ShippedData, EveryToolTakesEveryActeeThatFitsAndRejectsTheOthers) {
  const AgentSpec hand = load_agent(kSource + "/agents/hand.yaml");
  int placed = 0, rejected = 0;
  for (const char* tool : {"nutcracker", "tongs", "pliers"}) {
    const ObjectSpec o = load_object(kSource + "/objects/" + tool + ".yaml");
    EXPECT_EQ(o.name, tool);
    for (const auto& entry : std::filesystem::directory_iterator(kSource + "/actees")) {
      if (entry.path().extension() != ".yaml") continue;
      const ActeeSpec a = load_actee(entry.path().string());
      ModelOptions anywhere;
      anywhere.actee.in_jaws = false;
      const ActeeFit fit = fit_actee(compile(o, &a, &hand, anywhere));
      ModelOptions options;
      options.actee.distance = fit.fits ? fit.to : o.application.middle();
      options.actee.loc = SourceLoc{"session.yaml", 4, 9};
      if (fit.fits) {
        EXPECT_NO_THROW(compile(o, &a, &hand, options)) << tool << " + " << a.name;
        ++placed;
      } else {
        try {
          compile(o, &a, &hand, options);
          ADD_FAILURE() << tool << " + " << a.name << " should not fit";
        } catch (const DataError& e) {
          EXPECT_NE(std::string(e.what()).find("session.yaml:4:9: expected an actee that fits between the jaws"),
                    std::string::npos) << e.what();
        }
        ++rejected;
      }
    }
  }
  EXPECT_GT(placed, 10);
  EXPECT_GE(rejected, 3);  // the coconut, at least, fits none
}

TEST(ShippedData, MacadamiaAgreesWithTheRealCompressionCurves) {
  const std::string dir = std::string(AFFORD_SHARED_DIR) + "/data/real/macadamia";
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no shared data at " << dir;
  const ActeeSpec mac = load_actee(kSource + "/actees/macadamia.yaml");
  // The actee file was fitted on mac01, mac03 and mac05; check on the others.
  for (const char* held_out : {"mac02.txt", "mac04.txt"}) {
    const Curve c = read_macadamia(dir + "/" + held_out);
    ASSERT_GT(c.force.size(), 100u) << held_out;
    const size_t r = rupture_index(c);
    const double secant = c.force[r] / c.displacement[r];
    // Within a factor 1.6 of the held-out nut's secant stiffness, and the
    // limit within the spread of the five measured ruptures (1.6-3.4 kN).
    EXPECT_GT(mac.stiffness, secant / 1.6) << held_out;
    EXPECT_LT(mac.stiffness, secant * 1.6) << held_out;
  }
  EXPECT_GT(mac.limit, 1600);
  EXPECT_LT(mac.limit, 3400);
  EXPECT_TRUE(mac.breaks);
}

TEST(ShippedData, TheLargeActeeFitsNoShippedTool) {
  const ActeeSpec coconut = load_actee(kSource + "/actees/coconut.yaml");
  for (const char* tool : {"nutcracker", "tongs", "pliers"}) {
    const ObjectSpec o = load_object(kSource + "/objects/" + tool + ".yaml");
    ModelOptions options;
    options.actee.in_jaws = false;
    const Model m = compile(o, &coconut, nullptr, options);
    EXPECT_FALSE(fit_actee(m).fits) << tool;
  }
}

TEST(ShippedData, TheNutcrackerCracksAWalnutWithinAHandsForce) {
  const ObjectSpec o = load_object(kSource + "/objects/nutcracker.yaml");
  const ActeeSpec walnut = load_actee(kSource + "/actees/walnut.yaml");
  const AgentSpec hand = load_agent(kSource + "/agents/hand.yaml");
  ModelOptions options;
  options.actee.in_jaws = false;
  const Model m = compile(o, &walnut, &hand, options);
  const ActeeFit fit = fit_actee(m);
  ASSERT_TRUE(fit.fits);
  EXPECT_LT(fit.effort_to_limit, hand.max_force);
  // and the tongs (type 3) cannot.
  const ObjectSpec tongs = load_object(kSource + "/objects/tongs.yaml");
  const ActeeFit tong_fit = fit_actee(compile(tongs, &walnut, &hand, options));
  ASSERT_TRUE(tong_fit.fits);
  EXPECT_GT(tong_fit.effort_to_limit, hand.max_force);
}

}  // namespace
}  // namespace afford
