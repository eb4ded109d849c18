// Andrews' squeezing mechanism (examples/andrews_squeezer.yaml: seven bodies, seven tree hinges,
// three hinges at E closing three loops, a spring, a constant torque) over 0.03 s, tumble against
// MuJoCo 2.2.2 (Debian's libmujoco-dev), both against the reference of the Bari test set for IVP
// solvers (PSIDE at tolerances 1e-14).
//  - BM_AndrewsTumble/dop853_rtol_<r>: run_simulation of the example with its rtol replaced
//    (atol = rtol / 100, the example's ratio), rows at t = 0 and 0.03 only.
//  - BM_AndrewsMuJoCo/rk4_dt_<dt>: the same mechanism as MJCF, written from tumble's model of the
//    example (so both state the same bodies): each body's frame at its tree hinge, hinges about z,
//    the hinges at E `equality connect`s, the spring a spatial tendon with the example's
//    stiffness and rest length, the torque in qfrc_applied, contacts off, RK4 at a fixed step dt.
//    MuJoCo's constraints are soft; BM_AndrewsMuJoCoStiff holds them as stiff as its defaults let
//    it (solref's time constant 2 dt, solimp 0.9999), as bench/loop_bench.cpp does the four-bar.
// Counters:
//  - angle_error: the largest of the seven angles' errors at t = 0.03 s against the reference,
//    relative to each angle (the bar of tests/andrews_squeezer_test.cpp is 1e-7);
//  - loop_error_max: the largest distance between a hinge at E's points on its two bodies, m
//    (tumble: at its two rows, each after a step's projection; MuJoCo: after every step);
//  - steps (and evaluations, tumble).
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "example_timing.hpp"
#include "mujoco_xml.hpp"
#include "tumble/simulation/model_from_scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::andrews_bench {
namespace {

constexpr double kDuration = 0.03;  // s
constexpr std::size_t kAngles = 7;

// Per tree hinge, in the example's listing order (O, P, B, A5, Q, A7, R): the test set's angle
// (beta, Theta, gamma, delta, Phi, epsilon, Omega) at t = 0 and its reference at t = 0.03 s.
constexpr std::array<double, kAngles> kAtStart = {
    -0.0617138900142764496358948458001, 0.0,
    0.455279819163070380255912382449,   0.487364979543842550225598953530,
    0.222668390165885884674473185609,   1.23054744454982119249735015568,
    -0.222668390165885884674473185609};
constexpr std::array<double, kAngles> kReference = {
    15.81077119629904,   -15.75637105984298, 0.04082224013073101, 0.5244099658805304,
    -0.5347301163226948, 1.048080741042263,  0.5347301163226948};

// The largest error of the hinges' angles (0 at t = 0) against the reference, relative.
double angle_error(const std::array<double, kAngles>& angles) {
  double worst = 0.0;
  for (std::size_t i = 0; i < kAngles; ++i) {
    const double value = kAtStart[i] + angles[i];
    worst = std::max(worst, std::abs(value - kReference[i]) / std::abs(kReference[i]));
  }
  return worst;
}

Scenario andrews_scenario() {
  return load_scenario(example_path("andrews_squeezer"), {});
}

// ---- tumble ---------------------------------------------------------------------------------

void BM_AndrewsTumble(benchmark::State& state, double rtol) {
  Scenario scenario = andrews_scenario();
  scenario.simulate.rtol = rtol;
  scenario.simulate.atol = rtol / 100.0;
  PreparedSimulation simulation = prepare_simulation(scenario);
  simulation.options.output_every = simulation.t_end - simulation.t0;
  std::array<double, kAngles> angles{};
  double loop_max = 0.0;
  const FullRowObserver observe = [&](double, std::span<const BodyState>, const SystemQuantities&,
                                      const RowExtras& extras) {
    for (std::size_t i = 0; i < kAngles; ++i) angles[i] = extras.coordinates[i].values[0];
    loop_max = std::max(loop_max, extras.loops.gap);
  };
  SimulationResult result;
  for (auto _ : state) {
    result = run_simulation(simulation, observe);
    benchmark::ClobberMemory();
  }
  if (!result.report.completed) {
    state.SkipWithError(result.report.failure.c_str());
    return;
  }
  state.counters["angle_error"] = angle_error(angles);
  state.counters["loop_error_max"] = loop_max;
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
  state.counters["evaluations"] = static_cast<double>(result.report.stats.rhs_evaluations);
}

// ---- MuJoCo ---------------------------------------------------------------------------------

std::string xyz(const Vec3& v) {
  return fmt::format("{:.17g} {:.17g} {:.17g}", v.x(), v.y(), v.z());
}

// The example as MJCF, from tumble's model of it at t = 0. Each body's frame is at the tree hinge
// that holds it (the world's axes, qpos = 0 at t = 0); a hinge at E joins its first body's point
// there to its second's.
class AndrewsMjcf {
 public:
  AndrewsMjcf(const Model& model, std::vector<BodyState> start)
      : model_(model), start_(std::move(start)), origin_(model.bodies.size(), Vec3::Zero()) {
    for (const JointModel& joint : model_.joints) {
      if (joint.type != JointType::Hinge) throw std::runtime_error("a joint is not a hinge");
      if (!joint.closes_loop) origin_[static_cast<std::size_t>(joint.body_b)] = point_of(joint);
    }
  }

