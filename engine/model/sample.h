// One agent sample: what a device (script, recording, glove) says about the
// hand at one instant. Fixed size: passing one allocates nothing.
#pragma once

#include <Eigen/Geometry>
#include <array>

#include "spec.h"

namespace afford {

struct Sample {
  double t = 0;                                         // s
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();  // world pose of the hand (wrist)
  FingerPoints fingertip = finger_origins();     // m, world; [0] is the thumb
  std::array<std::array<double, kJoints>, kFingers> joint{};  // rad: distal, proximal, metacarpal
};

}  // namespace afford
