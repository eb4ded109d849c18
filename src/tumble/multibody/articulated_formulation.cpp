#include "tumble/multibody/articulated_formulation.hpp"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tumble/math/rotation.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

namespace {

// The inverse of a joint's symmetric positive definite S^T I^A S (1, 2, 3 or 6 freedoms) through
// fixed-size types, so nothing is allocated.
template <typename Matrix>
void invert_joint_inertia(const Matrix& D, Matrix& D_inv) {
  switch (D.rows()) {
    case 1:
      D_inv(0, 0) = 1.0 / D(0, 0);
      break;
    case 2:
      D_inv = Eigen::Matrix2d(D).inverse();
      break;
    case 3:
      D_inv = Mat3(D).inverse();
      break;
    case 6:
      D_inv = Mat6(D).ldlt().solve(Mat6::Identity());
      break;
    default:
      throw std::logic_error("a joint has 0, 1, 2, 3 or 6 freedoms");
  }
}

// The pseudo-inverse of a ball joint's S^T I^A S that may be singular: a point mass held at a
// pivot has no inertia about the line from the pivot through it (D d = 0). Turning about that
// line moves no mass and no force or moment can act about it, so its acceleration is taken as
// zero (the pseudo-inverse's minimum-norm solution) and the other two are solved as usual.
// Eigenvalues below 1e-12 of the largest are that line's.
template <typename Matrix>
void pseudo_invert_ball_joint_inertia(const Matrix& D, Matrix& D_inv) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen{Mat3(D)};
  const Vec3& lambda = eigen.eigenvalues();
  const double floor = 1e-12 * lambda.cwiseAbs().maxCoeff();
  Vec3 inverse = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (lambda(i) > floor) inverse(i) = 1.0 / lambda(i);
  }
  D_inv = eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
}

// The work-ledger's unit for its absolute tolerance, J: how much the system's energy changes
// when its state is off by one unit of each coordinate and speed (1 m, 1 m/s, 1 rad/s; a
// radian of a hinge), so that atol means the same for the books as for the state. Per body
// m |g| + m |v_G| + (tr I_G / 2) |omega| (its weight, linear and angular momentum at y0); per
// load, spring (its force or moment at y0), impulse and motor its own size: |F| or |M|, |J|, a
// speed motor's momentum about its axis (|m v| or (tr I / 2) |w|), an effort's |F| or |tau|. It
// scales as the masses do, so the same motion at any mass takes the same steps; a problem with
// none of these (nothing moves or drives) takes 1 J.
double ledger_unit(const Model& model, std::span<const BodyState> states,
                   std::span<const Vec6> element_wrenches_B) {
  double unit = 0.0;
  const double g = model.gravity_W.norm();
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const RigidBody& body = model.bodies[i];
    const double inertia = body.I_G_B.trace() / 2.0;
    unit += body.mass * (g + states[i].v_G.norm()) + inertia * states[i].omega_W.norm();
    unit += element_wrenches_B[i].head<3>().norm() + element_wrenches_B[i].tail<3>().norm();
  }
  for (const AppliedLoad& load : model.loads) unit += load.value.norm();
  for (const ImpulseLoad& impulse : model.impulses) unit += impulse.value.norm();
  // A motor drives both its bodies (either may be ground): the same whichever it lists first.
  for (const JointModel& joint : model.joints) {
    if (joint.motor.kind == JointMotor::Kind::None) continue;
    const double value = std::abs(joint.motor.value);
    if (joint.motor.kind == JointMotor::Kind::Effort) {
      unit += value;
      continue;
    }
    for (const int b : {joint.body_a, joint.body_b}) {
      if (b < 0) continue;
      const RigidBody& body = model.bodies[static_cast<std::size_t>(b)];
      unit += (joint.type == JointType::Prismatic ? body.mass : body.I_G_B.trace() / 2.0) * value;
    }
  }
  return unit > 0.0 ? unit : 1.0;
}

}  // namespace

