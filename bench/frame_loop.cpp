// One frame loop, for stable instruction counts: every frame of a session,
// `passes` times, nothing else timed. Run under callgrind:
//   valgrind --tool=callgrind --toggle-collect="afford::step(*"
//       --toggle-collect="afford::evaluate(*" build/bench/afford_frame_loop SESSION 5
// and divide the instructions collected by the frames it prints.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "rules.h"
#include "scripted_agent.h"
#include "session.h"
#include "state.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: afford_frame_loop SESSION PASSES\n");
    return 2;
  }
  using namespace afford;
  const CompiledSession session = load_session(argv[1]);
  const Model& model = session.model;
  const std::vector<Sample> samples = script_samples(session.script, model.timestep);
  auto state = make_state(model);
  auto rules = make_rule_state(*session.rules);
  const int passes = std::atoi(argv[2]);
  long frames = 0;
  for (int p = 0; p < passes; ++p) {
    reset(model, *state);
    reset(*session.rules, *rules);
    for (const Sample& s : samples) {
      step(model, *state, s);
      evaluate(*session.rules, *rules, model, *state);
      ++frames;
    }
  }
  std::printf("%ld frames\n", frames);
  return 0;
}
