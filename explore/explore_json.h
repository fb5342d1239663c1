// explore.json: a grid and its results (reports.h), as written by a whole
// run or by one shard, and read back by `afford explore --merge`. Numbers
// are written exactly (the shortest text that reads back as the same
// double), so a merge reproduces every other file byte for byte.
#pragma once

#include <string>

#include "results.h"

namespace afford {

std::string explore_json(const GridInfo& g, const ExploreResult& r);

// Reads a file explore_json() wrote. Throws std::runtime_error naming the
// file and, for bad JSON, the line and column; for a file of another shape
// or with indices outside its grid, what is wrong.
void read_explore_json(const std::string& path, GridInfo* g, ExploreResult* r);
// The same from the file's text; `name` stands for the file in errors.
void parse_explore_json(const std::string& text, const std::string& name, GridInfo* g, ExploreResult* r);

}  // namespace afford
