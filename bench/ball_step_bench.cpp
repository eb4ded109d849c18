// A ball rolling into a step (examples/ball_climbs_step.yaml: R 0.1 m, 0.5 kg, rolling at 0.9 m/s
// into a step 0.03 m high), tumble against MuJoCo 2.2.2, both against the closed form of the
// edge's plastic impact without slip, which keeps the angular momentum about the edge:
//     omega' = (v0 / R) (1 - 5 h / (7 R)).
// - BM_BallStepTumble: the example's 2 s; omega' from its edge impact's event (the kinetic energy
//   just after, (7/10) m R^2 omega'^2, all of it the ball's turn about the edge).
// - BM_BallStepMuJoCo/dt_<dt>_timeconst_<k>dt: a free sphere on a floor plane, the step a box
//   geom, friction 2 (it does not slip on the edge), the soft contact critically damped (e = 0)
//   with a time constant of k steps, at a fixed step, over 2 s; omega' is the ball's spin about y
//   at the first step after it touched the edge at which it no longer touches the floor.
// Counters: error, |omega' - closed| / closed; overlap, the deepest the ball went into the floor
// or the step (m; tumble's is none); climbs, whether the ball ends on the step's top.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "example_timing.hpp"
#include "mujoco_xml.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::ball_step_bench {
namespace {

constexpr double kR = 0.1, kMass = 0.5, kH = 0.03, kV0 = 0.9, kDuration = 2.0;

double omega_after() {
  return kV0 / kR * (1.0 - 5.0 * kH / (7.0 * kR));
}

void BM_BallStepTumble(benchmark::State& state) {
  PreparedSimulation simulation =
      prepare_simulation(load_scenario(example_path("ball_climbs_step"), {}));
  const SimulationResult result = time_runs(state, simulation);
  double omega = 0.0, x_end = 0.0;
  for (const ContactEventRecord& e : result.contact_events) {
    if (e.impact.has_value()) {
      omega = std::sqrt(e.kinetic_energy_after / (0.7 * kMass * kR * kR));
      break;
    }
  }
  run_simulation(simulation, [&](double, std::span<const BodyState> states,
                                 const SystemQuantities&) { x_end = states[0].r_G.x(); });
  state.counters["error"] = std::abs(omega - omega_after()) / omega_after();
  state.counters["overlap"] = 0.0;
  state.counters["climbs"] = x_end > 0.0 ? 1.0 : 0.0;
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
}
BENCHMARK(BM_BallStepTumble)->Unit(benchmark::kMillisecond);

class MuJoCoBallStep {
 public:
  MuJoCoBallStep(double dt, double timeconst) {
    const std::string contact =
        fmt::format(R"(friction="2 0.005 0.0001" solref="{:.17g} 1")", timeconst);
    mujoco_.load(fmt::format(R"(<mujoco model="ball_step">
  <option timestep="{0:.17g}" gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" {1}/>
    <geom name="step" type="box" size="0.5 0.5 {2:.17g}" pos="0.5 0 {2:.17g}" {1}/>
    <body name="ball" pos="-0.3 0 {3:.17g}"><freejoint/>
      <geom name="sphere" type="sphere" size="{3:.17g}" mass="{4:.17g}" {1}/></body>
  </worldbody>
</mujoco>
)",
                             dt, contact, kH / 2, kR, kMass),
                 "ball_step.xml");
    model_ = mujoco_.model();
    data_ = mujoco_.data();
    floor_ = mj_name2id(model_, mjOBJ_GEOM, "floor");
    step_ = mj_name2id(model_, mjOBJ_GEOM, "step");
    ball_ = mj_name2id(model_, mjOBJ_BODY, "ball");
    steps_ = std::lround(kDuration / dt);
  }

  // From the start to 2 s: the spin just after the edge's impact (into omega_), the deepest
  // overlap, m (MuJoCo's contact distance is negative inside).
  double run() {
    mj_resetData(model_, data_);
    data_->qvel[0] = kV0;       // a free joint's velocity: linear (world), then angular (local)
    data_->qvel[4] = kV0 / kR;  // rolling: about y
    double overlap = 0.0;
    bool on_edge = false, measured = false;
    omega_ = 0.0;
    for (long i = 0; i < steps_; ++i) {
      mj_step(model_, data_);
      bool on_floor = false;
      for (int c = 0; c < data_->ncon; ++c) {
        const mjContact& contact = data_->contact[c];
        overlap = std::max(overlap, -contact.dist);
        on_floor = on_floor || contact.geom1 == floor_ || contact.geom2 == floor_;
        on_edge = on_edge || contact.geom1 == step_ || contact.geom2 == step_;
      }
      if (on_edge && !on_floor && !measured) {
        mjtNum velocity[6];  // angular, then linear; world axes
        mj_objectVelocity(model_, data_, mjOBJ_BODY, ball_, velocity, 0);
        omega_ = velocity[1];
        measured = true;
      }
    }
    return overlap;
  }
  double omega() const { return omega_; }
  double x() const { return data_->qpos[0]; }
  long steps() const { return steps_; }

 private:
  MuJoCoModel mujoco_;
  mjModel* model_ = nullptr;  // mujoco_'s
  mjData* data_ = nullptr;
  int floor_ = -1, step_ = -1, ball_ = -1;
  long steps_ = 0;
  double omega_ = 0.0;
};

void BM_BallStepMuJoCo(benchmark::State& state, double dt, double steps_per_timeconst) {
  MuJoCoBallStep mujoco(dt, steps_per_timeconst * dt);
  for (auto _ : state) {
    benchmark::DoNotOptimize(mujoco.run());
    benchmark::ClobberMemory();
  }
  const double overlap = mujoco.run();
  state.counters["error"] = std::abs(mujoco.omega() - omega_after()) / omega_after();
  state.counters["overlap"] = overlap;
  state.counters["climbs"] = mujoco.x() > 0.0 ? 1.0 : 0.0;
  state.counters["steps"] = static_cast<double>(mujoco.steps());
}

[[maybe_unused]] const bool kBallStepMuJoCoRegistered = [] {
  for (const NamedValue dt : {NamedValue{"1e-3", 1e-3}, {"1e-4", 1e-4}, {"1e-5", 1e-5}}) {
    for (const double steps : {2.0, 10.0}) {
      benchmark::RegisterBenchmark(
          fmt::format("BM_BallStepMuJoCo/dt_{}_timeconst_{}dt", dt.name, steps).c_str(),
          BM_BallStepMuJoCo, dt.value, steps)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace tumble::ball_step_bench