ArticulatedFormulation::ArticulatedFormulation(std::shared_ptr<const ArticulatedModel> model)
    : Formulation(model->shared_model),
      shared_articulated_(std::move(model)),
      m_(*shared_articulated_),
      data_(std::make_unique<ArticulatedData>(m_)),
      d_(*data_),
      s_(hybrid_),
      contact_bodies_(*this),
      contacts_(model_.contacts, model_.bodies, model_.gravity_W, contact_bodies_, s_.contact,
                m_.dimension, model_.fixed_step),
      loops_(model_, contact_bodies_) {}

ArticulatedFormulation::ArticulatedFormulation(Model model)
    : ArticulatedFormulation(std::make_shared<const ArticulatedModel>(
          std::make_shared<const Model>(std::move(model)))) {}

void ArticulatedFormulation::calc_kinematics(const VecX& y, bool with_velocities) const {
  for (std::size_t k = 0; k < m_.tree.size(); ++k) {
    const TreeJoint& joint = m_.tree[k];
    Workspace& w = d_.work[k];
    Mat3 R_WP = Mat3::Identity();
    Vec3 r_P_W = Vec3::Zero();
    Vec6 v_P = Vec6::Zero();
    if (joint.parent != kGround) {
      const Workspace& parent = d_.work[m_.slot_of_body[static_cast<std::size_t>(joint.parent)]];
      R_WP = parent.R_WC;
      r_P_W = parent.r_G_W;
      v_P = parent.velocity;
    }
    Mat3 R_PC;
    Vec3 p_PC_P;
    joint.kind->calc_placement(joint, y, R_PC, p_PC_P);
    w.inertia_ready = false;  // a new configuration: the passes build the inertias again
    w.X.E = R_PC.transpose();
    w.X.r = p_PC_P;
    w.R_WC = R_WP * R_PC;
    w.r_G_W = r_P_W + R_WP * w.X.r;
    BodyState& s = d_.states[joint.child];
    s.r_G = w.r_G_W;
    s.R_WB = w.R_WC;
    if (w.moving >= 0) {
      ArticulatedData::MovingSubspace& m = d_.moving[static_cast<std::size_t>(w.moving)];
      joint.kind->calc_motion_subspace(joint, y, m.S, m.S_rate_u);
    }
    if (!with_velocities) continue;
    Vec6 v_joint = Vec6::Zero();
    if (joint.nv > 0) v_joint.noalias() = d_.S_of(joint, w) * y.segment(joint.v, joint.nv);
    w.velocity = w.X.apply_motion(v_P) + v_joint;
    w.bias = cross_motion(w.velocity, v_joint);
    if (w.moving >= 0) w.bias += d_.moving[static_cast<std::size_t>(w.moving)].S_rate_u;
    s.omega_W = w.R_WC * w.velocity.head<3>();
    s.v_G = w.R_WC * w.velocity.tail<3>();
  }
}

