// tumble: rigid-body dynamics from a scenario file. `tumble run` integrates and writes the
// trajectory and a summary; `tumble sweep` and `tumble find` run it at many parameter values;
// `tumble inertia` prints mass properties; `tumble plot` draws a CSV's columns. The executable's
// main and the Python module's `python3 -m tumble` both call run_cli.
#include <fmt/core.h>
#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "exit_status.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble::cli {
namespace {

// A flag's number, read from the whole of its text as strtod would but without its hex floats and
// leading spaces: nullopt for anything else, an infinity for a number beyond a double's range
// either way (1e999, 1e-999).
std::optional<double> flag_number(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (ptr != end || (error != std::errc() && error != std::errc::result_out_of_range)) {
    return std::nullopt;
  }
  if (error == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  return value;
}

// sweep's and find's --max-steps.
constexpr const char* kMaxStepsHelp =
    "Each run's budget of accepted steps, in place of the scenario's simulate.max_steps: a run "
    "that needs more stops there and fails (sweep: a 'failed' row; find: exit 4, naming the "
    "value)";

// CLI11 takes any double it can read (nan, inf, a width of -1) and wraps an unsigned integer
// (--seed -1 becomes 2^64 - 1): these check the text first, and their message follows the flag's
// name: "--tol: 0 is out of range: expected a finite number > 0 (...)".
CLI::Validator finite_number(const std::string& range, bool positive) {
  return CLI::Validator(
      [range, positive](const std::string& text) {
        const std::optional<double> value = flag_number(text);
        if (!value) return fmt::format("'{}' is not a number: expected {}", text, range);
        if (!std::isfinite(*value) || (positive && !(*value > 0.0))) {
          return fmt::format("{} is out of range: expected {}", text, range);
        }
        return std::string();
      },
      "NUMBER");
}

CLI::Validator seed_value() {
  return CLI::Validator(
      [](const std::string& text) {
        const std::string range =
            fmt::format("a whole number from 0 to {}", std::numeric_limits<std::uint64_t>::max());
        std::uint64_t seed = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, error] = std::from_chars(text.data(), end, seed);
        if (error == std::errc() && ptr == end) return std::string();
        const std::optional<double> value = flag_number(text);
        const bool outside = value && !(*value >= 0.0 && *value < 0x1p64);
        return fmt::format("{} is {}: expected {}", text,
                           outside ? "out of range" : "not a whole number", range);
      },
      "UINT64");
}

// --threads: a whole number from 1 to kMaxSweepThreads, the limit named in the message.
CLI::Validator thread_count() {
  return CLI::Validator(
      [](const std::string& text) {
        int threads = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, error] = std::from_chars(text.data(), end, threads);
        if (error == std::errc() && ptr == end && threads >= 1 && threads <= kMaxSweepThreads) {
          return std::string();
        }
        const std::optional<double> value = flag_number(text);
        const bool whole = value && std::isfinite(*value) && *value == std::floor(*value);
        return fmt::format(
            "{} is {}: expected a whole number from 1 to {} (the limit on a sweep's threads)", text,
            whole ? "out of range" : "not a whole number", kMaxSweepThreads);
      },
      "INT");
}

// Runs a command; running out of memory (std::bad_alloc) or of a system resource such as
// threads (std::system_error) anywhere in it ends the command with a line and exit status 5, not
// an abort.
int run_guarded(const char* command, const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "tumble {}: out of memory\n", command);
  } catch (const std::system_error& e) {
    fmt::print(stderr, "tumble {}: {}\n", command, e.what());
  }
  return kOutputError;
}

}  // namespace

