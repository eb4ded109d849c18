#include "tumble/modes/modal_analysis.hpp"

#include <fmt/core.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tumble {

namespace {

using Complex = std::complex<double>;

// The eigenvector over s from one of Q^T A Q: v = Q v_q + P b, where P spans the orbit and
// (P^T A P - lambda) b = -P^T A Q v_q (the orbit is invariant under A). Where lambda is an
// eigenvalue of P^T A P as well (to `tol`: a neutral mode, whose change only moves the state
// along the orbit, at a new rate), there is no such b: the shape is the change, Q v_q.
Eigen::VectorXcd full_shape(const Linearisation& lin, const Eigen::VectorXcd& v_q, Complex lambda,
                            double tol) {
  const MatX& Q = lin.quotient;
  Eigen::VectorXcd v = Q.cast<Complex>() * v_q;
  const MatX& P = lin.orbit_basis;
  const Eigen::Index orbit = P.cols();
  if (orbit == 0) return v;
  const Eigen::MatrixXcd block = (P.transpose() * lin.A * P).cast<Complex>() -
                                 lambda * Eigen::MatrixXcd::Identity(orbit, orbit);
  const Eigen::VectorXcd coupling = (P.transpose() * lin.A * Q).cast<Complex>() * v_q;
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(block, Eigen::ComputeThinU | Eigen::ComputeThinV);
  if (svd.singularValues()(orbit - 1) > tol) v -= P.cast<Complex>() * svd.solve(coupling);
  return v;
}

void normalise(const Linearisation& lin, Eigen::VectorXcd& shape) {
  Eigen::Index best = 0;
  double largest = -1.0;
  // By the largest position, unless the mode moves no position (a change of speed alone, as
  // along a family of steady motions): its positions are then round-off.
  double position_size = 0.0;
  for (std::size_t i = 0; i < lin.coordinates.size(); ++i) {
    if (!lin.coordinates[i].is_speed) {
      position_size = std::max(position_size, std::abs(shape(static_cast<Eigen::Index>(i))));
    }
  }
  const bool positions = position_size > 1e-9 * shape.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < shape.size(); ++i) {
    if (positions && lin.coordinates[static_cast<std::size_t>(i)].is_speed) continue;
    if (std::abs(shape(i)) > largest) {
      largest = std::abs(shape(i));
      best = i;
    }
  }
  if (largest <= 0.0) return;
  shape /= shape(best);
  // Entries far below the largest are round-off: shown as zero, not with a random phase.
  const double floor = 1e-12 * shape.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < shape.size(); ++i) {
    if (std::abs(shape(i)) < floor) shape(i) = 0.0;
  }
}

int rank_of_group(const Eigen::MatrixXcd& vectors) {
  Eigen::MatrixXcd normalised = vectors;
  for (Eigen::Index j = 0; j < normalised.cols(); ++j) {
    normalised.col(j).normalize();
  }
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(normalised);
  const Eigen::VectorXd s = svd.singularValues();
  int rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) rank += s(i) > 1e-6 ? 1 : 0;
  return rank;
}

int order_of(Mode::Kind kind) {
  switch (kind) {
    case Mode::Kind::Growing:
      return 0;
    case Mode::Kind::Oscillating:
    case Mode::Kind::DampedOscillation:
      return 1;
    case Mode::Kind::Decaying:
    case Mode::Kind::DecayingTwin:
      return 2;
    case Mode::Kind::Neutral:
      return 3;
  }
  return 3;
}

}  // namespace

double Mode::frequency_hz() const {
  return damped_frequency / (2.0 * std::numbers::pi);
}

double Mode::period() const {
  return damped_frequency > 0.0 ? 2.0 * std::numbers::pi / damped_frequency : 0.0;
}

std::string kind_name(Mode::Kind kind) {
  switch (kind) {
    case Mode::Kind::Growing:
      return "growing";
    case Mode::Kind::Oscillating:
      return "oscillating";
    case Mode::Kind::DampedOscillation:
      return "damped oscillation";
    case Mode::Kind::Decaying:
      return "decaying";
    case Mode::Kind::DecayingTwin:
      return "decaying twin";
    case Mode::Kind::Neutral:
      return "neutral";
  }
  return "neutral";
}

