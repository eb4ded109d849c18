#pragma once
// Contact with planes as a subsystem of its own (docs/design.md, "Contact"): a hybrid system in
// which each contact is apart, sliding or rolling (sticking), and only located events change
// that. In a mode the contact's force is whatever keeps its constraints' accelerations zero
// (sliding: the normal one, with Coulomb's friction mu N against the slip; rolling: all three),
// found from the bodies' response to unit wrenches; project() puts positions and velocities back
// on the constraints after every step; touchdowns are impacts (restitution and friction on the
// impulse).
//
// It talks to the dynamics only through ContactDynamics (contact_dynamics.hpp): poses, twists,
// accelerations, responses to wrenches and impulses. The formulation that owns it forwards its
// contact events, projection, step limit and start checks here, and calls solve_forces() in its
// right-hand side between gathering the loads and the last solve.
//
// Model, data, state: the contacts (PlaneContact) are the model's, constant and shared; the
// scratch is this run's ContactData; the modes and records are the run's ContactState (in its
// HybridState), which a checkpoint copies. The code is in contact_forces.cpp (forces, impulses,
// projection), contact_modes.cpp (events, modes, impacts), slip_onset.cpp and
// contact_step_limit.cpp; what differs from one kind of surface to another is its contact pair's
// (contact_pair.hpp), which this class asks and never tests the kind of.
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "tumble/body/rigid_body.hpp"
#include "tumble/contact/contact_data.hpp"
#include "tumble/contact/contact_dynamics.hpp"
#include "tumble/contact/contact_hold.hpp"
#include "tumble/contact/contact_pair.hpp"
#include "tumble/contact/contact_status.hpp"
#include "tumble/contact/plane_contact.hpp"

namespace tumble {

class ContactSystem {
 public:
  // The contacts of `bodies` (gravity_W m/s^2), moved by `dynamics`, whose state y has
  // `dimension` numbers; its modes and records are kept in `state`. Both references must
  // outlive this object. `fixed_step`: the step a fixed-step method takes whatever step_limit
  // says (Model::fixed_step; 0 for an adaptive method).
  ContactSystem(std::span<const PlaneContact> contacts, std::span<const RigidBody> bodies,
                const Vec3& gravity_W, const ContactDynamics& dynamics, ContactState& state,
                Eigen::Index dimension, double fixed_step = 0.0);

  bool empty() const { return contacts_.empty(); }
  std::size_t size() const { return contacts_.size(); }
  // What was found for contact c at the state last evaluated, and its status.
  const ContactNow& now(std::size_t c) const { return d_.now[c]; }
  // As now(c) for a row of output, after the dynamics' calc_motion and a solve: a pair the broad
  // phase left far has its points found too (its slip; it is apart, with no force).
  const ContactNow& row_now(std::size_t c) const {
    if (d_.screen.far(c)) {
      calc_pair_point(c);
      ContactNow& now = d_.now[c];
      now.force_W.setZero();
      now.normal_force = 0.0;
      now.friction_W.setZero();
    }
    return d_.now[c];
  }
  const ContactStatus& status(std::size_t c) const { return s_.contacts[c]; }

  // The time of the state about to be evaluated (a starting slip's direction turns with it).
  void set_time(double t) const { d_.time_now = t; }

  // After the dynamics' calc_motion (with velocities) and its loads: the contacts' forces in
  // their current modes, and the dynamics' accelerations under the loads and those forces
  // (solve_under_loads_and).
  void solve_forces() const;
  // Each contact's power (its wrench on its body's twist, W) into rates at offset + its work
  // entry, after solve_forces.
  void write_powers(VecX& rates, Eigen::Index offset) const;

  // Why the run cannot start from y0: a contact inside its plane, or touching it and moving into
  // it.
  struct StartProblem {
    std::size_t contact = 0;
    std::string why;
  };
  std::optional<StartProblem> start_problem(const VecX& y0) const;
  // The modes at the start: touching contacts roll, stick or slide; the others are apart.
  void begin(double t0, const VecX& y);
  // After a breakpoint (a load switched; with `speeds_jumped`, an impulse, a lock or a motor's
  // start): the touching contacts' modes again. A jump that sends every touching point away from
  // the plane (a kick, a brake that throws a body up) leaves the contact apart.
  void reclassify(double t, VecX& y, bool speeds_jumped);

