#include "measurement.h"

#include <cmath>

#include "data_files.h"
#include "load.h"
#include "trace_table.h"
#include "units.h"

namespace afford {
namespace {

// Fewer rows than this leave nothing to judge a fit on.
constexpr size_t kMinRows = 50;

Dimension dimension_of(Signal s) {
  switch (s) {
    case Signal::t: return dim::time;
    case Signal::angle: return dim::angle;
    case Signal::effort_force:
    case Signal::actee_force:
    case Signal::force: return dim::force;
    case Signal::displacement: return dim::length;
    case Signal::broken: return dim::none;
  }
  return dim::none;
}

// `format: {skip, separator, columns: {signal: {column, unit}}}`.
TableFormat read_format(const Node& node, Rig rig) {
  MapReader m(node, "the trace format", {"skip", "footer", "separator", "columns"});
  TableFormat f;
  f.loc = node.loc();
  if (std::optional<Node> skip = m.optional("skip")) {
    f.skip = read_int(*skip);
    if (f.skip < 0 || f.skip > 10000) skip->fail("a number of lines from 0 to 10000");
  }
  if (std::optional<Node> footer = m.optional("footer")) {
    f.footer = read_int(*footer);
    if (f.footer < 0 || f.footer > 10000) footer->fail("a number of lines from 0 to 10000");
  }
  if (std::optional<Node> sep = m.optional("separator")) {
    const std::string s = read_choice(*sep, {"comma", "tab", "blanks"});
    f.separator = s == "comma" ? ',' : (s == "tab" ? '\t' : ' ');
  }
  std::vector<std::string> names;
  for (int i = 0; i < kSignals; ++i) names.emplace_back(signal_name(static_cast<Signal>(i)));
  const Node columns = m.required("columns");
  MapReader cols(columns, "the columns", names);
  for (const auto& [name, value] : cols.entries()) {
    int s = 0;
    while (names[static_cast<size_t>(s)] != name) ++s;
    MapReader c(value, "the column of " + name, {"column", "unit"});
    f.column[static_cast<size_t>(s)] = read_string(c.required("column"));
    const Dimension want = dimension_of(static_cast<Signal>(s));
    if (std::optional<Node> unit = c.optional("unit")) {
      std::string error;
      const std::optional<Quantity> q = parse_unit(read_string(*unit), &error);
      if (!q || !(q->dimension == want)) unit->fail("a unit of " + describe_dimension(want));
      f.scale[static_cast<size_t>(s)] = q->si;
    } else {
      if (!(want == dim::none)) value.fail("key 'unit' (" + describe_dimension(want) + ")", "no such key");
      f.scale[static_cast<size_t>(s)] = 1.0;
    }
  }
  for (int s = 0; s < kSignals; ++s) {
    const bool need = s == 0 || (rig == Rig::lever ? (s == 1 || s == 2) : (s == 5 || s == 6));
    if (need && f.column[static_cast<size_t>(s)].empty()) {
      columns.fail(std::string("a column for '") + signal_name(static_cast<Signal>(s)) + "'", "none");
    }
  }
  return f;
}

}  // namespace

Measurement read_measurement(const Node& root) {
  const std::string kind = file_kind(root);
  if (kind != "measurement") {
    root.child(root.yaml().begin()->first).fail("a measurement file (its first key 'measurement')", "'" + kind + "'");
  }
  MapReader m(root, "a measurement file",
              {"measurement", "description", "rig", "object", "actee", "effort_at", "trace", "traces", "format",
               "effects"});
  Measurement out;
  out.file = root.loc().file;
  out.files.push_back(out.file);
  Files files(root, "measurement", &out.files);
  out.name = read_name(m.required("measurement"));
  if (std::optional<Node> d = m.optional("description")) (void)read_string(*d);
  if (std::optional<Node> rig = m.optional("rig")) {
    out.rig = read_choice(*rig, {"lever", "plates"}) == "plates" ? Rig::plates : Rig::lever;
  }

  if (out.rig == Rig::lever) {
    out.object = read_object(files.document(root, "object", m.required("object")));
    const Node at = m.required("effort_at");
    out.effort_at = read_quantity(at, dim::length);
    const double lo = std::min(out.object->emphasis.from, out.object->emphasis.to);
    const double hi = std::max(out.object->emphasis.from, out.object->emphasis.to);
    if (out.effort_at < lo || out.effort_at > hi) {
      at.fail("a distance in the emphasis region, " + format_quantity(lo, dim::length) + " to " +
              format_quantity(hi, dim::length));
    }
    if (std::optional<Node> a = m.optional("actee")) {
      out.actee.emplace();
      read_actee_entry(*a, files, &*out.actee, &out.options);
      if (!out.options.actee.in_jaws) key_node(*a, "position").fail("'at' (a distance on the fixed jaw)", "'position'");
    }
  } else {
    for (const char* key : {"object", "effort_at"}) {
      if (m.has(key)) key_node(root, key).fail("no '" + std::string(key) + "' with rig: plates (an actee alone)", "one");
    }
    const Node a = m.required("actee");
    MapReader entry(a, "the actee", {"file"});
    out.actee = read_actee(files.document(a, "file", entry.required("file")));
  }

  if (m.has("trace") == m.has("traces")) {
    root.fail("exactly one of 'trace' (a file) and 'traces' (a list of files)", m.has("trace") ? "both" : "neither");
  }
  const TableFormat format = [&] {
    if (std::optional<Node> f = m.optional("format")) return read_format(*f, out.rig);
    TableFormat d = default_format(out.rig);
    d.loc = root.loc();
    return d;
  }();
  std::vector<std::pair<Node, std::string>> paths;
  if (std::optional<Node> t = m.optional("trace")) {
    paths.emplace_back(*t, files.resolve(root, "trace", *t));
  } else {
    const Node list = m.required("traces");
    if (!list.is_sequence() || list.size() == 0) list.fail("a list of trace files");
    if (list.size() > 1000) list.fail("at most 1000 traces", std::to_string(list.size()));
    for (size_t i = 0; i < list.size(); ++i) paths.emplace_back(list[i], files.resolve(root, "traces", list[i]));
  }
  for (const auto& [node, path] : paths) {
    TableFormat f = format;
    f.loc = node.loc();
    out.traces.push_back(read_trace(path, f, out.rig, kMinRows));
  }
  if (std::optional<Node> e = m.optional("effects")) out.options.effects = read_effects(*e, EffectHome::measurement);
  return out;
}

Measurement load_measurement(const std::string& path) { return read_measurement(load_yaml_file(path)); }

Model compile_measurement(const Measurement& m) {
  if (!m.object) throw LogicError("compile_measurement() on a plates measurement");
  return compile(*m.object, m.actee ? &*m.actee : nullptr, nullptr, m.options);
}

}  // namespace afford
