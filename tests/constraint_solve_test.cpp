// The small dense solve of constraint forces (math/constraint_solve.hpp): independent rows give
// the one solution; redundant but consistent rows give the least-norm one, A^+ b, which the tests
// compute independently by Eigen's complete orthogonal decomposition; contradicting rows throw,
// unless they differ by less than the caller's zero.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "tumble/math/constraint_solve.hpp"

namespace tumble {
namespace {

// Solves the leading n x n block of A x = b in a larger preallocated matrix, as the contact
// system does.
VecX solve_block(const MatX& A, const VecX& b, double zero = 0.0, const VecX& scales = VecX()) {
  const Eigen::Index n = A.rows(), room = n + 3;
  MatX work = MatX::Constant(room, room, 7.0);  // entries outside the block must not matter
  VecX x = VecX::Constant(room, 7.0);
  work.topLeftCorner(n, n) = A;
  x.head(n) = b;
  ConstraintSolveScratch scratch(room);
  VecX scales_room = VecX::Constant(room, 7.0);
  scales_room.head(scales.size()) = scales;
  solve_constraints_in_place(work, x, n, scratch, zero, scales.size() > 0 ? &scales_room : nullptr);
  return x.head(n);
}

TEST(ConstraintSolve, IndependentRowsGiveTheSolution) {
  MatX A(3, 3);
  A << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  const VecX x_true = (VecX(3) << 1, -2, 0.5).finished();
  const VecX x = solve_block(A, A * x_true);
  EXPECT_LT((x - x_true).cwiseAbs().maxCoeff(), 1e-14);
}

// Four wheels' normal rows on a cart's three freedoms off the plane: A = G W G^T with G 4 x 3 is
// of rank 3. Of the forces that give the motion, the least-norm one.
TEST(ConstraintSolve, RedundantRowsGiveTheLeastNormForces) {
  MatX G(4, 3);  // each wheel's normal row on (heave, roll, pitch)
  G << 1, 0.2, 0.25, 1, -0.2, 0.25, 1, 0.2, -0.25, 1, -0.2, -0.25;
  const Eigen::Vector3d W(1.0 / 6.0, 1.0 / 0.05, 1.0 / 0.08);
  const MatX A = G * W.asDiagonal() * G.transpose();
  const VecX b = A * (VecX(4) << 3, 1, 2, 5).finished();  // consistent: in A's range
  const VecX x = solve_block(A, b);
  const VecX least = A.completeOrthogonalDecomposition().solve(b);
  EXPECT_LT((A * x - b).cwiseAbs().maxCoeff(), 1e-12 * b.cwiseAbs().maxCoeff());
  EXPECT_LT((x - least).cwiseAbs().maxCoeff(), 1e-12 * least.cwiseAbs().maxCoeff());
  // The weight alone (heave): shared evenly by the four.
  const VecX heave = A * VecX::Constant(4, 2.5);
  const VecX shares = solve_block(A, heave);
  for (Eigen::Index i = 0; i < 4; ++i) EXPECT_NEAR(shares(i), 2.5, 1e-12);
}

// With scales, of the forces that give the motion, the least in sum (x_i / s_i)^2: here the
// least-norm one of (A S) x' = b, times S, by Eigen's decomposition. A contact on a bob that a
// joint holds: its normal row and a friction row are one freedom; the normal row scaled 1e3
// carries the load, the friction ~1e-6 of it (x_f = b / (1 + s^2) for rows of equal response).
TEST(ConstraintSolve, ScalesChooseWhichRedundantRowsCarryTheLoad) {
  MatX G(4, 3);
  G << 1, 0.2, 0.25, 1, -0.2, 0.25, 1, 0.2, -0.25, 1, -0.2, -0.25;
  const Eigen::Vector3d W(1.0 / 6.0, 1.0 / 0.05, 1.0 / 0.08);
  const MatX A = G * W.asDiagonal() * G.transpose();
  const VecX b = A * (VecX(4) << 3, 1, 2, 5).finished();
  const VecX scales = (VecX(4) << 1.0, 1e3, 2.0, 1.0).finished();
  const VecX x = solve_block(A, b, 0.0, scales);
  const MatX AS = A * scales.asDiagonal();
  const VecX expected = scales.asDiagonal() * AS.completeOrthogonalDecomposition().solve(b);
  EXPECT_LT((A * x - b).cwiseAbs().maxCoeff(), 1e-12 * b.cwiseAbs().maxCoeff());
  EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());

  MatX pair(2, 2);
  pair << 1, 1, 1, 1;  // a normal and a friction row that move the one freedom alike
  const VecX load = solve_block(pair, VecX::Constant(2, 2.0), 0.0, VecX::Constant(2, 1.0));
  EXPECT_NEAR(load(0), 1.0, 1e-15);  // equal scales: shared evenly, as without
  const double s = 1e3;
  const VecX held = solve_block(pair, VecX::Constant(2, 2.0), 0.0, (VecX(2) << 1.0, s).finished());
  EXPECT_NEAR(held(0), 2.0 / (1.0 + s * s), 1e-15);
  EXPECT_NEAR(held(1), 2.0 * s * s / (1.0 + s * s), 1e-12);
  // Independent rows have one solution: the scales are not read.
  MatX B(2, 2);
  B << 2, 1, 1, 3;
  EXPECT_EQ(solve_block(B, VecX::Constant(2, 1.0), 0.0, (VecX(2) << 1.0, s).finished()),
            solve_block(B, VecX::Constant(2, 1.0)));
}

// A row repeated twice and a third row that is their sum: the same least-norm answer in any
// order of the rows.
TEST(ConstraintSolve, TheLeastNormForcesDoNotDependOnTheRowsOrder) {
  MatX G(3, 2);
  G << 1, 0, 1, 0, 1, 1;
  const MatX A = G * G.transpose();
  const VecX b = A * (VecX(3) << 1, 2, 3).finished();
  const VecX x = solve_block(A, b);
  Eigen::PermutationMatrix<3> P;
  P.indices() << 2, 0, 1;
  const VecX y = P.transpose() * solve_block(P * A * P.transpose(), P * b);
  EXPECT_LT((x - y).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((x - A.completeOrthogonalDecomposition().solve(b)).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(ConstraintSolve, ContradictingRowsThrowUnlessWithinTheCallersZero) {
  MatX A(2, 2);
  A << 1, 1, 1, 1;
  VecX b(2);
  b << 1e-17, -2e-17;  // round-off of zero: relative to b's largest they disagree
  EXPECT_THROW(solve_block(A, b), InconsistentConstraints);
  EXPECT_NO_THROW(solve_block(A, b, 1e-12));  // within the rows' own zero they agree
  b << 1.0, 2.0;
  EXPECT_THROW(solve_block(A, b, 1e-12), InconsistentConstraints);
}

}  // namespace
}  // namespace tumble
