#pragma once
// A thin coin (radius r = 12.5 mm, 7.5 g) on its rim on a level table, leaning in by theta with
// its COM on a circle of radius rho: the steady motion of a rolling disk, from the Newton-Euler
// equations about the COM (I_axis = m r^2 / 2, I_diameter = m r^2 / 4) and the rolling
// constraint:
//   Omega^2 = g tan(theta) / (3 rho / 2 + r sin(theta) / 4),  spin s = -Omega (rho + r sin) / r.
// `lean` scales the starting precession Omega (1: the steady motion; otherwise it wobbles).
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

namespace tumble::test {

struct RollingCoin {
  double theta = 0.0, rho = 0.0;  // lean (rad) and the COM's circle (m)
  double r = 0.0125, g = 9.81;
  double precession() const {
    return std::sqrt(g * std::tan(theta) / (1.5 * rho + 0.25 * r * std::sin(theta)));
  }
  double period() const { return 2 * std::numbers::pi / precession(); }
};

inline std::string rolling_coin_scenario(const RollingCoin& coin, double mu, double lean,
                                         double duration, double output_every) {
  const double Omega = coin.precession();
  const double s = -Omega * (coin.rho + coin.r * std::sin(coin.theta)) / coin.r;
  return fmt::format(
      "tumble: 1\n"
      "parameters: {{theta: {theta}}}\n"
      "bodies:\n"
      "  coin: {{shape: disk, radius: {r}, mass: 0.0075, position: [{rho}, 0, {r} * "
      "cos(theta)],\n"
      "          orientation: {{axis: [0, 1, 0], angle: 90 deg - theta}},\n"
      "          velocity: [0, {v}, 0],\n"
      "          angular_velocity: [{s} * cos(theta), 0, {lean} * {Omega} + {s} * sin(theta)]}}\n"
      "contacts:\n"
      "  - {{name: table, type: plane, body: coin, plane: {{point: [0, 0, 0], normal: [0, 0, 1]}}, "
      "friction: {mu}}}\n"
      "simulate: {{duration: {T}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: {dt}, max_steps: 200000}}\n",
      fmt::arg("theta", coin.theta), fmt::arg("r", coin.r), fmt::arg("rho", coin.rho),
      fmt::arg("v", Omega * coin.rho), fmt::arg("s", s), fmt::arg("Omega", Omega),
      fmt::arg("lean", lean), fmt::arg("mu", mu), fmt::arg("T", duration),
      fmt::arg("dt", output_every));
}

}  // namespace tumble::test
