#include "tumble/math/constraint_solve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace tumble {

namespace {

// A pivot this small against A's largest entry is round-off: its row depends on the others.
constexpr double kRedundantPivot = 1e-12;
// A dependent row's right-hand side this small against b's largest is consistent with the others.
constexpr double kConsistentRemainder = 1e-9;

// The solutions of the consistent rows are x_b + N w, N = [-Z; I] a basis of A's null space with
// Z = U11^-1 U12 (the eliminated rows [U11 U12], in pivot order); the least-norm one has
// (N^T N) w = -N^T x_b, that is (Z^T Z + I) w = Z^T x_b1, and then x1 = x_b1 - Z w, x2 = w.
// The unknowns are forces (N; a face's turn, N m): no choice among forces that give the same
// motion is physically preferred, and this one shares a load evenly among rows that carry it
// alike (four wheels on a plane, two points of one edge) and does not depend on the rows' order.
// In place: Z over U12 in A, the small system in the scratch.
void least_norm_solution(MatX& A, VecX& b, Eigen::Index n, Eigen::Index rank,
                         ConstraintSolveScratch& scratch) {
  const Eigen::Index m = n - rank;
  if (m == 0 || rank == 0) return;
  for (Eigen::Index c = rank; c < n; ++c) {
    for (Eigen::Index r = rank; r-- > 0;) {
      double sum = A(r, c);
      for (Eigen::Index k = r + 1; k < rank; ++k) sum -= A(r, k) * A(k, c);
      A(r, c) = sum / A(r, r);
    }
  }
  MatX& G = scratch.A;  // the saved A is no longer needed
  VecX& w = scratch.b;
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) {
      double sum = i == j ? 1.0 : 0.0;
      for (Eigen::Index k = 0; k < rank; ++k) sum += A(k, rank + i) * A(k, rank + j);
      G(i, j) = sum;
    }
    double rhs = 0.0;
    for (Eigen::Index k = 0; k < rank; ++k) rhs += A(k, rank + i) * b(k);
    w(i) = rhs;
  }
  // Cholesky of the symmetric positive definite Z^T Z + I (its lower triangle), then the solve.
  for (Eigen::Index j = 0; j < m; ++j) {
    double d = G(j, j);
    for (Eigen::Index k = 0; k < j; ++k) d -= G(j, k) * G(j, k);
    G(j, j) = std::sqrt(d);
    for (Eigen::Index i = j + 1; i < m; ++i) {
      double sum = G(i, j);
      for (Eigen::Index k = 0; k < j; ++k) sum -= G(i, k) * G(j, k);
      G(i, j) = sum / G(j, j);
    }
  }
  for (Eigen::Index i = 0; i < m; ++i) {
    double sum = w(i);
    for (Eigen::Index k = 0; k < i; ++k) sum -= G(i, k) * w(k);
    w(i) = sum / G(i, i);
  }
  for (Eigen::Index i = m; i-- > 0;) {
    double sum = w(i);
    for (Eigen::Index k = i + 1; k < m; ++k) sum -= G(k, i) * w(k);
    w(i) = sum / G(i, i);
  }
  for (Eigen::Index k = 0; k < rank; ++k) {
    double sum = b(k);
    for (Eigen::Index i = 0; i < m; ++i) sum -= A(k, rank + i) * w(i);
    b(k) = sum;
  }
  for (Eigen::Index i = 0; i < m; ++i) b(rank + i) = w(i);
}

