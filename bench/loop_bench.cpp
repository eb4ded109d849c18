// Closed loops: the four-bar linkage of examples/four_bar.yaml (three rods hinged about y in the
// x-z plane, gravity -z, the hinge B closing the loop) for 10 s, tumble against MuJoCo 2.2.2
// (Debian's libmujoco-dev).
//  - BM_FourBarTumble/<method>_rtol_<r>: run_simulation of the example with its rtol and atol
//    replaced (atol = rtol / 100, the example's ratio), integration only (rows at t = 0 and 10).
//    B is a constraint on the tree (crank and coupler from O2, rocker from O4), projected onto
//    the manifold after each step.
//  - BM_FourBarMuJoCo/rk4_dt_<dt>: the same linkage written as MJCF (below): bodies with the
//    rods' masses and inertias, hinges O2, A, O4 about y, B an `equality connect`, contacts off,
//    RK4 at a fixed step dt, 10 s / dt calls of mj_step from mj_resetData. MuJoCo's constraints
//    are soft: with its default solref (time constant 0.02 s) and solimp, B opens by up to 17 mm.
//    BM_FourBarMuJoCoStiff/rk4_dt_<dt> is the same with B as stiff as MuJoCo's defaults let it
//    be: solref's time constant at its floor, 2 dt (MuJoCo raises a smaller one to 2 dt unless
//    its refsafe flag is off), and solimp 0.9999.
// Counters, so that the whole table comes from one run:
//  - crank: O2.angle at t = 10 s, rad; crank_error: |crank - reference|, rad. The reference is
//  tumble's dop853 at rtol
//    1e-13, atol 1e-15. MuJoCo's angle is the qpos of its O2 hinge, 0 at the start and positive
//    by the right-hand rule about +y, as tumble's O2.angle.
//  - loop_error: the distance between B's point on the coupler and B's on the rocker at 10 s, m;
//    loop_error_max: its largest over the run (tumble: over rows every 0.01 s, each after a
//    step's projection; MuJoCo: after every step), from one more run outside the timing.
//  - steps (and evaluations, tumble): of the timed run.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "example_timing.hpp"
#include "mujoco_xml.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::four_bar_bench {
namespace {

constexpr double kReferenceRtol = 1e-13;
constexpr double kReferenceAtol = 1e-15;

// ---- tumble ---------------------------------------------------------------------------------

struct TumbleRun {
  PreparedSimulation simulation;
  std::size_t crank_joint = 0;  // O2's index in the model's joints (its extras' coordinates)
};

TumbleRun prepare_four_bar(const char* integrator, double rtol, double atol, bool every_row) {
  Scenario scenario = load_scenario(example_path("four_bar"), {});
  scenario.simulate.integrator = integrator;
  scenario.simulate.rtol = rtol;
  scenario.simulate.atol = atol;
  TumbleRun run{prepare_simulation(scenario), 0};
  // Rows at the two ends only (the integration is timed), or the example's every 0.01 s.
  if (!every_row) run.simulation.options.output_every = run.simulation.t_end - run.simulation.t0;
  const auto& joints = run.simulation.formulation->model().joints;
  const auto o2 = std::find_if(joints.begin(), joints.end(),
                               [](const JointModel& joint) { return joint.name == "O2"; });
  if (o2 == joints.end()) throw std::runtime_error("four_bar.yaml has no joint O2");
  run.crank_joint = static_cast<std::size_t>(o2 - joints.begin());
  return run;
}

struct TumbleEnd {
  SimulationResult result;
  double crank = 0.0;     // O2.angle at the last row, rad
  double loop_gap = 0.0;  // B's gap at the last row, m
};

void run_four_bar(TumbleRun& run, TumbleEnd& end) {
  const FullRowObserver observe = [&](double, std::span<const BodyState>, const SystemQuantities&,
                                      const RowExtras& extras) {
    end.crank = extras.coordinates[run.crank_joint].values[0];
    end.loop_gap = extras.loops.gap;
  };
  end.result = run_simulation(run.simulation, observe);
}

// O2.angle at t = 10 s of the reference run, computed once.
double reference_crank() {
  static const double crank = [] {
    TumbleRun run = prepare_four_bar("dop853", kReferenceRtol, kReferenceAtol, false);
    TumbleEnd end;
    run_four_bar(run, end);
    if (!end.result.report.completed) throw std::runtime_error(end.result.report.failure);
    return end.crank;
  }();
  return crank;
}

void BM_FourBarTumble(benchmark::State& state, const char* integrator, double rtol) {
  const double atol = rtol / 100.0;
  const double reference = reference_crank();
  TumbleRun run = prepare_four_bar(integrator, rtol, atol, false);
  TumbleEnd end;
  for (auto _ : state) {
    run_four_bar(run, end);
    // Not DoNotOptimize(end.crank): GCC may take its "+m,r" for a double into a general register
    // and hand back garbage (Google Benchmark 1.7.1); the run writes through a std::function.
    benchmark::ClobberMemory();
  }
  if (!end.result.report.completed) {
    state.SkipWithError(end.result.report.failure.c_str());
    return;
  }
  // The largest loop error over the example's rows, outside the timing.
  TumbleRun rows = prepare_four_bar(integrator, rtol, atol, true);
  TumbleEnd every;
  run_four_bar(rows, every);
  state.counters["crank"] = end.crank;
  state.counters["crank_error"] = std::abs(end.crank - reference);
  state.counters["loop_error"] = end.loop_gap;
  state.counters["loop_error_max"] = every.result.conservation.max_loop_error.gap;
  state.counters["steps"] = static_cast<double>(end.result.report.stats.accepted_steps);
  state.counters["evaluations"] = static_cast<double>(end.result.report.stats.rhs_evaluations);
}

// ---- MuJoCo ---------------------------------------------------------------------------------

// The example's geometry (examples/four_bar.yaml, to its 17 digits): the joint points, in the
// x-z plane (y = 0), and the links' masses and lengths.
constexpr std::array<double, 2> kO2 = {0.0, 0.0};
constexpr std::array<double, 2> kA = {0.10000000000000003, 0.17320508075688773};
constexpr std::array<double, 2> kO4 = {0.6, 0.0};
constexpr std::array<double, 2> kB = {0.6032015300873869, 0.4999897501000391};
constexpr double kCrankMass = 1.0, kCouplerMass = 2.0, kRockerMass = 1.5;  // kg
// A rod has no inertia about its own axis; MuJoCo wants every principal moment positive.
constexpr double kAxialInertia = 1e-9;  // kg m^2

// A rod from p to q (its COM midway, m L^2 / 12 about its transverse axes) as an MJCF
// `inertial`, in the frame of a body whose origin is `origin` and whose axes are the world's:
// principal axes x along the rod, y the hinges' axis, z the other transverse one.
std::string rod_inertial(std::array<double, 2> p, std::array<double, 2> q,
                         std::array<double, 2> origin, double mass) {
  const double dx = q[0] - p[0], dz = q[1] - p[1];
  const double length = std::hypot(dx, dz);
  const double transverse = mass * length * length / 12.0;
  // A turn about y by phi takes x to (cos phi, 0, -sin phi): phi = -atan2(dz, dx) lays x on it.
  const double phi = -std::atan2(dz, dx);
  return fmt::format(
      R"(<inertial pos="{:.17g} 0 {:.17g}" quat="{:.17g} 0 {:.17g} 0" mass="{:.17g}" )"
      R"(diaginertia="{:.17g} {:.17g} {:.17g}"/>)",
      0.5 * (p[0] + q[0]) - origin[0], 0.5 * (p[1] + q[1]) - origin[1], std::cos(phi / 2),
      std::sin(phi / 2), mass, kAxialInertia, transverse, transverse);
}

// Each body's frame sits at its hinge with the world's axes at t = 0 (qpos = 0 there): crank at
// O2, the coupler (its child) at A, the rocker at O4. No geoms: the inertias are explicit and
// nothing collides (contacts are off as well). B joins the coupler's point B - A to the rocker's
// point at B (MuJoCo takes the second from the configuration at qpos = 0, which closes the loop).
std::string four_bar_mjcf(double dt, bool stiff) {
  const std::string softness =
      stiff ? fmt::format(R"(solref="{:.17g} 1" solimp="0.9999 0.9999 0.001")", 2 * dt) : "";
  return fmt::format(
      R"(<mujoco model="four_bar">
  <option timestep="{dt:.17g}" integrator="RK4" gravity="0 0 -9.81">
    <flag contact="disable"/>
  </option>
  <worldbody>
    <body name="crank" pos="{o2x:.17g} 0 {o2z:.17g}">
      <joint name="O2" type="hinge" pos="0 0 0" axis="0 1 0"/>
      {crank}
      <body name="coupler" pos="{ax:.17g} 0 {az:.17g}">
        <joint name="A" type="hinge" pos="0 0 0" axis="0 1 0"/>
        {coupler}
      </body>
    </body>
    <body name="rocker" pos="{o4x:.17g} 0 {o4z:.17g}">
      <joint name="O4" type="hinge" pos="0 0 0" axis="0 1 0"/>
      {rocker}
    </body>
  </worldbody>
  <equality>
    <connect name="B" body1="coupler" body2="rocker" anchor="{bx:.17g} 0 {bz:.17g}" {softness}/>
  </equality>
</mujoco>
)",
      fmt::arg("dt", dt), fmt::arg("o2x", kO2[0]), fmt::arg("o2z", kO2[1]),
      fmt::arg("crank", rod_inertial(kO2, kA, kO2, kCrankMass)), fmt::arg("ax", kA[0] - kO2[0]),
      fmt::arg("az", kA[1] - kO2[1]), fmt::arg("coupler", rod_inertial(kA, kB, kA, kCouplerMass)),
      fmt::arg("o4x", kO4[0]), fmt::arg("o4z", kO4[1]),
      fmt::arg("rocker", rod_inertial(kO4, kB, kO4, kRockerMass)), fmt::arg("bx", kB[0] - kA[0]),
      fmt::arg("bz", kB[1] - kA[1]), fmt::arg("softness", softness));
}

