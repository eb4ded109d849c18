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

// Complete pivoting on the saved A and b; the unknowns past the rank are zero.
void solve_with_redundant_rows(MatX& A, VecX& b, Eigen::Index n, double scale,
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
    if (std::abs(b(r)) > kConsistentRemainder * b_scale) {
      throw InconsistentConstraints(
          "the contacts' constraints contradict each other (two contacts, or a contact and a "
          "joint, ask for different motions of the same freedom)");
    }
  }
  // Back-substitution over the kept pivots; the rest of the unknowns are zero.
  for (Eigen::Index r = n; r-- > rank;) b(r) = 0.0;
  for (Eigen::Index r = rank; r-- > 0;) {
    double sum = b(r);
    for (Eigen::Index c = r + 1; c < rank; ++c) sum -= A(r, c) * b(c);
    b(r) = sum / A(r, r);
  }
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

void solve_constraints_in_place(MatX& A, VecX& b, Eigen::Index n, ConstraintSolveScratch& scratch) {
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
      solve_with_redundant_rows(A, b, n, scale, scratch);
      return;
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
}

}  // namespace tumble
