// `simulate:` (how long, by which method, to what tolerance) and `output:` (where the trajectory
// and the animation page go). Defaults live in SimulateSpec and OutputSpec.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

const std::vector<std::string> kIntegrators = {"dopri5", "dop853", "rk4",  "rkmk4",
                                               "radau5", "trbdf2", "auto", "exact"};
const std::vector<std::string> kFormulations = {"body", "textbook"};

std::string read_choice(const Reader& reader, const Field& field,
                        const std::vector<std::string>& choices, std::string_view what) {
  const std::string value = reader.text(field);
  if (std::find(choices.begin(), choices.end(), value) != choices.end()) return value;
  std::string why = fmt::format("unknown {} '{}'", what, value);
  if (const auto match = closest_match(value, choices)) why += "; did you mean '" + *match + "'?";
  reader.fail_at_value(field, why + fmt::format(" (the {}s are {})", what, join(choices)));
}

// A number that must satisfy `ok`; `rule` is the condition as the message states it.
double checked(const Reader& reader, const Field& field, bool (*ok)(double),
               std::string_view rule) {
  const double value = reader.number(field);
  if (!ok(value)) {
    reader.fail_at_value(
        field, fmt::format("{} must be {}, got {}", field.key(), rule, format_number(value)));
  }
  return value;
}

bool positive(double x) {
  return x > 0.0;
}
bool non_negative(double x) {
  return x >= 0.0;
}
bool valid_rtol(double x) {
  return tolerances::rtol_asked_valid(x);
}
bool valid_atol(double x) {
  return tolerances::atol_valid(x);
}

}  // namespace

SimulateSpec read_simulate(const Reader& reader, const Field& field, bool has_forces,
                           bool has_system, int format_version) {
  SimulateSpec sim;
  if (format_version >= 2) sim.integrator = "auto";
  const MapReader map(reader, field, "the run's settings {duration: s, integrator: ..., ...}");
  map.allow_only({"duration", "integrator", "formulation", "rtol", "atol", "step", "max_step",
                  "initial_step", "output_every", "max_steps", "max_rows"},
                 "simulate");
  sim.where = reader.location(field.key_mark);
  sim.duration =
      checked(reader, map.require("duration", "the time to simulate, s, > 0"), positive, "> 0 (s)");
  std::optional<Field> integrator = map.find("integrator");
  if (integrator) {
    sim.integrator = read_choice(reader, *integrator, kIntegrators, "integrator");
    sim.where = reader.location(integrator->value_mark());
  }
  if (const auto f = map.find("formulation")) {
    sim.formulation = read_choice(reader, *f, kFormulations, "formulation");
    if (sim.formulation == "textbook" && has_system) {
      reader.fail_at_value(
          *f,
          "the textbook formulation integrates free bodies (the chapter's "
          "[R; omega]); joints, springs, impulses and contacts need formulation: body");
    }
  }
  if (const auto f = map.find("rtol")) {
    sim.rtol = checked(reader, *f, valid_rtol, tolerances::kRtolAskedRule);
    sim.rtol_given = true;
    if (sim.rtol < tolerances::kMinRtol) {
      reader.warn(*f, fmt::format("rtol {:g} is below what round-off allows (100 eps = {:.7g}: "
                                  "below it each step's error estimate is round-off, and the "
                                  "steps shrink without end); raised to {:.7g}",
                                  sim.rtol, tolerances::kMinRtol, tolerances::kMinRtol));
      sim.rtol = tolerances::kMinRtol;
    }
  }
  if (const auto f = map.find("atol")) {
    sim.atol = checked(reader, *f, valid_atol, tolerances::kAtolRule);
    sim.atol_given = true;
  } else if (sim.rtol_given) {
    sim.atol = sim.rtol * tolerances::kAtolPerRtol;
  }
  const std::optional<Field> step = map.find("step");
  if (step) sim.step = checked(reader, *step, positive, "> 0 (s)");
  if (const auto f = map.find("max_step")) {
    sim.max_step = checked(reader, *f, non_negative, ">= 0 (s; 0 = a tenth of the duration)");
  }
  if (const auto f = map.find("initial_step")) {
    sim.initial_step = checked(reader, *f, non_negative, ">= 0 (s; 0 = chosen automatically)");
  }
  if (const auto f = map.find("output_every")) {
    sim.output_every = checked(reader, *f, non_negative, ">= 0 (s; 0 = every accepted step)");
  }
  const auto whole = [&](const Field& f) {
    const double n = reader.number(f);
    if (!(n >= 1.0) || n != std::floor(n) || n > 1e15) {
      reader.fail_at_value(
          f, fmt::format("{} must be a whole number > 0, got {}", f.key(), format_number(n)));
    }
    return static_cast<long>(n);
  };
  if (const auto f = map.find("max_steps")) sim.max_steps = whole(*f);
  if (const auto f = map.find("max_rows")) sim.max_rows = whole(*f);

  const bool fixed_step = sim.integrator == "rk4" || sim.integrator == "rkmk4";
  if (fixed_step && !step) {
    reader.fail(integrator->value_mark(), integrator->path,
                sim.integrator +
                    " takes a fixed step: give simulate.step (s, > 0), e.g. "
                    "step: 0.001, or choose dopri5 to adapt the step");
  }
  // Bounded work and output, refused before the run rather than found out by a full disk: a
  // fixed step's count is known, and so is the number of rows at a fixed output interval (the
  // driver also stops a run whose rows, one per adaptive step, pass max_rows).
  if (fixed_step) {
    const double steps = std::ceil(sim.duration / sim.step);
    if (steps > static_cast<double>(sim.max_steps)) {
      reader.fail_at_value(*step, fmt::format("duration / step is {:.3g} steps, more than "
                                              "simulate.max_steps = {}: take a longer step, or "
                                              "raise max_steps on purpose",
                                              steps, sim.max_steps));
    }
  }
  if (sim.output_every > 0.0) {
    const double rows = std::floor(sim.duration / sim.output_every) + 2.0;
    if (rows > static_cast<double>(sim.max_rows)) {
      reader.fail_at_value(
          *map.find("output_every"),
          fmt::format("duration / output_every is about {:.3g} rows, more than "
                      "simulate.max_rows = {}: write less often (output_every: "
                      "{:.3g} gives {} rows), or raise max_rows on purpose",
                      rows, sim.max_rows, sim.duration / static_cast<double>(sim.max_rows - 2),
                      sim.max_rows));
    }
  } else if (fixed_step) {
    const double rows = std::ceil(sim.duration / sim.step) + 1.0;
    if (rows > static_cast<double>(sim.max_rows)) {
      reader.fail_at_value(*step, fmt::format("one row per step is {:.3g} rows, more than "
                                              "simulate.max_rows = {}: give output_every, or raise "
                                              "max_rows on purpose",
                                              rows, sim.max_rows));
    }
  }
  if (sim.integrator == "exact" && has_forces) {
    reader.fail_at_value(*integrator,
                         "exact is for torque-free free bodies; remove forces and joints or choose "
                         "dopri5");
  }
  return sim;
}

