#pragma once
// Cubic Hermite interpolation over one step from the values and slopes at both ends, the
// continuous extension of the fixed-step methods. With s = (t - t0) / h in [0, 1]:
//   y(s) = (1 + 2s)(1 - s)^2 y0 + s^2 (3 - 2s) y1 + h [ s (1 - s)^2 f0 + s^2 (s - 1) f1 ],
// which matches y and y' at both ends and is O(h^4) accurate locally (the global O(h^4) error
// of RK4 dominates it).
#include "tumble/math/types.hpp"

namespace tumble {

// y_out = the Hermite cubic at t in [t0, t1] (t1 != t0). y_out must not alias the inputs.
inline void hermite_interpolate(double t0, const VecX& y0, const VecX& f0, double t1,
                                const VecX& y1, const VecX& f1, double t, VecX& y_out) {
  const double h = t1 - t0;
  const double s = (t - t0) / h;
  const double r = 1.0 - s;
  const double w_y0 = (1.0 + 2.0 * s) * r * r;
  const double w_y1 = s * s * (3.0 - 2.0 * s);
  const double w_f0 = h * s * r * r;
  const double w_f1 = -h * s * s * r;
  y_out = w_y0 * y0 + w_y1 * y1 + w_f0 * f0 + w_f1 * f1;
}

}  // namespace tumble
