#pragma once
// A run's scratch for its contacts (part of what MuJoCo calls mjData): the points, forces and
// constraint rows found at the state last evaluated, and the small dense solve's matrix, sized
// once for the model's contacts so that nothing is allocated in a step. It holds nothing a run
// needs to go on (that is y and the ContactState): any evaluation overwrites it. One per run.
#include <array>
#include <limits>
#include <span>
#include <vector>

#include "tumble/contact/broad_phase.hpp"
#include "tumble/contact/contact_dynamics.hpp"
#include "tumble/contact/contact_status.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/constraint_solve.hpp"

namespace tumble {

// What calc_contact_points and solve_forces found for a contact at the current y. The reference
// point O is where slip is taken and friction acts: a curved surface's contact point, a
// polyhedron's feature centroid (apart: its lowest vertex).
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
  // A two-point part: each end's slip, the tangential velocity of the body's point there.
  std::array<Vec3, 2> end_slip_W = {Vec3::Zero(), Vec3::Zero()};
  Vec6 wrench_B = Vec6::Zero();          // the contact's (moment about the COM; force), body axes
  Vec6 other_wrench_B = Vec6::Zero();    // between two bodies: the other's, in its axes
  Vec3 force_W = Vec3::Zero();           // its force
  double normal_force = 0.0;             // force_W's component along the plane's normal
  Vec3 friction_W = Vec3::Zero();        // force_W's tangential part
  Vec3 moment_about_O_B = Vec3::Zero();  // its moment about O, body axes
  // A two-point part: the normal force and the friction (world) at each end.
  std::array<double, 2> end_normal_force = {0.0, 0.0};
  std::array<Vec3, 2> end_friction_W = {Vec3::Zero(), Vec3::Zero()};
  // A polyhedron on a body a joint holds: the least normal force (or impulse) among the feature's
  // points whose rows the solve kept (the joint takes the rest of the load), and that point.
  double least_point_force = 0.0;
  Vec3 least_point_B = Vec3::Zero();
  // A contact between two bodies: the normal (unit, world) from the other body's sphere towards
  // this body's, and the reference point O (the midpoint of the spheres' nearest points) from
  // the other body's COM, its axes, and how fast O moves over that body (as over this one,
  // reference_rate_B). velocity_W is this body's point there less the other's.
  Vec3 pair_normal_W = Vec3::UnitZ();
  Vec3 other_reference_B = Vec3::Zero();
  Vec3 other_reference_rate_B = Vec3::Zero();
  // The body's core's point (its axes, from its COM: the sphere's centre; a capsule's axis's point
  // nearest the other capsule's) and how fast it slides over the body.
  Vec3 core_B = Vec3::Zero();
  Vec3 core_rate_B = Vec3::Zero();
  // The other body's core's point nearest the sphere's centre (its axes, from its COM: a
  // sphere's centre, a box's nearest point) and how fast it slides over that body; and what n's
  // turning adds to the gap's second derivative, n' . (the centre's velocity less that point's).
  Vec3 other_core_B = Vec3::Zero();
  Vec3 other_core_rate_B = Vec3::Zero();
  double pair_turning = 0.0;
};

// One unknown of the contact forces and the constraint row that goes with it: the row is
// linear_W . (velocity or acceleration of the material point at point_B) + angular_W . omega.
// Between two bodies, the row is the body's point's less the other body's point's at
// other_point_B (its axes), and the unknown pushes the other body by other_wrench_B.
struct ContactUnknown {
  std::size_t contact = 0;
  Vec3 point_B = Vec3::Zero();
  Vec3 point_rate_B = Vec3::Zero();  // the point's motion over the body
  Vec3 linear_W = Vec3::Zero();
  Vec3 angular_W = Vec3::Zero();
  bool normal = false;  // a row of the normal motion (restitution applies at impacts)
  int anchor = -1;      // a sticking polyhedron's row: the ContactStatus::anchor_W it holds
  int end = -1;         // a two-point part's row: the end (0, 1) whose force it carries
  Vec6 wrench_B = Vec6::Zero();  // per unit of the unknown: (moment about the COM; force)
  Vec3 other_point_B = Vec3::Zero();
  Vec3 other_point_rate_B = Vec3::Zero();
  Vec6 other_wrench_B = Vec6::Zero();
  // What the row's direction turning adds to its rate (m/s^2): between two spheres the normal
  // turns as the line of their centres does.
  double turning_acceleration = 0.0;
};

// The most rows one contact has: a face's six; a held polyhedron's three at each of three points.
inline constexpr std::size_t kMostRowsPerContact = 9;

struct ContactData {
  // Sized for these contacts, bodies and a state of `dimension` numbers.
  ContactData(std::span<const PlaneContact> contacts, std::size_t bodies, Eigen::Index dimension);

  // Room for this many rows, and what goes with them; more allocates (reserve_rows).
  void reserve_rows(std::size_t rows);
  std::size_t row_room() const { return unknowns.size(); }

  std::vector<ContactNow> now;           // per contact
  std::vector<ContactUnknown> unknowns;  // sized to the most rows that may touch at once
  MatX matrix;                           // the rows' response to the unknowns
  VecX rhs, x;
  ConstraintSolveScratch solve_scratch;  // for rows that joints or other contacts make redundant
  VecX row_scales;                       // per row, for those: normal rows carry the load first
  MatX saved_matrix;                     // the rows before a solve, and its right-hand side, for
  VecX saved_rhs;                        // the second solve of redundant rows
  // The solve's islands (contact_islands.cpp): the rows island by island, where each island
  // ends in that list, and one island's right-hand side; per motion group, its union-find
  // parent and its island.
  std::vector<Eigen::Index> island_rows, island_ends;
  VecX island_x;
  std::vector<std::size_t> group_parent, group_island;
  // Per motion group, a pair's settling impulse's: whether it moves in that impulse.
  std::vector<char> tied_group;
  std::vector<BodyWrench> wrenches;  // two per row and per contact: forces or impulses
  std::vector<int> touching;         // find_touching_vertices's, reserved for the most vertices
  VecX impact_y;                     // impact()'s
  // Per contact, a pair's impulse (sphere_pairs.cpp): whether a touching plane is held in it.
  std::vector<char> held_in_impact;
  // Per contact, classify_touching's: whether a jump left it slipping while it rolled.
  std::vector<char> slipping_after_jump;
  ContactStatus landing;     // impact()'s: the part it lands on, reserved for the most vertices
  VecX onset_y, onset_dydt;  // turn_starting_slip()'s
  // The broad phase's: which contacts a step watches, and its bodies' boxes (broad_phase.hpp).
  PairScreen screen;
  std::vector<AlignedBox> boxes;
  bool rescreened = false;  // the last screening changed the watched contacts
  // The time of the state being evaluated: a starting slip's direction turns with it.
  double time_now = 0.0;
};

}  // namespace tumble
