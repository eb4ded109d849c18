#pragma once
// A run's scratch in joint coordinates (what MuJoCo calls mjData, Pinocchio Data): what the
// articulated-body passes and the contact solves compute at a state, sized once for an
// ArticulatedModel and reused at every evaluation, so nothing is allocated in a step. It holds
// nothing a run needs to go on (that is y and the HybridState): any evaluation overwrites it.
// One per thread.
#include <array>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/constraint_solve.hpp"
#include "tumble/multibody/articulated_model.hpp"
#include "tumble/multibody/spatial.hpp"

namespace tumble {

struct ArticulatedData {
  explicit ArticulatedData(const ArticulatedModel& model);

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

  std::vector<Workspace> work;           // per tree joint
  std::vector<BodyState> states;         // per body, from the last calc_kinematics
  VecX rates;                            // the ledger's rates (calc_row_extras)
  std::vector<ContactNow> contact_now;   // per contact
  std::vector<ContactUnknown> unknowns;  // sized to 6 per contact
  MatX contact_matrix;
  VecX contact_rhs, contact_x;
  ConstraintSolveScratch solve_scratch;  // for rows that joints or other contacts make redundant
  std::vector<int> touching;             // find_touching_vertices's, reserved for the most vertices
  VecX impact_y;                         // impact()'s
  VecX onset_y, onset_dydt;              // turn_starting_slip()'s
  // The time of the state being evaluated: a starting slip's direction turns with it.
  double time_now = 0.0;
};

}  // namespace tumble
