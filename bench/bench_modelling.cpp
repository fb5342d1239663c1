// afford model's speed (issue 28: a 100,000-triangle tool in under 2 s on
// one core): the volume, centre and inertia, the search for planes of
// symmetry and the faces it rests on, of a UV ellipsoid of 100,352
// triangles with three unequal axes (240 x 60 x 20 mm, a tool's
// proportions), and of a ball of as many (every direction a candidate for
// a plane, every vertex a corner of the hull: the slowest case). And the
// whole two-part tool (BM_ModelTwoPartTool): two such arms of 50,176
// triangles each, hinged at one end, modelled into its object file (the
// lever from the gap, masses, symmetry, resting faces, convex parts).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include "mass_properties.h"
#include "primitive_meshes.h"
#include "stable_poses.h"
#include "symmetry_planes.h"
#include "tool_model.h"

namespace {

using afford::modelling::TriangleMesh;

void model(benchmark::State& state, const Eigen::Vector3d& radius) {
  const TriangleMesh mesh = afford::modelling::ellipsoid_mesh(radius, 197, 256);  // 100,352 triangles
  size_t planes = 0;
  for (auto _ : state) {
    const auto p = afford::modelling::mass_properties(mesh);
    const auto s = afford::modelling::symmetry_planes(mesh, p);
    const auto poses = afford::modelling::resting_poses(mesh, p.centroid);
    planes = s.planes.size();
    benchmark::DoNotOptimize(planes);
    benchmark::DoNotOptimize(poses.faces.data());
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  state.counters["planes"] = static_cast<double>(planes);
}

void BM_ModelToolMesh(benchmark::State& state) { model(state, {0.120, 0.030, 0.010}); }
void BM_ModelBallMesh(benchmark::State& state) { model(state, {0.020, 0.020, 0.020}); }
// Two arms 200 mm long that bulge towards each other, touching at their
// middles when closed, hinged at x = 0 and opened 0 to 30 deg.
void BM_ModelTwoPartTool(benchmark::State& state) {
  using afford::modelling::ellipsoid_mesh;
  afford::modelling::UrdfTool tool;
  tool.file = "bench";
  tool.limited = true;
  tool.upper = 0.5;
  const TriangleMesh arm = ellipsoid_mesh({0.100, 0.008, 0.008}, 99, 256);  // 50,176 triangles
  afford::modelling::append(tool.fixed, arm, Eigen::Isometry3d(Eigen::Translation3d(0.100, -0.008, 0)));
  afford::modelling::append(tool.moving, arm, Eigen::Isometry3d(Eigen::Translation3d(0.100, 0.008, 0)));
  tool.fixed_pieces.push_back({"fixed", tool.fixed, ""});
  tool.moving_pieces.push_back({"moving", tool.moving, ""});
  afford::modelling::ToolModelOptions options;
  options.name = "bench";
  options.density = 7850;
  size_t parts = 0;
  for (auto _ : state) {
    const auto m = afford::modelling::model_tool(tool, options);
    const std::string text = afford::modelling::object_yaml(m);
    parts = m.parts.size();
    benchmark::DoNotOptimize(text.data());
  }
  state.counters["triangles"] = static_cast<double>(tool.fixed.triangles.size() + tool.moving.triangles.size());
  state.counters["parts"] = static_cast<double>(parts);
}

BENCHMARK(BM_ModelToolMesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ModelTwoPartTool)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ModelBallMesh)->Unit(benchmark::kMillisecond);

}  // namespace
