// afford explore: the generated sessions push with the effort asked for,
// thresholds agree with the lever worked out by hand, results do not depend
// on the threads, shards merge into the whole, bad grids and damaged shard
// files are clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <fstream>

#include "explore_json.h"
#include "reports.h"
#include "files.h"
#include "test_util.h"

namespace afford {
namespace {
using test::kSource;

using test::thrown;
#define EXPECT_THROW_MSG(call, text) EXPECT_NE(thrown([&] { (void)(call); }).find(text), std::string::npos) << thrown([&] { (void)(call); })


ExploreFiles shipped(const std::string& object, std::vector<std::string> actees) {
  ExploreFiles f;
  f.object = kSource + "/objects/" + object;
  f.agent = kSource + "/agents/hand.yaml";
  f.rules = kSource + "/rules/functions.yaml";
  f.grasps = kSource + "/rules/grasps.yaml";
  for (const std::string& a : actees) f.actees.push_back(kSource + "/actees/" + a);
  return f;
}

GridOptions small_grid() {
  GridOptions g;
  g.placements = 2;
  g.thumbs = 2;
  g.efforts = 4;
  g.grasps = {"medium_wrap", "tip_pinch"};
  g.tolerance = 0.5;
  return g;
}


TEST(Explore, TheHandPushesWithTheEffortAskedFor) {
  GridOptions grid = small_grid();
  grid.grasps = {"medium_wrap"};
  const Explorer e = make_explorer(shipped("nutcracker.yaml", {"walnut.yaml"}), grid);
  // Below the walnut's limit: the hand's push while it holds is the 60 N asked for
  // (the impedance's squeeze is worked out from the forced balance).
  for (int thumb = 0; thumb < 2; ++thumb) {
    const PointResult r = run_point(e, {0, 0, thumb, 0, 0}, 60.0);
    EXPECT_NEAR(r.peak_effort, 60.0, 0.6) << "thumb " << thumb;
    EXPECT_LT(r.broke_at, 0);
  }
}

TEST(Explore, TheCrackingThresholdIsTheLeverWorkedOutByHand) {
  GridOptions grid = small_grid();
  grid.grasps = {"medium_wrap"};
  grid.efforts = 5;  // 0, 100, 200, 300, 400 N
  const Explorer e = make_explorer(shipped("nutcracker.yaml", {"walnut.yaml"}), grid);
  const ExploreResult r = explore(e, Shard{}, 2);
  // The walnut (an ellipsoid of semi-axes 18, 14.1, 14.1 mm) at 55 mm on the
  // fixed jaw, the thumb at 180 mm. The moving jaw's face (through the hinge
  // at theta, normal (-sin, cos)) touches it where r sin - b cos =
  // sqrt(a^2 sin^2 + b^2 cos^2): theta_c = 0.52126 rad, and pushes there
  // with the lever arm D = r cos + b sin - (a^2 - b^2) sin cos / that root
  // = 51.151 mm (test_util.h), not 55. The shell's 378 N needs
  // 378 D / 180 = 107.41 N at the thumb; the spring (about 0.09 N at the
  // thumb) and the pivot's friction (0.01 N*m / 0.18 m = 0.06 N) add a little.
  const test::JawTouch touch = test::ellipsoid_under_jaw(0.018, 0.0141, 0.055, 30 * std::numbers::pi / 180);
  const double lever = touch.lever;  // m
  EXPECT_NEAR(touch.angle, 0.52126, 1e-5);
  EXPECT_NEAR(lever, 0.051151, 1e-6);
  const double needed = 378 * lever / 0.180;  // N
  const GridInfo& g = e.grid;
  ASSERT_DOUBLE_EQ(g.actees[0].placements[0], 0.055);
  ASSERT_DOUBLE_EQ(g.thumbs[1], 0.180);
  const SeriesResult* s = nullptr;
  for (const SeriesResult& x : r.series) {
    if (x.key.placement == 0 && x.key.thumb == 1) s = &x;
  }
  ASSERT_NE(s, nullptr);
  const int crash = test::index_of(g.functions, "crash");
  const Threshold* to_crash = nullptr;
  for (const Threshold& t : s->thresholds) {
    if (t.to == crash) to_crash = &t;
  }
  ASSERT_NE(to_crash, nullptr);
  EXPECT_GE(to_crash->effort, needed);
  EXPECT_LE(to_crash->effort, needed + 0.09 + 0.06 + g.tolerance + 0.3);
  EXPECT_LE(to_crash->effort - to_crash->below, g.tolerance);
  EXPECT_GT(to_crash->at.broke_at, 0);
  EXPECT_NEAR(s->mechanical_advantage, 0.180 / lever, 1e-9);
  EXPECT_NEAR(s->lever_effort_at_limit, needed + 0.09, 0.05);
}

TEST(Explore, AWeakGraspNeverCracksAndTheSummarySaysSo) {
  const Explorer e = make_explorer(shipped("nutcracker.yaml", {"walnut.yaml", "egg.yaml"}), small_grid());
  const ExploreResult r = explore(e, Shard{}, 2);
  const std::string summary = summary_text(e.grid, r);
  // The tip pinch pushes at most 65 N (rules/grasps.yaml): never the 115 N the shell needs.
  EXPECT_NE(summary.find("ends in crash: from "), std::string::npos) << summary;
  EXPECT_NE(summary.find("never with tip_pinch"), std::string::npos) << summary;
  EXPECT_NE(summary.find("egg: does not fit the nutcracker: the jaws fully open"), std::string::npos) << summary;
  EXPECT_TRUE(e.models[1].empty());
}

TEST(Explore, ResultsDoNotDependOnTheThreads) {
  GridOptions grid = small_grid();
  grid.thumbs = 1;
  const Explorer e = make_explorer(shipped("nutcracker.yaml", {"walnut.yaml", "peanut.yaml"}), grid);
  const std::string one = explore_json(e.grid, explore(e, Shard{}, 1));
  EXPECT_EQ(explore_json(e.grid, explore(e, Shard{}, 2)), one);
  EXPECT_EQ(explore_json(e.grid, explore(e, Shard{}, 5)), one);
}

TEST(Explore, ShardsMergeIntoTheWholeGrid) {
  GridOptions grid = small_grid();
  grid.thumbs = 1;
  const Explorer e = make_explorer(shipped("nutcracker.yaml", {"walnut.yaml", "peanut.yaml"}), grid);
  const ExploreResult whole = explore(e, Shard{}, 2);
  const auto dir = std::filesystem::temp_directory_path() / "afford_explore_shards";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<ExploreResult> parts;
  for (int k = 1; k <= 3; ++k) {
    const std::string file = (dir / ("shard" + std::to_string(k) + ".json")).string();
    write_file_checked(file, explore_json(e.grid, explore(e, Shard{k, 3}, 1)));
    GridInfo g;
    ExploreResult part;
    read_explore_json(file, &g, &part);
    EXPECT_TRUE(g == e.grid);
    EXPECT_EQ(part.shard.part, k);
    parts.push_back(std::move(part));
  }
  const ExploreResult merged = merge(e.grid, parts);
  EXPECT_EQ(explore_json(e.grid, merged), explore_json(e.grid, whole));
  EXPECT_EQ(points_csv(e.grid, merged), points_csv(e.grid, whole));
  EXPECT_EQ(summary_text(e.grid, merged), summary_text(e.grid, whole));

  // A part missing, or given twice, is an error that says so.
  std::vector<ExploreResult> missing = {parts[0], parts[2]};
  EXPECT_THROW_MSG(merge(e.grid, missing), "is in no shard: a part is missing");
  std::vector<ExploreResult> twice = {parts[0], parts[1], parts[2], parts[1]};
  EXPECT_THROW_MSG(merge(e.grid, twice), "is in two shards");
  std::filesystem::remove_all(dir);
}

TEST(Explore, ADamagedShardFileIsAnErrorWithItsPlace) {
  const auto file = std::filesystem::temp_directory_path() / "afford_explore_bad.json";
  GridInfo g;
  ExploreResult r;
  write_file_checked(file.string(), "{\n  \"object\": \"tongs\",\n  \"functions\": [,]\n}\n");
  EXPECT_THROW_MSG(read_explore_json(file.string(), &g, &r), "afford_explore_bad.json:3:17: not JSON");
  write_file_checked(file.string(), "{\"object\": \"tongs\", \"functions\": [\"pinch\"], \"tolerance_N\": 0.5}\n");
  EXPECT_THROW_MSG(read_explore_json(file.string(), &g, &r), "expected the key 'thumbs_m'");
  // An index outside the grid it describes.
  write_file_checked(file.string(),
                     "{\"object\": \"t\", \"functions\": [], \"tolerance_N\": 0.5, \"thumbs_m\": [0.1], \"efforts_N\": [1],"
                     " \"grasps\": [], \"actees\": [], \"series\": [{\"index\": 0, \"actee\": 3}]}\n");
  EXPECT_THROW_MSG(read_explore_json(file.string(), &g, &r), "a grid without thumbs, efforts or grasps");
  write_file_checked(file.string(),
                     "{\"object\": \"t\", \"functions\": [], \"tolerance_N\": 0.5, \"thumbs_m\": [0.1], \"efforts_N\": [1],"
                     " \"grasps\": [{\"name\": \"g\", \"limit_N\": 1}], \"actees\": [],"
                     " \"series\": [{\"index\": 0, \"actee\": 3}]}\n");
  EXPECT_THROW_MSG(read_explore_json(file.string(), &g, &r), "'actee' is not an index below 0");
  // A number beyond a double (found by fuzz_explore_json): an error, not a crash.
  write_file_checked(file.string(), "{\"object\": \"t\", \"tolerance_N\": 41e30800}\n");
  EXPECT_THROW_MSG(read_explore_json(file.string(), &g, &r), "afford_explore_bad.json: not JSON: ");
  std::filesystem::remove(file);
}

TEST(Explore, ABadGridIsAUsageError) {
  GridOptions grid = small_grid();
  grid.grasps = {"medium_wrapp"};
  EXPECT_THROW_MSG(make_explorer(shipped("tongs.yaml", {"egg.yaml"}), grid),
                   "--grasps: medium_wrapp is not a grasp type of");
  EXPECT_THROW_MSG(make_explorer(shipped("tongs.yaml", {"egg.yaml"}), grid), "did you mean 'medium_wrap'");
  grid = small_grid();
  grid.max_effort = 1000;
  EXPECT_THROW_MSG(make_explorer(shipped("tongs.yaml", {"egg.yaml"}), grid), "at most the hand's limit 400 N");
  grid = small_grid();
  grid.placements = 1000;
  grid.thumbs = 1000;
  grid.efforts = 1000;
  EXPECT_THROW_MSG(make_explorer(shipped("tongs.yaml", {"egg.yaml"}), grid), "run it in --shard parts");
}

}  // namespace
}  // namespace afford
