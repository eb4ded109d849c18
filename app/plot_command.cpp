// `tumble plot`: a figure of some columns of a CSV (a trajectory, usually) for a report, drawn by
// gnuplot into PNG or SVG. tumble checks the columns against the header, writes a gnuplot script
// to a temporary file and runs gnuplot from an argument vector (no shell). The figure is drawn
// under a temporary name beside the destination and renamed: it appears only when complete.
#include <fcntl.h>
#include <unistd.h>

#include <fmt/core.h>
#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "child_process.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "tumble/input/bounded_read.hpp"
#include "tumble/output/atomic_file.hpp"

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;

// A user-facing failure and the exit status it calls for.
class PlotError : public std::runtime_error {
 public:
  PlotError(int status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  int status() const { return status_; }

 private:
  int status_;
};

std::string errno_text() {
  return std::generic_category().message(errno);
}

// The header row, split on commas (the trajectory CSV's names never contain one or a quote).
std::vector<std::string> read_header(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in) {
    throw PlotError(kBadCommandLine, fmt::format("cannot read {}: {}", csv.string(), errno_text()));
  }
  // Read up to the first newline, and no further than the limit: /dev/zero has none.
  std::string line;
  std::uint64_t limit = 0;
  try {
    limit = limit_bytes(kCsvHeaderReadLimit);
  } catch (const ReadLimitError& e) {
    throw PlotError(kBadCommandLine, fmt::format("{}: {}", csv.string(), e.what()));
  }
  for (char c = 0; in.get(c) && c != '\n';) {
    line += c;
    if (line.size() > limit) {
      throw PlotError(kBadCommandLine, fmt::format("{}: its header row {}", csv.string(),
                                                   too_large_message(kCsvHeaderReadLimit, 0)));
    }
  }
  if (in.bad() || line.empty() || line == "\r") {
    throw PlotError(kBadCommandLine,
                    fmt::format("{}: no header row (expected column names: t,...)", csv.string()));
  }
  if (line.back() == '\r') line.pop_back();
  std::vector<std::string> names;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = line.find(',', begin);
    names.push_back(line.substr(begin, comma - begin));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return names;
}

// The 1-based column number gnuplot's `using` takes; names with dots (prism.wx) would not parse
// there, so they appear only as titles.
int column_number(const std::vector<std::string>& header, const std::string& name,
                  const fs::path& csv) {
  const auto found = std::find(header.begin(), header.end(), name);
  if (found == header.end()) {
    std::string available;
    for (const std::string& h : header) available += (available.empty() ? "" : ", ") + h;
    throw PlotError(kBadCommandLine, fmt::format("no column '{}' in {}; available: {}", name,
                                                 csv.string(), available));
  }
  return static_cast<int>(found - header.begin()) + 1;
}

// The unit of a column of the trajectory CSV (docs/scenario.md, "The trajectory CSV"); empty
// for the rotation tensor's entries and for names the contract does not define.
std::string unit_of(const std::string& column) {
  const auto is_one_of = [](const std::string& s, std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return s == n; });
  };
  if (column == "t") return "s";
  if (is_one_of(column, {"KE", "PE", "E"})) return "J";
  if (is_one_of(column, {"px", "py", "pz"})) return "kg m/s";
  if (is_one_of(column, {"Lx", "Ly", "Lz"})) return "kg m^2/s";
  const std::size_t dot = column.rfind('.');
  if (dot == std::string::npos) return "";
  const std::string field = column.substr(dot + 1);
  if (is_one_of(field, {"x", "y", "z"})) return "m";
  if (is_one_of(field, {"vx", "vy", "vz"})) return "m/s";
  if (is_one_of(field, {"wx", "wy", "wz"})) return "rad/s";
  return "";
}

std::string with_unit(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : fmt::format("{} ({})", name, unit);
}

// `text` as a gnuplot string literal. Single quotes, because inside double quotes gnuplot runs
// `backquoted` text as a shell command; inside single quotes it takes every character as it is
// but for '' standing for one quote. A newline cannot sit inside a literal, so lines are joined
// with the double-quoted "\n"; other control characters become spaces.
std::string gnuplot_string(const std::string& text) {
  std::string literal = "'";
  for (const char c : text) {
    if (c == '\'') {
      literal += "''";
    } else if (c == '\n') {
      literal += "'.\"\\n\".'";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      literal += ' ';
    } else {
      literal += c;
    }
  }
  return literal + "'";
}

// The script reads the figure's path as ARG1 and the CSV's as ARG2 (gnuplot -c), so neither is
// ever parsed as gnuplot text. Both are absolute: gnuplot would run a file name starting with
// '<' (or an output starting with '|') as a shell command.
std::string gnuplot_script(const PlotArguments& args, bool svg, int x_number,
                           const std::vector<int>& y_numbers) {
  std::string script;
  const auto line = [&](const std::string& text) { script += text + "\n"; };
  line(fmt::format("set terminal {} size {},{} noenhanced font 'sans,11'{}",
                   svg ? "svg" : "pngcairo", args.width, args.height,
                   svg ? " background '#ffffff'" : ""));
  line("set output ARG1");
  line("set datafile separator comma");
  if (!args.title.empty()) line("set title " + gnuplot_string(args.title));
  line("set xlabel " + gnuplot_string(with_unit(args.x_column, unit_of(args.x_column))));
  // One column: its name and unit on the y axis; several sharing a unit: the unit.
  const std::string unit = unit_of(args.columns.front());
  const bool one_unit = std::all_of(args.columns.begin(), args.columns.end(),
                                    [&](const std::string& c) { return unit_of(c) == unit; });
  if (args.columns.size() == 1) {
    line("set ylabel " + gnuplot_string(with_unit(args.columns.front(), unit)));
  } else if (one_unit && !unit.empty()) {
    line("set ylabel " + gnuplot_string(unit));
  }
  line("set grid");
  line("set key outside right top");
  std::string plot = "plot";
  for (std::size_t i = 0; i < y_numbers.size(); ++i) {
    plot += fmt::format("{} ARG2 using {}:{} skip 1 with lines linewidth 1.5 title {}",
                        i == 0 ? "" : ",", x_number, y_numbers[i], gnuplot_string(args.columns[i]));
  }
  line(plot);
  line("unset output");
  return script;
}

