#pragma once
// The contacts a linearisation holds (`tumble modes`): those touching their planes at t0, each at
// one point. With friction the body's point there does not move (rolling or sticking: three
// constraints, as in a run's rolling mode); without, it only stays on the plane (one). The plane's
// force is whatever holds them, so the equations stay smooth and can be differentiated. A body
// resting on an edge, a face or a line of its side is refused: a small tilt moves its force to
// one edge or the other, and the motion has no linearisation there.
//
// Where the point is from the body's COM (world axes) as the body turns, and how fast that
// offset changes (a rim's lowest point runs round the rim as the body rolls):
//  - a sphere or shell: its lowest point, p = -r n, which does not change;
//  - a disk, ring, cylinder or cone: the lowest point of one end's rim, p = R c + rho u, with c
//    the rim's centre and u the unit vector in the rim's plane most opposed to n;
//  - a polyhedron's vertex or a cone's apex: a point of the body, p = R p_B.
// A rim's lowest point moves along the rim's tangent, which is parallel to the plane: the offset's
// rate has the normal component of the body's point there, so the height's rate is the normal
// velocity of that point, and the rolling constraint's rate is its acceleration's.
#include <string>
#include <vector>

#include "tumble/dynamics/model.hpp"

namespace tumble {

struct ModalContact {
  std::size_t contact = 0;  // in the model's contacts
  enum class Point { Lowest, Rim, Material } point = Point::Lowest;
  Vec3 p_B = Vec3::Zero();  // Rim: the rim's centre; Material: the point (body axes, from the COM)
  double radius = 0.0;      // Lowest: the sphere's; Rim: the rim's
  bool rolls = true;        // with friction: the point's whole motion held; without: the normal
  int rows() const { return rolls ? 3 : 1; }
};

// The contacts touching their planes with the bodies at r_G_W, R_WB (per body). Throws NotSteady
// for one resting on an edge, a face or a line.
std::vector<ModalContact> touching_contacts(const Model& model, const std::vector<Vec3>& r_G_W,
                                            const std::vector<Mat3>& R_WB);

// The offset p_GP_W from the body's COM G to the contact point P and its rate (world axes), the
// body turned by R_WB and turning at omega_W.
template <typename S>
void contact_offset(const ModalContact& contact, const Vec3& n_W,
                    const Eigen::Matrix<S, 3, 3>& R_WB, const Eigen::Matrix<S, 3, 1>& omega_W,
                    Eigen::Matrix<S, 3, 1>& p_GP_W, Eigen::Matrix<S, 3, 1>& p_GP_rate_W) {
  using V3 = Eigen::Matrix<S, 3, 1>;
  using std::sqrt;
  switch (contact.point) {
    case ModalContact::Point::Lowest:
      p_GP_W = -contact.radius * n_W.cast<S>();
      p_GP_rate_W = V3::Zero();
      return;
    case ModalContact::Point::Material:
      p_GP_W = R_WB * contact.p_B.cast<S>();
      p_GP_rate_W = omega_W.cross(p_GP_W);
      return;
    case ModalContact::Point::Rim: {
      const V3 n = n_W.cast<S>();
      const V3 axis = R_WB.col(2);
      const V3 axis_rate = omega_W.cross(axis);
      const V3 w = n - n.dot(axis) * axis;  // n's part in the rim's plane
      const V3 w_rate = -n.dot(axis_rate) * axis - n.dot(axis) * axis_rate;
      const S length = sqrt(w.squaredNorm());
      const V3 w_unit = w / length;
      const V3 centre_W = R_WB * contact.p_B.cast<S>();
      p_GP_W = centre_W - contact.radius * w_unit;
      p_GP_rate_W = omega_W.cross(centre_W) -
                    contact.radius * (w_rate - w_unit.dot(w_rate) * w_unit) / length;
      return;
    }
  }
}

}  // namespace tumble
