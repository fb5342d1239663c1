#include "blocks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

namespace afford {
namespace {

constexpr size_t kBlocks = 4;           // blocks cut from a measurement's traces, about (at least one a trace)
constexpr size_t kMinContactCut = 50;   // fitted samples in a short contact, and on each side of its cut
constexpr double kStencilReach = 3;     // samples: how far before a delayed time its stencil reads

// Samples from..to of a replay: a block of its trace, judged on its own.
// A block is cut for judging, not the force sensor's memory: a late
// sensor at the block's first samples reads the effort of the samples
// before it, so those (as far back as the longest delay searched, and
// the stencil's reach) come along as its history, never fitted, judged
// or counted. Cut without them, a late set's prediction held the block's
// first value for the whole delay: in a stiff actee's contact many times
// the noise, at every cut.
Replay slice(const Replay& r, size_t from, size_t to) {
  size_t first = from;
  if (from > 0) {
    const double reach = kLongestDelay + kStencilReach * (r.t[from] - r.t[from - 1]);  // s
    while (first > 0 && r.t[from] - r.t[first - 1] <= reach) --first;
  }
  auto cut = [&](const auto& v) {
    return std::decay_t<decltype(v)>(v.begin() + static_cast<long>(first), v.begin() + static_cast<long>(to));
  };
  Replay h;
  char label[96];
  std::snprintf(label, sizeof label, " (%.3f to %.3f s)", r.t[from], r.t[to - 1]);
  h.file = r.file + label;
  h.turned = r.turned;
  h.x_noise = r.x_noise;
  h.step = r.step;
  h.inertia = r.inertia;
  h.resolution = r.resolution;
  h.rig = r.rig;
  h.to_newtons = r.to_newtons;
  h.break_at = r.break_at == SIZE_MAX ? SIZE_MAX : (r.break_at <= first ? 0 : r.break_at - first);
  h.history = from - first;
  h.t = cut(r.t);
  h.x = cut(r.x);
  h.rate = cut(r.rate);
  h.accel = cut(r.accel);
  h.rate_noise = cut(r.rate_noise);
  h.accel_noise = cut(r.accel_noise);
  h.measured = cut(r.measured);
  h.nominal = cut(r.nominal);
  h.deflection = cut(r.deflection);
  h.slope = cut(r.slope);
  h.weight = cut(r.weight);
  if (!r.actee_measured.empty()) {
    h.actee_measured = cut(r.actee_measured);
    h.actee_nominal = cut(r.actee_nominal);
  }
  h.phase = cut(r.phase);
  h.fitted = cut(r.fitted);
  h.held = cut(r.held);
  for (size_t s = 0; s < h.history; ++s) {
    h.fitted[s] = false;
    h.held[s] = false;
  }
  return h;
}

// A sample fitted with the jaws on the actee.
bool fitted_in_contact(const Replay& r, size_t s) { return r.fitted[s] && r.deflection[s] > 0; }

// A contact too short to share out (a squeeze before an early crack)
// still holds all that the actee's law shows. Left in one block, the fold
// that judges it fits the law on no contact at all and the law is never
// judged (development seed 6140: 155 samples before the crack, `unexplained`
// at 1.25 times the noise with the actee's stiffness among the truth). Each
// block that holds contact is cut at its contact's middle, the law fitted
// on one half of the loading judged on the other; each side may hold fewer
// than kMinBlock fitted samples (the free motion before an early touch is
// short), but not fewer than kMinContactCut. A touch of fewer than
// kMinContactCut samples (12 where a sine's first closing cracks a nut at
// once) is left whole: halves of a few samples fit no law and judge none,
// and the cut would only leave a block far smaller than the rest.
std::vector<Block> with_contact_cut(const std::vector<Replay>& replays, const std::vector<Block>& blocks) {
  std::vector<Block> out;
  for (const Block& b : blocks) {
    const Replay& r = replays[b.trace];
    size_t contact = 0, fitted = 0;
    for (size_t s = b.from; s < b.to; ++s) {
      contact += fitted_in_contact(r, s) ? 1 : 0;
      fitted += r.fitted[s] ? 1 : 0;
    }
    size_t cut = b.from, seen = 0, fitted_before = 0;
    for (; cut < b.to && 2 * seen < contact; ++cut) {
      seen += fitted_in_contact(r, cut) ? 1 : 0;
      fitted_before += r.fitted[cut] ? 1 : 0;
    }
    if (contact < kMinContactCut || fitted_before < kMinContactCut || fitted - fitted_before < kMinContactCut) {
      out.push_back(b);
      continue;
    }
    out.push_back({b.trace, b.from, cut});
    out.push_back({b.trace, cut, b.to});
  }
  return out;
}

}  // namespace

size_t fitted_samples(const std::vector<Replay>& replays) {
  size_t n = 0;
  for (const Replay& r : replays) n += static_cast<size_t>(std::count(r.fitted.begin(), r.fitted.end(), true));
  return n;
}

std::vector<Block> blocks_of(const std::vector<Replay>& replays) {
  double fitted_all = 0, contact_all = 0;
  for (const Replay& r : replays) {
    for (size_t s = 0; s < r.t.size(); ++s) {
      fitted_all += r.fitted[s] ? 1 : 0;
      contact_all += fitted_in_contact(r, s) ? 1 : 0;
    }
  }
  // Each sample's share of what can be judged: all of it adds up to 1.
  const bool short_contact = contact_all > 0 && contact_all < static_cast<double>(kMinBlock);
  if (short_contact) contact_all = 0;
  const double halves = contact_all > 0 ? 2 : 1;
  auto mass = [&](const Replay& r, size_t s) {
    return ((r.fitted[s] ? 1 / fitted_all : 0.0) + (contact_all > 0 && fitted_in_contact(r, s) ? 1 / contact_all : 0.0)) /
           halves;
  };
  std::vector<double> owns(replays.size(), 0.0);
  std::vector<size_t> fitted(replays.size(), 0), counts(replays.size());
  for (size_t i = 0; i < replays.size(); ++i) {
    const Replay& r = replays[i];
    for (size_t s = 0; s < r.t.size(); ++s) {
      owns[i] += fitted_all > 0 ? mass(r, s) : 0.0;
      fitted[i] += r.fitted[s] ? 1 : 0;
    }
    // What one trace alone shows is judged by folds fitted on the others
    // alone where that trace is one block: a way up only it holds (one way
    // up cannot tell a weight from a preload, and the held-out trace judged
    // a wild guess: the tongs turned 90 deg in one trace of three,
    // development seed 3140), or an inertia only its quick strokes excite
    // (fitted on the slow traces as none, and the inertia that one trace
    // of three showed read `unexplained`: development seed 6246, both
    // engines). Each trace that holds enough is cut in two at least.
    const size_t most = std::max<size_t>(1, fitted[i] / kMinBlock);
    const auto share = static_cast<size_t>(std::lround(static_cast<double>(kBlocks) * owns[i]));
    counts[i] = std::clamp<size_t>(share, std::min<size_t>(2, most), most);
  }
  std::vector<Block> out;
  for (size_t i = 0; i < replays.size(); ++i) {
    // A trace with nothing fitted (all of it the snap after a crack, or
    // held still) is no block: a fold of it judges nothing, and the fold
    // that leaves the others out has nothing to fit (development seed
    // 7130, ODE: judged "over 2 folds (fitted samples: 0 228)", every fit
    // invalid).
    if (fitted[i] == 0 && fitted_all > 0) continue;
    const Replay& r = replays[i];
    const double own = owns[i];
    const size_t blocks = counts[i];
    // Cut where the running share passes each b / blocks of the trace's;
    // a block left with fewer than kMinBlock fitted samples joins the next
    // (the last joins the one before).
    size_t from = 0, fitted_since = 0;
    double seen = 0;
    const size_t first = out.size();
    for (size_t s = 0, b = 1; s < r.t.size() && b < blocks; ++s) {
      seen += mass(r, s);
      fitted_since += r.fitted[s] ? 1 : 0;
      if (seen < own * static_cast<double>(b) / static_cast<double>(blocks)) continue;
      ++b;
      if (fitted_since < kMinBlock) continue;
      out.push_back({i, from, s + 1});
      from = s + 1;
      fitted_since = 0;
    }
    size_t rest = 0;
    for (size_t s = from; s < r.t.size(); ++s) rest += r.fitted[s] ? 1 : 0;
    if (rest < kMinBlock && out.size() > first) {
      out.back().to = r.t.size();
    } else {
      out.push_back({i, from, r.t.size()});
    }
  }
  if (short_contact) out = with_contact_cut(replays, out);
  return out;
}

std::vector<Replay> sliced(const std::vector<Replay>& replays, const std::vector<Block>& blocks) {
  std::vector<Replay> out;
  for (const Block& b : blocks) {
    const Replay& r = replays[b.trace];
    out.push_back(b.from == 0 && b.to == r.t.size() ? r : slice(r, b.from, b.to));
  }
  return out;
}

}  // namespace afford
