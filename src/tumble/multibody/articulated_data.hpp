#pragma once
// A run's scratch in joint coordinates (what MuJoCo calls mjData, Pinocchio Data): what the
// articulated-body passes compute at a state (the contacts' scratch is their own ContactData),
// sized once for an ArticulatedModel and reused at every evaluation, so nothing is allocated in a
// step. It holds nothing a run needs to go on (that is y and the HybridState): any evaluation
// overwrites it. One per thread.
#include <string>
#include <vector>

#include "tumble/body/rigid_body.hpp"
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
    // Where the joint's motion subspace turns with its coordinates (JointKind::moving_subspace):
    // its entry in `moving`; -1 where the tree's S holds.
    int moving = -1;
    Vec6 applied = Vec6::Zero();  // the loads in `external` before contact forces join them
    // The articulated inertia this joint hands its parent (I^A - U D^-1 U^T, or I^A where it is
    // prescribed), and whether IA, U, D_inv and it hold for the configuration last evaluated
    // with `known` as it is (calc_kinematics clears it; a full pass sets it).
    Mat6 IA_passed = Mat6::Zero();
    bool inertia_ready = false;
  };
  // A motion subspace that turns with the joint's coordinates, at the state last evaluated
  // (calc_kinematics sets it, with (dS/dt) u, which joins the joint's velocity terms). Kept apart
  // from the workspaces, which stay small for the joints whose S is constant.
  struct MovingSubspace {
    MotionSubspace S;
    Vec6 S_rate_u = Vec6::Zero();
  };
  // The joint's motion subspace at the state last evaluated.
  const MotionSubspace& S_of(const TreeJoint& joint, const Workspace& w) const {
    return w.moving < 0 ? joint.S : moving[static_cast<std::size_t>(w.moving)].S;
  }
  std::vector<Workspace> work;  // per tree joint
  // Per tree joint that roots a tree: whether this solve takes the tree's articulated inertias
  // from the last (at the same configuration, the same joints prescribed).
  std::vector<char> reuse_inertia;
  std::vector<MovingSubspace> moving;
  std::vector<BodyState> states;  // per body, from the last calc_kinematics
  VecX rates;                     // the ledger's rates (calc_row_extras)
  // Why the loops could not be closed at the start (assemble), for start_problem; empty if
  // they were.
  std::string assembly_problem;
};

}  // namespace tumble
