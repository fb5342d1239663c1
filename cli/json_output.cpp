#include "json_output.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace afford::cli {

Json json_number(double v) {
  if (!std::isfinite(v)) return nullptr;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  const double rounded = std::strtod(buf, nullptr);
  // Whole numbers as integers ("0", not nlohmann's "0.0"), as printf wrote them.
  if (rounded == std::trunc(rounded) && std::abs(rounded) < 1e15) return static_cast<std::int64_t>(rounded);
  return rounded;  // nlohmann prints the shortest text that reads back as this
}

Json inferences_json(const RunResult& r) {
  Json functions = Json::array();
  for (const Inference& inf : r.inferences) {
    Json explanation = Json::array();
    for (size_t i = 0; i < inf.nodes.size(); ++i) {
      Json node = {{"t", json_number(inf.nodes[i].t)}, {"text", inf.nodes[i].text}};
      if (i < inf.node_details.size() && !inf.node_details[i].empty()) node["detail"] = inf.node_details[i];
      explanation.push_back(node);
    }
    functions.push_back({{"name", inf.function}, {"t", json_number(inf.t)}, {"explanation", explanation}});
  }
  return functions;
}

}  // namespace afford::cli
