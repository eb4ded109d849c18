#include "tumble/integrators/radau5.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "tumble/integrators/step_size_control.hpp"

namespace tumble {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Newton iterations a step may take before it is tried again shorter (RADAU5's default).
constexpr int kMostIterations = 7;
// A Newton contraction rate at or above this diverges; at or below the second, the Jacobian is
// kept for the next step (RADAU5's 0.001).
constexpr double kDiverging = 0.99;
constexpr double kKeepJacobian = 0.001;
// Bounds on h_new / h; the step-size safety factor.
constexpr double kMostGrowth = 8.0, kMostShrink = 5.0;
constexpr double kSafety = 0.9;

// Radau IIA's coefficients, derived from their definitions (the class comment).
struct Tableau {
  Eigen::Vector3d c;
  Eigen::Matrix3d T, T_inv;
  double gamma = 0.0, alpha = 0.0, beta = 0.0;  // A^-1's eigenvalues gamma and alpha +- i beta
  Eigen::Vector3d e;                            // the error estimate's weights on z
};

// The Lagrange basis polynomial of node k among `nodes`, at s.
template <int N>
double lagrange(const Eigen::Matrix<double, N, 1>& nodes, int k, double s) {
  double value = 1.0;
  for (int j = 0; j < N; ++j) {
    if (j != k) value *= (s - nodes(j)) / (nodes(k) - nodes(j));
  }
  return value;
}

Tableau derive_tableau() {
  Tableau t;
  const double root6 = std::sqrt(6.0);
  t.c << (4.0 - root6) / 10.0, (4.0 + root6) / 10.0, 1.0;
  // Collocation: a_ij is the integral from 0 to c_i of the j-th Lagrange polynomial on c, whose
  // form (s - c_p)(s - c_q) / ((c_j - c_p)(c_j - c_q)) integrates in closed form.
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) {
    const double p = t.c((j + 1) % 3), q = t.c((j + 2) % 3);
    const double denominator = (t.c(j) - p) * (t.c(j) - q);
    for (int i = 0; i < 3; ++i) {
      const double x = t.c(i);
      A(i, j) = (x * x * x / 3.0 - (p + q) * x * x / 2.0 + p * q * x) / denominator;
    }
  }
  const Eigen::Matrix3d A_inv = A.inverse();
  // A^-1's eigenvalues, from its characteristic polynomial x^3 - c2 x^2 + c1 x - c0 (c2 its
  // trace, c1 the sum of its principal 2 x 2 minors, c0 its determinant): its one real root gamma
  // by Newton's method from above (the cubic is convex and rising right of its inflection c2/3,
  // where gamma lies), and the pair alpha +- i beta the quadratic left over gives
  // (2 alpha = c2 - gamma, alpha^2 + beta^2 = c0 / gamma).
  const Eigen::Matrix3d& M = A_inv;
  const double c2 = M.trace();
  const double c1 = M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0) + M(0, 0) * M(2, 2) - M(0, 2) * M(2, 0) +
                    M(1, 1) * M(2, 2) - M(1, 2) * M(2, 1);
  const double c0 = M.determinant();
  double gamma = 1.0 + std::max({std::abs(c2), std::abs(c1), std::abs(c0)});  // above every root
  for (int i = 0; i < 100; ++i) {
    const double step =
        (((gamma - c2) * gamma + c1) * gamma - c0) / ((3.0 * gamma - 2.0 * c2) * gamma + c1);
    gamma -= step;
    if (!(std::abs(step) > 4.0 * kEpsilon * gamma)) break;
  }
  const double alpha = 0.5 * (c2 - gamma);
  const std::complex<double> mu(alpha, std::sqrt(c0 / gamma - alpha * alpha));
  // Each eigenvector spans the null space of M - lambda I (rank 2): the cross product of two of
  // its rows (the pair whose product is largest), complex rows for the complex pair.
  const auto null_vector = [](const auto& rows) {
    using V = Eigen::Matrix<typename std::decay_t<decltype(rows)>::Scalar, 3, 1>;
    V best = V::Zero();
    for (int a = 0; a < 3; ++a) {
      const V candidate = V(rows.row(a).transpose()).cross(V(rows.row((a + 1) % 3).transpose()));
      if (candidate.norm() > best.norm()) best = candidate;
    }
    return best;
  };
  const Eigen::Vector3d v = null_vector(Eigen::Matrix3d(M - gamma * Eigen::Matrix3d::Identity()));
  const Eigen::Vector3cd u = null_vector(
      Eigen::Matrix3cd(M.cast<std::complex<double>>() - mu * Eigen::Matrix3cd::Identity()));
  // A^-1 = T Lambda T^-1 with T = [v, Re u, Im u]: Lambda = [gamma 0 0; 0 alpha b; 0 -b alpha],
  // b = +-beta as u's eigenvalue has it; read from Lambda itself.
  t.T.col(0) = v;
  t.T.col(1) = u.real();
  t.T.col(2) = u.imag();
  t.T_inv = t.T.inverse();
  const Eigen::Matrix3d lambda = t.T_inv * A_inv * t.T;
  t.gamma = lambda(0, 0);
  t.alpha = lambda(1, 1);
  t.beta = lambda(2, 1);
  // The embedded method y_hat = y_n + h (gamma_0 f(t_n, y_n) + sum b_hat_i f(Y_i)), gamma_0 =
  // 1/gamma, of order 3: gamma_0 [k = 0] + sum_i b_hat_i c_i^k = 1/(k + 1) for k = 0, 1, 2.
  // Against b (A's last row), h sum (b_hat - b)_i f(Y_i) = sum_j e_j z_j with e = A^-T (b_hat - b)
  // (h F = A^-1 z).
  const double gamma_0 = 1.0 / t.gamma;
  Eigen::Matrix3d powers;
  for (int i = 0; i < 3; ++i) {
    powers(0, i) = 1.0;
    powers(1, i) = t.c(i);
    powers(2, i) = t.c(i) * t.c(i);
  }
  const Eigen::Vector3d b_hat = powers.lu().solve(Eigen::Vector3d(1.0 - gamma_0, 0.5, 1.0 / 3.0));
  t.e = A_inv.transpose() * (b_hat - A.row(2).transpose());
  return t;
}

