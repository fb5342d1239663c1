// afford: infer what an articulated hand tool is for, by simulating it.
// The command line is declared with CLI11 (commands.h); this file maps its
// outcomes to the exit statuses: 0 ok, 1 bad data, 2 bad usage, 3 internal.
#include <iostream>

#include "commands.h"
#include "did_you_mean.h"
#include "errors.h"

#ifndef AFFORD_VERSION
#error "AFFORD_VERSION comes from the project version (cli/CMakeLists.txt)"
#endif

namespace afford::cli {

int usage_error(const std::string& message) {
  std::cerr << "afford: " << message << "\n";
  return 2;
}

namespace {

// Help lines "--runs N", "--silence S=2", "--guides [FILE]": the value's
// kind and default; what is allowed is said by the option's description.
class Formatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* o) const override {
    if (o->get_expected_max() == 0) return "";
    std::string out = o->get_expected_min() == 0 ? " [" + o->get_type_name() + "]" : " " + o->get_type_name();
    if (!o->get_default_str().empty()) out += "=" + o->get_default_str();
    if (o->get_required()) out += " (required)";
    return out;
  }
};

// The long names of an app's options ("--json") or its commands.
std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  }
  return names;
}

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(c->get_name());
  return names;
}

// What the declarations left over: an unknown option, or one argument
// too many. `where` is "" for the top level, else "COMMAND: ".
int leftover_error(const CLI::App& app, const std::string& where, const std::string& word) {
  if (word.starts_with("-")) {
    return usage_error(where + "unknown option '" + word + "'" + did_you_mean(word, option_names(app)) +
                       "; see afford " + (where.empty() ? "" : app.get_name() + " ") + "--help");
  }
  if (where.empty()) {
    return usage_error("unknown command '" + word + "'" + did_you_mean(word, command_names(app)) +
                       "; see afford --help");
  }
  return usage_error(where + "unexpected argument '" + word + "'; see afford " + app.get_name() + " --help");
}

int run_program(int argc, char** argv) {
  CLI::App app{"afford: infer what an articulated hand tool is for, by simulating it", "afford"};
  app.formatter(std::make_shared<Formatter>());  // before the commands: they inherit it
  app.get_formatter()->column_width(26);
  app.set_version_flag("--version", "afford " AFFORD_VERSION);
  app.set_help_all_flag("--help-all", "Print the help of every command");
  app.footer("Run 'afford COMMAND --help' for the options of a command.");
  app.require_subcommand(0, 1);  // one command; a later word is its argument
  app.allow_extras();            // unknown words get our own message below
  Run run;
  for (auto add : {add_check, add_describe, add_explore, add_gap, add_render, add_guide, add_rules, add_run, add_live,
                   add_serve, add_view, add_replay, add_schema, add_test, add_export, add_model, add_completion}) {
    add(app, &run);
  }
  for (CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; })) c->allow_extras();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const std::vector<CLI::App*> chosen = app.get_subcommands();
    if (chosen.empty()) return usage_error(std::string(e.what()) + "; see afford --help");
    const std::string name = chosen.front()->get_name();
    return usage_error(name + ": " + e.what() + "; see afford " + name + " --help");
  }
  if (!app.remaining().empty()) return leftover_error(app, "", app.remaining().front());
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  if (chosen.empty()) {
    std::cout << app.help();
    return 2;
  }
  CLI::App& command = *chosen.front();
  if (!command.remaining().empty()) {
    return leftover_error(command, command.get_name() + ": ", command.remaining().front());
  }
  return run();
}

}  // namespace
}  // namespace afford::cli

int main(int argc, char** argv) {
  try {
    return afford::cli::run_program(argc, argv);
  } catch (const afford::DataError& e) {
    std::cerr << e.what() << "\n";
    return 1;
  } catch (const afford::LogicError& e) {
    std::cerr << "afford: internal error (please report): " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "afford: " << e.what() << "\n";
    return 1;
  }
}
