// The signals predicates are written over: a registry with a manifest per
// signal (its arguments, type, unit and meaning), read from the State each
// frame. `afford rules --list` prints it.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model.h"
#include "state.h"
#include "units.h"

namespace afford {

enum class Entity { agent, object, actee };

struct Signal {
  const char* name;
  std::vector<Entity> args;
  bool symmetric;  // the two arguments may come in either order
  bool boolean;    // true: a condition; false: a number of `dimension`
  Dimension dimension;
  const char* doc;
  double (*read)(const Model&, const State&);  // 0/1 for conditions
};

const std::vector<Signal>& signal_registry();

// Finds the signal for name(args); nullptr when none matches. `names` gets
// every signal name, for "did you mean".
const Signal* find_signal(const std::string& name, const std::vector<Entity>& args);
// The number that says why a condition holds or not, given with it in an
// inference's explanation: grip_margin(actee) for held(actee). nullptr: none.
const Signal* explaining_signal(const Signal& condition);
std::vector<std::string> signal_names();
bool parse_entity(const std::string& text, Entity* out);
const char* entity_name(Entity e);
std::string signature(const Signal& s);  // "force(object, actee)"

}  // namespace afford
