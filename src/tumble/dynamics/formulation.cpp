#include "tumble/dynamics/formulation.hpp"

namespace tumble {

void Formulation::unpack_all(const VecX& y, std::span<BodyState> states) const {
  for (std::size_t i = 0; i < states.size(); ++i) states[i] = unpack(y, i);
}

void Formulation::calc_row_extras(double /*t*/, const VecX& /*y*/, RowExtras& extras) const {
  extras.reset();
}

}  // namespace tumble