int run_cli(int argc, const char* const* argv) {
  const std::string version = fmt::format("tumble {}", TUMBLE_VERSION);

  CLI::App app{
      "tumble: rigid-body dynamics you can check. Scenario format: docs/scenario.md (files read "
      "have size limits, raised by TUMBLE_MAX_SCENARIO_MIB and TUMBLE_MAX_MESH_MIB: its \"Limits "
      "on input\"). Any command out of memory or threads exits 5.",
      "tumble"};
  app.set_version_flag("--version", version);
  app.require_subcommand(1);

  RunArguments run_args;
  CLI::App* run = app.add_subcommand(
      "run",
      "Integrate a scenario; write its trajectory CSV, its events CSV when it has contact events, "
      "jumps or events of its own (`events:`, located to the integrator's precision; "
      "`stop: true` ends the run there) (with --animate an HTML page that animates it, with "
      "--video an .mp4 or .gif of that page's 3D view) and print a summary (steps, "
      "evaluations, wall time, drift of E and |L|, largest |R^T R - I|, the events).\nExit "
      "status: 0 done, "
      "2 bad command line (also a --resume FILE that is not a whole checkpoint of this scenario "
      "and these --set values, or a trajectory under --out that is not the stopped run's), 3 "
      "invalid scenario (FILE:LINE:COL: KEY: why; a scenario file over 64 MiB or a mesh over 1 "
      "GiB: TUMBLE_MAX_SCENARIO_MIB and TUMBLE_MAX_MESH_MIB raise the limits, "
      "docs/scenario.md), 4 integration failed (the rows so far stay a valid CSV), 5 "
      "output not writable (or the video could not be made: node, Chromium or ffmpeg missing or "
      "failing; no partial video is left), or out of memory or threads.");
  run->set_version_flag("--version", version);
  run->add_option("scenario", run_args.scenario, "Scenario file (YAML)")->required();
  run->add_option("--out", run_args.out_dir, "Directory for the output files (created if missing)")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](const std::string& dir) {
            return dir.empty() ? std::string(
                                     "an empty path names no directory (use . for this "
                                     "one)")
                               : std::string();
          },
          "DIR"));
  run->add_option("--set", run_args.sets,
                  "Override a parameter: NAME=VALUE (VALUE may be an expression); repeatable");
  run->add_flag("--animate", run_args.animate,
                "Also write the animation page: one self-contained HTML file (3D view of the "
                "bodies, plots of omega, E, |L| and output.plots' columns, the events marked) "
                "named like the trajectory with .html, or output.animation");
  CLI::Option* video =
      run->add_option("--video", run_args.video,
                      "Also write a video of the page's 3D view, with the name and the time: "
                      "PATH.mp4 (H.264) or PATH.gif (from the current directory, not under --out), "
                      "drawn by headless Chromium and encoded by ffmpeg (docs/video.md)");
  run->add_option("--video-size", run_args.video_size,
                  "The video's WIDTHxHEIGHT in pixels, 16 to 8192 each (even for .mp4)")
      ->capture_default_str()
      ->needs(video);
  run->add_option("--video-fps", run_args.video_fps, "Frames per second of the video")
      ->check(CLI::Range(1, 240))
      ->capture_default_str()
      ->needs(video);
  run->add_option("--video-speed", run_args.video_speed,
                  "Simulation seconds per second of video (2: twice as fast as real time)")
      ->capture_default_str()
      ->needs(video);
  run->add_option("--digits", run_args.digits,
                  "Significant digits of the summary's values (energies, works, a jump's KE, "
                  "L and reaction impulses), 1 to 17 (17: every double exactly)")
      ->check(CLI::Range(1, 17))
      ->capture_default_str();
  CLI::Option* stop_at =
      run->add_option("--stop-at", run_args.stop_at,
                      "Stop the run at the end of its first step at or after T seconds (the "
                      "summary says when) and save its state to --save-state's FILE")
          ->check(CLI::Validator(
              [](const std::string& text) {
                double t = 0.0;
                return CLI::detail::lexical_cast(text, t) && std::isfinite(t)
                           ? std::string()
                           : std::string("--stop-at: a time in seconds, not '" + text + "'");
              },
              "T"));
  CLI::Option* save_state =
      run->add_option("--save-state", run_args.save_state,
                      "Where --stop-at saves the run's state: a text file of every number the "
                      "run needs to go on exactly (docs/checkpoints.md)");
  stop_at->needs(save_state);
  save_state->needs(stop_at);
  run->add_option("--resume", run_args.resume,
                  "Go on from the state a --stop-at run saved in FILE (the same scenario and "
                  "--set values): the rows after it are exactly the rows of the run that never "
                  "stopped; in the stopped run's --out, its trajectory goes on, else the new "
                  "trajectory has the rows after the stop")
      ->check(CLI::ExistingFile);

  InertiaArguments inertia_args;
  CLI::App* inertia = app.add_subcommand(
      "inertia",
      "Print each body's mass, COM, inertia about the COM, principal moments and axes (and with\n"
      "--about, its inertia about that point). The scenario needs no simulate: section.\nExit "
      "status: 0 done, 2 bad command line (or no such body), 3 invalid scenario, 5 out of "
      "memory.");
  inertia->set_version_flag("--version", version);
  inertia->add_option("scenario", inertia_args.scenario, "Scenario file (YAML)")->required();
  inertia->add_option("body", inertia_args.body, "Only this body");
  inertia
      ->add_option("--about", inertia_args.about,
                   "X Y Z: also the inertia about this world point at t = 0 (a pivot O, m): "
                   "I_O = I_G + m (|d|^2 E - d d^T), d from O to the COM (parallel axis "
                   "theorem), in world and body axes, with its principal moments; each a "
                   "finite number")
      ->expected(3)
      ->check(finite_number("a finite number (m, world)", false));
  inertia
      ->add_option("--digits", inertia_args.digits,
                   "Significant digits of the values, 1 to 17 (17: every double exactly)")
      ->check(CLI::Range(1, 17))
      ->capture_default_str();

  SweepArguments sweep_args;
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Run the scenario at every point of a grid of its parameters (or at seeded random points), "
      "on every core, and under mpirun on every process; write DIR/sweep.csv, one row per run "
      "in a fixed order (the same bytes whatever the thread or process count): the run's number, "
      "its parameter values, status (ok, failed, invalid), accepted steps, E and |L| drift, the "
      "recorded values and, for a run that did not finish, its message (docs/sweeps.md).\nExit "
      "status: 0 done (runs that failed are rows), 2 bad command line (an unknown parameter, an "
      "empty range, a malformed record, --threads over 256), 3 invalid scenario (a scenario file "
      "over 64 MiB: TUMBLE_MAX_SCENARIO_MIB raises the limit), 5 output not writable (--out is "
      "checked before the first run) or out of memory or threads.");
  sweep->set_version_flag("--version", version);
  sweep->add_option("scenario", sweep_args.scenario, "Scenario file (YAML)")->required();
  sweep
      ->add_option("--vary", sweep_args.vary,
                   "NAME=START:STOP:COUNT: COUNT values of parameter NAME from START to STOP "
                   "(numbers or expressions such as pi/4, 30 deg); with --random, NAME=LO:HI; "
                   "repeatable (a grid: the first varies slowest)")
      ->required();
  sweep
      ->add_option("--random", sweep_args.random,
                   "Instead of the grid, this many points drawn uniformly between the bounds")
      ->check(CLI::Range(1L, 10'000'000L));
  sweep
      ->add_option("--seed", sweep_args.seed,
                   "Seed of the random points: a whole number from 0 to 2^64 - 1")
      ->check(seed_value())
      ->capture_default_str();
  sweep->add_option(
      "--record", sweep_args.record,
      "NAME=REDUCTION: a column of sweep.csv. REDUCTION is an expression over "
      "final(X), max(X), min(X), mean(X), time_of_max(X) (X a column or an "
      "expression of columns and parameters), first(EVENT), count(EVENT) (EVENT: "
      "CONTACT.KIND, event.NAME, impulse.NAME, lock.NAME, motor.NAME), first(CONDITION), "
      "count(CONDITION) (CONDITION: a comparison of columns, e.g. prism.w3 < 0), each of one "
      "argument; jump(JUMP, FIELD) (JUMP: impulse.NAME, lock.NAME, motor.NAME; FIELD: KE_before, "
      "KE_after or a joint's reaction impulse JOINT.Fx ... JOINT.Mz); after(EVENT, X): X just "
      "after EVENT's first occurrence (e.g. after(floor.rolls, disk.vx)); and what tumble modes "
      "says of the initial state: modes.stable, modes.unstable, modes.growth_rate, "
      "modes.frequency. Expressions only read: = (assignment) is refused, == compares; "
      "repeatable");
  sweep->add_option("--set", sweep_args.sets, "Fix a parameter for every run: NAME=VALUE");
  sweep
      ->add_option("--threads", sweep_args.threads,
                   fmt::format("Threads, 1 to {} (default: every core, at most {})",
                               kMaxSweepThreads, kMaxSweepThreads))
      ->check(thread_count());
  sweep->add_option("--max-steps", sweep_args.max_steps, kMaxStepsHelp)
      ->check(CLI::Range(1L, 1'000'000'000L));
  sweep->add_option("--out", sweep_args.out_dir, "Directory for sweep.csv (created if missing)")
      ->capture_default_str();
  sweep->add_flag("--resume", sweep_args.resume,
                  "Go on from DIR/sweep.csv as a stopped sweep of the same scenario, --vary, "
                  "--random, --seed and --record left it: its rows are kept, the rest are run "
                  "(a file of another sweep is refused, exit 2)");

  FindArguments find_args;
  CLI::App* find = app.add_subcommand(
      "find",
      "Find the value of one parameter at which a yes/no outcome of the run changes (a critical "
      "friction, speed or stiffness), by bisection to --tol, and print the bracket and the runs "
      "it took (docs/sweeps.md).\nExit status: 0 found, 2 bad command line (an unknown "
      "parameter, an empty range, a malformed condition, or the same outcome at both ends), 3 "
      "invalid scenario, 4 a run failed, 5 out of memory or threads.");
  find->set_version_flag("--version", version);
  find->add_option("scenario", find_args.scenario, "Scenario file (YAML)")->required();
  find->add_option("--vary", find_args.vary,
                   "NAME=LO:HI: the parameter and the range to search (the outcome must differ "
                   "at LO and HI)")
      ->required();
  find->add_option("--when", find_args.when,
                   "The condition, an expression of reductions as for sweep --record (read-only: "
                   "= is refused), true where not 0: e.g. \"max(frame.angle) > pi/4\", or "
                   "modes.stable (no run: the linearisation's verdict)")
      ->required();
  find->add_option("--tol", find_args.tol,
                   "Width of the final bracket, a finite number > 0 in the parameter's units "
                   "(default 1e-9 of the larger bound's magnitude)")
      ->check(finite_number("a finite number > 0 (the final bracket's width)", true));
  find->add_option("--set", find_args.sets, "Fix a parameter: NAME=VALUE");
  find->add_option("--max-steps", find_args.max_steps, kMaxStepsHelp)
      ->check(CLI::Range(1L, 1'000'000'000L));

  ModesArguments modes_args;
  CLI::App* modes = app.add_subcommand(
      "modes",
      "Linearise the equations of motion about the scenario's initial state (an equilibrium, or "
      "a steady motion: a spin about a principal axis, a steady precession, a wheel rolling) in "
      "the joints' coordinates, reduced by the contacts that touch (rolling, sticking or "
      "frictionless), by automatic differentiation, and print its modes: eigenvalues, natural "
      "frequencies (rad/s, Hz), periods, damping ratios, growth rates, mode shapes by "
      "coordinate, and a verdict (stable, marginal, unstable and which mode). Writes "
      "STEM_modes.csv beside where the trajectory would go (docs/modes.md).\nExit status: 0 "
      "done, 2 bad command line, 3 invalid scenario, 5 output not writable, 6 the initial state "
      "is neither an equilibrium nor a steady motion (the message says which rate is off and by "
      "how much), or a contact it cannot linearise (resting on an edge, a face or a line; "
      "sliding with friction; lifting off; touching without pressing; two bodies touching along a "
      "line or a circle, or a sphere over a seam of the other's surface: a box's edge, a rim).");
  modes->set_version_flag("--version", version);
  modes->add_option("scenario", modes_args.scenario, "Scenario file (YAML)")->required();
  modes->add_option("--out", modes_args.out_dir, "Directory for the output files")
      ->capture_default_str();
  modes->add_option("--set", modes_args.sets, "Override a parameter: NAME=VALUE; repeatable");
  modes->add_flag("--animate", modes_args.animate,
                  "Also write STEM_modes.html, the animation page with each mode shape moving "
                  "in turn (three cycles each) about the initial configuration");

  PlotArguments plot_args;
  CLI::App* plot = app.add_subcommand(
      "plot",
      "Plot columns of a CSV (a trajectory, or a sweep.csv) against t or another column into a PNG "
      "or SVG, with "
      "gnuplot (docs/plotting.md). The figure appears only when complete.\nExit status: 0 done, "
      "2 bad command line (unreadable CSV, no such column, not .png/.svg), 5 output could not be "
      "produced (gnuplot missing or failed, output not writable).");
  plot->set_version_flag("--version", version);
  plot->add_option("csv", plot_args.csv, "CSV file with a header row")->required();
  plot->add_option("--columns", plot_args.columns, "Columns to plot, by name: A,B,...")
      ->required()
      ->delimiter(',')
      ->allow_extra_args(false);  // one argument each time: `--columns A,B CSV` leaves CSV
  plot->add_option("-x,--x-column", plot_args.x_column, "Column on the x axis")
      ->capture_default_str();
  plot->add_option("-o,--output", plot_args.output, "Figure to write: a .png or .svg file")
      ->required();
  plot->add_option("--title", plot_args.title, "Title above the plot");
  plot->add_option("--width", plot_args.width, "Width in pixels")
      ->check(CLI::Range(16, 20000))
      ->capture_default_str();
  plot->add_option("--height", plot_args.height, "Height in pixels")
      ->check(CLI::Range(16, 20000))
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadCommandLine;
  }
  if (run->parsed()) return run_guarded("run", [&] { return run_command(run_args); });
  if (plot->parsed()) return run_guarded("plot", [&] { return plot_command(plot_args); });
  if (sweep->parsed()) return run_guarded("sweep", [&] { return sweep_command(sweep_args); });
  if (find->parsed()) return run_guarded("find", [&] { return find_command(find_args); });
  if (modes->parsed()) return run_guarded("modes", [&] { return modes_command(modes_args); });
  return run_guarded("inertia", [&] { return inertia_command(inertia_args); });
}

}  // namespace tumble::cli
