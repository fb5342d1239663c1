// Where a measurement's traces are cut for cross-validation: contiguous
// blocks of its replays, each judged by fits on the others.
#pragma once

#include <cstddef>
#include <vector>

#include "replay.h"

namespace afford {

// Fitted samples: a block with fewer joins its neighbour, and nothing is
// judged on fewer.
inline constexpr size_t kMinBlock = 200;

// Samples from..to of replay `trace`.
struct Block {
  size_t trace = 0, from = 0, to = 0;
};

// Where the traces are cut for cross-validation: each trace into
// contiguous blocks that hold about equal shares of what can be judged
// (never at its middle in time: an actee that breaks early leaves its
// first half all but unfitted), about four in all, a block of fewer
// than kMinBlock fitted samples joined to its neighbour. What can be
// judged is the fitted samples and, apart, those in the actee's contact,
// each half of the whole where the jaws touch one: an actee's law is
// fitted and judged in the contact alone, and where one trace held all
// of it, as one block, the folds that judged it had none to fit the law
// on (a light squeeze that touched only one way up). A contact of fewer
// than kMinBlock fitted samples (a brush at a crack) is too little to
// share out, and counts as what it is among the rest.
std::vector<Block> blocks_of(const std::vector<Replay>& replays);

// Each block as a replay of its own, with the history a late sensor's
// readings at its first samples need (never fitted, judged or counted).
std::vector<Replay> sliced(const std::vector<Replay>& replays, const std::vector<Block>& blocks);

// The samples fitted in every replay.
size_t fitted_samples(const std::vector<Replay>& replays);

}  // namespace afford