std::string verdict_name(ModalAnalysis::Verdict verdict) {
  switch (verdict) {
    case ModalAnalysis::Verdict::Stable:
      return "stable";
    case ModalAnalysis::Verdict::Marginal:
      return "marginal";
    case ModalAnalysis::Verdict::Unstable:
      return "unstable";
  }
  return "stable";
}

ModalAnalysis analyse_modes(const Linearisation& lin) {
  const MatX Aq = lin.quotient.transpose() * lin.A * lin.quotient;
  const Eigen::EigenSolver<MatX> eigen(Aq);
  const Eigen::VectorXcd lambdas = eigen.eigenvalues();
  const Eigen::MatrixXcd vectors = eigen.eigenvectors();
  // Each eigenvalue's round-off: the error in A's entries times its condition number
  // |x| |y| / |y^H x|, with the left eigenvectors y^H the rows of the inverse of the right ones
  // (so y^H x = 1). A's entries come out of the solves that make the equations, so their error
  // is taken as 1000 eps |A| (on the examples the real parts of undamped modes come out within
  // 5 eps |A|). An eigenvalue's real part counts as zero only within its own round-off, so that
  // a growth rate crossing zero (a bicycle's weave at its critical speed) is told to round-off,
  // not to 1e-7 of the largest.
  const Eigen::MatrixXcd left_vectors = vectors.inverse();
  const double roundoff = 1000.0 * std::numeric_limits<double>::epsilon() * lin.A.norm();
  ModalAnalysis analysis;
  const double radius = lambdas.size() > 0 ? lambdas.cwiseAbs().maxCoeff() : 0.0;
  // Eigenvalues are good to about 1e-15 of the largest; a repeated one that is defective splits
  // by up to sqrt(1e-16) of it, so that is what counts as zero.
  analysis.tolerance = 1e-7 * std::max(1.0, radius);
  const double tol = analysis.tolerance;

  std::vector<bool> done(static_cast<std::size_t>(lambdas.size()), false);
  bool drifts = false;
  std::size_t drifting = 0;
  for (Eigen::Index i = 0; i < lambdas.size(); ++i) {
    if (done[static_cast<std::size_t>(i)]) continue;
    Complex lambda = lambdas(i);
    // Equal eigenvalues (to tol): do they have as many shapes? If not, a Jordan block.
    std::vector<Eigen::Index> group;
    for (Eigen::Index j = i; j < lambdas.size(); ++j) {
      if (!done[static_cast<std::size_t>(j)] && std::abs(lambdas(j) - lambda) <= tol) {
        group.push_back(j);
      }
    }
    Eigen::MatrixXcd group_vectors(vectors.rows(), static_cast<Eigen::Index>(group.size()));
    for (std::size_t g = 0; g < group.size(); ++g) {
      group_vectors.col(static_cast<Eigen::Index>(g)) = vectors.col(group[g]);
    }
    const bool defective = rank_of_group(group_vectors) < static_cast<int>(group.size());
    for (const Eigen::Index j : group) {
      done[static_cast<std::size_t>(j)] = true;
      Complex mu = lambdas(j);
      if (std::abs(mu.imag()) <= tol) mu = Complex(mu.real(), 0.0);
      // A defective eigenvalue splits by up to tol; any other is good to its round-off (two
      // close ones with shapes of their own: a bicycle's capsize mode near its critical speed,
      // beside the neutral change of speed).
      const double condition = left_vectors.row(j).norm() * vectors.col(j).norm();
      const double real_zero =
          defective || !(condition * roundoff < tol) ? tol : condition * roundoff;
      if (std::abs(mu.real()) <= real_zero) mu = Complex(0.0, mu.imag());
      if (mu.imag() < 0.0) continue;  // its conjugate stands for the pair
      Mode mode;
      mode.eigenvalue = mu;
      mode.natural_frequency = std::abs(mu);
      mode.damped_frequency = std::abs(mu.imag());
      mode.growth_rate = mu.real();
      mode.damping_ratio =
          mode.natural_frequency > 0.0 ? 0.0 - mu.real() / mode.natural_frequency : 0.0;
      if (mu.real() > 0.0) {
        mode.kind = Mode::Kind::Growing;
      } else if (mu.real() < 0.0) {
        mode.kind = mu.imag() > 0.0 ? Mode::Kind::DampedOscillation : Mode::Kind::Decaying;
      } else {
        mode.kind = mu.imag() > 0.0 ? Mode::Kind::Oscillating : Mode::Kind::Neutral;
      }
      mode.shape = full_shape(lin, vectors.col(j), lambdas(j), tol);
      normalise(lin, mode.shape);
      if (defective && mu.real() == 0.0 && !drifts) {
        drifts = true;
        drifting = analysis.modes.size();
      }
      analysis.modes.push_back(std::move(mode));
    }
  }
  // Order; keep track of the drifting mode through the sort.
  std::vector<std::size_t> order(analysis.modes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Mode& x = analysis.modes[a];
    const Mode& y = analysis.modes[b];
    if (order_of(x.kind) != order_of(y.kind)) return order_of(x.kind) < order_of(y.kind);
    if (x.kind == Mode::Kind::Growing) return x.growth_rate > y.growth_rate;
    return x.natural_frequency < y.natural_frequency;
  });
  std::vector<Mode> sorted;
  for (std::size_t i = 0; i < order.size(); ++i) {
    sorted.push_back(analysis.modes[order[i]]);
    if (drifts && order[i] == drifting) drifting = i;
  }
  analysis.modes = std::move(sorted);
  // The twins: a decaying mode whose mirror -conj(lambda) is a growing mode's eigenvalue.
  for (Mode& mode : analysis.modes) {
    if (mode.kind != Mode::Kind::Decaying && mode.kind != Mode::Kind::DampedOscillation) continue;
    for (std::size_t j = 0; j < analysis.modes.size(); ++j) {
      const Mode& growing = analysis.modes[j];
      if (growing.kind == Mode::Kind::Growing &&
          std::abs(growing.eigenvalue + std::conj(mode.eigenvalue)) <= tol) {
        mode.kind = Mode::Kind::DecayingTwin;
        mode.twin_of = j;
        mode.damping_ratio = std::numeric_limits<double>::quiet_NaN();
        break;
      }
    }
  }

  if (!analysis.modes.empty() && analysis.modes.front().kind == Mode::Kind::Growing) {
    const Mode& mode = analysis.modes.front();
    analysis.verdict = ModalAnalysis::Verdict::Unstable;
    analysis.deciding_mode = 0;
    analysis.verdict_text =
        fmt::format("unstable: mode 1 grows at {:.10g} 1/s (by e in {:.6g} s){}", mode.growth_rate,
                    1.0 / mode.growth_rate,
                    mode.damped_frequency > 0.0
                        ? fmt::format(", oscillating at {:.10g} rad/s", mode.damped_frequency)
                        : std::string());
  } else if (!lin.unrestored.empty()) {
    analysis.verdict = ModalAnalysis::Verdict::Marginal;
    std::string names;
    for (const std::string& name : lin.unrestored) names += (names.empty() ? "" : ", ") + name;
    analysis.verdict_text = fmt::format(
        "marginal: nothing restores {} (to first order): a small push sets it drifting", names);
  } else if (drifts) {
    analysis.verdict = ModalAnalysis::Verdict::Marginal;
    analysis.deciding_mode = drifting;
    analysis.verdict_text = fmt::format(
        "marginal: no mode grows exponentially, but mode {} is repeated without as many shapes, "
        "so its coordinates drift linearly in time",
        drifting + 1);
  } else {
    analysis.verdict = ModalAnalysis::Verdict::Stable;
    std::size_t oscillating = 0, decaying = 0, neutral = 0;
    for (const Mode& mode : analysis.modes) {
      if (mode.kind == Mode::Kind::Oscillating) ++oscillating;
      if (mode.kind == Mode::Kind::DampedOscillation || mode.kind == Mode::Kind::Decaying) {
        ++decaying;
      }
      if (mode.kind == Mode::Kind::Neutral) ++neutral;
    }
    analysis.verdict_text = fmt::format(
        "stable: no mode grows ({} decaying, {} oscillating without damping, {} neutral)", decaying,
        oscillating, neutral);
  }
  return analysis;
}

}  // namespace tumble