void ArticulatedFormulation::accumulate_element_loads(const VecX& y, double mode_time, VecX& rates,
                                                      Eigen::Index offset,
                                                      double* elastic_energy) const {
  for (Workspace& w : d_.work) w.external.setZero();
  const auto add = [&](int body, const Vec3& F_W, const Vec3& M_G_W) {
    if (body == kGround) return;
    Workspace& w = d_.work[m_.slot_of_body[static_cast<std::size_t>(body)]];
    w.external.head<3>() += w.R_WC.transpose() * M_G_W;
    w.external.tail<3>() += w.R_WC.transpose() * F_W;
  };
  double elastic = 0.0;
  Eigen::Index slot = offset;
  for (const AppliedLoad& load : model_.loads) {
    double power = 0.0;
    if (load.active_at(mode_time)) {
      const BodyState& s = d_.states[load.body];
      const LoadOnBody on_body = calc_load_on_body(load, s.R_WB);
      add(static_cast<int>(load.body), on_body.F_W, on_body.M_G_W);
      // F . v_P + M_G . omega with M_G = p_GP x F: the force's power at its point.
      power = on_body.F_W.dot(s.v_G) + on_body.M_G_W.dot(s.omega_W);
    }
    rates(slot++) = power;
  }
  for (const LinearSpring& spring : model_.springs) {
    const ElementLoad e = calc_spring_load(spring, d_.states);
    add(spring.body_a, e.F_a_W, e.M_a_W);
    add(spring.body_b, e.F_b_W, e.M_b_W);
    elastic += e.energy;
    rates(slot++) = e.power;
  }
  for (const TorsionalSpring& spring : model_.torsional_springs) {
    double angle = 0.0, rate = 0.0;
    Vec3 axis_W = Vec3::UnitZ();
    if (spring.hinge >= 0) {
      const auto j = static_cast<std::size_t>(spring.hinge);
      const std::size_t k = static_cast<std::size_t>(m_.slot_of_joint[j]);
      angle = m_.hinge_angle(y, j);
      rate = m_.joint_rate(y, j);
      axis_W = d_.work[k].R_WC * m_.tree[k].axis_C;
      if (m_.tree[k].reversed) axis_W = -axis_W;
    }
    const ElementLoad e = calc_torsional_spring_load(spring, d_.states, angle, rate, axis_W);
    add(spring.body_a, e.F_a_W, e.M_a_W);
    add(spring.body_b, e.F_b_W, e.M_b_W);
    elastic += e.energy;
    rates(slot++) = e.power;
  }
  // A motor across a loop's closing joint has no coordinate of the tree to drive: its effort is
  // a load on its two bodies (a tree joint's is its generalised force, in solve).
  for (const std::size_t j : m_.motor_joints) {
    const JointModel& joint = model_.joints[j];
    if (!joint.closes_loop || !joint.motor.active_at(mode_time)) continue;
    const ElementLoad e = calc_loop_motor_load(joint, d_.states);
    add(joint.body_a, e.F_a_W, e.M_a_W);
    add(joint.body_b, e.F_b_W, e.M_b_W);
  }
  if (elastic_energy != nullptr) *elastic_energy = elastic;
}

