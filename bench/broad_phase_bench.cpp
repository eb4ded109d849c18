// The broad phase's cost as the bodies grow in number: a hard-sphere gas (balls of radius 0.05 m
// and 0.1 kg on a jittered grid of 0.2 m, up to 1 m/s along each axis, no gravity, elastic and
// frictionless) in a closed box of six walls welded to ground, the box grown with the balls so
// that their density stays the same, over 1 s; one contact, `bodies: all`.
// - BM_BallGas/screened/<n>: n balls, the group's pairs screened (contact/broad_phase.hpp);
// - BM_BallGas/every_pair_watched/<n>: the same with every pair named on its own, which each step
//   watches (the narrow phase of all n (n - 1) / 2 + 6 n pairs at every evaluation), for scale;
// - BM_BallGasMuJoCo/dt_<dt>_period_<k>dt/<n>: the same balls and walls in MuJoCo 2.2.2 at a
//   fixed step, frictionless (condim 1), its soft contact an undamped spring whose stiffness
//   m (2 pi / T)^2 gives a ball on it the period T of k steps (solref's direct form, "-stiffness
//   0": e = 1). A damping ratio of 0 MuJoCo takes as unset, and damps critically: that took 95%
//   of the energy in 1 s; ratios of 0.05 and 0.3 blew up.
// Counters: steps, time per step (s), pairs (tumble's contacts), impacts (tumble's), and the
// error against the closed form that an elastic gas keeps its kinetic energy: |KE(1 s) - KE(0)| /
// KE(0); overlap, the deepest two bodies went into each other (m; tumble's is none: each impact
// is at its located touch).
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "example_timing.hpp"
#include "mujoco_xml.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::broad_phase_bench {
namespace {

constexpr double kRadius = 0.05, kMass = 0.1, kSpacing = 4 * kRadius, kWall = 0.05;
constexpr double kDuration = 1.0;

// The balls' starts and the box's inner width, the same for both engines.
struct Gas {
  std::vector<Vec3> position, velocity;
  double width = 0.0;
  double kinetic_energy() const {
    double KE = 0.0;
    for (const Vec3& v : velocity) KE += 0.5 * kMass * v.squaredNorm();
    return KE;
  }
};

Gas make_gas(int n) {
  const int per_side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n)) - 1e-9));
  Gas gas;
  gas.width = per_side * kSpacing;
  std::uint64_t seed = 2026;
  const auto uniform = [&seed] {  // in [0, 1), the same on every platform
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(seed >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < n; ++i) {
    const int cell[3] = {i % per_side, (i / per_side) % per_side, i / (per_side * per_side)};
    Vec3 p, v;
    for (int k = 0; k < 3; ++k) {
      p(k) = -gas.width / 2 + kSpacing * (cell[k] + 0.5) + kRadius * (uniform() - 0.5);
      v(k) = 2 * uniform() - 1;
    }
    gas.position.push_back(p);
    gas.velocity.push_back(v);
  }
  return gas;
}

// The six walls: name, size (full), centre.
struct Wall {
  std::string name;
  Vec3 size, centre;
};
std::vector<Wall> walls_of(const Gas& gas) {
  std::vector<Wall> walls;
  const double at = gas.width / 2 + kWall / 2;
  for (int axis = 0; axis < 3; ++axis) {
    for (const int side : {-1, 1}) {
      Wall wall{fmt::format("wall_{}{}", "xyz"[axis], side < 0 ? "lo" : "hi"),
                Vec3::Constant(gas.width), Vec3::Zero()};
      wall.size(axis) = kWall;
      wall.centre(axis) = side * at;
      walls.push_back(wall);
    }
  }
  return walls;
}

std::string tumble_yaml(const Gas& gas, bool every_pair_named) {
  std::string yaml = "tumble: 1\ngravity: [0, 0, 0]\nbodies:\n";
  std::vector<std::string> names;
  for (std::size_t i = 0; i < gas.position.size(); ++i) {
    const Vec3 &p = gas.position[i], &v = gas.velocity[i];
    names.push_back(fmt::format("b{}", i));
    yaml += fmt::format(
        "  b{}: {{shape: sphere, radius: {}, mass: {}, position: [{}, {}, {}], velocity: [{}, "
        "{}, {}]}}\n",
        i, kRadius, kMass, p.x(), p.y(), p.z(), v.x(), v.y(), v.z());
  }
  const std::vector<Wall> walls = walls_of(gas);
  for (const Wall& w : walls) {
    yaml += fmt::format(
        "  {}: {{shape: box, size: [{}, {}, {}], mass: 9, position: [{}, {}, {}]}}\n", w.name,
        w.size.x(), w.size.y(), w.size.z(), w.centre.x(), w.centre.y(), w.centre.z());
  }
  yaml += "joints:\n";
  for (const Wall& w : walls) {
    yaml +=
        fmt::format("  fix_{0}: {{type: fixed, bodies: [ground, {0}], at: [0, 0, 0]}}\n", w.name);
  }
  yaml += "contacts:\n";
  if (!every_pair_named) {
    yaml += "  - {name: hit, type: bodies, bodies: all, friction: 0, restitution: 1}\n";
  } else {
    for (const Wall& w : walls) names.push_back(w.name);
    for (std::size_t a = 0; a < gas.position.size(); ++a) {
      for (std::size_t b = a + 1; b < names.size(); ++b) {
        yaml += fmt::format(
            "  - {{name: hit_{0}_{1}, type: bodies, bodies: [{0}, {1}], friction: 0, restitution: "
            "1}}\n",
            names[a], names[b]);
      }
    }
  }
  yaml += fmt::format(
      "simulate: {{duration: {0}, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: "
      "{0}}}\n",
      kDuration);
  return yaml;
}

