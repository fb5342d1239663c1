// afford explore OBJECT [--actees DIR|FILE...] [--agent FILE] [--rules FILE]
//                [--taxonomy FILE] [--placements N] [--thumbs N] [--efforts N]
//                [--max-effort N] [--fixed-efforts] [--grasps a,b] [--tolerance N]
//                [--threads N] [--shard K/N] [--out DIR]
// afford explore --merge DIR... --out DIR
// One tool on every actee, placement, thumb position, grasp type and effort
// (explore/explore.h); prints the summary in words and writes the tables,
// explore.json and the maps (explore/reports.h). A shard writes only its
// explore.json; --merge joins the shards' into the files of a whole run.
// It says how many sessions it will run before it starts, and shows its
// progress on stderr (cli/progress.h). The output folder is checked before
// the work starts (engine/base/output_file.h), and cleared of the files an
// earlier explore wrote there and this one did not (an actee's old maps).
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "data_dir.h"
#include "effort_axes.h"
#include "explore_json.h"
#include "option_checks.h"
#include "output_file.h"
#include "parallel.h"
#include "progress.h"
#include "reports.h"

namespace afford::cli {
namespace {

namespace fs = std::filesystem;

struct ExploreOptions {
  std::string object, agent, rules, taxonomy, out_dir, shard, grasps;
  std::vector<std::string> actees, merge;
  GridOptions grid;
  int threads = 0;
  bool fixed_efforts = false;
  bool force = false;  // replace files afford did not write
};

// The points of a whole grid, each at most one session (explore skips
// those its thresholds already decide): every fitting actee's placements,
// thumbs, grasps and efforts.
long long grid_sessions(const GridInfo& g) {
  long long total = 0;
  for (const GridActee& a : g.actees) {
    if (!a.fits) continue;
    const size_t efforts = a.efforts.empty() ? g.efforts.size() : a.efforts.size();
    total += static_cast<long long>(a.placements.size() * g.thumbs.size() * g.grasps.size() * efforts);
  }
  return total;
}

// The files a run writes whatever the results, checked before the work:
// an input or a file afford did not write there is refused at once, not
// after hours.
void check_outputs_first(const std::string& dir, bool shard) {
  const fs::path d(dir);
  if (shard) {
    check_output((d / "explore.json").string());
    return;
  }
  for (const char* name : {"points.csv", "thresholds.csv", "summary.txt", "explore.json"}) {
    check_output((d / name).string());
  }
}

// Removes what an earlier explore wrote into the folder and this one did not.
void clear_stale(const std::string& dir) {
  clear_stale_outputs(dir);
  clear_stale_outputs((fs::path(dir) / "maps").string());
}

// "K/N" with 1 <= K <= N.
bool parse_shard(const std::string& text, Shard* shard) {
  int part = 0, count = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &part, &slash, &count, &extra) != 3 || slash != '/') return false;
  if (count < 1 || count > 100000 || part < 1 || part > count) return false;
  shard->part = part;
  shard->count = count;
  return true;
}

CLI::Validator shard_text() {
  return CLI::Validator(
      [](std::string& text) {
        Shard s;
        return parse_shard(text, &s) ? std::string() : "expected K/N with 1 <= K <= N, found '" + text + "'";
      },
      "");
}

// Every .yaml of a folder (sorted), or the file itself.
std::vector<std::string> actee_files(const std::vector<std::string>& given) {
  std::vector<std::string> files;
  for (const std::string& g : given.empty() ? std::vector<std::string>{shipped_path("actees")} : given) {
    if (!fs::is_directory(g)) {
      files.push_back(g);  // a file; load_actee says what is wrong with it
      continue;
    }
    std::vector<std::string> in_dir;
    for (const auto& entry : fs::directory_iterator(g)) {
      if (entry.path().extension() == ".yaml") in_dir.push_back(entry.path().string());
    }
    if (in_dir.empty()) throw std::runtime_error("--actees " + g + ": no .yaml file in the folder");
    std::sort(in_dir.begin(), in_dir.end());
    files.insert(files.end(), in_dir.begin(), in_dir.end());
  }
  return files;
}

