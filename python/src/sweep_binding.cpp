// tumble.sweep and tumble.find: the command line's sweep and find (the same arguments, checks,
// runs and sweep.csv), with the GIL released while they run.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>

#include "bindings.hpp"
#include "tumble/sweep/find.hpp"
#include "tumble/sweep/sweep_setup.hpp"

namespace tumble::python {
namespace {

// The command line's most points, for the same reason: each is held in memory.
constexpr std::size_t kMaxRuns = 10'000'000;

std::vector<Outcome> parse_records(const std::vector<std::string>& records) {
  std::vector<Outcome> outcomes;
  for (const std::string& record : records) {
    try {
      outcomes.push_back(parse_record(record));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("record " + std::string(e.what()));
    }
  }
  return outcomes;
}

// A Python int within [lo, hi], or std::invalid_argument "NAME: VALUE is out of range:
// expected RANGE" (an int past 64 bits too, which the binding's own conversion would refuse as
// a TypeError naming neither).
template <typename T>
T whole_number(const py::int_& value, const char* name, T lo, T hi, const std::string& range) {
  // Compared as Python ints, which have no overflow.
  if (PyObject_RichCompareBool(value.ptr(), py::int_(lo).ptr(), Py_GE) != 1 ||
      PyObject_RichCompareBool(value.ptr(), py::int_(hi).ptr(), Py_LE) != 1) {
    throw std::invalid_argument(fmt::format("{}: {} is out of range: expected {}", name,
                                            py::str(value.ptr()).cast<std::string>(), range));
  }
  return value.cast<T>();
}

py::dict sweep(const ScenarioSource& source, const Overrides& overrides,
               const std::vector<std::string>& vary, const std::vector<std::string>& records,
               const py::int_& random_arg, const py::int_& seed_arg, const py::int_& threads_arg) {
  const long random = whole_number<long>(
      random_arg, "random", 0L, static_cast<long>(kMaxRuns),
      fmt::format("0 (the grid) or 1 to {} points (the most a sweep holds)", kMaxRuns));
  const std::uint64_t seed = whole_number<std::uint64_t>(
      seed_arg, "seed", 0, std::numeric_limits<std::uint64_t>::max(),
      fmt::format("a whole number from 0 to {}", std::numeric_limits<std::uint64_t>::max()));
  const int threads = whole_number<int>(
      threads_arg, "threads", 0, kMaxSweepThreads,
      fmt::format("0 (every core) or 1 to {} (the limit on a sweep's threads)", kMaxSweepThreads));
  std::vector<VaryRange> ranges;
  for (const std::string& argument : vary) ranges.push_back(parse_vary(argument, random == 0));
  std::vector<Outcome> outcomes = parse_records(records);
  SweepSpec spec = make_sweep_spec(source.text(), source.path(), to_overrides(overrides), ranges,
                                   std::move(outcomes), {"vary", "record"});
  const std::vector<std::vector<double>> points =
      random > 0 ? random_points(ranges, static_cast<std::size_t>(random), seed)
                 : grid_points(ranges, kMaxRuns);
  const int thread_count =
      threads > 0
          ? threads
          : std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMaxSweepThreads);
  std::vector<RunRecord> records_done;
  std::string csv = sweep_csv_header(spec);
  // Ctrl-C (SignalWatch, asked on this thread) stops the runs going on at their next step and
  // starts no other; its exception is raised here.
  SignalWatch signals;
  std::atomic<bool> stopping{false};
  spec.stop_requested = [&stopping] { return stopping.load(std::memory_order_relaxed); };
  struct Interrupted {};
  try {
    const py::gil_scoped_release unlocked;
    records_done = run_points(spec, points, thread_count, [&](std::size_t, std::size_t) {
      if (signals()) {
        stopping = true;
        throw Interrupted{};
      }
    });
    for (std::size_t i = 0; i < points.size(); ++i) {
      csv += sweep_csv_line(i, points[i], records_done[i], spec.outcomes.size());
    }
  } catch (const Interrupted&) {
    throw *signals.raised();
  }

