// The afford command-line program: one file per subcommand. Each declares
// its options and arguments on its own CLI11 subcommand (add_<name>), so
// that --help, the bash completion and the man page all come from the same
// declarations; when the command line names it, *run becomes the command
// with the parsed values.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace afford::cli {

// The parsed command, ready to run: returns the exit status.
using Run = std::function<int()>;

void add_check(CLI::App& app, Run* run);
void add_describe(CLI::App& app, Run* run);
void add_explore(CLI::App& app, Run* run);
void add_gap(CLI::App& app, Run* run);
void add_render(CLI::App& app, Run* run);
void add_guide(CLI::App& app, Run* run);
void add_rules(CLI::App& app, Run* run);
void add_run(CLI::App& app, Run* run);
void add_live(CLI::App& app, Run* run);
void add_serve(CLI::App& app, Run* run);
void add_view(CLI::App& app, Run* run);
// --port and --bind of serve and view (serve.cpp).
CLI::Validator port_number();
CLI::Validator ipv4_address();
void add_replay(CLI::App& app, Run* run);
void add_schema(CLI::App& app, Run* run);
void add_test(CLI::App& app, Run* run);
void add_export(CLI::App& app, Run* run);
void add_model(CLI::App& app, Run* run);
void add_completion(CLI::App& app, Run* run);

// Prints "afford: <message>" to stderr and returns the exit status 2.
int usage_error(const std::string& message);

}  // namespace afford::cli