const Tableau& tableau() {
  static const Tableau t = derive_tableau();
  return t;
}

// The continuous extension's weight of stage k (0..2) at s: the Lagrange polynomial of c_k on
// the nodes 0, c_1, c_2, c_3 (the node 0 carries y_n, whose increment is zero).
double extension_weight(int k, double s) {
  const Tableau& t = tableau();
  const Eigen::Vector4d nodes(0.0, t.c(0), t.c(1), t.c(2));
  return lagrange<4>(nodes, k + 1, s);
}

// An upper bound on the spectral radius of J: the infinity norm of D^-1 J D after Osborne's
// balancing sweeps, each making row i's off-diagonal sum equal to column i's (B_ij = J_ij d_j /
// d_i: row sum r / d_i, column sum c d_i, equal at d_i = sqrt(r / c)). Every induced norm bounds
// the spectral radius, and balancing brings the bound down to it where units set the entries
// apart (k/m beside 1 in a spring's Jacobian). `d` is scratch of J's size.
double balanced_radius_bound(const MatX& J, VecX& d) {
  constexpr int kSweeps = 5;
  const Eigen::Index n = J.rows();
  d.setOnes();
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    for (Eigen::Index i = 0; i < n; ++i) {
      double r = 0.0, c = 0.0;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (j == i) continue;
        r += std::abs(J(i, j)) * d(j);
        c += std::abs(J(j, i)) / d(j);
      }
      if (r > 0.0 && c > 0.0 && std::isfinite(r / c)) d(i) = std::sqrt(r / c);
    }
  }
  double bound = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    double row = std::abs(J(i, i));
    for (Eigen::Index j = 0; j < n; ++j) {
      if (j != i) row += std::abs(J(i, j)) * d(j) / d(i);
    }
    bound = std::max(bound, row);
  }
  return bound;
}

}  // namespace

Radau5::Radau5(const StepControl& control) : ImplicitMethod("radau5", control) {}

