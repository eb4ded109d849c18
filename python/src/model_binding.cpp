// A model (the scenario read and built once) and its runs: the rows reach numpy as one table,
// handed over without a copy; the integration runs with the GIL released, so Python threads run
// models side by side.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <tuple>

#include "bindings.hpp"
#include "tumble/simulation/checkpoint_file.hpp"
#include "tumble/simulation/table_run.hpp"

namespace tumble::python {
namespace {

struct LoadedModel {
  Scenario scenario;
  std::shared_ptr<const SimulationModel> model;
  std::uint64_t fingerprint = 0;  // of the scenario's text and set= values, as tumble run's
};

// Where a run stopped, to go on from in another run of the same model (or, saved to a file, in
// a model loaded again from the same scenario and values, or by `tumble run --resume`).
struct SavedState {
  std::shared_ptr<const SimulationModel> model;
  SimulationCheckpoint checkpoint;
  CheckpointOrigin origin;  // the scenario it belongs to (no trajectory file: none written)
};

LoadedModel load(const ScenarioSource& source, const Overrides& overrides) {
  LoadedModel loaded;
  const std::vector<ParameterOverride> sets = to_overrides(overrides);
  loaded.scenario = source.is_text ? load_scenario_text(source.source, source.name, sets)
                                   : load_scenario(source.source, sets);
  loaded.model = build_simulation_model(loaded.scenario);
  loaded.fingerprint = scenario_fingerprint(source.text(), sets);
  return loaded;
}

void save_state(const SavedState& state, const std::filesystem::path& path) {
  write_checkpoint_file(path, state.checkpoint, state.origin);
}

SavedState load_state(const LoadedModel& loaded, const std::filesystem::path& path) {
  PreparedSimulation prepared = prepare_run(*loaded.model);
  LoadedCheckpoint file;
  try {
    file = read_checkpoint_file(path, prepared);
  } catch (const CheckpointFileError& e) {
    throw std::invalid_argument(e.what());
  }
  if (file.origin.fingerprint != loaded.fingerprint) {
    throw std::invalid_argument(
        path.string() + ": a state of " + file.origin.scenario +
        " as it was, with the set= values it had, when its run stopped; this model (" +
        loaded.scenario.file +
        ") is not that (its text or its set= values differ): load the scenario with the values "
        "it was stopped with");
  }
  return SavedState{loaded.model, std::move(file.checkpoint), std::move(file.origin)};
}

// The rows as a (rows x columns) float64 array that owns them: the vector moves into the capsule
// that the array keeps alive.
py::array_t<double> rows_array(std::vector<double> values, std::size_t columns) {
  auto* owned = new std::vector<double>(std::move(values));
  const py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  const std::size_t rows = columns == 0 ? 0 : owned->size() / columns;
  const auto stride = static_cast<py::ssize_t>(sizeof(double));
  return py::array_t<double>({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)},
                             {static_cast<py::ssize_t>(columns) * stride, stride}, owned->data(),
                             owner);
}

py::list contact_and_scenario_events(const Scenario& scenario, const SimulationResult& result) {
  // events.csv's order: at one instant the contacts' events before the scenario's own.
  std::vector<std::tuple<double, int, std::string, std::string, const ContactEventRecord*>> events;
  for (const ContactEventRecord& e : result.contact_events) {
    events.emplace_back(e.t, 0, scenario.contacts[e.contact].name, e.what, &e);
  }
  for (const UserEventRecord& e : result.user_events) {
    events.emplace_back(e.t, 1, "event", e.stopped ? e.name + " (stops the run)" : e.name, nullptr);
  }
  std::stable_sort(events.begin(), events.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) < std::get<0>(b)
                                            : std::get<1>(a) < std::get<1>(b);
  });
  py::list out;
  for (const auto& [t, order, source, what, contact_event] : events) {
    py::dict event;
    event["t"] = t;
    event["source"] = source;
    event["what"] = what;
    if (contact_event != nullptr) {  // events.csv's numbers of a contact's event
      event["KE_before"] = contact_event->kinetic_energy_before;
      event["KE_after"] = contact_event->kinetic_energy_after;
      if (const auto& impact = contact_event->impact) {
        event["approach_speed"] = impact->approach_speed;
        event["rebound_speed"] = impact->rebound_speed;
        event["impulse"] = Vec3(impact->impulse_W);
      }
      event["normal_speed"] = contact_event->normal_speed;
      event["slip_speed"] = contact_event->slip_speed;
      event["point"] = Vec3(contact_event->point_W);
      event["normal"] = Vec3(contact_event->normal_W);
    }
    out.append(event);
  }
  return out;
}

py::list jumps(const Scenario& scenario, const SimulationResult& result) {
  py::list out;
  for (const JumpRecord& jump : result.jumps) {
    py::dict record;
    record["t"] = jump.t;
    record["what"] = jump.what;
    record["KE_before"] = jump.kinetic_energy_before;
    record["KE_after"] = jump.kinetic_energy_after;
    py::dict impulses;  // per joint: [Fx, Fy, Fz, Mx, My, Mz], N s and N m s, world
    for (std::size_t j = 0; j < scenario.joints.size() && j < jump.reaction_impulses.size(); ++j) {
      const JointReaction& r = jump.reaction_impulses[j];
      impulses[py::str(scenario.joints[j].name)] = std::vector<double>{
          r.F_W.x(), r.F_W.y(), r.F_W.z(), r.M_J_W.x(), r.M_J_W.y(), r.M_J_W.z()};
    }
    record["impulses"] = impulses;
    out.append(record);
  }
  return out;
}