void ArticulatedFormulation::solve(double mode_time, bool impulsive, std::size_t only_tree) const {
  // Every tree, or one: a contact row's response moves only the tree it pushes.
  const std::span<const std::size_t> slots = only_tree == kEveryTree
                                                 ? std::span<const std::size_t>(m_.every_slot)
                                                 : m_.slots_of_tree(only_tree);
  // The articulated inertias depend only on the configuration and on which joints are
  // prescribed: the passes at one state (the free motion, each contact row's response, the
  // motion under the contact forces) build them once, and the rest take them as they are.
  for (const std::size_t k : slots) {
    if (m_.tree_root[k] == k) d_.reuse_inertia[k] = 1;
  }
  for (const std::size_t k : slots) {
    Workspace& w = d_.work[k];
    const bool known = m_.prescribed(k, mode_time);
    if (!w.inertia_ready || known != w.known) d_.reuse_inertia[m_.tree_root[k]] = 0;
    w.known = known;
  }
  const auto reused = [&](std::size_t k) { return d_.reuse_inertia[m_.tree_root[k]] != 0; };
  // Pass 1: each body alone.
  for (const std::size_t k : slots) {
    const TreeJoint& joint = m_.tree[k];
    const RigidBody& body = model_.bodies[joint.child];
    Workspace& w = d_.work[k];
    if (!reused(k)) w.IA = spatial_inertia_about_com(body.mass, body.I_G_B);
    w.pA = -w.external;
    if (!impulsive) {
      w.pA += cross_force(w.velocity, apply_inertia_about_com(body.mass, body.I_G_B, w.velocity));
    }
    if (joint.nv == 0) continue;
    w.tau.setZero();
    if (w.known && !impulsive) w.qdd.setZero();  // locks and speed motors hold their rate
    if (!impulsive && joint.model_joint >= 0) {
      const JointMotor& motor = model_.joints[static_cast<std::size_t>(joint.model_joint)].motor;
      if (motor.kind == JointMotor::Kind::Effort && motor.active_at(mode_time) && !w.known) {
        w.tau(motor.freedom) = motor.value;
      }
    }
  }
  // Pass 2: articulated inertias and bias forces, from the leaves in.
  for (auto slot = slots.rbegin(); slot != slots.rend(); ++slot) {
    const std::size_t k = *slot;
    const TreeJoint& joint = m_.tree[k];
    Workspace& w = d_.work[k];
    const Vec6 c = impulsive ? Vec6::Zero() : w.bias;
    const bool build = !reused(k);
    Vec6 pa;
    if (joint.type == JointType::Free && !w.known) {
      // A free joint's S is the identity and its parent is ground: U = D = I^A, and nothing
      // passes on. A body with nothing hung from it has I^A = diag(I_G, M): inverted in closed
      // form.
      if (build) {
        w.U = w.IA;
        if (m_.has_children[k]) {
          invert_joint_inertia(SpeedMatrix(w.IA), w.D_inv);
        } else {
          const RigidBody& body = model_.bodies[joint.child];
          w.D_inv.setZero();
          w.D_inv.topLeftCorner(3, 3) = body.I_G_B_inv;
          w.D_inv.bottomRightCorner(3, 3) = Mat3::Identity() / body.mass;
        }
      }
      w.inertia_ready = true;
      w.u = w.tau - w.pA;
      continue;
    }
    const MotionSubspace& S = d_.S_of(joint, w);
    if (w.known) {
      Vec6 a_joint = c;
      if (joint.nv > 0) a_joint.noalias() += S * w.qdd;
      if (build) w.IA_passed = w.IA;
      pa = w.pA + w.IA * a_joint;
    } else {
      if (build) {
        w.U.noalias() = w.IA * S;
        const SpeedMatrix D = S.transpose() * w.U;
        if (m_.holds_point_on_ball[k]) {
          pseudo_invert_ball_joint_inertia(D, w.D_inv);
        } else {
          invert_joint_inertia(D, w.D_inv);
        }
        w.IA_passed = w.IA;
        w.IA_passed.noalias() -= w.U * (w.D_inv * w.U.transpose());
      }
      w.u = w.tau;
      w.u.noalias() -= S.transpose() * w.pA;
      pa = w.pA + w.IA_passed * c;
      pa.noalias() += w.U * (w.D_inv * w.u);
    }
    w.inertia_ready = true;
    if (joint.parent == kGround) continue;
    Workspace& parent = d_.work[m_.slot_of_body[static_cast<std::size_t>(joint.parent)]];
    if (build) {
      const Mat6 X = w.X.matrix();
      parent.IA.noalias() += X.transpose() * w.IA_passed * X;
    }
    parent.pA += w.X.transpose_apply_force(pa);
  }
  // Pass 3: accelerations from ground out; ground accelerates at -g so that gravity needs no
  // force of its own (and the joint forces below include the weight they carry).
  Vec6 a_ground = Vec6::Zero();
  if (!impulsive) a_ground.tail<3>() = -model_.gravity_W;
  for (const std::size_t k : slots) {
    const TreeJoint& joint = m_.tree[k];
    Workspace& w = d_.work[k];
    const Vec6& a_P =
        joint.parent == kGround
            ? a_ground
            : d_.work[m_.slot_of_body[static_cast<std::size_t>(joint.parent)]].acceleration;
    Vec6 a = w.X.apply_motion(a_P);
    if (!impulsive) a += w.bias;
    const MotionSubspace& S = d_.S_of(joint, w);
    if (w.known) {
      if (joint.nv > 0) {
        a.noalias() += S * w.qdd;
        const Vec6 f = w.IA * a + w.pA;
        w.tau.noalias() = S.transpose() * f;
      }
    } else {
      w.qdd.noalias() = w.D_inv * (w.u - w.U.transpose() * a);
      a.noalias() += S * w.qdd;
    }
    w.acceleration = a;
  }
}

void ArticulatedFormulation::solve_with_contacts(double t) const {
  if (!loops_.empty()) {
    loops_.solve_forces(t);
  } else if (contacts_.empty()) {
    solve(s_.schedule_time, false);
  } else {
    contacts_.solve_forces();
  }
}

void ArticulatedFormulation::derivative(double t, const VecX& y, VecX& dydt) const {
  contacts_.set_time(t);
  calc_kinematics(y, true);
  accumulate_element_loads(y, s_.schedule_time, dydt, m_.ledger, nullptr);
  solve_with_contacts(t);
  write_state_rates(y, dydt);
  contacts_.write_powers(dydt, m_.ledger);
}