  // Three event functions per contact, into g from 3 c on: touchdown (a contact point, or a
  // polyhedron's vertex not yet touching, reaches the plane), support (the normal force reaches
  // 0: lift-off; or a polyhedron's centre of pressure reaches its feature's side: it tips), and
  // stick-slip (sliding: the slip stops; rolling or sticking: the friction it needs reaches the
  // cone's edge).
  void event_functions(double t, const VecX& y, VecX& g) const;
  bool refresh_event_functions(double t, const VecX& y);
  void on_event(std::size_t event_index, double t, VecX& y);
  // The dynamics' own projection (normalise), then each touching contact back on its plane and
  // its velocity on its mode's constraints (no normal velocity; rolling: no slip).
  void project(double t, VecX& y) const;
  // While a contact is apart: no step so long that a point of its surface could dip through the
  // plane and back unseen (landing_bound.hpp).
  double step_limit(double t, const VecX& y) const;
  // Whether the last step_limit changed which contacts are watched (the broad phase): their
  // event functions' values at the step's start are then to be evaluated again.
  bool events_rescreened() const { return d_.rescreened; }
  // How each contact holds its body at (t, y) in its current mode, into `holds` (one per
  // contact): what the Jacobian of the run's equations takes of it.
  void calc_holds(double t, const VecX& y, std::span<ContactHold> holds) const;

