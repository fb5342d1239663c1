// Same model and samples, same state, bit for bit: twice in a row, and on
// several threads sharing one model (a sweep).
#include <gtest/gtest.h>

#include <thread>

#include "rig.h"

namespace afford::test {
namespace {

// Grasp, close on the nut, crush it, carry the tool away; one hash per frame.
std::vector<std::uint64_t> run_scenario(const Model& m, double effort) {
  Rig rig(m, effort);
  std::vector<std::uint64_t> hashes;
  rig.close_to(rig.state().contact_angle);
  for (int i = 0; i < 400; ++i) {
    rig.push(5e-5, 5e-5);
    hashes.push_back(state_hash(rig.state()));
  }
  for (int i = 0; i < 200; ++i) {
    Sample& s = rig.sample();
    s.hand.translation() += Eigen::Vector3d(0, 0, 2e-4);
    for (auto& tip : s.fingertip) tip += Eigen::Vector3d(0, 0, 2e-4);
    rig.frame();
    hashes.push_back(state_hash(rig.state()));
  }
  return hashes;
}

TEST(Determinism, SameInputTwiceGivesTheSameStateEveryFrame) {
  const std::string nut = nut_yaml(150);
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, &nut, tool.load);
  const std::vector<std::uint64_t> first = run_scenario(m, tool.effort);
  const std::vector<std::uint64_t> second = run_scenario(m, tool.effort);
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) ASSERT_EQ(first[i], second[i]) << "frame " << i;
  // The hash sees the state change: the run is not standing still.
  EXPECT_NE(first.front(), first.back());
}

TEST(Determinism, ThreadsSharingOneModelAgree) {
  const std::string nut = nut_yaml(150);
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, &nut, tool.load);
  const std::vector<std::uint64_t> reference = run_scenario(m, tool.effort);
  std::vector<std::vector<std::uint64_t>> results(4);
  std::vector<std::thread> threads;
  for (auto& r : results) threads.emplace_back([&m, &r, &tool] { r = run_scenario(m, tool.effort); });
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r, reference);
}

TEST(Determinism, EveryEffectOnThreadsAgreeBitForBit) {
  const Model m = model_with_every_effect();
  const std::vector<std::uint64_t> reference = run_scenario(m, 0.150);
  std::vector<std::vector<std::uint64_t>> results(3);
  std::vector<std::thread> threads;
  for (auto& r : results) threads.emplace_back([&m, &r] { r = run_scenario(m, 0.150); });
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r, reference);
  EXPECT_NE(reference.front(), reference.back());
}

TEST(Determinism, HashChangesWithAnySimulatedField) {
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, nullptr, 0);
  auto s = make_state(m);
  const std::uint64_t base = state_hash(*s);
  s->effort_force = std::nextafter(s->effort_force, 1.0);
  EXPECT_NE(state_hash(*s), base);
  reset(m, *s);
  EXPECT_EQ(state_hash(*s), base);
  s->torque[kPivotFriction] = 1e-300;
  EXPECT_NE(state_hash(*s), base);
}

}  // namespace
}  // namespace afford::test
