// The tools of the withheld check: the three shipped ones and two new
// geometries derived from them by changing numbers (a heavy press from the
// nutcracker, long-handled snips from the pliers), read by afford's loaders
// for their numbers; and the actees each can hold.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "truth.h"

namespace gapcheck {

// "nutcracker", "tongs", "pliers" (objects/), "press", "snips" (new).
const std::vector<std::string>& tool_names();

// The object file of a tool: a shipped one under SOURCE/objects, or a new
// geometry written into `dir` (named `stem`.yaml). Returns its path.
std::filesystem::path tool_file(const std::filesystem::path& source, const std::filesystem::path& dir,
                                const std::string& stem, const std::string& tool);

// A tool's numbers from its object file.
Tool load_tool(const std::filesystem::path& file);

// An actee a tool holds: its shipped file's name and where it sits along
// the fixed arm.
struct ActeePlace {
  std::string actee;
  double at = 0;  // m
};
std::vector<ActeePlace> actee_places(const std::string& tool);  // empty: its jaws hold none of the shipped actees

// The tool with the actee in its jaws: the file's numbers and where
// MuJoCo's collision finds that the jaws touch it (jaw_contact.h).
Tool with_actee(Tool tool, const std::filesystem::path& source, const ActeePlace& place);

}  // namespace gapcheck
