// Two balls head on (tests/sphere_pairs_test.cpp's: 2 kg of radius 0.1 m at 3 m/s, 0.5 kg of
// radius 0.05 m at -1 m/s, 0.85 m apart, restitution e = 0.7, no gravity) over 0.5 s, tumble
// against MuJoCo 2.2.2 (Debian's libmujoco-dev), both against Newton's closed form
//     v1' = (m1 v1 + m2 v2 - m2 e (v1 - v2)) / (m1 + m2),  v2' = ... + m1 e (v1 - v2) ...
// - BM_SphereImpactTumble/<method>: the run with its `type: bodies` contact (the impact a located
//   event and an impulse), rows every 0.05 s.
// - BM_SphereImpactMuJoCo/dt_<dt>: two free bodies with sphere geoms, at a fixed step, the
//   contact's solref (time constant 2 dt, MuJoCo's least for a stable contact, and the damping
//   ratio zeta = -ln(e) / sqrt(pi^2 + ln(e)^2) of a linear spring and damper whose bounce is e)
//   making its soft contact's restitution as near e as that model comes.
// Counters: error, |v1' - closed| + |v2' - closed| after the run over |v1 - v2|; overlap, the
// deepest the two balls went into each other (m; tumble's is none: the impact is at the located
// touch); steps.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "example_timing.hpp"
#include "mujoco_xml.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::sphere_impact_bench {
namespace {

constexpr double kM1 = 2.0, kR1 = 0.1, kV1 = 3.0, kM2 = 0.5, kR2 = 0.05, kV2 = -1.0;
constexpr double kGap = 0.85, kRestitution = 0.7, kDuration = 0.5;

double v1_after() {
  return (kM1 * kV1 + kM2 * kV2 - kM2 * kRestitution * (kV1 - kV2)) / (kM1 + kM2);
}
double v2_after() {
  return (kM1 * kV1 + kM2 * kV2 + kM1 * kRestitution * (kV1 - kV2)) / (kM1 + kM2);
}
double relative_error(double v1, double v2) {
  return (std::abs(v1 - v1_after()) + std::abs(v2 - v2_after())) / (kV1 - kV2);
}

const char* const kScenario = R"(tumble: 1
gravity: [0, 0, 0]
bodies:
  a: {shape: sphere, radius: 0.1, mass: 2, position: [0, 0, 0], velocity: [3, 0, 0]}
  b: {shape: sphere, radius: 0.05, mass: 0.5, position: [1, 0, 0], velocity: [-1, 0, 0]}
contacts:
  - {name: touch, type: bodies, bodies: [a, b], friction: 0.3, restitution: 0.7}
simulate: {duration: 0.5, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 0.05}
)";

void BM_SphereImpactTumble(benchmark::State& state, const char* method) {
  Scenario scenario = load_scenario_text(kScenario, "two_balls.yaml", {});
  scenario.simulate.integrator = method;
  PreparedSimulation simulation = prepare_simulation(scenario);
  const SimulationResult result = time_runs(state, simulation);
  double v1 = 0.0, v2 = 0.0;
  run_simulation(simulation,
                 [&](double, std::span<const BodyState> states, const SystemQuantities&) {
                   v1 = states[0].v_G.x();
                   v2 = states[1].v_G.x();
                 });
  state.counters["error"] = relative_error(v1, v2);
  state.counters["overlap"] = 0.0;
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
}

class MuJoCoBalls {
 public:
  MuJoCoBalls(double dt, double timeconst) {
    const double log_e = std::log(kRestitution);
    const double zeta = -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
    const std::string xml =
        fmt::format(R"(<mujoco model="two_balls">
  <option timestep="{:.17g}" gravity="0 0 0"/>
  <worldbody>
    <body name="a" pos="0 0 0"><freejoint/>
      <geom type="sphere" size="{:.17g}" mass="{:.17g}" solref="{:.17g} {:.17g}"/></body>
    <body name="b" pos="{:.17g} 0 0"><freejoint/>
      <geom type="sphere" size="{:.17g}" mass="{:.17g}" solref="{:.17g} {:.17g}"/></body>
  </worldbody>
</mujoco>
)",
                    dt, kR1, kM1, timeconst, zeta, kGap + kR1 + kR2, kR2, kM2, timeconst, zeta);
    mujoco_.load(xml, "two_balls.xml");
    model_ = mujoco_.model();
    data_ = mujoco_.data();
    steps_ = std::lround(kDuration / dt);
  }

  // From the start to 0.5 s; the deepest overlap of the two, m (MuJoCo's contact distance is
  // negative inside).
  double run() {
    mj_resetData(model_, data_);
    data_->qvel[0] = kV1;  // a free joint's velocity: linear, then angular
    data_->qvel[6] = kV2;
    double overlap = 0.0;
    for (long i = 0; i < steps_; ++i) {
      mj_step(model_, data_);
      for (int c = 0; c < data_->ncon; ++c) overlap = std::max(overlap, -data_->contact[c].dist);
    }
    return overlap;
  }
  double v1() const { return data_->qvel[0]; }
  double v2() const { return data_->qvel[6]; }
  long steps() const { return steps_; }

 private:
  MuJoCoModel mujoco_;
  mjModel* model_ = nullptr;  // mujoco_'s
  mjData* data_ = nullptr;
  long steps_ = 0;
};

void BM_SphereImpactMuJoCo(benchmark::State& state, double dt, double timeconst) {
  MuJoCoBalls balls(dt, timeconst);
  for (auto _ : state) {
    benchmark::DoNotOptimize(balls.run());
    benchmark::ClobberMemory();
  }
  const double overlap = balls.run();
  state.counters["error"] = relative_error(balls.v1(), balls.v2());
  state.counters["overlap"] = overlap;
  state.counters["v1"] = balls.v1();
  state.counters["v2"] = balls.v2();
  state.counters["steps"] = static_cast<double>(balls.steps());
}

[[maybe_unused]] const bool kSphereImpactRegistered = [] {
  for (const char* method : {"dop853", "dopri5"}) {
    benchmark::RegisterBenchmark(fmt::format("BM_SphereImpactTumble/{}", method).c_str(),
                                 BM_SphereImpactTumble, method)
        ->Unit(benchmark::kMicrosecond);
  }
  for (const NamedValue dt : {NamedValue{"1e-3", 1e-3}, {"1e-4", 1e-4}, {"1e-5", 1e-5}}) {
    for (const double steps : {2.0, 10.0, 100.0}) {
      benchmark::RegisterBenchmark(
          fmt::format("BM_SphereImpactMuJoCo/dt_{}_timeconst_{}dt", dt.name, steps).c_str(),
          BM_SphereImpactMuJoCo, dt.value, steps * dt.value)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace tumble::sphere_impact_bench
