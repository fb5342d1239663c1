#include "phases.h"

#include <algorithm>
#include <array>

namespace afford {

std::vector<PhaseShare> phase_shares(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& before,
                                     const std::vector<std::vector<double>>& after) {
  double total_before = 0, total_after = 0;
  std::array<PhaseShare, kPhases> shares{};
  for (int p = 0; p < kPhases; ++p) shares[static_cast<size_t>(p)].phase = static_cast<Phase>(p);
  for (size_t i = 0; i < replays.size(); ++i) {
    for (size_t s = replays[i].history; s < replays[i].t.size(); ++s) {
      PhaseShare& ps = shares[static_cast<size_t>(replays[i].phase[s])];
      ++ps.samples;
      ps.before += before[i][s] * before[i][s];
      ps.after += after[i][s] * after[i][s];
      total_before += before[i][s] * before[i][s];
      total_after += after[i][s] * after[i][s];
    }
  }
  std::vector<PhaseShare> out;
  for (PhaseShare& ps : shares) {
    if (ps.samples == 0) continue;
    ps.before = total_before > 0 ? ps.before / total_before : 0;
    ps.after = total_after > 0 ? ps.after / total_after : 0;
    out.push_back(ps);
  }
  std::sort(out.begin(), out.end(), [](const PhaseShare& a, const PhaseShare& b) { return a.before > b.before; });
  return out;
}

}  // namespace afford
