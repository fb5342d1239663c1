// rules/guides.yaml -> GuideSpec, and the guides computed from a Model: plain
// geometry in the object (or moving arm) frame plus the facts behind it.
#include "guides.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "lever.h"
#include "load.h"
#include "model.h"
#include "terms.h"
#include "yaml_reader.h"

namespace afford {

const char* guide_kind_name(GuideKind k) {
  switch (k) {
    case GuideKind::symmetry_plane: return "symmetry_plane";
    case GuideKind::interaction_space: return "interaction_space";
    case GuideKind::emphasis: return "emphasis";
    case GuideKind::advantage: return "advantage";
  }
  return "?";
}

int Guides::find(const std::string& name) const {
  for (size_t i = 0; i < guides.size(); ++i) {
    if (guides[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

// ---------------------------------------------------------------- reading

namespace {

constexpr GuideKind kKinds[] = {GuideKind::symmetry_plane, GuideKind::interaction_space, GuideKind::emphasis,
                                GuideKind::advantage};

// [r, g, b], each a bare number in 0..1 (read_colour).
ValueSchema colour_value() { return schema::sequence(schema::number(), 3, 3); }

const MapSchema& ramp_schema() {
  using namespace schema;
  const ValueSchema colour = colour_value();
  static const MapSchema kRamp{"the colours of the advantage ramp",
                               {required_key("decline", colour, "below an advantage of 1"),
                                required_key("neutral", colour, "at an advantage of 1"),
                                required_key("amplify", colour, "at the saturating advantage")}};
  return kRamp;
}

// The keys of a guide of kind `k`: the keys every guide has, then its kind's.
MapSchema make_guide_schema(GuideKind k) {
  using namespace schema;
  const ValueSchema colour = colour_value();
  MapSchema m{std::string("a guide of kind ") + guide_kind_name(k),
              {required_key("name", name(), "the guide's name, unique in the file"),
               required_key("kind", choice({guide_kind_name(k)}), "what the guide shows"),
               required_key("description", text(), "what the guide shows, in a sentence"),
               required_key("colour", colour, "its colour [r, g, b], each from 0 to 1"),
               optional_key("alpha", number(), "its opacity from 0 to 1 (default 1)"),
               optional_key("lift", quantity(dim::length), "how far it is drawn off the surface")}};
  switch (k) {
    case GuideKind::symmetry_plane:
      m.keys.push_back(
          optional_key("margin", quantity(dim::length), "how far the plane's rectangle exceeds the object"));
      m.keys.push_back(
          optional_key("gravity", plain_vector(), "gravity's direction in the world (default [0, 0, -1])"));
      break;
    case GuideKind::interaction_space:
      m.keys.push_back(optional_key("fit_colour", colour, "the colour of an actee that fits"));
      m.keys.push_back(optional_key("misfit_colour", colour, "the colour of an actee that does not"));
      break;
    case GuideKind::emphasis:
      m.keys.push_back(optional_key("faces", choice({"closing", "opening", "both"}),
                                    "the faces to mark: pressed to close, to open, or both"));
      break;
    case GuideKind::advantage: {
      m.keys.push_back(required_key("step", quantity(dim::length), "the segment length along each arm"));
      m.keys.push_back(optional_key("load_at", choice({"from", "middle", "to"}), "where in the application "
                                    "region the load sits"));
      m.keys.push_back(optional_key("saturate", number(),
                                    "the advantage, above 1, at which the ramp reaches amplify (default 2)"));
      m.keys.push_back(required_key("ramp", mapping(ramp_schema()), "the colours of the ramp"));
      break;
    }
  }
  return m;
}

const MapSchema& guide_schema(GuideKind k) {
  static const std::vector<MapSchema> kSchemas = [] {
    std::vector<MapSchema> all;
    for (GuideKind kind : kKinds) all.push_back(make_guide_schema(kind));
    return all;
  }();
  size_t i = 0;
  while (kKinds[i] != k) ++i;
  return kSchemas[i];
}

GuideKind read_kind(const Node& node) {
  const std::string s =
      read_choice(node, {"symmetry_plane", "interaction_space", "emphasis", "advantage"});
  for (GuideKind k : kKinds) {
    if (s == guide_kind_name(k)) return k;
  }
  throw LogicError("guide kind accepted but unknown: " + s);
}

// [r, g, b], each a bare number in 0..1.
GuideColour read_colour(const Node& node, double alpha) {
  if (!node.is_sequence() || node.size() != 3) node.fail("a colour [r, g, b] of three numbers from 0 to 1");
  GuideColour c;
  double* rgb[3] = {&c.r, &c.g, &c.b};
  for (size_t i = 0; i < 3; ++i) {
    const double v = read_number(node[i]);
    if (!(v >= 0 && v <= 1)) node[i].fail("a colour component from 0 to 1");
    *rgb[i] = v;
  }
  c.a = alpha;
  return c;
}

GuideSpec read_guide(const Node& node, const std::vector<GuideSpec>& before) {
  if (!node.is_map()) node.fail("a mapping for a guide");
  // The kind decides the keys a guide may have: with a kind we know, only
  // its keys are accepted; otherwise any guide's key is, and the kind itself
  // is reported (with "did you mean") once the keys have been checked.
  const YAML::Node kind_yaml = node.yaml()["kind"];
  std::optional<GuideKind> known;
  if (kind_yaml && kind_yaml.IsScalar()) {
    for (GuideKind k : kKinds) {
      if (kind_yaml.Scalar() == guide_kind_name(k)) known = k;
    }
  }
  std::vector<std::string> keys;
  for (GuideKind k : kKinds) {
    if (known && k != *known) continue;
    for (const std::string& key : guide_schema(k).key_names()) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  MapReader m(node, known ? std::string("a guide of kind ") + guide_kind_name(*known) : "a guide", keys);

  GuideSpec g;
  g.loc = node.loc();
  const Node name = m.required("name");
  g.name = read_name(name);
  for (const GuideSpec& other : before) {
    if (other.name == g.name) {
      name.fail("a guide name not used before", "'" + g.name + "' again (first at " + other.loc.str() + ")");
    }
  }
  g.kind = read_kind(m.required("kind"));
  g.description = read_string(m.required("description"));
  double alpha = 1;
  if (std::optional<Node> a = m.optional("alpha")) {
    alpha = read_number(*a);
    if (!(alpha >= 0 && alpha <= 1)) a->fail("an alpha from 0 to 1");
  }
  g.colour = read_colour(m.required("colour"), alpha);
  if (std::optional<Node> n = m.optional("lift")) g.lift = read_non_negative(*n, dim::length);
  g.fit_colour = g.misfit_colour = g.colour;
  g.decline = g.neutral = g.amplify = g.colour;

  switch (g.kind) {
    case GuideKind::symmetry_plane:
      if (std::optional<Node> n = m.optional("margin")) g.margin = read_non_negative(*n, dim::length);
      if (std::optional<Node> n = m.optional("gravity")) g.gravity = read_direction(*n);
      break;
    case GuideKind::interaction_space:
      if (std::optional<Node> n = m.optional("fit_colour")) g.fit_colour = read_colour(*n, 1);
      if (std::optional<Node> n = m.optional("misfit_colour")) g.misfit_colour = read_colour(*n, 1);
      break;
    case GuideKind::emphasis:
      if (std::optional<Node> n = m.optional("faces")) {
        const std::string f = read_choice(*n, {"closing", "opening", "both"});
        g.faces = f == "closing" ? GuideFaces::closing : f == "opening" ? GuideFaces::opening : GuideFaces::both;
      }
      break;
    case GuideKind::advantage: {
      g.step = read_positive(m.required("step"), dim::length);
      if (std::optional<Node> n = m.optional("load_at")) {
        const std::string l = read_choice(*n, {"from", "middle", "to"});
        g.load_at = l == "from" ? GuideLoadAt::from : l == "to" ? GuideLoadAt::to : GuideLoadAt::middle;
      }
      if (std::optional<Node> n = m.optional("saturate")) {
        g.saturate = read_number(*n);
        if (!(g.saturate > 1)) n->fail("a mechanical advantage greater than 1");
      }
      MapReader ramp(m.required("ramp"), "the colour ramp", ramp_schema());
      g.decline = read_colour(ramp.required("decline"), alpha);
      g.neutral = read_colour(ramp.required("neutral"), alpha);
      g.amplify = read_colour(ramp.required("amplify"), alpha);
      break;
    }
  }
  return g;
}

}  // namespace

const MapSchema& guides_schema() {
  using namespace schema;
  static const MapSchema kGuides = [] {
    ValueSchema guide = any_of({});
    for (GuideKind k : kKinds) guide.items.push_back(mapping(guide_schema(k)));
    return MapSchema{"a guides file: what the renderer draws on a tool (rules/README.md)",
                     {required_key("guides", sequence(guide, 1), "the guides")}};
  }();
  return kGuides;
}

std::vector<GuideSpec> read_guides(const Node& root) {
  MapReader top(root, "a guides file", guides_schema());
  const Node list = top.required("guides");
  if (!list.is_sequence() || list.size() == 0) list.fail("a sequence of guides");
  std::vector<GuideSpec> guides;
  for (size_t i = 0; i < list.size(); ++i) guides.push_back(read_guide(list[i], guides));
  return guides;
}

std::vector<GuideSpec> load_guides(const std::string& path) { return read_guides(load_yaml_file(path)); }

// ---------------------------------------------------------------- computing

namespace {

using Eigen::Vector3d;

Eigen::Isometry3d arm_pose(Arm arm, double theta) {
  return arm == Arm::moving ? moving_arm_pose(theta) : Eigen::Isometry3d::Identity();
}

// The axis-aligned box of a part in its arm's frame, m.
Eigen::AlignedBox3d part_box(const ModelPart& p) {
  const Eigen::AlignedBox3d& local = p.geometry.local_box();
  Eigen::AlignedBox3d box;
  for (int c = 0; c < 8; ++c) box.extend(p.in_arm * local.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
  return box;
}

// The box of the whole object in the object frame over its opening range.
Eigen::AlignedBox3d object_box(const Model& m) {
  Eigen::AlignedBox3d box;
  for (const ModelPart& p : m.parts) {
    const Eigen::AlignedBox3d b = part_box(p);
    for (double theta : {m.theta_min, m.theta_rest, m.theta_max}) {
      const Eigen::Isometry3d pose = arm_pose(p.arm, theta);
      for (int c = 0; c < 8; ++c) box.extend(pose * b.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
    }
  }
  if (box.isEmpty()) box.extend(Vector3d::Zero());
  return box;
}

// max over the part of x . n in its arm's frame (n unit).
double part_support(const ModelPart& p, const Vector3d& n) {
  return n.dot(p.in_arm.translation()) + p.geometry.support(p.in_arm.linear().transpose() * n);
}

// The parts of `arm` whose box covers [from, to] in part (overlap), their
// outermost extent along n and their z range. False when none does.
bool arm_face(const Model& m, Arm arm, double from, double to, const Vector3d& n, double* out, double* zmin,
              double* zmax) {
  bool any = false;
  for (const ModelPart& p : m.parts) {
    if (p.arm != arm) continue;
    const Eigen::AlignedBox3d b = part_box(p);
    if (b.max().x() <= from || b.min().x() >= to) continue;
    const double s = part_support(p, n);
    *out = any ? std::max(*out, s) : s;
    *zmin = any ? std::min(*zmin, b.min().z()) : b.min().z();
    *zmax = any ? std::max(*zmax, b.max().z()) : b.max().z();
    any = true;
  }
  return any;
}

// The outward normal (arm frame) of the face the agent presses at signed
// distance r to close the jaws. Closing turns the moving arm by -theta, so
// at r it is pushed along -y*sign(r), and the fixed arm the other way; the
// pressed face's normal points against the push.
Vector3d closing_face_normal(Arm arm, double r) {
  const double s = r < 0 ? -1 : 1;
  return (arm == Arm::moving ? s : -s) * Vector3d::UnitY();
}

GuideColour lerp(const GuideColour& a, const GuideColour& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, a.a + (b.a - a.a) * t};
}

std::string fixed2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// The paper's stable orientation (GuideFacts): the turn about the tool's
// x axis that puts the symmetry plane's normal across gravity with the
// moving arm (+y of the object frame) up, and the moving arm's weight
// about the pivot there and half a turn on. The weight is the model's own
// (the gravity effect's: the moving arm's share of the mass at its
// centroid), whether or not the file switches gravity on.
void stable_turn(const Model& m, const Vector3d& normal, const Vector3d& gravity, GuideFacts& f) {
  const Eigen::Matrix3d pose = m.object_start.linear();
  auto across = [&](double phi) { return (pose * Eigen::AngleAxisd(phi, Vector3d::UnitX()) * normal).dot(gravity); };
  // Already parallel (to the rounding a turn written in degrees leaves):
  // no turn, with the moving arm above or half a turn on.
  constexpr double kParallel = 1e-9;  // rad
  if (std::abs(across(0)) < kParallel) {
    f.stable_turn_found = true;
    f.stable_turn = (pose * Vector3d::UnitY()).dot(gravity) > 0 ? std::numbers::pi : 0.0;
  }
  constexpr int kSteps = 360;  // one degree apart, then halved down to the root
  for (int i = 0; i < kSteps && !f.stable_turn_found; ++i) {
    double lo = 2 * std::numbers::pi * i / kSteps, hi = 2 * std::numbers::pi * (i + 1) / kSteps;
    if ((across(lo) > 0) == (across(hi) > 0) && across(lo) != 0) continue;
    for (int k = 0; k < 60; ++k) ((across(lo) > 0) == (across(0.5 * (lo + hi)) > 0) ? lo : hi) = 0.5 * (lo + hi);
    const Eigen::Matrix3d turned = pose * Eigen::AngleAxisd(lo, Vector3d::UnitX()).toRotationMatrix();
    if ((turned * Vector3d::UnitY()).dot(gravity) > 0) continue;  // the moving arm below: the other root
    f.stable_turn_found = true;
    f.stable_turn = lo;
  }
  if (!f.stable_turn_found) return;
  Model weighed = m;
  weighed.gravity = true;
  weighed.gravity_extra = 0;
  auto weight = [&](double phi) {
    double c = 0, s = 0;
    gravity_coefficients(weighed, pose * Eigen::AngleAxisd(phi, Vector3d::UnitX()).toRotationMatrix(), &c, &s);
    return c * std::cos(m.theta_rest) + s * std::sin(m.theta_rest);
  };
  f.weight_above = weight(f.stable_turn);
  f.weight_below = weight(f.stable_turn + std::numbers::pi);
  f.spring_at_rest = spring_torques(m, m.theta_rest).preload;
  f.friction_at_rest = m.friction_torque;
}

void add_symmetry_plane(const Model& m, int index, const GuideSpec& g, Guides& out) {
  const Eigen::AlignedBox3d box = object_box(m);
  GuideRect r;
  r.guide = index;
  r.frame = Arm::fixed;
  r.normal = m.symmetry_normal.normalized();
  // u: the arm axis projected onto the plane (the pivot axis when the plane
  // is across the arm).
  Vector3d u = Vector3d::UnitX() - r.normal * r.normal.dot(Vector3d::UnitX());
  if (u.norm() < 1e-6) u = Vector3d::UnitY() - r.normal * r.normal.dot(Vector3d::UnitY());
  r.u = u.normalized();
  r.v = r.normal.cross(r.u);
  const Vector3d c = box.center();
  r.centre = c - r.normal * r.normal.dot(c - m.symmetry_point);
  for (int k = 0; k < 8; ++k) {
    const Vector3d d = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)) - r.centre;
    r.half_u = std::max(r.half_u, std::abs(d.dot(r.u)));
    r.half_v = std::max(r.half_v, std::abs(d.dot(r.v)));
  }
  r.half_u += g.margin;
  r.half_v += g.margin;
  r.colour = g.colour;
  out.rects.push_back(r);

  // Gravity at the functional pose, drawn in the object frame from the
  // plane's centre.
  const Vector3d down = (m.object_start.linear().transpose() * g.gravity).normalized();
  const double len = 0.5 * std::max(r.half_u, r.half_v);
  GuideSegment s;
  s.guide = index;
  s.a = r.centre;
  s.b = r.centre + down * len;
  s.colour = g.colour;
  s.colour.a = 1;
  out.segments.push_back(s);

  GuideFacts& f = out.facts;
  f.symmetry_point = m.symmetry_point;
  f.symmetry_normal = r.normal;
  f.functional_pose = m.object_start;
  const Vector3d n_world = m.object_start.linear() * r.normal;
  f.plane_to_gravity = std::asin(std::min(1.0, std::abs(n_world.dot(g.gravity.normalized()))));
  if (f.plane_to_gravity < 1e-9) f.plane_to_gravity = 0;  // the rounding of a turn written in degrees
  stable_turn(m, r.normal, g.gravity.normalized(), f);
  out.labels.push_back({index, Arm::fixed, "plane of symmetry", r.centre + r.u * r.half_u + r.v * r.half_v, s.colour});
  out.labels.push_back({index, Arm::fixed, "gravity", s.b, s.colour});
}

// The interaction space from the tool's shape (the object's table): the
// strip over the fixed jaw's face (y = 0) as high as the gap fully open at
// each distance, from z0 to z1, wound outward.
GuideMesh table_mesh(const InteractionSpace& space, double z0, double z1) {
  GuideMesh mesh;
  for (size_t k = 0; k < space.distances.size(); ++k) {
    for (double z : {z0, z1}) {
      mesh.vertices.emplace_back(space.distances[k], 0, z);
      mesh.vertices.emplace_back(space.distances[k], space.gaps[k], z);
    }
  }
  auto quad = [&mesh](int a, int b, int c, int d, const Vector3d& outward) {
    for (std::array<int, 3> t : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}}) {
      const Vector3d& p = mesh.vertices[static_cast<size_t>(t[0])];
      const Vector3d n = (mesh.vertices[static_cast<size_t>(t[1])] - p).cross(mesh.vertices[static_cast<size_t>(t[2])] - p);
      if (n.dot(outward) < 0) std::swap(t[1], t[2]);
      mesh.triangles.push_back(t);
    }
  };
  // Column k's corners: 4k + 0 (face, z0), 1 (gap, z0), 2 (face, z1), 3 (gap, z1).
  const int last = 4 * (static_cast<int>(space.distances.size()) - 1);
  for (int i = 0; i < last; i += 4) {
    const int j = i + 4;
    const size_t k = static_cast<size_t>(i / 4);
    quad(i, j, j + 1, i + 1, -Vector3d::UnitZ());
    quad(i + 2, j + 2, j + 3, i + 3, Vector3d::UnitZ());
    quad(i, j, j + 2, i + 2, -Vector3d::UnitY());  // on the fixed jaw's face
    const Vector3d up(space.gaps[k] - space.gaps[k + 1], space.distances[k + 1] - space.distances[k], 0);
    quad(i + 1, j + 1, j + 3, i + 3, up);  // under the moving jaw
  }
  quad(0, 1, 3, 2, -Vector3d::UnitX());
  quad(last, last + 1, last + 3, last + 2, Vector3d::UnitX());
  return mesh;
}

void add_interaction_space(const Model& m, int index, const GuideSpec& g, const std::vector<ActeeFit>& fits,
                           Guides& out) {
  const InteractionSpace space = interaction_space(m);
  out.facts.space = space;
  out.facts.actees = fits;
  const Eigen::AlignedBox3d box = object_box(m);
  const double z0 = box.min().z(), z1 = box.max().z();
  const Eigen::Isometry3d open = moving_arm_pose(m.theta_max);
  GuideMesh mesh;
  if (space.from_shape) {
    mesh = table_mesh(space, z0, z1);
  } else {
    // The wedge between the jaws' inner faces (y = 0 in each arm's frame).
    const Vector3d q[4] = {Vector3d(space.from, 0, 0), Vector3d(space.to, 0, 0), open * Vector3d(space.to, 0, 0),
                           open * Vector3d(space.from, 0, 0)};
    for (int i = 0; i < 4; ++i) mesh.vertices.push_back(q[i] + Vector3d(0, 0, z0));
    for (int i = 0; i < 4; ++i) mesh.vertices.push_back(q[i] + Vector3d(0, 0, z1));
    const std::array<int, 3> tris[12] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                         {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    Vector3d centre = Vector3d::Zero();
    for (const Vector3d& v : mesh.vertices) centre += v / 8.0;
    for (std::array<int, 3> t : tris) {
      const Vector3d& a = mesh.vertices[t[0]];
      const Vector3d n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
      if (n.dot(a - centre) < 0) std::swap(t[1], t[2]);  // wind outward whatever the arm's side
      mesh.triangles.push_back(t);
    }
  }
  mesh.guide = index;
  mesh.colour = g.colour;
  out.meshes.push_back(mesh);

  GuideColour text = g.colour;
  text.a = 1;
  const Vector3d top = (space.from_shape ? Vector3d(space.to, space.gap_to, 0) : Vector3d(open * Vector3d(space.to, 0, 0))) +
                       Vector3d(0, 0, z1);
  out.labels.push_back({index, Arm::fixed, "interaction space", top, text});
  // The actees: a bar on the fixed jaw over where each fitting one can sit,
  // stacked above the object, and a label each.
  const double spacing = 0.08 * std::max(std::abs(space.to - space.from), 1e-3);
  for (size_t k = 0; k < fits.size(); ++k) {
    const ActeeFit& fit = fits[k];
    const double z = z1 + g.lift + spacing * static_cast<double>(k + 1);
    if (fit.fits) {
      GuideSegment s;
      s.guide = index;
      s.a = Vector3d(fit.from, 0, z);
      s.b = Vector3d(fit.to, 0, z);
      s.colour = g.fit_colour;
      s.value = fit.effort_to_limit;
      s.distance = 0.5 * (fit.from + fit.to);
      out.segments.push_back(s);
      out.labels.push_back({index, Arm::fixed, fit.name + " fits", Vector3d(fit.to, 0, z), g.fit_colour});
    } else {
      out.labels.push_back(
          {index, Arm::fixed, fit.name + " does not fit", Vector3d(space.to, 0, z), g.misfit_colour});
    }
  }
}

std::vector<Vector3d> face_normals(Arm arm, double r, GuideFaces faces) {
  const Vector3d n = closing_face_normal(arm, r);
  if (faces == GuideFaces::closing) return {n};
  if (faces == GuideFaces::opening) return {-n};
  return {n, -n};
}

void add_emphasis(const Model& m, int index, const GuideSpec& g, Guides& out) {
  out.facts.emphasis_from = m.emphasis_from;
  out.facts.emphasis_to = m.emphasis_to;
  const double mid = 0.5 * (m.emphasis_from + m.emphasis_to);
  for (Arm arm : {Arm::fixed, Arm::moving}) {
    for (const Vector3d& n : face_normals(arm, mid, g.faces)) {
      double face = 0, z0 = 0, z1 = 0;
      if (!arm_face(m, arm, m.emphasis_from, m.emphasis_to, n, &face, &z0, &z1)) continue;
      GuideRect r;
      r.guide = index;
      r.frame = arm;
      r.normal = n;
      r.u = Vector3d::UnitX();
      r.v = n.cross(r.u);
      r.centre = Vector3d(mid, 0, 0.5 * (z0 + z1)) + n * (face + g.lift);
      r.half_u = 0.5 * (m.emphasis_to - m.emphasis_from);
      r.half_v = 0.5 * (z1 - z0);
      r.colour = g.colour;
      out.rects.push_back(r);
      GuideColour text = g.colour;
      text.a = 1;
      const bool closing = n.isApprox(closing_face_normal(arm, mid));
      out.labels.push_back({index, arm, closing ? "push" : "push to open", r.centre + n * 0.5 * r.half_v, text});
    }
  }
}

void add_advantage(const Model& m, int index, const GuideSpec& g, Guides& out) {
  GuideFacts& f = out.facts;
  f.load_at = g.load_at == GuideLoadAt::from ? m.application_from
              : g.load_at == GuideLoadAt::to ? m.application_to
                                             : 0.5 * (m.application_from + m.application_to);
  f.ma_min = std::min(mechanical_advantage(m.emphasis_from, f.load_at), mechanical_advantage(m.emphasis_to, f.load_at));
  f.ma_max = std::max(mechanical_advantage(m.emphasis_from, f.load_at), mechanical_advantage(m.emphasis_to, f.load_at));
  f.ma_arm_min = std::numeric_limits<double>::infinity();
  f.ma_arm_max = 0;
  // The cuts along the arm: every step, and the fulcrum (the advantage is
  // zero there and the pattern changes across it).
  std::vector<double> cuts;
  for (double r = m.arm_from; r < m.arm_to; r += g.step) cuts.push_back(r);
  cuts.push_back(m.arm_to);
  if (m.arm_from < 0 && m.arm_to > 0) cuts.push_back(0);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }),
             cuts.end());
  for (Arm arm : {Arm::fixed, Arm::moving}) {
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double r0 = cuts[i], r1 = cuts[i + 1], mid = 0.5 * (r0 + r1);
      const Vector3d n = closing_face_normal(arm, mid);
      double face = 0, z0 = 0, z1 = 0;
      if (!arm_face(m, arm, r0, r1, n, &face, &z0, &z1)) continue;  // no part there
      const double ma = mechanical_advantage(mid, f.load_at);
      GuideSegment s;
      s.guide = index;
      s.frame = arm;
      const Vector3d off = n * (face + g.lift) + Vector3d(0, 0, 0.5 * (z0 + z1));
      s.a = Vector3d(r0, 0, 0) + off;
      s.b = Vector3d(r1, 0, 0) + off;
      s.colour = advantage_colour(g, ma);
      s.value = ma;
      s.distance = mid;
      out.segments.push_back(s);
      f.ma_arm_min = std::min(f.ma_arm_min, ma);
      f.ma_arm_max = std::max(f.ma_arm_max, ma);
    }
  }
  if (f.ma_arm_max == 0) f.ma_arm_min = 0;
  // Labels at the ends of the emphasis region, on the fixed arm.
  for (double r : {m.emphasis_from, m.emphasis_to}) {
    const double ma = mechanical_advantage(r, f.load_at);
    const Vector3d n = closing_face_normal(Arm::fixed, r);
    double face = 0, z0 = 0, z1 = 0;
    if (!arm_face(m, Arm::fixed, r - 1e-9, r + 1e-9, n, &face, &z0, &z1)) continue;
    const std::string text = ma >= 1 ? "force x" + fixed2(ma) : "distance x" + fixed2(1 / ma);
    GuideColour c = advantage_colour(g, ma);
    c.a = 1;
    out.labels.push_back({index, Arm::fixed, text, Vector3d(r, 0, z1) + n * (face + g.lift), c});
  }
  const Vector3d mark = Vector3d(f.load_at, 0, 0);
  GuideColour c = g.colour;
  c.a = 1;
  out.labels.push_back({index, Arm::fixed, "load", mark, c});
}

}  // namespace

