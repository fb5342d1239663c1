// afford completion bash: a bash completion script made from the command
// declarations themselves (the CLI11 app tree), so that it always offers
// the commands and options the program accepts. Values declared FILE
// complete to file names, DIR to folders, any other value to nothing.
#include <iostream>
#include <sstream>

#include "commands.h"
#include "option_checks.h"

namespace afford::cli {
namespace {

std::vector<const CLI::App*> all_commands(const CLI::App& app) {
  std::vector<const CLI::App*> out;
  for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; })) out.push_back(c);
  return out;
}

// The bash words that complete a value of this kind.
std::string value_completion(const CLI::Option& o) {
  if (o.get_type_name() == kFile) return "COMPREPLY=($(compgen -f -- \"$cur\"))";
  if (o.get_type_name() == kDir) return "COMPREPLY=($(compgen -d -- \"$cur\"))";
  return "COMPREPLY=()";
}

// One `case` branch of the script per command: its options, the values
// they take, and its positional arguments.
void print_command(std::ostream& out, const CLI::App& c) {
  std::string options;
  out << "    " << c.get_name() << ")\n      case \"$prev\" in\n";
  std::string positional = "COMPREPLY=()";
  for (const CLI::Option* o : c.get_options()) {
    if (o->get_positional()) {
      positional = value_completion(*o);
      continue;
    }
    for (const std::string& n : o->get_lnames()) options += " --" + n;
    for (const std::string& n : o->get_snames()) options += " -" + n;
    // An option with an optional value (render --guides) also completes.
    if (o->get_expected_max() == 0) continue;
    for (const std::string& n : o->get_lnames()) {
      out << "        --" << n << ") " << value_completion(*o) << "; return ;;\n";
    }
  }
  out << "      esac\n"
      << "      if [[ \"$cur\" == -* ]]; then\n"
      << "        COMPREPLY=($(compgen -W \"" << options.substr(1) << "\" -- \"$cur\"))\n"
      << "      else\n"
      << "        " << positional << "\n"
      << "      fi ;;\n";
}

void print_bash(const CLI::App& app) {
  std::ostringstream out;
  std::string commands;
  for (const CLI::App* c : all_commands(app)) commands += " " + c->get_name();
  out << "# bash completion for afford, made by `afford completion bash`.\n"
      << "# Install: afford completion bash > ~/.local/share/bash-completion/completions/afford\n"
      << "_afford() {\n"
      << "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
      << "  if [ \"$COMP_CWORD\" -eq 1 ]; then\n"
      << "    COMPREPLY=($(compgen -W \"" << commands.substr(1) << " --help --help-all --version\" -- \"$cur\"))\n"
      << "    return\n"
      << "  fi\n"
      << "  case \"${COMP_WORDS[1]}\" in\n";
  for (const CLI::App* c : all_commands(app)) print_command(out, *c);
  out << "  esac\n"
      << "}\n"
      << "complete -o filenames -F _afford afford\n";
  std::cout << out.str();
}

}  // namespace

void add_completion(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand("completion", "print a shell completion script for afford");
  auto shell = std::make_shared<std::string>();
  cmd->add_option("SHELL", *shell, "the shell: bash")->required()->check(CLI::IsMember({"bash"}));
  // The callback owns the option's storage: CLI11 writes into it after this returns.
  cmd->callback([run, &app, shell] {
    *run = [&app] {
      print_bash(app);
      return 0;
    };
  });
}

}  // namespace afford::cli
