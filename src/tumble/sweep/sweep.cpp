#include "tumble/sweep/sweep.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "tumble/modes/scenario_modes.hpp"
#include "tumble/output/csv_text.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/run_recorder.hpp"
#include "tumble/sweep/velocity_only_runs.hpp"

namespace tumble {

namespace {

ModesOutcome modes_outcome(const ModalAnalysis& analysis) {
  ModesOutcome out;
  out.stable = analysis.verdict == ModalAnalysis::Verdict::Stable ? 1.0 : 0.0;
  out.unstable = analysis.verdict == ModalAnalysis::Verdict::Unstable ? 1.0 : 0.0;
  for (std::size_t i = 0; i < analysis.modes.size(); ++i) {
    const Mode& mode = analysis.modes[i];
    out.growth_rate = i == 0 ? mode.growth_rate : std::max(out.growth_rate, mode.growth_rate);
    const bool oscillates =
        mode.kind == Mode::Kind::Oscillating || mode.kind == Mode::Kind::DampedOscillation;
    if (oscillates && !(mode.natural_frequency >= out.frequency)) {
      out.frequency = mode.natural_frequency;
    }
  }
  return out;
}

bool any_outcome(const SweepSpec& spec, bool (Outcome::*reads)() const) {
  return std::any_of(spec.outcomes.begin(), spec.outcomes.end(),
                     [&](const Outcome& o) { return (o.*reads)(); });
}

}  // namespace

const char* run_status_name(RunStatus status) {
  switch (status) {
    case RunStatus::Ok:
      return "ok";
    case RunStatus::Failed:
      return "failed";
    case RunStatus::Invalid:
      return "invalid";
  }
  return "?";
}

SweepRunner::SweepRunner(const SweepSpec& spec, SweepModelShare* share)
    : spec_(&spec),
      own_share_(share != nullptr ? nullptr : std::make_unique<SweepModelShare>()),
      share_(share != nullptr ? share : own_share_.get()),
      document_(ScenarioDocument::from_text(spec.text, spec.path)) {}

void SweepRunner::adopt_shared_model() {
  const std::lock_guard<std::mutex> lock(share_->mutex);
  if (const auto& shared = share_->velocity_only) {
    velocity_only_ =
        VelocityOnlyRuns::make(spec_->varied, shared->trace, shared->scenario, shared->model);
  }
}

SweepRunner::~SweepRunner() = default;

RunRecord SweepRunner::run(std::span<const double> values) {
  RunRecord record;
  try {
    if (spec_->share_models && !velocity_only_) adopt_shared_model();
    if (velocity_only_) {
      const Scenario* scenario = nullptr;
      try {
        scenario = &velocity_only_->scenario_at(values);
      } catch (const ExpressionError&) {
        // Read the document instead, for the message that says where.
      }
      if (scenario != nullptr) {
        record_run(*spec_, *scenario, velocity_only_->model(), true, recorder_, record);
        return record;
      }
    }
    std::vector<ParameterOverride> overrides = spec_->fixed;
    for (std::size_t i = 0; i < values.size(); ++i) {
      // 17 significant digits read back as the same double.
      overrides.push_back({spec_->varied[i], fmt::format("{:.17g}", values[i])});
    }
    // Until a run has been read and built, follow the varied parameters to learn whether the
    // runs can share its model.
    std::optional<ParameterTrace> trace;
    if (spec_->share_models) {
      const std::lock_guard<std::mutex> lock(share_->mutex);
      if (!share_->decided) trace = ParameterTrace{spec_->varied, {}};
    }
    const Scenario scenario = document_.read(overrides, true, trace ? &*trace : nullptr);
    const std::shared_ptr<const SimulationModel> model = build_simulation_model(scenario);
    record_run(*spec_, scenario, *model, false, recorder_, record);
    if (trace) {
      const std::lock_guard<std::mutex> lock(share_->mutex);
      if (!share_->decided) {
        share_->decided = true;
        if (VelocityOnlyRuns::make(spec_->varied, *trace, scenario, model)) {
          share_->velocity_only = SweepModelShare::Model{std::move(*trace), scenario, model};
        }
      }
    }
  } catch (const ScenarioError& e) {
    record.status = RunStatus::Invalid;
    record.message = e.what();
  } catch (const std::exception& e) {  // an outcome that cannot be recorded at these values
    record.status = RunStatus::Invalid;
    record.message = e.what();
  }
  return record;
}

void record_run(const SweepSpec& spec, const Scenario& scenario, const SimulationModel& model,
                bool scenarios_initial_state, std::unique_ptr<RunRecorder>& recorder,
                RunRecord& record) {
  // What tumble modes says of the initial state, where an outcome reads it: a state with no
  // linearisation makes the run invalid, with the command's reason.
  std::optional<ModesOutcome> modes;
  if (any_outcome(spec, &Outcome::reads_modes)) {
    try {
      modes = modes_outcome(modes_of_scenario(scenario).analysis);
    } catch (const NotSteady& e) {
      record.status = RunStatus::Invalid;
      record.message = fmt::format("tumble modes: {}", e.what());
      return;
    }
  }
  PreparedSimulation simulation = prepare_run(model);
  if (spec.max_steps > 0) {
    simulation.options.max_steps = spec.max_steps;
    simulation.options.max_steps_name = "--max-steps";
  }
  simulation.options.stop_requested = spec.stop_requested;
  if (scenarios_initial_state) {
    // On the run's own formulation: an evaluation writes its scratch.
    simulation.y0 = initial_state_vector(scenario, *simulation.formulation);
  }
  const ColumnLayout layout = column_layout(scenario, *simulation.formulation);
  if (!recorder || !recorder->fits(layout, scenario)) {
    recorder = std::make_unique<RunRecorder>(spec.outcomes, layout, scenario);
  }
  recorder->start(scenario);
  if (!recorder->reads_rows()) {
    // No outcome reads a row: the run makes one at each step's end (where the summary's E_drift
    // and L_drift are taken), not one per output_every, which can cost more than the steps (the
    // prism's flip-time sweep, rows 0.01 s apart: 6.2 times its integration). The rows are not
    // kept, so the scenario's max_rows, a bound on the disk they would fill, does not apply.
    simulation.options.output_every = 0.0;
    simulation.options.max_rows = std::numeric_limits<long>::max();
    simulation.drifts_only = true;
  }
  if (!any_outcome(spec, &Outcome::reads_run)) {  // the modes alone: no integration (0 steps)
    record.values = recorder->finish({}, {}, {}, modes ? &*modes : nullptr);
    return;
  }
  if (recorder->reads_event_states()) {
    simulation.on_event_state = [&](double t, std::span<const BodyState> states,
                                    const SystemQuantities& q, const RowExtras& extras) {
      recorder->observe_event_state({t, states, &q, &extras});
    };
  }
  if (recorder->reads_pieces()) {
    simulation.on_piece = [&](PieceRows& piece) { recorder->observe_piece(piece); };
  }
  const SimulationResult result =
      run_simulation(simulation, [&](double t, std::span<const BodyState> states,
                                     const SystemQuantities& q, const RowExtras& extras) {
        recorder->observe({t, states, &q, &extras});
      });
  record.steps = result.report.stats.accepted_steps;
  record.rows = result.rows;
  record.energy_drift = result.conservation.scaled_energy_drift();
  record.momentum_drift = result.conservation.scaled_angular_momentum_drift();
  if (!result.report.completed) {
    record.status = RunStatus::Failed;
    record.message = "integration failed: " + result.report.failure;
    return;
  }
  record.values = recorder->finish(result.contact_events, result.jumps, result.user_events,
                                   modes ? &*modes : nullptr);
}

std::vector<RunRecord> run_points(const SweepSpec& spec,
                                  std::span<const std::vector<double>> points, int threads,
                                  const SweepProgress& progress, const SweepRunsDone& in_order) {
  if (threads < 1 || threads > kMaxSweepThreads) {
    throw std::invalid_argument(
        fmt::format("threads: {} is out of range: expected 1 to {}", threads, kMaxSweepThreads));
  }
  std::vector<RunRecord> records(points.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::mutex mutex;
  std::condition_variable finished;
  std::exception_ptr failure;
  SweepModelShare share;
  // Which runs have finished, and the first not yet handed to in_order (under `mutex`).
  std::vector<char> finished_runs(in_order ? points.size() : 0, 0);
  std::size_t handed = 0;
  const auto hand_over = [&](std::size_t i) {
    const std::lock_guard<std::mutex> lock(mutex);
    finished_runs[i] = 1;
    for (; handed < points.size() && finished_runs[handed] != 0; ++handed) {
      in_order(handed, records[handed]);
    }
  };
  const auto work = [&] {
    try {
      SweepRunner runner(spec, &share);
      for (std::size_t i = next++; i < points.size(); i = next++) {
        records[i] = runner.run(points[i]);
        if (in_order) hand_over(i);
        ++done;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      next = points.size();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    finished.notify_all();
  };
  const std::size_t count = std::max<std::size_t>(
      1, std::min<std::size_t>(static_cast<std::size_t>(threads), points.size()));
  std::vector<std::thread> workers;
  // A thread that cannot be started (out of memory or of the process's thread limit) stops the
  // others after their current run: a joinable std::thread destroyed unjoined would abort.
  const auto start_worker = [&] {
    try {
      workers.emplace_back(work);
    } catch (...) {
      next = points.size();
      for (std::thread& worker : workers) worker.join();
      throw;
    }
  };
  for (std::size_t k = 1; k < count; ++k) start_worker();
  if (progress) {
    // This thread reports; the others run.
    start_worker();
    std::unique_lock<std::mutex> lock(mutex);
    while (done < points.size() && !failure) {
      finished.wait_for(lock, std::chrono::milliseconds(100));
      lock.unlock();
      try {
        progress(done, points.size());
      } catch (...) {  // the caller stops the sweep (Python's Ctrl-C): no run starts after it
        lock.lock();
        if (!failure) failure = std::current_exception();
        next = points.size();
        break;
      }
      lock.lock();
    }
  } else {
    work();
  }
  for (std::thread& worker : workers) worker.join();
  if (failure) std::rethrow_exception(failure);
  return records;
}

std::string sweep_csv_header(const SweepSpec& spec) {
  std::string line = "run";
  for (const std::string& name : spec.varied) line += "," + name;
  line += ",status,steps,E_drift,L_drift";
  for (const Outcome& outcome : spec.outcomes) line += "," + outcome.name;
  return line + ",message\n";
}

std::string sweep_csv_point(std::size_t run, std::span<const double> point) {
  fmt::memory_buffer text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "{},", run);
  for (const double value : point) fmt::format_to(out, "{:.17g},", value);
  return fmt::to_string(text);
}

std::string sweep_csv_line(std::size_t run, std::span<const double> point, const RunRecord& record,
                           std::size_t outcomes) {
  fmt::memory_buffer text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "{}", sweep_csv_point(run, point));
  fmt::format_to(out, "{},{},{:.17g},{:.17g}", run_status_name(record.status), record.steps,
                 record.energy_drift, record.momentum_drift);
  // A run that did not finish has no outcomes: empty cells, then why.
  for (std::size_t i = 0; i < outcomes; ++i) {
    if (i < record.values.size()) {
      fmt::format_to(out, ",{:.17g}", record.values[i]);
    } else {
      text.push_back(',');
    }
  }
  fmt::format_to(out, ",{}\n", record.message.empty() ? std::string() : csv_quoted(record.message));
  return fmt::to_string(text);
}

}  // namespace tumble
