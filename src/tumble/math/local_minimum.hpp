#pragma once
// The least value of a function on an interval, by Brent's method: parabolic interpolation
// through the three best points where it behaves, golden-section steps where it does not, so a
// smooth minimum takes a handful of evaluations and any unimodal one is still found. A sweep's
// max() and min() find the extremum between two samples of the continuous solution with it.
#include "tumble/math/function_ref.hpp"

namespace tumble {

struct LocalMinimum {
  double x = 0.0;
  double value = 0.0;
};

// The least value of f on [a, b] found from x0 (inside, f(x0) = f0), to |x - x*| within about
// sqrt(eps) (b - a) (or a few ulps of x, if more): near a smooth minimum f is flat, so its value
// is then within about eps |f''| (b - a)^2 of the least, eps of f's change over [a, b]. Never
// worse than f0.
LocalMinimum local_minimum(double a, double b, double x0, double f0, FunctionRef<double(double)> f);

}  // namespace tumble
