#include "urdf_tool.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

#include "errors.h"
#include "files.h"
#include "mesh_file.h"
#include "primitive_meshes.h"

namespace afford::modelling {
namespace {

namespace fs = std::filesystem;
using Eigen::Isometry3d;
using Eigen::Vector3d;

constexpr size_t kMaxUrdfBytes = 16u << 20;  // a description, not its meshes

// The URDF's path and text: errors name the element they are about by its
// place in the text (urdfdom keeps no lines).
struct UrdfText {
  std::string path, xml;

  // Where the first <tag whose name attribute is `name` starts (any <tag
  // for an empty name); the file's start where there is none.
  SourceLoc at(const std::string& tag, const std::string& name = "") const {
    size_t pos = 0;
    while ((pos = xml.find("<" + tag, pos)) != std::string::npos) {
      const size_t after = pos + 1 + tag.size();
      const bool whole = after < xml.size() && (std::isspace(static_cast<unsigned char>(xml[after])) ||
                                                xml[after] == '>' || xml[after] == '/');
      const std::string head = xml.substr(pos, xml.find('>', pos) - pos);
      if (whole && (name.empty() || head.find("name=\"" + name + "\"") != std::string::npos ||
                    head.find("name='" + name + "'") != std::string::npos)) {
        break;
      }
      ++pos;
    }
    if (pos == std::string::npos) return {path, 1, 1};
    const size_t newline = pos == 0 ? std::string::npos : xml.rfind('\n', pos - 1);
    const int line = 1 + static_cast<int>(std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    const int column = static_cast<int>(pos - (newline == std::string::npos ? 0 : newline + 1)) + 1;
    return {path, line, column};
  }
};

// urdfdom says why it could not read a file through console_bridge: the
// last error it logged becomes the found part of our error.
class LastError : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) last = text;
  }
  std::string last;
};

Isometry3d pose_of(const urdf::Pose& p) {
  Isometry3d t = Isometry3d::Identity();
  t.translation() = Vector3d(p.position.x, p.position.y, p.position.z);
  t.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized().toRotationMatrix();
  return t;
}

// A mesh's file: "package://pkg/path" and plain paths are taken beside
// the URDF (and for package:// also one folder up, the package's root).
std::string mesh_path(const std::string& urdf, const std::string& name) {
  const fs::path here = fs::path(urdf).parent_path();
  std::string rest = name;
  if (rest.rfind("file://", 0) == 0) return rest.substr(7);
  if (rest.rfind("package://", 0) == 0) {
    rest = rest.substr(10);
    const size_t slash = rest.find('/');
    const std::string inside = slash == std::string::npos ? rest : rest.substr(slash + 1);
    if (fs::exists(here / inside)) return (here / inside).string();
    return (here.parent_path() / rest).string();
  }
  return fs::path(name).is_absolute() ? name : (here / name).string();
}

TriangleMesh geometry_mesh(const UrdfText& urdf, const std::string& link, const urdf::Geometry& g) {
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(g);
      return box_mesh(Vector3d(b.dim.x, b.dim.y, b.dim.z));
    }
    case urdf::Geometry::SPHERE:
      return sphere_mesh(static_cast<const urdf::Sphere&>(g).radius);
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      return cylinder_mesh(c.radius, c.length);
    }
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(g);
      const std::string path = mesh_path(urdf.path, m.filename);
      TriangleMesh mesh;
      try {
        mesh = read_mesh(path, format_says_unit(path) ? std::nullopt : std::optional<double>(1.0));
      } catch (const DataError& e) {
        fail(urdf.at("link", link), "link '" + link + "' to name a mesh afford can read", e.what());
      }
      const Vector3d scale(m.scale.x, m.scale.y, m.scale.z);
      for (Vector3d& v : mesh.vertices) v = v.cwiseProduct(scale);
      if (scale.prod() < 0) {  // a mirroring scale turns the triangles inside out
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
      }
      return mesh;
    }
  }
  fail(urdf.at("link", link), "a box, sphere, cylinder or mesh in link '" + link + "'", "another geometry");
}

