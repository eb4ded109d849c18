#pragma once
// A scenario as read from its YAML file (docs/scenario.md; the contract is scenario-v1): plain
// structs whose fields map one to one onto the keys, with every default here, in one place.
// Numbers are already evaluated (expressions, parameters, --set) and checked.
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tumble/dynamics/joint_type.hpp"
#include "tumble/inertia/mass_properties.hpp"
#include "tumble/inertia/shapes.hpp"
#include "tumble/integrators/tolerances.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// Where a key or value sits in its file; line and column count from 1.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// Invalid input. what() is "FILE:LINE:COL: KEY: why", the format the command line prints.
class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(SourceLocation where, std::string key, std::string why);
  const SourceLocation& where() const { return where_; }
  const std::string& key() const { return key_; }
  const std::string& why() const { return why_; }

 private:
  SourceLocation where_;
  std::string key_;
  std::string why_;
};

// One part of a composite body, in the body's frame.
struct PartSpec {
  std::string name;  // "parts[2]" when not named
  Shape shape;
  MassProperties mass_properties;  // resolved, in the body's frame
  Vec3 position_B = Vec3::Zero();  // origin of the part's frame in the body's frame, m
  Mat3 R_BP = Mat3::Identity();    // orientation: part axes -> body axes
};

struct BodySpec {
  std::string name;
  Shape shape;  // kind Point when the body is a composite of parts
  std::vector<PartSpec> parts;
  // Resolved mass properties in the body frame: for a single shape, com = 0 (the frame sits at
  // the COM); for a composite, the COM of the parts in the body's frame.
  MassProperties mass_properties;
  bool inertia_overridden = false;  // `inertia:` was given
  // Slender: its inertia about the COM is singular (a rod has none about its own axis, a point
  // none at all, parts on one line none about it). Valid only where its joints allow it no turn
  // about those axes (a hinge across a rod, or away from a point; a slider; a weld), which
  // check_slender_bodies checks once the joints are read; `slender_where` and `slender_key` say
  // where its shape (or parts) is written.
  bool slender = false;
  SourceLocation slender_where;
  std::string slender_key;
  Vec3 position_W = Vec3::Zero();          // origin of the body frame at t = 0, world, m
  Mat3 R_WB = Mat3::Identity();            // orientation at t = 0
  Vec3 velocity_W = Vec3::Zero();          // COM velocity at t = 0, world, m/s
  Vec3 angular_velocity_W = Vec3::Zero();  // at t = 0, world, rad/s
  SourceLocation where;
  // Where `velocity:` and `angular_velocity:` are written (line 0: not given). A body held by
  // joints takes the velocities its joints allow; given ones must agree with them.
  SourceLocation velocity_where, angular_velocity_where;
};

// A constant force or a pure torque on one body, optionally switched on a from/to schedule.
struct LoadSpec {
  enum class Kind { Force, Torque } kind = Kind::Force;
  std::string name;  // `name:`, or "force1", "torque2" by type and list position
  std::string body;
  Vec3 value = Vec3::Zero();  // N or N m; world frame unless body_frame
  bool body_frame = false;    // `frame: body`: value turns with the body
  Vec3 at_W = Vec3::Zero();   // force: point of application, world at t = 0, m
  bool has_point = false;     // force: `at:` given (else at the COM)
  double from = -std::numeric_limits<double>::infinity();  // s
  double to = std::numeric_limits<double>::infinity();     // s
  SourceLocation where;
};

// A body named in a joint or a force element: "ground" (the fixed world) or one of the bodies.
inline constexpr const char* kGroundName = "ground";

// `motor:` of a hinge: a prescribed relative speed or a torque, optionally on a schedule.
struct MotorSpec {
  // Speed: rad/s about a hinge, m/s along a slider; Effort: `torque:` (N m) about a hinge's or a
  // cylindrical joint's axis, `force:` (N) along a slider's or a cylindrical joint's.
  enum class Kind { None, Speed, Effort } kind = Kind::None;
  double value = 0.0;
  int freedom = 0;  // a cylindrical joint's: 0 its turn (torque:), 1 its slide (force:)
  double from = -std::numeric_limits<double>::infinity();  // s
  double to = std::numeric_limits<double>::infinity();     // s
  SourceLocation where;
};