// Complete pivoting on the saved A and b; of the solutions of the consistent rows, the least
// norm's.
void solve_with_redundant_rows(MatX& A, VecX& b, Eigen::Index n, double scale, double zero,
                               ConstraintSolveScratch& scratch) {
  std::vector<Eigen::Index>& column_of = scratch.column_of;
  column_of.resize(static_cast<std::size_t>(n));  // reserved: no allocation
  for (Eigen::Index k = 0; k < n; ++k) column_of[static_cast<std::size_t>(k)] = k;
  double b_scale = 0.0;
  for (Eigen::Index r = 0; r < n; ++r) b_scale = std::max(b_scale, std::abs(b(r)));
  Eigen::Index rank = 0;
  for (; rank < n; ++rank) {
    Eigen::Index pr = rank, pc = rank;
    for (Eigen::Index c = rank; c < n; ++c) {
      for (Eigen::Index r = rank; r < n; ++r) {
        if (std::abs(A(r, c)) > std::abs(A(pr, pc))) {
          pr = r;
          pc = c;
        }
      }
    }
    if (!(std::abs(A(pr, pc)) > kRedundantPivot * scale)) break;
    if (pr != rank) {
      for (Eigen::Index c = 0; c < n; ++c) std::swap(A(pr, c), A(rank, c));
      std::swap(b(pr), b(rank));
    }
    if (pc != rank) {
      for (Eigen::Index r = 0; r < n; ++r) std::swap(A(r, pc), A(r, rank));
      std::swap(column_of[static_cast<std::size_t>(pc)], column_of[static_cast<std::size_t>(rank)]);
    }
    for (Eigen::Index r = rank + 1; r < n; ++r) {
      const double factor = A(r, rank) / A(rank, rank);
      for (Eigen::Index c = rank; c < n; ++c) A(r, c) -= factor * A(rank, c);
      b(r) -= factor * b(rank);
    }
  }
  for (Eigen::Index r = rank; r < n; ++r) {
    if (std::abs(b(r)) > std::max(kConsistentRemainder * b_scale, zero)) {
      throw InconsistentConstraints(
          "the contacts' constraints contradict each other (two contacts, or a contact and a "
          "joint, ask for different motions of the same freedom)");
    }
  }
  // Back-substitution over the kept pivots, the rest of the unknowns zero: a basic solution x_b.
  for (Eigen::Index r = n; r-- > rank;) b(r) = 0.0;
  for (Eigen::Index r = rank; r-- > 0;) {
    double sum = b(r);
    for (Eigen::Index c = r + 1; c < rank; ++c) sum -= A(r, c) * b(c);
    b(r) = sum / A(r, r);
  }
  least_norm_solution(A, b, n, rank, scratch);
  // Back to the unknowns' own order: position k holds unknown column_of[k].
  VecX& x = scratch.b;
  for (Eigen::Index k = 0; k < n; ++k) x(column_of[static_cast<std::size_t>(k)]) = b(k);
  for (Eigen::Index k = 0; k < n; ++k) b(k) = x(k);
}

}  // namespace

ConstraintSolveScratch::ConstraintSolveScratch(Eigen::Index largest)
    : A(largest, largest), b(largest) {
  column_of.reserve(static_cast<std::size_t>(largest));
}

bool solve_constraints_in_place(MatX& A, VecX& b, Eigen::Index n, ConstraintSolveScratch& scratch,
                                double zero, const VecX* scales) {
  double scale = 0.0;
  for (Eigen::Index c = 0; c < n; ++c) {
    for (Eigen::Index r = 0; r < n; ++r) scale = std::max(scale, std::abs(A(r, c)));
  }
  scratch.A.topLeftCorner(n, n) = A.topLeftCorner(n, n);
  scratch.b.head(n) = b.head(n);
  for (Eigen::Index col = 0; col < n; ++col) {
    Eigen::Index pivot = col;
    for (Eigen::Index r = col + 1; r < n; ++r) {
      if (std::abs(A(r, col)) > std::abs(A(pivot, col))) pivot = r;
    }
    // A non-finite pivot (a stage that blew up) goes through as NaN, and the integrator retries
    // that step shorter; one at round-off means redundant rows.
    if (std::abs(A(pivot, col)) <= kRedundantPivot * scale) {
      A.topLeftCorner(n, n) = scratch.A.topLeftCorner(n, n);
      b.head(n) = scratch.b.head(n);
      if (scales == nullptr) {
        solve_with_redundant_rows(A, b, n, scale, zero, scratch);
        return true;
      }
      // x = S x' with S = diag(scales): the least-norm x' of (A S) x' = b is the x of least
      // sum (x_i / scales_i)^2.
      double scaled = 0.0;
      for (Eigen::Index c = 0; c < n; ++c) {
        A.col(c).head(n) *= (*scales)(c);
        scaled = std::max(scaled, A.col(c).head(n).cwiseAbs().maxCoeff());
      }
      solve_with_redundant_rows(A, b, n, scaled, zero, scratch);
      b.head(n).array() *= scales->head(n).array();
      return true;
    }
    if (pivot != col) {
      for (Eigen::Index c = col; c < n; ++c) std::swap(A(pivot, c), A(col, c));
      std::swap(b(pivot), b(col));
    }
    for (Eigen::Index r = col + 1; r < n; ++r) {
      const double factor = A(r, col) / A(col, col);
      for (Eigen::Index c = col; c < n; ++c) A(r, c) -= factor * A(col, c);
      b(r) -= factor * b(col);
    }
  }
  for (Eigen::Index r = n; r-- > 0;) {
    double sum = b(r);
    for (Eigen::Index c = r + 1; c < n; ++c) sum -= A(r, c) * b(c);
    b(r) = sum / A(r, r);
  }
  return false;
}

}  // namespace tumble