void ArticulatedFormulation::write_state_rates(const VecX& y, VecX& dydt) const {
  for (std::size_t k = 0; k < m_.tree.size(); ++k) {
    const TreeJoint& joint = m_.tree[k];
    const Workspace& w = d_.work[k];
    joint.kind->write_coordinate_rates(joint, y, d_.states[joint.child], dydt);
    if (joint.nv > 0) dydt.segment(joint.v, joint.nv) = w.qdd;
  }
  write_joint_powers(y, dydt, m_.ledger);
}

void ArticulatedFormulation::write_joint_powers(const VecX& y, VecX& rates,
                                                Eigen::Index offset) const {
  // Motors work at tau theta'; impulses and locks act only at their instants (and contacts' entries
  // are written by the contact subsystem's write_powers).
  Eigen::Index entry = offset + m_.first_motor_entry();
  for (const std::size_t j : m_.motor_joints) {
    const JointModel& joint = model_.joints[j];
    if (joint.closes_loop) {
      rates(entry++) = joint.motor.active_at(s_.schedule_time)
                           ? calc_loop_motor_load(joint, d_.states).power
                           : 0.0;
      continue;
    }
    const std::size_t k = static_cast<std::size_t>(m_.slot_of_joint[j]);
    const int f = joint.motor.freedom;
    rates(entry++) = d_.work[k].tau(f) * y(m_.tree[k].v + f);
  }
  for (; entry < rates.size(); ++entry) rates(entry) = 0.0;
}

bool ArticulatedFormulation::jacobian(double t, const VecX& y, MatX& dfdy) const {
  if (state_jacobian_ == nullptr) return false;
  holds_.resize(contacts_.size());
  if (!contacts_.empty()) contacts_.calc_holds(t, y, holds_);
  return state_jacobian_(shared_articulated_, s_.schedule_time, y, holds_, dfdy);
}

bool ArticulatedFormulation::gives_jacobian() const {
  return state_jacobian_ != nullptr;
}

void ArticulatedFormulation::pack(std::span<const BodyState> states, VecX& y) const {
  y.setZero();
  for (const TreeJoint& joint : m_.tree) {
    const BodyState& child = states[joint.child];
    const BodyState& parent = state_or_ground(states, joint.parent);
    joint.kind->pack(joint, parent, child, y);
  }
}

void ArticulatedFormulation::assemble(VecX& y) const {
  if (loops_.empty()) return;
  try {
    loops_.project(s_.schedule_time, y);
  } catch (const std::runtime_error& error) {
    // A loop that cannot close at the start is the scenario's problem: start_problem says so at
    // the closing joint.
    d_.assembly_problem = error.what();
  }
}

void ArticulatedFormulation::unpack_all(const VecX& y, std::span<BodyState> states) const {
  calc_kinematics(y, true);
  for (std::size_t i = 0; i < states.size(); ++i) states[i] = d_.states[i];
}

BodyState ArticulatedFormulation::unpack(const VecX& y, std::size_t body) const {
  calc_kinematics(y, true);
  return d_.states[body];
}

void ArticulatedFormulation::tolerance_units(const VecX& y0, VecX& units) const {
  units.setOnes();
  calc_kinematics(y0, true);
  accumulate_element_loads(y0, s_.schedule_time, d_.rates, 0, nullptr);
  std::vector<Vec6> element_wrenches_B(body_count(), Vec6::Zero());  // once, at the start
  for (std::size_t i = 0; i < body_count(); ++i) {
    element_wrenches_B[i] = d_.work[m_.slot_of_body[i]].external;
  }
  units.tail(m_.dimension - m_.ledger)
      .setConstant(ledger_unit(model_, d_.states, element_wrenches_B));
}

double ArticulatedFormulation::kinetic_energy() const {
  double T = 0.0;
  for (std::size_t k = 0; k < m_.tree.size(); ++k) {
    const RigidBody& body = model_.bodies[m_.tree[k].child];
    const Vec6& v = d_.work[k].velocity;
    T += 0.5 * v.dot(apply_inertia_about_com(body.mass, body.I_G_B, v));
  }
  return T;
}

Vec3 ArticulatedFormulation::angular_momentum_about_origin() const {
  Vec3 L = Vec3::Zero();
  for (std::size_t i = 0; i < body_count(); ++i) {
    L += calc_angular_momentum_about_point_W(model_.bodies[i], d_.states[i], Vec3::Zero());
  }
  return L;
}

