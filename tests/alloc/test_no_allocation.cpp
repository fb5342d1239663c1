// A frame allocates nothing: every frame of every shipped session, and of a
// scene with every effect on, counted by a replaced operator new (its own
// test program, so that the replacement touches no other test).
#include <gtest/gtest.h>

#include <filesystem>

#include "../rig.h"
#include "alloc_counter.h"
#include "rules.h"
#include "scripted_agent.h"
#include "session.h"

namespace afford::test {
namespace {

TEST(NoAllocation, EveryFrameOfEveryShippedSession) {
  int sessions = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(AFFORD_SOURCE_DIR) + "/sessions")) {
    if (entry.path().extension() != ".yaml") continue;
    const CompiledSession s = load_session(entry.path().string());
    const std::vector<Sample> samples = script_samples(s.script, s.model.timestep);
    auto state = make_state(s.model);
    auto rules = make_rule_state(*s.rules);
    long frames = 0, allocations = 0;
    for (const Sample& sample : samples) {
      const long before = allocation_count();
      step(s.model, *state, sample);
      evaluate(*s.rules, *rules, s.model, *state);
      allocations += allocation_count() - before;
      ++frames;
    }
    EXPECT_GT(frames, 1000) << entry.path();
    EXPECT_EQ(allocations, 0) << entry.path();
    ++sessions;
  }
  EXPECT_GE(sessions, 5);
}

TEST(NoAllocation, EveryEffectOn) {
  const Model m = model_with_every_effect();
  Rig rig(m, 0.150);
  const long before = allocation_count();
  rig.close_to(rig.state().contact_angle);
  for (int i = 0; i < 300; ++i) rig.push(5e-5, 5e-5);
  EXPECT_EQ(allocation_count() - before, 0);
  EXPECT_EQ(rig.state().condition, ActeeCondition::broken);  // the whole path: squeeze and crack
}

}  // namespace
}  // namespace afford::test
