#include "tumble/math/local_minimum.hpp"

#include <cmath>
#include <limits>

namespace tumble {

LocalMinimum local_minimum(double a, double b, double x0, double f0,
                           FunctionRef<double(double)> f) {
  const double golden = 0.5 * (3.0 - std::sqrt(5.0));
  const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  // x: the best point so far; w: the second best; v: the one before w.
  double x = x0, w = x0, v = x0;
  double fx = f0, fw = f0, fv = f0;
  double step = 0.0, step_before = 0.0;  // this step and the one before last
  const double width = b - a;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double middle = 0.5 * (a + b);
    // Relative to the interval, not to t: a minimum late in a long run is found as finely as an
    // early one (down to the spacing of doubles near x).
    const double tol =
        root_eps * width / 3.0 + 2.0 * std::numeric_limits<double>::epsilon() * std::abs(x);
    if (std::abs(x - middle) <= 2.0 * tol - 0.5 * (b - a)) break;
    bool parabolic = false;
    if (std::abs(step_before) > tol) {
      // The vertex of the parabola through x, w and v, as x + p / q.
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      const double older = step_before;
      step_before = step;
      // Taken only if it lies inside and moves less than half the step before last: otherwise
      // the parabola is not converging and a golden section step is surer.
      if (std::abs(p) < std::abs(0.5 * q * older) && p > q * (a - x) && p < q * (b - x)) {
        step = p / q;
        const double u = x + step;
        if (u - a < 2.0 * tol || b - u < 2.0 * tol) step = x < middle ? tol : -tol;
        parabolic = true;
      }
    }
    if (!parabolic) {
      step_before = (x < middle ? b : a) - x;
      step = golden * step_before;
    }
    const double u = x + (std::abs(step) >= tol ? step : (step > 0.0 ? tol : -tol));
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return {x, fx};
}

}  // namespace tumble
