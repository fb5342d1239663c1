// The scripted agent: a SampleSource that plays a compiled Script
// (engine/session/script.h), interpolating between its keyframes linearly in time.
#pragma once

#include <vector>

#include "sample_source.h"
#include "script.h"

namespace afford {

class ScriptedAgent : public SampleSource {
 public:
  // Keeps a reference: the script must outlive the agent.
  explicit ScriptedAgent(const Script& script);

  // The sample at t (s): before the first keyframe its values, after the
  // last (t > duration) nothing (returns false). Between keyframes the
  // hand's position is interpolated linearly and its rotation by slerp;
  // each fingertip linearly in the hand frame (a squeezing thumb by its
  // angle about the pivot, script.h), then placed in the world by the
  // interpolated hand; each joint angle linearly. At a keyframe's time the
  // sample is that keyframe exactly. Allocates nothing.
  bool sample_at(double t, Sample* out) override;

  // The last keyframe's time, s.
  double duration() const override { return script_.duration(); }

 private:
  // What holds across the span before keyframe i (from keyframe i - 1; the
  // first and the last keyframe alone at either end), found once so that a
  // frame copies what does not change instead of interpolating it. The
  // copy is bit for bit what std::lerp gives for equal ends.
  struct Span {
    bool turning = false;  // the hand's rotation changes
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // the hand's, where it does not turn
    bool moving = false;  // the hand's position changes
    bool arc = false;     // the thumb turns about the pivot (script.h)
    std::array<bool, kFingers> tip_moves{};  // fingertip f changes in the hand frame
    bool joints_move = false;
  };

  const Script& script_;
  std::vector<Span> spans_;  // keyframes + 1
  size_t last_ = 0;          // the span of the last sample: where the next is looked for first
};

// Every sample of a script at frames of `timestep` seconds, the first at
// t = timestep (benchmarks and tests that step without the run loop).
std::vector<Sample> script_samples(const Script& script, double timestep);

}  // namespace afford
