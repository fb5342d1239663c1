// actees/*.yaml -> ActeeSpec.
#include "load.h"

namespace afford {
namespace {

const MapSchema& look_schema() {
  using namespace schema;
  static const MapSchema kLook{
      "how the actee is drawn; changes nothing in the physics",
      {required_key("colour", text(), "its outside, \"#rrggbb\" (quoted: an unquoted # starts a YAML comment)"),
       optional_key("inside", text(), "where it has broken open, \"#rrggbb\" (default: colour halfway to white)"),
       optional_key("broken", choice({"halves", "crushed", "shards"}),
                    "how it is drawn once broken (default shards); only for an actee that breaks")}};
  return kLook;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

const char* const kColourExpected = "a colour \"#rrggbb\" (quoted: an unquoted # starts a YAML comment)";

// "#rrggbb", as in CSS and matplotlib.
ActeeLook::Srgb read_colour(const Node& node) {
  const std::string expected = kColourExpected;
  if (!node.is_scalar()) node.fail(expected);
  const std::string s = node.yaml().Scalar();
  ActeeLook::Srgb c{};
  bool ok = s.size() == 7 && s[0] == '#';
  for (size_t k = 0; ok && k < 3; ++k) {
    const int hi = hex_digit(s[1 + 2 * k]), lo = hex_digit(s[2 + 2 * k]);
    ok = hi >= 0 && lo >= 0;
    c[k] = static_cast<std::uint8_t>(16 * hi + lo);
  }
  if (!ok) node.fail(expected);
  return c;
}

// The `look:` mapping; a file without one gets the defaults of actee_look.h.
ActeeLook read_look(const Node& node, bool breaks) {
  MapReader m(node, "the look", look_schema());
  // An unquoted "#..." reads as nothing: say why before "a value is missing".
  // (Named at its key: an empty value has no place of its own.)
  for (const auto& kv : node.yaml()) {
    const std::string key = kv.first.Scalar();
    if ((key == "colour" || key == "inside") && kv.second.IsNull()) {
      node.child(kv.first).fail(kColourExpected, "nothing");
    }
  }
  ActeeLook look;
  look.colour = read_colour(m.required("colour"));
  look.inside = lighter_half(look.colour);
  if (std::optional<Node> inside = m.optional("inside")) look.inside = read_colour(*inside);
  if (std::optional<Node> broken = m.optional("broken")) {
    if (!breaks) {
      broken->fail("no broken look for an actee that never breaks (breaks: false)", "broken: " + broken->found());
    }
    const std::string b = read_choice(*broken, {"halves", "crushed", "shards"});
    look.broken = b == "halves" ? ActeeLook::Broken::halves
                  : b == "crushed" ? ActeeLook::Broken::crushed
                                   : ActeeLook::Broken::shards;
  }
  return look;
}

}  // namespace

const MapSchema& actee_schema() {
  using namespace schema;
  static const MapSchema kActee{
      "an actee file: what a tool acts on (actees/README.md)",
      {required_key("actee", name(), "the actee's name"),
       required_key("description", text(), "what it is, in a sentence"),
       required_key("shape", mapping(shape_schema()), "its collision shape"),
       required_key("mass", quantity(dim::mass), "its mass"),
       required_key("force_direction", plain_vector(),
                    "A_d: the direction (actee frame) along which force counts against the limit"),
       required_key("limit", quantity(dim::force),
                    "A_pv: the force along force_direction above which it breaks (or counts as squeezed)"),
       required_key("stiffness", quantity(dim::stiffness), "its contact stiffness at small deflections"),
       required_key("breaks", boolean(), "true: brittle, breaks above the limit; false: compliant, never breaks"),
       required_key("friction", mapping(friction_schema()),
                    "its static friction on the jaws: the grip must carry its weight for it to count as held"),
       optional_key("effects", mapping(effects_schema(EffectHome::actee)), "optional effects of the actee"),
       optional_key("look", mapping(look_schema()),
                    "how it is drawn: colour, inside, broken (default a tan colour, broken in shards)")}};
  return kActee;
}

ActeeSpec read_actee(const Node& root) {
  MapReader m(root, "an actee file", actee_schema());
  ActeeSpec a;
  a.loc = root.loc();
  a.file = root.loc().file;
  a.name = read_name(m.required("actee"));
  a.description = read_string(m.required("description"));
  a.shape = read_shape(m.required("shape"));
  a.mass = read_positive(m.required("mass"), dim::mass);
  a.force_direction = read_direction(m.required("force_direction"));
  const Node limit = m.required("limit");
  a.limit_loc = limit.loc();
  a.limit = read_positive(limit, dim::force);
  a.stiffness = read_positive(m.required("stiffness"), dim::stiffness);
  a.breaks = read_bool(m.required("breaks"));
  a.friction = read_friction(m.required("friction"), &a.friction_source);
  if (std::optional<Node> effects = m.optional("effects")) a.effects = read_effects(*effects, EffectHome::actee);
  if (std::optional<Node> look = m.optional("look")) a.look = read_look(*look, a.breaks);
  return a;
}

ActeeSpec load_actee(const std::string& path) { return read_actee(load_yaml_file(path)); }

}  // namespace afford
