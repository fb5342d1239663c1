// The nutcracker session the session tests share, and the state a session
// reaches at a time.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "scripted_agent.h"
#include "session.h"

namespace afford::test {

// Session documents in tests are named as if they sat in sessions/, so that
// their relative paths reach the shipped files.
inline const std::string kSessionName = std::string(AFFORD_SOURCE_DIR) + "/sessions/test.yaml";

// The nutcracker with `actee` (its lines, "actee: ..." or "actees: ..."),
// gripped at 160 mm from the start, then `keyframes`. Line numbers with
// one actee line: 1-3 the head, 4 the actee, 5-8 agent to script, 9-12
// the first keyframe, `keyframes` from 13.
inline std::string nutcracker_session(const std::string& actee, const std::string& keyframes) {
  return "session: test\n"
         "description: a test session\n"
         "object: ../objects/nutcracker.yaml\n" +
         actee +
         "agent: ../agents/hand.yaml\n"
         "rules: ../rules/functions.yaml\n"
         "grasps: ../rules/grasps.yaml\n"
         "script:\n"
         "  - t: 0 s\n"
         "    hand: {position: [80 mm, 40 mm, 190 mm]}\n"
         "    grip: {thumb: 160 mm, index: 160 mm, squeeze: 0 mm}\n"
         "    posture: medium_wrap\n" +
         keyframes;
}

// sessions/paper-nutcracker.yaml, loaded once for the tests that only read it.
inline const CompiledSession& paper_nutcracker() {
  static const CompiledSession s = load_session(std::string(AFFORD_SOURCE_DIR) + "/sessions/paper-nutcracker.yaml");
  return s;
}

inline const std::string kWalnutAt60 = "actee: {file: ../actees/walnut.yaml, at: 60 mm}\n";

// A walnut at 60 mm, squeezed 10 mm by 1 s (lines 13 and 14).
inline const std::string kNutcrackerSession =
    nutcracker_session(kWalnutAt60, "  - t: 1 s\n    grip: {thumb: 160 mm, index: 160 mm, squeeze: 10 mm}\n");

// The state of session `s` after its frames up to time t (s).
inline std::unique_ptr<State> state_at(const CompiledSession& s, double t) {
  std::unique_ptr<State> state = make_state(s.model);
  ScriptedAgent agent(s.script);
  Sample sample;
  for (std::int64_t k = 1; static_cast<double>(k) * s.model.timestep <= t + 1e-9; ++k) {
    const double tk = static_cast<double>(k) * s.model.timestep;
    agent.sample_at(tk, &sample);
    sample.t = tk;
    step(s.model, *state, sample);
  }
  return state;
}

}  // namespace afford::test
