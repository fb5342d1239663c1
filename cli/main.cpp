// afford: infer what an articulated hand tool is for, by simulating it.
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "did_you_mean.h"
#include "errors.h"

namespace afford::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> kCommands = {
      {"check", "check FILE...", "validate object, actee and agent files", run_check},
      {"describe", "describe FILE [--actees DIR] | describe --effects",
       "what the model derives from a file: lever, advantage, interaction space, fits",
       run_describe},
      {"gap", "gap MEASUREMENT [--json] [--effects a,b] [--write-patch DIR] [--probe]",
       "where a measured tool differs from its model, which effect explains it, how far the gap shrinks",
       run_gap},
      {"render", "render SESSION [--out DIR] [--fps N] [--size WxH] [--guides [FILE]] [--no-frames]",
       "render a session offscreen: PNG frames, contact sheet, timeline plot, MP4 with ffmpeg", run_render},
      {"guide", "guide FILE [--actees DIR] [--guides FILE] [--json]",
       "the four guides (symmetry, actee, emphasis, amplify/decline) as text or JSON", run_guide},
      {"rules", "rules --list | rules FILE", "the predicate vocabulary, or the function models of a file",
       run_rules},
      {"run", "run SESSION [--json] [--out DIR] [--record FILE] [--watch [--runs N]]",
       "simulate a session: inferred functions and why, timeline and trace files", run_run},
      {"live", "live SESSION --device DEV.yaml [--duration S] [--wait S] [--silence S] [--record FILE] [--out DIR]",
       "run a session in real time against a USB device: functions as they happen, force feedback", run_live},
      {"replay", "replay REC [--rules FILE] [--json] [--out DIR]",
       "re-run a recording: the recorded events bit for bit, or the timeline diff under edited rules",
       run_replay},
      {"schema", "schema KIND|--all [--out DIR]", "the JSON Schema of a kind of YAML file, for editors", run_schema},
      {"test", "test [DIR] [--coverage]",
       "run the rule test cases under DIR (default tests/rules): PASS/FAIL each, nodes reached", run_test},
  };
  return kCommands;
}

int usage_error(const std::string& message) {
  std::cerr << "afford: " << message << "\n";
  return 2;
}

namespace {

void print_help() {
  std::cout << "usage: afford COMMAND [ARGS]\n\ncommands:\n";
  for (const Command& c : commands()) {
    std::printf("  %-52s %s\n", c.usage, c.summary);
  }
}

}  // namespace
}  // namespace afford::cli

int main(int argc, char** argv) {
  using namespace afford::cli;
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    print_help();
    return argc < 2 ? 2 : 0;
  }
  const std::string name = argv[1];
  const Args args(argv + 2, argv + argc);
  std::vector<std::string> names;
  for (const Command& c : commands()) {
    names.emplace_back(c.name);
    if (name != c.name) continue;
    try {
      return c.run(args);
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
  return usage_error("unknown command '" + name + "'" + afford::did_you_mean(name, names) +
                     "; see afford --help");
}
