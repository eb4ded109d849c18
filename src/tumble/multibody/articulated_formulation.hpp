#pragma once
// The production formulation for systems: bodies held by joints (ball, hinge, fixed) in a tree
// rooted at ground, in joint coordinates, integrated with Featherstone's articulated-body
// algorithm (RBDA 2008, ch. 7): O(n) per evaluation for n bodies, and the joints hold by
// construction (the state has no coordinates that could break them), so nothing drifts off the
// constraints and no stabilisation is needed. Hinges that are locked or driven at a prescribed
// speed are joints of known acceleration (hybrid dynamics, RBDA ch. 9.2); their torque is the
// motor's or the brake's. Joint reactions come from the same passes: the spatial force across
// joint i is I^A_i a_i + p^A_i.
//
// State y = [ joint coordinates | joint speeds | work ledger ]: the work each element has done
// since t0 is integrated with the motion (its power is one more right-hand side), so the rows can
// report it to the integrator's accuracy. Impulses, motor starts and locks are breakpoints: the
// speeds jump there by the impulsive form of the same algorithm.
//
// Contacts with planes (articulated_contacts.cpp) make it a hybrid system: each contact is apart,
// sliding or rolling, and only located events change that. In a mode the contact's force is
// whatever keeps its constraints' accelerations zero (sliding: the normal one, with Coulomb's
// friction mu N against the slip; rolling: all three), found from the same algorithm's response
// to unit forces; project() puts positions and velocities back on the constraints after every
// step. Touchdowns are impacts (restitution and friction on the impulse).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tumble/contact/plane_contact.hpp"

#include "tumble/dynamics/formulation.hpp"
#include "tumble/multibody/kinematic_tree.hpp"

namespace tumble {

// A jump of the speeds at a breakpoint, for the summary.
// A contact's mode change or impact, for the summary.
struct ContactEventRecord {
  double t = 0.0;
  std::size_t contact = 0;
  std::string what;  // "touchdown, rolls", "impact: normal speed 4.4 -> 3.5 m/s", "slides", ...
};

struct JumpRecord {
  double t = 0.0;
  std::string what;  // "impulse hit", "lock knob", "motor wheel starts"
  double kinetic_energy_before = 0.0, kinetic_energy_after = 0.0;
  Vec3 angular_momentum_before_W = Vec3::Zero();  // about the world origin
  Vec3 angular_momentum_after_W = Vec3::Zero();
  std::vector<JointReaction> reaction_impulses;  // N s and N m s, one per Model::joints entry
};

class ArticulatedFormulation final : public Formulation {
 public:
  // Throws std::invalid_argument if the joints close a loop.
  explicit ArticulatedFormulation(Model model);

  std::string_view name() const override { return "body, joint coordinates"; }
  Eigen::Index dimension() const override { return dimension_; }
  void derivative(double t, const VecX& y, VecX& dydt) const override;
  std::span<const Eigen::Index> unit_quaternion_offsets() const override {
    return quaternion_offsets_;
  }
  // Joint coordinates from the bodies' states: each joint takes the relative angular velocity
  // its freedoms allow (a hinge the component along its axis); velocities the joints forbid are
  // dropped. consistency_error() says by how much.
  void pack(std::span<const BodyState> states, VecX& y) const override;
  BodyState unpack(const VecX& y, std::size_t body) const override;
  void unpack_all(const VecX& y, std::span<BodyState> states) const override;

  // A new run starts with no jumps recorded.
  void begin(double t0, const VecX& y) override;
  void at_breakpoint(double t, VecX& y) override;

  // Contact events, three per contact: touchdown (height reaches 0 while apart), lift-off (the
  // normal force reaches 0), and stick-slip (sliding: the slip stops; rolling: the friction it
  // needs reaches the cone's edge).
  std::span<const EventSpec> events() const override { return event_specs_; }
  void event_functions(double t, const VecX& y, VecX& g) const override;
  EventAction on_event(std::size_t event_index, double t, VecX& y) override;
  // Also puts each touching contact back on the plane and its velocity on the mode's
  // constraints (no normal velocity; rolling: no slip).
  void project(double t, VecX& y) const override;
  bool refresh_event_functions(double t, const VecX& y) override;
  const std::vector<ContactEventRecord>& contact_events() const { return contact_events_; }
  // Why the bodies cannot start where the scenario puts them (a contact inside its plane, or
  // touching it and moving into it), if they cannot.
  struct ContactStartProblem {
    std::size_t contact = 0;
    std::string why;
  };
  std::optional<ContactStartProblem> contact_start_problem(const VecX& y0) const;

