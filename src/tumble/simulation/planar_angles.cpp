#include "tumble/simulation/planar_angles.hpp"

#include <cmath>
#include <numbers>

namespace tumble {

void continue_planar_angles(double t, std::span<const BodyState> states, RowExtras& extras) {
  const bool first = extras.planar_angles.size() != states.size();
  extras.planar_angles.resize(states.size());
  extras.planar_rates.resize(states.size());
  for (std::size_t b = 0; b < states.size(); ++b) {
    const Mat3& R = states[b].R_WB;
    const double raw = std::atan2(R(1, 0), R(0, 0));
    const double rate = states[b].omega_W.z();
    double angle = raw;
    if (!first) {
      const double expected =
          extras.planar_angles[b] + 0.5 * (extras.planar_rates[b] + rate) * (t - extras.planar_t);
      angle =
          raw + 2.0 * std::numbers::pi * std::round((expected - raw) / (2.0 * std::numbers::pi));
    }
    extras.planar_angles[b] = angle;
    extras.planar_rates[b] = rate;
  }
  extras.planar_t = t;
}

}  // namespace tumble
