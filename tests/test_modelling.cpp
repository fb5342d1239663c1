// afford model's static steps (issue 28, paper Sec. 3.2 steps 2-3): a
// mesh's volume, surface, centre and inertia, exact for closed meshes and
// from voxels for open ones, and its planes of symmetry; every figure
// worked by hand for a box, an L-shape, a cube and a ball.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

#include "cross_section.h"
#include "errors.h"
#include "mass_properties.h"
#include "mesh_file.h"
#include "primitive_meshes.h"
#include "stable_poses.h"
#include "symmetry_planes.h"
#include "test_util.h"
#include "urdf_tool.h"

namespace afford::test {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;
using modelling::TriangleMesh;

// A mesh written to a file of the temporary folder, removed afterwards.
class MeshFile {
 public:
  MeshFile(const std::string& name, const std::string& text)
      : path_(fs::temp_directory_path() / ("afford_model_" + std::to_string(::getpid()) + "_" + name)) {
    std::ofstream(path_, std::ios::binary) << text;
  }
  ~MeshFile() { fs::remove(path_); }
  MeshFile(const MeshFile&) = delete;
  MeshFile& operator=(const MeshFile&) = delete;
  std::string path() const { return path_.string(); }

 private:
  fs::path path_;
};

struct Obj {
  std::vector<Vector3d> v;
  std::vector<std::array<int, 3>> f;
  // A quad a b c d, counter-clockwise seen from outside, as two triangles.
  void quad(int a, int b, int c, int d) {
    f.push_back({a, b, c});
    f.push_back({a, c, d});
  }
  std::string text() const {
    std::string s;
    char buf[128];
    for (const Vector3d& p : v) {
      std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
      s += buf;
    }
    for (const auto& t : f) {
      std::snprintf(buf, sizeof buf, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
      s += buf;
    }
    return s;
  }
};

// A prism: the polygon `outline` (counter-clockwise in x-y) from z0 to z1,
// its side faces as quads and its caps as fans (the outline must be
// star-shaped from its first vertex).
Obj prism(const std::vector<Eigen::Vector2d>& outline, double z0, double z1) {
  Obj o;
  const int n = static_cast<int>(outline.size());
  for (const auto& p : outline) o.v.emplace_back(p.x(), p.y(), z0);
  for (const auto& p : outline) o.v.emplace_back(p.x(), p.y(), z1);
  for (int i = 0; i < n; ++i) o.quad(i, (i + 1) % n, n + (i + 1) % n, n + i);
  for (int i = 1; i + 1 < n; ++i) {
    o.f.push_back({0, i + 1, i});              // bottom, seen from below
    o.f.push_back({n, n + i, n + i + 1});      // top
  }
  return o;
}

Obj box(const Vector3d& lo, const Vector3d& hi) {
  return prism({{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}}, lo.z(), hi.z());
}

// A UV ball of radius r about c: `rings` bands of `slices` quads.
Obj ball(double r, const Vector3d& c, int rings, int slices) {
  const TriangleMesh m = modelling::sphere_mesh(r, rings, slices);
  Obj o;
  for (const Vector3d& v : m.vertices) o.v.push_back(c + v);
  o.f = m.triangles;
  return o;
}

TriangleMesh read(const Obj& o, const std::string& name) {
  const MeshFile file(name, o.text());
  return modelling::read_mesh(file.path(), 0.001);  // millimetres
}

bool has_normal(const modelling::Symmetry& s, const Vector3d& n, double tol) {
  for (const auto& p : s.planes) {
    if (std::abs(std::abs(p.normal.dot(n.normalized())) - 1) < tol) return true;
  }
  return false;
}

TEST(ModelMesh, ABoxWorkedByHand) {
  // 40 x 20 x 10 mm from (-15, -4, 2) mm: volume 8000 mm^3, surface
  // 2 (800 + 400 + 200) = 2800 mm^2, centre (5, 6, 7) mm. With 100 g its
  // moments are m/12 (b^2 + c^2): 0.1/12 (20^2 + 10^2) mm^2 = 4.1667e-6,
  // 0.1/12 (40^2 + 10^2) = 1.4167e-5, 0.1/12 (40^2 + 20^2) = 1.6667e-5 kg*m^2.
  const TriangleMesh mesh = read(box({-15, -4, 2}, {25, 16, 12}), "box.obj");
  const auto p = modelling::mass_properties(mesh);
  EXPECT_TRUE(p.exact);
  EXPECT_FALSE(p.turned_out);
  EXPECT_NEAR(p.volume / 8000e-9, 1, 1e-12);
  EXPECT_NEAR(p.surface / 2800e-6, 1, 1e-12);
  EXPECT_NEAR((p.centroid - Vector3d(5e-3, 6e-3, 7e-3)).norm(), 0, 1e-15);
  const Eigen::Matrix3d I = modelling::inertia_about(p, 0.1, p.centroid);
  EXPECT_NEAR(I(0, 0) / (0.1 / 12 * (4e-4 + 1e-4)), 1, 1e-12);
  EXPECT_NEAR(I(1, 1) / (0.1 / 12 * (16e-4 + 1e-4)), 1, 1e-12);
  EXPECT_NEAR(I(2, 2) / (0.1 / 12 * (16e-4 + 4e-4)), 1, 1e-12);
  EXPECT_NEAR(I(0, 1), 0, 1e-18);
  // Three planes of symmetry, across each side, through the centre.
  const auto s = modelling::symmetry_planes(mesh, p);
  ASSERT_EQ(s.planes.size(), 3u);
  for (const Vector3d& n : {Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1)}) EXPECT_TRUE(has_normal(s, n, 1e-12));
  for (const auto& plane : s.planes) {
    EXPECT_LT(plane.relative, 1e-9);
    EXPECT_NEAR((plane.point - p.centroid).norm(), 0, 1e-15);
  }
  // About its centre (5, 6, 7) mm, by the parallel axis theorem: the x
  // moment grows by m (6^2 + 7^2) mm^2 = 0.1 * 85e-6 = 8.5e-6 kg*m^2.
  const Eigen::Matrix3d I0 = modelling::inertia_about(p, 0.1, Vector3d::Zero());
  EXPECT_NEAR(I0(0, 0) - I(0, 0), 8.5e-6, 1e-18);
  EXPECT_NEAR(I0(0, 1), -0.1 * 5e-3 * 6e-3, 1e-18);
}

TEST(ModelMesh, AnLShapeHasOnePlane) {
  // An L of 60 x 10 mm and 10 x 30 mm (legs unequal), 8 mm thick: its
  // outline from (0, 0): (60, 0), (60, 10), (10, 10), (10, 40), (0, 40).
  // Areas 600 and 300 mm^2: the 600 centred at (30, 5), the upright 10 x 30
  // at (5, 25): centre ((600*30 + 300*5)/900, (600*5 + 300*25)/900) =
  // (21.667, 11.667) mm, volume 900 * 8 = 7200 mm^3. Only the plane half
  // way through its thickness is a plane of symmetry.
  const TriangleMesh mesh = read(prism({{0, 0}, {60, 0}, {60, 10}, {10, 10}, {10, 40}, {0, 40}}, -4, 4), "l.obj");
  const auto p = modelling::mass_properties(mesh);
  EXPECT_NEAR(p.volume / 7200e-9, 1, 1e-12);
  EXPECT_NEAR((p.centroid - Vector3d(65e-3 / 3, 35e-3 / 3, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR(p.surface / (2 * 900e-6 + 8e-3 * 200e-3), 1, 1e-12);  // the outline is 200 mm round
  const auto s = modelling::symmetry_planes(mesh, p);
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_TRUE(has_normal(s, Vector3d::UnitZ(), 1e-12));
  EXPECT_LT(s.planes[0].relative, 1e-9);
}

// A line of the section with this direction (either sign), within `tol`.
bool has_line(const modelling::CrossSection& c, const Vector3d& d, double tol) {
  for (const auto& l : c.lines) {
    if (std::abs(std::abs(l.direction.dot(d.normalized())) - 1) < tol) return true;
  }
  return false;
}

TEST(ModelSection, ABoxCutThroughItsCentreOnEachPlane) {
  // tests/data/meshes/box.obj: 40 x 20 x 10 mm about (5, 6, 7) mm. Across x
  // the section is 20 x 10 = 200 mm^2, 60 mm round; across y 40 x 10 = 400
  // mm^2, 100 mm; across z 40 x 20 = 800 mm^2, 120 mm. A rectangle that is
  // not a square has two lines of symmetry, along its sides.
  const TriangleMesh mesh = modelling::read_mesh(AFFORD_SOURCE_DIR "/tests/data/meshes/box.obj", 0.001);
  const Vector3d centre(5e-3, 6e-3, 7e-3);
  const double area[3] = {200e-6, 400e-6, 800e-6}, round[3] = {60e-3, 100e-3, 120e-3};
  for (int k = 0; k < 3; ++k) {
    const auto c = modelling::cross_section(mesh, Vector3d::Unit(k), centre);
    ASSERT_TRUE(c.closed) << c.why_not;
    EXPECT_EQ(c.loops.size(), 1u);
    EXPECT_NEAR(c.area / area[k], 1, 1e-12);
    EXPECT_NEAR(c.perimeter / round[k], 1, 1e-12);
    EXPECT_NEAR((c.centre - centre).norm(), 0, 1e-15);
    ASSERT_EQ(c.lines.size(), 2u) << "across axis " << k;
    EXPECT_TRUE(has_line(c, Vector3d::Unit((k + 1) % 3), 1e-12));
    EXPECT_TRUE(has_line(c, Vector3d::Unit((k + 2) % 3), 1e-12));
    EXPECT_LT(c.best.relative, 1e-12);
  }
}

TEST(ModelSection, TheUnequalLHasNoLineOfSymmetry) {
  // tests/data/meshes/l-shape.obj on its plane of symmetry z = 0: the L
  // itself, 600 + 300 = 900 mm^2, 200 mm round, centred at (21.667, 11.667)
  // mm; legs of 60 and 30 mm: no line maps it onto itself. Cut across the
  // upright leg at x = 5 mm: 40 x 8 = 320 mm^2, 96 mm round, centre (5, 20, 0).
  const TriangleMesh mesh = modelling::read_mesh(AFFORD_SOURCE_DIR "/tests/data/meshes/l-shape.obj", 0.001);
  const auto c = modelling::cross_section(mesh, Vector3d::UnitZ(), Vector3d(0.02, 0.01, 0));
  ASSERT_TRUE(c.closed) << c.why_not;
  EXPECT_NEAR(c.area / 900e-6, 1, 1e-12);
  EXPECT_NEAR(c.perimeter / 200e-3, 1, 1e-12);
  EXPECT_NEAR((c.centre - Vector3d(65e-3 / 3, 35e-3 / 3, 0)).norm(), 0, 1e-15);
  EXPECT_TRUE(c.lines.empty());
  EXPECT_GT(c.best.relative, modelling::kSymmetryTolerance);
  const auto across = modelling::cross_section(mesh, Vector3d::UnitX(), Vector3d(5e-3, 0, 0));
  ASSERT_TRUE(across.closed) << across.why_not;
  EXPECT_NEAR(across.area / 320e-6, 1, 1e-12);
  EXPECT_NEAR(across.perimeter / 96e-3, 1, 1e-12);
  EXPECT_NEAR((across.centre - Vector3d(5e-3, 20e-3, 0)).norm(), 0, 1e-15);
  EXPECT_EQ(across.lines.size(), 2u);
}

TEST(ModelSection, AnEqualLIsSymmetricAboutItsDiagonal) {
  // Legs 40 x 10 and 10 x 30 mm from the corner (0, 0): 400 mm^2 at (20, 5)
  // and 300 mm^2 at (5, 25): 700 mm^2 centred at (9500/700, 9500/700) mm,
  // on the diagonal, its one line of symmetry. The diagonal plane cuts the
  // corner square along its diagonal: 10 sqrt 2 x 8 mm = 113.14 mm^2.
  const TriangleMesh mesh = read(prism({{0, 0}, {40, 0}, {40, 10}, {10, 10}, {10, 40}, {0, 40}}, -4, 4), "equal-l.obj");
  const double at = 9.5e-3 / 0.7;
  const auto c = modelling::cross_section(mesh, Vector3d::UnitZ(), Vector3d::Zero());
  ASSERT_TRUE(c.closed) << c.why_not;
  EXPECT_NEAR(c.area / 700e-6, 1, 1e-12);
  EXPECT_NEAR((c.centre - Vector3d(at, at, 0)).norm(), 0, 1e-15);
  ASSERT_EQ(c.lines.size(), 1u);
  EXPECT_TRUE(has_line(c, Vector3d(1, 1, 0), 1e-12));
  const auto diagonal = modelling::cross_section(mesh, Vector3d(1, -1, 0).normalized(), Vector3d(at, at, 0));
  ASSERT_TRUE(diagonal.closed) << diagonal.why_not;
  EXPECT_NEAR(diagonal.area / (10e-3 * std::sqrt(2.0) * 8e-3), 1, 1e-12);
  EXPECT_NEAR(diagonal.perimeter / (2 * (10e-3 * std::sqrt(2.0) + 8e-3)), 1, 1e-12);
}

TEST(ModelSection, ASquareTubeHasAHoleAndFourLines) {
  // A 30 mm cube with a 10 mm cube hollowed out of its middle (the inner
  // box's triangles turned to face into the void): cut half way, the
  // square ring of 900 - 100 = 800 mm^2, 120 + 40 mm round. Its equal
  // moments send the search round every direction: four lines, along the
  // sides and the diagonals.
  Obj o = box({0, 0, 0}, {30, 30, 30});
  const Obj inner = box({10, 10, 10}, {20, 20, 20});
  const int offset = static_cast<int>(o.v.size());
  for (const Vector3d& v : inner.v) o.v.push_back(v);
  for (const auto& t : inner.f) o.f.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  const TriangleMesh mesh = read(o, "hollow.obj");
  const auto c = modelling::cross_section(mesh, Vector3d::UnitZ(), Vector3d(0, 0, 15e-3));
  ASSERT_TRUE(c.closed) << c.why_not;
  EXPECT_EQ(c.loops.size(), 2u);
  EXPECT_NEAR(c.area / 800e-6, 1, 1e-12);
  EXPECT_NEAR(c.perimeter / 160e-3, 1, 1e-12);
  EXPECT_NEAR((c.centre - Vector3d(15e-3, 15e-3, 15e-3)).norm(), 0, 1e-15);
  ASSERT_EQ(c.lines.size(), 4u);
  for (const Vector3d& d : {Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(1, 1, 0), Vector3d(1, -1, 0)}) {
    EXPECT_TRUE(has_line(c, d, 1e-9)) << d.transpose();
  }
}

TEST(ModelSection, AnOpenCutOrAMissedMeshSaysWhy) {
  Obj o = box({0, 0, 0}, {40, 20, 10});
  o.f.erase(o.f.begin());  // a side triangle, which the plane z = 5 mm cuts
  const auto open = modelling::cross_section(read(o, "open-box.obj"), Vector3d::UnitZ(), Vector3d(0, 0, 5e-3));
  EXPECT_FALSE(open.closed);
  EXPECT_THAT(open.why_not, ::testing::HasSubstr("does not close (the mesh is open there)"));
  EXPECT_TRUE(open.loops.empty());
  const TriangleMesh whole = read(box({0, 0, 0}, {40, 20, 10}), "whole-box.obj");
  const auto missed = modelling::cross_section(whole, Vector3d::UnitZ(), Vector3d(0, 0, 0.5));
  EXPECT_FALSE(missed.closed);
  EXPECT_EQ(missed.why_not, "the plane does not cut the mesh");
}

TEST(ModelMesh, WhereABoxAndAnLRest) {
  // The 40 x 20 x 10 mm box rests on each of its six faces; most stably on
  // a 40 x 20 face (either), its centre 5 mm up and 10 mm from the nearest
  // edge.
  const TriangleMesh box_mesh = read(box({-15, -4, 2}, {25, 16, 12}), "box.obj");
  const auto b = modelling::resting_poses(box_mesh, modelling::mass_properties(box_mesh).centroid);
  ASSERT_EQ(b.faces.size(), 6u);
  EXPECT_EQ(b.hull_corners, 8);
  EXPECT_EQ(b.hull_outside, 0.0);
  EXPECT_NEAR(std::abs(b.faces[0].down.z()), 1, 1e-12);
  EXPECT_NEAR(b.faces[0].height, 5e-3, 1e-15);
  EXPECT_NEAR(b.faces[0].margin, 10e-3, 1e-15);
  EXPECT_NEAR(b.faces[0].area, 800e-6, 1e-15);
  // The L (AnLShapeHasOnePlane) lies flat most stably: 4 mm up, its centre
  // (21.667, 11.667) mm 11.667 mm from the hull's nearest edge, y = 0. On
  // its side the hull's five sides hold it where the centre's foot falls
  // inside: y = 0, x = 0 and the slope from (60, 10) to (10, 40); not
  // x = 60 (its foot at y = 11.7 is past the 10 mm side) nor y = 40 (x =
  // 21.7 past 10). 2 + 3 = 5 faces.
  const TriangleMesh l = read(prism({{0, 0}, {60, 0}, {60, 10}, {10, 10}, {10, 40}, {0, 40}}, -4, 4), "l.obj");
  const auto r = modelling::resting_poses(l, modelling::mass_properties(l).centroid);
  ASSERT_EQ(r.faces.size(), 5u);
  EXPECT_EQ(r.hull_corners, 10);  // the inner corner (10, 10) is not one
  EXPECT_NEAR(std::abs(r.faces[0].down.z()), 1, 1e-12);
  EXPECT_NEAR(r.faces[0].height, 4e-3, 1e-15);
  EXPECT_NEAR(r.faces[0].margin, 35e-3 / 3, 1e-15);
}

TEST(ModelMesh, ACubeHasNinePlanes) {
  // Three across its faces and six through opposite edges; its three
  // moments are equal, so the search spreads over every direction.
  const TriangleMesh mesh = read(box({0, 0, 0}, {20, 20, 20}), "cube.obj");
  const auto p = modelling::mass_properties(mesh);
  const auto s = modelling::symmetry_planes(mesh, p);
  EXPECT_FALSE(s.every_plane);
  ASSERT_EQ(s.planes.size(), 9u);
  for (const Vector3d& n : {Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1), Vector3d(1, 1, 0),
                            Vector3d(1, -1, 0), Vector3d(1, 0, 1), Vector3d(1, 0, -1), Vector3d(0, 1, 1),
                            Vector3d(0, 1, -1)}) {
    EXPECT_TRUE(has_normal(s, n, 1e-9)) << n.transpose();
  }
}

TEST(ModelMesh, ABallIsSymmetricAboutEveryPlane) {
  // A UV ball of 20 mm about (1, 2, 3) mm: its volume approaches
  // 4/3 pi r^3 = 33,510 mm^3 from below (a polyhedron inside the ball),
  // within 1 % at 48 x 96; its centre is the ball's by symmetry, to the
  // single precision Assimp reads vertices in (20 mm * 6e-8 = 1.2 nm).
  const TriangleMesh mesh = read(ball(20, {1, 2, 3}, 48, 96), "ball.obj");
  const auto p = modelling::mass_properties(mesh);
  const double exact = 4.0 / 3 * std::numbers::pi * 20e-3 * 20e-3 * 20e-3;
  EXPECT_LT(p.volume, exact);
  EXPECT_GT(p.volume, 0.99 * exact);
  EXPECT_NEAR((p.centroid - Vector3d(1e-3, 2e-3, 3e-3)).norm(), 0, 1e-9);
  const auto s = modelling::symmetry_planes(mesh, p);
  EXPECT_TRUE(s.every_plane);
  EXPECT_FALSE(s.planes.empty());
}

TEST(ModelMesh, TrianglesFacingInwardBoundTheSameSolid) {
  Obj o = box({0, 0, 0}, {30, 20, 10});
  for (auto& t : o.f) std::swap(t[1], t[2]);
  const auto p = modelling::mass_properties(read(o, "inward.obj"));
  EXPECT_TRUE(p.turned_out);
  EXPECT_NEAR(p.volume / 6000e-9, 1, 1e-12);
  EXPECT_NEAR((p.centroid - Vector3d(15e-3, 10e-3, 5e-3)).norm(), 0, 1e-15);
}

TEST(ModelMesh, AnOpenMeshIsFilledAsVoxels) {
  // The ball with one small triangle gone (a hole of a scan): not closed,
  // so voxels of 40 mm / 160 = 0.25 mm fill it; the hole is smaller than a
  // voxel, so the outside does not leak in. Volume within 2 %, centre
  // within a voxel.
  Obj o = ball(20, {0, 0, 0}, 48, 96);
  o.f.erase(o.f.begin() + 500);
  const TriangleMesh mesh = read(o, "holed.obj");
  const auto p = modelling::mass_properties(mesh);
  EXPECT_FALSE(p.exact);
  EXPECT_THAT(p.open_because, ::testing::HasSubstr("is run by 1 triangle(s) one way and 0 the other"));
  EXPECT_NEAR(p.voxel_size, 40e-3 / 160, 1e-15);
  const double exact = 4.0 / 3 * std::numbers::pi * 20e-3 * 20e-3 * 20e-3;
  EXPECT_NEAR(p.volume / exact, 1, 0.02);
  EXPECT_LT(p.centroid.norm(), p.voxel_size);
}

TEST(ModelMesh, AnSTLIsWeldedIntoAClosedSurface) {
  // STL repeats every vertex per triangle; read, they are one again.
  const Obj o = box({0, 0, 0}, {10, 10, 10});
  std::string stl(80, '\0');
  auto put = [&](const void* p, size_t n) { stl.append(static_cast<const char*>(p), n); };
  const std::uint32_t count = static_cast<std::uint32_t>(o.f.size());
  put(&count, 4);
  for (const auto& t : o.f) {
    const float normal[3] = {0, 0, 0};
    put(normal, sizeof normal);
    for (int k = 0; k < 3; ++k) {
      const float v[3] = {static_cast<float>(o.v[t[k]].x()), static_cast<float>(o.v[t[k]].y()),
                          static_cast<float>(o.v[t[k]].z())};
      put(v, sizeof v);
    }
    const std::uint16_t attribute = 0;
    put(&attribute, 2);
  }
  const MeshFile file("cube.stl", stl);
  const TriangleMesh mesh = modelling::read_mesh(file.path(), 0.001);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_TRUE(modelling::closure(mesh).closed);
  EXPECT_NEAR(modelling::mass_properties(mesh).volume / 1000e-9, 1, 1e-12);
}

std::string read_error(const std::string& path, std::optional<double> unit = 0.001) {
  return thrown<DataError>([&] { (void)modelling::read_mesh(path, unit); });
}

TEST(ModelMeshErrors, EachNamesTheFileAndWhatWasWrong) {
  const MeshFile nan("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_THAT(read_error(nan.path()), ::testing::HasSubstr("expected finite vertex coordinates, found vertex 0"));
  const MeshFile empty("empty.obj", "");
  EXPECT_THAT(read_error(empty.path()), ::testing::StartsWith(empty.path() + ":"));
  const MeshFile points("points.obj", "v 0 0 0\nv 1 0 0\n");
  EXPECT_THAT(read_error(points.path()), ::testing::HasSubstr("expected a mesh"));
  EXPECT_THAT(read_error(fs::temp_directory_path().string()), ::testing::HasSubstr("found a directory"));
  EXPECT_THAT(read_error("/nonexistent/tool.obj"), ::testing::HasSubstr("found no such file"));
  const MeshFile other("tool.fbx", "x");
  EXPECT_THAT(read_error(other.path()), ::testing::HasSubstr("expected an OBJ, STL, PLY, DAE or glTF"));
  const MeshFile box_file("box.obj", box({0, 0, 0}, {1, 1, 1}).text());
  EXPECT_THAT(read_error(box_file.path(), std::nullopt),
              ::testing::HasSubstr("expected --unit mm or --unit m (OBJ, STL and PLY do not say their unit)"));
  const MeshFile gltf("tool.gltf", "{}");
  EXPECT_THAT(read_error(gltf.path()), ::testing::HasSubstr("expected no --unit for a DAE or glTF file"));
  // A flat surface, closed but bounding nothing.
  Obj flat;
  flat.v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  flat.f = {{0, 1, 2}, {0, 2, 1}};
  const MeshFile flat_file("flat.obj", flat.text());
  EXPECT_THAT(thrown<DataError>([&] { (void)modelling::mass_properties(modelling::read_mesh(flat_file.path(), 1.0)); }),
              ::testing::HasSubstr("expected a mesh that bounds a volume"));
}

TEST(ModelMeshErrors, AFileOverTheCapIsRefusedBeforeItIsRead) {
  // 101 MiB, sparse: refused by its size, not parsed.
  const MeshFile big("big.stl", "");
  fs::resize_file(big.path(), (101u << 20));
  EXPECT_THAT(read_error(big.path()), ::testing::HasSubstr("expected a mesh file of at most 100 MiB, found 101 MiB"));
}

// tests/data/urdf/two-arms: PartNet-Mobility's layout (a base link, a fixed
// joint to link_0, a revolute joint to link_1, OBJ meshes in metres).
TEST(ModelUrdf, TwoArmsWorkedByHand) {
  // The hinge 10 mm along the fixed arm, about z, 0 to 30 deg. Each arm is
  // 100 x 10 x 8 mm (8 cm^3): with 100 g shared by volume, 50 g each. The
  // moving arm spans x 0 to 100 mm, y 0 to 10 mm in the fixed frame, so
  // its centre is (50, 5, 0) mm and its inertia about the hinge axis is
  // m/12 (a^2 + b^2) + m d^2 = 0.05/12 (0.1^2 + 0.01^2)
  // + 0.05 ((0.05 - 0.01)^2 + 0.005^2) = 4.2083e-5 + 8.125e-5
  // = 1.2333e-4 kg*m^2. The files' single precision bounds the match.
  const modelling::UrdfTool tool = modelling::read_urdf_tool(AFFORD_SOURCE_DIR "/tests/data/urdf/two-arms/mobility.urdf");
  EXPECT_EQ(tool.joint, "joint_1");
  EXPECT_EQ(tool.fixed_link, "link_0");
  EXPECT_EQ(tool.moving_link, "link_1");
  EXPECT_NEAR((tool.hinge_point - Vector3d(0.01, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((tool.hinge_axis - Vector3d::UnitZ()).norm(), 0, 1e-12);
  EXPECT_TRUE(tool.limited);
  EXPECT_EQ(tool.lower, 0.0);
  EXPECT_NEAR(tool.upper, std::numbers::pi / 6, 1e-15);
  const auto moving = modelling::mass_properties(tool.moving);
  EXPECT_NEAR(moving.volume / 8e-6, 1, 1e-6);
  EXPECT_NEAR((moving.centroid - Vector3d(0.05, 0.005, 0)).norm(), 0, 1e-8);
  const Eigen::Matrix3d I = modelling::inertia_about(moving, 0.05, tool.hinge_point);
  EXPECT_NEAR(I(2, 2) / 1.23333333e-4, 1, 1e-6);
  const auto fixed = modelling::mass_properties(tool.fixed);
  EXPECT_NEAR((fixed.centroid - Vector3d(0.05, -0.005, 0)).norm(), 0, 1e-8);
}

std::string urdf_error(const std::string& xml, const std::string& fixed = "", const std::string& moving = "") {
  const MeshFile file("tool.urdf", xml);
  return thrown<DataError>([&] { (void)modelling::read_urdf_tool(file.path(), fixed, moving); });
}

const std::string kArms = R"(<robot name="t">
  <link name="a"><collision><geometry><box size="0.1 0.01 0.008"/></geometry></collision></link>
  <link name="b"><collision><geometry><cylinder radius="0.005" length="0.1"/></geometry></collision></link>
  <joint name="j" type="JOINT_TYPE"><parent link="a"/><child link="b"/><axis xyz="AXIS"/>
    <limit lower="0" upper="0.5" effort="1" velocity="1"/></joint>
</robot>)";

std::string arms(const std::string& type, const std::string& axis) {
  return replace_once(replace_once(kArms, "JOINT_TYPE", type), "AXIS", axis);
}

// Each error is located at the element it is about: the joint at 4:3,
// link a at 2:3, the document's <robot> at 1:1.
TEST(ModelUrdfErrors, EachNamesTheFileAndTheElement) {
  EXPECT_THAT(urdf_error(arms("fixed", "0 0 1")),
              ::testing::HasSubstr(".urdf:1:1: expected one revolute (or continuous) joint, or --links FIXED,MOVING, found none"));
  EXPECT_THAT(urdf_error(arms("revolute", "0 0 1"), "a", "c"), ::testing::HasSubstr(":1:1: expected a link 'c', found none"));
  EXPECT_THAT(urdf_error("<robot name='t'><link name='a'/>"), ::testing::HasSubstr(":1:1: expected a URDF urdfdom can read"));
  EXPECT_THAT(urdf_error(replace_once(arms("revolute", "0 0 1"), "<box size=\"0.1 0.01 0.008\"/>",
                                      "<mesh filename=\"missing.obj\"/>")),
              ::testing::HasSubstr(".urdf:2:3: expected link 'a' to name a mesh afford can read"));
  EXPECT_THAT(thrown<DataError>([] { (void)modelling::read_urdf_tool(fs::temp_directory_path().string()); }),
              ::testing::HasSubstr(fs::temp_directory_path().string() + ": expected"));
  const std::string zero = urdf_error(arms("revolute", "0 0 0"));
  EXPECT_THAT(zero, ::testing::StartsWith(fs::temp_directory_path().string()));
  EXPECT_THAT(zero, ::testing::HasSubstr(".urdf:4:3: expected an axis of some length in joint 'j', found (0.000000, 0.000000, 0.000000)"));
  EXPECT_THAT(urdf_error(replace_once(arms("revolute", "0 0 1"), "upper=\"0.5\"", "upper=\"-0.5\"")),
              ::testing::HasSubstr(".urdf:4:3: expected a lower limit below the upper in joint 'j'"));
  // A joint from a link to itself (found by fuzz_urdf; it threw
  // std::out_of_range).
  EXPECT_THAT(urdf_error(replace_once(arms("revolute", "0 0 1"), "<parent link=\"a\"/>", "<parent link=\"b\"/>")),
              ::testing::HasSubstr(".urdf:4:3: expected two links in joint 'j', found link 'b' on both sides"));
}

TEST(ModelUrdf, PrimitivesStandForMeshes) {
  // Link b is a cylinder of radius 5 mm and length 100 mm: with 48 sides,
  // its volume is 48/2 sin(2 pi/48) r^2 l = 7.8284e-6 m^3 (the inscribed
  // polygon's area times the length).
  const MeshFile file("prims.urdf", arms("continuous", "0 0 1"));
  const modelling::UrdfTool tool = modelling::read_urdf_tool(file.path());
  EXPECT_FALSE(tool.limited);
  const double polygon = 24 * std::sin(2 * std::numbers::pi / 48) * 25e-6;
  EXPECT_NEAR(modelling::mass_properties(tool.moving).volume / (polygon * 0.1), 1, 1e-12);
  EXPECT_NEAR(modelling::mass_properties(tool.fixed).volume / 8e-6, 1, 1e-12);
}

}  // namespace
}  // namespace afford::test
