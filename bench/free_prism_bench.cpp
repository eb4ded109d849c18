// The chapter's tumbling prism integrated to t = 20 s, timed from a warmed-up workspace: each
// tumble method at the tolerance that brings its error at t = 20 below 1e-9 (counter `error`,
// measured against the 40-digit reference), and Boost.Odeint's controlled dopri5 with dense
// output on the very same right-hand side in the same process, so the ratio is side by side.
// Counters: error (max over R and omega_W), steps, evaluations.
#include <benchmark/benchmark.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <memory>

#include "tumble/dynamics/body_frame_formulation.hpp"
#include "tumble/dynamics/textbook_formulation.hpp"
#include "tumble/integrators/driver.hpp"
#include "tumble/simulation/make_formulation.hpp"

namespace tumble {
namespace {

// The reference state at t = 20 (tests/data/free-prism-40digit.json, case "unstable").
const double kOmegaW20[3] = {-0.0034796450061459842, 0.011475293773717123, 0.99998264360266215};
const double kR20[9] = {0.78896496167655365,   0.61439986445431223,  0.0068626383583127594,
                        0.61438013952946379,   -0.78868768983768379, -0.022555975932202559,
                        -0.008445910162370816, 0.022012143399047902, -0.99972202743788181};

double error_at_20(const BodyState& s) {
  double e = 0.0;
  for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(s.omega_W(k) - kOmegaW20[k]));
  for (int k = 0; k < 9; ++k) e = std::max(e, std::abs(s.R_WB(k / 3, k % 3) - kR20[k]));
  return e;
}

Model prism_model() {
  Model model;
  model.gravity_W.setZero();
  model.bodies.push_back(RigidBody::make("prism", 12.0, Vec3(5.0, 20.0, 17.0).asDiagonal()));
  return model;
}

BodyState prism_start() {
  BodyState s;
  s.omega_W = Vec3(0.0, 0.01, 1.0);
  return s;
}

void BM_Tumble(benchmark::State& state, const char* formulation_name, const char* method,
               double rtol) {
  std::unique_ptr<Formulation> system = make_formulation(formulation_name, prism_model());
  StepControl control;
  control.rtol = rtol;
  control.atol = rtol * 1e-3;
  std::unique_ptr<Integrator> integrator = make_integrator(method, control);
  VecX y0(system->dimension());
  const BodyState s0 = prism_start();
  system->pack(std::span<const BodyState>(&s0, 1), y0);
  DriverOptions options;
  options.output_every = 20.0;  // rows at t = 0 and t = 20 only: time the integration
  BodyState last;
  IntegrationReport report;
  for (auto _ : state) {
    report = integrate(*integrator, *system, 0.0, y0, 20.0, options,
                       [&](double, const VecX& y) { last = system->unpack(y, 0); });
    benchmark::DoNotOptimize(last);
  }
  state.counters["error"] = error_at_20(last);
  state.counters["steps"] = static_cast<double>(report.stats.accepted_steps);
  state.counters["evaluations"] = static_cast<double>(report.stats.rhs_evaluations);
}

// Boost.Odeint on the same right-hand side: std::array state, copied into the formulation's
// vector (13 doubles; negligible beside the evaluation itself).
struct OdeintRhs {
  const BodyFrameFormulation* system;
  VecX* y;
  VecX* dydt;
  void operator()(const std::array<double, 13>& x, std::array<double, 13>& dxdt, double t) const {
    std::copy(x.begin(), x.end(), y->data());
    system->derivative(t, *y, *dydt);
    std::copy(dydt->data(), dydt->data() + 13, dxdt.begin());
  }
};

// Boost.Odeint with a controlled, dense-output stepper (dopri5), or a controlled one (Fehlberg
// 7(8), the closest of its methods to dop853), atol = rtol * 1e-3 as tumble's rule.
template <class MakeStepper>
void BM_Odeint(benchmark::State& state, double tolerance, MakeStepper make_stepper) {
  namespace odeint = boost::numeric::odeint;
  const BodyFrameFormulation system(prism_model());
  VecX y(13), dydt(13);
  const BodyState s0 = prism_start();
  VecX y0(13);
  system.pack(std::span<const BodyState>(&s0, 1), y0);
  OdeintRhs rhs{&system, &y, &dydt};
  long evaluations = 0;
  auto counting_rhs = [&](const std::array<double, 13>& x, std::array<double, 13>& dxdt, double t) {
    ++evaluations;
    rhs(x, dxdt, t);
  };
  std::array<double, 13> x;
  std::size_t steps = 0;
  for (auto _ : state) {
    std::copy(y0.data(), y0.data() + 13, x.begin());
    evaluations = 0;
    auto stepper = make_stepper(tolerance * 1e-3, tolerance);
    steps = odeint::integrate_adaptive(stepper, counting_rhs, x, 0.0, 20.0, 0.01);
    benchmark::DoNotOptimize(x);
  }
  std::copy(x.begin(), x.end(), y.data());
  system.project(20.0, y);
  state.counters["error"] = error_at_20(system.unpack(y, 0));
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["evaluations"] = static_cast<double>(evaluations);
}

using State13 = std::array<double, 13>;

void BM_OdeintDopri5(benchmark::State& state, double tolerance) {
  namespace odeint = boost::numeric::odeint;
  BM_Odeint(state, tolerance, [](double atol, double rtol) {
    return odeint::make_dense_output(atol, rtol, odeint::runge_kutta_dopri5<State13>());
  });
}

void BM_OdeintFehlberg78(benchmark::State& state, double tolerance) {
  namespace odeint = boost::numeric::odeint;
  BM_Odeint(state, tolerance, [](double atol, double rtol) {
    return odeint::make_controlled(atol, rtol, odeint::runge_kutta_fehlberg78<State13>());
  });
}

// The chapter's formulation and tolerance, for scale.
BENCHMARK_CAPTURE(BM_Tumble, textbook_dopri5_1e_8, "textbook", "dopri5", 1e-8)
    ->Unit(benchmark::kMicrosecond);
// tumble's production formulation, each method at two tolerances around an error of 1e-9 ... 1e-11.
BENCHMARK_CAPTURE(BM_Tumble, body_dopri5_1e_10, "body", "dopri5", 1e-10)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tumble, body_dopri5_1e_11, "body", "dopri5", 1e-11)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tumble, body_dop853_1e_10, "body", "dop853", 1e-10)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tumble, body_dop853_1e_11, "body", "dop853", 1e-11)
    ->Unit(benchmark::kMicrosecond);
// The peer on the same right-hand side.
BENCHMARK_CAPTURE(BM_OdeintDopri5, rtol_1e_10, 1e-10)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_OdeintDopri5, rtol_1e_11, 1e-11)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_OdeintFehlberg78, rtol_1e_10, 1e-10)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_OdeintFehlberg78, rtol_1e_11, 1e-11)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace tumble
