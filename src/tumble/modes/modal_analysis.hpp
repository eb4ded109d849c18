#pragma once
// The modes of a linearisation (linearisation.hpp): the eigenvalues lambda = sigma + i omega_d of
// its matrix, what each means (natural frequency |lambda|, damped frequency omega_d, period
// 2 pi / omega_d, damping ratio -sigma / |lambda|, growth rate sigma), the mode shapes over the
// kept coordinates, and a verdict.
//   unstable: some mode grows (sigma > 0); the fastest is named;
//   marginal: none grows, but a joint's coordinate has nothing to restore it (a mast on a
//             spring exactly at its critical stiffness), or a neutral or undamped mode is
//             repeated without as many shapes (a Jordan block): its coordinates drift linearly
//             in time;
//   stable:   none grows and none drifts: every mode decays, oscillates without growing, or is
//             a neutral direction (a change to a neighbouring equilibrium or steady motion).
// A conjugate pair is one mode (the member with omega_d > 0).
#include <complex>
#include <string>
#include <vector>

#include "tumble/modes/linearisation.hpp"

namespace tumble {

struct Mode {
  // DecayingTwin: the mirror -conj(lambda) of a growing mode, which a system without damping
  // has for each one (the growing motion run backwards in time). It decays without any
  // damping, so it has no damping ratio (NaN); `twin_of` names its growing mode.
  enum class Kind { Growing, Oscillating, DampedOscillation, Decaying, DecayingTwin, Neutral };
  std::complex<double> eigenvalue;
  Kind kind = Kind::Neutral;
  double natural_frequency = 0.0;  // |lambda|, rad/s
  double damped_frequency = 0.0;   // |Im lambda|, rad/s
  double damping_ratio = 0.0;      // -Re lambda / |lambda| (0 for lambda = 0)
  double growth_rate = 0.0;        // Re lambda, 1/s
  std::size_t twin_of = 0;         // DecayingTwin: the growing mode's index in the analysis
  // Over Linearisation::coordinates, scaled so that its largest position (or, with no
  // positions, its largest speed) is 1 at phase 0.
  Eigen::VectorXcd shape;

  double frequency_hz() const;  // omega_d / (2 pi); 0 without oscillation
  double period() const;        // 2 pi / omega_d; 0 without oscillation
};

std::string kind_name(Mode::Kind kind);

struct ModalAnalysis {
  enum class Verdict { Stable, Marginal, Unstable } verdict = Verdict::Stable;
  // Growing (fastest first), oscillating (slowest first), decaying and decaying twins, neutral.
  std::vector<Mode> modes;
  std::size_t deciding_mode = 0;  // unstable: the fastest growing; marginal: the drifting one
  std::string verdict_text;       // one line
  double tolerance = 0.0;         // |sigma| and |lambda| below this count as zero, 1/s
};

// "stable", "marginal", "unstable".
std::string verdict_name(ModalAnalysis::Verdict verdict);

ModalAnalysis analyse_modes(const Linearisation& linearisation);

}  // namespace tumble
