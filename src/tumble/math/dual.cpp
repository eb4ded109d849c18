#include "tumble/math/dual.hpp"

#include <cmath>

#include "tumble/math/rotation.hpp"

namespace tumble {

double value_of(const Dual& x) {
  return x.value();
}

Dual atan2_of(const Dual& y, const Dual& x) {
  // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2); a plain number has no derivatives at all.
  const double squared_hypot = y.value() * y.value() + x.value() * x.value();
  const DualDerivatives& dy = y.derivatives();
  const DualDerivatives& dx = x.derivatives();
  DualDerivatives d;
  if (dy.size() > 0 && dx.size() > 0) {
    d = (dy * x.value() - y.value() * dx) / squared_hypot;
  } else if (dy.size() > 0) {
    d = dy * x.value() / squared_hypot;
  } else if (dx.size() > 0) {
    d = -y.value() * dx / squared_hypot;
  }
  return Dual(std::atan2(y.value(), x.value()), d);
}

}  // namespace tumble
