// The stages of one frame, in the order step() runs them; each writes its
// group of the State. Internal to the engine.
#pragma once

#include "model.h"
#include "sample.h"
#include "state.h"

namespace afford {

// Pose of a part in the object frame at opening angle theta.
Eigen::Isometry3d part_in_object(const ModelPart& part, double theta_rad);

// Why an actee placed at actee_in_object is not between the jaws.
enum class JawFit { fits, too_large, out_of_reach, not_on_fixed_jaw };

// The largest opening angle in [theta_min, theta_max] at which the moving
// arm touches an actee placed at actee_in_object; the load's lever arm
// there (m, signed as the actee's distance along the arm: the moment of the
// moving jaw's push about the hinge per newton); and (if `contacts` is not
// null, sized to the parts) where each part touches it there, in the part's
// arm frame. theta_c and load_distance are set only when it fits.
JawFit find_contact_angle(const Model& m, const Eigen::Isometry3d& actee_in_object,
                          ContactQuery& query, double* theta_c, double* load_distance,
                          std::vector<JawContact>* contacts);

// The actee's extent (m) across the jaws, placed at actee_in_object: along
// the fixed jaw's normal, the object's y axis.
double thickness_across_jaws(const Model& m, const Eigen::Isometry3d& actee_in_object);

// 1. Bodies in the world: the sample, the grasped object, the held actee.
void place_bodies(const Model& m, State& s, const Sample& sample);
// 2. The grasp starts and ends, from the contacts of the last frame.
void update_grasp(const Model& m, State& s);
// 3. The lever-spring solver: angle, spring, forces, named torques.
void solve_lever(const Model& m, State& s);
// 4. The actee's condition (intact, squeezed, broken) and whether it is held.
void update_actee(const Model& m, State& s);
// 5. Agent-object, object-actee and agent-actee contacts at the solved angle.
void find_contacts(const Model& m, State& s);

}  // namespace afford
