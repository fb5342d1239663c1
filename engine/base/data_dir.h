// Where afford's shipped data is: the folder holding rules/, agents/,
// actees/, objects/, sessions/ and devices/ (the function models, grasps,
// guides, the hand, the actees, the example objects and sessions, the
// device descriptions). Files a user writes name their files relative to
// themselves (data_files.h); only the defaults of the commands (the guides
// of `afford guide`, the actees of `afford describe`) come from here.
//
// The folder is the first of:
//   1. $AFFORD_DATA_DIR, when set (and then it must hold the shipped data:
//      a wrong value is an error, not skipped);
//   2. the source tree, when the program runs from its build tree;
//   3. the installed data folder beside the program (bin/../share/afford),
//      which follows an install moved with `cmake --install --prefix`;
//   4. the installed data folder as configured (CMAKE_INSTALL_FULL_DATADIR/afford).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace afford {

// The shipped data folder; throws std::runtime_error naming every place it
// looked (or the bad $AFFORD_DATA_DIR) when none holds the shipped data.
std::string data_dir();

// A shipped file or folder by its path in the data folder, e.g.
// shipped_path("rules/guides.yaml").
std::string shipped_path(std::string_view relative);

// The places data_dir() looks, given explicitly (for tests).
struct DataDirSearch {
  std::optional<std::string> env;  // $AFFORD_DATA_DIR, if set
  std::string program;             // the running program's path
  std::string build_dir;           // the build tree it was built in
  std::string source_dir;          // the source tree of that build
  std::string program_to_data;     // the installed data folder, relative to the program's folder
  std::string installed_dir;       // the installed data folder, absolute
};

// data_dir() over the given places.
std::string find_data_dir(const DataDirSearch& search);

// True when the folder holds the shipped data (its rules/, agents/,
// actees/ and objects/ folders).
bool holds_shipped_data(const std::string& dir);

}  // namespace afford