struct JointSpec {
  JointType type = JointType::Ball;
  std::string name;                  // the key under `joints:`
  std::string body_a = kGroundName;  // `bodies: [a, b]`, or `body: b` (then a is ground)
  std::string body_b;
  Vec3 at_W = Vec3::Zero();  // the joint point, world at t = 0, m (distance: the rod's end on b)
  Vec3 rod_end_a_W = Vec3::Zero();  // distance: the rod's end on a, world at t = 0, m
  // hinge, prismatic, cylindrical: unit axis, world at t = 0; universal: the second axis (fixed
  // in b), with first_axis_W the first (fixed in a), at right angles
  Vec3 axis_W = Vec3::UnitZ();
  Vec3 first_axis_W = Vec3::UnitX();
  MotorSpec motor;  // hinge, prismatic, cylindrical
  // hinge, prismatic, cylindrical, universal: `lock: {at: t}`
  double lock_at = std::numeric_limits<double>::infinity();
  // Its bodies are already joined through the joints listed before it: it closes a loop, and the
  // run holds it as a constraint on the tree the others form.
  bool closes_loop = false;
  SourceLocation where;
};

// `type: spring`: a linear spring-damper between two body points.
struct SpringSpec {
  std::string name;
  std::string body_a, body_b;
  Vec3 at_a_W = Vec3::Zero(), at_b_W = Vec3::Zero();  // world points at t = 0, m
  double stiffness = 0.0;                             // N/m, >= 0
  double damping = 0.0;                               // N s/m, >= 0
  std::optional<double> rest_length;                  // m; default: the length at t = 0
  SourceLocation where;
};

// `type: torsional_spring` between two bodies (or a body and ground).
struct TorsionalSpringSpec {
  std::string name;
  std::string body_a, body_b;
  double stiffness = 0.0;  // N m/rad, >= 0
  double damping = 0.0;    // N m s/rad, >= 0
  // `rest:` an orientation of b's frame relative to a's, or (across a hinge) an angle; default:
  // the relative orientation at t = 0.
  std::optional<Mat3> rest_orientation;
  std::optional<double> rest_angle;  // rad
  SourceLocation where;
};

// `type: impulse`: a jump of momentum at a body point at one instant.
struct ImpulseSpec {
  std::string name;
  std::string body;
  Vec3 value = Vec3::Zero();  // N s
  bool body_frame = false;
  Vec3 at_W = Vec3::Zero();
  bool has_point = false;
  double time = 0.0;  // s, > 0
  SourceLocation where;
};

// `contacts:` entry of type plane: a body touching a fixed plane.
struct ContactSpec {
  std::string name;  // `name:`, or "contact1", "contact2" by list position
  std::string body;
  Vec3 plane_point_W = Vec3::Zero();
  Vec3 plane_normal_W = Vec3::UnitZ();  // unit (the given normal, normalised)
  double friction = 0.0;                // Coulomb mu, >= 0
  double restitution = 0.0;             // Newton's e, 0 ... 1
  // A composite body's part that touches (an index into its parts; `part:`), -1 for a body of
  // one shape.
  int part = -1;
  // `type: bodies`: the second body (empty: the contact is with the plane) and its part that
  // touches (-1: the body is that sphere). The plane's point and normal are then unused.
  std::string other_body;
  int other_part = -1;
  // A pair of a group (`bodies:` naming more than two, or `all`): the broad phase watches it only
  // while the two come near (docs/design.md, "Broad phase").
  bool screened = false;
  // `bodies: all`'s pairs: the contact's name (hit, of hit_ball1_ball2), whose one work-ledger
  // entry (hit.P, hit.W) they share; they have no columns of their own. Empty for any other.
  std::string pool;
  SourceLocation where;
};

struct SimulateSpec {
  double duration = 0.0;  // s, > 0, required
  // ode45's (format 2's default is auto); the others: simulate_reader.cpp, kIntegrators
  std::string integrator = "dopri5";
  std::string formulation = "body";  // body (production) | textbook (the chapter's [R; omega])
  double rtol = tolerances::kDefaultRtol;  // integrators/tolerances.hpp: the valid range
  double atol = tolerances::kDefaultAtol;
  bool rtol_given = false;
  bool atol_given = false;      // when only rtol is given, atol = rtol * 1e-3 (see docs)
  double step = 0.0;            // s: fixed step (rk4, rkmk4); > 0 when required
  double max_step = 0.0;        // s: 0 = a tenth of the duration, as ode45
  double initial_step = 0.0;    // s: 0 = chosen automatically
  double output_every = 0.0;    // s: 0 = one row per accepted step
  long max_steps = 10'000'000;  // guard against a run that would never end
  // Output rows a run may write (a guard against filling the disk: 1e6 rows of one body are
  // about 0.5 GB of CSV); raise it on purpose.
  long max_rows = 1'000'000;
  SourceLocation where;
};

