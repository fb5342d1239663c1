// Rule test cases: read, load, run with a progress observer, judge (see
// rule_tests.h).
#include "rule_tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <unistd.h>

#include "did_you_mean.h"
#include "load.h"
#include "closest_approach.h"
#include "rules_impl.h"
#include "run.h"
#include "units.h"
#include "validate.h"

namespace afford {
namespace {

namespace fs = std::filesystem;

// A session given in place: a session file's keys but the camera (nothing
// is rendered), its name and description optional and its rules optional
// when the case gives them.
const MapSchema& session_in_place_schema() {
  static const MapSchema kInPlace = [] {
    MapSchema m{"the session's keys in place (rules may come from the case instead)"};
    for (const KeySchema& k : session_schema().keys) {
      if (k.key == "camera") continue;
      m.keys.push_back(k);
      if (k.key == "session" || k.key == "description" || k.key == "rules") m.keys.back().required = false;
    }
    return m;
  }();
  return kInPlace;
}

// The same when the case gives no rules: the session must.
const MapSchema& session_in_place_with_rules_schema() {
  static const MapSchema kWithRules = [] {
    MapSchema m = session_in_place_schema();
    for (KeySchema& k : m.keys) k.required = k.required || k.key == "rules";
    return m;
  }();
  return kWithRules;
}

const MapSchema& expected_function_schema() {
  using namespace schema;
  static const MapSchema kExpected{
      "a function expected, in a time window and a number of times",
      {required_key("function", name(), "the function's name"),
       optional_key("within", sequence(quantity(dim::time), 2, 2), "the window [from, to] it must happen in"),
       optional_key("times", integer(), "how many times it must be inferred, 0 or more")}};
  return kExpected;
}

const MapSchema& rejected_function_schema() {
  using namespace schema;
  static const MapSchema kRejected{
      "a function that must not be inferred, in a time window",
      {required_key("function", name(), "the function's name"),
       optional_key("within", sequence(quantity(dim::time), 2, 2), "the window [from, to] it must not happen in")}};
  return kRejected;
}


std::string window_text(const TimeWindow& w) {
  return "[" + format_quantity(w.from, dim::time) + ", " + format_quantity(w.to, dim::time) + "]";
}

// ------------------------------------------------------------ reading

TimeWindow read_window(const Node& node) {
  if (!node.is_sequence() || node.size() != 2) node.fail("a window [from, to] of two times");
  TimeWindow w;
  w.from = read_quantity(node[0], dim::time);
  w.to = read_quantity(node[1], dim::time);
  if (w.from < 0) node[0].fail("a time of 0 s or more");
  if (w.to < w.from) node[1].fail("a time not before " + format_quantity(w.from, dim::time));
  return w;
}

Node non_empty_sequence(const Node& node, const std::string& what) {
  if (!node.is_sequence() || node.size() == 0) node.fail("a sequence of " + what);
  return node;
}

void read_expect(const Node& list, std::vector<CaseExpectation>* out) {
  non_empty_sequence(list, "functions expected: a name, or {function, within, times}");
  for (size_t i = 0; i < list.size(); ++i) {
    const Node item = list[i];
    CaseExpectation e;
    if (item.is_scalar()) {
      e.function = read_name(item);
      e.loc = item.loc();
    } else {
      MapReader m(item, "an expected function", expected_function_schema());
      const Node name = m.required("function");
      e.function = read_name(name);
      e.loc = name.loc();
      if (std::optional<Node> w = m.optional("within")) e.within = read_window(*w);
      if (std::optional<Node> n = m.optional("times")) {
        e.times = read_int(*n);
        if (e.times < 0) n->fail("a count of 0 or more");
      }
    }
    out->push_back(std::move(e));
  }
}

void read_reject(const Node& list, std::vector<CaseRejection>* out) {
  non_empty_sequence(list, "functions rejected: a name, or {function, within}");
  for (size_t i = 0; i < list.size(); ++i) {
    const Node item = list[i];
    CaseRejection r;
    if (item.is_scalar()) {
      r.function = read_name(item);
      r.loc = item.loc();
    } else {
      MapReader m(item, "a rejected function", rejected_function_schema());
      const Node name = m.required("function");
      r.function = read_name(name);
      r.loc = name.loc();
      if (std::optional<Node> w = m.optional("within")) r.within = read_window(*w);
    }
    out->push_back(std::move(r));
  }
}

// A session given in place: its keys checked here, where a missing one can
// still be reported at the mapping (read_session sees a copy, below).
void check_inline_session(const Node& node, bool case_has_rules) {
  MapReader m(node, "the session in place", session_in_place_schema());
  for (const char* key : {"object", "agent", "grasps", "script"}) m.required(key);
  if (!m.has("rules") && !case_has_rules) {
    node.fail("key 'rules' in the session in place (or in the case)", "no such key");
  }
  // read_session reads the values; `session` and `description` too, when given.
  if (std::optional<Node> name = m.optional("session")) read_name(*name);
  if (std::optional<Node> d = m.optional("description")) read_string(*d);
}

// The path a case's key names, relative to the case's folder, checked to
// be a readable file (reported at the key).
std::string resolve(const RuleCase& c, const SourceLoc& key, const Node& value) {
  const std::string given = read_string(value);
  if (given.empty()) value.fail("a path to a file");
  fs::path p(given);
  if (p.is_relative()) p = fs::path(c.file).parent_path() / p;
  const std::string path = p.lexically_normal().string();
  const std::string expected =
      "a readable file '" + given + "'" + (fs::path(given).is_relative() ? " (relative to the case's folder)" : "");
  std::error_code ec;
  if (fs::is_directory(path, ec)) fail(key, expected, "a directory");
  if (!fs::is_regular_file(path, ec) || ::access(path.c_str(), R_OK) != 0) fail(key, expected, "none");
  return path;
}

// The session in place as a session document: `session` first (the
// case's name if not given), `description` (the note, or the name), the
// case's `rules` if the session has none, then the session's own keys.
// The values, and the keys given, are the case file's own nodes, so that
// read_session reports a mistake at its place in the case file.
Node inline_session_document(const RuleCase& c) {
  const Node& given = *c.session;
  const YAML::Node& in = given.yaml();
  YAML::Node doc(YAML::NodeType::Map);
  auto copy = [&](const std::string& key) {
    for (auto it = in.begin(); it != in.end(); ++it) {
      if (it->first.Scalar() == key) doc.force_insert(it->first, it->second);
    }
  };
  auto has = [&](const std::string& key) {
    for (auto it = in.begin(); it != in.end(); ++it) {
      if (it->first.Scalar() == key) return true;
    }
    return false;
  };
  if (has("session")) {
    copy("session");
  } else {
    doc.force_insert(YAML::Node("session"), YAML::Node(c.name));
  }
  if (has("description")) {
    copy("description");
  } else {
    doc.force_insert(YAML::Node("description"), YAML::Node(c.note.empty() ? c.name : c.note));
  }
  if (!has("rules") && c.rules) doc.force_insert(YAML::Node("rules"), c.rules->yaml());
  for (auto it = in.begin(); it != in.end(); ++it) {
    const std::string& key = it->first.Scalar();
    if (key != "session" && key != "description") doc.force_insert(it->first, it->second);
  }
  return given.child(doc);
}

// ------------------------------------------------------------ judging

std::string explain(const Inference& inf) {
  std::string s;
  for (const NodeExplanation& n : inf.nodes) s += (s.empty() ? "" : ", ") + n.text + " at " + format_seconds(n.t);
  return s;
}

bool in_window(double t, const std::optional<TimeWindow>& w) {
  return !w || (t >= w->from - 1e-9 && t <= w->to + 1e-9);
}

// How far an inference lies from a window (0 inside it).
double distance(double t, const std::optional<TimeWindow>& w) {
  if (!w) return 0;
  return t < w->from ? w->from - t : (t > w->to ? t - w->to : 0.0);
}

// "pinch at 1.181 s, 3.100 s; nearest at 1.181 s because ..." (all not empty).
std::string inferred_text(const std::string& function, const std::vector<const Inference*>& all,
                          const std::optional<TimeWindow>& window) {
  std::string s = function + " at ";
  const Inference* nearest = all.front();
  for (size_t i = 0; i < all.size(); ++i) {
    s += (i ? ", " : "") + format_seconds(all[i]->t);
    if (distance(all[i]->t, window) < distance(nearest->t, window)) nearest = all[i];
  }
  return s + (all.size() > 1 ? "; nearest at " + format_seconds(nearest->t) : std::string()) + " because " + explain(*nearest);
}

std::string times_text(int n) { return n == 1 ? "once" : (n == 2 ? "twice" : std::to_string(n) + " times"); }

}  // namespace

// ------------------------------------------------------------ reading

const MapSchema& rule_test_schema() {
  using namespace schema;
  static const MapSchema kCase = [] {
    MapSchema m{
        "a rule test case: a session and the functions it must infer (tests/rules/README.md)",
        {required_key("test", name(), "the case's name"),
         optional_key("note", text(), "why the case exists, in a sentence"),
         required_key("session", any_of({path(), mapping(session_in_place_schema())}),
                      "the session file, or the session's keys in place"),
         optional_key("rules", path(), "a function-model file used instead of the session's"),
         optional_key("expect", sequence(any_of({name(), mapping(expected_function_schema())}), 1),
                      "functions that must be inferred"),
         optional_key("reject", sequence(any_of({name(), mapping(rejected_function_schema())}), 1),
                      "functions that must not be inferred"),
         optional_key("error", text(), "a text the error of loading the files must contain")}};
    m.stricter_without.push_back(
        {"rules", "session", any_of({path(), mapping(session_in_place_with_rules_schema())})});
    return m;
  }();
  return kCase;
}

RuleCase read_rule_case(const Node& root) {
  const std::string kind = file_kind(root);
  if (kind != "test") {
    root.child(root.yaml().begin()->first).fail("a rule test case (its first key 'test')", "'" + kind + "'");
  }
  MapReader m(root, "a rule test case", rule_test_schema());
  RuleCase c;
  c.file = root.loc().file;
  const Node name = m.required("test");
  c.name = read_name(name);
  c.loc = name.loc();
  if (std::optional<Node> note = m.optional("note")) c.note = read_string(*note);
  c.session = m.required("session");
  c.session_key = key_node(root, "session").loc();
  if (std::optional<Node> rules = m.optional("rules")) {
    if (!rules->is_scalar()) rules->fail("a path to a function-model file");
    c.rules = *rules;
    c.rules_key = key_node(root, "rules").loc();
  }
  if (c.session->is_map()) {
    check_inline_session(*c.session, c.rules.has_value());
  } else if (!c.session->is_scalar()) {
    c.session->fail("a path to a session file, or the session's keys as a mapping");
  }
  if (std::optional<Node> e = m.optional("expect")) read_expect(*e, &c.expect);
  if (std::optional<Node> r = m.optional("reject")) read_reject(*r, &c.reject);
  if (std::optional<Node> e = m.optional("error")) {
    if (m.has("expect") || m.has("reject")) {
      key_node(root, "error").fail("either 'error' (the files must fail to load) or 'expect' and 'reject'", "both");
    }
    c.error = read_string(*e);
    if (c.error->empty()) e->fail("a text that the error message must contain");
  }
  if (!m.has("expect") && !m.has("reject") && !m.has("error")) {
    root.fail("key 'expect', 'reject' or 'error' in a rule test case", "none of them");
  }
  return c;
}

RuleCase load_rule_case(const std::string& path) { return read_rule_case(load_yaml_file(path)); }

CompiledSession compile_rule_case(const RuleCase& c) {
  if (!c.session) throw LogicError("compile_rule_case: a case without its session");
  CompiledSession session;
  bool rules_inserted = false;
  if (c.session->is_scalar()) {
    session = load_session(resolve(c, c.session_key, *c.session));
  } else {
    rules_inserted = c.rules && !MapReader(*c.session, "the session in place", session_in_place_schema()).has("rules");
    session = read_session(inline_session_document(c));
  }
  if (c.rules && !rules_inserted) {
    const std::string path = resolve(c, c.rules_key, *c.rules);
    session.rules = load_rules(path);
    session.files.push_back(path);
  }
  return session;
}

// ------------------------------------------------------------ running

CaseRun run_case_session(const CompiledSession& session, const AgentFactory& agent) {
  std::unique_ptr<SampleSource> source = agent(session.script);
  if (!source) throw LogicError("run_case_session: the agent factory gave no source");
  ProgressObserver progress;
  Observer* const observers[] = {&progress};
  RunResult result = run_session(session, *session.rules, *source, observers);
  CaseRun run;
  run.inferences = std::move(result.inferences);
  run.progress = progress.progress();
  run.coverage = progress.coverage();
  run.end_time = result.end_time;
  return run;
}

std::vector<std::string> judge_rule_case(const RuleCase& c, const CaseRun& run) {
  std::vector<std::string> names;
  for (const FunctionProgress& p : run.progress) names.push_back(p.function);
  auto find = [&](const std::string& function, const SourceLoc& loc, std::string* unknown) -> const FunctionProgress* {
    for (const FunctionProgress& p : run.progress) {
      if (p.function == function) return &p;
    }
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    *unknown = loc.str() + ": expected a function of " + (run.coverage.file.empty() ? "the rules" : run.coverage.file) +
               " (" + list + "), found '" + function + "'" + did_you_mean(function, names);
    return nullptr;
  };
  auto inferred = [&](const std::string& function) {
    std::vector<const Inference*> out;
    for (const Inference& inf : run.inferences) {
      if (inf.function == function) out.push_back(&inf);
    }
    return out;
  };

  std::vector<std::string> failures;
  for (const CaseExpectation& e : c.expect) {
    std::string unknown;
    const FunctionProgress* p = find(e.function, e.loc, &unknown);
    if (p == nullptr) {
      failures.push_back(unknown);
      continue;
    }
    const std::vector<const Inference*> all = inferred(e.function);
    const auto count = std::count_if(all.begin(), all.end(), [&](const Inference* i) { return in_window(i->t, e.within); });
    const bool ok = e.times < 0 ? count > 0 : count == e.times;
    if (ok) continue;
    std::string want = "expected " + e.function;
    if (e.times >= 0) want += " " + times_text(e.times);
    if (e.within) want += " within " + window_text(*e.within);
    std::string got;
    if (all.empty()) {
      got = "got none: " + progress_text(*p);
    } else if (e.times >= 0) {
      got = "got it " + (count == 0 ? std::string("no time") : times_text(static_cast<int>(count))) +
            (e.within ? " there" : "") + ": " + inferred_text(e.function, all, e.within);
    } else {
      got = "got " + inferred_text(e.function, all, e.within);
    }
    failures.push_back(want + ", " + got);
  }
  for (const CaseRejection& r : c.reject) {
    std::string unknown;
    if (find(r.function, r.loc, &unknown) == nullptr) {
      failures.push_back(unknown);
      continue;
    }
    std::vector<const Inference*> hits;
    for (const Inference* i : inferred(r.function)) {
      if (in_window(i->t, r.within)) hits.push_back(i);
    }
    if (hits.empty()) continue;
    std::string s = "expected no " + r.function + (r.within ? " within " + window_text(*r.within) : "") + ", got " +
                    r.function + " at ";
    for (size_t i = 0; i < hits.size(); ++i) s += (i ? ", " : "") + format_seconds(hits[i]->t);
    failures.push_back(s + " because " + explain(*hits.front()));
  }
  return failures;
}

std::string RuleCaseResult::reason() const {
  std::string s;
  for (const std::string& f : failures) s += (s.empty() ? "" : "; ") + f;
  return s;
}

RuleCaseResult run_rule_case(const RuleCase& c, const AgentFactory& agent) {
  RuleCaseResult r;
  r.file = c.file;
  r.name = c.name;
  std::optional<CompiledSession> session;
  try {
    session.emplace(compile_rule_case(c));
  } catch (const DataError& e) {
    const std::string message = e.what();
    if (!c.error) {
      r.failures.push_back("the files did not load: " + message);
    } else if (message.find(*c.error) == std::string::npos) {
      r.failures.push_back("expected the files to fail to load with \"" + *c.error + "\", got: " + message);
    }
    r.passed = r.failures.empty();
    return r;
  }
  if (c.error) {
    r.failures.push_back("expected the files to fail to load with \"" + *c.error + "\", but they loaded");
    return r;
  }
  CaseRun run = run_case_session(*session, agent);
  r.failures = judge_rule_case(c, run);
  r.coverage = std::move(run.coverage);
  r.simulated = run.end_time;
  r.passed = r.failures.empty();
  return r;
}

RuleCaseResult run_rule_case(const std::string& path, const AgentFactory& agent) {
  RuleCase c;
  try {
    c = load_rule_case(path);
  } catch (const DataError& e) {
    RuleCaseResult r;
    r.file = path;
    r.name = fs::path(path).stem().string();
    r.failures.push_back(e.what());
    return r;
  }
  return run_rule_case(c, agent);
}

void merge_coverage(std::vector<RulesCoverage>* total, const RulesCoverage& run) {
  auto key = [](const std::string& file) {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(file, ec);
    return ec ? fs::path(file).lexically_normal().string() : p.string();
  };
  const std::string k = key(run.file);
  RulesCoverage* into = nullptr;
  for (RulesCoverage& t : *total) {
    if (key(t.file) == k) into = &t;
  }
  if (into == nullptr) {
    total->push_back(run);
    return;
  }
  for (const FunctionCoverage& f : run.functions) {
    FunctionCoverage* g = nullptr;
    for (FunctionCoverage& h : into->functions) {
      if (h.name == f.name) g = &h;
    }
    if (g == nullptr) {
      into->functions.push_back(f);
      continue;
    }
    for (size_t i = 0; i < f.nodes.size(); ++i) {
      if (i < g->nodes.size()) {
        g->nodes[i].reached = g->nodes[i].reached || f.nodes[i].reached;
      } else {
        g->nodes.push_back(f.nodes[i]);
      }
    }
  }
}

void add_rule_test_file_kind() {
  add_file_kind("test", [](const Node& root) {
    const RuleCase c = read_rule_case(root);
    if (!c.error) compile_rule_case(c);
    return "rule test " + c.name;
  });
}

}  // namespace afford
