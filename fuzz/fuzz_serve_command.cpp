// Fuzzes the reader of what a page sends `afford serve` (serve/protocol.h,
// parse_command): every message off the WebSocket goes through it. A false
// with an error is the expected answer to a bad message; a crash, a throw
// or a command outside the limits is a bug.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "protocol.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::array<std::string, 3> kShelf = {"egg", "walnut", "sponge"};
  const afford::serve::CommandLimits limits;
  afford::serve::Command c;
  std::string error;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (afford::serve::parse_command(text, limits, kShelf, &c, &error)) {
    // What it accepts lies within what the page may ask.
    if (!(c.squeeze >= 0 && c.squeeze <= limits.max_squeeze)) std::abort();
    for (size_t k = 0; k < 3; ++k) {
      if (!(c.position[k] >= limits.hand_min[k] && c.position[k] <= limits.hand_max[k])) std::abort();
    }
    if (c.actee < -1 || c.actee >= static_cast<int>(kShelf.size())) std::abort();
  } else if (error.empty()) {
    std::abort();  // a refusal always says why
  }
  return 0;
}