std::optional<fs::path> find_on_path(const std::string& program) {
  const char* path_variable = std::getenv("PATH");
  const std::string path =
      path_variable != nullptr ? path_variable : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= path.size()) {
    const std::size_t end = std::min(path.find(':', begin), path.size());
    // An empty entry would mean the current directory: skipped, so a stray ./gnuplot never runs.
    if (end > begin) {
      const fs::path candidate = fs::path(path.substr(begin, end - begin)) / program;
      std::error_code ignored;
      if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate, ignored)) {
        return candidate;
      }
    }
    begin = end + 1;
  }
  return std::nullopt;
}

int plot(const PlotArguments& args) {
  const fs::path csv(args.csv);
  const fs::path output(args.output);
  const std::string extension = lowercase_extension(output);
  if (extension != ".png" && extension != ".svg") {
    throw PlotError(kBadCommandLine,
                    fmt::format("-o {}: the figure's name must end in .png or .svg", args.output));
  }

  const std::vector<std::string> header = read_header(csv);
  const int x_number = column_number(header, args.x_column, csv);
  std::vector<int> y_numbers;
  for (const std::string& c : args.columns) y_numbers.push_back(column_number(header, c, csv));

  const std::optional<fs::path> gnuplot = find_on_path("gnuplot");
  if (!gnuplot) {
    throw PlotError(kOutputError,
                    "gnuplot is not installed (not found on PATH): install it with "
                    "`apt-get install gnuplot-nox` (Debian) or run scripts/setup.sh");
  }

  std::error_code error;
  const fs::path destination = fs::absolute(output, error);
  if (error)
    throw PlotError(kOutputError, fmt::format("cannot write {}: {}", args.output, error.message()));
  fs::create_directories(destination.parent_path(), error);
  if (error) {
    throw PlotError(kOutputError, fmt::format("cannot write {}: {}: {}", args.output,
                                              destination.parent_path().string(), error.message()));
  }
  // gnuplot draws into a directory of tumble's own, and the finished figure is installed through
  // an AtomicFile: nothing planted beside the destination is ever written through.
  std::optional<TemporaryDirectory> scratch;
  try {
    scratch.emplace("tumble-plot");
  } catch (const std::runtime_error& e) {
    throw PlotError(kOutputError, fmt::format("cannot write {}: {}", args.output, e.what()));
  }
  const fs::path figure = scratch->path() / ("figure" + extension);
  const std::string script_name = (scratch->path() / "figure.gp").string();
  const int script_fd =
      ::open(script_name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (script_fd < 0) {
    throw PlotError(kOutputError, fmt::format("cannot write the gnuplot script {}: {}", script_name,
                                              errno_text()));
  }
  const std::string script = gnuplot_script(args, extension == ".svg", x_number, y_numbers);
  const bool script_written =
      ::write(script_fd, script.data(), script.size()) == static_cast<ssize_t>(script.size());
  if (::close(script_fd) != 0 || !script_written) {
    throw PlotError(kOutputError, fmt::format("cannot write the gnuplot script {}", script_name));
  }

  const fs::path absolute_csv = fs::absolute(csv, error);
  if (error) throw PlotError(kBadCommandLine, fmt::format("{}: {}", args.csv, error.message()));
  // gnuplot's own messages go straight to the user.
  ChildOutcome gnuplot_run;
  try {
    gnuplot_run = run_child({gnuplot->string(), "--default-settings", "-c", script_name,
                             figure.string(), absolute_csv.string()},
                            ChildOutput::Inherit);
  } catch (const ChildProcessError& e) {
    throw PlotError(kOutputError,
                    fmt::format("{}; nothing was written to {}", e.what(), args.output));
  }
  if (!gnuplot_run.succeeded()) {
    throw PlotError(kOutputError, fmt::format("gnuplot failed ({}); nothing was written to {}",
                                              gnuplot_run.how_it_ended(), args.output));
  }
  if (fs::file_size(figure, error) == 0 || error) {
    throw PlotError(kOutputError,
                    fmt::format("gnuplot drew nothing; nothing was written to {}", args.output));
  }
  try {
    install_copy(figure, destination);
  } catch (const std::runtime_error& e) {
    throw PlotError(kOutputError, e.what());
  }
  return kDone;
}

}  // namespace

int plot_command(const PlotArguments& args) {
  try {
    return plot(args);
  } catch (const PlotError& e) {
    fmt::print(stderr, "tumble plot: {}\n", e.what());
    return e.status();
  }
}

}  // namespace tumble::cli
