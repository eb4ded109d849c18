#pragma once
// Mass, centre of mass and inertia tensor of a body or part, all expressed in ONE frame F:
// the chapter's section 6.7.2. Composites follow from the parallel axis theorem
//   I_O = I_G + M (|c|^2 I - c c^T),  c = r_G - r_O,
// and rotated parts from I_F = R_FP I_P R_FP^T.
#include <span>
#include <stdexcept>
#include <string>

#include "tumble/math/types.hpp"

namespace tumble {

struct MassProperties {
  double mass = 0.0;                      // kg, > 0 for a body
  Vec3 com = Vec3::Zero();                // centre of mass G in frame F, m
  Mat3 inertia_about_com = Mat3::Zero();  // I_G in the axes of F, kg m^2
};

// A physically impossible inertia or mass: the message says what is wrong and by how much.
class InertiaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Properties of a part given in its own frame P, expressed in the parent frame F, where the part's
// frame has orientation R_FP and origin p_FoPo_F (in F).
MassProperties express_in_parent(const MassProperties& part_P, const Mat3& R_FP,
                                 const Vec3& p_FoPo_F);

// Sum of parts already expressed in one frame: total mass, mass-weighted COM, and the inertia
// about the total COM by the parallel axis theorem.
MassProperties combine(std::span<const MassProperties> parts);

// Parallel axis theorem: the inertia about point O (in the same frame as the COM).
Mat3 inertia_about_point(const MassProperties& mp, const Vec3& r_O);

// Principal moments in ascending order and the principal axes as the columns of a proper
// rotation (det +1): I = axes * diag(moments) * axes^T.
struct PrincipalAxes {
  Vec3 moments = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
};
PrincipalAxes principal_axes(const Mat3& inertia);

// Throws InertiaError unless the tensor is symmetric, positive definite and satisfies the triangle
// inequality of principal moments (each <= the sum of the other two), within relative_tolerance
// of the largest moment. The message names the failed condition and the amount, e.g.
// "principal moments 1, 1, 3 break the triangle inequality: 3 > 1 + 1 by 1".
// Laminae (plate, disk, ring) lie exactly on the triangle-inequality boundary and pass. A slender
// rod (zero moment about its axis) or a point (zero tensor) is rejected: such parts are valid
// inside a composite, so check the combined body's inertia, not the part's.
void validate_inertia(const Mat3& inertia, double relative_tolerance = 1e-9);

}  // namespace tumble
