#include "tumble/math/sign_change.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble {

double sign_change_in(double a, double b, double ga, double gb, FunctionRef<double(double)> g) {
  if (gb == 0.0) return b;
  int last_side = 0;  // +1: the last probe replaced b; -1: it replaced a
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double width_floor =
        4.0 * std::numeric_limits<double>::epsilon() * std::max({1.0, std::abs(a), std::abs(b)});
    if (b - a <= width_floor) break;
    double c = b - gb * (b - a) / (gb - ga);
    if (!(c > a && c < b)) c = 0.5 * (a + b);  // keep strictly inside the bracket
    const double gc = g(c);
    if (gc == 0.0) return c;
    if ((gc > 0.0) == (gb > 0.0)) {
      b = c;
      gb = gc;
      if (last_side == +1) ga *= 0.5;
      last_side = +1;
    } else {
      a = c;
      ga = gc;
      if (last_side == -1) gb *= 0.5;
      last_side = -1;
    }
  }
  return b;
}

}  // namespace tumble
