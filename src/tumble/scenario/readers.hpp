#pragma once
// The readers of the scenario's sections, one file each; scenario.cpp calls them in order.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/yaml_reader.hpp"

namespace tumble::scenario_reading {

// `shape:` with its dimension keys, `mass:` or `density:`, `inertia:` and `orientation:` of a body
// or a part (shape_reader.cpp).
struct ShapeRead {
  Shape shape;
  Field shape_field;  // where `shape:` is written
  double mass = 0.0;  // kg
  Field mass_field;   // `mass:` or `density:`, for errors about the mass properties
};

// The dimension keys of a shape, as the contract names them.
const std::vector<std::string>& dimension_keys(ShapeKind kind);
// Every dimension key of every shape.
const std::vector<std::string>& all_dimension_keys();
// "rod, ring, disk, ..." (without point unless with_point).
std::string shape_list(bool with_point);

// Reads `shape:` and its dimensions, then `mass:` or `density:`. `directory` is where a mesh's
// relative path starts. A point is accepted only when point_allowed (in parts). The mapping may
// hold other_keys besides the shape's own dimensions; any other key is an error that names
// `what` ("a body") and lists the keys.
ShapeRead read_shape_and_mass(const Reader& reader, const MapReader& map,
                              const std::filesystem::path& directory, bool point_allowed,
                              const std::vector<std::string>& other_keys, const std::string& what);
// `inertia:`: three principal moments [Ixx, Iyy, Izz] on the frame's axes or a full symmetric
// 3x3, checked by validate_inertia.
Mat3 read_inertia(const Reader& reader, const Field& field);
// `orientation:`: identity | {axis, angle} | {matrix} | {quaternion: [w, x, y, z]}.
Mat3 read_orientation(const Reader& reader, const Field& field);

// `bodies:` (body_reader.cpp).
std::vector<BodySpec> read_bodies(const Reader& reader, const Field& field,
                                  const std::filesystem::path& directory);
// `joints:` (joints_reader.cpp), after the bodies.
std::vector<JointSpec> read_joints(const Reader& reader, const Field& field,
                                   const std::vector<BodySpec>& bodies);
// `forces:` (forces_reader.cpp), after the bodies and joints: fills scenario.loads, impulses,
// springs and torsional_springs.
void read_forces(const Reader& reader, const Field& field, Scenario& scenario);
// The joint that holds each held body in that tree, by the body's name: its inboard joint, the
// one that moves it relative to its parent (an index into scenario.joints).
std::unordered_map<std::string, std::size_t> inboard_joints(
    const Scenario& scenario, const std::vector<ContactSpec>& contacts);
// Each slender body (BodySpec::slender) is held (held_bodies), and every joint that holds it lets
// it turn only about axes it has inertia about: a hinge whose axis gives it n.I_G.n + m |n x d|^2
// > 0 (d from the joint point to its COM), a slider, or a weld; not a ball joint. Throws
// ScenarioError at its shape, saying why (body_reader.cpp).
void check_slender_bodies(const Scenario& scenario);
// A system whose joints close a loop: refuses, at the item, what loops do not take part in yet
// (contacts).
void check_loop_system(const Scenario& scenario);
// Which bodies joints connect to each other (ground included): a union-find over their names,
// whose walks to a group's root are halved as they go, so that a chain of n bodies is grouped
// in about n log n steps, not n^2 (body_groups.cpp).
class BodyGroups {
 public:
  // The name that stands for the body's group (the body itself when no joint connects it).
  std::string root(const std::string& body);
  // Joins the two bodies' groups; false when they were one group already (a joint between them
  // would close a loop).
  bool join(const std::string& a, const std::string& b);

 private:
  std::unordered_map<std::string, std::string> parent_;
};

// `contacts:` (contacts_reader.cpp), after the bodies and joints.
std::vector<ContactSpec> read_contacts(const Reader& reader, const Field& field,
                                       const Scenario& scenario);
// A body's name as a joint or force names it; "ground" only where ground_allowed. Fails with the
// names there are (and the likely one, for a typo).
std::string read_body_or_ground(const Reader& reader, const Field& field,
                                const std::vector<BodySpec>& bodies, bool ground_allowed);
// `events:` (events_reader.cpp): their names, conditions, directions and whether each stops the
// run. The conditions' names are checked against the columns when the model is built.
std::vector<UserEventSpec> read_events(const Reader& reader, const Field& field,
                                       const Scenario& scenario);
// `simulate:` and `output:` (simulate_reader.cpp).
// has_forces: any load, force element or joint; has_system: joints, springs or impulses;
// format_version: the scenario's `tumble:` (which sets the default integrator).
SimulateSpec read_simulate(const Reader& reader, const Field& field, bool has_forces,
                           bool has_system, int format_version);
OutputSpec read_output(const Reader& reader, const std::optional<Field>& field,
                       const std::string& file_stem);

// Checks a body's, joint's, force's, contact's or event's name: it prefixes CSV columns
// ("prism.x") and shows in messages, so no control character, '.', ',', quotes or spaces
// (column_heads.cpp).
void check_name(const Reader& reader, const Field& where, const std::string& name,
                std::string_view what);

// The names that head CSV columns: bodies, joints, forces and contacts share one set of them, so
// that `floor.W` means one thing in the CSV, in expressions and in plots. Each reader claims its
// names as it reads them, against what was read before (column_heads.cpp); a hash map, so that
// reading stays linear in the number of names.
class ColumnHeads {
 public:
  ColumnHeads() = default;
  // Everything `scenario` has read so far.
  explicit ColumnHeads(const Scenario& scenario);
  // Records `name` (already checked) as naming a `what` at `where`.
  void note(const std::string& name, std::string_view what, const SourceLocation& where);
  // Records `name` as naming a `what` at `at`; fails at `where`'s key when it already names
  // something, saying what and where.
  void claim(const Reader& reader, const Field& where, const std::string& name,
             std::string_view what, const SourceLocation& at);

 private:
  struct Head {
    std::string what;
    SourceLocation where;
  };
  std::unordered_map<std::string, Head> heads_;
};

}  // namespace tumble::scenario_reading
