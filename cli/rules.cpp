// afford rules --list: the vocabulary predicates are written in.
// afford rules FILE: the function models a file defines, node by node.
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "rules.h"

namespace afford::cli {

int run_rules(const Args& args) {
  if (args.size() == 1 && args[0] == "--list") {
    std::cout << "signals (arguments are agent, object, actee; entity.name reads as name(entity)):\n";
    for (const SignalDoc& d : vocabulary()) {
      std::printf("  %-28s %-32s %s\n", d.signature.c_str(), d.type.c_str(), d.doc.c_str());
    }
    std::cout << "\noperators: + - * / (units combine), < <= > >= == != (same units on both sides),\n"
                 "           and, or, not (conditions); numbers carry their unit: 5 cm, 30 N, 200 ms\n";
    return 0;
  }
  if (args.size() != 1) return usage_error("rules takes --list or one FILE");
  const auto rules = load_rules(args[0]);
  for (int f = 0; f < function_count(*rules); ++f) {
    std::cout << function_name(*rules, f) << ":\n";
    for (int n = 0; n < node_count(*rules, f); ++n) {
      std::cout << "  " << n + 1 << ". " << node_text(*rules, f, n) << "\n";
    }
  }
  return 0;
}

}  // namespace afford::cli