  std::vector<std::string> element_names() const override;
  void calc_row_extras(double t, const VecX& y, RowExtras& extras) const override;

  const std::vector<TreeJoint>& tree() const { return tree_; }
  const std::vector<JumpRecord>& jumps() const { return jumps_; }
  // The hinge angle and rate of a model joint (its sign as the scenario states it).
  double hinge_angle(const VecX& y, std::size_t joint) const;
  double hinge_rate(const VecX& y, std::size_t joint) const;

 private:
  using SpeedMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  using SpeedVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
  // Per tree joint, what the passes compute (child axes at the child's COM).
  struct Workspace {
    Mat3 R_WC = Mat3::Identity();
    Vec3 r_G_W = Vec3::Zero();
    Transform X;                       // parent coordinates -> child coordinates
    Vec6 velocity = Vec6::Zero();      // spatial velocity of the child
    Vec6 bias = Vec6::Zero();          // c = v x (S qdot)
    Vec6 external = Vec6::Zero();      // applied force (or impulse) on the child, child axes
    Mat6 IA = Mat6::Zero();            // articulated inertia
    Vec6 pA = Vec6::Zero();            // articulated bias force
    MotionSubspace U;                  // IA S
    SpeedMatrix D_inv;                 // (S^T IA S)^-1
    SpeedVector u;                     // tau - S^T pA
    SpeedVector tau;                   // generalized force on the joint's freedoms
    SpeedVector qdd;                   // joint accelerations (or speed jumps)
    Vec6 acceleration = Vec6::Zero();  // spatial acceleration (with -g at ground)
    bool known = false;                // prescribed: qdd is given, tau follows
    Vec6 applied = Vec6::Zero();       // the loads in `external` before contact forces join them
  };
  enum class ContactMode { Apart = 0, Sliding = 1, Rolling = 2 };
  struct ContactStatus {
    ContactMode mode = ContactMode::Apart;
    Vec3 slide_direction_W = Vec3::UnitX();  // slip direction while the slip speed is ~0
    double slip_zero = 0.0;                  // m/s: slower slip counts as none
    double settle_speed = 0.0;               // m/s: slower touchdowns settle instead of bouncing
    double touching_height = 0.0;            // m: nearer the plane counts as touching
  };
  // What calc_contact_points and solve_with_contacts found for each contact at the current y.
  struct ContactNow {
    SupportPoint support;
    Vec3 n_B = Vec3::UnitZ();
    Vec3 support_rate_B = Vec3::Zero();  // the contact point's motion over the body
    Vec3 velocity_W = Vec3::Zero();      // of the body's material point at the contact
    Vec3 slip_W = Vec3::Zero();          // its tangential part
    Vec3 force_W = Vec3::Zero();         // on the body at the contact
    double normal_force = 0.0;           // force_W's component along the plane's normal
    Vec3 friction_W = Vec3::Zero();      // force_W's tangential part
  };
  // One unknown of the contact forces and the constraint row that goes with it.
  struct ContactUnknown {
    std::size_t contact = 0;
    Vec3 row_W = Vec3::Zero();    // the constraint: row . (acceleration or velocity) = 0
    Vec3 force_W = Vec3::Zero();  // the force per unit of the unknown
  };
  enum class ContactRows { Motion, Projection };
  // Positions and velocities of every body from y (forward pass), into the workspace.
  void calc_kinematics(const VecX& y, bool with_velocities) const;
  // The articulated-body passes after calc_kinematics, in the modes of `mode_time`: the
  // accelerations (impulsive = false), or the jumps of the speeds that the impulses in
  // Workspace::external cause with the prescribed joints jumping by their Workspace::qdd
  // (impulsive = true: no velocity terms, no gravity).
  void solve(double mode_time, bool impulsive) const;
  // Locked hinges, hinges driven at a speed, fixed joints: their acceleration is known.
  bool prescribed(std::size_t tree_index, double mode_time) const;
  // Applied loads and force elements on each body (into Workspace::external); their powers into
  // rates from `offset` on, in ledger order; the springs' stored energy into elastic_energy.
  void accumulate_element_loads(const VecX& y, double mode_time, VecX& rates, Eigen::Index offset,
                                double* elastic_energy) const;
  // Ledger entry of the first motor (after the loads, springs and torsional springs).
  Eigen::Index first_motor_entry() const;
  // Motors' powers (tau theta', after solve()) and zero for impulses and locks, into rates from
  // offset + first_motor_entry() to the end.
  void write_joint_powers(const VecX& y, VecX& rates, Eigen::Index offset) const;
  JointReaction reaction_of(std::size_t model_joint) const;

