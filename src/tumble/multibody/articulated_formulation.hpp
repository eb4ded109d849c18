#pragma once
// The production formulation for systems: bodies held by joints (multibody/joints/: ball, hinge,
// prismatic, fixed) in a tree rooted at ground, in joint coordinates, integrated with
// Featherstone's articulated-body algorithm (RBDA 2008, ch. 7): O(n) per evaluation for n bodies,
// and the joints hold by construction (the state has no coordinates that could break them), so
// nothing drifts off the constraints and no stabilisation is needed. Hinges and sliders that are
// locked or driven at a prescribed speed are joints of known acceleration (hybrid dynamics, RBDA
// ch. 9.2); their torque or force is the motor's or the brake's. Joint reactions come from the same
// passes: the spatial force across joint i is I^A_i a_i + p^A_i.
//
// State y = [ joint coordinates | joint speeds | work ledger ]: the work each element has done
// since t0 is integrated with the motion (its power is one more right-hand side), so the rows can
// report it to the integrator's accuracy. Impulses, motor starts and locks are breakpoints: the
// speeds jump there by the impulsive form of the same algorithm.
//
// Contacts with planes make it a hybrid system: the contact subsystem (contact/contact_system.hpp)
// keeps their modes, events, impacts and projection, and asks of this formulation only what
// ContactDynamics offers: a body's pose, twist and acceleration, and the passes' response to
// unit wrenches and impulses. So a contact works on any body of the tree.
//
// Model, data, state: the ArticulatedModel (tree, layout, events) is constant and shared by every
// run; this object is one run's, with its ArticulatedData (scratch, written by the const
// evaluations) and its HybridState (Formulation::hybrid_state). new_run() makes another.
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tumble/contact/contact_dynamics.hpp"
#include "tumble/contact/contact_system.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/multibody/articulated_data.hpp"
#include "tumble/multibody/articulated_model.hpp"
#include "tumble/multibody/loop_joints.hpp"

namespace tumble {

class ArticulatedFormulation final : public Formulation {
 public:
  // One run of a shared model, with its own scratch and state.
  explicit ArticulatedFormulation(std::shared_ptr<const ArticulatedModel> model);
  // Throws std::invalid_argument if the joints close a loop, or a body a joint holds touches a
  // plane with a round body (a disk, ring, cylinder, tube or cone).
  explicit ArticulatedFormulation(Model model);

  std::unique_ptr<Formulation> new_run() const override {
    auto run = std::make_unique<ArticulatedFormulation>(shared_articulated_);
    run->state_jacobian_ = state_jacobian_;
    return run;
  }

  std::string_view name() const override { return "body, joint coordinates"; }
  Eigen::Index dimension() const override { return m_.dimension; }
  void derivative(double t, const VecX& y, VecX& dydt) const override;
  std::span<const Eigen::Index> unit_quaternion_offsets() const override {
    return m_.quaternion_offsets;
  }
  // Joint coordinates from the bodies' states: each joint takes the relative angular velocity
  // its freedoms allow (a hinge the component along its axis); velocities the joints forbid are
  // dropped.
  void pack(std::span<const BodyState> states, VecX& y) const override;
  // The loops closed (LoopJoints::project): the velocities go onto their tangent by the least
  // change in kinetic energy, so that the bodies of a loop may leave theirs to the joints.
  void assemble(VecX& y) const override;
  BodyState unpack(const VecX& y, std::size_t body) const override;
  void unpack_all(const VecX& y, std::span<BodyState> states) const override;

  // A new run starts with no jumps recorded.
  void begin(double t0, const VecX& y) override;
  void at_breakpoint(double t, VecX& y) override;

  // The contacts' events, projection, step limit and start check are the contact subsystem's
  // (contact/contact_system.hpp): three events per contact (touchdown, support, stick-slip).
  std::span<const EventSpec> events() const override { return m_.event_specs; }
  void event_functions(double t, const VecX& y, VecX& g) const override;
  EventAction on_event(std::size_t event_index, double t, VecX& y) override;
  // df/dy at the schedule's mode and the contacts' modes (each as contact/contact_hold.hpp says),
  // from the function set_state_jacobian gave (false without one).
  bool jacobian(double t, const VecX& y, MatX& dfdy) const override;
  // With a source.
  bool gives_jacobian() const override;
  // The Jacobian's source: automatic differentiation of the one physics
  // (modes/state_jacobian.hpp), which this layer does not depend on; the simulation layer hands
  // it over (FormulationModel::new_run).
  using StateJacobian = bool (*)(const std::shared_ptr<const ArticulatedModel>& model, double t,
                                 const VecX& y, std::span<const ContactHold> holds, MatX& dfdy);
  void set_state_jacobian(StateJacobian source) { state_jacobian_ = source; }
  // Normalises the quaternions, then puts each touching contact back on the plane and its
  // velocity on the mode's constraints (no normal velocity; rolling: no slip), and closes the
  // loops (LoopJoints::project).
  void project(double t, VecX& y) const override;
  bool refresh_event_functions(double t, const VecX& y) override;
  // While a contact is apart: no step so long that a point of its surface could dip through the
  // plane and back unseen (contact/landing_bound.hpp).
  double step_limit(double t, const VecX& y) const override;
  bool events_rescreened() const override { return contacts_.events_rescreened(); }
  std::optional<StartProblem> start_problem(const VecX& y0) const override;