  std::string xml(double dt, bool stiff) const {
    const std::string softness =
        stiff ? fmt::format(R"( solref="{:.17g} 1" solimp="0.9999 0.9999 0.001")", 2 * dt) : "";
    std::string connects;
    for (const JointModel& joint : model_.joints) {
      if (!joint.closes_loop) continue;
      connects += fmt::format(R"(    <connect name="{}" body1="{}" body2="{}" anchor="{}"{}/>)",
                              joint.name, body_name(joint.body_a), body_name(joint.body_b),
                              xyz(point_of(joint) - origin_of(joint.body_a)), softness) +
                  "\n";
    }
    if (model_.springs.size() != 1 || model_.springs[0].body_a != kGround) {
      throw std::runtime_error("the example's spring is from ground to a body");
    }
    const LinearSpring& spring = model_.springs[0];
    const auto b = static_cast<std::size_t>(spring.body_b);
    const Vec3 on_b = start_[b].r_G + start_[b].R_WB * spring.p_B_B;
    return fmt::format(R"(<mujoco model="andrews_squeezer">
  <option timestep="{:.17g}" integrator="RK4" gravity="{}">
    <flag contact="disable"/>
  </option>
  <worldbody>
    <site name="spring_fixed" pos="{}"/>
{}  </worldbody>
  <tendon>
    <spatial name="spring" stiffness="{:.17g}">
      <site site="spring_fixed"/>
      <site site="spring_moving"/>
    </spatial>
  </tendon>
  <equality>
{}  </equality>
</mujoco>
)",
                       dt, xyz(model_.gravity_W), xyz(spring.p_A_A),
                       children_of(kGround, "    ", b, on_b), spring.stiffness, connects);
  }

  // The closing hinges' points on their two bodies, each in its body's frame (as MJCF states it).
  struct Anchor {
    std::string body1, body2;
    Vec3 on_1 = Vec3::Zero(), on_2 = Vec3::Zero();
  };
  std::vector<Anchor> anchors() const {
    std::vector<Anchor> anchors;
    for (const JointModel& joint : model_.joints) {
      if (!joint.closes_loop) continue;
      anchors.push_back({body_name(joint.body_a), body_name(joint.body_b),
                         point_of(joint) - origin_of(joint.body_a),
                         point_of(joint) - origin_of(joint.body_b)});
    }
    return anchors;
  }

