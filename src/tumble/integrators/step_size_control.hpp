#pragma once
// The pieces of adaptive step-size control that the embedded Runge-Kutta methods share: the two
// error norms (MATLAB ode45's maximum norm and Hairer's root-mean-square norm), the minimum step,
// the clipping of a step to the driver's stop time, and the checks on a StepControl.
//
// References: L. F. Shampine and M. W. Reichelt, "The MATLAB ODE Suite", SIAM J. Sci. Comput. 18
// (1997) 1-22, and the ode45.m code it describes; E. Hairer, S. P. Norsett and G. Wanner, "Solving
// Ordinary Differential Equations I", 2nd ed., Springer 1993, section II.4 (step control, eq.
// 4.11 norm, the starting step) and the DOP853 code that goes with it.
#include <algorithm>
#include <string_view>

#include "tumble/integrators/integrator.hpp"

namespace tumble::step_control {

// ode45's error measure of one step:
//   err = max_i |e_i| / max(|y_i|, |y_new_i|, threshold_i),   threshold_i = atol_i / rtol,
// compared with rtol (err <= rtol accepts). e is the local error estimate (already times h).
double max_norm_error(const VecX& error, const VecX& y, const VecX& y_new, const VecX& thresholds);

// Hairer's DOP853 error measure, combining the 5th-order estimate e5 and the 3rd-order one e3
// (both WITHOUT the factor h) in the RMS norm with sk_i = atol_i + rtol * max(|y_i|, |y_new_i|):
//   E5 = sum_i (e5_i / sk_i)^2,  E3 = sum_i (e3_i / sk_i)^2,
//   err = |h| E5 / sqrt(n (E5 + 0.01 E3))      (1 when E5 + 0.01 E3 == 0 is replaced by 1),
// compared with 1. The 3rd-order estimate in the denominator keeps the 5th-order one, which is
// asymptotically too small for large steps, honest (Hairer-Norsett-Wanner I, section II.10).
double dop853_error(const VecX& error5, const VecX& error3, const VecX& y, const VecX& y_new,
                    const VecX& atol, double rtol, double h);

// The absolute tolerance per component, atol in each component's unit
// (OdeSystem::tolerance_units). Called once when a method starts.
void absolute_tolerances(const OdeSystem& system, const VecX& y0, double atol, VecX& atols);

// MATLAB's eps(t): the gap from |t| to the next larger double.
double spacing(double t);

// The smallest step ode45 takes at t, 16 eps(t); a rejected step this small is a step-size
// underflow (the solution changes faster than the time grid can resolve).
double minimum_step(double t);

// The size a step tries first: the method's proposal h, within its largest step h_max and the
// bound a system asked for (Integrator::bound_next_step), and not below h_min.
inline double first_try(double h, double h_max, double step_bound, double h_min) {
  return std::min({h_max, std::max(h_min, step_bound), std::max(h_min, h)});
}

// ode45's first step: h = min(h_max, |t_end - t0|); rh = ||f0 ./ max(|y0|, atol_i/rtol)||_inf
// / (0.8 rtol^(1/5)); if h rh > 1 then h = 1 / rh; then at least minimum_step(t0).
double ode45_initial_step(const VecX& y0, const VecX& f0, double rtol, const VecX& atol,
                          double h_max, double span, double t0);

// A step too long for the solution can blow its stages up (a fast mode, a contact's friction
// turning over): a rejection, retried ten times shorter. Shortens h_abs (not below h_min) and
// returns true; false when h_abs is already h_min: then the state itself is non-finite.
bool shorten_after_blow_up(double& h_abs, double h_min);

// A step of magnitude h_abs from t towards t_stop (direction +1 or -1). If it would reach past
// t_stop, or fall short of it by less than (stretch - 1) h_abs, the step is stretched or shortened
// to land on t_stop exactly, so no sliver of a step is left over.
struct ClippedStep {
  double h_abs = 0.0;  // the magnitude of the step to take, s
  double t_new = 0.0;  // where it ends: t_stop exactly when it lands
  bool lands = false;  // true when the step ends on t_stop
};
ClippedStep clip_to_stop(double t, double h_abs, double t_stop, double direction, double stretch);

// Where the next fixed step from t ends: on the grid t_grid + (n + 1) h, or on t_stop when the
// grid point would pass it or fall short of it by less than a tiny fraction of h.
struct FixedStepEnd {
  double t_new = 0.0;
  bool lands = false;
};
FixedStepEnd next_fixed_step_end(double t_grid, long grid_steps, double h_abs, double direction,
                                 double t_stop);

// Throws std::invalid_argument unless t_stop lies strictly ahead of t in the direction of
// integration; `method` names the caller in the message.
void require_ahead(std::string_view method, double t, double t_stop, double direction);

// Throws std::invalid_argument with the parameter, its value and the fix unless rtol, atol,
// initial_step and max_step make sense for an adaptive method.
void validate_adaptive(std::string_view method, const StepControl& control);

// Throws std::invalid_argument unless fixed_step is positive and finite.
void validate_fixed(std::string_view method, const StepControl& control);

// Throws std::invalid_argument unless y0 has the system's dimension and t_end differs from t0.
void validate_start(std::string_view method, const OdeSystem& system, double t0, const VecX& y0,
                    double t_end);

}  // namespace tumble::step_control
