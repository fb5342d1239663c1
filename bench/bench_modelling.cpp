// afford model's speed (issue 28: a 100,000-triangle tool in under 2 s on
// one core): the volume, centre and inertia, the search for planes of
// symmetry and the faces it rests on, of a UV ellipsoid of 100,352
// triangles with three unequal axes (240 x 60 x 20 mm, a tool's
// proportions), and of a ball of as many (every direction a candidate for
// a plane, every vertex a corner of the hull: the slowest case).
#include <benchmark/benchmark.h>

#include "mass_properties.h"
#include "primitive_meshes.h"
#include "stable_poses.h"
#include "symmetry_planes.h"

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
BENCHMARK(BM_ModelToolMesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ModelBallMesh)->Unit(benchmark::kMillisecond);

}  // namespace