 private:
  // The joint's point at t = 0, world.
  Vec3 point_of(const JointModel& joint) const {
    const BodyState& b = start_[static_cast<std::size_t>(joint.body_b)];
    return b.r_G + b.R_WB * joint.p_BJ_B;
  }
  Vec3 origin_of(int body) const {
    return body == kGround ? Vec3::Zero() : origin_[static_cast<std::size_t>(body)];
  }
  std::string body_name(int body) const {
    return body == kGround ? "world" : model_.bodies[static_cast<std::size_t>(body)].name;
  }
  // The MJCF bodies the tree hinges hold to `parent`, nested; the spring's moving site on
  // `spring_body` at the world point `spring_at`.
  std::string children_of(int parent, const std::string& indent, std::size_t spring_body,
                          const Vec3& spring_at) const {
    std::string text;
    for (const JointModel& joint : model_.joints) {
      if (joint.closes_loop || joint.body_a != parent) continue;
      const auto b = static_cast<std::size_t>(joint.body_b);
      const RigidBody& body = model_.bodies[b];
      const BodyState& s = start_[b];
      Mat3 I_W = s.R_WB * body.I_G_B * s.R_WB.transpose();
      // Every hinge turns about z, so the moments across it never enter; a flat disk meets
      // MuJoCo's check A + B >= C with equality, which round-off breaks: they are made larger.
      I_W(0, 0) *= 1.0 + 1e-6;
      I_W(1, 1) *= 1.0 + 1e-6;
      const Vec3 axis_W = s.R_WB * joint.axis_B;
      text += fmt::format(R"({0}<body name="{1}" pos="{2}">
{0}  <joint name="{3}" type="hinge" pos="0 0 0" axis="{4}"/>
{0}  <inertial pos="{5}" mass="{6:.17g}" fullinertia="{7:.17g} {8:.17g} {9:.17g} {10:.17g} {11:.17g} {12:.17g}"/>
)",
                          indent, body.name, xyz(origin_[b] - origin_of(parent)), joint.name,
                          xyz(axis_W), xyz(s.r_G - origin_[b]), body.mass, I_W(0, 0), I_W(1, 1),
                          I_W(2, 2), I_W(0, 1), I_W(0, 2), I_W(1, 2));
      if (b == spring_body) {
        text += fmt::format(R"({}  <site name="spring_moving" pos="{}"/>)", indent,
                            xyz(spring_at - origin_[b])) +
                "\n";
      }
      text += children_of(static_cast<int>(b), indent + "  ", spring_body, spring_at);
      text += indent + "</body>\n";
    }
    return text;
  }

  const Model& model_;
  std::vector<BodyState> start_;
  std::vector<Vec3> origin_;  // per body: its frame's origin, world, at t = 0
};

class MuJoCoAndrews {
 public:
  MuJoCoAndrews(double dt, bool stiff) {
    const Scenario scenario = andrews_scenario();
    const PreparedSimulation simulation = prepare_simulation(scenario);
    const Model& model = simulation.formulation->model();
    const AndrewsMjcf mjcf(model, initial_states(scenario));
    mujoco_.load(mjcf.xml(dt, stiff), "andrews_squeezer.xml");
    model_ = mujoco_.model();
    data_ = mujoco_.data();
    for (const JointModel& joint : model.joints) {
      if (joint.closes_loop) continue;
      const int id = mj_name2id(model_, mjOBJ_JOINT, joint.name.c_str());
      hinge_qpos_.push_back(model_->jnt_qposadr[id]);
      if (joint.motor.kind == JointMotor::Kind::Effort) {
        torques_.push_back({model_->jnt_dofadr[id], joint.motor.value});
      }
    }
    if (hinge_qpos_.size() != kAngles) throw std::runtime_error("not seven tree hinges");
    // The spring's rest length, as the example states it (MuJoCo's own is its length at qpos0).
    model_->tendon_lengthspring[0] = model.springs[0].rest_length;
    for (const AndrewsMjcf::Anchor& anchor : mjcf.anchors()) {
      anchors_.push_back({mj_name2id(model_, mjOBJ_BODY, anchor.body1.c_str()),
                          mj_name2id(model_, mjOBJ_BODY, anchor.body2.c_str()), anchor.on_1,
                          anchor.on_2});
    }
    steps_ = std::lround(kDuration / dt);
  }

