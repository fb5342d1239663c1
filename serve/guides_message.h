// The guides of `afford guide` (guides/guides.h: symmetry plane, interaction
// space, emphasis, force amplification) as JSON for the page's scene: each
// primitive in its arm's frame ("fixed": the object frame, "moving": the
// moving arm's), so the page hangs it on that arm and it follows the tool;
// and the facts `afford guide` prints.
//
//   {"guides":[{"name","kind","description","colour":[r,g,b,a]}],
//    "rects":[{"guide","frame","centre":[3],"u":[3],"v":[3],"half_u","half_v","colour":[4]}],
//    "meshes":[{"guide","frame","vertices":[[3]...],"triangles":[[3]...],"colour":[4]}],
//    "segments":[{"guide","frame","a":[3],"b":[3],"colour":[4],"value"}],
//    "labels":[{"guide","frame","text","anchor":[3],"colour":[4]}],
//    "facts":{"pattern","symmetry_plane":{"point","normal"},
//             "interaction_space":{"from","to","gap_from","gap_to"},
//             "emphasis":{"from","to"},
//             "advantage":{"load_at","ma_min","ma_max","ma_arm_min","ma_arm_max"}}}
// Lengths in m, colours 0..1.
#pragma once

#include <nlohmann/json.hpp>

#include "guides.h"

namespace afford::serve {

nlohmann::json guides_json(const Guides& g);

}  // namespace afford::serve
