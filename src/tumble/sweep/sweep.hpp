#pragma once
// Many runs of one scenario at other parameter values: the runs of `tumble sweep` and
// `tumble find`. Each thread reads the scenario from a document it parsed once (reading a parsed
// document costs microseconds; parsing, a fifth of a millisecond), builds that run's model and
// records the outcomes as the rows go by. Where the varied parameters reach only the bodies'
// initial velocities, the threads run one model and each run computes only its initial state. A
// run's result depends on its parameter values alone, never on the thread or process it ran on,
// so a sweep's rows are the same bytes however it is shared out.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/outcome.hpp"

namespace tumble {

class RunRecorder;
class VelocityOnlyRuns;

enum class RunStatus {
  Ok,       // ran to the end
  Failed,   // the integration failed (tumble run's exit 4)
  Invalid,  // the scenario is invalid at these values (tumble run's exit 3)
};
const char* run_status_name(RunStatus status);

struct RunRecord {
  RunStatus status = RunStatus::Ok;
  std::string message;  // why it failed or is invalid
  long steps = 0;       // accepted steps
  long rows = 0;        // rows made (not written): one per step where no outcome reads rows
  // max |E - E0| over the larger of |E0| and the largest KE; max ||L| - |L0|| over the largest
  // |L| (L about the origin), over the run's rows: tumble run's summary's drifts.
  double energy_drift = 0.0, momentum_drift = 0.0;
  std::vector<double> values;  // one per outcome; empty unless Ok
};

// The parameters a sweep sets, and to what, on top of fixed --set overrides.
struct SweepSpec {
  std::string text, path;                // the scenario's text and file name
  std::vector<ParameterOverride> fixed;  // --set
  std::vector<std::string> varied;       // the parameters each point gives values for
  std::vector<Outcome> outcomes;         // what each run records
  // Runs whose varied parameters reach only the bodies' initial velocities share one model
  // (VelocityOnlyRuns); false reads and builds each run's own, for tests that compare the two.
  bool share_models = true;
  // > 0: each run's budget of accepted steps, in place of its simulate.max_steps (--max-steps): a
  // run that needs more is a failed row, not minutes of a search gone quiet.
  long max_steps = 0;
  // Asked by each run after each of its steps whether to stop (Python's Ctrl-C), from every
  // thread the runs are on; empty: never. A run stopped so is a failed record.
  std::function<bool()> stop_requested;
};

// What the runners of one sweep, on every thread, learn together: whether the varied parameters
// reach only the bodies' initial velocities (decided by the first run that is read and built)
// and, if they do, that run's scenario, trace and model, which every runner then runs.
struct SweepModelShare {
  std::mutex mutex;
  bool decided = false;
  struct Model {
    ParameterTrace trace;
    Scenario scenario;
    std::shared_ptr<const SimulationModel> model;
  };
  std::optional<Model> velocity_only;  // once decided, where the runs can share it
};

// One thread's runner: its own parsed document and recorder and, where the varied parameters
// reach only the initial velocities, the sweep's one model.
class SweepRunner {
 public:
  // Throws ScenarioError if the text does not parse. Runners given the same share (which must
  // outlive them) decide once whether they can share a model; without one, a runner decides
  // for itself.
  explicit SweepRunner(const SweepSpec& spec, SweepModelShare* share = nullptr);
  // It keeps a reference to the spec: a temporary one would be gone before the first run.
  explicit SweepRunner(SweepSpec&& spec, SweepModelShare* share = nullptr) = delete;
  ~SweepRunner();
  SweepRunner(const SweepRunner&) = delete;
  SweepRunner& operator=(const SweepRunner&) = delete;

  // A run at `values` (one per SweepSpec::varied). Never throws for what a run meets: an invalid
  // scenario or a failed integration is the record's status.
  RunRecord run(std::span<const double> values);
  // Whether its runs now share one model (after a run that showed they can).
  bool shares_model() const { return velocity_only_ != nullptr; }

 private:
  // Takes the share's model, if it has one, when this runner has none yet.
  void adopt_shared_model();

  const SweepSpec* spec_;
  std::unique_ptr<SweepModelShare> own_share_;  // when not given one
  SweepModelShare* share_;
  ScenarioDocument document_;
  std::unique_ptr<RunRecorder> recorder_;
  std::unique_ptr<VelocityOnlyRuns> velocity_only_;  // once a run has shown that they can
};

// One run of a sweep: the model run from its y0 or (for a model shared by runs that differ in
// it) from the scenario's initial state, for the spec's outcomes (the initial state linearised
// where one reads modes.*; no integration where none reads the run), recorded by `recorder`,
// which is made where it is null or was made for other columns or parameters. Throws
// ScenarioError for an initial state the checks refuse, and what the recorder throws. What
// SweepRunner::run does with each scenario it reads; the expression fuzz target calls it on
// scenarios it builds in memory.
void record_run(const SweepSpec& spec, const Scenario& scenario, const SimulationModel& model,
                bool scenarios_initial_state, std::unique_ptr<RunRecorder>& recorder,
                RunRecord& record);

// Called on the calling thread about ten times a second while the runs go on. An exception from
// it stops the sweep: the runs going on finish, no other starts, and run_points throws it.
using SweepProgress = std::function<void(std::size_t done, std::size_t total)>;

// The most threads a sweep runs on (tumble sweep --threads, Python's threads=): each thread
// holds a run's state and its stack, and a thousand of them under a memory limit cannot all be
// started. Larger counts are refused before any run (docs/sweeps.md).
inline constexpr int kMaxSweepThreads = 256;

// Called with each run's record in the points' order, as soon as it and every run before it
// have finished (one call at a time, from whichever thread finished the last of them): what
// writes sweep.csv's rows as the sweep goes.
using SweepRunsDone = std::function<void(std::size_t index, const RunRecord& record)>;

// Runs every point on `threads` threads (1 to kMaxSweepThreads, else std::invalid_argument); the
// records are in the points' order. A thread that cannot be started (std::system_error) stops
// the sweep: the threads started finish their runs and the error is thrown, as is an exception
// from `in_order` (after which no run starts).
std::vector<RunRecord> run_points(const SweepSpec& spec,
                                  std::span<const std::vector<double>> points, int threads,
                                  const SweepProgress& progress = {},
                                  const SweepRunsDone& in_order = {});

// sweep.csv: "run,<varied...>,status,steps,E_drift,L_drift,<outcomes...>,message", numbers to
// 17 significant digits (they read back to the same doubles), the message quoted.
std::string sweep_csv_header(const SweepSpec& spec);
// The start of a run's line: its number and its point's values, each followed by a comma.
std::string sweep_csv_point(std::size_t run, std::span<const double> point);
// A run's line, with `outcomes` cells for its outcomes (empty where it did not finish).
std::string sweep_csv_line(std::size_t run, std::span<const double> point, const RunRecord& record,
                           std::size_t outcomes);

}  // namespace tumble
