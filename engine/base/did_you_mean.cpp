#include "did_you_mean.h"

#include <algorithm>
#include <cctype>

namespace afford {
namespace {

// Optimal string alignment distance (Levenshtein plus transpositions),
// case-insensitive: "Constnat" and "constant" are one typo apart.
int edit_distance(std::string_view a, std::string_view b) {
  auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      const int cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1])) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

}  // namespace

std::string closest_name(std::string_view wrong,
                         const std::vector<std::string>& candidates) {
  // Allow about one typo per four letters, at least one; a name cut short
  // ("grasp" for "grasping") counts as one typo.
  const int allowed = std::max(1, static_cast<int>(wrong.size()) / 4);
  std::string best;
  int best_distance = allowed + 1;
  for (const std::string& c : candidates) {
    const bool cut_short = wrong.size() >= 3 && c.size() > wrong.size() && c.compare(0, wrong.size(), wrong) == 0;
    const int dist = cut_short ? 1 : edit_distance(wrong, c);
    if (dist < best_distance) {
      best_distance = dist;
      best = c;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view wrong,
                         const std::vector<std::string>& candidates) {
  const std::string best = closest_name(wrong, candidates);
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

}  // namespace afford
