#include "tumble/inertia/mass_properties.hpp"
#include "tumble/inertia/message_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace tumble {
namespace {

using inertia_detail::format_number;

constexpr std::array<char, 3> kAxisNames = {'x', 'y', 'z'};

std::string entry_name(int row, int col) {
  return std::string("I_") + kAxisNames[row] + kAxisNames[col];
}

// Parallel axis term M (|c|^2 I - c c^T): the inertia about O of the mass M concentrated at c,
// where c is the offset of the COM from O.
Mat3 point_mass_inertia(double mass, const Vec3& c) {
  return mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
}

}  // namespace

// I_F = R_FP I_P R_FP^T (the chapter's rotated-body rule), and the COM moves as a point:
//   r_G_F = p_FoPo_F + R_FP r_G_P.
MassProperties express_in_parent(const MassProperties& part_P, const Mat3& R_FP,
                                 const Vec3& p_FoPo_F) {
  MassProperties part_F;
  part_F.mass = part_P.mass;
  part_F.com = p_FoPo_F + R_FP * part_P.com;
  part_F.inertia_about_com = R_FP * part_P.inertia_about_com * R_FP.transpose();
  return part_F;
}

// M = sum m_i,  r_G = sum m_i r_Gi / M,
// I_G = sum [ I_Gi + m_i (|c_i|^2 I - c_i c_i^T) ],  c_i = r_Gi - r_G.
MassProperties combine(std::span<const MassProperties> parts) {
  if (parts.empty()) throw InertiaError("cannot combine an empty list of parts: give at least one");
  MassProperties total;
  Vec3 first_moment = Vec3::Zero();
  for (const MassProperties& part : parts) {
    if (!(part.mass >= 0.0) || !std::isfinite(part.mass)) {
      throw InertiaError("part mass must be >= 0, got " + format_number(part.mass));
    }
    total.mass += part.mass;
    first_moment += part.mass * part.com;
  }
  if (!(total.mass > 0.0)) {
    throw InertiaError("total mass of the parts must be > 0, got " + format_number(total.mass));
  }
  total.com = first_moment / total.mass;
  // Offsets are taken from the combined COM itself (not from the frame origin) so that the sum
  // does not cancel large terms when the parts sit far from the origin.
  for (const MassProperties& part : parts) {
    total.inertia_about_com +=
        part.inertia_about_com + point_mass_inertia(part.mass, part.com - total.com);
  }
  return total;
}

// I_O = I_G + M (|c|^2 I - c c^T),  c = r_G - r_O.
Mat3 inertia_about_point(const MassProperties& mp, const Vec3& r_O) {
  return mp.inertia_about_com + point_mass_inertia(mp.mass, mp.com - r_O);
}

PrincipalAxes principal_axes(const Mat3& inertia) {
  // Eigen's self-adjoint solver returns the eigenvalues in ascending order and orthonormal
  // eigenvectors; it reads the lower triangle, so the symmetric part is passed explicitly.
  const Mat3 symmetric = 0.5 * (inertia + inertia.transpose());
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(symmetric);
  PrincipalAxes result;
  result.moments = solver.eigenvalues();
  result.axes = solver.eigenvectors();
  // An eigenvector's sign is arbitrary: flip the last axis to make the frame right-handed.
  if (result.axes.determinant() < 0.0) result.axes.col(2) = -result.axes.col(2);
  return result;
}

// A rigid body's inertia about its COM is symmetric, positive definite, and its principal moments
// satisfy I_1 + I_2 >= I_3 (I_1 + I_2 - I_3 = 2 int rho d_3^2 dV >= 0). Thin planar shapes (a
// plate, a disk, a ring) sit exactly on the boundary I_3 = I_1 + I_2, so the comparisons allow
// relative_tolerance times the largest |moment|. A rod (one zero moment) and a point (zero tensor)
// are rejected: callers that hold such a part check the whole body instead.
void validate_inertia(const Mat3& inertia, double relative_tolerance) {
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      if (!std::isfinite(inertia(row, col))) {
        throw InertiaError("inertia has a non-finite entry: " + entry_name(row, col) + " = " +
                           format_number(inertia(row, col)));
      }
    }
  }

  const double largest_entry = inertia.cwiseAbs().maxCoeff();
  for (int row = 0; row < 3; ++row) {
    for (int col = row + 1; col < 3; ++col) {
      const double difference = std::abs(inertia(row, col) - inertia(col, row));
      if (difference > relative_tolerance * largest_entry) {
        throw InertiaError("inertia is not symmetric: " + entry_name(row, col) + " = " +
                           format_number(inertia(row, col)) + " but " + entry_name(col, row) +
                           " = " + format_number(inertia(col, row)) + " (differ by " +
                           format_number(difference) + ")");
      }
    }
  }

  const Vec3 moments = principal_axes(inertia).moments;  // ascending
  const double scale = moments.cwiseAbs().maxCoeff();
  if (!(moments(0) > relative_tolerance * scale)) {
    throw InertiaError("inertia is not positive definite: smallest principal moment is " +
                       format_number(moments(0)) +
                       " (every moment must be > 0; a rod or a point alone has no valid inertia)");
  }
  // With the moments ascending only the largest can exceed the sum of the other two.
  const double excess = moments(2) - (moments(0) + moments(1));
  if (excess > relative_tolerance * scale) {
    throw InertiaError("principal moments " + format_number(moments(0)) + ", " +
                       format_number(moments(1)) + ", " + format_number(moments(2)) +
                       " break the triangle inequality: " + format_number(moments(2)) + " > " +
                       format_number(moments(0)) + " + " + format_number(moments(1)) + " by " +
                       format_number(excess));
  }
}

}  // namespace tumble
