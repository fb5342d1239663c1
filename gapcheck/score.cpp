#include "score.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace gapcheck {
namespace {

std::string joined(const std::vector<std::string>& names, const char* sep) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : sep) + n;
  return s.empty() ? "none" : s;
}

bool right_set(const Diagnosed& d, const std::vector<std::string>& truth) {
  if (d.verdict == "explained") return d.effects == truth;
  if (d.verdict == "ambiguous" && d.alternatives.size() <= 3) {
    return std::find(d.alternatives.begin(), d.alternatives.end(), truth) != d.alternatives.end();
  }
  return false;
}

struct Tally {
  int effect_cases = 0, right = 0, free_cases = 0, free_none = 0, outside_cases = 0, outside_unexplained = 0;
  int withheld = 0, withheld_unexplained = 0;
  std::vector<double> shrinks, ceilings;
};

// "-" for none.
std::string median_of(std::vector<double> v) {
  if (v.empty()) return "-";
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.3f", n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
  return buf;
}

std::string fraction(int a, int b) {
  if (b == 0) return "-";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%d/%d %3.0f%%", a, b, 100.0 * a / b);
  return buf;
}

}  // namespace

std::string Diagnosed::named() const {
  if (verdict == "explained") return joined(effects, "+");
  if (verdict == "ambiguous") {
    std::string s;
    for (const auto& set : alternatives) s += (s.empty() ? "" : " | ") + joined(set, "+");
    return "ambiguous(" + s + ")";
  }
  return verdict;
}

std::vector<std::string> label_effects(const std::string& label) {
  std::vector<std::string> out;
  if (label == "none" || label.rfind("outside:", 0) == 0) return out;
  std::stringstream in(label);
  std::string name;
  while (std::getline(in, name, '+')) out.push_back(name);
  std::sort(out.begin(), out.end());
  return out;
}

void score(const std::vector<Diagnosed>& cases, const std::map<std::string, std::string>& labels,
           const std::map<std::string, std::string>& withheld, const std::string& engine, const std::string& seeds,
           const std::filesystem::path& out) {
  std::map<std::string, Tally> groups;
  std::map<std::string, std::map<std::string, int>> confusion;
  std::ofstream csv(out / "results.csv");
  csv << "case,engine,group,label,verdict,named,shrink,gap,ceiling,withheld\n";
  for (const Diagnosed& d : cases) {
    const std::string& label = labels.at(d.name);
    const bool outside = label.rfind("outside:", 0) == 0;
    const std::string kind = label == "none" ? "effect-free" : outside ? "outside the library" : "in the library";
    const std::string group = d.scenario + (d.several_orientations ? "+turned" : "");
    const auto w = withheld.find(d.name);
    csv << d.name << "," << engine << "," << group << "," << label << ",\"" << d.verdict << "\",\"" << d.named()
        << "\"," << d.shrink << "," << d.gap << "," << d.ceiling << ",\"" << (w != withheld.end() ? w->second : "")
        << "\"\n";
    ++confusion[label][d.named()];
    for (const std::string& key : {std::string("all"), "scenario " + d.scenario,
                                   std::string(d.several_orientations ? "several orientations" : "one orientation"),
                                   "effects " + kind}) {
      Tally& t = groups[key];
      if (label == "none") {
        ++t.free_cases;
        t.free_none += d.verdict == "none" ? 1 : 0;
      } else if (outside) {
        ++t.outside_cases;
        t.outside_unexplained += d.verdict == "unexplained" ? 1 : 0;
      } else {
        ++t.effect_cases;
        t.right += right_set(d, label_effects(label)) ? 1 : 0;
        t.shrinks.push_back(d.shrink);
        t.ceilings.push_back(d.ceiling);
        if (w != withheld.end()) {
          ++t.withheld;
          t.withheld_unexplained += w->second == "unexplained" ? 1 : 0;
        }
      }
    }
  }
  std::printf("\n%s figures, %s, %zu cases\n", seeds.c_str(), engine.c_str(), cases.size());
  std::printf("%-34s %-14s %-14s %-14s %-8s %-8s %-14s\n", "group", "right set", "free: none", "outside: unexpl",
              "shrink", "ceiling", "withheld: unexpl");
  for (const auto& [key, t] : groups) {
    std::printf("%-34s %-14s %-14s %-14s %-8s %-8s %-14s\n", key.c_str(), fraction(t.right, t.effect_cases).c_str(),
                fraction(t.free_none, t.free_cases).c_str(), fraction(t.outside_unexplained, t.outside_cases).c_str(),
                median_of(t.shrinks).c_str(), median_of(t.ceilings).c_str(),
                fraction(t.withheld_unexplained, t.withheld).c_str());
  }
  std::printf("\nconfusion (true: what the diagnosis said, cases)\n");
  for (const auto& [label, row] : confusion) {
    std::printf("  %-40s", label.c_str());
    for (const auto& [named, count] : row) std::printf(" %s x%d;", named.c_str(), count);
    std::printf("\n");
  }
}

}  // namespace gapcheck
