#pragma once
/// The job a `stratum` process belongs to: under `mpirun`/`srun` (and a
/// build with STRATUM_MPI) an MPI job whose ranks split the heavy commands'
/// work (stratum/distributed.hpp); otherwise this process alone, exactly as
/// a build without MPI. Rank 0 prints and writes; the other ranks' stdout
/// and stderr are silenced, and an error is printed once, by the lowest
/// rank that failed (docs/distributed.md).
#include <memory>
#include <string>

namespace stratum::cli {

class DistributedJob {
 public:
  /// Joins the MPI job when this process was launched as one of its ranks.
  DistributedJob(int& argc, char**& argv);
  ~DistributedJob();
  DistributedJob(const DistributedJob&) = delete;
  DistributedJob& operator=(const DistributedJob&) = delete;

  /// Ends the command: every rank learns whether any failed; `message` (an
  /// error, empty on success) is printed by the lowest failed rank only.
  /// Returns the exit code: `code`, or 1 on a rank that succeeded while
  /// another failed.
  int finish(int code, const std::string& message);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stratum::cli