  // From the start to t = 0.03 s; with `loop_max`, the hinges at E's largest gap after each step.
  void run(double* loop_max = nullptr) {
    mj_resetData(model_, data_);
    for (const Torque& torque : torques_) data_->qfrc_applied[torque.dof] = torque.value;
    for (long i = 0; i < steps_; ++i) {
      mj_step(model_, data_);
      if (loop_max != nullptr) *loop_max = std::max(*loop_max, loop_gap());
    }
  }
  std::array<double, kAngles> angles() const {
    std::array<double, kAngles> angles{};
    for (std::size_t i = 0; i < kAngles; ++i) angles[i] = data_->qpos[hinge_qpos_[i]];
    return angles;
  }
  long steps() const { return steps_; }
  // The largest distance between a closing hinge's points on its two bodies at the current qpos
  // (mj_step leaves the bodies' poses of the step's start: recomputed here).
  double loop_gap() {
    mj_kinematics(model_, data_);
    double worst = 0.0;
    for (const Anchor& anchor : anchors_) {
      worst = std::max(
          worst,
          (point_on(anchor.body1, anchor.on_1) - point_on(anchor.body2, anchor.on_2)).norm());
    }
    return worst;
  }

 private:
  struct Torque {
    int dof = 0;
    double value = 0.0;
  };
  struct Anchor {
    int body1 = 0, body2 = 0;
    Vec3 on_1 = Vec3::Zero(), on_2 = Vec3::Zero();
  };
  Vec3 point_on(int body, const Vec3& p_B) const {
    const Vec3 x(data_->xpos[3 * body], data_->xpos[3 * body + 1], data_->xpos[3 * body + 2]);
    Mat3 R;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) R(r, c) = data_->xmat[9 * body + 3 * r + c];
    }
    return x + R * p_B;
  }

  MuJoCoModel mujoco_;
  mjModel* model_ = nullptr;  // mujoco_'s
  mjData* data_ = nullptr;
  std::vector<int> hinge_qpos_;
  std::vector<Torque> torques_;
  std::vector<Anchor> anchors_;
  long steps_ = 0;
};

void BM_AndrewsMuJoCo(benchmark::State& state, double dt, bool stiff) {
  MuJoCoAndrews andrews(dt, stiff);
  for (auto _ : state) {
    andrews.run();
    benchmark::ClobberMemory();
  }
  const std::array<double, kAngles> angles = andrews.angles();
  double loop_max = 0.0;
  andrews.run(&loop_max);
  state.counters["angle_error"] = angle_error(angles);
  state.counters["loop_error_max"] = loop_max;
  state.counters["steps"] = static_cast<double>(andrews.steps());
}

[[maybe_unused]] const bool kAndrewsRegistered = [] {
  for (const NamedValue rtol :
       {NamedValue{"1e-6", 1e-6}, {"1e-7", 1e-7}, {"1e-8", 1e-8}, {"1e-10", 1e-10}}) {
    benchmark::RegisterBenchmark(fmt::format("BM_AndrewsTumble/dop853_rtol_{}", rtol.name).c_str(),
                                 BM_AndrewsTumble, rtol.value)
        ->Unit(benchmark::kMillisecond);
  }
  for (const bool stiff : {false, true}) {
    for (const NamedValue dt : {NamedValue{"1e-5", 1e-5}, {"1e-6", 1e-6}, {"1e-7", 1e-7}}) {
      benchmark::RegisterBenchmark(
          fmt::format("BM_AndrewsMuJoCo{}/rk4_dt_{}", stiff ? "Stiff" : "", dt.name).c_str(),
          BM_AndrewsMuJoCo, dt.value, stiff)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace tumble::andrews_bench
