#include "measurement.h"

#include <cmath>
#include <numbers>

#include "data_files.h"
#include "load.h"
#include "trace_table.h"
#include "units.h"
#include "validate.h"

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

// Where a signal is in the table: its unit is required unless it is a count.
const MapSchema& column_schema(Signal s) {
  static const std::vector<MapSchema> kColumns = [] {
    std::vector<MapSchema> all;
    for (int i = 0; i < kSignals; ++i) {
      const Dimension d = dimension_of(static_cast<Signal>(i));
      const bool count = d == dim::none;
      all.push_back(MapSchema{"where a signal is in the table",
                              {schema::required_key("column", schema::text(), "the column's header"),
                               KeySchema{"unit", schema::text(), !count,
                                         count ? "none: the signal is a count"
                                               : "the unit of its values, " + describe_dimension(d)}}});
    }
    return all;
  }();
  return kColumns[static_cast<size_t>(s)];
}

const MapSchema& columns_schema() {
  static const MapSchema kColumns = [] {
    MapSchema m{"the columns of the signals; t always, and the rig's two"};
    for (int i = 0; i < kSignals; ++i) {
      const char* name = signal_name(static_cast<Signal>(i));
      m.keys.push_back(schema::optional_key(name, schema::mapping(column_schema(static_cast<Signal>(i))),
                                            std::string("the column of ") + name));
    }
    return m;
  }();
  return kColumns;
}

const MapSchema& format_schema() {
  using namespace schema;
  static const MapSchema kFormat{
      "how the trace files are laid out",
      {optional_key("skip", integer(), "lines before the header, 0 to 10000"),
       optional_key("footer", integer(), "lines after the table, 0 to 10000"),
       optional_key("separator", choice({"comma", "tab", "blanks"}), "what separates the columns"),
       required_key("columns", mapping(columns_schema()), "the columns of the signals")}};
  return kFormat;
}

// The actee of a plates rig: the actee alone.
const MapSchema& plates_actee_schema() {
  using namespace schema;
  static const MapSchema kActee{"the actee between the plates",
                                {required_key("file", any_of({path(), mapping(actee_schema())}),
                                              "the actee file, or its content as a mapping")}};
  return kActee;
}

// A trace named with how the tool was held: `{file: a.csv, turned: 180 deg}`.
const MapSchema& trace_entry_schema() {
  using namespace schema;
  static const MapSchema kEntry{
      "a trace file and how the tool was held while it was measured",
      {required_key("file", path(), "the trace file"),
       optional_key("turned", quantity(dim::angle),
                    "the tool turned about its hinge from how its file holds it, -360 deg to 360 deg "
                    "(180 deg: upside down), which turns its weight's torque")}};
  return kEntry;
}

// `format: {skip, separator, columns: {signal: {column, unit}}}`.
TableFormat read_format(const Node& node, Rig rig) {
  MapReader m(node, "the trace format", format_schema());
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
  const std::vector<std::string> names = columns_schema().key_names();
  const Node columns = m.required("columns");
  MapReader cols(columns, "the columns", columns_schema());
  for (const auto& [name, value] : cols.entries()) {
    int s = 0;
    while (names[static_cast<size_t>(s)] != name) ++s;
    MapReader c(value, "the column of " + name, column_schema(static_cast<Signal>(s)));
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

const MapSchema& measurement_schema() {
  using namespace schema;
  static const MapSchema kMeasurement = [] {
    MapSchema m{
        "a measurement file: a real tool's traces (gap/README.md)",
        {required_key("measurement", name(), "the measurement's name"),
         optional_key("description", text(), "what was measured, in a sentence"),
         optional_key("rig", choice({"lever", "plates"}), "a tool worked by its lever (default), or plates"),
         optional_key("object", any_of({path(), mapping(object_schema())}), "the object file (lever rig)"),
         optional_key("actee", any_of({mapping(actee_entry_schema()), mapping(plates_actee_schema())}),
                      "the actee, at a distance on the jaw (lever rig) or alone (plates)"),
         optional_key("effort_at", quantity(dim::length), "where the effort was applied, in the emphasis region"),
         optional_key("trace", any_of({path(), mapping(trace_entry_schema())}),
                      "the trace file, or {file, turned} (or traces)"),
         optional_key("traces", sequence(any_of({path(), mapping(trace_entry_schema())}), 1, 1000),
                      "the trace files, each or {file, turned} (or trace)"),
         optional_key("format", mapping(format_schema()), "how the trace files are laid out"),
         optional_key("effects", mapping(effects_schema(EffectHome::measurement)), "effects to switch on")},
        false,
        {{"trace", "traces"}}};
    m.required_when.push_back({"rig", "plates", {"actee"}, {"object", "effort_at"}});
    return m;
  }();
  return kMeasurement;
}

Measurement read_measurement(const Node& root) {
  const std::string kind = file_kind(root);
  if (kind != "measurement") {
    root.child(root.yaml().begin()->first).fail("a measurement file (its first key 'measurement')", "'" + kind + "'");
  }
  MapReader m(root, "a measurement file", measurement_schema());
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
    MapReader entry(a, "the actee", plates_actee_schema());
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
  // Each trace: a path, or {file, turned}.
  auto read_entry = [&](const Node& parent, std::string_view key, const Node& node) {
    std::string path;
    double turned = 0;
    if (node.is_map()) {
      MapReader entry(node, "a trace", trace_entry_schema());
      path = files.resolve(node, "file", entry.required("file"));
      if (std::optional<Node> turn = entry.optional("turned")) {
        turned = read_quantity(*turn, dim::angle);
        if (std::abs(turned) > 2 * std::numbers::pi) turn->fail("an angle from -360 deg to 360 deg");
        if (out.rig == Rig::plates) turn->fail("no 'turned' with rig: plates (no hinge to turn about)", "one");
      }
    } else {
      path = files.resolve(parent, key, node);
    }
    TableFormat f = format;
    f.loc = node.loc();
    out.traces.push_back(read_trace(path, f, out.rig, kMinRows));
    out.traces.back().turned = turned;
  };
  if (std::optional<Node> t = m.optional("trace")) {
    read_entry(root, "trace", *t);
  } else {
    const Node list = m.required("traces");
    if (!list.is_sequence() || list.size() == 0) list.fail("a list of trace files");
    if (list.size() > 1000) list.fail("at most 1000 traces", std::to_string(list.size()));
    for (size_t i = 0; i < list.size(); ++i) read_entry(root, "traces", list[i]);
  }
  if (std::optional<Node> e = m.optional("effects")) out.options.effects = read_effects(*e, EffectHome::measurement);
  return out;
}

Measurement load_measurement(const std::string& path) { return read_measurement(load_yaml_file(path)); }

Model compile_measurement(const Measurement& m) {
  if (!m.object) throw LogicError("compile_measurement() on a plates measurement");
  return compile(*m.object, m.actee ? &*m.actee : nullptr, nullptr, m.options);
}

void add_measurement_file_kind() {
  add_file_kind("measurement", [](const Node& root) {
    const Measurement m = read_measurement(root);
    return "measurement " + m.name + ", " + std::to_string(m.traces.size()) + " traces";
  });
}

}  // namespace afford
