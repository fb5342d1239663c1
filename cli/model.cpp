// afford model MESH|URDF|FIXED MOVING [--unit mm|cm|m] [--links FIXED,MOVING]
//              [--hinge X,Y,Z,AX,AY,AZ --range MIN,MAX] [--density KG_M3 | --mass G]
//              [--spring K,REST [--spring-at MM]] [--emphasis FROM,TO] [--application FROM,TO]
//              [--symmetry-tolerance R] [--out objects/NAME.yaml] [--json]:
// the modelling steps of the paper (Sec. 3.2). For one rigid mesh: its
// volume and surface (exact for a closed mesh, voxels for an open one), its
// mass, centre of gravity and inertia, its planes of symmetry with how well
// each holds, and how it rests. For a two-part tool (a URDF, or two meshes
// and the hinge): the hinge, its limits, each part's volume, mass and
// inertia about it, the lever found from the shape, and with --out the
// object file (modelling/tool_model.h).
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <numbers>
#include <optional>

#include "commands.h"
#include "cross_section.h"
#include "files.h"
#include "json_output.h"
#include "lever.h"
#include "lever_geometry.h"
#include "mass_properties.h"
#include "mesh_file.h"
#include "mesh_pair.h"
#include "option_checks.h"
#include "output_file.h"
#include "quantity_text.h"
#include "stable_poses.h"
#include "symmetry_planes.h"
#include "tool_model.h"
#include "units.h"
#include "urdf_tool.h"