namespace {

// A path relative to the output directory: not empty, not absolute, not through "..".
std::string read_relative_path(const Reader& reader, const Field& field, std::string_view example) {
  const std::string text = reader.text(field);
  const std::filesystem::path path(text);
  if (text.empty()) {
    reader.fail_at_value(field, fmt::format("empty path; give a file name such as {}", example));
  }
  if (path.has_root_path()) {
    reader.fail_at_value(field, "'" + text +
                                    "' is an absolute path; give a path relative to the "
                                    "output directory (choose that with --out)");
  }
  for (const auto& part : path) {
    if (part == "..") {
      reader.fail_at_value(field, "'" + text +
                                      "' leaves the output directory through '..'; give "
                                      "a path inside it (choose the directory with --out)");
    }
  }
  return text;
}

}  // namespace

OutputSpec read_output(const Reader& reader, const std::optional<Field>& field,
                       const std::string& file_stem) {
  OutputSpec output;
  output.trajectory = file_stem + ".csv";
  output.events = file_stem + "_events.csv";
  if (!field) return output;
  const MapReader map(reader, *field,
                      "the output's settings {trajectory: file.csv, animation: file.html, "
                      "events: file.csv, plots: [[COLUMN, ...], ...]}");
  map.allow_only({"trajectory", "animation", "events", "plots"}, "output");
  if (const auto f = map.find("plots")) {
    output.plots_given = true;
    const char* form =
        "of plots, each a column or a list of columns (e.g. [disk.speed, "
        "[floor.slip, floor.N]])";
    for (const Field& item : reader.items(*f, form)) {
      PlotSpec plot;
      const auto add = [&](const Field& column) {
        if (!column.node.IsScalar()) {
          reader.fail_at_value(column,
                               "expected a column's name (a trajectory CSV header, "
                               "e.g. disk.speed)");
        }
        plot.columns.push_back(reader.text(column));
        plot.keys.push_back(column.path);
        plot.where.push_back(reader.location(column.value_mark()));
      };
      if (item.node.IsSequence()) {
        for (const Field& column : reader.items(item, "of columns")) add(column);
        if (plot.columns.empty()) reader.fail_at_value(item, "a plot needs a column at least");
      } else {
        add(item);
      }
      output.plots.push_back(std::move(plot));
    }
  }
  if (const auto f = map.find("trajectory")) {
    output.trajectory = read_relative_path(reader, *f, "run.csv");
    output.trajectory_where = reader.location(f->value_mark());
  }
  if (const auto f = map.find("animation")) {
    output.animation = read_relative_path(reader, *f, "run.html");
    output.animation_where = reader.location(f->value_mark());
    // One file each: the page would replace the trajectory, and the run would lose it.
    if (std::filesystem::path(output.animation).lexically_normal() ==
        std::filesystem::path(output.trajectory).lexically_normal()) {
      reader.fail_at_value(*f, "'" + output.animation +
                                   "' is output.trajectory too: the page would overwrite the "
                                   "trajectory; give each its own file (e.g. run.csv and "
                                   "run.html)");
    }
  }
  if (const auto f = map.find("events"); !f) {
    // The default beside a trajectory that took its name: the trajectory's own name + _events.
    if (std::filesystem::path(output.events).lexically_normal() ==
        std::filesystem::path(output.trajectory).lexically_normal()) {
      output.events =
          std::filesystem::path(output.trajectory).replace_extension().string() + "_events.csv";
    }
  } else {
    output.events = read_relative_path(reader, *f, "run_events.csv");
    output.events_given = true;
    output.events_where = reader.location(f->value_mark());
    const std::filesystem::path events = std::filesystem::path(output.events).lexically_normal();
    for (const std::string* other : {&output.trajectory, &output.animation}) {
      if (events == std::filesystem::path(*other).lexically_normal()) {
        reader.fail_at_value(*f, "'" + output.events +
                                     "' is another output's file too; give the events their "
                                     "own (e.g. run_events.csv)");
      }
    }
  }
  return output;
}

}  // namespace tumble::scenario_reading