// The model, its data and what the benchmark reads, loaded from the MJCF through a virtual file.
class MuJoCoFourBar {
 public:
  MuJoCoFourBar(double dt, bool stiff) {
    mujoco_.load(four_bar_mjcf(dt, stiff), "four_bar.xml");
    model_ = mujoco_.model();
    data_ = mujoco_.data();
    crank_qpos_ = model_->jnt_qposadr[mj_name2id(model_, mjOBJ_JOINT, "O2")];
    coupler_ = mj_name2id(model_, mjOBJ_BODY, "coupler");
    rocker_ = mj_name2id(model_, mjOBJ_BODY, "rocker");
    steps_ = std::lround(kDuration / dt);
  }

  // From the start to t = 10 s; with `loop_max`, B's largest gap after each step into it.
  void run(double* loop_max = nullptr) {
    mj_resetData(model_, data_);
    for (long i = 0; i < steps_; ++i) {
      mj_step(model_, data_);
      if (loop_max != nullptr) *loop_max = std::max(*loop_max, loop_gap());
    }
  }
  double crank() const { return data_->qpos[crank_qpos_]; }
  long steps() const { return steps_; }
  double time() const { return data_->time; }
  // The distance between B's point on the coupler and on the rocker at the current qpos
  // (mj_step leaves the bodies' poses of the step's start: recomputed here).
  double loop_gap() {
    mj_kinematics(model_, data_);
    const std::array<double, 3> on_coupler =
        point_on(coupler_, {kB[0] - kA[0], 0.0, kB[1] - kA[1]});
    const std::array<double, 3> on_rocker =
        point_on(rocker_, {kB[0] - kO4[0], 0.0, kB[1] - kO4[1]});
    return std::hypot(on_coupler[0] - on_rocker[0], on_coupler[1] - on_rocker[1],
                      on_coupler[2] - on_rocker[2]);
  }

