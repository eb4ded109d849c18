#pragma once
// The processes a sweep's runs are shared among. Started by mpirun (in a build with MPI), they
// are the ranks of MPI_COMM_WORLD; otherwise this process alone. MPI is started only under
// mpirun, so a plain `tumble sweep` pays nothing for it.
#include <string>
#include <vector>

namespace tumble::cli {

class ProcessGroup {
 public:
  ProcessGroup();
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Rank 0 receives every rank's text, in rank order; the other ranks receive nothing.
  std::vector<std::string> gather(const std::string& mine) const;
  // The processes on this machine (mpirun's local size), for the default thread count.
  int local_size() const { return local_size_; }

 private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
  [[maybe_unused]] bool started_mpi_ = false;  // read only in a build with MPI
};

}  // namespace tumble::cli
