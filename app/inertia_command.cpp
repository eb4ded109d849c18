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

// The inertia about a world point O at t = 0 by the parallel axis theorem: I_O = I_G + m (|d|^2 E
// - d d^T), d = r_G - O; in world axes (R I_G_B R^T for I_G) and in body axes.
void print_about(const BodySpec& body, const Vec3& O_W) {
  const MassProperties& mp = body.mass_properties;
  const Vec3 r_G_W = body.position_W + body.R_WB * mp.com;
  const Vec3 d_W = r_G_W - O_W;
  const Mat3 I_O_W = body.R_WB * mp.inertia_about_com * body.R_WB.transpose() +
                     mp.mass * (d_W.squaredNorm() * Mat3::Identity() - d_W * d_W.transpose());
  const Mat3 I_O_B = body.R_WB.transpose() * I_O_W * body.R_WB;
  fmt::print("  inertia about O = [{:.8g} {:.8g} {:.8g}] (world, t=0), world axes (kg m^2)\n",
             O_W.x(), O_W.y(), O_W.z());
  for (int r = 0; r < 3; ++r) print_row("", I_O_W.row(r));
  fmt::print("  inertia about O, body axes (kg m^2)\n");
  for (int r = 0; r < 3; ++r) print_row("", I_O_B.row(r));
  print_row("principal, about O", principal_axes(I_O_B).moments.transpose());
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
    scenario = load_scenario(args.scenario, {}, false);
  } catch (const ScenarioError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInvalidScenario;
  }
  bool found = false;
  for (const BodySpec& body : scenario.bodies) {
    if (!args.body.empty() && body.name != args.body) continue;
    print_body(body);
    if (args.about.size() == 3)
      print_about(body, Vec3(args.about[0], args.about[1], args.about[2]));
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
