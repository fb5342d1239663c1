// The hand a page drives: the page says what the hand should do (close the
// fingers on the arms, squeeze the thumb so far, move the hand there, open
// the fingers) and this turns it into agent samples exactly as a session's
// script would (engine/session/script.h): a grip puts the thumb on the moving arm's
// outer face, turned about the pivot by squeeze / |D_ag| past the rest
// angle, and the index on the fixed arm's; while the fingers hold the tool
// it moves with the hand; after they open, the tool stays where it was.
//
// The page's wishes are reached at bounded rates, in session time, so that
// the same commands at the same frames give the same samples bit for bit:
// the fingers close or open in kCloseTime, the thumb moves at most
// kSqueezeRate, the hand at most kHandSpeed (and only while the fingers are
// not closing or opening, as a script closes them with the hand still).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>

#include "protocol.h"
#include "sample.h"
#include "script.h"
#include "session.h"

namespace afford::serve {

// Where the fingers go when they close on the tool, in the tool's frames.
struct PageGrip {
  Eigen::Vector3d thumb_rest = Eigen::Vector3d::Zero();  // m, the thumb's point on the moving arm at rest (its frame)
  double thumb_distance = 0;                             // m, |D_ag|, > 0
  Eigen::Vector3d index = Eigen::Vector3d::Zero();       // m, the index on the fixed arm (object frame)
  JointAngles joint{};                                   // rad, the grasp posture
  std::string posture;                                   // its grasp type's name
};

// The grip of the session's script (its first grip that grasps the tool),
// or, when the script has none, the thumb and the index at the middle of
// the emphasis region in the first grasp type the hand can take. Throws
// std::runtime_error when neither exists.
PageGrip page_grip(const CompiledSession& session);

// Where the hand starts and how it holds its fingers open: the script's
// first keyframe (fingertips in the hand frame; curled into the palm when
// that keyframe is a grip).
struct PageStart {
  Eigen::Vector3d hand_position = Eigen::Vector3d::Zero();  // m, world
  Eigen::Quaterniond hand_rotation = Eigen::Quaterniond::Identity();
  FingerPoints open_fingertip = finger_origins();  // m, hand frame
  JointAngles open_joint{};                                 // rad
};
PageStart page_start(const CompiledSession& session);

// What a page may ask of this session's hand: squeezes up to closing the
// tool and 30 mm beyond (pressing the arm on its stop), the hand within
// 0.3 m of where it starts.
CommandLimits command_limits(const Model& model, const PageGrip& grip, const PageStart& start);

class PageAgent {
 public:
  static constexpr double kCloseTime = 0.25;    // s, fingers from open to closed
  static constexpr double kSqueezeRate = 0.03;  // m/s
  static constexpr double kHandSpeed = 0.1;     // m/s

  PageAgent(const Model& model, const PageGrip& grip, const PageStart& start);

  // A page's command (thumb, grasp, release, move; the others are the
  // server's). Allocates nothing.
  void apply(const Command& c);
  // Advances to session time t (s, not before the last) and writes the
  // sample. Allocates nothing.
  void sample(double t, Sample* out);

  double squeeze() const { return squeeze_; }                // m
  double squeeze_target() const { return squeeze_target_; }  // m
  bool gripping() const { return closing_; }                 // asked to close (or closed)
  double closed() const { return blend_; }                   // 0 open .. 1 closed
  std::int64_t applied_seq() const { return applied_seq_; }   // the last applied command's seq (-1 none)

 private:
  const Model& model_;
  PageGrip grip_;
  PageStart start_;
  double last_t_ = 0;
  bool closing_ = false;
  double blend_ = 0;  // 0 open, 1 closed
  double squeeze_ = 0, squeeze_target_ = 0;
  Eigen::Vector3d hand_ = Eigen::Vector3d::Zero(), hand_target_ = Eigen::Vector3d::Zero();
  Eigen::Isometry3d object_world_ = Eigen::Isometry3d::Identity();    // where the tool is while not held
  Eigen::Isometry3d object_in_hand_ = Eigen::Isometry3d::Identity();  // the tool in the hand frame while held
  bool holding_ = false;  // the fingers closed on the tool: it moves with the hand
  std::int64_t applied_seq_ = -1;
};

}  // namespace afford::serve