void BM_BallGas(benchmark::State& state, bool every_pair_named) {
  const Gas gas = make_gas(static_cast<int>(state.range(0)));
  const Scenario scenario = load_scenario_text(tumble_yaml(gas, every_pair_named), "gas.yaml", {});
  PreparedSimulation simulation = prepare_simulation(scenario);
  const SimulationResult result = time_runs(state, simulation);
  double KE = 0.0;
  run_simulation(simulation, [&](double, std::span<const BodyState>, const SystemQuantities& q) {
    KE = q.kinetic_energy;
  });
  const auto steps = static_cast<double>(result.report.stats.accepted_steps);
  state.counters["steps"] = steps;
  state.counters["time_per_step"] = benchmark::Counter(
      steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(scenario.contacts.size());
  state.counters["impacts"] = static_cast<double>(result.contact_events.size());
  state.counters["error"] = std::abs(KE - gas.kinetic_energy()) / gas.kinetic_energy();
  state.counters["overlap"] = 0.0;
}

BENCHMARK_CAPTURE(BM_BallGas, screened, false)
    ->Arg(25)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Unit(benchmark::kMillisecond);
// Every pair watched: its contacts' dense scratch grows as their square, so no more than 50.
BENCHMARK_CAPTURE(BM_BallGas, every_pair_watched, true)
    ->Arg(25)
    ->Arg(50)
    ->Unit(benchmark::kMillisecond);

class MuJoCoGas {
 public:
  MuJoCoGas(const Gas& gas, double dt, double period) : gas_(gas) {
    // A free ball's geoms and the walls' (world geoms), frictionless, undamped.
    const double stiffness = kMass * std::pow(2.0 * std::numbers::pi / period, 2.0);
    const std::string contact = fmt::format(R"(condim="1" solref="{:.17g} 0")", -stiffness);
    std::string bodies;
    for (std::size_t i = 0; i < gas.position.size(); ++i) {
      const Vec3& p = gas.position[i];
      bodies += fmt::format(
          R"(    <body pos="{:.17g} {:.17g} {:.17g}"><freejoint/><geom type="sphere" size="{}" mass="{}" {}/></body>
)",
          p.x(), p.y(), p.z(), kRadius, kMass, contact);
    }
    for (const Wall& w : walls_of(gas)) {
      bodies += fmt::format(
          R"(    <geom type="box" size="{:.17g} {:.17g} {:.17g}" pos="{:.17g} {:.17g} {:.17g}" {}/>
)",
          w.size.x() / 2, w.size.y() / 2, w.size.z() / 2, w.centre.x(), w.centre.y(), w.centre.z(),
          contact);
    }
    mujoco_.load(fmt::format(R"(<mujoco model="ball_gas">
  <option timestep="{:.17g}" gravity="0 0 0"/>
  <size nconmax="{}" njmax="{}"/>
  <worldbody>
{}  </worldbody>
</mujoco>
)",
                             dt, 20 * gas.position.size(), 20 * gas.position.size(), bodies),
                 "ball_gas.xml");
    model_ = mujoco_.model();
    data_ = mujoco_.data();
    steps_ = std::lround(kDuration / dt);
  }

  // From the start to 1 s; the deepest overlap, m (MuJoCo's contact distance is negative inside).
  double run() {
    mj_resetData(model_, data_);
    for (std::size_t i = 0; i < gas_.velocity.size(); ++i) {
      for (int k = 0; k < 3; ++k) data_->qvel[6 * i + k] = gas_.velocity[i](k);  // linear first
    }
    double overlap = 0.0;
    for (long i = 0; i < steps_; ++i) {
      mj_step(model_, data_);
      for (int c = 0; c < data_->ncon; ++c) overlap = std::max(overlap, -data_->contact[c].dist);
    }
    return overlap;
  }
  double kinetic_energy() const {
    double KE = 0.0;
    for (std::size_t i = 0; i < gas_.velocity.size(); ++i) {
      const Eigen::Map<const Vec3> v(data_->qvel + 6 * i);
      KE += 0.5 * kMass * v.squaredNorm();  // a ball's spin is never excited (frictionless)
    }
    return KE;
  }
  long steps() const { return steps_; }

 private:
  const Gas& gas_;
  MuJoCoModel mujoco_;
  mjModel* model_ = nullptr;  // mujoco_'s
  mjData* data_ = nullptr;
  long steps_ = 0;
};

void BM_BallGasMuJoCo(benchmark::State& state, double dt, double steps_per_period) {
  const Gas gas = make_gas(static_cast<int>(state.range(0)));
  MuJoCoGas mujoco(gas, dt, steps_per_period * dt);
  for (auto _ : state) {
    benchmark::DoNotOptimize(mujoco.run());
    benchmark::ClobberMemory();
  }
  const double overlap = mujoco.run();
  const auto steps = static_cast<double>(mujoco.steps());
  state.counters["steps"] = steps;
  state.counters["time_per_step"] = benchmark::Counter(
      steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["error"] =
      std::abs(mujoco.kinetic_energy() - gas.kinetic_energy()) / gas.kinetic_energy();
  state.counters["overlap"] = overlap;
}

[[maybe_unused]] const bool kBallGasMuJoCoRegistered = [] {
  for (const NamedValue dt : {NamedValue{"1e-3", 1e-3}, {"1e-4", 1e-4}}) {
    for (const double steps : {2.0, 10.0}) {
      benchmark::RegisterBenchmark(
          fmt::format("BM_BallGasMuJoCo/dt_{}_period_{}dt", dt.name, steps).c_str(),
          BM_BallGasMuJoCo, dt.value, steps)
          ->Arg(25)
          ->Arg(50)
          ->Arg(100)
          ->Arg(200)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace tumble::broad_phase_bench