 private:
  static constexpr double kDuration = 10.0;  // s

  // World position of a point given in a body's frame.
  std::array<double, 3> point_on(int body, const std::array<double, 3>& p_B) const {
    const mjtNum* x = data_->xpos + 3 * body;
    const mjtNum* R = data_->xmat + 9 * body;
    std::array<double, 3> p_W{};
    for (int r = 0; r < 3; ++r) {
      p_W[static_cast<std::size_t>(r)] =
          x[r] + R[3 * r] * p_B[0] + R[3 * r + 1] * p_B[1] + R[3 * r + 2] * p_B[2];
    }
    return p_W;
  }

  MuJoCoModel mujoco_;
  mjModel* model_ = nullptr;  // mujoco_'s
  mjData* data_ = nullptr;
  int crank_qpos_ = 0;
  int coupler_ = 0;
  int rocker_ = 0;
  long steps_ = 0;
};

void BM_FourBarMuJoCo(benchmark::State& state, double dt, bool stiff) {
  const double reference = reference_crank();
  MuJoCoFourBar four_bar(dt, stiff);
  for (auto _ : state) {
    four_bar.run();
    benchmark::DoNotOptimize(four_bar.crank());
  }
  const double crank = four_bar.crank();
  const double loop_gap = four_bar.loop_gap();
  double loop_max = 0.0;
  four_bar.run(&loop_max);
  state.counters["crank"] = crank;
  state.counters["crank_error"] = std::abs(crank - reference);
  state.counters["loop_error"] = loop_gap;
  state.counters["loop_error_max"] = loop_max;
  state.counters["steps"] = static_cast<double>(four_bar.steps());
  state.counters["t_end"] = four_bar.time();
}

// Registered by name here: a BENCHMARK_CAPTURE name cannot hold "1e-6" (clang-format splits it).
[[maybe_unused]] const bool kFourBarRegistered = [] {
  for (const NamedValue rtol : {NamedValue{"1e-6", 1e-6}, {"1e-8", 1e-8}, {"1e-10", 1e-10}}) {
    benchmark::RegisterBenchmark(fmt::format("BM_FourBarTumble/dop853_rtol_{}", rtol.name).c_str(),
                                 BM_FourBarTumble, "dop853", rtol.value)
        ->Unit(benchmark::kMillisecond);
  }
  for (const bool stiff : {false, true}) {
    for (const NamedValue dt : {NamedValue{"1e-3", 1e-3}, {"2.5e-4", 2.5e-4}, {"1e-4", 1e-4}}) {
      benchmark::RegisterBenchmark(
          fmt::format("BM_FourBarMuJoCo{}/rk4_dt_{}", stiff ? "Stiff" : "", dt.name).c_str(),
          BM_FourBarMuJoCo, dt.value, stiff)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace tumble::four_bar_bench
