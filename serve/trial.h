// The trials of a served session. Each trial is a session of its own: the
// served session's tool, hand, rules and start, with the actee the page
// took from the shelf, written as a session file into the output folder
// (its paths relative to it) so that the trial's recording holds every
// file it ran with and `afford replay` loads the same session.
//
// Names, for participant P and trial N (three digits) in DIR:
//   DIR/P-trial-NNN.yaml     the trial's session
//   DIR/P-trial-NNN.afrec    its recording
//   DIR/P-trial-NNN/         timeline.jsonl and trace.csv, as `afford run` writes
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "session.h"

namespace afford::serve {

// An actee a page may take: the shipped actees folder's files (data_dir.h).
struct ShelfActee {
  std::string name;  // the file's name without .yaml
  std::string file;  // its path
};
std::vector<ShelfActee> actee_shelf(const std::string& folder);
// The shelf of `shipped` (a folder) and then a user's folder's actees
// (`user`, "" none), each file of the user's loaded (a mistake throws
// DataError naming file:line:col) and its name new on the shelf (one a
// shipped actee has throws std::runtime_error naming both files).
std::vector<ShelfActee> actee_shelf(const std::string& shipped, const std::string& user);
std::vector<std::string> shelf_names(const std::vector<ShelfActee>& shelf);

// True for a participant id of 1 to 32 letters, digits, '-' and '_'.
bool valid_participant(const std::string& id);
// "P-trial-NNN".
std::string trial_stem(const std::string& participant, int trial);
// One after the highest trial of the participant already in DIR (1 when
// none), so that a new serve never overwrites an earlier one's trials.
int next_trial(const std::filesystem::path& dir, const std::string& participant);

// Writes DIR/<stem>.yaml: the session `original` (its file as named) with
// the actee `actee_file` (empty: the session's own first actee, as it
// places it) on the fixed jaw where it fits (the middle of the stretch of
// the application region where the jaws close on it), or, when it fits
// nowhere, in the world 150 mm beside the fixed arm; and its script cut to
// the first keyframe, held still a second (a script must last; the page
// drives instead). Loads and returns it. Throws DataError or
// std::runtime_error.
CompiledSession write_trial_session(const CompiledSession& original, const std::string& actee_file,
                                    const std::filesystem::path& dir, const std::string& stem);

}  // namespace afford::serve
