#include <fmt/core.h>
#include <stdexcept>

#include "commands.hpp"
#include "exit_status.hpp"
#include "tumble/inertia/mass_properties.hpp"

namespace tumble::cli {

namespace {

// Each value to `digits` significant digits, in a column wide enough for them.
void print_row(const char* label, const Eigen::RowVector3d& row, int digits) {
  const int width = digits + 6;
  fmt::print("  {:<22}[{:>{}.{}g} {:>{}.{}g} {:>{}.{}g}]\n", label, row(0), width, digits, row(1),
             width, digits, row(2), width, digits);
}

// The inertia about a world point O at t = 0 by the parallel axis theorem: I_O = I_G + m (|d|^2 E
// - d d^T), d = r_G - O; in world axes (R I_G_B R^T for I_G) and in body axes.
void print_about(const BodySpec& body, const Vec3& O_W, int digits) {
  const MassProperties& mp = body.mass_properties;
  const Vec3 r_G_W = body.position_W + body.R_WB * mp.com;
  const Vec3 d_W = r_G_W - O_W;
  const Mat3 I_O_W = body.R_WB * mp.inertia_about_com * body.R_WB.transpose() +
                     mp.mass * (d_W.squaredNorm() * Mat3::Identity() - d_W * d_W.transpose());
  const Mat3 I_O_B = body.R_WB.transpose() * I_O_W * body.R_WB;
  fmt::print("  inertia about O = [{:.{}g} {:.{}g} {:.{}g}] (world, t=0), world axes (kg m^2)\n",
             O_W.x(), digits, O_W.y(), digits, O_W.z(), digits);
  for (int r = 0; r < 3; ++r) print_row("", I_O_W.row(r), digits);
  fmt::print("  inertia about O, body axes (kg m^2)\n");
  for (int r = 0; r < 3; ++r) print_row("", I_O_B.row(r), digits);
  print_row("principal, about O", principal_axes(I_O_B).moments.transpose(), digits);
}

void print_body(const BodySpec& body, int digits) {
  const MassProperties& mp = body.mass_properties;
  const PrincipalAxes principal = principal_axes(mp.inertia_about_com);
  fmt::print("{}\n", body.name);
  fmt::print("  {:<22}{:.{}g} kg\n", "mass", mp.mass, digits);
  print_row("COM, body frame (m)", mp.com.transpose(), digits);
  print_row("COM, world at t=0 (m)", (body.position_W + body.R_WB * mp.com).transpose(), digits);
  fmt::print("  inertia about the COM, body axes (kg m^2){}\n",
             body.inertia_overridden ? " [given by inertia:]" : "");
  for (int r = 0; r < 3; ++r) print_row("", mp.inertia_about_com.row(r), digits);
  print_row("principal moments", principal.moments.transpose(), digits);
  fmt::print("  principal axes (columns, body axes)\n");
  for (int r = 0; r < 3; ++r) print_row("", principal.axes.row(r), digits);
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
    print_body(body, args.digits);
    if (args.about.size() == 3)
      print_about(body, Vec3(args.about[0], args.about[1], args.about[2]), args.digits);
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
