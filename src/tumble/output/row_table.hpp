#pragma once
// A run's rows kept in memory as one table of doubles, row-major (rows x columns, the columns of
// columns.hpp in their order): what the Python module hands to numpy without a copy or a loop
// over rows. The values are the trajectory CSV's, before they are printed.
#include <cstddef>
#include <string>
#include <vector>

#include "tumble/output/columns.hpp"
#include "tumble/output/output_row.hpp"

namespace tumble {

class RowTable final : public RowSink {
 public:
  // Room for `expected_rows` rows is taken now, so that a run that writes no more does not grow
  // the table while it steps.
  RowTable(ColumnLayout layout, std::size_t expected_rows);

  void write_row(const OutputRow& row) override;

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows() const { return columns_.empty() ? 0 : values_.size() / columns_.size(); }
  // Row r's value in column c is values()[r * columns().size() + c].
  const std::vector<double>& values() const { return values_; }
  // Hands the values over (the table is left empty).
  std::vector<double> take_values() { return std::move(values_); }

 private:
  ColumnLayout layout_;
  std::vector<std::string> columns_;
  std::vector<double> values_;
};

// The rows a run of this length is expected to write: one per output interval where the scenario
// gives one (duration / output_every, and the last), else an estimate the table grows past.
std::size_t expected_rows(double duration, double output_every, long max_rows);

}  // namespace tumble
