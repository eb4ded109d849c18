#include "tumble/math/dual.hpp"

namespace tumble {

double value_of(const Dual& x) {
  return x.value();
}

}  // namespace tumble