 private:
  // Every body's motion at y under its loads and the contacts' forces in their current modes,
  // and dy/dt at (t, y): from the dynamics' motion, loads and rates around this system's own
  // solve_forces (the dynamics are asked, never re-entered).
  void calc_accelerations(const VecX& y) const;
  void calc_rates(double t, const VecX& y, VecX& dydt) const;
  // The contacts a step watches, in order: all but a group's pairs the broad phase found far
  // (broad_phase.hpp), whose points no evaluation finds and whose event functions hold at 1.
  std::span<const std::size_t> watched() const { return d_.screen.watched(); }
  bool any_touching() const;
  // The broad phase, from the bodies' motion after a solve: each group's pair near enough to
  // touch before the step's end is watched (its points found), the others are far. Returns the
  // horizon: no step may be longer, for the far pairs to stay apart through it. +infinity where
  // no pair is screened, or no body of a group moves.
  double screen_pairs() const;
  // Contact c as its pair (contact_pair.hpp) sees it.
  PairView view(std::size_t contact) const;
  // Contact points, reference points and their velocities, after the dynamics' calc_motion.
  void calc_contact_points() const;
  // Which constraints a contact's unknowns hold:
  //  - Motion: its mode's (sliding: the normal motion, with Coulomb's friction riding on each
  //    normal force; rolling or sticking: all its motion the feature allows);
  //  - Projection: as Motion, with no friction on sliding's normal impulses;
  //  - Position: the normal motion, with normal forces; a sticking polyhedron: its Projection
  //    rows (held at its anchor).
  enum class ContactRows { Motion, Projection, Position };
  // The unknowns of every touching contact (into d_.unknowns); returns their count.
  Eigen::Index gather_contact_unknowns(ContactRows rows) const;
  // Appends contact c's unknowns in `mode` at d_.unknowns[count...], with sliding friction along
  // `slide_W` (Motion); returns the new count.
  Eigen::Index append_contact_unknowns(std::size_t c, ContactMode mode, ContactRows rows,
                                       const Vec3& slide_W, Eigen::Index count) const;
  // What the rows measure: their zero is the contacts' own (the largest touching height, slip
  // zero, or slip zero over the time scale): dependent rows whose right-hand sides differ by
  // less agree.
  enum class RowQuantity { Acceleration, Velocity, Position };
  // Solves A x = b for the leading count rows, in place (b becomes x), A the rows' response to
  // the unknowns; throws InconsistentConstraints if the rows contradict each other. The rows
  // split into islands that no body ties together (contact_islands.cpp), each solved alone.
  void solve_contact_rows(Eigen::Index count, VecX& x, RowQuantity rows) const;
  // The islands of the leading count rows, into d_.island_rows and d_.island_ends; returns how
  // many.
  Eigen::Index find_islands(Eigen::Index count) const;
  // The zero of what the rows measure: the largest of the watched contacts'.
  double rows_zero(RowQuantity rows) const;
  // The matrix A of one island's rows (`rows`: the unknowns', in order) into d_.matrix's leading
  // block, from the responses to unit wrenches.
  void calc_contact_matrix(std::span<const Eigen::Index> rows) const;
  // Adds to A's column j those rows' response to a unit wrench on one body.
  void add_contact_response(Eigen::Index j, std::size_t body, const Vec6& wrench_B,
                            std::span<const Eigen::Index> rows) const;
  // Solves that A x = b in place (x: the island's right-hand side, in the rows' order).
  void solve_contact_system(std::span<const Eigen::Index> rows, VecX& x, double zero) const;
  // Each contact's resultant (d_.now's wrench, force, normal force, friction, moment about O)
  // from the unknowns' values x.
  void set_contact_resultants(Eigen::Index count, const VecX& x) const;
  // A row's value on the current velocities (after calc_motion).
  double row_velocity(const ContactUnknown& row) const;
  // The dynamics' response (speed jumps) to the impulses x_j along the unknowns j.
  void respond_to_contact_impulses(Eigen::Index count, const VecX& impulses) const;
  // Jump the speeds by the impulses x_j along the unknowns j.
  void apply_contact_impulses(Eigen::Index count, const VecX& impulses, VecX& y) const;
  // project()'s position step when a polyhedron, a round body or a held body touches (after
  // calc_contact_points).
  void project_feature_positions(VecX& y) const;
  // The current slip direction of a sliding contact (at d_.time_now); `follows_slip` (where
  // given): whether it is the slip's own direction rather than one the slip is held to.
  Vec3 slide_direction(std::size_t contact, bool* follows_slip = nullptr) const;
  // Whether contact c's part is two points (an edge, a round body's side) on a free body, which
  // slides with friction at each end against that end's own slip, and may pivot about one end
  // (after calc_contact_points).
  bool two_point(std::size_t contact) const;
  // The direction of end `end`'s slip that its friction opposes: its own slip where that is
  // followed (as slide_direction's), else the way it was pushed, else the part's slide
  // direction slide_W (slip space: tangential, and rho times the spin about the normal) as the
  // rigid motion it is, at this end.
  // `follows_slip` (where given): whether it is the end's own slip.
  Vec3 end_slide_direction(std::size_t contact, int end, const Vec3& slide_W,
                           bool* follows_slip = nullptr) const;
  // The part's slide direction slide_W (slip space) as the rigid motion it is, at the part's
  // point p_B (body axes, from the COM; in the plane, unit).
  Vec3 rigid_slide_at(std::size_t contact, const Vec3& p_B, const Vec3& slide_W) const;
  // calc_holds' hold of a part held on more than one point (ContactHold::Kind::Points).
  void calc_points_hold(std::size_t contact, ContactHold& hold) const;
  // Sliding on a two-point part: the end that stops first among those whose slip is watched, and
  // the value its stop watches (its slip along its direction); a pivot's pinned end, and the
  // margin of its friction inside the cone. -1 where none.
  int stopping_end(std::size_t contact, double& value) const;
  double pinned_friction_margin(std::size_t contact) const;
  // Sliding on a two-point part at y, slips of which only one end's is at rest: pinned there if
  // its friction fits in the cone, else sliding from rest the way it is pushed (after a solve).
  void pin_or_push_end(std::size_t contact, int end, const VecX& y);
  bool end_stop_watched(std::size_t contact) const;
  // The stick-slip event of a two-point part whose ends are watched: the pinned end lets go, or
  // an end's slip stops (after which the contact is classified again).
  void on_end_slip_event(std::size_t contact, double t, VecX& y);
  // The slip direction of a contact that must slide with no slip yet: the way it is pushed,
  // against the friction sticking needs (from d_.now).
  Vec3 pushed_direction(std::size_t contact) const;
  // Contact c, with no slip, starts to slide along pushed_direction (after a rolling solve at y;
  // slip_onset.cpp). True if the slip can grow that way: its acceleration along it is positive
  // or, where the needed friction has just reached the cone's edge (no acceleration), its jerk
  // is, with the direction turning as it needs. False where friction would drive the slip back
  // (Painleve's case: friction high enough that it presses the contact on).
  bool start_sliding(std::size_t contact, double t, const VecX& y);
  // start_sliding on a two-point part: it pivots about an end whose friction still fits, the
  // other end sliding against its share of the friction, or both ends slide so.
  bool start_sliding_on_two_points(std::size_t contact, double t, const VecX& y);
  // How far the friction sticking needs is inside the cone (scaled by `edge`; >= 0: it sticks),
  // after a rolling or sticking solve: mu N less its friction demand's size, or on a two-point
  // part, the least room left at either end's cone with the friction along the part shared
  // between them.
  double stick_margin(std::size_t contact, double edge) const;
  // A two-point part's friction after a rolling or sticking solve, per end: mu N there (scaled by
  // `edge`), the friction across the part, and the room left in its cone for friction along the
  // part; and the part's direction (world, in the plane) and the friction along it, all told.
  struct EndFrictions {
    Vec3 along_direction_W = Vec3::Zero();
    std::array<double, 2> cap{}, room{};
    std::array<Vec3, 2> across_W = {Vec3::Zero(), Vec3::Zero()};
    double along = 0.0;
  };
  EndFrictions end_frictions(std::size_t contact, double edge) const;
  // A two-point part's direction along the plane, from its first end to its second (world).
  Vec3 part_direction_W(std::size_t contact) const;
  // Where the rolling contact c cannot start sliding: it lifts off if, with no force, its points
  // (a round body's other end too, if it is at the plane) leave the plane; if not, no mode is
  // consistent, and it slides along the pushed direction.
  void lift_off_or_hold_slide(std::size_t contact, double t, const VecX& y);
  // The support event of a touching contact: it lifts off, or tips onto a smaller part.
  void on_support_event(std::size_t contact, double t, VecX& y);
  // After the event of contact `handled` changed its modes: every other touching contact that
  // the change left pulling on its body (N below zero by more than the tolerance it is solved
  // to) has had its support event at this instant (its function jumped across zero rather than
  // crossing it within a step, where the event would have been located), and takes it.
  void release_pulling_contacts(std::size_t handled, double t, VecX& y);
  // Whether touching contact c pulls on its body after a solve: its push (a held polyhedron's
  // least point's) below zero by more than the tolerance it is solved to (kSlipZero of the
  // body's weight). Its support event has then happened at this instant.
  bool pulling(std::size_t c) const;
  // At the cone's edge: the rate the starting slip's direction turns at (into slide_turn_W);
  // false if no turn lets the slip grow.
  bool turn_starting_slip(std::size_t contact, double t, const VecX& y);
  // The slip's rate of change (slip_W's) after a solve, and at y sliding along slide_W.
  Vec3 slip_acceleration(std::size_t contact) const;
  Vec3 slip_acceleration_at(std::size_t contact, const VecX& y, const Vec3& slide_W);
  // The acceleration (world axes, gravity's included) of the point p_B that moves over the body
  // at rate_B, after a solve: d/dt of its velocity R (v_G + omega x p).
  Vec3 moving_point_acceleration_W(const BodyMotion& w, const Vec3& p_B, const Vec3& rate_B) const;
  // N times the CoP's least distance inside a polyhedron's feature (N itself for a point), and
  // the side of the feature where it is least; from d_.now.
  double support_margin_of(std::size_t contact, int& side) const;
  // The friction the contact carries as a slip-space vector: the tangential force, and the
  // moment about the normal over the spin radius along the normal. Its length is what the
  // cone bounds by mu N; from d_.now.
  Vec3 friction_demand(std::size_t contact) const;
  // The mode a touching contact takes now (slip stopped, touchdown settled, start): rolling or
  // sticking if the friction that needs fits in the cone, else sliding the way the body is
  // pushed; a polyhedron tips onto a smaller feature while its CoP would leave the feature.
  // Notes the mode if it changed (or, with always_note, in any case).
  void classify_contact(std::size_t contact, double t, VecX& y, bool always_note = false);
  // Tries contact c on its current feature or part: sticking if the friction fits, else
  // sliding; true if the forces are consistent (N > 0, the CoP in the part, no touching vertex
  // (d_.touching) or other point the candidate leaves out (left_out) going into the plane).
  bool settle_on_feature(std::size_t contact, double t, VecX& y,
                         std::span<const SurfacePoint> left_out = {});
  // classify_contact's candidates for contact c, its pair's (settle_on_feature on the part, then
  // on each part it may tip onto); true if one holds.
  bool settle_on_candidates(std::size_t contact, double t, VecX& y);
  void set_apart(std::size_t contact);
  // The acceleration along the plane's normal of the point p_B moving over the body at rate_B
  // (0: the material point), after a solve.
  double normal_acceleration(std::size_t contact, const Vec3& p_B,
                             const Vec3& rate_B = Vec3::Zero()) const;
  // The height above the plane of the body's point p_B, and its material velocity along the
  // plane's normal (after calc_motion).
  double height_above_plane(std::size_t contact, const Vec3& p_B) const;
  double normal_speed(std::size_t contact, const Vec3& p_B) const;
  // What the touchdown event sees of a point at this height moving at this normal speed.
  double watched_height(std::size_t contact, double height, double normal_speed) const;
  // Apart: the touchdown event's value, the least watched height over the points that may land
  // first, and the point that sets it (after calc_contact_points).
  double landing_watch(std::size_t contact, Vec3& landing_B) const;
  // A polyhedron that starts sticking: its anchor where it is now (after calc_contact_points).
  void anchor_contact(std::size_t contact);
  // Whether contact c, sticking, is held at an anchor (its pair's answer; a held polyhedron's
  // points are held one by one instead).
  bool anchored(std::size_t contact) const;
  void impact(std::size_t contact, double t, VecX& y);
  // After an impact at `landed`: each other touching contact whose every point the impulse sends
  // away from its plane lifts off at that instant (a rimless wheel's foot that it rolled on, as
  // the next foot lands), before the landing contact's mode is chosen with the others' rows.
  void release_contacts_sent_away(std::size_t landed, double t, VecX& y);
  // After a settled landing at `speed`: throws std::runtime_error where such landings have
  // come kCascadeEvents in a row, each going apart at once (no consistent mode).
  void check_landing_cascade(std::size_t contact, double t, double speed);
  // After a slip stop: throws std::runtime_error where such stops have come kCascadeEvents in a
  // row, each sliding on at once.
  void check_slip_stop_cascade(std::size_t contact, double t);
  // Counts an event in the contact's cascade (`undone`: the same instant undid it); whether the
  // cascade has come kCascadeEvents in a row.
  bool cascade_goes_on(std::size_t contact, double t, bool undone);
  void note_contact(double t, std::size_t contact, std::string what,
                    std::optional<ContactImpactNumbers> impact = std::nullopt);
  // The numbers of the events from `first` on, in the state y they leave: the kinetic energy
  // and the contact point's velocity relative to the plane (ContactEventRecord).
  void note_event_numbers(std::size_t first, const VecX& y);
  // The work J done on contact c's body at an instant (an impact, a projection), into y's ledger.
  void add_work(std::size_t contact, double work, VecX& y) const;
  // After a jump of the speeds: whether a touching contact still touches (some of its points at
  // the plane and not leaving it); its feature or part becomes those points.
  bool still_touches_after_jump(std::size_t contact, const VecX& y);
  // Each touching contact's mode again (reclassify's), noting `lifts_off` for one that a jump of
  // the speeds sent away from its plane.
  void classify_touching(double t, VecX& y, bool speeds_jumped, const char* lifts_off);
  // A held polyhedron's point p_B (least_point_B) leaves its feature: the feature becomes the
  // rest of its vertices, or none (apart).
  void drop_point(std::size_t contact, const Vec3& p_B);