std::vector<std::string> split_commas(const std::string& list) {
  std::vector<std::string> out;
  if (list.empty()) return out;
  size_t start = 0;
  for (size_t comma; (comma = list.find(',', start)) != std::string::npos; start = comma + 1) {
    out.push_back(list.substr(start, comma - start));
  }
  out.push_back(list.substr(start));
  return out;
}

void print_written(const std::vector<std::string>& written) {
  std::cout << "wrote";
  for (const std::string& w : written) std::cout << " " << w;
  std::cout << "\n";
}

int merge_shards(const ExploreOptions& o) {
  if (!o.object.empty()) return usage_error("explore --merge takes the shards' folders, not an OBJECT");
  if (o.out_dir.empty()) return usage_error("explore --merge needs --out DIR for the joined files");
  std::vector<std::string> inputs;
  for (const std::string& dir : o.merge) inputs.push_back((fs::path(dir) / "explore.json").string());
  const OutputScope scope({.writer = "explore", .force = o.force, .inputs = inputs});
  check_outputs_first(o.out_dir, false);
  GridInfo grid;
  std::vector<ExploreResult> parts;
  for (const std::string& dir : o.merge) {
    const std::string file = (fs::path(dir) / "explore.json").string();
    GridInfo g;
    ExploreResult r;
    read_explore_json(file, &g, &r);
    if (parts.empty()) {
      grid = g;
    } else if (!(g == grid)) {
      throw std::runtime_error(file + ": a shard of another grid than " + o.merge.front());
    }
    parts.push_back(std::move(r));
  }
  const ExploreResult whole = merge(grid, std::move(parts));
  const std::vector<std::string> written = write_explore(o.out_dir, grid, whole);
  clear_stale(o.out_dir);
  std::cout << summary_text(grid, whole);
  print_written(written);
  return 0;
}

int explore_command(const ExploreOptions& o) {
  if (!o.merge.empty()) return merge_shards(o);
  if (o.object.empty()) return usage_error("explore needs an OBJECT (or --merge DIR...)");
  ExploreFiles files;
  files.object = o.object;
  files.agent = o.agent.empty() ? shipped_path("agents/hand.yaml") : o.agent;
  files.rules = o.rules.empty() ? shipped_path("rules/functions.yaml") : o.rules;
  files.grasps = o.taxonomy.empty() ? shipped_path("rules/grasps.yaml") : o.taxonomy;
  files.actees = actee_files(o.actees);
  GridOptions grid = o.grid;
  grid.grasps = split_commas(o.grasps);
  grid.scale_efforts = !o.fixed_efforts;
  Shard shard;
  if (!o.shard.empty()) parse_shard(o.shard, &shard);  // checked by its validator
  std::vector<std::string> inputs = {files.object, files.agent, files.rules, files.grasps};
  inputs.insert(inputs.end(), files.actees.begin(), files.actees.end());
  const OutputScope scope({.writer = "explore", .force = o.force, .inputs = inputs});

  Explorer e;
  try {
    e = make_explorer(files, grid);
  } catch (const GridError& error) {
    return usage_error(std::string("explore: ") + error.what());
  }
  const int threads = o.threads > 0 ? o.threads : default_threads();
  std::string dir = o.out_dir;
  if (dir.empty()) {
    dir = "out/explore-" + e.grid.object;
    if (!shard.whole()) dir += "-shard-" + std::to_string(shard.part) + "-of-" + std::to_string(shard.count);
  }
  check_outputs_first(dir, !shard.whole());
  const long long sessions = grid_sessions(e.grid);
  std::cerr << "explore: " << sessions << " grid points, each at most one session"
            << (shard.whole() ? "" : " in the whole grid (this shard runs about 1/" + std::to_string(shard.count) + ")")
            << " on " << threads << (threads == 1 ? " thread" : " threads") << "; progress on stderr\n";
  if (grid.scale_efforts) {
    TerminalProgress progress("scouting session");  // the common axis, to find where each actee turns
    fit_effort_axes(e, threads, [&](size_t done, size_t total) {
      progress.update(static_cast<long long>(done), static_cast<long long>(total));
    });
  }
  ExploreResult result;
  {
    TerminalProgress progress("session");
    result = explore(e, shard, threads,
                     [&](size_t done, size_t total) { progress.update(static_cast<long long>(done), static_cast<long long>(total)); });
  }
  if (!shard.whole()) {
    fs::create_directories(dir);
    const std::string file = (fs::path(dir) / "explore.json").string();
    write_file_checked(file, explore_json(e.grid, result));
    clear_stale(dir);
    std::cout << "shard " << shard.part << "/" << shard.count << ": " << result.series.size()
              << " series; join the shards with afford explore --merge DIR... --out DIR\n";
    print_written({file});
    return 0;
  }
  const std::vector<std::string> written = write_explore(dir, e.grid, result);
  clear_stale(dir);
  std::cout << summary_text(e.grid, result);
  print_written(written);
  return 0;
}

}  // namespace

