#include "tumble/output/row_table.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

RowTable::RowTable(ColumnLayout layout, std::size_t expected_rows)
    : layout_(std::move(layout)), columns_(column_names(layout_)) {
  values_.reserve(expected_rows * columns_.size());
}

void RowTable::write_row(const OutputRow& row) {
  walk_columns(layout_, row,
               [&](std::string_view, std::string_view, double value) { values_.push_back(value); });
}

std::size_t expected_rows(double duration, double output_every, long max_rows) {
  // Without an output interval a row follows each accepted step, whose count is not known
  // before the run: a thousand rows covers the chapter's examples, and the table grows past it.
  constexpr double kRowsPerStepRun = 1000.0;
  const double rows = output_every > 0.0 && duration > 0.0
                          ? std::ceil(duration / output_every) + 2.0
                          : kRowsPerStepRun;
  return static_cast<std::size_t>(
      std::clamp(rows, 1.0, static_cast<double>(std::max(1L, max_rows))));
}

}  // namespace tumble
