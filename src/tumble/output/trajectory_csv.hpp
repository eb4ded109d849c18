#pragma once
// The trajectory CSV of the scenario contract: one header row, then one row per output time, with
// the columns of columns.hpp. Numbers carry 17 significant digits, enough to round-trip a double.
// The file is written under a temporary name beside its destination and renamed into place by
// finish(), so a reader never sees half a file; a run that fails part way still finishes the
// rows it has, which form a valid CSV.
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tumble/output/atomic_file.hpp"
#include "tumble/output/columns.hpp"
#include "tumble/output/output_row.hpp"

namespace tumble {

class TrajectoryCsvWriter final : public RowSink {
 public:
  // Throws std::runtime_error naming the path if the temporary file cannot be created.
  // Destroyed before finish(), it leaves nothing behind.
  TrajectoryCsvWriter(std::filesystem::path path, ColumnLayout layout);
  // The same going on from a trajectory of these columns written before (a run stopped at a
  // checkpoint): its bytes, header and rows, come first, then the rows written here. Throws
  // std::runtime_error naming `earlier` if it cannot be read.
  TrajectoryCsvWriter(std::filesystem::path path, ColumnLayout layout,
                      const std::filesystem::path& earlier);

  void write_row(const OutputRow& row) override;
  // Flushes, closes and renames the file to its destination. Throws on an I/O error.
  void finish();

  const std::filesystem::path& path() const { return file_.path(); }
  std::size_t rows() const { return rows_; }

 private:
  AtomicFile file_;
  ColumnLayout layout_;
  fmt::memory_buffer line_;
  std::size_t rows_ = 0;
};

}  // namespace tumble
