#pragma once
// The error control's defaults and valid ranges, in one place: StepControl, the scenario's
// `simulate:` (its defaults and checks), the adaptive methods' own checks and docs/scenario.md all
// say what these say.
#include <cmath>
#include <limits>

namespace tumble::tolerances {

inline constexpr double kDefaultRtol = 1e-3;  // ode45's RelTol
inline constexpr double kDefaultAtol = 1e-6;  // ode45's AbsTol
// When only rtol is given, atol follows it in ode45's ratio of defaults (1e-6 / 1e-3): RelTol
// 1e-8 with the default AbsTol 1e-6 would otherwise cap the accuracy near 4e-4.
inline constexpr double kAtolPerRtol = kDefaultAtol / kDefaultRtol;
// Below ~100 eps the error estimate is round-off: the methods refuse such an rtol, and a
// scenario's is raised to it, as ode45 raises one below 100 eps, with a note in the summary.
inline constexpr double kMinRtol = 100.0 * std::numeric_limits<double>::epsilon();

inline bool rtol_valid(double rtol) {
  return rtol >= kMinRtol && rtol < 1.0;
}
// What a scenario may ask for: the raise above takes what is below the floor.
inline bool rtol_asked_valid(double rtol) {
  return rtol > 0.0 && rtol < 1.0;
}
inline bool atol_valid(double atol) {
  return atol > 0.0 && std::isfinite(atol);
}
// The rules as messages state them.
inline constexpr const char* kRtolRule = "in [2.2e-14, 1) (e.g. 1e-8)";
inline constexpr const char* kRtolAskedRule =
    "in (0, 1) (e.g. 1e-8; below 2.2e-14, what round-off allows, it is raised to that)";
inline constexpr const char* kAtolRule = "> 0 and finite (in the state's units, e.g. 1e-10)";

}  // namespace tumble::tolerances
