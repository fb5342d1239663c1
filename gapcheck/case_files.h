// A played case on disk: OUT/cases/NAME.yaml (the measurement file of
// gap/README.md), its traces NAME-K.csv, the actee's file as the plates
// measured it (NAME-actee.yaml) and, apart, OUT/labels/NAME.txt.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "design.h"
#include "reality.h"

namespace gapcheck {

// Returns the measurement file's path.
std::filesystem::path write_case(const std::filesystem::path& out, const Case& c,
                                 const std::vector<std::vector<Measured>>& traces, const std::optional<PlatesLaw>& plates);

// A case played and written: its measurement file, and the actee's
// plates measurement (none without an actee), whose misfit the case files
// do not keep.
struct Played {
  std::filesystem::path measurement;
  std::optional<PlatesLaw> plates;
};

// Every drive of `c` played in `reality` with its own noise seed, the
// actee (where there is one) measured on the reality's plates, and the
// case written as write_case writes it.
Played play_and_write(const std::filesystem::path& out, const Case& c, const Reality& reality);

}  // namespace gapcheck
