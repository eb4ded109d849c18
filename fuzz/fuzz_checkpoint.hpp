#pragma once
// One input of the checkpoint fuzz target (fuzz/checkpoint_fuzz.cpp), as the target reads it and
// as tests/fuzz_regression_test.cpp replays the seeds and the inputs found so far: a checkpoint
// file's text without its last line, the digest of the lines before it, which is appended here.
// The digest (FNV-1a) tells a cut or edited file from a whole one; it is no secret, and a crafted
// file can carry a matching one, so the reader behind it must hold up on its own. Without the
// digest appended, every mutation would stop there.
//
// The scenario is the example the input's `scenario` line names (`examples/NAME.yaml`, as
// `tumble run` saves it from the source tree; read and built once a process); an input that
// names none is not read further. The state is read for a run of that example and, where it is
// read, the run goes on from it for at most kResumedSteps steps and rows (and kRunWork), so that a
// state the reader let through cannot crash or hang the run either. The seeds
// (tests/data/fuzz-checkpoint/*.state) are states `tumble run --stop-at T --save-state FILE`
// saved, their last line removed.
#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "bounded_run.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/checkpoint_file.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::fuzzing {

inline constexpr long kResumedSteps = 100;

// The example the `scenario` line names, as a path under examples/ ("planar/backspin_disk.yaml"),
// or empty where it names none: what follows the last "examples/" in it, if that is letters,
// digits, '_', '-' and '/' and ends in ".yaml".
inline std::string named_example(const std::string& text) {
  const std::string key = "scenario ";
  std::size_t at = text.rfind("\n" + key);
  if (at == std::string::npos) return {};
  at += 1 + key.size();
  const std::string line = text.substr(at, text.find('\n', at) - at);
  const std::size_t folder = line.rfind("examples/");
  if (folder == std::string::npos) return {};
  const std::string name = line.substr(folder + 9);
  if (name.size() < 6 || !name.ends_with(".yaml") || name.find("..") != std::string::npos)
    return {};
  for (const char c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '_' || c == '-' || c == '/' || c == '.';
    if (!plain) return {};
  }
  return name;
}

struct ExampleModel {
  Scenario scenario;
  std::shared_ptr<const SimulationModel> model;
};

// The example read and built, once a process; null where there is no such example.
inline const ExampleModel* example_model(const std::string& name) {
  static std::map<std::string, std::unique_ptr<ExampleModel>> built;
  const std::string path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + name;
  if (const auto found = built.find(name); found != built.end()) return found->second.get();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return nullptr;  // nothing kept
  Scenario scenario = load_scenario(path, {});
  auto model = build_simulation_model(scenario);
  auto& kept = built[name];
  kept = std::make_unique<ExampleModel>(ExampleModel{std::move(scenario), std::move(model)});
  return kept.get();
}

// Whether the input was read as a state (and resumed); false where it names no example or the
// reader refused it (CheckpointFileError, with its line and key). Anything else escaping is a
// finding.
inline bool resume_input(const std::string& body) {
  const std::string name = named_example(body);
  const ExampleModel* example = name.empty() ? nullptr : example_model(name);
  if (example == nullptr) return false;
  const std::string text = body + fmt::format("digest {:016x}\n", content_digest(body));
  PreparedSimulation simulation = prepare_run(*example->model);
  LoadedCheckpoint loaded;
  try {
    loaded = read_checkpoint_text(text, "fuzz.state", simulation);
  } catch (const CheckpointFileError&) {
    return false;
  }
  simulation.options.max_rows = kResumedSteps;
  simulation.options.stop_requested = bounded_run(kResumedSteps);
  (void)resume_simulation(simulation, loaded.checkpoint,
                          FullRowObserver([](double, std::span<const BodyState>,
                                             const SystemQuantities&, const RowExtras&) {}));
  return true;
}

}  // namespace tumble::fuzzing
