// afford rules --list: the vocabulary predicates are written in.
// afford rules FILE: the function models a file defines, node by node.
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "option_checks.h"
#include "rules.h"

namespace afford::cli {

namespace {

struct RulesOptions {
  bool list = false;
  std::string file;
};

int rules(const RulesOptions& o) {
  if (o.list) {
    std::cout << "signals (arguments are agent, object, actee; entity.name reads as name(entity)):\n";
    for (const SignalDoc& d : vocabulary()) {
      std::printf("  %-28s %-32s %s\n", d.signature.c_str(), d.type.c_str(), d.doc.c_str());
    }
    std::cout << "\noperators: + - * / (units combine), < <= > >= == != (same units on both sides),\n"
                 "           and, or, not (conditions); numbers carry their unit: 5 cm, 30 N, 200 ms\n";
    return 0;
  }
  const auto rules = load_rules(o.file);
  for (int f = 0; f < function_count(*rules); ++f) {
    std::cout << function_name(*rules, f) << ":\n";
    for (int n = 0; n < node_count(*rules, f); ++n) {
      std::cout << "  " << n + 1 << ". " << node_text(*rules, f, n) << "\n";
    }
  }
  return 0;
}

}  // namespace

void add_rules(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand("rules", "the predicate vocabulary, or the function models of a file");
  auto o = std::make_shared<RulesOptions>();
  CLI::Option* list = cmd->add_flag("--list", o->list, "list the signals and operators predicates are written with");
  CLI::Option* file = cmd->add_option("FILE", o->file, "a file of function models to print node by node");
  file->type_name(kFile)->excludes(list);
  cmd->require_option(1);  // --list or FILE
  cmd->callback([run, o] { *run = [o] { return rules(*o); }; });
}

}  // namespace afford::cli
