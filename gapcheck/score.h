// The scorer: reads the labels only after every case is diagnosed, and
// gives the figures by design group.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gapcheck {

// What the diagnosis said about one case (no label yet).
struct Diagnosed {
  std::string name;
  std::string scenario;                 // actee_scenario_name
  bool several_orientations = false;
  std::string verdict;                  // none, explained, ambiguous, unexplained; "error: ..." if it threw
  std::vector<std::string> effects;     // adopted, sorted
  // Ambiguous: every set that fits as well (the adopted one among them),
  // each sorted.
  std::vector<std::vector<std::string>> alternatives;
  double shrink = 0;                    // held out
  double gap = 0;                       // the nominal model's held-out RMSE over the noise floor
  // The largest shrink the noise leaves room for where `shrink` is
  // measured: 1 - floor / the nominal's held-out RMSE there. A set that
  // takes the gap to the noise floor shrinks it this far and no further.
  double ceiling = 0;
  std::string named() const;            // the effects joined by '+', "ambiguous(a | b)", or the verdict
};

// The label's effects ("none" and "outside:..." have none).
std::vector<std::string> label_effects(const std::string& label);

// The figures by design group, over every case and by its scenario, by one
// orientation or several, by in-library or outside effects: the right set
// named (explained with exactly the true set, or ambiguous with it among
// at most three), effect-free kept `none`, `unexplained` for effects
// outside the library, the median held-out shrink of the effect cases and
// the median of their ceilings, and `unexplained` with the true single
// effect withheld (`withheld`: case to verdict). Prints them and a
// confusion list; writes OUT/results.csv (case, engine, group, label,
// verdict, named, shrink, gap, ceiling, withheld).
void score(const std::vector<Diagnosed>& cases, const std::map<std::string, std::string>& labels,
           const std::map<std::string, std::string>& withheld, const std::string& engine, const std::string& seeds,
           const std::filesystem::path& out);

}  // namespace gapcheck