// One of the animation page's own plots (output.plots): trajectory columns drawn on one panel.
struct PlotSpec {
  std::vector<std::string> columns;   // as the CSV's header names them
  std::vector<std::string> keys;      // each one's key, "output.plots[1][0]"
  std::vector<SourceLocation> where;  // and its place
};

struct OutputSpec {
  std::string trajectory;  // relative path; default "<scenario file stem>.csv"
  std::string animation;   // relative path of the animation page; empty: none (unless --animate)
  // relative path of the events CSV (output/events_csv.hpp); default "<file stem>_events.csv",
  // written when the run has contact events or jumps, or always when given
  std::string events;
  bool events_given = false;
  SourceLocation trajectory_where;  // where output.trajectory is given (line 0: the default)
  SourceLocation animation_where;   // ... output.animation (line 0: not given)
  SourceLocation events_where;      // ... output.events (line 0: the default)
  // The animation page's plots of the scenario's choosing, after its own (omega, energy, |L|);
  // not given: each body's speed, and the joints' angles where there are any.
  std::vector<PlotSpec> plots;
  bool plots_given = false;
};

// An `events:` entry: a moment the run locates, as it does contacts' mode changes (to the
// integrator's precision), and reports, and may end at.
struct UserEventSpec {
  enum class Direction { Up, Down, Both };
  std::string name;
  // An expression of the trajectory's columns and the parameters whose zero is the event
  // ("box.x - d"), or a condition "A > B" (or <, >=, <=) whose becoming true is.
  std::string when;
  Direction direction = Direction::Both;  // which crossings of the expression's zero count
  bool stop = false;                      // the run ends at the event's first occurrence
  SourceLocation where;                   // the entry
  SourceLocation when_where;              // its `when:` value
};

struct Scenario {
  std::string file;  // as given on the command line
  std::string name;
  // `tumble: 1` or `tumble: 2`. They read alike but for one default: format 2's integrator is
  // `auto` (stiffness found and taken by itself), format 1's `dopri5`, as its contract says.
  int format_version = 1;
  // `planar: true`: everything moves in the world's x-y plane (z out of it). The reader has
  // turned its 2D statement (points [x, y], angles and rates about z) into this 3D one; the
  // trajectory gets each body's angle and rate.
  bool planar = false;
  std::map<std::string, double> parameters;            // after --set
  Vec3 gravity_W = Vec3(0.0, 0.0, -9.81);              // m/s^2
  std::vector<BodySpec> bodies;                        // file order
  std::vector<JointSpec> joints;                       // file order
  std::vector<LoadSpec> loads;                         // `forces:` entries of type force and torque
  std::vector<SpringSpec> springs;                     // ... of type spring
  std::vector<TorsionalSpringSpec> torsional_springs;  // ... of type torsional_spring
  std::vector<ImpulseSpec> impulses;                   // ... of type impulse
  std::vector<ContactSpec> contacts;                   // `contacts:`
  std::vector<UserEventSpec> events;                   // `events:`
  SimulateSpec simulate;
  OutputSpec output;
  // What the reader accepted but that is likely not what was meant (an angle of more than a turn
  // written as a bare number), "FILE:LINE:COL: KEY: why"; `tumble run` prints them.
  std::vector<std::string> warnings;
};

// A --set NAME=VALUE override; VALUE is an expression.
struct ParameterOverride {
  std::string name;
  std::string value;
};

// Reads, evaluates and checks a scenario. Throws ScenarioError (with file, line, column and key)
// for anything the contract rejects, including a missing or unreadable file (line 0).
// With `needs_simulate` false (`tumble inertia`: the bodies are all it reads), `simulate:` may be
// left out, and the defaults stand.
// Slender bodies (BodySpec::slender) need joints that make their motion well-posed; without
// `needs_simulate` (the bodies alone, for their mass properties) that is not checked.
Scenario load_scenario(const std::string& path, const std::vector<ParameterOverride>& overrides,
                       bool needs_simulate = true);
// The same from scenario text in memory; `path` names it in messages and places files it refers
// to (meshes) relative to its directory.
Scenario load_scenario_text(const std::string& text, const std::string& path,
                            const std::vector<ParameterOverride>& overrides,
                            bool needs_simulate = true);

}  // namespace tumble