void Radau5::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  start_implicit(system, t0, y0, t_end);
  const Eigen::Index n = y0.size();
  for (int k = 0; k < 3; ++k) {
    z_[k].setZero(n);
    w_[k].setZero(n);
    f_[k].setZero(n);
    extension_[k].setZero(n);
  }
  stage_y_.setZero(n);
  residual_.setZero(n);
  delta_.setZero(n);
  scale_.setZero(n);
  complex_rhs_.setZero(n);
  complex_delta_.setZero(n);
  real_lu_ = Eigen::PartialPivLU<MatX>(n);
  complex_lu_ = Eigen::PartialPivLU<MatXc>(n);
  have_extension_ = false;
  first_step_ = true;
  theta_ = 1.0;
  h_accepted_ = err_accepted_ = 0.0;
}

void Radau5::restart(double t, const VecX& y) {
  restart_implicit(t, y);
  // The last step's polynomial belongs to what came before the jump.
  have_extension_ = false;
  first_step_ = true;
}

void Radau5::on_new_jacobian() {
  if (balance_.size() != jacobian_.rows()) balance_.resize(jacobian_.rows());
  jacobian_radius_bound_ = balanced_radius_bound(jacobian_, balance_);
}

void Radau5::factor(double h) {
  const Tableau& t = tableau();
  const Eigen::Index n = jacobian_.rows();
  real_lu_.compute((t.gamma / h) * MatX::Identity(n, n) - jacobian_);
  const std::complex<double> shift(t.alpha / h, t.beta / h);
  complex_lu_.compute(shift * MatXc::Identity(n, n) - jacobian_.cast<std::complex<double>>());
  factored_h_ = h;
  ++factorisations_;
}

void Radau5::start_stages(double h) {
  if (!have_extension_) {
    for (VecX& z : z_) z.setZero();
    return;
  }
  // The last step's collocation polynomial, read past its end: u(1 + c_i h / h_last) - y_n.
  const Tableau& t = tableau();
  const double h_last = t_ - t_previous_;
  for (int i = 0; i < 3; ++i) {
    const double s = 1.0 + t.c(i) * h / h_last;
    z_[i] = extension_weight(0, s) * extension_[0] + extension_weight(1, s) * extension_[1] +
            (extension_weight(2, s) - 1.0) * extension_[2];
  }
}

Radau5::Newton Radau5::solve_stages(double h, double& shrink, int& iterations) {
  const Tableau& t = tableau();
  const Eigen::Index n = y_.size();
  for (int k = 0; k < 3; ++k) {
    w_[k] = t.T_inv(k, 0) * z_[0] + t.T_inv(k, 1) * z_[1] + t.T_inv(k, 2) * z_[2];
  }
  scale_ = atol_.array() + control_.rtol * y_.array().abs();
  const double enough = newton_enough();
  faccon_ = std::pow(std::max(faccon_, kEpsilon), 0.8);
  // A Newton iteration that is done at its first correction has no rate: it keeps the Jacobian.
  theta_ = kKeepJacobian;
  double previous = 0.0, previous_rate = 0.0;
  for (iterations = 1;; ++iterations) {
    if (iterations > kMostIterations) {
      shrink = 0.5;
      return Newton::Failed;
    }
    for (int i = 0; i < 3; ++i) {
      stage_y_ = y_ + z_[i];
      system_->derivative(t_ + t.c(i) * h, stage_y_, f_[i]);
    }
    stats_.rhs_evaluations += 3;
    if (!f_[0].allFinite() || !f_[1].allFinite() || !f_[2].allFinite()) {
      shrink = 0.5;
      return Newton::Failed;
    }
    // The residual of Lambda w / h = T^-1 F, row by row: the real one, then the complex pair.
    residual_ = t.T_inv(0, 0) * f_[0] + t.T_inv(0, 1) * f_[1] + t.T_inv(0, 2) * f_[2] -
                (t.gamma / h) * w_[0];
    delta_.noalias() = real_lu_.solve(residual_);
    complex_rhs_.real() = t.T_inv(1, 0) * f_[0] + t.T_inv(1, 1) * f_[1] + t.T_inv(1, 2) * f_[2] -
                          (t.alpha / h) * w_[1] + (t.beta / h) * w_[2];
    complex_rhs_.imag() = t.T_inv(2, 0) * f_[0] + t.T_inv(2, 1) * f_[1] + t.T_inv(2, 2) * f_[2] -
                          (t.beta / h) * w_[1] - (t.alpha / h) * w_[2];
    complex_delta_.noalias() = complex_lu_.solve(complex_rhs_);
    const double size =
        std::sqrt(((delta_.array() / scale_.array()).square().sum() +
                   (complex_delta_.real().array() / scale_.array()).square().sum() +
                   (complex_delta_.imag().array() / scale_.array()).square().sum()) /
                  static_cast<double>(3 * n));
    if (iterations > 1) {
      const double rate = size / previous;
      theta_ = iterations == 2 ? rate : std::sqrt(rate * previous_rate);
      previous_rate = rate;
      if (!(theta_ < kDiverging)) {
        shrink = 0.5;
        return Newton::Failed;
      }
      faccon_ = theta_ / (1.0 - theta_);
      // What the iterations left would leave: too much, and the step is tried shorter at once.
      const double predicted =
          faccon_ * size * std::pow(theta_, kMostIterations - iterations) / enough;
      if (predicted >= 1.0) {
        const double q = std::clamp(predicted, 1e-4, 20.0);
        shrink = 0.8 * std::pow(q, -1.0 / (4.0 + kMostIterations - iterations));
        return Newton::Failed;
      }
    }
    previous = std::max(size, kEpsilon);
    w_[0] += delta_;
    w_[1] += complex_delta_.real();
    w_[2] += complex_delta_.imag();
    for (int k = 0; k < 3; ++k) {
      z_[k] = t.T(k, 0) * w_[0] + t.T(k, 1) * w_[1] + t.T(k, 2) * w_[2];
    }
    if (faccon_ * size <= enough) return Newton::Converged;
  }
}