GuideColour advantage_colour(const GuideSpec& spec, double ma) {
  if (!(ma > 0)) return spec.decline;
  const double t = std::clamp(std::log(ma) / std::log(spec.saturate), -1.0, 1.0);
  return t < 0 ? lerp(spec.neutral, spec.decline, -t) : lerp(spec.neutral, spec.amplify, t);
}

Guides compute_guides(const Model& m, const std::vector<GuideSpec>& specs, const std::vector<ActeeFit>& fits) {
  Guides out;
  out.object = m.object_name;
  out.guides = specs;
  out.facts.pattern = m.pattern;
  out.facts.symmetry_point = m.symmetry_point;
  out.facts.symmetry_normal = m.symmetry_normal;
  out.facts.functional_pose = m.object_start;
  out.facts.space = interaction_space(m);
  out.facts.actees = fits;
  for (size_t i = 0; i < specs.size(); ++i) {
    const int index = static_cast<int>(i);
    switch (specs[i].kind) {
      case GuideKind::symmetry_plane: add_symmetry_plane(m, index, specs[i], out); break;
      case GuideKind::interaction_space: add_interaction_space(m, index, specs[i], fits, out); break;
      case GuideKind::emphasis: add_emphasis(m, index, specs[i], out); break;
      case GuideKind::advantage: add_advantage(m, index, specs[i], out); break;
    }
  }
  return out;
}

