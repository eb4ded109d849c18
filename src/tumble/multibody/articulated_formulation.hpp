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
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tumble/contact/contact_feature.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/contact/round_contact.hpp"

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

  // Contact events, three per contact: touchdown (a contact point, or a polyhedron's vertex not
  // yet touching, reaches the plane), support (the normal force reaches 0: lift-off; or a
  // polyhedron's centre of pressure reaches its feature's side: it tips), and stick-slip
  // (sliding: the slip stops; rolling or sticking: the friction it needs reaches the cone's
  // edge).
  std::span<const EventSpec> events() const override { return event_specs_; }
  void event_functions(double t, const VecX& y, VecX& g) const override;
  EventAction on_event(std::size_t event_index, double t, VecX& y) override;
  // Also puts each touching contact back on the plane and its velocity on the mode's
  // constraints (no normal velocity; rolling: no slip).
  void project(double t, VecX& y) const override;
  bool refresh_event_functions(double t, const VecX& y) override;
  // While a contact is apart: no step so long that a point of its surface could dip through the
  // plane and back unseen (contact/landing_bound.hpp).
  double step_limit(double t, const VecX& y) const override;
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
  enum class ContactMode { Apart = 0, Sliding = 1, Rolling = 2 };  // rolling: or sticking
  struct ContactStatus {
    ContactMode mode = ContactMode::Apart;
    ContactFeature feature;  // a polyhedron's touching vertex, edge or face (empty: apart)
    RoundPart round_part = RoundPart::None;  // a round body's touching part
    // Where a round body's rim points were at the last step (body axes, unit): refreshed after
    // each step near flat (rim_direction_kept_up), it fixes them where a face is flat
    // (round_contact.hpp's rim_direction).
    Vec3 rim_direction_B = Vec3::UnitX();
    // Slip direction (slip_W's) while the slip speed is ~0.
    Vec3 slide_direction_W = Vec3::UnitX();
    // A slip that starts from rolling turns from slide_direction_W at this rate (1/s, normal to
    // it) from slide_start_t on, until it is above slip_zero (articulated_slip_onset.cpp).
    Vec3 slide_turn_W = Vec3::Zero();
    double slide_start_t = 0.0;
    bool slip_grown = false;      // the slip has been above slip_zero at the end of a step
    bool slip_left_near = false;  // ... and above kSlipStoppedNear slip_zero
    double slip_last_step = 0.0;  // m/s, sliding: the slip at the end of the last step
    // A grown slip left below slip_zero by the last step stops at slip_stop_by (s).
    bool slip_stop_armed = false;
    double slip_stop_by = 0.0;
    // Settled landings in a row that nothing held, from cascade_first_t; the last landing's t.
    int cascade_landings = 0;
    double cascade_first_t = 0.0, cascade_last_t = 0.0;
    double slip_zero = 0.0;        // m/s: slower slip counts as none
    double slip_floor = 0.0;       // m/s: a grown slip is followed down to this
    double settle_speed = 0.0;     // m/s: slower touchdowns settle instead of bouncing
    double touching_height = 0.0;  // m: nearer the plane counts as touching
    double landing_height = 0.0;   // m: vertices this near the plane land with a touchdown
    double time_scale = 0.0;       // s: the contact's size over its speed scale
    // Where a polyhedron (a cone on its apex, a round body on a face) sticks (mode rolling): the
    // points its rows hold (a vertex or face centroid, or an edge's ends) and the body's
    // orientation, so that projection keeps it exactly there rather than letting round-off walk it
    // away.
    std::array<Vec3, 2> anchor_W = {Vec3::Zero(), Vec3::Zero()};
    Mat3 anchor_R_WB = Mat3::Identity();
  };
  // What calc_contact_points and solve_with_contacts found for each contact at the current y.
  // The reference point O is where slip is taken and friction acts: a curved surface's contact
  // point, a polyhedron's feature centroid (apart: its lowest vertex).
  struct ContactNow {
    // Touchdown: the curved surface's contact point, or the lowest polyhedron vertex not in the
    // feature, its height and its velocity along the normal.
    SupportPoint support;
    double support_normal_speed = 0.0;
    Vec3 n_B = Vec3::UnitZ();
    Vec3 reference_B = Vec3::Zero();       // O from the COM, body axes
    Vec3 reference_rate_B = Vec3::Zero();  // O's motion over the body (curved surfaces)
    // The points whose normal motion the contact constrains (the vertex, the edge's ends, three
    // of the face's corners; curved: O).
    std::array<Vec3, 3> normal_points_B = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    // Their motion over the body (curved surfaces).
    std::array<Vec3, 3> normal_point_rates_B = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    int normal_point_count = 0;
    double spin_radius = 0.0;        // torsional friction radius of the feature (0 at a point)
    Vec3 velocity_W = Vec3::Zero();  // of the body's material point at O
    // Slip: O's tangential velocity, and the spin about the normal times the feature's spin
    // radius as the component along the normal (a polyhedron's face or edge; 0 otherwise).
    Vec3 slip_W = Vec3::Zero();
    Vec6 wrench_B = Vec6::Zero();          // the contact's (moment about the COM; force), body axes
    Vec3 force_W = Vec3::Zero();           // its force
    double normal_force = 0.0;             // force_W's component along the plane's normal
    Vec3 friction_W = Vec3::Zero();        // force_W's tangential part
    Vec3 moment_about_O_B = Vec3::Zero();  // its moment about O, body axes
  };
  // One unknown of the contact forces and the constraint row that goes with it: the row is
  // linear_W . (velocity or acceleration of the material point at point_B) + angular_W . omega.
  struct ContactUnknown {
    std::size_t contact = 0;
    Vec3 point_B = Vec3::Zero();
    Vec3 point_rate_B = Vec3::Zero();  // the point's motion over the body
    Vec3 linear_W = Vec3::Zero();
    Vec3 angular_W = Vec3::Zero();
    bool normal = false;  // a row of the normal motion (restitution applies at impacts)
    int anchor = -1;      // a sticking polyhedron's row: the ContactStatus::anchor_W it holds
    Vec6 wrench_B = Vec6::Zero();  // per unit of the unknown: (moment about the COM; force)
  };
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

  // Contacts: their forces and projection (articulated_contacts.cpp), their modes, events and
  // impacts (articulated_contact_modes.cpp).
  void set_up_contacts();
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
  // The ledger entry of a contact (after the locks).
  Eigen::Index contact_entry(std::size_t contact) const;
  void write_contact_powers(VecX& rates, Eigen::Index offset) const;
  double kinetic_energy() const;
  Vec3 angular_momentum_about_origin() const;  // from states_

  std::vector<TreeJoint> tree_;
  std::vector<std::size_t> slot_of_body_;  // tree index of each body's inbound joint
  std::vector<bool> has_children_;         // per tree joint: another body hangs from its child
  std::vector<std::size_t> tree_root_;     // per tree joint: its ancestor hung from ground
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
  mutable std::vector<ContactUnknown> unknowns_;  // sized to 6 per contact
  mutable MatX contact_matrix_;
  mutable VecX contact_rhs_, contact_x_;
  mutable std::vector<int> touching_;  // scratch of find_touching_vertices, reserved
  VecX impact_y_;                      // scratch of impact()
  VecX onset_y_, onset_dydt_;          // scratch of turn_starting_slip()
  // The time of the state being evaluated: a starting slip's direction turns with it.
  mutable double time_now_ = 0.0;
  // The time of the last event handled, once on_event is done (watched_height).
  double last_event_t_ = -std::numeric_limits<double>::infinity();
  // Scratch of derivative() and the other const queries, sized once here: no allocation per call.
  mutable std::vector<Workspace> work_;
  mutable std::vector<BodyState> states_;
  mutable VecX rates_;
};

}  // namespace tumble
