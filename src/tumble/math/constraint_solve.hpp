#pragma once
// The small dense solves of constraint forces and impulses: A x = b for the leading n x n block
// of a preallocated matrix, in place (b becomes x), allocating nothing.
//
// Rows may be redundant: a contact on a body that a joint already holds asks for motion the joint
// has taken away (a pendulum's bob striking a wall: the bob can only move about the pivot, so
// its contact point's three velocity components are one freedom). Then A is singular, and its
// rows are consistent (they describe the same motion). The solve first eliminates with partial
// pivoting, as for independent rows; should a pivot come out at round-off of A's scale, it starts
// again from the saved A and b with complete pivoting, keeps the rows whose pivots are not
// round-off, and of the solutions takes the least-norm one: the forces that reach every motion
// the rows ask for, shared evenly among rows that carry a load alike (four wheels on a plane; the
// joints carry the rest of the load), whatever the rows' order. Rows that contradict each other
// (the right-hand sides of the dependent ones above round-off of b's largest, and above `zero`,
// the caller's zero of what the rows measure) throw InconsistentConstraints.
#include <stdexcept>
#include <vector>

#include "tumble/math/types.hpp"

namespace tumble {

// Rows that ask for motions no force can give together: the mode they state is impossible (a
// pendulum's bob cannot both bounce off a wall and stop slipping on it), and the caller tries
// another.
class InconsistentConstraints : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Room for the redundant-row path, sized once for the largest n.
struct ConstraintSolveScratch {
  explicit ConstraintSolveScratch(Eigen::Index largest = 0);
  MatX A;
  VecX b;
  std::vector<Eigen::Index> column_of;  // the unknown at each pivot position
};

// With `scales` (n entries, > 0), the solution taken where rows are redundant is the least in
// sum (x_i / scales_i)^2 instead: unknowns of a large scale carry the load before the others.
// (Independent rows have one solution: the scales are not read.) Returns whether the rows were
// redundant (and the least-norm solution taken).
bool solve_constraints_in_place(MatX& A, VecX& b, Eigen::Index n, ConstraintSolveScratch& scratch,
                                double zero = 0.0, const VecX* scales = nullptr);

}  // namespace tumble
