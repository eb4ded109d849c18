// tumble sweep: the scenario run at every point of a grid (or at seeded random points) of its
// parameters, on every core and, under mpirun, on every process; one row of sweep.csv per run.
#include <fmt/core.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <stdexcept>
#include <thread>

#include "commands.hpp"
#include "exit_status.hpp"
#include "process_group.hpp"
#include "sweep_setup.hpp"
#include "tumble/input/bounded_read.hpp"
#include "tumble/output/atomic_file.hpp"

namespace tumble::cli {
namespace {

// A bar on stderr, when it is a terminal and the sweep has gone on for more than 2 s.
class ProgressBar {
 public:
  ProgressBar() : start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO)) {}
  void show(std::size_t done, std::size_t total) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (!terminal_ || elapsed < 2.0 || total == 0) return;
    constexpr int kWidth = 40;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    const int filled = static_cast<int>(fraction * kWidth);
    const double left = done > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    fmt::print(stderr, "\r[{:=<{}}{: <{}}] {}/{} runs, {:.0f} s left ", "", filled, "",
               kWidth - filled, done, total, left);
    shown_ = true;
  }
  ~ProgressBar() {
    if (shown_) fmt::print(stderr, "\n");
  }

 private:
  std::chrono::steady_clock::time_point start_;
  bool terminal_;
  bool shown_ = false;
};

// The rows that a stopped sweep of these points wrote to `path` (--resume): its header must be
// this sweep's, and its rows whole lines numbered from 0 in order, each with this sweep's values
// of its point; a last line cut short is dropped. Returns how many there are, with their text in
// `kept` and the count of those not ok in `not_ok`. None where there is no file. Throws
// std::invalid_argument where the file is another sweep's.
std::size_t resumed_rows(const std::filesystem::path& path, const SweepSpec& spec,
                         std::span<const std::vector<double>> points, std::string& kept,
                         std::size_t& not_ok) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return 0;
  std::string text;
  try {
    text = read_bounded(path.string(), in, kSweepCsvReadLimit);
  } catch (const std::runtime_error& e) {  // over its limit, or a read error
    throw std::invalid_argument(fmt::format("--resume: {}: {}", path.string(), e.what()));
  }
  const std::string header = sweep_csv_header(spec);
  if (text.compare(0, header.size(), header) != 0) {
    const std::string first = text.substr(0, text.find('\n'));
    throw std::invalid_argument(fmt::format(
        "--resume: {} is another sweep's (its header is '{}'; this sweep's is '{}'): resume with "
        "the same --vary and --record, or give another --out",
        path.string(), first, header.substr(0, header.size() - 1)));
  }
  std::size_t at = header.size(), rows = 0;
  for (std::size_t end = text.find('\n', at); end != std::string::npos;
       at = end + 1, end = text.find('\n', at)) {
    const std::string_view line = std::string_view(text).substr(at, end - at);
    const std::string point =
        rows < points.size() ? sweep_csv_point(rows, points[rows]) : std::string();
    if (point.empty() || line.substr(0, point.size()) != point) {
      throw std::invalid_argument(fmt::format(
          "--resume: {} is another sweep's: its row {} is not this sweep's run {} ('{}'): "
          "resume with the same --vary, --random and --seed, or give another --out",
          path.string(), rows + 1, rows, line.substr(0, 60)));
    }
    if (line.substr(point.size(), 3) != "ok,") ++not_ok;
    ++rows;
  }
  kept = text.substr(header.size(), at - header.size());
  return rows;
}

}  // namespace