std::vector<ActeeFit> fit_actees(const ObjectSpec& object, const std::vector<ActeeSpec>& actees) {
  std::vector<ActeeFit> fits;
  for (const ActeeSpec& a : actees) {
    ModelOptions options;
    options.actee.in_jaws = false;  // fit_actee places it itself
    fits.push_back(fit_actee(compile(object, &a, nullptr, options)));
  }
  return fits;
}

std::vector<ActeeSpec> load_actee_folder(const std::string& dir) {
  std::vector<std::string> files;
  if (!std::filesystem::is_directory(dir)) return {};
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<ActeeSpec> actees;
  for (const std::string& file : files) actees.push_back(load_actee(file));
  return actees;
}

Guides posed_guides(const Guides& g, double theta_rad, const Eigen::Isometry3d& object_in_world) {
  Guides out = g;
  const Eigen::Isometry3d moving = object_in_world * moving_arm_pose(theta_rad);
  auto pose = [&](Arm frame) -> const Eigen::Isometry3d& { return frame == Arm::moving ? moving : object_in_world; };
  for (GuideRect& r : out.rects) {
    const Eigen::Isometry3d& p = pose(r.frame);
    r.centre = p * r.centre;
    r.u = p.linear() * r.u;
    r.v = p.linear() * r.v;
    r.normal = p.linear() * r.normal;
    r.frame = Arm::fixed;
  }
  for (GuideMesh& mesh : out.meshes) {
    const Eigen::Isometry3d& p = pose(mesh.frame);
    for (Vector3d& v : mesh.vertices) v = p * v;
    mesh.frame = Arm::fixed;
  }
  for (GuideSegment& s : out.segments) {
    const Eigen::Isometry3d& p = pose(s.frame);
    s.a = p * s.a;
    s.b = p * s.b;
    s.frame = Arm::fixed;
  }
  for (GuideLabel& l : out.labels) {
    l.anchor = pose(l.frame) * l.anchor;
    l.frame = Arm::fixed;
  }
  return out;
}

}  // namespace afford