JointReaction ArticulatedFormulation::reaction_of(std::size_t model_joint) const {
  if (model_.joints[model_joint].closes_loop) return loops_.reaction(model_joint);
  const std::size_t k = static_cast<std::size_t>(m_.slot_of_joint[model_joint]);
  const TreeJoint& joint = m_.tree[k];
  const Workspace& w = d_.work[k];
  // What the parent exerts on the child's subtree across the joint: I^A a + p^A, child axes,
  // about the child's COM; moved to the joint point.
  const Vec6 f = w.IA * w.acceleration + w.pA;
  const Vec3 F_C = f.tail<3>();
  const Vec3 M_J_C = f.head<3>() - joint.p_CJ_C.cross(F_C);
  const double sign = joint.reversed ? -1.0 : 1.0;
  return {sign * (w.R_WC * F_C), sign * (w.R_WC * M_J_C)};
}

void ArticulatedFormulation::calc_row_extras(double t, const VecX& y, RowExtras& extras) const {
  contacts_.set_time(t);
  calc_kinematics(y, true);
  accumulate_element_loads(y, s_.schedule_time, d_.rates, 0, &extras.elastic_energy);
  solve_with_contacts(t);
  extras.joints.resize(model_.joints.size());
  extras.coordinates.resize(model_.joints.size());
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    extras.joints[j] = reaction_of(j);
    const JointModel& joint = model_.joints[j];
    if (joint.closes_loop) continue;  // its coordinates are not in the state: it has no columns
    const TreeJoint& tree_joint = m_.tree[static_cast<std::size_t>(m_.slot_of_joint[j])];
    tree_joint.kind->calc_coordinate_columns(
        tree_joint, y, state_or_ground(d_.states, joint.body_a),
        state_or_ground(d_.states, joint.body_b), extras.coordinates[j].values);
  }
  extras.contacts.resize(model_.contacts.size());
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const ContactNow& now = contacts_.row_now(c);
    ContactOutput& out = extras.contacts[c];
    out.mode = static_cast<int>(contacts_.status(c).mode);
    out.normal_force = now.normal_force;
    out.friction_W = now.friction_W;
    out.slip_speed = now.slip_W.norm();
  }
  if (!loops_.empty()) extras.loops = loops_.errors_now();
  write_joint_powers(y, d_.rates, 0);
  contacts_.write_powers(d_.rates, 0);
  extras.elements.resize(static_cast<std::size_t>(d_.rates.size()));
  for (Eigen::Index i = 0; i < d_.rates.size(); ++i) {
    extras.elements[static_cast<std::size_t>(i)] = {d_.rates(i), y(m_.ledger + i)};
  }
}

void ArticulatedFormulation::begin(double t0, const VecX& y) {
  Formulation::begin(t0, y);
  loops_.retake_rank();
  contacts_.set_time(t0);
  s_.jumps.clear();
  contacts_.begin(t0, y);
}

void ArticulatedFormulation::at_breakpoint(double t, VecX& y) {
  s_.schedule_time = t;
  loops_.retake_rank();
  contacts_.set_time(t);
  const bool speeds_jumped = apply_jumps_at(t, y);
  contacts_.reclassify(t, y, speeds_jumped);
}

void ArticulatedFormulation::event_functions(double t, const VecX& y, VecX& g) const {
  contacts_.event_functions(t, y, g);
}

EventAction ArticulatedFormulation::on_event(std::size_t event_index, double t, VecX& y) {
  contacts_.on_event(event_index, t, y);
  return EventAction::Jump;
}

void ArticulatedFormulation::project(double t, VecX& y) const {
  contacts_.project(t, y);
  if (!loops_.empty()) loops_.project(t, y);
}

bool ArticulatedFormulation::refresh_event_functions(double t, const VecX& y) {
  return contacts_.refresh_event_functions(t, y);
}

double ArticulatedFormulation::step_limit(double t, const VecX& y) const {
  return contacts_.step_limit(t, y);
}

