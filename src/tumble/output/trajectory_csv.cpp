#include "tumble/output/trajectory_csv.hpp"

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
