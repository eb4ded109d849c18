#pragma once
// Where a function that changes sign on [a, b] crosses zero, pinned down to a bracket of a few ulps
// of t by the Illinois variant of regula falsi (which halves the value kept at an end that
// survives twice running, so one end cannot stall): superlinear on a smooth crossing, never
// outside the bracket. Events on the dense output and a sweep's conditions both locate with it.
#include "tumble/math/function_ref.hpp"

namespace tumble {

// The crossing of g in [a, b], where g(a) = ga and g(b) = gb lie on opposite sides of zero (or
// gb is zero): a point where g is zero, else the end of the final bracket on b's side. A zero at
// b is b itself (a condition that turns exactly at a step's end).
double sign_change_in(double a, double b, double ga, double gb, FunctionRef<double(double)> g);

}  // namespace tumble