namespace afford::cli {
namespace {

using modelling::MassProperties;
using modelling::Symmetry;
using modelling::SymmetryPlane;
using modelling::TriangleMesh;

struct ModelOptions {
  std::vector<std::string> inputs;  // one mesh or URDF, or the fixed and the moving mesh
  std::string file, unit, links;  // file: the first input; links: "FIXED,MOVING" of a URDF
  double density = 0, mass_g = 0;  // kg/m^3, g; 0: not given
  double tolerance = modelling::kSymmetryTolerance;
  bool json = false;
  std::string out;                 // the object file to write
  bool force = false;              // --out may replace a file afford did not write (engine/base/output_file.h)
  std::string hinge, range;        // two meshes: "X,Y,Z,AX,AY,AZ" (mm, plain), "MIN,MAX" (deg)
  std::string spring, spring_at;   // "K_N_M_PER_RAD,REST_DEG", "MM"
  std::string emphasis, application;  // "FROM,TO", mm
  std::string rotation;               // "RX,RY,RZ", deg
  bool arm_dynamics = false;          // arm_inertia enabled
};

// Comma-separated numbers, `count` of them (already checked by numbers()).
std::vector<double> numbers_of(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(*parse_number(item));
  return out;
}

CLI::Validator numbers(size_t count, const std::string& what) {
  return CLI::Validator(
      [count, what](std::string& text) -> std::string {
        std::stringstream in(text);
        std::string item;
        size_t n = 0;
        bool ok = !text.empty() && text.back() != ',';
        while (ok && std::getline(in, item, ',')) ok = parse_number(item).has_value() && ++n <= count;
        if (ok && n == count) return "";
        return "expected " + what + ", found '" + text + "'";
      },
      "");  // the type name says the form
}

std::optional<RangeSpec> region_of(const std::string& text, const char* option) {
  if (text.empty()) return std::nullopt;
  const std::vector<double> v = numbers_of(text);
  if (!(v[0] < v[1])) throw std::invalid_argument(std::string(option) + ": FROM below TO, found '" + text + "'");
  return RangeSpec{v[0] * 1e-3, v[1] * 1e-3, {}};
}

std::string direction(const Eigen::Vector3d& v) {
  char buf[96];
  auto clean = [](double x) { return std::abs(x) < 5e-10 ? 0.0 : x; };
  std::snprintf(buf, sizeof buf, "[%.6g, %.6g, %.6g]", clean(v.x()), clean(v.y()), clean(v.z()));
  return buf;
}

Json vec_json(const Eigen::Vector3d& v) { return Json::array({json_number(v.x()), json_number(v.y()), json_number(v.z())}); }

// The unit of a file that does not say its own: a length unit (checked on
// the command line by length_unit()).
std::optional<double> metres_per_unit(const std::string& unit) {
  if (unit.empty()) return std::nullopt;
  std::string error;
  return parse_unit(unit, &error)->si;
}

CLI::Validator length_unit() {
  return CLI::Validator(
      [](std::string& unit) -> std::string {
        std::string error;
        const std::optional<Quantity> u = parse_unit(unit, &error);
        if (u && u->dimension == dim::length) return "";
        return "expected a length unit (mm, cm, m), found '" + unit + "'";
      },
      "UNIT");
}

struct Mass {
  double kg = 0;       // 0: neither --mass nor --density
  double density = 0;  // kg/m^3
  const char* from = "";
};

Mass mass_of(const ModelOptions& o, const MassProperties& p) {
  if (o.mass_g > 0) return {o.mass_g * 1e-3, o.mass_g * 1e-3 / p.volume, "--mass"};
  if (o.density > 0) return {o.density * p.volume, o.density, "--density"};
  return {};
}

void print_plane(const SymmetryPlane& s, double diagonal) {
  std::cout << "    normal " << direction(s.normal) << " through " << qv(s.point, dim::length) << ": the reflection "
            << q(s.score, dim::length) << " RMS from the surface (" << format_quantity(100 * s.score / diagonal, dim::none)
            << " % of the diagonal)\n";
}

// The cross-section on the best plane of symmetry and its lines of symmetry.
void print_section(const modelling::CrossSection& c) {
  if (!c.closed) {
    std::cout << "  cross-section on the best plane: none (" << c.why_not << ")\n";
    return;
  }
  const std::string tol = format_quantity(100 * c.tolerance, dim::none) + " % of its diagonal";
  std::cout << "  cross-section on the best plane: area " << format_quantity(c.area * 1e4, dim::none) << " cm^2, "
            << c.loops.size() << (c.loops.size() == 1 ? " loop" : " loops") << " " << q(c.perimeter, dim::length)
            << " long, centre " << qv(c.centre, dim::length) << "\n";
  auto line = [](const modelling::SectionLine& l) {
    std::cout << "    along " << direction(l.direction) << ": the reflection " << q(l.score, dim::length)
              << " RMS from the boundary (" << format_quantity(100 * l.relative, dim::none) << " % of the diagonal)\n";
  };
  if (c.lines.empty()) {
    std::cout << "  the section has no line of symmetry within " << tol << "; the nearest, through its centre:\n";
    line(c.best);
  } else {
    std::cout << "  the section has " << c.lines.size() << (c.lines.size() == 1 ? " line" : " lines")
              << " of symmetry through its centre (within " << tol << "), best first:\n";
  }
  for (const modelling::SectionLine& l : c.lines) line(l);
}

Json section_json(const modelling::CrossSection& c) {
  Json j{{"normal", vec_json(c.normal)}, {"point_m", vec_json(c.point)}, {"closed", c.closed}};
  if (!c.closed) {
    j["why_not"] = c.why_not;
    return j;
  }
  auto line = [](const modelling::SectionLine& l) {
    return Json{{"direction", vec_json(l.direction)}, {"rms_m", json_number(l.score)}, {"relative", json_number(l.relative)}};
  };
  Json lines = Json::array();
  for (const modelling::SectionLine& l : c.lines) lines.push_back(line(l));
  j["area_m2"] = json_number(c.area);
  j["loops"] = c.loops.size();
  j["perimeter_m"] = json_number(c.perimeter);
  j["centre_m"] = vec_json(c.centre);
  j["lines"] = lines;
  j["best_line"] = line(c.best);
  return j;
}

void print_text(const ModelOptions& o, const TriangleMesh& mesh, const MassProperties& p, const Mass& mass,
                const Symmetry& sym) {
  const double diagonal = (modelling::box_max(mesh) - modelling::box_min(mesh)).norm();
  std::cout << "model of " << mesh.file << ": " << mesh.triangles.size() << " triangles, " << mesh.vertices.size()
            << " vertices" << (o.unit.empty() ? " (in metres, as the file says)" : " (in " + o.unit + ")") << "\n";
  std::cout << "  box " << qv(modelling::box_min(mesh), dim::length) << " to " << qv(modelling::box_max(mesh), dim::length)
            << ", diagonal " << q(diagonal, dim::length) << "\n";
  if (p.exact) {
    std::cout << "  closed and oriented: volume exact from the surface"
              << (p.turned_out ? " (its triangles face inward; taken as the solid they bound)" : "") << "\n";
  } else {
    std::cout << "  not closed (" << p.open_because << "): volume from voxels of " << q(p.voxel_size, dim::length)
              << " (those the surface crosses count half)\n";
  }
  std::cout << "  volume " << format_quantity(p.volume * 1e6, dim::none) << " cm^3, surface "
            << format_quantity(p.surface * 1e4, dim::none) << " cm^2\n";
  std::cout << "  centre of the volume " << qv(p.centroid, dim::length) << "\n";
  if (mass.kg > 0) {
    std::cout << "  mass " << q(mass.kg, dim::mass) << " (from " << mass.from << "; density "
              << format_quantity(mass.density, dim::none) << " kg/m^3)\n";
    const Eigen::Matrix3d inertia = modelling::inertia_about(p, mass.kg, p.centroid);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
    std::cout << "  centre of gravity " << qv(p.centroid, dim::length) << "; principal moments about it:\n";
    for (int k = 0; k < 3; ++k) {
      std::cout << "    " << q(eig.eigenvalues()[k], dim::inertia) << " about " << direction(eig.eigenvectors().col(k))
                << "\n";
    }
  } else {
    std::cout << "  mass: give --mass G or --density KG_M3 for the mass and the inertia\n";
  }
  const std::string tol = format_quantity(100 * sym.tolerance, dim::none) + " % of the diagonal";
  if (sym.every_plane) {
    std::cout << "  symmetric about every plane through its centre (a ball, within " << tol << "); the principal ones:\n";
  } else if (sym.every_plane_through_axis) {
    std::cout << "  symmetric about every plane through the axis " << direction(sym.axis) << " (a body of revolution, within "
              << tol << "); the principal ones:\n";
  } else if (sym.planes.empty()) {
    std::cout << "  no plane of symmetry within " << tol << "; the nearest:\n";
    print_plane(sym.best, diagonal);
  } else {
    std::cout << "  " << sym.planes.size() << (sym.planes.size() == 1 ? " plane" : " planes")
              << " of symmetry (within " << tol << "), best first:\n";
  }
  for (const SymmetryPlane& s : sym.planes) print_plane(s, diagonal);
}

// The resting face that keeps a plane of symmetry parallel to gravity (its
// `down` in the plane, within 3 deg: a smooth body's hull is facets), the
// most stable such; null when none does.
constexpr double kParallelDeg = 3;

const modelling::RestingFace* functioning_face(const modelling::RestingPoses& poses, const Symmetry& sym) {
  const double across = std::sin(kParallelDeg * std::numbers::pi / 180);
  for (const modelling::RestingFace& f : poses.faces) {
    if (sym.every_plane) return &f;
    for (const SymmetryPlane& s : sym.planes) {
      if (std::abs(f.down.dot(s.normal)) <= across) return &f;
    }
  }
  return nullptr;
}

void print_resting(const modelling::RestingPoses& poses, const Symmetry& sym) {
  auto face = [](const modelling::RestingFace& f) {
    return "down " + direction(f.down) + " (gravity in the mesh's frame), the centre " + q(f.height, dim::length) +
           " above the face, " + q(f.margin, dim::length) + " inside its nearest edge";
  };
  std::cout << "  rests on " << poses.faces.size() << (poses.faces.size() == 1 ? " face" : " faces")
            << " of its convex hull (" << poses.hull_corners << " corners";
  if (poses.hull_outside > 0) std::cout << "; vertices up to " << q(poses.hull_outside, dim::length) << " outside it";
  std::cout << ")\n";
  if (poses.faces.empty()) return;
  std::cout << "    most stable: " << face(poses.faces.front()) << "\n";
  const modelling::RestingFace* f = functioning_face(poses, sym);
  if (f != nullptr) {
    std::cout << "    for functioning (a plane of symmetry parallel to gravity within 3 deg, Sec. 4.4): " << face(*f) << "\n";
  } else {
    std::cout << "    for functioning: no resting face keeps a plane of symmetry parallel to gravity\n";
  }
}

Json resting_json(const modelling::RestingFace* f) {
  if (f == nullptr) return nullptr;
  return Json{{"down", vec_json(f->down)}, {"height_m", json_number(f->height)}, {"margin_m", json_number(f->margin)}};
}

Json plane_json(const SymmetryPlane& s) {
  return Json{{"normal", vec_json(s.normal)}, {"point_m", vec_json(s.point)}, {"rms_m", json_number(s.score)},
              {"relative", json_number(s.relative)}};
}

Json report_json(const ModelOptions& o, const TriangleMesh& mesh, const MassProperties& p, const Mass& mass,
                 const Symmetry& sym) {
  Json j;
  j["file"] = mesh.file;
  j["unit"] = o.unit.empty() ? Json("file") : Json(o.unit);
  j["triangles"] = mesh.triangles.size();
  j["vertices"] = mesh.vertices.size();
  j["box_m"] = Json::array({vec_json(modelling::box_min(mesh)), vec_json(modelling::box_max(mesh))});
  j["closed"] = p.exact;
  if (!p.exact) {
    j["open_because"] = p.open_because;
    j["voxel_size_m"] = json_number(p.voxel_size);
  }
  j["faces_inward"] = p.turned_out;
  j["volume_m3"] = json_number(p.volume);
  j["surface_m2"] = json_number(p.surface);
  j["centre_m"] = vec_json(p.centroid);
  if (mass.kg > 0) {
    j["mass_kg"] = json_number(mass.kg);
    j["density_kg_m3"] = json_number(mass.density);
    const Eigen::Matrix3d inertia = modelling::inertia_about(p, mass.kg, p.centroid);
    Json rows = Json::array();
    for (int r = 0; r < 3; ++r) rows.push_back(vec_json(inertia.row(r).transpose()));
    j["inertia_about_centre_kg_m2"] = rows;
  }
  Json planes = Json::array();
  for (const SymmetryPlane& s : sym.planes) planes.push_back(plane_json(s));
  j["symmetry"] = Json{{"tolerance", json_number(sym.tolerance)},
                       {"every_plane", sym.every_plane},
                       {"every_plane_through_axis", sym.every_plane_through_axis ? vec_json(sym.axis) : Json(nullptr)},
                       {"planes", planes},
                       {"best", plane_json(sym.best)}};
  return j;
}

// A two-part tool's parts: the hinge, and each part's volume, mass (the
// given mass shared by volume, or the density), centre and inertia about
// the hinge axis, all in the fixed part's frame with the joint at zero.
struct UrdfPart {
  const char* name;
  const TriangleMesh* mesh;
  MassProperties p;
  double kg = 0;
};

// The tool: a URDF's two links, or two meshes and --hinge; --range gives
// or replaces the joint's limits.
modelling::UrdfTool read_tool(const ModelOptions& o) {
  modelling::UrdfTool tool;
  if (o.inputs.size() == 2) {
    if (o.hinge.empty() || o.range.empty()) {
      throw std::invalid_argument("two meshes (the fixed and the moving part) need --hinge X,Y,Z,AX,AY,AZ and --range MIN,MAX");
    }
    const std::vector<double> h = numbers_of(o.hinge), r = numbers_of(o.range);
    const double rad = std::numbers::pi / 180;
    return modelling::mesh_pair_tool(o.inputs[0], o.inputs[1], metres_per_unit(o.unit),
                                     Eigen::Vector3d(h[0], h[1], h[2]) * 1e-3, Eigen::Vector3d(h[3], h[4], h[5]),
                                     r[0] * rad, r[1] * rad);
  }
  if (!o.hinge.empty()) throw std::invalid_argument("--hinge is for two meshes; a URDF's joint is its hinge");
  std::string fixed, moving;
  if (!o.links.empty()) {
    const size_t comma = o.links.find(',');
    fixed = o.links.substr(0, comma);
    moving = o.links.substr(comma + 1);
  }
  tool = modelling::read_urdf_tool(o.file, fixed, moving);
  if (!o.range.empty()) {
    const std::vector<double> r = numbers_of(o.range);
    if (!(r[0] < r[1])) throw std::invalid_argument("--range: MIN below MAX, found '" + o.range + "'");
    tool.limited = true;
    tool.lower = r[0] * std::numbers::pi / 180;
    tool.upper = r[1] * std::numbers::pi / 180;
  }
  return tool;
}

// The object's name: the --out file's stem, a name as the object format
// takes it.
std::string object_name(const std::string& out) {
  const std::string stem = std::filesystem::path(out).stem().string();
  bool ok = !stem.empty() && (std::isalpha(static_cast<unsigned char>(stem[0])) || stem[0] == '_');
  for (char c : stem) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
  if (!ok) throw std::invalid_argument("--out: a file named as the object is (letters, digits, _ and -), found '" + out + "'");
  return stem;
}

modelling::ToolModelOptions tool_options(const ModelOptions& o) {
  modelling::ToolModelOptions t;
  t.name = o.out.empty() ? "tool" : object_name(o.out);
  if (o.mass_g > 0) t.mass = o.mass_g * 1e-3;
  if (o.density > 0) t.density = o.density;
  if (!o.spring.empty()) {
    const std::vector<double> v = numbers_of(o.spring);
    if (!(v[0] > 0) || !(v[1] > 0) || !(v[1] < 180)) {
      throw std::invalid_argument("--spring: a torsion above 0 N*m/rad and a free opening between 0 and 180 deg, found '" +
                                  o.spring + "'");
    }
    modelling::SpringGiven s{v[0], v[1] * std::numbers::pi / 180, std::nullopt};
    if (!o.spring_at.empty()) s.position = numbers_of(o.spring_at)[0] * 1e-3;
    t.spring = s;
  } else if (!o.spring_at.empty()) {
    throw std::invalid_argument("--spring-at places the spring --spring gives");
  }
  t.regions.emphasis = region_of(o.emphasis, "--emphasis");
  t.regions.application = region_of(o.application, "--application");
  if (!o.rotation.empty()) t.rotation = Eigen::Vector3d(numbers_of(o.rotation).data()) * (std::numbers::pi / 180);
  t.arm_dynamics = o.arm_dynamics;
  t.symmetry_tolerance = o.tolerance;
  return t;
}

std::string region_text(const RangeSpec& r) { return q(r.from, dim::length) + " to " + q(r.to, dim::length); }

void print_lever(const modelling::UrdfTool& tool, const modelling::LeverGeometry& l) {
  std::cout << "  lever (the object frame: the hinge at the origin along +z, the fixed arm along +x):\n";
  std::cout << "    the parts meet at joint angle " << q(0.0 - l.theta_at_zero * l.joint_sign + 0.0, dim::angle)
            << " (opening 0 deg); the joint's limits open it from " << q(l.theta_min, dim::angle) << " to "
            << q(l.theta_max, dim::angle)
            << (l.closes_on_contact ? " (the lower limit closes it further: theta_min is where the parts meet)" : "")
            << "\n";
  double widest = 0, at = 0;
  for (const modelling::GapBin& b : l.gap) {
    if (b.angle > widest) widest = b.angle, at = 0.5 * (b.from + b.to);
  }
  std::cout << "    gap between the closed parts along the arm: 0 deg where they meet, up to " << q(widest, dim::angle)
            << " at " << q(at, dim::length) << "\n";
  std::cout << "    pattern " << pattern_name(l.pattern) << ": jaws (application) " << region_text(l.application)
            << (l.application_found ? " (where the gap is smallest)" : " (as given)") << ", handle (emphasis) "
            << region_text(l.emphasis) << (l.emphasis_found ? " (the other end from the jaws)" : " (as given)")
            << "; the arm " << region_text(l.arm) << "\n";
  (void)tool;
}

void print_model(const modelling::ToolModel& m) {
  std::cout << "  the tool at rest (" << q(m.rest, dim::angle) << "): mass " << q(m.mass(), dim::mass) << " (from "
            << m.mass_from << "), centre of gravity " << qv(m.centre_of_gravity, dim::length)
            << ", the moving part's inertia about the hinge " << q(m.arm_inertia, dim::inertia) << "\n";
  std::cout << "  plane of symmetry" << (m.symmetry.planes.empty() ? " (none within the tolerance; the nearest)" : "")
            << ": normal " << direction(m.plane.normal) << " through " << qv(m.plane.point, dim::length)
            << ", the reflection " << q(m.plane.score, dim::length) << " RMS from the surface\n";
  if (!m.resting.faces.empty()) {
    const modelling::RestingFace& f = m.resting.faces.front();
    std::cout << "  rests most stably on: down " << direction(f.down) << " (object frame), the centre "
              << q(f.height, dim::length) << " above the face, " << q(f.margin, dim::length) << " inside its nearest edge\n";
  }
  std::cout << "  for functioning (the plane of symmetry parallel to gravity, Sec. 4.4): rotation ["
            << q(m.pose_rotation.x(), dim::angle) << ", " << q(m.pose_rotation.y(), dim::angle) << ", "
            << q(m.pose_rotation.z(), dim::angle) << "]\n";
  int fixed = 0;
  for (const modelling::ConvexPart& p : m.parts) fixed += p.arm == Arm::fixed;
  std::cout << "  contact geometry: " << m.parts.size() << " convex parts (" << fixed << " fixed, "
            << m.parts.size() - fixed << " moving)\n";
  const modelling::JawGaps& j = m.jaws;
  std::cout << "  interaction space (L_is) from the shape: the gap between the jaws, mm, at " << j.distances.size()
            << " places from " << q(j.distances.front(), dim::length) << " to " << q(j.distances.back(), dim::length)
            << " along the arm:\n";
  for (size_t a = 0; a < j.angles.size(); ++a) {
    std::cout << "    opening " << q(j.angles[a], dim::angle) << ":";
    for (size_t k = 0; k < j.gap[a].size(); ++k) {
      const double gap = j.gap[a][k] < 1e-9 ? 0.0 : j.gap[a][k];  // m: closed jaws meet to rounding
      std::cout << (k == 0 ? " " : ", ") << format_quantity(gap * 1e3, dim::none);
    }
    std::cout << "\n";
  }
  std::cout << "    fully open the shape's jaws are " << q(j.gap_from(), dim::length) << " to " << q(j.gap_to(), dim::length)
            << " apart (the object file's interaction_space: what guide and explore fit actees in); the wedge of "
               "flat jaws through the pivot (|r| sin theta_max) would be "
            << q(j.wedge_from, dim::length) << " to " << q(j.wedge_to, dim::length) << "\n";
  auto face = [](const char* what, const modelling::FacePlane& f) {
    std::cout << "    " << what << ": ";
    if (!f.found) {
      std::cout << "none (the part has no outline from " << q(f.from, dim::length) << " to " << q(f.to, dim::length) << ")\n";
      return;
    }
    std::cout << "normal " << direction(f.normal) << " through " << qv(f.point, dim::length) << ", from "
              << q(f.from, dim::length) << " to " << q(f.to, dim::length) << ", the face " << q(f.rms < 1e-9 ? 0.0 : f.rms, dim::length)  // m: flat to rounding
              << " RMS off flat\n";
  };
  std::cout << "  contact planes (L_cp, the handles' outer faces) and the support plane (the fixed jaw's face):\n";
  face("fixed handle (object frame)", m.faces.fixed_contact);
  face("moving handle (its arm's frame)", m.faces.moving_contact);
  face("support (object frame)", m.faces.support);
  if (m.spring) {
    std::cout << "  spring: " << q(m.spring->constant, dim::stiffness) << " at " << q(m.spring->position, dim::length)
              << (m.spring->rest_length > 0 ? ", free length " + q(m.spring->rest_length, dim::length)
                                            : ", preload " + q(m.spring->preload, dim::force))
              << "\n";
  } else {
    std::cout << "  spring: none (a URDF or a mesh has none): give --spring K_N_M_PER_RAD,REST_DEG, or fit one with afford "
                 "gap --probe\n";
  }
}

Json lever_json(const modelling::LeverGeometry& l) {
  auto region = [](const RangeSpec& r) { return Json::array({json_number(r.from), json_number(r.to)}); };
  return Json{{"pattern", pattern_name(l.pattern)},
              {"theta_min_rad", json_number(l.theta_min)},
              {"theta_max_rad", json_number(l.theta_max)},
              {"theta_min_from_contact", l.closes_on_contact},
              {"opening_at_joint_zero_rad", json_number(l.theta_at_zero)},
              {"arm_m", region(l.arm)},
              {"application_m", region(l.application)},
              {"application_found", l.application_found},
              {"emphasis_m", region(l.emphasis)},
              {"emphasis_found", l.emphasis_found}};
}

Json face_json(const modelling::FacePlane& f) {
  if (!f.found) return nullptr;
  return Json{{"normal", vec_json(f.normal)}, {"point_m", vec_json(f.point)},
              {"along_m", Json::array({json_number(f.from), json_number(f.to)})}, {"rms_m", json_number(f.rms)}};
}

Json jaws_json(const modelling::JawGaps& j) {
  Json angles = Json::array(), distances = Json::array(), gap = Json::array();
  for (const double a : j.angles) angles.push_back(json_number(a));
  for (const double r : j.distances) distances.push_back(json_number(r));
  for (const auto& row : j.gap) {
    Json g = Json::array();
    for (const double x : row) g.push_back(json_number(x));
    gap.push_back(g);
  }
  return Json{{"angles_rad", angles}, {"distances_m", distances}, {"gap_m", gap},
              {"wedge_m", Json::array({json_number(j.wedge_from), json_number(j.wedge_to)})}};
}

Json model_json(const modelling::ToolModel& m) {
  return Json{{"mass_kg", json_number(m.mass())},
              {"mass_from", m.mass_from},
              {"rest_rad", json_number(m.rest)},
              {"centre_of_gravity_m", vec_json(m.centre_of_gravity)},
              {"arm_inertia_kg_m2", json_number(m.arm_inertia)},
              {"symmetry_plane", plane_json(m.plane)},
              {"functional_rotation_rad", vec_json(m.pose_rotation)},
              {"parts", m.parts.size()},
              {"interaction_space", jaws_json(m.jaws)},
              {"contact_plane_fixed", face_json(m.faces.fixed_contact)},
              {"contact_plane_moving", face_json(m.faces.moving_contact)},
              {"support_plane", face_json(m.faces.support)},
              {"spring", m.spring.has_value()}};
}

int model_two_part(const ModelOptions& o) {
  const modelling::UrdfTool tool = read_tool(o);
  // The meshes a URDF names are inputs too: --out never over one of them.
  std::vector<std::string> inputs = o.inputs;
  for (const auto* pieces : {&tool.fixed_pieces, &tool.moving_pieces}) {
    for (const modelling::NamedMesh& piece : *pieces) {
      if (!piece.mesh_file.empty()) inputs.push_back(piece.mesh_file);
    }
  }
  const OutputScope scope({.writer = "model", .force = o.force, .inputs = inputs});
  UrdfPart parts[2] = {{"fixed", &tool.fixed, modelling::mass_properties(tool.fixed)},
                       {"moving", &tool.moving, modelling::mass_properties(tool.moving)}};
  const double volume = parts[0].p.volume + parts[1].p.volume;
  for (UrdfPart& part : parts) {
    part.kg = o.mass_g > 0 ? o.mass_g * 1e-3 * part.p.volume / volume : o.density * part.p.volume;
  }

  // The lever, and with a mass the whole model: an error with --out, a line
  // of the report without.
  const bool has_mass =
      o.mass_g > 0 || o.density > 0 || (tool.fixed_inertial.given && tool.moving_inertial.given);
  std::optional<modelling::LeverGeometry> lever;
  std::optional<modelling::ToolModel> whole;
  std::string no_lever;
  const modelling::ToolModelOptions options = tool_options(o);
  try {
    if (has_mass || !o.out.empty()) {
      whole = modelling::model_tool(tool, options);
      lever = whole->lever;
    } else {
      lever = modelling::lever_geometry(tool, options.regions);
    }
  } catch (const DataError& e) {
    if (!o.out.empty()) throw;
    no_lever = e.what();
  }

  if (o.json) {
    Json j;
    j["file"] = o.file;
    j["joint"] = tool.joint;
    j["hinge"] = Json{{"point_m", vec_json(tool.hinge_point)},
                      {"axis", vec_json(tool.hinge_axis)},
                      {"limits_rad", tool.limited ? Json::array({json_number(tool.lower), json_number(tool.upper)})
                                                  : Json(nullptr)}};
    for (const UrdfPart& part : parts) {
      Json pj{{"link", part.name == std::string("fixed") ? tool.fixed_link : tool.moving_link},
              {"triangles", part.mesh->triangles.size()},
              {"closed", part.p.exact},
              {"volume_m3", json_number(part.p.volume)},
              {"centre_m", vec_json(part.p.centroid)}};
      if (part.kg > 0) {
        const Eigen::Matrix3d I = modelling::inertia_about(part.p, part.kg, tool.hinge_point);
        pj["mass_kg"] = json_number(part.kg);
        pj["inertia_about_hinge_kg_m2"] = json_number(tool.hinge_axis.dot(I * tool.hinge_axis));
      }
      j[part.name] = pj;
    }
    j["lever"] = lever ? lever_json(*lever) : Json(no_lever);
    if (whole) j["model"] = model_json(*whole);
    std::cout << j.dump() << "\n";
  } else {
    std::cout << "model of " << o.file << ": joint '" << tool.joint << "' turns link '" << tool.moving_link
              << "' (moving) against '" << tool.fixed_link << "' (fixed); in the fixed link's frame, the joint at 0:\n";
    std::cout << "  hinge through " << qv(tool.hinge_point, dim::length) << " about " << direction(tool.hinge_axis);
    if (tool.limited) {
      std::cout << ", from " << q(tool.lower, dim::angle) << " to " << q(tool.upper, dim::angle) << "\n";
    } else {
      std::cout << ", continuous (no limits)\n";
    }
    for (const UrdfPart& part : parts) {
      std::cout << "  " << part.name << " part: " << part.mesh->triangles.size() << " triangles, "
                << (part.p.exact ? "closed" : "not closed (voxels of " + q(part.p.voxel_size, dim::length) + ")")
                << ", volume " << format_quantity(part.p.volume * 1e6, dim::none) << " cm^3, centre "
                << qv(part.p.centroid, dim::length) << "\n";
      if (part.kg > 0) {
        const Eigen::Matrix3d I = modelling::inertia_about(part.p, part.kg, tool.hinge_point);
        std::cout << "    mass " << q(part.kg, dim::mass) << ", inertia about the hinge "
                  << q(tool.hinge_axis.dot(I * tool.hinge_axis), dim::inertia) << "\n";
      }
    }
    if (parts[0].kg > 0) {
      const Eigen::Vector3d centre = (parts[0].kg * parts[0].p.centroid + parts[1].kg * parts[1].p.centroid) /
                                     (parts[0].kg + parts[1].kg);
      std::cout << "  the tool: mass " << q(parts[0].kg + parts[1].kg, dim::mass) << ", centre of gravity "
                << qv(centre, dim::length) << "\n";
    } else if (!has_mass) {
      std::cout << "  mass: give --mass G (shared by volume) or --density KG_M3\n";
    }
    if (lever) {
      print_lever(tool, *lever);
    } else {
      std::cout << "  lever: not found: " << no_lever << "\n";
    }
    if (whole) print_model(*whole);
  }
  if (!o.out.empty()) {
    write_file_checked(o.out, modelling::object_yaml(*whole));  // WriteError names the file, exit 1
    std::cout << (o.json ? "" : "wrote ") << (o.json ? "" : o.out + "\n");
  }
  return 0;
}

// Coordinates below 1e-12 of the mesh's size are the sums' rounding: 0.
Eigen::Vector3d tidy(Eigen::Vector3d v, double size) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(v[k]) < 1e-12 * size) v[k] = 0;
  }
  return v;
}

