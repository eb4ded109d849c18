#pragma once
// TR-BDF2: an L-stable implicit method of order 2 for stiff systems at moderate tolerances, where
// radau5's order 5 buys little: a step is a trapezoidal stage to t_n + gamma h and a BDF2 stage
// from y_n and it to t_n + h, both solved with the one real matrix I - h d J (radau5 solves a real
// and a complex n x n system per Newton iteration). The method is that of R. E. Bank, W. M.
// Coughran, W. Fichtner, E. H. Grosse, D. J. Rose and R. K. Smith (1985), as M. E. Hosea and L. F.
// Shampine analysed and implemented it ("Analysis and implementation of TR-BDF2", Applied
// Numerical Mathematics 20 (1996) 21-37; MATLAB's ode23tb).
//
// As a singly diagonally implicit Runge-Kutta method with an explicit first stage:
//     c = (0, gamma, 1),  A = [0 0 0; d d 0; w w d],  b = (w, w, d),
//     gamma = 2 - sqrt 2,  d = gamma / 2,  w = (1 - d) / 2 = sqrt 2 / 4,
// stiffly accurate (y_{n+1} is the last stage) and L-stable; its first stage is f at the step's
// start, the last step's end (first same as last). Each implicit stage Y = base + h d f(Y) is
// solved by simplified Newton with J = df/dy (OdeSystem::jacobian), the stage's slope then read
// from the equation itself, f(Y) = (Y - base) / (h d), as Hosea and Shampine do: consistent with
// the stage, where a new evaluation at a Y converged only to Newton's tolerance would not be.
//
// Error: the embedded weights b_hat of order 3 on the same stages (sum b_hat = 1, sum b_hat c =
// 1/2, sum b_hat c^2 = 1/3: b_hat = ((1 - w)/3, (3w + 1)/3, d/3)), est = h sum (b_hat - b)_i f_i,
// filtered through (I - h d J)^-1 (the Newton matrix: bounded for stiff components instead of
// growing as h J), in the RMS norm with sk_i = atol_i + rtol max(|y_n,i|, |y_{n+1},i|); a step is
// accepted below 1. Step size: h_new = h min(5, max(0.2, 0.9 err^(-1/3))).
// Newton (as radau5.hpp): stops once its predicted remaining error is a small fraction of the
// tolerance; a contraction rate at 0.9 or above, or more than kMostIterations iterations, fail the
// step, which is tried at half its size with a new Jacobian if the one in use was taken earlier;
// after a step whose Newton contracted slower than 0.1 the next takes J anew, otherwise J and its
// factorisation serve on (a step size within 1..1.2 times the last is kept, as radau5 keeps it).
// Continuous extension: the cubic Hermite through both ends' states and slopes (hermite.hpp),
// of order 3, above the method's 2; the slope at the new end is f at the projected state, the
// next step's first stage.
//
// No allocation in a step: every vector, matrix and factorisation is sized in start().
// rhs_evaluations = 1 per Newton iteration + 1 per accepted step (f at the new state) + 1 per
// start and restart.
#include <Eigen/LU>

#include "tumble/integrators/implicit_method.hpp"

namespace tumble {

class TrBdf2 final : public ImplicitMethod {
 public:
  // Throws std::invalid_argument for tolerances or step bounds that make no sense;
  // StepControl::fixed_step is ignored. The largest step is the whole span unless max_step.
  explicit TrBdf2(const StepControl& control);

  std::string_view name() const override { return "trbdf2"; }
  int order() const override { return 2; }
  bool adaptive() const override { return true; }

  // Throws std::invalid_argument where the system gives no Jacobian (OdeSystem::jacobian).
  void start(OdeSystem& system, double t0, const VecX& y0, double t_end) override;
  void restart(double t, const VecX& y) override;
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override {
    auto copy = std::make_unique<TrBdf2>(*this);
    copy->system_ = &system;
    return copy;
  }
  void archive_memory(StateArchive& archive) override;
  StepOutcome step(double t_stop) override;
  void dense_output(double t, VecX& y_out) const override;

 private:
  enum class Newton { Converged, Failed };

  // Factors I - h d J for the signed step h.
  void factor(double h);
  // Newton for the stage Y = base + h d f(t_stage, Y) from the starting value in `stage`.
  Newton solve_stage(double t_stage, double h, const VecX& base, VecX& stage);

  Eigen::PartialPivLU<MatX> lu_;  // of I - h d J

  VecX f_previous_;  // f(t_previous_, y_previous_), for the continuous extension
  VecX base_;        // the known part of the stage being solved
  VecX stage2_;      // Y_2, the trapezoidal stage
  VecX stage3_;      // Y_3, the BDF2 stage: the new state
  VecX f2_, f3_;     // their slopes, from the stage equations
  VecX f_iterate_;   // f at a Newton iterate
  VecX residual_, delta_, scale_;
  double theta_ = 0.0;  // the slowest Newton contraction rate of the last try
};

}  // namespace tumble