  // The work ledger's entries are held to atol in units of what the system's energy changes by
  // when its state is off by a unit of each coordinate and speed (ledger_unit, J), the
  // coordinates and speeds to atol in their own units. Held to atol joules, a heavy body's books
  // (a cone of 1e9 kg rolling, whose contact's power N v is round-off of a 5e9 N force) asked for
  // less than round-off and took 2,000 times the steps of the same motion at 1 kg.
  void tolerance_units(const VecX& y0, VecX& units) const override;

  std::vector<std::string> element_names() const override { return m_.element_names(); }
  bool keeps_work_ledger() const override { return true; }
  void calc_row_extras(double t, const VecX& y, RowExtras& extras) const override;

  const std::vector<TreeJoint>& tree() const { return m_.tree; }
  const std::shared_ptr<const ArticulatedModel>& shared_articulated_model() const {
    return shared_articulated_;
  }
  double joint_rate(const VecX& y, std::size_t joint) const override {
    return m_.joint_rate(y, joint);
  }

 private:
  using Workspace = ArticulatedData::Workspace;
  using SpeedMatrix = ArticulatedData::SpeedMatrix;
  using SpeedVector = ArticulatedData::SpeedVector;
  // Positions and velocities of every body from y (forward pass), into the workspace.
  void calc_kinematics(const VecX& y, bool with_velocities) const;
  // The articulated-body passes after calc_kinematics, in the modes of `mode_time`: the
  // accelerations (impulsive = false), or the jumps of the speeds that the impulses in
  // Workspace::external cause with the prescribed joints jumping by their Workspace::qdd
  // (impulsive = true: no velocity terms, no gravity).
  // With `only_tree` (a tree index whose parent is ground), only that subtree: the bodies of
  // the others do not move under loads on it (their workspaces are left as they were).
  static constexpr std::size_t kEveryTree = static_cast<std::size_t>(-1);
  void solve(double mode_time, bool impulsive, std::size_t only_tree = kEveryTree) const;
  // Applied loads, force elements and the efforts of motors across loops' closing joints on each
  // body (into Workspace::external); the loads' and elements' powers into rates from `offset` on,
  // in ledger order (the motors' are write_joint_powers'); the springs' stored energy into
  // elastic_energy.
  void accumulate_element_loads(const VecX& y, double mode_time, VecX& rates, Eigen::Index offset,
                                double* elastic_energy) const;
  // solve() with the contacts' forces in their current modes (the contact subsystem's
  // solve_forces) and the loops' (LoopJoints::solve_forces), after calc_kinematics and
  // accumulate_element_loads.
  void solve_with_contacts(double t) const;
  // Motors' powers (tau theta', after solve(); across a loop's closing joint, its effort times
  // the joint's rate) and zero for impulses and locks, into rates from
  // offset + first_motor_entry() to the end.
  void write_joint_powers(const VecX& y, VecX& rates, Eigen::Index offset) const;
  // After the last solve: every joint's coordinate rates and accelerations into dydt, and the
  // joints' powers into its ledger (write_joint_powers).
  void write_state_rates(const VecX& y, VecX& dydt) const;
  JointReaction reaction_of(std::size_t model_joint) const;
  // Impulses, locks and starting motors at a breakpoint; whether any jumped the speeds.
  bool apply_jumps_at(double t, VecX& y);
  double kinetic_energy() const;               // from the workspaces' velocities
  Vec3 angular_momentum_about_origin() const;  // from the states of the last calc_kinematics

  // What the contact subsystem asks of the dynamics (contact/contact_dynamics.hpp), for a body
  // anywhere in the tree: its pose, twist and acceleration are its workspace's; the responses
  // are the impulsive passes; a body moves with the others hung from the same ground joint.
  class ContactBodies final : public ContactDynamics {
   public:
    explicit ContactBodies(const ArticulatedFormulation& f);
    const BodyState& state(std::size_t body) const override;
    void calc_motion(const VecX& y, bool with_velocities) const override;
    void gather_loads(const VecX& y) const override;
    void gather_loads(const VecX& y, VecX& dydt) const override;
    void write_rates(const VecX& y, VecX& dydt) const override;
    void solve_under_loads() const override;
    void solve_under_loads_and(std::span<const BodyWrench> wrenches) const override;
    void respond_to_unit_wrench(const BodyWrench& unit) const override;
    void respond_to_impulses(std::span<const BodyWrench> impulses) const override;
    void apply_speed_jumps(VecX& y) const override;
    void apply_displacement(VecX& y) const override;
    bool moves_freely(std::size_t body) const override;
    void translate(std::size_t body, const Vec3& delta_W, VecX& y) const override;
    void normalise(double t, VecX& y) const override;
    double kinetic_energy() const override;
    Eigen::Index ledger_start() const override;
    Eigen::Index work_entry(std::size_t contact) const override;
    Eigen::Index contact_ledger_size() const override;

   private:
    const ArticulatedFormulation& f_;
  };

  StateJacobian state_jacobian_ = nullptr;
  // How each contact holds its body, for the Jacobian (refreshed at each one asked for).
  mutable std::vector<ContactHold> holds_;
  std::shared_ptr<const ArticulatedModel> shared_articulated_;
  const ArticulatedModel& m_;  // *shared_articulated_: constant, shared by every run
  // This run's scratch, written by const evaluations (derivative, event functions, rows): a
  // formulation serves one thread at a time.
  std::unique_ptr<ArticulatedData> data_;
  ArticulatedData& d_;  // *data_
  HybridState& s_;      // hybrid_: the modes and records (Formulation::hybrid_state)
  ContactBodies contact_bodies_;
  ContactSystem contacts_;  // the planes' contacts, their scratch, and their state in s_.contact
  LoopJoints loops_;        // the joints that close loops: constraints on the tree
};

}  // namespace tumble
