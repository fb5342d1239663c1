// The hand's reach (paper Fig. 8): where a fingertip can be, given the
// hand's pose and the joint ranges of the agent file.
//
// Each finger is a planar chain of three links (agents/README.md, `reach`):
// from its base (the metacarpal joint; the thumb's CMC joint) the metacarpal
// joint turns the first link, the proximal joint the second, the distal
// joint the third, which ends at the tip's centre. Flexion is positive.
// Two simplifications, both making the reach larger, never smaller, so the
// test is a necessary condition:
//  - the chain's plane is free (abduction and the thumb's second CMC axis
//    are not in Fig. 8): the tip's distance from the base then depends only
//    on the proximal and distal angles, and takes every value between
//    chain_min and chain_max (a continuous function on a connected range);
//  - the wrist is free (the hand frame's origin, engine/session/script.h; its joint
//    is not in Fig. 8 either): the palm may turn about it, so a tip is within
//    reach when its distance from the wrist lies between reach_min and
//    reach_max, a spherical shell about the wrist.
// Nothing here allocates; finger_chain() may run in a frame.
#pragma once

#include <Eigen/Geometry>
#include <array>

#include "spec.h"

namespace afford {

struct Model;

// The nearest and farthest distance (m) of a planar chain's tip from its
// base, over the joint ranges (rad). link, lo and hi are in the agent
// file's joint order [distal, proximal, metacarpal]; a link may be 0 (a
// chain of two links). The metacarpal range does not matter (it turns the
// whole chain). Exact in the distal angle, on a 0.05 deg grid in the
// proximal one (error below a micrometre for a hand).
void chain_range(const std::array<double, kJoints>& link, const std::array<double, kJoints>& lo,
                 const std::array<double, kJoints>& hi, double* nearest, double* farthest);

// The tip's distance (m) from the base at the proximal and distal angles (rad).
double chain_distance(const std::array<double, kJoints>& link, double proximal_rad, double distal_rad);

// Compiler pass: the agent's chains into the model (Model::has_reach ...).
void compile_reach(const AgentSpec& agent, Model& m);

// How far (m) a tip at `tip` (hand frame) lies outside its finger's reach:
// 0 within it. Needs m.has_reach.
double reach_short(const Model& m, int finger, const Eigen::Vector3d& tip);

// The point of the finger's reach nearest to `tip` (hand frame): `tip`
// itself when it is within reach, else on the shell's surface, along the
// line from the wrist through it.
Eigen::Vector3d nearest_reachable(const Model& m, int finger, const Eigen::Vector3d& tip);

// One finger drawn from the kinematics (hand frame, m): its base (turned
// about the wrist as far as the tip needs), the proximal and distal joints
// and the tip's centre, and the joint angles (rad) that put it there. The
// tip is nearest_reachable(tip); `short_by` (m) how far the target was
// beyond it. The chain bends toward the palm (-z of the hand frame).
struct FingerChain {
  std::array<Eigen::Vector3d, kJoints + 1> point{};  // base, proximal joint, distal joint, tip
  std::array<double, kJoints> angle{};               // rad, [distal, proximal, metacarpal]; metacarpal from the base's line to the first link
  double short_by = 0;                                // m
};
FingerChain finger_chain(const Model& m, int finger, const Eigen::Vector3d& tip);

}  // namespace afford