  // Contacts between two bodies' spheres (sphere_pairs.cpp): apart, or meeting in impacts.
  // The pair's gap and its rate, the reference point O (the midpoint of the spheres' nearest
  // points) on either body, their velocity there relative to each other and its tangential part
  // (into d_.now[contact]), after the dynamics' calc_motion.
  void calc_pair_point(std::size_t contact) const;
  // The contact's normal (world, unit): a plane's, or a pair's from the other body's sphere to
  // the body's (after calc_contact_points).
  const Vec3& normal_of(std::size_t contact) const;
  std::optional<StartProblem> pair_start_problem(std::size_t contact) const;
  // While apart: the first time the gap could be the landing height deep (landing_bound.hpp),
  // after a solve.
  double pair_time_to_depth(std::size_t contact) const;
  // The acceleration of the body's sphere centre less the other body's point at its core's
  // nearest point (sliding over it), world, gravity's included; after a solve.
  Vec3 core_relative_acceleration_W(std::size_t contact) const;
  // The second derivative of the pair's gap (m/s^2), after a solve: < 0, the bodies are pushed
  // into each other (its part from the normal turning is d_.now's pair_turning).
  double pair_gap_acceleration(std::size_t contact) const;
  // A touching pair's unknowns (append_contact_unknowns' for two bodies): the normal row, and
  // rolling or sticking, the two tangential ones.
  Eigen::Index append_pair_unknowns(std::size_t contact, ContactMode mode, ContactRows rows,
                                    const Vec3& slide_W, Eigen::Index count) const;
  // A touching pair's slip acceleration (slip_acceleration's), after a solve.
  Vec3 pair_slip_acceleration(std::size_t contact) const;
  // Each pair apart at y that touches with no normal speed, and that with no force between them
  // would be pushed into each other, is classified (it rolls, sticks or slides); the others stay
  // apart. After the impacts (and the planes' contacts classified in the speeds they left), and
  // at the start.
  void enter_pressed_pairs(double t, VecX& y);
  // The impacts at a pair's touchdown: one pair at a time, the touching pair that approaches
  // fastest first, until no touching pair approaches (docs/scenario.md, "Bodies that touch").
  // Returns the speed at which the pair that touched down approached.
  double pair_impacts(std::size_t contact, double t, VecX& y);
  // One pair's impulse: Newton's restitution on the normal motion (none where the pair comes
  // together slower than a settling touchdown), Coulomb on the tangential impulse; noted as an
  // event.
  void pair_impulse(std::size_t contact, double t, VecX& y);
  // Marks in d_.held_in_impact each touching plane contact, not marked yet, of a body that moves
  // with either of the pair's, that the pair's impulse applied at d_.impact_y drives into its
  // plane; `settling`, each touching pair too (but the pair itself) that comes together, no
  // faster than a settling touchdown. Returns whether it marked any.
  bool hold_driven_in(std::size_t contact, bool settling);
  // Marks in d_.tied_group the motion groups of the pair's bodies and the held contacts'; then
  // whether contact k has a body in a marked group.
  void mark_tied_groups(std::size_t contact);
  bool moved_by_impulse(std::size_t k) const;
  // The pair's impulse (world, on its body) with Newton's e on its normal motion, Coulomb's
  // friction if `friction`, and the marked planes and pairs held (their normal motion stopped);
  // from y into d_.impact_y.
  Vec3 pair_impulse_holding(std::size_t contact, double e, bool friction, bool settling,
                            const VecX& y);

  std::span<const PlaneContact> contacts_;  // the model's: constant, shared by every run
  std::vector<const ContactPair*> pairs_;   // per contact: its pair, from contact_pair()'s table
  std::span<const RigidBody> bodies_;
  double fixed_step_ = 0.0;  // s, a fixed-step method's (the broad phase screens that long)
  Vec3 gravity_W_;
  const ContactDynamics& dynamics_;
  // Per contact: a polyhedron on a body a joint holds. Its rows are its feature's points, each
  // held still, and the solve keeps those the joint leaves free (contact_forces.cpp).
  std::vector<bool> held_polyhedron_;
  // Whether any contact is on a body a joint holds, whose rows may be ones no force moves; and
  // the floor of a real response (1/kg): below this fraction of the heaviest touching body's
  // 1/m, a row's response is round-off (solve_contact_system).
  bool any_held_ = false;
  double least_response_ = 0.0;
  // This run's scratch, written by const evaluations: a run serves one thread at a time.
  std::unique_ptr<ContactData> data_;
  ContactData& d_;  // *data_
  ContactState& s_;
};

}  // namespace tumble
