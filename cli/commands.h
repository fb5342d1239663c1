// The afford command-line program: one function per subcommand.
#pragma once

#include <string>
#include <vector>

namespace afford::cli {

using Args = std::vector<std::string>;

struct Command {
  const char* name;
  const char* usage;    // "check FILE..."
  const char* summary;  // one line
  int (*run)(const Args& args);
};

const std::vector<Command>& commands();

int run_check(const Args& args);
int run_describe(const Args& args);
int run_gap(const Args& args);
int run_guide(const Args& args);
int run_live(const Args& args);
int run_run(const Args& args);
int run_replay(const Args& args);
int run_render(const Args& args);
int run_rules(const Args& args);
int run_schema(const Args& args);
int run_test(const Args& args);

// Prints "afford: <message>" to stderr and returns the exit status 2.
int usage_error(const std::string& message);

}  // namespace afford::cli
