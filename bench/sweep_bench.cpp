// tumble sweep's throughput: runs per second of a 1,000-run sweep (run_points, which each run
// reads the scenario from its thread's parsed document, builds the run's model, integrates and
// records the outcomes) on 1 and 2 threads, and the same 1,000 runs' integration alone (the models
// built beforehand, rows made and dropped, as tumble run makes them for its CSV): the sweep's cost
// per run over that is what reading, building and recording add. And a 2,000-run sweep of the
// prism's flip time, whose rows 0.01 s apart no record reads, against its runs' integration with
// no rows at all (the issue of studies that pay only for what they record).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/parameter_space.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {
namespace {

struct SweepCase {
  const char* stem;    // under examples/
  const char* vary;    // NAME=START:STOP:COUNT
  const char* record;  // NAME=REDUCTION
  // Text the example's is given in place of some of its own: {written, instead}.
  std::vector<std::pair<std::string, std::string>> edits = {};
  // Whether the integration alone makes the example's rows (as tumble run does) or none but the
  // first and last (the steps alone).
  bool rows_made = true;
};
// The prism's size reaches its inertia: each run reads the document and builds its model.
const SweepCase kPrism{"tumbling_prism", "a=3.9:4.1:1000", "w3=min(prism.w3)"};
// Its tilt (the chapter's 0.01 rad/s about j, made a parameter) and the disk's speed reach only
// the initial state: the runs share one model (VelocityOnlyRuns).
const SweepCase kPrismTilt{
    "tumbling_prism",
    "tilt=0.005:0.02:1000",
    "w3=min(prism.w3)",
    {{"parameters: {a: 4, b: 1, c: 2}", "parameters: {a: 4, b: 1, c: 2, tilt: 0}"},
     {"angular_velocity: [0, 0.01, 1]", "angular_velocity: [0, tilt, 1]"}}};
const SweepCase kBackspin{"backspin_disk", "v0=1.5:2.5:1000", "roll=first(floor.rolls)"};
// The prism's first flip against its tilt, 10^-2 to 10^-8 rad/s (dop853 at rtol 1e-12 to 60 s,
// rows 0.01 s apart): 6,001 rows a run that no record reads.
const SweepCase kFlipTime{
    "sweeps/prism_flip_time", "decades=2:8:2000", "flip=first(prism.w3 < 0)", {}, false};

struct PreparedSweep {
  SweepSpec spec;
  std::vector<std::vector<double>> points;
  std::vector<std::shared_ptr<const SimulationModel>> models;  // one per point
};

const PreparedSweep& prepared(const SweepCase& c) {
  static std::map<std::string, PreparedSweep> sweeps;
  PreparedSweep& p = sweeps[std::string(c.stem) + c.vary];
  if (p.points.empty()) {
    p.spec.path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + c.stem + ".yaml";
    p.spec.text = read_scenario_file(p.spec.path);
    for (const auto& [written, instead] : c.edits) {
      const std::size_t at = p.spec.text.find(written);
      if (at == std::string::npos)
        throw std::runtime_error(p.spec.path + " no longer has " + written);
      p.spec.text.replace(at, written.size(), instead);
    }
    const VaryRange range = parse_vary(c.vary, true);
    p.spec.varied = {range.name};
    p.spec.outcomes = {parse_record(c.record)};
    p.points = grid_points(std::vector<VaryRange>{range}, static_cast<std::size_t>(range.count));
    const ScenarioDocument document = ScenarioDocument::from_text(p.spec.text, p.spec.path);
    for (const std::vector<double>& point : p.points) {
      p.models.push_back(
          build_simulation_model(document.read({{range.name, fmt::format("{:.17g}", point[0])}})));
    }
  }
  return p;
}

void BM_Sweep1000(benchmark::State& state, const SweepCase& c) {
  const PreparedSweep& p = prepared(c);
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const std::vector<RunRecord> records = run_points(p.spec, p.points, threads);
    benchmark::DoNotOptimize(records.data());
    if (records.front().status != RunStatus::Ok) state.SkipWithError("a run failed");
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.points.size()));
}

void BM_Integration1000(benchmark::State& state, const SweepCase& c) {
  const PreparedSweep& p = prepared(c);
  const RowObserver ignore = [](double, std::span<const BodyState>, const SystemQuantities&) {};
  for (auto _ : state) {
    for (const auto& model : p.models) {
      PreparedSimulation run = prepare_run(*model);
      if (!c.rows_made) run.options.output_every = run.t_end - run.t0;
      const SimulationResult result = run_simulation(run, ignore);
      benchmark::DoNotOptimize(result.rows);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.points.size()));
}

// Each case's integration alone, and its sweep on 1 and 2 threads.
[[maybe_unused]] const bool kSweepsRegistered = [] {
  struct NamedCase {
    const char* name;
    const SweepCase* sweep;
  };
  for (const NamedCase c : {NamedCase{"tumbling_prism", &kPrism},
                            {"tumbling_prism_tilt", &kPrismTilt},
                            {"backspin_disk", &kBackspin},
                            {"prism_flip_time_2000", &kFlipTime}}) {
    benchmark::RegisterBenchmark(fmt::format("BM_Integration1000/{}", c.name).c_str(),
                                 BM_Integration1000, *c.sweep)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(fmt::format("BM_Sweep1000/{}", c.name).c_str(), BM_Sweep1000,
                                 *c.sweep)
        ->Arg(1)
        ->Arg(2)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace

}  // namespace tumble
