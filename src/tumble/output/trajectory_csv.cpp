#include "tumble/output/trajectory_csv.hpp"

#include <unistd.h>
#include <stdexcept>
#include <system_error>

namespace tumble {

std::vector<std::string> trajectory_columns(std::span<const std::string> body_names) {
  std::vector<std::string> columns{"t"};
  static const char* const kBodyFields[] = {"x",   "y",   "z",   "vx",  "vy",  "vz",
                                            "wx",  "wy",  "wz",  "R11", "R12", "R13",
                                            "R21", "R22", "R23", "R31", "R32", "R33"};
  for (const std::string& body : body_names) {
    for (const char* field : kBodyFields) columns.push_back(body + "." + field);
  }
  for (const char* c : {"KE", "PE", "E", "px", "py", "pz", "Lx", "Ly", "Lz"}) {
    columns.emplace_back(c);
  }
  return columns;
}

TrajectoryCsvWriter::TrajectoryCsvWriter(std::filesystem::path path,
                                         std::span<const std::string> body_names)
    : path_(std::move(path)) {
  // A name unique to this process beside the destination: rename() then stays on one file
  // system and is atomic.
  temporary_path_ = path_;
  temporary_path_ += fmt::format(".partial-{}", static_cast<long>(::getpid()));
  file_ = std::fopen(temporary_path_.c_str(), "wb");
  if (file_ == nullptr) {
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path_.string(), std::generic_category().message(errno)));
  }
  const std::vector<std::string> columns = trajectory_columns(body_names);
  fmt::memory_buffer header;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    fmt::format_to(std::back_inserter(header), "{}{}", i == 0 ? "" : ",", columns[i]);
  }
  header.push_back('\n');
  std::fwrite(header.data(), 1, header.size(), file_);
}

TrajectoryCsvWriter::~TrajectoryCsvWriter() {
  if (file_ != nullptr) {
    std::fclose(file_);
    std::error_code ignored;
    std::filesystem::remove(temporary_path_, ignored);
  }
}

void TrajectoryCsvWriter::write_row(double t, std::span<const BodyState> states,
                                    const SystemQuantities& q) {
  line_.clear();
  auto out = std::back_inserter(line_);
  fmt::format_to(out, "{:.17g}", t);
  const auto put = [&](double v) { fmt::format_to(out, ",{:.17g}", v); };
  for (const BodyState& s : states) {
    for (int k = 0; k < 3; ++k) put(s.r_G(k));
    for (int k = 0; k < 3; ++k) put(s.v_G(k));
    for (int k = 0; k < 3; ++k) put(s.omega_W(k));
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) put(s.R_WB(r, c));
    }
  }
  put(q.kinetic_energy);
  put(q.potential_energy);
  put(q.total_energy);
  for (int k = 0; k < 3; ++k) put(q.linear_momentum(k));
  for (int k = 0; k < 3; ++k) put(q.angular_momentum_about_origin(k));
  line_.push_back('\n');
  std::fwrite(line_.data(), 1, line_.size(), file_);
  ++rows_;
}

void TrajectoryCsvWriter::finish() {
  const bool write_failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (write_failed || close_failed) {
    std::error_code ignored;
    std::filesystem::remove(temporary_path_, ignored);
    throw std::runtime_error(fmt::format("error writing {}", path_.string()));
  }
  std::filesystem::rename(temporary_path_, path_);
}

}  // namespace tumble
