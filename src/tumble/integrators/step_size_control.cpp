#include "tumble/integrators/step_size_control.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tumble::step_control {

namespace {

[[noreturn]] void fail(std::string_view method, std::string_view what, double value,
                       std::string_view fix) {
  std::ostringstream message;
  message << method << ": " << what << " = " << value << "; " << fix;
  throw std::invalid_argument(message.str());
}

}  // namespace

double max_norm_error(const VecX& error, const VecX& y, const VecX& y_new, const VecX& thresholds) {
  // A NaN anywhere must come out as NaN (std::max would drop it), so the ratio is summed into
  // the result through a comparison that NaN wins.
  double err = 0.0;
  for (Eigen::Index i = 0; i < error.size(); ++i) {
    const double scale = std::max({std::abs(y[i]), std::abs(y_new[i]), thresholds[i]});
    const double ratio = std::abs(error[i]) / scale;
    if (!(ratio <= err)) err = ratio;
  }
  return err;
}

double dop853_error(const VecX& error5, const VecX& error3, const VecX& y, const VecX& y_new,
                    const VecX& atol, double rtol, double h) {
  double sum5 = 0.0;
  double sum3 = 0.0;
  for (Eigen::Index i = 0; i < error5.size(); ++i) {
    const double sk = atol[i] + rtol * std::max(std::abs(y[i]), std::abs(y_new[i]));
    const double e5 = error5[i] / sk;
    const double e3 = error3[i] / sk;
    sum5 += e5 * e5;
    sum3 += e3 * e3;
  }
  double denominator = sum5 + 0.01 * sum3;
  if (denominator <= 0.0) denominator = 1.0;  // both estimates vanish: the step is exact
  return std::abs(h) * sum5 / std::sqrt(static_cast<double>(error5.size()) * denominator);
}

void absolute_tolerances(const OdeSystem& system, const VecX& y0, double atol, VecX& atols) {
  atols.resize(y0.size());
  system.tolerance_units(y0, atols);
  atols *= atol;
}

double spacing(double t) {
  const double a = std::abs(t);
  return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}

double minimum_step(double t) {
  return 16.0 * spacing(t);
}

double ode45_initial_step(const VecX& y0, const VecX& f0, double rtol, const VecX& atol,
                          double h_max, double span, double t0) {
  double h = std::min(h_max, std::abs(span));
  double f_scaled = 0.0;
  for (Eigen::Index i = 0; i < y0.size(); ++i) {
    const double threshold = atol[i] / rtol;
    f_scaled = std::max(f_scaled, std::abs(f0[i]) / std::max(std::abs(y0[i]), threshold));
  }
  const double rh = f_scaled / (0.8 * std::pow(rtol, 0.2));
  if (h * rh > 1.0) h = 1.0 / rh;
  return std::max(h, minimum_step(t0));
}

bool shorten_after_blow_up(double& h_abs, double h_min) {
  if (h_abs <= h_min) return false;
  h_abs = std::max(h_min, 0.1 * h_abs);
  return true;
}

ClippedStep clip_to_stop(double t, double h_abs, double t_stop, double direction, double stretch) {
  const double distance = (t_stop - t) * direction;
  if (stretch * h_abs >= distance) return {distance, t_stop, true};
  return {h_abs, t + direction * h_abs, false};
}

// A grid point this close to t_stop (as a fraction of h) is taken to be t_stop, so no sliver of
// a step is left when t_stop is a multiple of h up to round-off.
constexpr double kLandingSlack = 1e-8;

FixedStepEnd next_fixed_step_end(double t_grid, long grid_steps, double h_abs, double direction,
                                 double t_stop) {
  const double t_next = t_grid + direction * static_cast<double>(grid_steps + 1) * h_abs;
  if ((t_next - t_stop) * direction >= -kLandingSlack * h_abs) return {t_stop, true};
  return {t_next, false};
}

void require_ahead(std::string_view method, double t, double t_stop, double direction) {
  if (!((t_stop - t) * direction > 0.0)) {
    std::ostringstream message;
    message << method << ": step(t_stop = " << t_stop << ") from t = " << t
            << " does not point in the direction of integration; call step only with a stop "
               "time strictly ahead of t()";
    throw std::invalid_argument(message.str());
  }
}

void validate_adaptive(std::string_view method, const StepControl& control) {
  if (!tolerances::rtol_valid(control.rtol)) {
    fail(method, "rtol", control.rtol,
         std::string("use a relative tolerance ") + tolerances::kRtolRule);
  }
  if (!tolerances::atol_valid(control.atol)) {
    fail(method, "atol", control.atol,
         std::string("use an absolute tolerance ") + tolerances::kAtolRule);
  }
  if (!(control.initial_step >= 0.0 && std::isfinite(control.initial_step))) {
    fail(method, "initial_step", control.initial_step,
         "use 0 (chosen automatically) or a positive step in s");
  }
  if (!(control.max_step >= 0.0 && std::isfinite(control.max_step))) {
    fail(method, "max_step", control.max_step, "use 0 (the default bound) or a positive step in s");
  }
}

void validate_fixed(std::string_view method, const StepControl& control) {
  if (!(control.fixed_step > 0.0 && std::isfinite(control.fixed_step))) {
    fail(method, "fixed_step", control.fixed_step,
         "a fixed-step method needs a positive step in s (StepControl::fixed_step)");
  }
}

void validate_start(std::string_view method, const OdeSystem& system, double t0, const VecX& y0,
                    double t_end) {
  if (y0.size() != system.dimension()) {
    std::ostringstream message;
    message << method << ": y0 has " << y0.size() << " components but the system has dimension "
            << system.dimension() << "; pass a state of the system's dimension";
    throw std::invalid_argument(message.str());
  }
  if (!(std::isfinite(t0) && std::isfinite(t_end) && t_end != t0)) {
    std::ostringstream message;
    message << method << ": t0 = " << t0 << ", t_end = " << t_end
            << "; the span must be finite and non-empty (t_end != t0)";
    throw std::invalid_argument(message.str());
  }
}

}  // namespace tumble::step_control
