// Where the benchmarks find the shipped files: the source tree.
#pragma once

#include <string>

namespace afford::bench {

inline const std::string kSource = AFFORD_SOURCE_DIR;

}  // namespace afford::bench
