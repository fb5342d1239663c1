#include "data_dir.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace afford {

namespace fs = std::filesystem;

namespace {

// The folders every shipped data folder holds.
constexpr const char* kShippedFolders[] = {"rules", "agents", "actees", "objects"};
constexpr const char* kShippedList = "rules/, agents/, actees/, objects/";

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

// Resolved, for comparing a program's path with its build tree.
fs::path canonical_or_same(const fs::path& p) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(p, ec);
  return ec ? p : c;
}

// True when `path` lies inside folder `dir`.
bool inside(const fs::path& path, const fs::path& dir) {
  const fs::path rel = canonical_or_same(path).lexically_relative(canonical_or_same(dir));
  return !rel.empty() && *rel.begin() != "..";
}

// The running program's path (Linux); empty if unknown.
std::string running_program() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : p.string();
}

}  // namespace

bool holds_shipped_data(const std::string& dir) {
  for (const char* folder : kShippedFolders) {
    if (!is_dir(fs::path(dir) / folder)) return false;
  }
  return true;
}

std::string find_data_dir(const DataDirSearch& s) {
  if (s.env) {
    // Asked for by name: a wrong folder is an error, never passed over.
    if (holds_shipped_data(*s.env)) return *s.env;
    throw std::runtime_error("AFFORD_DATA_DIR=" + *s.env + ": expected a folder holding afford's shipped data (" +
                             kShippedList + "), found " + (is_dir(*s.env) ? "a folder without them" : "no folder"));
  }
  std::string looked = "AFFORD_DATA_DIR (not set)";
  const bool in_build_tree = !s.program.empty() && !s.build_dir.empty() && inside(s.program, s.build_dir);
  if (in_build_tree && holds_shipped_data(s.source_dir)) return s.source_dir;
  looked += in_build_tree ? ", " + s.source_dir + " (the source tree)"
                          : ", not the source tree (the program is not in its build tree " + s.build_dir + ")";
  if (!s.program.empty()) {
    const std::string beside =
        (fs::path(s.program).parent_path() / s.program_to_data).lexically_normal().string();
    if (holds_shipped_data(beside)) return beside;
    looked += ", " + beside + " (beside the program)";
  }
  if (holds_shipped_data(s.installed_dir)) return s.installed_dir;
  looked += ", " + s.installed_dir + " (installed)";
  throw std::runtime_error(std::string("expected afford's shipped data (") + kShippedList +
                           "), found none; looked in " + looked + ". Set AFFORD_DATA_DIR to the folder that holds them");
}

std::string data_dir() {
  DataDirSearch s;
  if (const char* env = std::getenv("AFFORD_DATA_DIR")) s.env = env;
  s.program = running_program();
  // Compiled in by engine/CMakeLists.txt.
  s.build_dir = AFFORD_BUILD_TREE;
  s.source_dir = AFFORD_SOURCE_TREE;
  s.program_to_data = AFFORD_PROGRAM_TO_DATA;
  s.installed_dir = AFFORD_INSTALLED_DATA;
  return find_data_dir(s);
}

std::string shipped_path(std::string_view relative) {
  return (fs::path(data_dir()) / relative).string();
}

}  // namespace afford