  // sweep.csv's columns, each a numpy array (the status and message as lists of str).
  const std::size_t n = points.size();
  py::dict columns;
  py::array_t<long> run(static_cast<py::ssize_t>(n));
  py::array_t<long> steps(static_cast<py::ssize_t>(n));
  py::array_t<double> energy_drift(static_cast<py::ssize_t>(n));
  py::array_t<double> momentum_drift(static_cast<py::ssize_t>(n));
  std::vector<py::array_t<double>> varied(spec.varied.size());
  for (auto& v : varied) v = py::array_t<double>(static_cast<py::ssize_t>(n));
  std::vector<py::array_t<double>> recorded(spec.outcomes.size());
  for (auto& r : recorded) r = py::array_t<double>(static_cast<py::ssize_t>(n));
  std::vector<std::string> status(n), message(n);
  const double nan = std::nan("");
  for (std::size_t i = 0; i < n; ++i) {
    const RunRecord& record = records_done[i];
    run.mutable_at(i) = static_cast<long>(i);
    for (std::size_t k = 0; k < varied.size(); ++k) varied[k].mutable_at(i) = points[i][k];
    status[i] = run_status_name(record.status);
    steps.mutable_at(i) = record.steps;
    energy_drift.mutable_at(i) = record.energy_drift;
    momentum_drift.mutable_at(i) = record.momentum_drift;
    for (std::size_t k = 0; k < recorded.size(); ++k) {
      recorded[k].mutable_at(i) = k < record.values.size() ? record.values[k] : nan;
    }
    message[i] = record.message;
  }
  columns["run"] = run;
  for (std::size_t k = 0; k < varied.size(); ++k) columns[py::str(spec.varied[k])] = varied[k];
  columns["status"] = status;
  columns["steps"] = steps;
  columns["E_drift"] = energy_drift;
  columns["L_drift"] = momentum_drift;
  for (std::size_t k = 0; k < recorded.size(); ++k) {
    columns[py::str(spec.outcomes[k].name)] = recorded[k];
  }
  columns["message"] = message;
  py::dict out;
  out["columns"] = columns;
  out["csv"] = csv;
  out["varied"] = spec.varied;
  out["threads"] = thread_count;
  return out;
}

py::dict find(const ScenarioSource& source, const Overrides& overrides, const std::string& vary,
              const std::string& when, std::optional<double> tol) {
  const VaryRange range = parse_vary(vary, false);
  std::vector<Outcome> outcomes;
  try {
    outcomes.push_back(parse_outcome("condition", when));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("when " + std::string(e.what()));
  }
  const double tolerance =
      tol ? *tol : 1e-9 * std::max(std::abs(range.start), std::abs(range.stop));
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("tol: give a positive width");
  }
  SweepSpec spec = make_sweep_spec(source.text(), source.path(), to_overrides(overrides),
                                   std::span(&range, 1), std::move(outcomes), {"vary", "when"});
  // The runs are on this thread, one after another: each asks Ctrl-C itself (SignalWatch), and
  // a run it stops ends the search with its exception.
  SignalWatch signals;
  spec.stop_requested = std::ref(signals);
  struct Interrupted {};
  std::vector<std::tuple<double, bool, long>> history;
  std::optional<FindResult> found;
  std::optional<FindError> failed;
  {
    const py::gil_scoped_release unlocked;
    try {
      found = find_change(spec, range.start, range.stop, tolerance,
                          [&](double value, bool outcome, const RunRecord& record) {
                            if (signals.raised()) throw Interrupted{};
                            history.emplace_back(value, outcome, record.steps);
                          });
    } catch (const FindError& e) {
      failed = e;
    } catch (const Interrupted&) {
    }
  }
  if (signals.raised()) throw *signals.raised();
  if (failed) {
    const py::object error_class = py::module_::import("tumble._errors").attr("FindError");
    const RunRecord& record = failed->record();
    const py::object error = error_class(failed->what(), failed->same_at_both_ends(),
                                         run_status_name(record.status), record.message);
    PyErr_SetObject(error_class.ptr(), error.ptr());
    throw py::error_already_set();
  }
  py::dict out;
  out["name"] = range.name;
  out["lo"] = found->lo;
  out["hi"] = found->hi;
  out["at_lo"] = found->at_lo;
  out["at_hi"] = found->at_hi;
  out["runs"] = found->runs;
  out["tolerance"] = tolerance;
  out["history"] = history;
  return out;
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def(
      "sweep",
      [](const std::string& source, bool is_text, const std::string& name,
         const Overrides& overrides, const std::vector<std::string>& vary,
         const std::vector<std::string>& records, const py::int_& random, const py::int_& seed,
         const py::int_& threads) {
        return sweep(ScenarioSource{source, is_text, name}, overrides, vary, records, random, seed,
                     threads);
      },
      py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"), py::arg("vary"),
      py::arg("record"), py::arg("random"), py::arg("seed"), py::arg("threads"));
  m.def(
      "find",
      [](const std::string& source, bool is_text, const std::string& name,
         const Overrides& overrides, const std::string& vary, const std::string& when,
         std::optional<double> tol) {
        return find(ScenarioSource{source, is_text, name}, overrides, vary, when, tol);
      },
      py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"), py::arg("vary"),
      py::arg("when"), py::arg("tol").none(true));
}

}  // namespace tumble::python