double Radau5::error_norm(double h, bool refine) {
  const Tableau& t = tableau();
  // sum_j e_j z_j times gamma/h, the filter's own factor (the class comment).
  const double g = t.gamma / h;
  residual_ = f0_ + (g * t.e(0)) * z_[0] + (g * t.e(1)) * z_[1] + (g * t.e(2)) * z_[2];
  delta_.noalias() = real_lu_.solve(residual_);
  scale_ = atol_.array() + control_.rtol * y_.array().abs().max((y_ + z_[2]).array().abs());
  double err = rms(delta_, scale_);
  if (err >= 1.0 && refine) {
    stage_y_ = y_ + delta_;
    system_->derivative(t_, stage_y_, residual_);
    ++stats_.rhs_evaluations;
    residual_ += (g * t.e(0)) * z_[0] + (g * t.e(1)) * z_[1] + (g * t.e(2)) * z_[2];
    delta_.noalias() = real_lu_.solve(residual_);
    err = rms(delta_, scale_);
  }
  return std::isfinite(err) ? std::max(err, 1e-10) : err;
}

StepOutcome Radau5::step(double t_stop) {
  if (system_ == nullptr) throw std::logic_error("radau5: step() before start()");
  step_control::require_ahead(name(), t_, t_stop, direction_);
  const double h_min = step_control::minimum_step(t_);
  double h_abs = step_control::first_try(h_, h_max_, step_bound_, h_min);
  bool rejected = false;
  for (;;) {
    const double h_proposed = h_abs;
    const step_control::ClippedStep clipped =
        step_control::clip_to_stop(t_, h_abs, t_stop, direction_, kLandingStretch);
    h_abs = clipped.h_abs;
    const double h = direction_ * h_abs;
    if (need_jacobian_) take_jacobian();
    if (h != factored_h_) factor(h);
    start_stages(h);

    double shrink = 1.0;
    int iterations = 0;
    if (solve_stages(h, shrink, iterations) == Newton::Failed) {
      ++stats_.rejected_steps;
      if (h_abs <= h_min) {
        h_ = h_abs;
        return StepOutcome::StepSizeUnderflow;
      }
      h_abs = std::max(h_min, h_abs * shrink);
      // With a Jacobian kept from an earlier state, take it anew here before shortening more.
      if (!jacobian_current_) need_jacobian_ = true;
      rejected = true;
      continue;
    }

    const double err = error_norm(h, first_step_ || rejected);
    if (!std::isfinite(err)) {
      ++stats_.rejected_steps;
      if (!step_control::shorten_after_blow_up(h_abs, h_min)) {
        h_ = h_abs;
        return StepOutcome::NonFiniteState;
      }
      rejected = true;
      continue;
    }
    const double fac =
        std::min(kSafety, kSafety * (2 * kMostIterations + 1) / (2 * kMostIterations + iterations));
    double quot = std::clamp(std::pow(err, 0.25) / fac, 1.0 / kMostGrowth, kMostShrink);

    if (err >= 1.0) {
      ++stats_.rejected_steps;
      if (h_abs <= h_min) {
        h_ = h_abs;
        return StepOutcome::StepSizeUnderflow;
      }
      h_abs = std::max(h_min, first_step_ ? 0.1 * h_abs : h_abs / quot);
      rejected = true;
      continue;
    }

    // Accepted.
    if (!first_step_) {
      // Gustafsson's predictive controller: the error's trend over the last two steps.
      const double predictive =
          std::clamp(h_accepted_ / h_abs * std::pow(err * err / err_accepted_, 0.25) / kSafety,
                     1.0 / kMostGrowth, kMostShrink);
      quot = std::max(quot, predictive);
    }
    h_accepted_ = h_abs;
    err_accepted_ = std::max(1e-2, err);
    double h_next = h_abs / quot;
    if (rejected) h_next = std::min(h_next, h_abs);
    if (clipped.lands) h_next = std::max(h_next, h_proposed);
    // Newton converged fast: the Jacobian serves the next step too, and a step that would grow
    // by less than a fifth is not worth new factorisations.
    const bool keep_jacobian = theta_ <= kKeepJacobian;
    const double growth = h_next / h_abs;
    if (keep_jacobian && growth >= 1.0 && growth <= kKeepSizeBelow && !clipped.lands) {
      h_next = h_abs;
    }

    y_previous_.swap(y_);
    y_ = y_previous_ + z_[2];
    system_->project(clipped.t_new, y_);
    t_previous_ = t_;
    t_ = clipped.t_new;
    // The continuous extension ends on the projected state.
    extension_[0] = z_[0];
    extension_[1] = z_[1];
    extension_[2] = y_ - y_previous_;
    have_extension_ = true;
    first_step_ = false;
    system_->derivative(t_, y_, f0_);
    ++stats_.rhs_evaluations;
    jacobian_current_ = false;
    need_jacobian_ = !keep_jacobian;
    h_ = std::min(h_next, h_max_);
    ++stats_.accepted_steps;
    return StepOutcome::Ok;
  }
}

