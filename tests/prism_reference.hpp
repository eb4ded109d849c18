#pragma once
// The chapter's torque-free prism and its two stable variants, with the 40-digit reference states
// of tests/data/free-prism-40digit.json (Jacobi elliptic solution, cross-checked by a 40-digit
// Taylor integration to 1e-34).
#include <string>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/model.hpp"

namespace tumble::testing {

struct ReferenceState {
  double t = 0.0;
  Vec3 omega_W, omega_B;
  Mat3 R_WB;
};

struct PrismCase {
  std::string id;                      // unstable | stable_max | stable_min
  Vec3 I0_diag;                        // kg m^2 (the chapter's I0, without M/12)
  Vec3 omega0_W;                       // rad/s
  double energy = 0.0;                 // J
  double L_norm = 0.0;                 // kg m^2 / s
  std::vector<ReferenceState> states;  // t = 20, 200, 2000
};

const std::vector<PrismCase>& prism_cases();
const PrismCase& prism_case(const std::string& id);

// One free prism of mass 12 kg (any mass: the rotation does not depend on it), no gravity.
Model prism_model(const PrismCase& c);
BodyState prism_initial_state(const PrismCase& c);

// max |a_ij - b_ij| of R and max |a_i - b_i| of omega, whichever is larger.
double state_error(const Mat3& R, const Vec3& omega_W, const ReferenceState& ref);

}  // namespace tumble::testing
