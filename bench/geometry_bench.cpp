// Geometry core benchmarks: evaluation, subdivision, wavelet decomposition, mass properties.
// Each family has a "baseline" variant measured in the same run; see ratio_reporter.h.
#include <vector>

#include <Eigen/Dense>
#include <benchmark/benchmark.h>

#include "engine/core/random.h"
#include "engine/geometry/boundary_validity.h"
#include "engine/geometry/mass_properties.h"
#include "engine/geometry/multiresolution.h"
#include "engine/geometry/periodic_bspline.h"
#include "engine/geometry/shapes.h"
#include "engine/geometry/subdivision.h"
#include "ratio_reporter.h"

namespace rugosim {
namespace {

std::vector<Vec2> blob(std::size_t n) {
  return blob_control_points(1.0, 0.5, n, 17);
}

std::vector<double> random_parameters(std::size_t count, double period) {
  Rng rng(3);
  std::vector<double> u(count);
  for (double& x : u)
    x = rng.uniform(0.0, period);
  return u;
}

// Baseline: the paper's eq. (1)-(2) as written, [t^3 t^2 t 1]·M·C_j / 6 at every call.
void eval_baseline(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto points = blob(n);
  const PeriodicBSpline curve(points);
  const auto params = random_parameters(4096, static_cast<double>(n));
  Eigen::Matrix4d m;
  m << -1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0;
  for (auto _ : state) {
    Vec2 sum = Vec2::Zero();
    for (double u : params) {
      const CurveParam p = curve.locate(u);
      Eigen::Matrix<double, 4, 2> cj;
      for (std::size_t k = 0; k < 4; ++k)
        cj.row(static_cast<Eigen::Index>(k)) = points[(p.segment + n - 1 + k) % n];
      const Eigen::RowVector4d powers(p.t * p.t * p.t, p.t * p.t, p.t, 1.0);
      sum += (powers * m * cj / 6.0).transpose();
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(params.size()));
}

// The cached power basis, point only and point with both derivatives.
void eval_power_basis(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const PeriodicBSpline curve(blob(n));
  const auto params = random_parameters(4096, static_cast<double>(n));
  for (auto _ : state) {
    Vec2 sum = Vec2::Zero();
    for (double u : params)
      sum += curve.point_at(u);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(params.size()));
}

void eval_point_and_derivatives(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const PeriodicBSpline curve(blob(n));
  const auto params = random_parameters(4096, static_cast<double>(n));
  for (auto _ : state) {
    Vec2 sum = Vec2::Zero();
    for (double u : params) {
      const CurveParam p = curve.locate(u);
      const CubicSegment& s = curve.segment(p.segment);
      sum += s.point(p.t) + s.derivative(p.t) + s.second_derivative(p.t);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(params.size()));
}

// Baseline for curve-sized work: copying the control points and building the curve's caches.
void curve_baseline(benchmark::State& state) {
  const auto points = blob(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    PeriodicBSpline curve(points);
    benchmark::DoNotOptimize(curve.segments().data());
  }
}

void curve_subdivide_points(benchmark::State& state) {
  const auto points = blob(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    auto fine = subdivide_control_points(points);
    benchmark::DoNotOptimize(fine.data());
  }
}

void curve_subdivide_and_build(benchmark::State& state) {
  const PeriodicBSpline curve(blob(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state) {
    PeriodicBSpline fine = subdivide(curve, 1);
    benchmark::DoNotOptimize(fine.segments().data());
  }
}

// Wavelets, against one level of subdivision of the same coarse count (the synthesis with
// zero details costs about as much, so the ratio shows what the details and analysis add).
void wavelet_baseline(benchmark::State& state) {
  const auto fine = blob(static_cast<std::size_t>(state.range(0)));
  const auto coarse = decompose(fine).coarse;
  for (auto _ : state) {
    auto out = subdivide_control_points(coarse);
    benchmark::DoNotOptimize(out.data());
  }
}

void wavelet_decompose(benchmark::State& state) {
  const auto fine = blob(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    auto level = decompose(fine);
    benchmark::DoNotOptimize(level.coarse.data());
  }
}

void wavelet_reconstruct(benchmark::State& state) {
  const auto level = decompose(blob(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state) {
    auto out = reconstruct(level.coarse, level.details);
    benchmark::DoNotOptimize(out.data());
  }
}

void wavelet_all_levels(benchmark::State& state) {
  const auto fine = blob(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    Multiresolution levels(fine);
    benchmark::DoNotOptimize(levels.control_points(levels.level_count()).data());
  }
}

// Mass properties, against the shoelace area of the control polygon (one pass over the points:
// the least any whole-curve computation can cost).
void mass_baseline(benchmark::State& state) {
  const auto points = blob(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    double twice_area = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      twice_area += cross(points[i], points[(i + 1) % points.size()]);
    }
    benchmark::DoNotOptimize(twice_area);
  }
}

void mass_exact_green(benchmark::State& state) {
  const PeriodicBSpline curve(blob(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state) {
    const MassProperties props = compute_mass_properties(curve);
    benchmark::DoNotOptimize(props.polar_moment);
  }
}

void mass_validity(benchmark::State& state) {
  const PeriodicBSpline curve(blob(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state) {
    const ValidityReport report = check_boundary(curve);
    benchmark::DoNotOptimize(report.valid);
  }
}

#define RUGOSIM_SIZES RangeMultiplier(4)->Range(16, 1024)
BENCHMARK(eval_baseline)->Name("eval/baseline")->RUGOSIM_SIZES;
BENCHMARK(eval_power_basis)->Name("eval/power_basis")->RUGOSIM_SIZES;
BENCHMARK(eval_point_and_derivatives)->Name("eval/point_d1_d2")->RUGOSIM_SIZES;
BENCHMARK(curve_baseline)->Name("curve/baseline")->RUGOSIM_SIZES;
BENCHMARK(curve_subdivide_points)->Name("curve/subdivide_points")->RUGOSIM_SIZES;
BENCHMARK(curve_subdivide_and_build)->Name("curve/subdivide_and_build")->RUGOSIM_SIZES;
BENCHMARK(wavelet_baseline)->Name("wavelet/baseline")->RUGOSIM_SIZES;
BENCHMARK(wavelet_decompose)->Name("wavelet/decompose")->RUGOSIM_SIZES;
BENCHMARK(wavelet_reconstruct)->Name("wavelet/reconstruct")->RUGOSIM_SIZES;
BENCHMARK(wavelet_all_levels)->Name("wavelet/all_levels")->RUGOSIM_SIZES;
BENCHMARK(mass_baseline)->Name("whole_curve/baseline")->RUGOSIM_SIZES;
BENCHMARK(mass_exact_green)->Name("whole_curve/mass_properties")->RUGOSIM_SIZES;
BENCHMARK(mass_validity)->Name("whole_curve/check_boundary")->RUGOSIM_SIZES;

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  return rugosim::bench::run_with_ratios(argc, argv);
}
