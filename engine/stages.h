// The stages of one frame, in the order step() runs them; each writes its
// group of the State. Internal to the engine.
#pragma once

#include "model.h"
#include "sample.h"
#include "state.h"

namespace afford {

// Pose of a part in the object frame at opening angle theta.
Eigen::Isometry3d part_in_object(const ModelPart& part, double theta_rad);

// The largest opening angle in [theta_min, theta_max] at which the moving
// arm touches an actee placed at actee_in_object; false when the jaws never
// close on it (outside the wedge) or it does not fit even fully open.
bool find_contact_angle(const Model& m, const Eigen::Isometry3d& actee_in_object,
                        ContactQuery& query, double* theta_c);

// 1. Bodies in the world: the sample, the grasped object, the held actee.
void place_bodies(const Model& m, State& s, const Sample& sample);
// 2. Which fingers touch which arm; the grasp starts and ends here.
void find_grasp(const Model& m, State& s);
// 3. The lever-spring solver: angle, spring, forces, named torques.
void solve_lever(const Model& m, State& s);
// 4. The actee's condition (intact, squeezed, broken) and whether it is held.
void update_actee(const Model& m, State& s);
// 5. Object-actee and agent-actee contacts at the solved angle.
void find_actee_contacts(const Model& m, State& s);

}  // namespace afford
