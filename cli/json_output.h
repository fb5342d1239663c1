// The JSON the commands print (--json), built with nlohmann-json instead of
// concatenated strings: escaping, nesting and commas are its job. Keys keep
// the order they are written in.
#pragma once

#include <nlohmann/json.hpp>

#include "run.h"

namespace afford::cli {

using Json = nlohmann::ordered_json;

// v to 9 significant digits, as the text output prints it: a time of
// 2581 frames of 1 ms is 2.581 in the JSON, not 2.5810000000000004.
// Non-finite values become null.
Json json_number(double v);

// The inferred functions of a run: [{name, t, explanation: [{t, text}]}].
Json inferences_json(const RunResult& r);

}  // namespace afford::cli
