#include "scenario_run.hpp"

#include <cmath>
#include <utility>

namespace tumble::test {

ScenarioRun run_inline_scenario(const std::string& yaml, const std::string& name) {
  return run_scenario(load_inline_scenario(yaml, name));
}

ScenarioRun run_scenario(Scenario scenario) {
  ScenarioRun run;
  run.scenario = std::move(scenario);
  PreparedSimulation simulation = prepare_simulation(run.scenario);
  run.result = run_simulation(simulation, [&](double t, std::span<const BodyState> states,
                                              const SystemQuantities& q, const RowExtras& e) {
    run.rows.push_back({t, std::vector<BodyState>(states.begin(), states.end()), q, e});
  });
  EXPECT_TRUE(run.result.report.completed) << run.result.report.failure;
  run.jumps = run.result.jumps;
  run.contact_events = run.result.contact_events;
  run.bodies = simulation.formulation->model().bodies;
  run.contacts = simulation.formulation->model().contacts;
  return run;
}

void expect_energy_never_rises(const ScenarioRun& run, double relative) {
  const double E0 = run.rows.front().quantities.total_energy;
  double E_before = E0;
  for (const Row& row : run.rows) {
    EXPECT_LE(row.quantities.total_energy, E_before + relative * std::abs(E0)) << "t " << row.t;
    E_before = row.quantities.total_energy;
  }
}

void expect_rolls_down_from_rest(const ScenarioRun& run, double a, const Vec3& down_W,
                                 const Vec3& axle_W, double rolling_radius, double M) {
  const Vec3 r0 = run.rows.front().states[0].r_G;
  const double E0 = run.rows.front().quantities.total_energy;
  const double spin_rate = a / rolling_radius;
  for (const Row& row : run.rows) {
    const BodyState& s = row.states[0];
    EXPECT_NEAR((s.r_G - r0).dot(down_W), a * row.t * row.t / 2, 1e-10 * a) << "t " << row.t;
    EXPECT_NEAR(s.v_G.dot(down_W), a * row.t, 1e-10 * a) << "t " << row.t;
    EXPECT_NEAR(s.omega_W.dot(axle_W), spin_rate * row.t, 1e-10 * spin_rate) << "t " << row.t;
    EXPECT_NEAR(s.omega_W.cross(axle_W).norm(), 0.0, 1e-10 * spin_rate) << "t " << row.t;
    for (const ContactOutput& contact : row.extras.contacts) EXPECT_EQ(contact.mode, 2) << row.t;
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-10 * M * a * a) << "t " << row.t;
  }
}

std::vector<double> upward_zero_crossings(const std::vector<double>& t,
                                          const std::vector<double>& x,
                                          const std::vector<double>& rate) {
  std::vector<double> crossings;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (!(x[i] < 0.0 && x[i + 1] >= 0.0)) continue;
    const double h = t[i + 1] - t[i];
    const auto hermite = [&](double s) {
      const double s2 = s * s, s3 = s2 * s;
      return (2 * s3 - 3 * s2 + 1) * x[i] + (s3 - 2 * s2 + s) * h * rate[i] +
             (-2 * s3 + 3 * s2) * x[i + 1] + (s3 - s2) * h * rate[i + 1];
    };
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (hermite(mid) < 0.0 ? lo : hi) = mid;
    }
    crossings.push_back(t[i] + 0.5 * (lo + hi) * h);
  }
  return crossings;
}

void expect_error(const std::string& yaml, int line, int column, const std::string& key,
                  const std::string& why) {
  try {
    const Scenario scenario = load_inline_scenario(yaml, "invalid");
    prepare_simulation(scenario);
    ADD_FAILURE() << "no error; expected one about " << key;
  } catch (const ScenarioError& error) {
    EXPECT_EQ(error.where().line, line) << error.what();
    EXPECT_EQ(error.where().column, column) << error.what();
    EXPECT_EQ(error.key(), key) << error.what();
    EXPECT_NE(error.why().find(why), std::string::npos) << error.what();
  }
}

}  // namespace tumble::test
