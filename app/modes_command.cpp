// tumble modes: the linearisation about the scenario's initial state and its modes
// (src/tumble/modes/, docs/modes.md).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "commands.hpp"
#include "exit_status.hpp"
#include "tumble/modes/mode_shape_rows.hpp"
#include "tumble/modes/scenario_modes.hpp"
#include "tumble/output/atomic_file.hpp"

namespace tumble::cli {

namespace {

std::string number(double x) {
  return fmt::format("{:.10g}", x);
}

void print_summary(const Scenario& scenario, const ScenarioModes& modes) {
  const Linearisation& lin = modes.linearisation;
  fmt::print("tumble modes: {}\n", scenario.name.empty() ? scenario.file : scenario.name);
  if (lin.equilibrium()) {
    fmt::print("about: an equilibrium (largest rate left {:.3g})\n", lin.largest_rate);
  } else {
    fmt::print("about: a steady motion (largest rate left {:.3g}):\n", lin.largest_rate);
    for (std::size_t i = 0; i < lin.symmetries.size(); ++i) {
      fmt::print("  {} at {} rad/s\n", lin.symmetries[i].description,
                 number(lin.symmetry_rates(static_cast<Eigen::Index>(i))));
    }
    for (const DriftingCoordinate& c : lin.drifting) {
      fmt::print("  {} (ignorable) moving at {} {}/s\n", c.name, number(c.rate), c.unit);
    }
  }
  for (const Symmetry& symmetry : lin.neutral_symmetries) {
    fmt::print("  neutral family taken out: {} (the motion carried over unchanged)\n",
               symmetry.description);
  }
  for (const ModalContact& held : modes.equations->contacts()) {
    const PlaneContact& contact = modes.equations->model().model.contacts[held.contact];
    fmt::print("contact {}: {}\n", contact.name,
               held.rolls  ? "rolling or sticking (its point held, friction within the cone)"
               : held.pair ? "frictionless (its point kept on the other's surface)"
                           : "frictionless (its point kept on the plane)");
  }
  std::string names;
  for (const ModalCoordinate& c : lin.coordinates) {
    names += fmt::format("{}{} [{}]", names.empty() ? "" : ", ", c.name, c.unit);
  }
  fmt::print("coordinates: {}\n", names);
  if (!lin.ignorable.empty()) {
    std::string set_aside;
    for (const std::string& name : lin.ignorable) {
      set_aside += (set_aside.empty() ? "" : ", ") + name;
    }
    fmt::print("ignorable (nothing depends on them): {}\n", set_aside);
  }
  fmt::print("linearised by automatic differentiation: exact derivatives, to round-off\n");
  fmt::print("{:>4}  {:<19} {:>19} {:>19} {:>14} {:>12} {:>12} {:>10} {:>14}\n", "mode", "kind",
             "Re lambda (1/s)", "Im lambda (rad/s)", "omega_n rad/s", "f (Hz)", "period (s)",
             "zeta", "growth (1/s)");
  for (std::size_t i = 0; i < modes.analysis.modes.size(); ++i) {
    const Mode& m = modes.analysis.modes[i];
    const bool oscillates = m.damped_frequency > 0.0;
    const std::string kind = m.kind == Mode::Kind::DecayingTwin
                                 ? fmt::format("{} of {}", kind_name(m.kind), m.twin_of + 1)
                                 : kind_name(m.kind);
    fmt::print(
        "{:>4}  {:<19} {:>19} {:>19} {:>14} {:>12} {:>12} {:>10} {:>14}\n", i + 1, kind,
        number(m.eigenvalue.real()), oscillates ? "+-" + number(m.eigenvalue.imag()) : number(0.0),
        number(m.natural_frequency), oscillates ? fmt::format("{:.6g}", m.frequency_hz()) : "-",
        oscillates ? fmt::format("{:.6g}", m.period()) : "-",
        m.natural_frequency > 0.0 && !std::isnan(m.damping_ratio)
            ? fmt::format("{:.4g}", m.damping_ratio)
            : "-",
        number(m.growth_rate));
  }
  fmt::print("shapes (amplitude, phase in degrees; the largest position 1):\n");
  for (std::size_t i = 0; i < modes.analysis.modes.size(); ++i) {
    const Mode& m = modes.analysis.modes[i];
    std::string shape;
    for (Eigen::Index j = 0; j < m.shape.size(); ++j) {
      const double a = std::abs(m.shape(j));
      if (a < 1e-6) continue;
      const double phase = std::arg(m.shape(j)) * 180.0 / std::numbers::pi;
      shape += fmt::format("{}{} {:.6g}", shape.empty() ? "" : ", ",
                           lin.coordinates[static_cast<std::size_t>(j)].name, a);
      if (std::abs(phase) > 1e-6) shape += fmt::format(" ({:.1f})", phase);
    }
    fmt::print("{:>4}  {}\n", i + 1, shape.empty() ? "-" : shape);
  }
  fmt::print("verdict: {}\n", modes.analysis.verdict_text);
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  AtomicFile file(path);
  file.write(text);
  file.finish();
}

}  // namespace

int modes_command(const ModesArguments& args) {
  int status = kDone;
  std::optional<Scenario> loaded = load_scenario_for("modes", args.scenario, args.sets, status);
  if (!loaded) return status;
  Scenario& scenario = *loaded;
  ScenarioModes modes;
  try {
    modes = modes_of_scenario(scenario);
  } catch (const ScenarioError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInvalidScenario;
  } catch (const NotSteady& e) {
    fmt::print(stderr, "{}: {}\n", scenario.file, e.what());
    return kNoLinearisation;
  }
  std::filesystem::path stem = std::filesystem::path(args.out_dir) / scenario.output.trajectory;
  stem.replace_extension();
  const std::filesystem::path csv = stem.string() + "_modes.csv";
  std::string wrote = csv.string();  // the summary's last line: what was written
  try {
    std::filesystem::create_directories(csv.parent_path());
    write_file(csv, modes_csv(modes));
    if (args.animate) {
      const AnimationScene scene = make_animation_scene(scenario);
      double size = 0.0;
      for (const AnimationBody& body : scene.bodies) size = std::max(size, body.extent);
      std::vector<ShownMode> shown;
      const RecordedTrajectory rows = mode_shape_rows(modes, std::max(size, 1e-3), shown);
      if (rows.rows() > 0) {
        const std::filesystem::path page = stem.string() + "_modes.html";
        // Each mode's start is marked on the plots, as a run's events are.
        std::vector<AnimationEvent> starts;
        std::string when;
        for (const ShownMode& s : shown) {
          starts.push_back({s.start, fmt::format("mode {}", s.mode + 1)});
          when += fmt::format("{}mode {} from t = {:.4g} s", when.empty() ? "" : ", ", s.mode + 1,
                              s.start);
        }
        write_animation_html(page, scene, rows, starts);
        wrote += fmt::format(" and {} ({})", page.string(), when);
      }
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "tumble modes: {}\n", e.what());
    return kOutputError;
  }
  print_summary(scenario, modes);
  fmt::print("wrote {}\n", wrote);
  return kDone;
}

}  // namespace tumble::cli
