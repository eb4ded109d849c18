#include <fmt/core.h>
#include <stdexcept>

#include "commands.hpp"
#include "exit_status.hpp"
#include "tumble/inertia/mass_properties.hpp"

namespace tumble::cli {

namespace {

void print_row(const char* label, const Eigen::RowVector3d& row) {
  fmt::print("  {:<22}[{:>14.8g} {:>14.8g} {:>14.8g}]\n", label, row(0), row(1), row(2));
}

void print_body(const BodySpec& body) {
  const MassProperties& mp = body.mass_properties;
  const PrincipalAxes principal = principal_axes(mp.inertia_about_com);
  fmt::print("{}\n", body.name);
  fmt::print("  {:<22}{:.10g} kg\n", "mass", mp.mass);
  print_row("COM, body frame (m)", mp.com.transpose());
  print_row("COM, world at t=0 (m)", (body.position_W + body.R_WB * mp.com).transpose());
  fmt::print("  inertia about the COM, body axes (kg m^2){}\n",
             body.inertia_overridden ? " [given by inertia:]" : "");
  for (int r = 0; r < 3; ++r) print_row("", mp.inertia_about_com.row(r));
  print_row("principal moments", principal.moments.transpose());
  fmt::print("  principal axes (columns, body axes)\n");
  for (int r = 0; r < 3; ++r) print_row("", principal.axes.row(r));
}

}  // namespace

int inertia_command(const InertiaArguments& args) {
  Scenario scenario;
  try {
    scenario = load_scenario(args.scenario, {});
  } catch (const ScenarioError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInvalidScenario;
  }
  bool found = false;
  for (const BodySpec& body : scenario.bodies) {
    if (!args.body.empty() && body.name != args.body) continue;
    print_body(body);
    found = true;
  }
  if (!found) {
    std::string names;
    for (const BodySpec& body : scenario.bodies) names += (names.empty() ? "" : ", ") + body.name;
    fmt::print(stderr, "tumble inertia: no body '{}' in {}; its bodies are {}\n", args.body,
               args.scenario, names);
    return kBadCommandLine;
  }
  return kDone;
}

}  // namespace tumble::cli