void Radau5::dense_output(double t, VecX& y_out) const {
  if (t_ == t_previous_) {  // no step since start or restart
    y_out = y_;
    return;
  }
  const double s = (t - t_previous_) / (t_ - t_previous_);
  y_out = y_previous_ + extension_weight(0, s) * extension_[0] +
          extension_weight(1, s) * extension_[1] + extension_weight(2, s) * extension_[2];
}

// Everything the next step depends on: the Jacobian it may keep, the factorisations' step (they
// are made again from it), the last step's polynomial, Newton's and the controller's memory.
void Radau5::archive_memory(StateArchive& archive) {
  archive_implicit(archive);
  for (int k = 0; k < 3; ++k)
    archive_sized(archive, "extension" + std::to_string(k), extension_[k]);
  archive.flag("have_extension", have_extension_);
  archive_newton_factor(archive);
  archive.number("theta", theta_);
  archive.number("h_accepted", h_accepted_);
  archive.number("err_accepted", err_accepted_);
  archive.require("err_accepted", std::isfinite(err_accepted_) && err_accepted_ >= 0.0,
                  "an error norm, not negative");
  archive.flag("first_step", first_step_);
  archive.require("first_step", first_step_ || err_accepted_ > 0.0,
                  "an accepted step's error where a step was accepted");
  // The factorisations are made again from the Jacobian and the step, as the run made them.
  if (archive.loading() && factored_h_ != 0.0) factor(factored_h_);
}

}  // namespace tumble