bool is_urdf(const std::string& file) {
  return file.size() >= 5 && (file.compare(file.size() - 5, 5, ".urdf") == 0 || file.compare(file.size() - 5, 5, ".URDF") == 0);
}

int model_rigid(const ModelOptions& o) {
  if (!o.links.empty()) return usage_error("model: --links names the links of a URDF; " + o.file + " is a mesh");
  if (o.arm_dynamics) return usage_error("model: --arm-dynamics is for a two-part tool; " + o.file + " is one mesh");
  for (const std::string* two_part :
       {&o.out, &o.hinge, &o.range, &o.spring, &o.spring_at, &o.emphasis, &o.application, &o.rotation}) {
    if (!two_part->empty()) {
      return usage_error("model: --out, --hinge, --range, --spring, --rotation and the regions are for a two-part tool (a URDF, or "
                         "two meshes); " + o.file + " is one mesh");
    }
  }
  const TriangleMesh mesh = modelling::read_mesh(o.file, metres_per_unit(o.unit));
  const double size = (modelling::box_max(mesh) - modelling::box_min(mesh)).norm();
  MassProperties p = modelling::mass_properties(mesh);
  const Mass mass = mass_of(o, p);
  Symmetry sym = modelling::symmetry_planes(mesh, p, o.tolerance);
  p.centroid = tidy(p.centroid, size);
  for (SymmetryPlane& plane : sym.planes) plane.point = tidy(plane.point, size);
  sym.best.point = tidy(sym.best.point, size);
  const modelling::RestingPoses poses = modelling::resting_poses(mesh, p.centroid);
  modelling::CrossSection section = modelling::cross_section(mesh, sym.best.normal, sym.best.point, o.tolerance);
  section.centre = tidy(section.centre, size);
  if (o.json) {
    Json j = report_json(o, mesh, p, mass, sym);
    j["cross_section"] = section_json(section);
    j["resting"] = Json{{"faces", poses.faces.size()},
                        {"hull_corners", poses.hull_corners},
                        {"hull_outside_m", json_number(poses.hull_outside)},
                        {"most_stable", resting_json(poses.faces.empty() ? nullptr : &poses.faces.front())},
                        {"functioning", resting_json(functioning_face(poses, sym))}};
    std::cout << j.dump() << "\n";
  } else {
    print_text(o, mesh, p, mass, sym);
    print_section(section);
    print_resting(poses, sym);
  }
  return 0;
}

