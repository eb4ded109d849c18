#pragma once
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "tumble/scenario/scenario.hpp"

namespace tumble::cli {

struct RunArguments {
  std::string scenario;
  std::string out_dir = ".";
  std::vector<std::string> sets;        // NAME=VALUE
  bool animate = false;                 // also write the animation page (output.animation does too)
  std::string video;                    // empty: no video; else .mp4 or .gif (docs/video.md)
  std::string video_size = "1280x720";  // WIDTHxHEIGHT, pixels
  int video_fps = 30;                   // frames per second of video
  double video_speed = 1.0;             // simulation seconds per second of video
  int digits = 10;                      // significant digits of the summary's values (1 to 17)
  // A checkpoint (docs/checkpoints.md): stop at the first step end at or after stop_at (s) and
  // save the state to save_state; go on from the state saved in resume.
  double stop_at = std::numeric_limits<double>::infinity();  // s; infinity: no --stop-at
  std::string save_state;
  std::string resume;
};

struct InertiaArguments {
  std::string scenario;
  std::string body;           // empty: every body
  std::vector<double> about;  // a world point at t = 0 (3 numbers), or empty
  int digits = 10;            // significant digits of the values (1 to 17)
};

// tumble modes: the linearisation about the initial state (docs/modes.md).
struct ModesArguments {
  std::string scenario;
  std::string out_dir = ".";
  std::vector<std::string> sets;  // NAME=VALUE
  bool animate = false;           // also the page where each mode shape moves
};

// tumble plot: columns of a CSV against another, drawn by gnuplot (docs/plotting.md).
struct PlotArguments {
  std::string csv;
  std::vector<std::string> columns;  // y columns, by header name
  std::string x_column = "t";
  std::string output;  // .png or .svg
  std::string title;   // empty: none
  int width = 800;     // pixels
  int height = 500;    // pixels
};

// tumble sweep: runs at every point of a grid (or at random points) of the parameters.
struct SweepArguments {
  std::string scenario;
  std::vector<std::string> sets;    // NAME=VALUE, fixed for every run
  std::vector<std::string> vary;    // NAME=START:STOP:COUNT, or NAME=LO:HI with --random
  long random = 0;                  // 0: the grid; else this many random points
  std::uint64_t seed = 1;           // of the random points
  std::vector<std::string> record;  // NAME=REDUCTION
  int threads = 0;                  // 0: every core (shared among mpirun's processes on it)
  std::string out_dir = ".";
  bool resume = false;  // keep the rows a stopped sweep of the same points wrote, run the rest
  long max_steps = 0;   // > 0: each run's budget of accepted steps (SweepSpec::max_steps)
};

// tumble find: where a yes/no outcome changes along one parameter.
struct FindArguments {
  std::string scenario;
  std::vector<std::string> sets;
  std::string vary;    // NAME=LO:HI
  std::string when;    // the condition
  double tol = 0.0;    // 0: 1e-9 of the larger bound's magnitude
  long max_steps = 0;  // > 0: each run's budget of accepted steps (SweepSpec::max_steps)
};

// The whole command line: parses argv (argv[0] the program) and runs the subcommand; returns the
// exit status (exit_status.hpp).
int run_cli(int argc, const char* const* argv);

int run_command(const RunArguments& args);
int sweep_command(const SweepArguments& args);
int find_command(const FindArguments& args);
int inertia_command(const InertiaArguments& args);
int plot_command(const PlotArguments& args);
int modes_command(const ModesArguments& args);

// The scenario with its overrides, or the exit status after the message on stderr (3 for the
// scenario's FILE:LINE:COL: KEY: why, 2 for a malformed override, prefixed "tumble COMMAND: ").
std::optional<Scenario> load_scenario_for(const char* command, const std::string& path,
                                          const std::vector<std::string>& sets, int& status);

// Splits each NAME=VALUE; throws std::invalid_argument for a malformed one.
std::vector<ParameterOverride> parse_overrides(const std::vector<std::string>& sets);

}  // namespace tumble::cli
