#pragma once
// Radau IIA of order 5: three implicit stages, stiffly accurate and L-stable, for stiff systems
// (a stiff spring or damper, a fast mode nobody wants resolved) where every explicit method's
// step is held by stability rather than by accuracy. The design is that of E. Hairer and G.
// Wanner, "Solving Ordinary Differential Equations II", 2nd ed., Springer 1996, section IV.8,
// and of their RADAU5 code described there.
//
// The step: the stages' increments z_i = Y_i - y_n solve the collocation equations
//     z_i = h sum_j a_ij f(t_n + c_j h, y_n + z_j),   c = ((4 - sqrt 6)/10, (4 + sqrt 6)/10, 1),
// and y_{n+1} = y_n + z_3 (the last stage is the solution: stiffly accurate). Simplified Newton
// with J = df/dy taken at the step's start (OdeSystem::jacobian), in the coordinates
// w = (T^-1 x I) z in which A^-1 = T Lambda T^-1 is block-diagonal (a real eigenvalue gamma and
// a complex pair alpha +- i beta): each iteration solves one real n x n system with
// (gamma/h I - J) and one complex one with ((alpha + i beta)/h I - J), each factored once per
// step size and Jacobian. Newton's contraction rate theta decides whether a step may go on (its
// error after the iterations left must be small), whether J is taken again at the next step
// (theta > 0.001) and whether a step size change is worth a new factorisation (not within
// 1..1.2 times, with J kept).
//
// Error: the difference from an embedded method of order 3, y_hat - y = gamma_0 h f(t_n, y_n) +
// sum_j e_j z_j, filtered through (I - h gamma_0 J)^-1 = (gamma/h)(gamma/h I - J)^-1
// (gamma_0 = 1/gamma, so the real factorisation serves), which leaves it bounded for stiff
// components instead of growing as h J; the first step after a start and a step after a
// rejection filter a second time from f(t_n, y_n + err) when the first says reject (Hairer's
// refinement). Measured in the RMS norm with sk_i = atol_i + rtol max(|y_n,i|, |y_{n+1},i|); a
// step is accepted when the norm is below 1.
// Tolerances: RADAU5 holds the estimate to 0.1 rtol^(2/3), not to rtol, since an estimate of
// order 3 overstates the error of steps of order 5. tumble holds it to rtol itself: the
// continuous extension (the rows, the events) has an error of the estimate's order in h, so held
// to rtol it is within the tolerance asked, where RADAU5's mapping leaves the rows 20 times
// above it at rtol 1e-8. The steps' own error is then far below rtol, for 2 to 3 times RADAU5's
// steps.
// Step size: h_new = h / quot, quot = err^(1/4) / fac, fac = 0.9 (2 n_max + 1)/(2 n_max + n_it)
// (fewer Newton iterations, a bolder step), at most 8 times longer or 5 times shorter, and after
// an accepted step no longer than Gustafsson's predictive controller allows
// (h_acc/h (err^2/err_acc)^(1/4) / 0.9).
// Continuous extension: the collocation polynomial of degree 3 through y_n and the three stages,
// no extra evaluation; its error is of order h^4, as the estimate's is. It ends on the projected
// state (its last node moved with the projection).
// Each new step's Newton iteration starts from that polynomial, extrapolated.
//
// The method's coefficients (A, T, Lambda, the embedded weights) are derived when first used
// from their definitions: collocation at c, the eigen-decomposition of A^-1, the order
// conditions; none is typed in.
//
// No allocation in a step: every vector, matrix and factorisation is sized in start().
// rhs_evaluations = 3 per Newton iteration + 1 per accepted step (f at the new state, for the
// next error estimate and Jacobian) + 1 per second filtering + 1 per start and restart.
#include <array>
#include <cmath>
#include <complex>

#include <Eigen/LU>

#include "tumble/integrators/implicit_method.hpp"

namespace tumble {

class Radau5 final : public ImplicitMethod {
 public:
  // Throws std::invalid_argument for tolerances or step bounds that make no sense;
  // StepControl::fixed_step is ignored. The largest step is the whole span unless max_step.
  explicit Radau5(const StepControl& control);

  std::string_view name() const override { return "radau5"; }
  int order() const override { return 5; }
  bool adaptive() const override { return true; }

  // Throws std::invalid_argument where the system gives no Jacobian (OdeSystem::jacobian).
  void start(OdeSystem& system, double t0, const VecX& y0, double t_end) override;
  void restart(double t, const VecX& y) override;
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override {
    auto copy = std::make_unique<Radau5>(*this);
    copy->system_ = &system;
    return copy;
  }
  void archive_memory(StateArchive& archive) override;
  StepOutcome step(double t_stop) override;
  void dense_output(double t, VecX& y_out) const override;

  // The last step's |h| times a bound on the spectral radius of the Jacobian in use: the
  // infinity norm of D^-1 J D, D the diagonal scaling that balances J's rows against its
  // columns (Osborne's iteration, a few sweeps), an upper bound for any D and a tight one for the
  // springs and dampers that make a system stiff. Computed when J is taken, not at every step.
  double last_step_h_lambda() const override {
    return std::abs(t_ - t_previous_) * jacobian_radius_bound_;
  }

 private:
  using VecXc = Eigen::VectorXcd;
  using MatXc = Eigen::MatrixXcd;
  enum class Newton { Converged, Failed };

  // jacobian_radius_bound_ from jacobian_.
  void on_new_jacobian() override;
  // Factors (gamma/h I - J) and ((alpha + i beta)/h I - J) for the signed step h.
  void factor(double h);
  // The Newton iteration for the stages of a step h from (t_, y_), from the starting values in
  // z_; on failure, `shrink` is the factor to take the step size by.
  Newton solve_stages(double h, double& shrink, int& iterations);
  // The filtered error estimate's RMS norm for the converged stages of a step h; `refine`: the
  // second filtering where the first says reject.
  double error_norm(double h, bool refine);
  // The stages' starting values for a step h: the last step's polynomial extrapolated, or zero.
  void start_stages(double h);

  double jacobian_radius_bound_ = 0.0;  // 1/s, >= the spectral radius of jacobian_
  VecX balance_;                        // the diagonal of D (last_step_h_lambda)
  Eigen::PartialPivLU<MatX> real_lu_;
  Eigen::PartialPivLU<MatXc> complex_lu_;

  std::array<VecX, 3> z_;          // the stages' increments of the step being tried
  std::array<VecX, 3> w_;          // the same in the transformed coordinates
  std::array<VecX, 3> f_;          // f at the stages
  std::array<VecX, 3> extension_;  // z of the last accepted step (its continuous extension)
  bool have_extension_ = false;    // a step accepted since the start or the last restart
  VecX stage_y_, residual_, delta_, scale_;
  VecXc complex_rhs_, complex_delta_;
  double theta_ = 1.0;       // the last Newton contraction rate
  double h_accepted_ = 0.0;  // Gustafsson's memory: the last accepted step's size and error
  double err_accepted_ = 0.0;
  bool first_step_ = true;  // no step accepted since the start or the last restart
};

}  // namespace tumble
