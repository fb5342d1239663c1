// The scene a page draws, sent once when it connects and again at each
// trial: the tool's parts and the actee as triangle meshes from the same
// geometry the engine collides (render/mesh.h tessellates it), the
// fingertips' radii, and what the page may ask (protocol.h's limits, the
// shelf). The bodies' poses come with each state message.
//
//   {"type":"scene","session":"paper-tongs","trial":1,"participant":"p01",
//    "recording":"out/.../p01-trial-001.afrec","actee_name":"egg",
//    "parts":[{"name":"...","arm":"fixed"|"moving","in_arm":[16],
//              "positions":[...],"normals":[...]}],
//    "actee":{"positions":[...],"normals":[...],"colour":"#rrggbb","limit":35} | null,
//    "fingertip_radius":[5 numbers],"theta":{"min":..,"max":..,"rest":..},
//    "limits":{"max_squeeze":..,"hand_min":[3],"hand_max":[3]},
//    "hand_start":[3],"grip":{"posture":"medium_wrap","thumb_distance":0.13},
//    "shelf":["coconut","egg",...],"timestep":0.001,
//    "guides":{...guides_message.h...} | null}
// Lengths in m, angles in rad, forces in N; matrices column-major.
#pragma once

#include <string>
#include <vector>

#include "guides.h"
#include "page_agent.h"
#include "protocol.h"
#include "session.h"

namespace afford::serve {

struct SceneInfo {
  int trial = 0;
  std::string participant, recording, actee_name;
  std::vector<std::string> shelf;
  const Guides* guides = nullptr;  // `afford guide`'s guides of the tool (guides_message.h); null: none sent
};

std::string scene_message(const CompiledSession& session, const PageGrip& grip, const PageStart& start,
                          const CommandLimits& limits, const SceneInfo& info);

}  // namespace afford::serve
