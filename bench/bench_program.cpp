// The whole program as a user runs it: `afford run sessions/paper-tongs.yaml
// --out DIR` in a child process, start-up, loading, the 7000 frames and the
// trace and timeline files included (goal: under 25 ms). `afford --version`
// is the start-up alone.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_source.h"

extern char** environ;

namespace {

using afford::bench::kSource;
const std::string kProgram = AFFORD_PROGRAM;

// Runs the program with args, its output thrown away; the exit status.
int run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(kProgram.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, kProgram.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + kProgram);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void BM_ProgramRun(benchmark::State& bs) {
  const std::string out = (std::filesystem::temp_directory_path() / "afford-bench-run").string();
  const std::vector<std::string> args = {"run", kSource + "/sessions/paper-tongs.yaml", "--out", out};
  for (auto _ : bs) {
    if (run_program(args) != 0) bs.SkipWithError("afford run failed");
  }
  std::filesystem::remove_all(out);
}
BENCHMARK(BM_ProgramRun)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ProgramStart(benchmark::State& bs) {
  for (auto _ : bs) {
    if (run_program({"--version"}) != 0) bs.SkipWithError("afford --version failed");
  }
}
BENCHMARK(BM_ProgramStart)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