std::optional<Formulation::StartProblem> ArticulatedFormulation::start_problem(
    const VecX& y0) const {
  if (std::optional<ContactSystem::StartProblem> problem = contacts_.start_problem(y0)) {
    return StartProblem{problem->contact, std::move(problem->why)};
  }
  if (loops_.empty()) return std::nullopt;
  if (!d_.assembly_problem.empty()) {
    return StartProblem{0, d_.assembly_problem, static_cast<int>(loops_.first_joint())};
  }
  // The freedoms the tree's joints give the bodies relative to each other and to ground, less
  // the loops' independent constraints: with none left and nothing driven, the loops make a
  // structure, whose reactions no motion decides. A floating group's own six freedoms (its free
  // joint's) are its own whatever a loop does, since a loop joins bodies already joined; but a
  // rod (a distance joint) may join the group to ground or to another group, and then takes its
  // share of them.
  const auto root_slot = [&](int body) {  // the joint that hangs the body's tree (-1: ground)
    if (body == kGround) return -1;
    return static_cast<int>(m_.tree_root[m_.slot_of_body[static_cast<std::size_t>(body)]]);
  };
  std::vector<bool> held_by_a_rod(m_.tree.size(), false);
  for (const JointModel& joint : model_.joints) {
    if (joint.type != JointType::Distance) continue;
    const int a = root_slot(joint.body_a), b = root_slot(joint.body_b);
    if (a == b) continue;
    for (const int slot : {a, b}) {
      if (slot >= 0) held_by_a_rod[static_cast<std::size_t>(slot)] = true;
    }
  }
  Eigen::Index freedoms = 0;
  bool driven = false;
  for (std::size_t k = 0; k < m_.tree.size(); ++k) {
    const TreeJoint& joint = m_.tree[k];
    if (joint.nv == 0) continue;
    if (joint.type == JointType::Free) {
      if (held_by_a_rod[k]) freedoms += joint.nv;
      continue;
    }
    if (m_.prescribed(k, s_.schedule_time)) {
      driven = true;
    } else {
      freedoms += joint.nv;
    }
  }
  const Eigen::Index constraints = loops_.rank_at(y0);
  if (driven || freedoms > constraints) return std::nullopt;
  return StartProblem{0,
                      fmt::format("the joints that close loops ({}) leave nothing free to move: "
                                  "the other joints' {} freedoms are all taken by the loops' {} "
                                  "independent constraints, and no motor drives one (a "
                                  "structure, whose reactions are statically indeterminate); "
                                  "take a joint out, or drive one at a speed",
                                  loops_.joint_names(), freedoms, constraints),
                      static_cast<int>(loops_.first_joint())};
}