  // Contacts (articulated_contacts.cpp).
  void set_up_contacts();
  // The contacts' modes at the start: touching ones roll or slide, the others are apart.
  void begin_contacts(double t0, const VecX& y);
  // After a breakpoint (a load switched, an impulse): the touching contacts' modes again.
  void reclassify_contacts(double t, VecX& y);
  // Impulses, locks and starting motors at a breakpoint.
  void apply_jumps_at(double t, VecX& y);
  // Support points and contact-point velocities, after calc_kinematics.
  void calc_contact_points() const;
  // solve() with the contact forces of the current modes, after calc_kinematics and
  // accumulate_element_loads; fills contact_now_.
  void solve_with_contacts(double mode_time) const;
  // Kinematics, loads and solve_with_contacts at y, in the current modes.
  void solve_contacts_at(const VecX& y) const;
  // The unknowns of the touching contacts' forces: their constraints in each mode (Motion) or
  // the velocity constraints with normal impulses for sliding contacts (Projection). Returns
  // their count.
  Eigen::Index gather_contact_unknowns(ContactRows rows) const;
  // The constraint matrix A (rows: unknowns_ rows, columns: their forces) from impulsive solves
  // of unit forces; leaves every Workspace::external zero.
  void calc_contact_matrix(Eigen::Index count, double mode_time) const;
  // Jump the speeds by the impulses x_j along unknowns_[j].force_W.
  void apply_contact_impulses(Eigen::Index count, const VecX& impulses, double mode_time,
                              VecX& y) const;
  // The current slip direction of a sliding contact.
  Vec3 slide_direction(std::size_t contact) const;
  // The mode a touching contact takes now (slip stopped, touchdown settled, start): rolling if
  // the friction that needs fits in the cone, else sliding the way the body is pushed.
  void classify_contact(std::size_t contact, double t, VecX& y);
  void impact(std::size_t contact, double t, VecX& y);
  void note_contact(double t, std::size_t contact, std::string what);
  // The ledger entry of a contact (after the locks).
  Eigen::Index contact_entry(std::size_t contact) const;
  void write_contact_powers(VecX& rates, Eigen::Index offset) const;
  double kinetic_energy() const;
  Vec3 angular_momentum_about_origin() const;  // from states_

  std::vector<TreeJoint> tree_;
  std::vector<std::size_t> slot_of_body_;  // tree index of each body's inbound joint
  std::vector<bool> has_children_;         // per tree joint: another body hangs from its child
  std::vector<int> slot_of_joint_;         // tree index of each model joint
  std::vector<Eigen::Index> quaternion_offsets_;
  Eigen::Index speeds_ = 0, ledger_ = 0, dimension_ = 0;
  // Ledger order: loads, springs, torsional springs, motors, impulses, locks.
  std::vector<std::size_t> motor_joints_, lock_joints_;
  std::vector<JumpRecord> jumps_;
  std::vector<ContactStatus> contact_status_;
  std::vector<EventSpec> event_specs_;
  std::vector<ContactEventRecord> contact_events_;
  mutable std::vector<ContactNow> contact_now_;
  mutable std::vector<ContactUnknown> unknowns_;  // sized to 3 per contact
  mutable MatX contact_matrix_;
  mutable VecX contact_rhs_, contact_x_;
  // Scratch of derivative() and the other const queries, sized once here: no allocation per call.
  mutable std::vector<Workspace> work_;
  mutable std::vector<BodyState> states_;
  mutable VecX rates_;
};

}  // namespace tumble
