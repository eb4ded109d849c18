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
// Contacts with planes (articulated_contacts.cpp) make it a hybrid system: each contact is apart,
// sliding or rolling, and only located events change that. In a mode the contact's force is
// whatever keeps its constraints' accelerations zero (sliding: the normal one, with Coulomb's
// friction mu N against the slip; rolling: all three), found from the same algorithm's response
// to unit forces; project() puts positions and velocities back on the constraints after every
// step. Touchdowns are impacts (restitution and friction on the impulse).
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

#include "tumble/dynamics/formulation.hpp"
#include "tumble/multibody/articulated_data.hpp"
#include "tumble/multibody/articulated_model.hpp"

namespace tumble {

class ArticulatedFormulation final : public Formulation {
 public:
  // One run of a shared model, with its own scratch and state.
  explicit ArticulatedFormulation(std::shared_ptr<const ArticulatedModel> model);
  // Throws std::invalid_argument if the joints close a loop, or a body a joint holds touches a
  // plane with anything but a sphere's or shell's point.
  explicit ArticulatedFormulation(Model model);

  std::unique_ptr<Formulation> new_run() const override {
    return std::make_unique<ArticulatedFormulation>(shared_articulated_);
  }

  std::string_view name() const override { return "body, joint coordinates"; }
  Eigen::Index dimension() const override { return m_.dimension; }
  void derivative(double t, const VecX& y, VecX& dydt) const override;
  std::span<const Eigen::Index> unit_quaternion_offsets() const override {
    return m_.quaternion_offsets;
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

  // Contact events, three per contact: touchdown (a contact point, or a polyhedron's vertex not
  // yet touching, reaches the plane), support (the normal force reaches 0: lift-off; or a
  // polyhedron's centre of pressure reaches its feature's side: it tips), and stick-slip
  // (sliding: the slip stops; rolling or sticking: the friction it needs reaches the cone's
  // edge).
  std::span<const EventSpec> events() const override { return m_.event_specs; }
  void event_functions(double t, const VecX& y, VecX& g) const override;
  EventAction on_event(std::size_t event_index, double t, VecX& y) override;
  // Also puts each touching contact back on the plane and its velocity on the mode's
  // constraints (no normal velocity; rolling: no slip).
  void project(double t, VecX& y) const override;
  bool refresh_event_functions(double t, const VecX& y) override;
  // While a contact is apart: no step so long that a point of its surface could dip through the
  // plane and back unseen (contact/landing_bound.hpp).
  double step_limit(double t, const VecX& y) const override;
  std::optional<StartProblem> start_problem(const VecX& y0) const override;

  std::vector<std::string> element_names() const override { return m_.element_names(); }
  bool keeps_work_ledger() const override { return true; }
  void calc_row_extras(double t, const VecX& y, RowExtras& extras) const override;

  const std::vector<TreeJoint>& tree() const { return m_.tree; }
  double joint_rate(const VecX& y, std::size_t joint) const override {
    return m_.joint_rate(y, joint);
  }

 private:
  using Workspace = ArticulatedData::Workspace;
  using ContactNow = ArticulatedData::ContactNow;
  using ContactUnknown = ArticulatedData::ContactUnknown;
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
  // Applied loads and force elements on each body (into Workspace::external); their powers into
  // rates from `offset` on, in ledger order; the springs' stored energy into elastic_energy.
  void accumulate_element_loads(const VecX& y, double mode_time, VecX& rates, Eigen::Index offset,
                                double* elastic_energy) const;
  // Motors' powers (tau theta', after solve()) and zero for impulses and locks, into rates from
  // offset + first_motor_entry() to the end.
  void write_joint_powers(const VecX& y, VecX& rates, Eigen::Index offset) const;
  JointReaction reaction_of(std::size_t model_joint) const;

  // The contacts' modes at the start: touching ones roll or slide, the others are apart.
  void begin_contacts(double t0, const VecX& y);
  // After a breakpoint (a load switched, an impulse): the touching contacts' modes again.
  void reclassify_contacts(double t, VecX& y);
  // Impulses, locks and starting motors at a breakpoint.
  void apply_jumps_at(double t, VecX& y);
  // Contact points, reference points and their velocities, after calc_kinematics.
  void calc_contact_points() const;
  // calc_contact_points for a touching round body: its part's points, and what may land next.
  void calc_round_contact_points(std::size_t contact, const Vec3& omega_B) const;
  // solve() with the contact forces of the current modes, after calc_kinematics and
  // accumulate_element_loads; fills contact_now_.
  void solve_with_contacts(double mode_time) const;
  // Kinematics, loads and solve_with_contacts at y, in the current modes.
  void solve_contacts_at(const VecX& y) const;
  // Which constraints a contact's unknowns hold:
  //  - Motion: its mode's (sliding: the normal motion, with Coulomb's friction riding on each
  //    normal force; rolling or sticking: all its motion the feature allows);
  //  - Projection: as Motion, with no friction on sliding's normal impulses;
  //  - Position: the normal motion, with normal forces; a sticking polyhedron: its Projection
  //    rows (held at its anchor).
  enum class ContactRows { Motion, Projection, Position };
  // The unknowns of every touching contact (into unknowns_); returns their count.
  Eigen::Index gather_contact_unknowns(ContactRows rows) const;
  // Appends contact c's unknowns in `mode` at unknowns_[count...], with sliding friction along
  // `slide_W` (Motion); returns the new count.
  Eigen::Index append_contact_unknowns(std::size_t c, ContactMode mode, ContactRows rows,
                                       const Vec3& slide_W, Eigen::Index count) const;
  // The constraint matrix A (rows: unknowns_ rows, columns: their forces) from impulsive solves
  // of unit forces; leaves every Workspace::external zero.
  void calc_contact_matrix(Eigen::Index count, double mode_time) const;
  // Solves contact_matrix_ x = b for the leading count rows, in place (b becomes x); throws
  // std::runtime_error if the rows are redundant.
  void solve_contact_system(Eigen::Index count, VecX& x) const;
  // Each contact's resultant (contact_now_'s wrench, force, normal force, friction, moment about
  // O) from the unknowns' values x.
  void set_contact_resultants(Eigen::Index count, const VecX& x) const;
  // A row's value on the current velocities (after calc_kinematics).
  double row_velocity(const ContactUnknown& row) const;
  // The speed jumps (Workspace::qdd) that the impulses x_j along unknowns_[j] cause.
  void respond_to_contact_impulses(Eigen::Index count, const VecX& impulses,
                                   double mode_time) const;
  // Jump the speeds by the impulses x_j along unknowns_[j].
  void apply_contact_impulses(Eigen::Index count, const VecX& impulses, double mode_time,
                              VecX& y) const;
  // project()'s position step when a polyhedron or a round body touches (after
  // calc_contact_points).
  void project_feature_positions(VecX& y) const;
  // The current slip direction of a sliding contact (at time_now_).
  Vec3 slide_direction(std::size_t contact) const;
  // The slip direction of a contact that must slide with no slip yet: the way it is pushed,
  // against the friction sticking needs (from contact_now_).
  Vec3 pushed_direction(std::size_t contact) const;
  // Contact c, with no slip, starts to slide along pushed_direction (after a rolling solve at y;
  // articulated_slip_onset.cpp). True if the slip can grow that way: its acceleration along it
  // is positive or, where the needed friction has just reached the cone's edge (no acceleration),
  // its jerk is, with the direction turning as it needs. False where friction would drive the
  // slip back (Painleve's case: friction high enough that it presses the contact on).
  bool start_sliding(std::size_t contact, double t, const VecX& y);
  // Where the rolling contact c cannot start sliding: it lifts off if, with no force, its points
  // (a round body's other end too, if it is at the plane) leave the plane; if not, no mode is
  // consistent, and it slides along the pushed direction.
  void lift_off_or_hold_slide(std::size_t contact, double t, const VecX& y);
  // At the cone's edge: the rate the starting slip's direction turns at (into slide_turn_W);
  // false if no turn lets the slip grow.
  bool turn_starting_slip(std::size_t contact, double t, const VecX& y);
  // The slip's rate of change (slip_W's) after a solve, and at y sliding along slide_W.
  Vec3 slip_acceleration(std::size_t contact) const;
  Vec3 slip_acceleration_at(std::size_t contact, const VecX& y, const Vec3& slide_W);
  // The acceleration (world axes, gravity's included) of the point p_B that moves over the body
  // at rate_B, after a solve: d/dt of its velocity R (v_G + omega x p).
  Vec3 moving_point_acceleration_W(const Workspace& w, const Vec3& p_B, const Vec3& rate_B) const;
  // N times the CoP's least distance inside a polyhedron's feature (N itself for a point), and
  // the side of the feature where it is least; from contact_now_.
  double support_margin_of(std::size_t contact, int& side) const;
  // The friction the contact carries as a slip-space vector: the tangential force, and the
  // moment about the normal over the spin radius along the normal. Its length is what the
  // cone bounds by mu N; from contact_now_.
  Vec3 friction_demand(std::size_t contact) const;
  // The touching vertices of a polyhedron contact into touching_, after calc_kinematics: those
  // within touching_height of the plane, and those within `within` not moving away from it (at
  // least the lowest).
  void find_touching_vertices(std::size_t contact, double within) const;
  // The mode a touching contact takes now (slip stopped, touchdown settled, start): rolling or
  // sticking if the friction that needs fits in the cone, else sliding the way the body is
  // pushed; a polyhedron tips onto a smaller feature while its CoP would leave the feature.
  // Notes the mode if it changed (or, with always_note, in any case).
  void classify_contact(std::size_t contact, double t, VecX& y, bool always_note = false);
  // Tries contact c on its current feature: sticking if the friction fits, else sliding; true
  // if the forces are consistent (N > 0, the CoP in the feature, no touching vertex left out
  // going into the plane). Touching vertices: touching_.
  // A round body's candidates also name the points they leave out (left_out_B).
  bool settle_on_feature(std::size_t contact, double t, VecX& y,
                         std::span<const Vec3> left_out_B = {});
  // classify_contact's candidates for contact c (settle_on_feature on the feature, its edges,
  // its vertices; settle_round); true if one holds.
  bool settle_on_candidates(std::size_t contact, double t, VecX& y);
  // classify_contact for a round body: its touching part, then (if that is inconsistent) the
  // parts it may tip onto: the side onto either end's rim point, a face onto the rim point where
  // its CoP left. True if one holds.
  bool settle_round(std::size_t contact, double t, VecX& y);
  // A round body on one end's rim point (a cone's apex): the other end's lowest rim point, into
  // other_B; false on no end's rim point, or for a disk or ring, whose ends are one rim (after
  // calc_kinematics).
  bool round_other_end_B(std::size_t contact, Vec3& other_B) const;
  // A round body on its side or a face tips onto the end of the side (support margin's side 0:
  // end A's rim point, 1: end B's), or the face's rim point where the CoP leaves it (after a
  // solve).
  void tip_round(std::size_t contact, int side);
  void set_apart(std::size_t contact);
  // Whether contact c holds a rim point near flat, where its direction is kept up with after
  // each step.
  bool rim_direction_kept_up(std::size_t contact) const;
  // The acceleration along the plane's normal of the body's material point p_B (after a solve).
  double normal_acceleration(std::size_t contact, const Vec3& p_B) const;
  // The height above the plane of the body's point p_B, and its material velocity along the
  // plane's normal (after calc_kinematics).
  double height_above_plane(std::size_t contact, const Vec3& p_B) const;
  double normal_speed(std::size_t contact, const Vec3& p_B) const;
  // Whether a point at this height (within the landing height) moving at this normal speed lands
  // with the one that touches down.
  bool lands_with(std::size_t contact, double height, double normal_speed) const;
  // What the touchdown event sees of a point at this height moving at this normal speed.
  double watched_height(std::size_t contact, double height, double normal_speed) const;
  // Apart: the touchdown event's value, the least watched height over the points that may land
  // first, and the point that sets it (after calc_contact_points).
  double landing_watch(std::size_t contact, Vec3& landing_B) const;
  // A polyhedron that starts sticking: its anchor where it is now (after calc_contact_points).
  void anchor_contact(std::size_t contact);
  // Whether contact c, sticking, is held at an anchor: a polyhedron, a cone on its apex, a round
  // body on a face (the parts fixed in the body); rolling parts move over the body and are not.
  bool anchored(std::size_t contact) const;
  // The part of a round body that touches (into its status, after calc_kinematics): a face if
  // its whole rim is within `within` of the plane, else the side if both ends' lowest rim points
  // are, else the end that is (at least the lower). A point counts if it lands with the touchdown
  // (lands_with: within `within` and not moving away, or at the plane and not bouncing off);
  // with `resting`, only if not moving away.
  void find_touching_round_part(std::size_t contact, double within, bool resting);
  void impact(std::size_t contact, double t, VecX& y);
  // After a settled landing at `speed`: throws std::runtime_error where such landings have
  // come kCascadeLandings in a row, each going apart at once (no consistent mode).
  void check_landing_cascade(std::size_t contact, double t, double speed);
  void note_contact(double t, std::size_t contact, std::string what);
  void write_contact_powers(VecX& rates, Eigen::Index offset) const;
  double kinetic_energy() const;
  Vec3 angular_momentum_about_origin() const;  // from states_

  std::shared_ptr<const ArticulatedModel> shared_articulated_;
  const ArticulatedModel& m_;  // *shared_articulated_: constant, shared by every run
  // This run's scratch, written by const evaluations (derivative, event functions, rows): a
  // formulation serves one thread at a time.
  std::unique_ptr<ArticulatedData> data_;
  ArticulatedData& d_;  // *data_
  HybridState& s_;      // hybrid_: the modes and records (Formulation::hybrid_state)
};

}  // namespace tumble
