// Setups that load and run but that the hand can never work as meant: a
// warning with the numbers, not an error, since a user may mean them (a
// locked tool, a spring under test). `afford check` and `afford run` print
// them.
#pragma once

#include <string>
#include <vector>

#include "errors.h"
#include "model.h"

namespace afford {

struct Warning {
  SourceLoc loc;        // where the value it is about was written
  std::string message;  // what the hand cannot do, with the numbers
  std::string str() const;  // "file:line:col: warning: message"
};

// The hand against the spring, the spring alone (no friction, no motion),
// at the far end of the emphasis region where the hand has the most
// leverage (moment balance, derive.h): the effort that moves the arm off
// its rest, and, with an actee between the jaws, the effort that closes
// them on it; each a warning when it is more than the hand's max_force.
// `spring` is where the object file gives its spring. The model must have
// its agent.
std::vector<Warning> setup_warnings(const Model& m, const SourceLoc& spring);

}  // namespace afford
