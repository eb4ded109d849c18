// Joints: how the articulated-body formulation (O(n) per evaluation, RBDA ch. 7) scales with the
// number of bodies, on an n-link pendulum chain of hinges, n = 1, 2, 4, ..., 256; and what the
// examples with joints cost end to end.
//  - BM_ChainDerivative: one right-hand side evaluation. Counter `per_body`: its time / n, which
//    stays flat if the cost is linear in n.
//  - BM_ChainIntegrate: dopri5 at rtol 1e-8 over a fixed simulated time. Counters `per_step`
//    (time per accepted step), `steps`, `evaluations`, and `energy_drift` (|E - E0| / |E0| at
//    the end) so that a fast but wrong run shows.
//  - BM_Example: run_simulation on examples/{compound_pendulum, bat_struck, gyroscope, cubli}.yaml
//    as the CLI runs them (their own output rows, to a no-op observer); BM_ExampleIntegrationOnly:
//    the same with rows at the two ends only, i.e. the integration alone. The issue asks < 10 ms.
//    Their `energy_drift` is the summary's: it includes the work of impulses and locks.
// The per_body and per_step rates divide CPU time (Google Benchmark's default for rates), so they
// hold on a busy machine where the Time column (wall) does not.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "example_timing.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/integrators/driver.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/simulation/make_formulation.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

// Identical thin cylinders along their body x axes, each hinged about y to the end of the one
// before, the first to ground at the origin. Slender links (r << l) like the chain example.
constexpr double kLinkLength = 0.1;    // m
constexpr double kLinkMass = 0.1;      // kg
constexpr double kLinkRadius = 0.005;  // m
// The chain starts straight, at rest, this far below the horizontal: E0 != 0, so the relative
// energy drift is defined, and the first hinge starts away from its zero.
constexpr double kStartAngle = 0.5;  // rad

Model chain_model(int n) {
  const double m = kLinkMass, l = kLinkLength, r = kLinkRadius;
  const double I_axial = m * r * r / 2;
  const double I_transverse = m * (3 * r * r + l * l) / 12;
  Model model;
  for (int i = 0; i < n; ++i) {
    model.bodies.push_back(RigidBody::make(fmt::format("link{}", i), m,
                                           Vec3(I_axial, I_transverse, I_transverse).asDiagonal()));
  }
  for (int i = 0; i < n; ++i) {
    JointModel joint;
    joint.type = JointType::Hinge;
    joint.name = fmt::format("j{}", i);
    joint.body_a = i == 0 ? kGround : i - 1;
    joint.body_b = i;
    // The parent's far end (ground: the world origin) meets the child's near end.
    joint.p_AJ_A = i == 0 ? Vec3::Zero() : Vec3(l / 2, 0, 0);
    joint.p_BJ_B = Vec3(-l / 2, 0, 0);
    joint.R_AB0 = Mat3::Identity();
    joint.axis_B = Vec3::UnitY();
    model.joints.push_back(joint);
  }
  return model;
}

// Every link turned by kStartAngle about y (its x axis tipped below the horizontal), COMs on the
// straight line from the origin, at rest: the state the joints allow.
std::vector<BodyState> chain_start(int n) {
  const Mat3 R_WB = rotation_from_axis_angle(Vec3::UnitY(), kStartAngle);
  const Vec3 along_W = R_WB * Vec3::UnitX();
  std::vector<BodyState> states(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    BodyState& s = states[static_cast<std::size_t>(i)];
    s.R_WB = R_WB;
    s.r_G = (i + 0.5) * kLinkLength * along_W;
  }
  return states;
}

double total_energy(const Formulation& system, const VecX& y) {
  std::vector<BodyState> states(system.body_count());
  system.unpack_all(y, states);
  return calc_system_quantities(system.model().bodies, states, system.model().gravity_W)
      .total_energy;
}

void BM_ChainDerivative(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::unique_ptr<Formulation> system = make_formulation("body", chain_model(n));
  VecX y(system->dimension()), dydt(system->dimension());
  system->pack(chain_start(n), y);
  // A state with speeds, so the velocity terms are not zeros: one derivative's worth of motion.
  system->derivative(0.0, y, dydt);
  y += 0.1 * dydt;
  for (auto _ : state) {
    system->derivative(0.0, y, dydt);
    benchmark::DoNotOptimize(dydt.data());
    benchmark::ClobberMemory();
  }
  state.counters["per_body"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * n,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Simulated time of the integration benchmark: long enough that the start is a small part of
// it, short enough that n = 256 takes well under a second per run.
constexpr double kChainDuration = 0.5;  // s

void BM_ChainIntegrate(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::unique_ptr<Formulation> system = make_formulation("body", chain_model(n));
  StepControl control;
  control.rtol = 1e-8;
  control.atol = 1e-10;
  const std::unique_ptr<Integrator> integrator = make_integrator("dopri5", control);
  VecX y0(system->dimension());
  system->pack(chain_start(n), y0);
  DriverOptions options;
  options.output_every = kChainDuration;  // rows at the two ends only: time the integration
  VecX y_end = y0;
  IntegrationReport report;
  for (auto _ : state) {
    report = integrate(*integrator, *system, 0.0, y0, kChainDuration, options,
                       [&](double, const VecX& y) { y_end = y; });
    benchmark::DoNotOptimize(y_end.data());
  }
  const double E0 = total_energy(*system, y0);
  state.counters["energy_drift"] = std::abs(total_energy(*system, y_end) - E0) / std::abs(E0);
  state.counters["steps"] = static_cast<double>(report.stats.accepted_steps);
  state.counters["evaluations"] = static_cast<double>(report.stats.rhs_evaluations);
  state.counters["per_step"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(report.stats.accepted_steps),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  if (!report.completed) state.SkipWithError(report.failure.c_str());
}

BENCHMARK(BM_ChainDerivative)->RangeMultiplier(2)->Range(1, 256)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_ChainIntegrate)->RangeMultiplier(2)->Range(1, 256)->Unit(benchmark::kMicrosecond);

// ---- The examples, as `tumble run` integrates them ------------------------------------------

void BM_Example(benchmark::State& state, const char* stem) {
  time_example(state, stem, true);
}
void BM_ExampleIntegrationOnly(benchmark::State& state, const char* stem) {
  time_example(state, stem, false);
}

BENCHMARK_CAPTURE(BM_Example, compound_pendulum, "compound_pendulum")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Example, bat_struck, "bat_struck")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Example, gyroscope, "gyroscope")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Example, cubli, "cubli")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExampleIntegrationOnly, compound_pendulum, "compound_pendulum")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExampleIntegrationOnly, bat_struck, "bat_struck")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExampleIntegrationOnly, gyroscope, "gyroscope")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExampleIntegrationOnly, cubli, "cubli")->Unit(benchmark::kMillisecond);

// The gyroscope's fast spin (100 rad/s) made it the one example over 10 ms with dopri5, so the
// example runs dop853 (about 7x fewer steps at the same rtol); this times dopri5 on it for
// comparison, integration only.
void BM_ExampleGyroscopeDopri5(benchmark::State& state) {
  time_example(state, "gyroscope", false, "dopri5");
}
BENCHMARK(BM_ExampleGyroscopeDopri5)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tumble