py::dict summary(const LoadedModel& loaded, const SimulationResult& result) {
  const IntegrationReport& report = result.report;
  const ConservationReport& c = result.conservation;
  py::dict s;
  s["completed"] = report.completed;
  s["failure"] = report.failure;
  s["t_reached"] = report.t_reached;
  s["rows"] = result.rows;
  s["integrator"] = loaded.model->integrator;
  s["formulation"] = loaded.model->formulation.name();
  s["rtol"] = loaded.scenario.simulate.rtol;
  s["atol"] = loaded.scenario.simulate.atol;
  s["accepted_steps"] = report.stats.accepted_steps;
  s["rejected_steps"] = report.stats.rejected_steps;
  s["rhs_evaluations"] = report.stats.rhs_evaluations;
  s["wall_seconds"] = result.wall_seconds;
  s["E0"] = c.initial_energy;
  s["max_energy_change"] = c.max_energy_change;
  s["energy_scale"] = c.energy_scale();
  s["energy_drift"] = c.scaled_energy_drift();
  s["L0"] = c.initial_angular_momentum;
  s["max_angular_momentum_change"] = c.max_angular_momentum_change;
  s["angular_momentum_drift"] = c.scaled_angular_momentum_drift();
  s["max_orthonormality_error"] = c.max_orthonormality_error;
  s["max_work_energy_residual"] = c.max_work_energy_residual;
  s["max_contact_work"] = c.max_contact_work;
  s["max_loop_gap"] = c.max_loop_error.gap;
  s["max_loop_turn"] = c.max_loop_error.turn;
  s["max_loop_speed"] = c.max_loop_error.speed;
  return s;
}

py::dict run(const LoadedModel& loaded, double stop_at, const SavedState* start) {
  if (start != nullptr && start->model != loaded.model) {
    throw std::invalid_argument(
        "start: a state goes on only in the model whose run it came from (Model.run of that "
        "model)");
  }
  TableRunOptions options;
  options.stop_at = stop_at;
  options.start = start != nullptr ? &start->checkpoint : nullptr;
  SignalWatch signals;
  options.stop_requested = std::ref(signals);
  std::optional<TableRun> done;
  {
    const py::gil_scoped_release unlocked;
    done.emplace(run_into_table(loaded.scenario, *loaded.model, options));
  }
  py::dict out;
  out["columns"] = done->table.columns();
  out["data"] = rows_array(done->table.take_values(), done->table.columns().size());
  out["events"] = contact_and_scenario_events(loaded.scenario, done->result);
  out["jumps"] = jumps(loaded.scenario, done->result);
  out["summary"] = summary(loaded, done->result);
  if (done->state) {
    CheckpointOrigin origin;
    origin.scenario = loaded.scenario.file;
    origin.fingerprint = loaded.fingerprint;
    origin.trajectory_rows = static_cast<long>(done->state->rows);
    out["state"] = SavedState{loaded.model, std::move(*done->state), std::move(origin)};
  } else {
    out["state"] = py::none();
  }
  if (signals.raised()) {
    // The rows so far go with the exception (tumble.Model.run makes them its .result).
    signals.raised()->value().attr("_tumble_partial") = out;
    throw *signals.raised();
  }
  return out;
}

std::vector<std::string> columns_of(const LoadedModel& loaded) {
  return column_names(column_layout(loaded.scenario, *loaded.model));
}

}  // namespace

void bind_model(py::module_& m) {
  py::class_<SavedState>(m, "State", "Where a run stopped (Model.run(stop_at=...)).")
      .def_property_readonly(
          "t", [](const SavedState& s) { return s.checkpoint.t(); }, "The time it stopped at, s.")
      .def("save", &save_state, py::arg("path"),
           "Writes the state to a file (docs/checkpoints.md) that Model.load_state, or tumble "
           "run --resume, goes on from.");

  py::class_<LoadedModel>(m, "LoadedModel")
      .def_property_readonly("name", [](const LoadedModel& l) { return l.scenario.name; })
      .def_property_readonly("file", [](const LoadedModel& l) { return l.scenario.file; })
      .def_property_readonly("parameters",
                             [](const LoadedModel& l) { return l.scenario.parameters; })
      .def_property_readonly("bodies",
                             [](const LoadedModel& l) {
                               std::vector<std::string> names;
                               for (const BodySpec& b : l.scenario.bodies) names.push_back(b.name);
                               return names;
                             })
      .def_property_readonly("planar", [](const LoadedModel& l) { return l.scenario.planar; })
      .def_property_readonly("t0", [](const LoadedModel& l) { return l.model->t0; })
      .def_property_readonly("t_end", [](const LoadedModel& l) { return l.model->t_end; })
      .def_property_readonly("columns", &columns_of)
      .def("run", &run, py::arg("stop_at"), py::arg("start").none(true))
      .def("load_state", &load_state, py::arg("path"));

  m.def(
      "load",
      [](const std::string& source, bool is_text, const std::string& name,
         const Overrides& overrides) {
        return load(ScenarioSource{source, is_text, name}, overrides);
      },
      py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"));
}

}  // namespace tumble::python