// One element's geometry, placed, added to the link's mesh and kept as a
// piece of its own.
void add_element(const UrdfText& urdf, const std::string& link, const std::string& name, const urdf::Geometry& g,
                 const Isometry3d& pose, TriangleMesh& out, std::vector<NamedMesh>& pieces) {
  NamedMesh piece{name, {}, {}};
  piece.mesh.file = urdf.path;
  if (g.type == urdf::Geometry::MESH) piece.mesh_file = mesh_path(urdf.path, static_cast<const urdf::Mesh&>(g).filename);
  append(piece.mesh, geometry_mesh(urdf, link, g), pose);
  append(out, piece.mesh, Isometry3d::Identity());
  pieces.push_back(std::move(piece));
}

// The link's collision geometry (its visual where it has none), in the
// frame `pose` puts the link in.
void add_link(const UrdfText& urdf, const urdf::Link& link, const Isometry3d& pose, TriangleMesh& out,
              std::vector<NamedMesh>& pieces) {
  bool any = false;
  for (const auto& c : link.collision_array) {
    if (!c || !c->geometry) continue;
    add_element(urdf, link.name, c->name, *c->geometry, pose * pose_of(c->origin), out, pieces);
    any = true;
  }
  if (!any) {
    for (const auto& v : link.visual_array) {
      if (!v || !v->geometry) continue;
      add_element(urdf, link.name, v->name, *v->geometry, pose * pose_of(v->origin), out, pieces);
      any = true;
    }
  }
  if (!any) fail(urdf.at("link", link.name), "collision or visual geometry in link '" + link.name + "'", "none");
}

// The link's <inertial> in the frame `pose` puts the link in; a mass that
// is not positive or an inertia that is not finite is an error at the link.
LinkInertial inertial_of(const UrdfText& urdf, const urdf::Link& link, const Isometry3d& pose) {
  LinkInertial out;
  if (!link.inertial) return out;
  const urdf::Inertial& i = *link.inertial;
  Eigen::Matrix3d tensor;
  tensor << i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz;
  if (!(i.mass > 0) || !std::isfinite(i.mass) || !tensor.allFinite()) {
    fail(urdf.at("link", link.name), "a positive mass and a finite inertia in the <inertial> of link '" + link.name + "'",
         "mass " + std::to_string(i.mass));
  }
  const Isometry3d at = pose * pose_of(i.origin);
  out.given = true;
  out.mass = i.mass;
  out.centre = at.translation();
  out.inertia = at.linear() * tensor * at.linear().transpose();
  return out;
}

// urdfdom's links hold their children by shared pointer, so a joint from a
// link to itself, which it accepts, makes a loop never freed: every link's
// children are let go when the reading ends, however it ends.
struct CutChildLinks {
  urdf::ModelInterface& model;
  ~CutChildLinks() {
    for (auto& [name, link] : model.links_) link->child_links.clear();
  }
};

// Each link's frame in the root link's, every joint at zero. A link met
// twice (urdfdom can leave a joint whose parent is its child) is placed
// once: a loop ends.
void place_links(const urdf::Link& link, const Isometry3d& pose, std::map<std::string, Isometry3d>& out) {
  if (!out.emplace(link.name, pose).second) return;
  for (const auto& child : link.child_links) {
    const auto& joint = child->parent_joint;
    place_links(*child, pose * pose_of(joint->parent_to_joint_origin_transform), out);
  }
}

}  // namespace

