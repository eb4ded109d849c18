// The stiff overdamped mount (examples/stiff_mount.yaml: 1 kg on a prismatic rail, a spring of
// k = 1e9 N/m with a damper of c = 1e6 N s/m, released 1 mm from its rest) over its 10 ms, tumble
// against MuJoCo 2.2.2 (Debian's libmujoco-dev), both against the closed form
//     x(t) = x0 (r2 e^(r1 t) - r1 e^(r2 t)) / (r2 - r1),   r1, r2 = (-c -+ sqrt(c^2 - 4 m k)) / 2m
// (r1 = -1001 /s, the slow mode; r2 = -998,999 /s, the stiff one).
//  - BM_StiffMountTumble/<method>_rtol_<r>: run_simulation of the example by radau5 (its own
//    method), trbdf2 (order 2, L-stable) or auto (dop853 until its stability holds the steps,
//    then radau5) with its rtol
//    replaced (atol = 1e-4 rtol x0, the example's ratio), rows 10 us apart as the example writes
//    them.
//  - BM_UndampedStiffSpring/<method>: the same mount without its damper (c = 0: 503 periods of
//    5.03 kHz in 0.1 s, fast but never stiff) at rtol 1e-10, atol 1e-13 m, by dop853 and by auto,
//    which must stay dop853 and cost no more; error against x0 cos(omega t) at the rows.
//  - BM_StiffMountMuJoCo/<integrator>_dt_<dt>: the same body on a slide joint whose stiffness and
//    damping are the mount's, at a fixed step dt: Euler (semi-implicit, the damping implicit:
//    MuJoCo's answer to stiff damping) and implicit (implicit in velocity, 2.2's own).
// Counters: error, the largest |x - x(t)| over the rows (tumble) or after every step (MuJoCo),
// relative to x0 (the issue asks for 1e-8 of it); steps.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "example_timing.hpp"
#include "mujoco_xml.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::stiff_mount_bench {
namespace {

// The example's: kg, N/m, N s/m, m; and its duration, s.
constexpr double kMass = 1.0, kStiffness = 1e9, kDamping = 1e6, kStretch = 1e-3;
constexpr double kDuration = 0.01;

// The closed form, with the roots taken without cancellation (r1 r2 = k / m).
double exact_stretch(double t) {
  const double root = std::sqrt(kDamping * kDamping - 4.0 * kMass * kStiffness);
  const double r2 = (-kDamping - root) / (2.0 * kMass);
  const double r1 = kStiffness / (kMass * r2);
  return kStretch * (r2 * std::exp(r1 * t) - r1 * std::exp(r2 * t)) / (r2 - r1);
}

// Times the whole run of `simulation`, then counts its steps and its largest |x - exact(t)| over
// the rows, relative to x0.
template <typename Exact>
void time_against(benchmark::State& state, PreparedSimulation& simulation, const Exact& exact) {
  const SimulationResult result = time_runs(state, simulation);
  double worst = 0.0;
  run_simulation(simulation,
                 [&](double t, std::span<const BodyState> states, const SystemQuantities&) {
                   worst = std::max(worst, std::abs(states[0].r_G.x() - exact(t)));
                 });
  state.counters["error"] = worst / kStretch;
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
}

void BM_StiffMountTumble(benchmark::State& state, const char* method, double rtol) {
  Scenario scenario = load_scenario(example_path("stiff_mount"), {});
  if (scenario.simulate.integrator != "radau5") throw std::runtime_error("not radau5");
  scenario.simulate.integrator = method;
  scenario.simulate.rtol = rtol;
  scenario.simulate.atol = 1e-4 * rtol * kStretch;
  PreparedSimulation simulation = prepare_simulation(scenario);
  time_against(state, simulation, exact_stretch);
}

void BM_UndampedStiffSpring(benchmark::State& state, const char* method) {
  Scenario scenario = load_scenario(example_path("stiff_mount"), {{"c", "0"}});
  scenario.simulate.integrator = method;
  scenario.simulate.duration = 0.1;
  scenario.simulate.rtol = 1e-10;
  scenario.simulate.atol = 1e-13;
  PreparedSimulation simulation = prepare_simulation(scenario);
  simulation.options.output_every = 1e-4;
  const double omega = std::sqrt(kStiffness / kMass);
  time_against(state, simulation, [omega](double t) { return kStretch * std::cos(omega * t); });
}

class MuJoCoMount {
 public:
  MuJoCoMount(const char* integrator, double dt) {
    const std::string xml = fmt::format(R"(<mujoco model="stiff_mount">
  <option timestep="{:.17g}" integrator="{}" gravity="0 0 0"/>
  <worldbody>
    <body name="box">
      <joint name="rail" type="slide" axis="1 0 0" stiffness="{:.17g}" damping="{:.17g}"
             springref="0"/>
      <geom type="box" size="0.05 0.05 0.05" mass="{:.17g}" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>
)",
                                        dt, integrator, kStiffness, kDamping, kMass);
    mujoco_.load(xml, "stiff_mount.xml");
    model_ = mujoco_.model();
    data_ = mujoco_.data();
    steps_ = std::lround(kDuration / dt);
  }

  // From the stretch x0 at rest to t = 10 ms; with `error`, the largest |x - x(t)| after a step.
  void run(double* error = nullptr) {
    mj_resetData(model_, data_);
    data_->qpos[0] = kStretch;
    for (long i = 0; i < steps_; ++i) {
      mj_step(model_, data_);
      if (error != nullptr) {
        *error = std::max(*error, std::abs(data_->qpos[0] - exact_stretch(data_->time)));
      }
    }
  }
  long steps() const { return steps_; }

 private:
  MuJoCoModel mujoco_;
  mjModel* model_ = nullptr;  // mujoco_'s
  mjData* data_ = nullptr;
  long steps_ = 0;
};

void BM_StiffMountMuJoCo(benchmark::State& state, const char* integrator, double dt) {
  MuJoCoMount mount(integrator, dt);
  for (auto _ : state) {
    mount.run();
    benchmark::ClobberMemory();
  }
  double error = 0.0;
  mount.run(&error);
  state.counters["error"] = error / kStretch;
  state.counters["steps"] = static_cast<double>(mount.steps());
}

[[maybe_unused]] const bool kStiffMountRegistered = [] {
  for (const char* method : {"radau5", "trbdf2", "auto"}) {
    for (const NamedValue rtol :
         {NamedValue{"1e-3", 1e-3}, {"1e-5", 1e-5}, {"1e-7", 1e-7}, {"1e-9", 1e-9}}) {
      benchmark::RegisterBenchmark(
          fmt::format("BM_StiffMountTumble/{}_rtol_{}", method, rtol.name).c_str(),
          BM_StiffMountTumble, method, rtol.value)
          ->Unit(benchmark::kMillisecond);
    }
  }
  for (const char* method : {"dop853", "auto"}) {
    benchmark::RegisterBenchmark(fmt::format("BM_UndampedStiffSpring/{}", method).c_str(),
                                 BM_UndampedStiffSpring, method)
        ->Unit(benchmark::kMillisecond);
  }
  for (const char* integrator : {"Euler", "implicit"}) {
    for (const NamedValue dt :
         {NamedValue{"1e-5", 1e-5}, {"1e-6", 1e-6}, {"1e-7", 1e-7}, {"1e-8", 1e-8}}) {
      benchmark::RegisterBenchmark(
          fmt::format("BM_StiffMountMuJoCo/{}_dt_{}", integrator, dt.name).c_str(),
          BM_StiffMountMuJoCo, integrator, dt.value)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace tumble::stiff_mount_bench