bool ArticulatedFormulation::apply_jumps_at(double t, VecX& y) {
  calc_kinematics(y, true);
  // Impulses now, on the body, about its COM, child axes (and the loops' share, if any); the
  // joints that lock (every freedom) or whose speed motor starts now jump to their rates, and
  // the other prescribed joints keep theirs. Returns what jumps.
  const auto load_jumps = [&](std::span<const BodyWrench> loop_impulses) {
    std::string what;
    const auto note = [&](const std::string& item) { what += (what.empty() ? "" : ", ") + item; };
    for (Workspace& w : d_.work) w.external.setZero();
    for (const ImpulseLoad& impulse : model_.impulses) {
      if (impulse.time != t) continue;
      Workspace& w = d_.work[m_.slot_of_body[impulse.body]];
      const Vec3 J_W = impulse.body_frame ? Vec3(w.R_WC * impulse.value) : impulse.value;
      w.external.head<3>() += w.R_WC.transpose() * (w.R_WC * impulse.p_GP_B).cross(J_W);
      w.external.tail<3>() += w.R_WC.transpose() * J_W;
      note("impulse " + impulse.name);
    }
    for (const BodyWrench& impulse : loop_impulses) {
      d_.work[m_.slot_of_body[impulse.body]].external += impulse.wrench_B;
    }
    for (std::size_t k = 0; k < m_.tree.size(); ++k) {
      const TreeJoint& joint = m_.tree[k];
      Workspace& w = d_.work[k];
      if (joint.nv == 0 || !m_.prescribed(k, t)) continue;
      w.qdd.setZero();
      const JointModel& model_joint = model_.joints[static_cast<std::size_t>(joint.model_joint)];
      const double rate = y(joint.v);
      if (model_joint.lock_at == t) {
        w.qdd = -y.segment(joint.v, joint.nv);
        note("lock " + model_joint.name);
      } else if (t < model_joint.lock_at && model_joint.motor.kind == JointMotor::Kind::Speed &&
                 model_joint.motor.from == t) {
        w.qdd(0) = model_joint.motor.value - rate;
        note("motor " + model_joint.name + " starts");
      }
    }
    return what;
  };
  const std::string what = load_jumps({});
  if (what.empty()) return false;

  JumpRecord record;
  record.t = t;
  record.what = what;
  record.kinetic_energy_before = kinetic_energy();
  record.angular_momentum_before_W = angular_momentum_about_origin();
  std::vector<BodyState> before(d_.states);
  solve(t, true);
  if (!loops_.empty()) {
    // The loops take their share of the blow: the impulses that put the tree's jumped velocities
    // onto the loops' tangent (ideal joints: they do no work). With them, the same passes give
    // the whole jump and every tree joint's reaction impulse.
    VecX jumped = y;
    for (std::size_t k = 0; k < m_.tree.size(); ++k) {
      const TreeJoint& joint = m_.tree[k];
      if (joint.nv > 0) jumped.segment(joint.v, joint.nv) += d_.work[k].qdd;
    }
    const std::span<const BodyWrench> loop_impulses = loops_.tangent_impulses(jumped);
    calc_kinematics(y, true);
    load_jumps(loop_impulses);
    solve(t, true);
  }
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    record.reaction_impulses.push_back(reaction_of(j));
  }
  // Work at an instant: the impulse times the mean of the velocities before and after it, for
  // impulses on body points and for the angular impulses of locks and starting motors alike.
  std::vector<SpeedStep> rate_before(m_.tree.size());
  for (std::size_t k = 0; k < m_.tree.size(); ++k) {
    const TreeJoint& joint = m_.tree[k];
    if (joint.nv == 0) continue;
    rate_before[k] = y.segment(joint.v, joint.nv);
    y.segment(joint.v, joint.nv) += d_.work[k].qdd;
  }
  calc_kinematics(y, true);
  record.kinetic_energy_after = kinetic_energy();
  record.angular_momentum_after_W = angular_momentum_about_origin();

  Eigen::Index slot = m_.ledger + m_.first_motor_entry();
  for (const std::size_t j : m_.motor_joints) {
    const JointModel& joint = model_.joints[j];
    // (A loop's closing joint takes no speed motor: the reader refuses one.)
    if (joint.motor.kind == JointMotor::Kind::Speed && joint.motor.from == t && t < joint.lock_at) {
      const std::size_t k = static_cast<std::size_t>(m_.slot_of_joint[j]);
      y(slot) += d_.work[k].tau(0) * 0.5 * (rate_before[k](0) + y(m_.tree[k].v));
    }
    ++slot;
  }
  for (const ImpulseLoad& impulse : model_.impulses) {
    if (impulse.time == t) {
      const BodyState& b0 = before[impulse.body];
      const BodyState& b1 = d_.states[impulse.body];
      const Vec3 J_W = impulse.body_frame ? Vec3(b0.R_WB * impulse.value) : impulse.value;
      const Vec3 p_W = b0.R_WB * impulse.p_GP_B;
      y(slot) += J_W.dot(0.5 * (velocity_of_point(b0.v_G, b0.omega_W, p_W) +
                                velocity_of_point(b1.v_G, b1.omega_W, p_W)));
    }
    ++slot;
  }
  for (const std::size_t j : m_.lock_joints) {
    const std::size_t k = static_cast<std::size_t>(m_.slot_of_joint[j]);
    if (model_.joints[j].lock_at == t) {
      // Each freedom's torque or force times its mean rate (its rate after is zero).
      const Workspace& w = d_.work[k];
      double work = w.tau(0) * 0.5 * rate_before[k](0);
      for (Eigen::Index i = 1; i < w.tau.size(); ++i) work += w.tau(i) * 0.5 * rate_before[k](i);
      y(slot) += work;
    }
    ++slot;
  }
  s_.jumps.push_back(std::move(record));
  return true;
}

}  // namespace tumble