int sweep_command(const SweepArguments& args) {
  const ProcessGroup processes;
  const bool lead = processes.rank() == 0;
  const auto bad_argument = [&](const std::string& why) {
    if (lead) fmt::print(stderr, "tumble sweep: {}\n", why);
    return kBadCommandLine;
  };
  if (args.out_dir.empty()) return bad_argument("--out: an empty path names no directory");
  std::vector<VaryRange> ranges;
  std::vector<Outcome> outcomes;
  try {
    for (const std::string& vary : args.vary) ranges.push_back(parse_vary(vary, args.random == 0));
    for (const std::string& record : args.record) {
      try {
        outcomes.push_back(parse_record(record));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--record " + std::string(e.what()));
      }
    }
  } catch (const std::invalid_argument& e) {
    return bad_argument(e.what());
  }
  SweepSpec spec;
  if (const int status = prepare_sweep("tumble sweep", "--record", args.scenario, args.sets, ranges,
                                       outcomes, spec);
      status != kDone) {
    return status;
  }
  spec.max_steps = args.max_steps;
  // The points are held in memory (about 60 bytes each): ten million is over half a gigabyte.
  constexpr std::size_t kMaxRuns = 10'000'000;
  std::vector<std::vector<double>> points;
  try {
    points = args.random > 0
                 ? random_points(ranges, static_cast<std::size_t>(args.random), args.seed)
                 : grid_points(ranges, kMaxRuns);
  } catch (const std::invalid_argument& e) {
    return bad_argument(e.what());
  }

  // sweep.csv is made before the first run, so that an --out that cannot be written is said at
  // once, not after the runs. Every process checks (they see one file system), so that all stop
  // together. In one process the file is put in place with its header at once and each run's row
  // is added as it and every run before it finish: a sweep stopped at any point (Ctrl-C, a kill,
  // a failure) leaves a valid sweep.csv of the runs so far, in order, which --resume goes on
  // from.
  const std::filesystem::path path = std::filesystem::path(args.out_dir) / "sweep.csv";
  std::string kept;       // --resume: the rows already there
  std::size_t first = 0;  // the first run to do
  std::size_t kept_not_ok = 0;
  if (args.resume) {
    try {
      first = resumed_rows(path, spec, points, kept, kept_not_ok);
    } catch (const std::invalid_argument& e) {
      return bad_argument(e.what());
    }
  }
  const std::span<const std::vector<double>> todo(points.data() + first, points.size() - first);
  std::optional<AtomicFile> file;
  try {
    std::error_code error;
    std::filesystem::create_directories(path.parent_path(), error);
    if (error) {
      throw std::runtime_error(fmt::format("cannot create the directory {}: {}",
                                           path.parent_path().string(), error.message()));
    }
    file.emplace(path);  // destroyed unpublished: removed, and sweep.csv untouched
    if (lead) {
      file->write(sweep_csv_header(spec));
      file->write(kept);
      if (processes.size() == 1) file->publish();
    }
  } catch (const std::exception& e) {
    if (lead) fmt::print(stderr, "tumble sweep: --out {}: {}\n", args.out_dir, e.what());
    return kOutputError;
  }
  if (!lead) file.reset();

  // Rank r runs the points r, r + size, r + 2 size, ...: neighbours on a grid cost alike, so
  // each rank gets a like share of cheap and dear runs.
  const auto size = static_cast<std::size_t>(processes.size());
  const auto rank = static_cast<std::size_t>(processes.rank());
  std::vector<std::vector<double>> mine;
  for (std::size_t i = rank; i < todo.size(); i += size) mine.push_back(todo[i]);
  const int threads = args.threads > 0
                          ? args.threads
                          : std::clamp(static_cast<int>(std::thread::hardware_concurrency()) /
                                           std::max(1, processes.local_size()),
                                       1, kMaxSweepThreads);
  const auto start = std::chrono::steady_clock::now();
  std::size_t not_ok = 0;  // of the runs done here
  const auto count = [&](const RunRecord& record) {
    if (record.status != RunStatus::Ok) ++not_ok;
  };
  // One process: each row to the file as it comes.
  const SweepRunsDone write_row = [&](std::size_t k, const RunRecord& record) {
    file->write(sweep_csv_line(first + k, mine[k], record, spec.outcomes.size()));
    file->flush();
    count(record);
  };
  std::vector<RunRecord> records;
  try {
    ProgressBar bar;
    records = run_points(
        spec, mine, threads,
        lead ? SweepProgress([&](std::size_t done, std::size_t total) { bar.show(done, total); })
             : SweepProgress(),
        size == 1 ? write_row : SweepRunsDone());
  } catch (const std::runtime_error& e) {  // sweep.csv cannot be written, or a thread started
    fmt::print(stderr, "tumble sweep: {}\n", e.what());  // the rows so far stay
    return kOutputError;
  }
  if (size == 1) {
    try {
      file->finish();
    } catch (const std::exception& e) {
      fmt::print(stderr, "tumble sweep: {}\n", e.what());
      return kOutputError;
    }
  } else {
    std::string lines;
    for (std::size_t k = 0; k < mine.size(); ++k) {
      lines += sweep_csv_line(first + rank + k * size, mine[k], records[k], spec.outcomes.size());
      count(records[k]);
    }
    // Each rank's lines are in its runs' order; run i is rank i mod size's next. The counts of
    // runs not ok are summed the same way.
    const std::vector<std::string> texts = processes.gather(lines + fmt::format("{}\n", not_ok));
    if (!lead) return kDone;
    not_ok = 0;
    std::vector<std::size_t> at(texts.size(), 0);
    std::string csv;
    for (std::size_t i = 0; i < todo.size(); ++i) {
      const std::size_t r = i % size;
      const std::size_t end = texts[r].find('\n', at[r]);
      csv += std::string_view(texts[r]).substr(at[r], end + 1 - at[r]);
      at[r] = end + 1;
    }
    for (std::size_t r = 0; r < texts.size(); ++r) not_ok += std::stoul(texts[r].substr(at[r]));
    try {
      file->write(csv);
      file->finish();
    } catch (const std::exception& e) {
      fmt::print(stderr, "tumble sweep: {}\n", e.what());
      return kOutputError;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  not_ok += kept_not_ok;
  fmt::print("sweep of {} over {}\n", args.scenario, fmt::join(spec.varied, ", "));
  fmt::print(
      "  runs           {} ({}{}), {}\n", points.size(),
      args.random > 0 ? fmt::format("random points, seed {}", args.seed) : std::string("a grid"),
      first > 0 ? fmt::format("; the first {} kept from sweep.csv", first) : std::string(),
      not_ok == 0 ? std::string("all ok")
                  : fmt::format("{} failed or invalid (see their status and message)", not_ok));
  fmt::print("  parallel       {} thread{} x {} process{}\n", threads, threads == 1 ? "" : "s",
             size, size == 1 ? "" : "es");
  fmt::print("  wall time      {:.3f} s ({:.1f} runs/s)\n", seconds,
             static_cast<double>(todo.size()) / seconds);
  fmt::print("  sweep.csv      {}\n", path.string());
  return kDone;
}

}  // namespace tumble::cli
