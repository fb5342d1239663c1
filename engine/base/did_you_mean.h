// "did you mean" hints for misspelt names (keys, vocabulary, device kinds).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace afford {

// The closest candidate within a small edit distance, or "" if none is close.
std::string closest_name(std::string_view wrong,
                         const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" or "" when nothing is close.
std::string did_you_mean(std::string_view wrong,
                         const std::vector<std::string>& candidates);

}  // namespace afford
