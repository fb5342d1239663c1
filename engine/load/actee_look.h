// How an actee is drawn: the `look` of its file (actees/README.md). Only
// the renderer reads it; it changes nothing in the physics.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace afford {

struct ActeeLook {
  // How it is drawn once broken: split in two and turned open (a nut),
  // flattened with its inside spilled (an egg), or in eight pieces pushed
  // apart (an ice cube, a hard shell).
  enum class Broken { halves, crushed, shards };
  using Srgb = std::array<std::uint8_t, 3>;  // 8-bit sRGB, as "#rrggbb" in the file

  Srgb colour{199, 140, 77};   // its outside, before lighting (default: a nut's tan)
  Srgb inside{227, 198, 166};  // where it has broken open (default: colour halfway to white)
  Broken broken = Broken::shards;
  bool operator==(const ActeeLook&) const = default;
};

// The default inside of an outside colour: halfway to white.
inline ActeeLook::Srgb lighter_half(const ActeeLook::Srgb& c) {
  ActeeLook::Srgb out{};
  for (std::size_t k = 0; k < 3; ++k) out[k] = static_cast<std::uint8_t>((c[k] + 256) / 2);
  return out;
}

}  // namespace afford
