// Fuzzes the reader of explore.json (explore/explore_json.h), what
// `afford explore --merge` reads from every shard. A std::runtime_error
// naming the file is the expected answer to a damaged file; anything else
// (a crash, an index out of bounds, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "explore_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  afford::GridInfo grid;
  afford::ExploreResult result;
  try {
    afford::parse_explore_json(text, "fuzz.json", &grid, &result);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
