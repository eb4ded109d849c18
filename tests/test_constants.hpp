#pragma once
// Constants that many tests share, defined once: tumble_tests is a unity build, in which test
// files are compiled together and could not each define their own kG.
#include <limits>
#include <numbers>

namespace tumble::test {

inline constexpr double kG = 9.81;  // the gravity of the tests' scenarios, m/s^2
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = std::numbers::pi / 180;                  // one degree in radians
inline constexpr double kEps = std::numeric_limits<double>::epsilon();  // double's round-off

}  // namespace tumble::test