UrdfTool read_urdf_tool(const std::string& path, const std::string& fixed, const std::string& moving) {
  const UrdfText urdf{path, read_regular_file(path, kMaxUrdfBytes)};  // DataError: missing, a directory, too large
  LastError errors;
  console_bridge::useOutputHandler(&errors);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf.xml);
  console_bridge::restorePreviousOutputHandler();
  if (!model) fail(urdf.at("robot"), "a URDF urdfdom can read", errors.last.empty() ? "it could not" : shorten(errors.last));
  const CutChildLinks cut_at_exit{*model};

  // The joint: the one revolute (or continuous) joint, or the one between
  // the named links.
  urdf::JointConstSharedPtr joint;
  int hinges = 0;
  for (const auto& [name, j] : model->joints_) {
    const bool hinge = j->type == urdf::Joint::REVOLUTE || j->type == urdf::Joint::CONTINUOUS;
    if (fixed.empty()) {
      if (!hinge) continue;
      ++hinges;
      joint = j;
    } else if ((j->parent_link_name == fixed && j->child_link_name == moving) ||
               (j->parent_link_name == moving && j->child_link_name == fixed)) {
      if (!hinge) {
        fail(urdf.at("joint", name), "a revolute joint between '" + fixed + "' and '" + moving + "'", "joint '" + name + "'");
      }
      joint = j;
    }
  }
  if (fixed.empty() && hinges != 1) {
    fail(urdf.at("robot"), "one revolute (or continuous) joint, or --links FIXED,MOVING",
               hinges == 0 ? "none" : std::to_string(hinges));
  }
  if (!fixed.empty()) {
    for (const std::string& name : {fixed, moving}) {
      if (!model->getLink(name)) fail(urdf.at("robot"), "a link '" + name + "'", "none");
    }
    if (!joint) fail(urdf.at("robot"), "a joint between links '" + fixed + "' and '" + moving + "'", "none");
  }

  UrdfTool tool;
  tool.file = path;
  tool.joint = joint->name;
  const bool forward = fixed.empty() || joint->parent_link_name == fixed;
  tool.fixed_link = forward ? joint->parent_link_name : joint->child_link_name;
  tool.moving_link = forward ? joint->child_link_name : joint->parent_link_name;
  const Vector3d axis(joint->axis.x, joint->axis.y, joint->axis.z);
  if (!(axis.norm() > 1e-9) || !axis.allFinite()) {
    fail(urdf.at("joint", joint->name), "an axis of some length in joint '" + joint->name + "'", "(" + std::to_string(axis.x()) + ", " +
                                                                             std::to_string(axis.y()) + ", " +
                                                                             std::to_string(axis.z()) + ")");
  }
  tool.limited = joint->type == urdf::Joint::REVOLUTE;
  if (tool.limited) {
    if (!joint->limits) fail(urdf.at("joint", joint->name), "limits in revolute joint '" + joint->name + "'", "none");
    tool.lower = joint->limits->lower;
    tool.upper = joint->limits->upper;
    if (!(tool.lower < tool.upper)) {
      fail(urdf.at("joint", joint->name), "a lower limit below the upper in joint '" + joint->name + "'",
                 std::to_string(tool.lower) + " and " + std::to_string(tool.upper));
    }
  }

  if (tool.fixed_link == tool.moving_link) {
    fail(urdf.at("joint", joint->name), "two links in joint '" + joint->name + "'", "link '" + tool.fixed_link + "' on both sides");
  }
  std::map<std::string, Isometry3d> frames;
  place_links(*model->getRoot(), Isometry3d::Identity(), frames);
  for (const std::string& link : {tool.fixed_link, tool.moving_link}) {
    if (!frames.count(link)) {
      fail(urdf.at("joint", joint->name), "links in the tree of the root link '" + model->getRoot()->name + "'",
           "link '" + link + "' outside it");
    }
  }
  const Isometry3d to_fixed = frames.at(tool.fixed_link).inverse();
  const Isometry3d joint_frame = to_fixed * frames.at(joint->parent_link_name) *
                                 pose_of(joint->parent_to_joint_origin_transform);
  tool.hinge_point = joint_frame.translation();
  tool.hinge_axis = (joint_frame.linear() * axis).normalized();
  tool.fixed.file = tool.moving.file = path;
  const Isometry3d moving_pose = to_fixed * frames.at(tool.moving_link);
  add_link(urdf, *model->getLink(tool.fixed_link), Isometry3d::Identity(), tool.fixed, tool.fixed_pieces);
  add_link(urdf, *model->getLink(tool.moving_link), moving_pose, tool.moving, tool.moving_pieces);
  tool.fixed_inertial = inertial_of(urdf, *model->getLink(tool.fixed_link), Isometry3d::Identity());
  tool.moving_inertial = inertial_of(urdf, *model->getLink(tool.moving_link), moving_pose);
  if (joint->dynamics) {
    tool.friction = joint->dynamics->friction;
    tool.damping = joint->dynamics->damping;
    if (!(tool.friction >= 0) || !(tool.damping >= 0)) {
      fail(urdf.at("joint", joint->name), "a friction and a damping of 0 or more in the <dynamics> of joint '" + joint->name + "'",
           std::to_string(tool.friction) + " and " + std::to_string(tool.damping));
    }
  }
  return tool;
}

}  // namespace afford::modelling