int model(ModelOptions o) {
  o.file = o.inputs.front();
  const OutputScope scope({.writer = "model", .force = o.force, .inputs = o.inputs});  // --out never over an input
  try {
    if (o.inputs.size() == 2 || is_urdf(o.file)) {
      if (o.inputs.size() == 2 && !o.links.empty()) return usage_error("model: --links names the links of a URDF");
      return model_two_part(o);
    }
    return model_rigid(o);
  } catch (const std::invalid_argument& e) {
    return usage_error(std::string("model: ") + e.what());
  }
}

}  // namespace

void add_model(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "model",
      "model an object from its mesh (volume, mass, centre of gravity, inertia, planes of symmetry) or a two-part tool "
      "from its URDF or two meshes (the hinge and its limits, each part's mass and inertia about the hinge, the lever "
      "pattern and the jaws and handle found from the gap between the parts; --out writes the object file)");
  auto o = std::make_shared<ModelOptions>();
  cmd->add_option("INPUT", o->inputs,
                  "a mesh file (OBJ, STL, PLY with --unit; DAE, glTF), a URDF of a two-part tool, or two meshes: the "
                  "fixed and the moving part (with --hinge and --range)")
      ->required()
      ->expected(1, 2)
      ->type_name(kFile);
  cmd->add_option("--out", o->out, "write the two-part tool's object file (objects/NAME.yaml; NAME is the object's name)")
      ->type_name(kFile);
  cmd->add_flag("--force", o->force, "with --out: replace an existing file that afford did not write");
  cmd->add_option("--hinge", o->hinge,
                  "two meshes: the hinge's point in mm and its axis (plain numbers) in the meshes' frame; the moving "
                  "part opens by the right-hand rule about the axis")
      ->type_name("X,Y,Z,AX,AY,AZ")
      ->check(numbers(6, "six numbers X,Y,Z,AX,AY,AZ"));
  cmd->add_option("--range", o->range,
                  "the moving part's turn about the hinge, deg, from its pose in the file (two meshes; replaces a URDF "
                  "joint's limits)")
      ->type_name("MIN,MAX")
      ->check(numbers(2, "two angles MIN,MAX in deg"));
  cmd->add_option("--spring", o->spring,
                  "the spring a URDF or a mesh lacks: its torsional stiffness about the hinge, N*m/rad, and the opening, "
                  "deg, at which it pushes nothing (above theta_max it holds the tool open with a preload)")
      ->type_name("K_N_M_PER_RAD,REST_DEG")
      ->check(numbers(2, "K_N_M_PER_RAD,REST_DEG"));
  cmd->add_option("--spring-at", o->spring_at,
                  "where the spring sits on the arm, mm from the hinge (signed; default the middle of the handle)")
      ->type_name("MM")
      ->check(numbers(1, "a distance in mm"));
  cmd->add_flag("--arm-dynamics", o->arm_dynamics,
                "switch on the arm_inertia effect (the moving part's inertia about the hinge, written either way); "
                "without it the lever is quasi-static, as the shipped tools are");
  cmd->add_option("--rotation", o->rotation,
                  "the functional pose's rotation, deg about world x, then y, then z, instead of the plane of symmetry "
                  "upright")
      ->type_name("RX,RY,RZ")
      ->check(numbers(3, "three angles RX,RY,RZ in deg"));
  cmd->add_option("--emphasis", o->emphasis, "the handle (where the hand pushes), mm along the arm, instead of found")
      ->type_name("FROM,TO")
      ->check(numbers(2, "FROM,TO in mm"));
  cmd->add_option("--application", o->application,
                  "the jaws (where the actee sits), mm along the arm, instead of found from the gap")
      ->type_name("FROM,TO")
      ->check(numbers(2, "FROM,TO in mm"));
  cmd->add_option("--links", o->links, "a URDF's fixed and moving links, where it has more than one revolute joint")
      ->type_name("FIXED,MOVING")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            const size_t comma = v.find(',');
            if (comma == std::string::npos || comma == 0 || comma + 1 == v.size() || v.find(',', comma + 1) != std::string::npos) {
              return "expected two link names, FIXED,MOVING, found '" + v + "'";
            }
            return "";
          },
          "FIXED,MOVING"));
  cmd->add_option("--unit", o->unit, "the length unit of an OBJ, STL or PLY file (mm, cm, m)")
      ->type_name("UNIT")
      ->check(length_unit());
  auto* density = cmd->add_option("--density", o->density, "the material's density, kg/m^3 (water 1000, steel 7850)")
                      ->type_name("KG_M3")
                      ->check(CLI::Range(1e-3, 3e4));
  cmd->add_option("--mass", o->mass_g, "the object's mass, g")->type_name("G")->check(CLI::Range(1e-6, 1e7))->excludes(density);
  cmd->add_option("--symmetry-tolerance", o->tolerance,
                  "how far a reflected surface may lie from the surface and still be symmetric, as a fraction of the "
                  "box's diagonal (default 0.01)")
      ->type_name("R")
      ->check(CLI::Range(1e-9, 0.5));
  cmd->add_flag("--json", o->json, "print the model as JSON");
  cmd->callback([run, o] { *run = [o] { return model(*o); }; });
}

}  // namespace afford::cli
