#pragma once
// The trajectory CSV of the scenario contract: one header row, then one row per output time:
//   t, per body B: B.x B.y B.z (COM, world), B.vx B.vy B.vz, B.wx B.wy B.wz (world),
//   B.R11 ... B.R33 (row-major, body axes -> world), then KE PE E px py pz Lx Ly Lz (about the
//   world origin), then per joint J: J.Fx J.Fy J.Fz J.Mx J.My J.Mz (what its first body exerts on
//   its second, world, moment about the joint point), then per contact C: C.N C.Fx C.Fy C.Fz
//   C.slip C.mode (normal force, friction force on the body, world, slip speed, 0 apart /
//   1 sliding / 2 rolling), then per force element, motor, impulse, lock and contact E: E.P E.W
//   (power now, work since t0). Numbers carry 17 significant digits, enough to
//   round-trip a double.
// The file is written under a temporary name beside its destination and renamed into place by
// finish(), so a reader never sees half a file; a run that fails part way still finishes the
// rows it has, which form a valid CSV.
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/output/atomic_file.hpp"

namespace tumble {

std::vector<std::string> trajectory_columns(std::span<const std::string> body_names,
                                            std::span<const std::string> joint_names = {},
                                            std::span<const std::string> contact_names = {},
                                            std::span<const std::string> element_names = {});

class TrajectoryCsvWriter {
 public:
  // Throws std::runtime_error naming the path if the temporary file cannot be created.
  // Destroyed before finish(), it leaves nothing behind.
  TrajectoryCsvWriter(std::filesystem::path path, std::span<const std::string> body_names,
                      std::span<const std::string> joint_names = {},
                      std::span<const std::string> contact_names = {},
                      std::span<const std::string> element_names = {});

  // extras: the row's joint reactions, contacts and element powers and works, in the
  // constructor's order.
  void write_row(double t, std::span<const BodyState> states, const SystemQuantities& q,
                 const RowExtras* extras = nullptr);
  // Flushes, closes and renames the file to its destination. Throws on an I/O error.
  void finish();

  const std::filesystem::path& path() const { return file_.path(); }
  std::size_t rows() const { return rows_; }

 private:
  AtomicFile file_;
  fmt::memory_buffer line_;
  std::size_t rows_ = 0;
};

}  // namespace tumble
