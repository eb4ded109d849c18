#pragma once
// Fixed-size linear algebra types used throughout tumble. Every 3-vector carries its frame in
// its name (see docs/notation.md): r_G (COM, world), omega_B (angular velocity, body axes), ...
#include <Eigen/Dense>

namespace tumble {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // (w, x, y, z); unit quaternions stand for rotations
// A spatial vector (Featherstone): a motion (omega; v) or a force (moment; force), angular first.
using Vec6 = Eigen::Matrix<double, 6, 1>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

}  // namespace tumble
