#include "tumble/output/trajectory_csv.hpp"

#include <array>
#include <fstream>
#include <stdexcept>

namespace tumble {

TrajectoryCsvWriter::TrajectoryCsvWriter(std::filesystem::path path, ColumnLayout layout)
    : file_(std::move(path)), layout_(std::move(layout)) {
  const std::vector<std::string> columns = column_names(layout_);
  fmt::memory_buffer header;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    fmt::format_to(std::back_inserter(header), "{}{}", i == 0 ? "" : ",", columns[i]);
  }
  header.push_back('\n');
  file_.write(std::string_view(header.data(), header.size()));
}

TrajectoryCsvWriter::TrajectoryCsvWriter(std::filesystem::path path, ColumnLayout layout,
                                         const std::filesystem::path& earlier)
    : file_(std::move(path)), layout_(std::move(layout)) {
  std::ifstream in(earlier, std::ios::binary);
  if (!in) throw std::runtime_error(earlier.string() + ": cannot be read");
  std::array<char, 1 << 16> buffer;
  while (in) {
    in.read(buffer.data(), buffer.size());
    file_.write(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())));
  }
  if (in.bad()) throw std::runtime_error(earlier.string() + ": cannot be read");
}

void TrajectoryCsvWriter::write_row(const OutputRow& row) {
  line_.clear();
  auto out = std::back_inserter(line_);
  bool first = true;
  walk_columns(layout_, row, [&](std::string_view, std::string_view, double value) {
    if (first) {
      fmt::format_to(out, "{:.17g}", value);
      first = false;
    } else {
      fmt::format_to(out, ",{:.17g}", value);
    }
  });
  line_.push_back('\n');
  file_.write(std::string_view(line_.data(), line_.size()));
  ++rows_;
}

void TrajectoryCsvWriter::finish() {
  file_.finish();
}

}  // namespace tumble