void add_explore(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "explore", "try a tool on every actee, placement, thumb, grasp and effort: what it can do, and the thresholds");
  auto o = std::make_shared<ExploreOptions>();
  cmd->add_option("OBJECT", o->object, "the tool's object file")->type_name(kFile);
  cmd->add_option("--actees", o->actees, "actee files or folders of them (default: the shipped actees)")
      ->type_name("DIR|FILE")
      ->expected(1, -1);
  cmd->add_option("--agent", o->agent, "the hand (default: the shipped agents/hand.yaml)")->type_name(kFile);
  cmd->add_option("--rules", o->rules, "the function models (default: the shipped rules/functions.yaml)")
      ->type_name(kFile);
  cmd->add_option("--taxonomy", o->taxonomy, "the grasp taxonomy (default: the shipped rules/grasps.yaml)")
      ->type_name(kFile);
  cmd->add_option("--placements", o->grid.placements, "placements per actee, over where it fits (default 3)")
      ->check(CLI::Range(1, kMaxPerAxis));
  cmd->add_option("--thumbs", o->grid.thumbs, "thumb positions over the emphasis region (default 3)")
      ->check(CLI::Range(1, kMaxPerAxis));
  cmd->add_option("--efforts", o->grid.efforts, "efforts from 0 N up to --max-effort (default 9)")
      ->check(CLI::Range(1, kMaxPerAxis));
  cmd->add_option("--max-effort", o->grid.max_effort, "the largest effort, the common axis's top, N (default: the hand's limit)")
      ->type_name("N")
      ->check(CLI::Range(1e-3, 1e6));
  cmd->add_flag("--fixed-efforts", o->fixed_efforts,
                "every actee on the efforts 0 N to --max-effort, not on its own axis scaled to where it turns");
  cmd->add_option("--grasps", o->grasps, "grasp types tried, comma-separated (default: every type)")
      ->type_name("NAME,...");
  cmd->add_option("--tolerance", o->grid.tolerance, "the thresholds' tolerance, N (default 0.5)")
      ->type_name("N")
      ->check(CLI::Range(1e-3, 100.0));
  cmd->add_option("--threads", o->threads, "worker threads (default: every core)")->check(CLI::Range(1, 1024));
  cmd->add_option("--shard", o->shard, "run the K-th of N disjoint parts (write only DIR/explore.json)")
      ->type_name("K/N")
      ->check(shard_text());
  cmd->add_option("--merge", o->merge, "join the shards' output folders into the files of a whole run")
      ->type_name(kDir)
      ->expected(1, -1);
  cmd->add_option("--out", o->out_dir, "the output folder (default out/explore-OBJECT)")->type_name(kDir);
  cmd->add_flag("--force", o->force, "replace existing files in the output folder that afford did not write");
  cmd->callback([run, o] { *run = [o] { return explore_command(*o); }; });
}

}  // namespace afford::cli
