// afford model MESH|URDF [--unit mm|cm|m] [--links FIXED,MOVING]
//                        [--density KG_M3 | --mass G] [--symmetry-tolerance R] [--json]:
// the static modelling steps of the paper (Sec. 3.2, steps 2 and 3) for one
// rigid mesh: its volume and surface (exact for a closed mesh, voxels for
// an open one), its mass, centre of gravity and inertia, and its planes of
// symmetry with how well each holds. For a URDF of a two-part tool: the
// hinge, its limits, and each part's volume, mass and inertia about it.
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <optional>

#include "commands.h"
#include "json_output.h"
#include "mass_properties.h"
#include "mesh_file.h"
#include "option_checks.h"
#include "stable_poses.h"
#include "symmetry_planes.h"
#include "units.h"
#include "urdf_tool.h"

namespace afford::cli {
namespace {

using modelling::MassProperties;
using modelling::Symmetry;
using modelling::SymmetryPlane;
using modelling::TriangleMesh;

struct ModelOptions {
  std::string file, unit, links;  // links: "FIXED,MOVING" of a URDF
  double density = 0, mass_g = 0;  // kg/m^3, g; 0: not given
  double tolerance = modelling::kSymmetryTolerance;
  bool json = false;
};

std::string q(double si, const Dimension& d) { return format_quantity(si, d); }

std::string qv(const Eigen::Vector3d& v, const Dimension& d) {
  return "[" + q(v.x(), d) + ", " + q(v.y(), d) + ", " + q(v.z(), d) + "]";
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

// A URDF's two parts: the hinge, and each part's volume, mass (the given
// mass shared by volume, or the density), centre and inertia about the
// hinge axis, all in the fixed link's frame with the joint at zero.
struct UrdfPart {
  const char* name;
  const TriangleMesh* mesh;
  MassProperties p;
  double kg = 0;
};

int model_urdf(const ModelOptions& o) {
  std::string fixed, moving;
  if (!o.links.empty()) {
    const size_t comma = o.links.find(',');
    fixed = o.links.substr(0, comma);
    moving = o.links.substr(comma + 1);
  }
  const modelling::UrdfTool tool = modelling::read_urdf_tool(o.file, fixed, moving);
  UrdfPart parts[2] = {{"fixed", &tool.fixed, modelling::mass_properties(tool.fixed)},
                       {"moving", &tool.moving, modelling::mass_properties(tool.moving)}};
  const double volume = parts[0].p.volume + parts[1].p.volume;
  for (UrdfPart& part : parts) {
    part.kg = o.mass_g > 0 ? o.mass_g * 1e-3 * part.p.volume / volume : o.density * part.p.volume;
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
    std::cout << j.dump() << "\n";
    return 0;
  }
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
  } else {
    std::cout << "  mass: give --mass G (shared by volume) or --density KG_M3\n";
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

int model(const ModelOptions& o) {
  if (is_urdf(o.file)) return model_urdf(o);
  if (!o.links.empty()) return usage_error("model: --links names the links of a URDF; " + o.file + " is a mesh");
  const TriangleMesh mesh = modelling::read_mesh(o.file, metres_per_unit(o.unit));
  const double size = (modelling::box_max(mesh) - modelling::box_min(mesh)).norm();
  MassProperties p = modelling::mass_properties(mesh);
  const Mass mass = mass_of(o, p);
  Symmetry sym = modelling::symmetry_planes(mesh, p, o.tolerance);
  p.centroid = tidy(p.centroid, size);
  for (SymmetryPlane& plane : sym.planes) plane.point = tidy(plane.point, size);
  sym.best.point = tidy(sym.best.point, size);
  const modelling::RestingPoses poses = modelling::resting_poses(mesh, p.centroid);
  if (o.json) {
    Json j = report_json(o, mesh, p, mass, sym);
    j["resting"] = Json{{"faces", poses.faces.size()},
                        {"hull_corners", poses.hull_corners},
                        {"hull_outside_m", json_number(poses.hull_outside)},
                        {"most_stable", resting_json(poses.faces.empty() ? nullptr : &poses.faces.front())},
                        {"functioning", resting_json(functioning_face(poses, sym))}};
    std::cout << j.dump() << "\n";
  } else {
    print_text(o, mesh, p, mass, sym);
    print_resting(poses, sym);
  }
  return 0;
}

}  // namespace

void add_model(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "model",
      "model an object from its mesh (volume, mass, centre of gravity, inertia, planes of symmetry) or a two-part tool "
      "from its URDF (the hinge and its limits, each part's mass and inertia about the hinge)");
  auto o = std::make_shared<ModelOptions>();
  cmd->add_option("INPUT", o->file, "a mesh file (OBJ, STL, PLY with --unit; DAE, glTF) or a URDF of a two-part tool")->required()->type_name(kFile);
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
