/// DistributedJob: MPI when built with it and launched by mpirun/srun.
#include "distributed_job.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <limits>

#include "stratum/distributed.hpp"

#ifdef STRATUM_MPI
#include <mpi.h>
#endif

namespace stratum::cli {

namespace {

void print_error(int fd, const std::string& message) {
  const std::string line = "stratum: error: " + message + "\n";
  if (fd == STDERR_FILENO) std::fflush(stderr);
  for (std::size_t done = 0; done < line.size();) {
    const ssize_t wrote = ::write(fd, line.data() + done, line.size() - done);
    if (wrote <= 0) return;
    done += static_cast<std::size_t>(wrote);
  }
}

#ifdef STRATUM_MPI
/// Launched as a rank of an MPI job: Open MPI's mpirun, PMI (MPICH, srun
/// --mpi=pmi2) or PMIx (srun --mpi=pmix). A plain run never calls MPI_Init.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

/// MPI_COMM_WORLD as a distributed::Group. Every collective starts with a
/// status exchange, so a rank that failed (and calls report() once instead
/// of the collectives it skips) stops every other rank at its next
/// collective instead of leaving it waiting: no hang, one message.
class MpiGroup final : public distributed::Group {
 public:
  MpiGroup() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    // Fault injection for the tests of the failure path (docs/distributed.md).
    if (const char* fault = std::getenv("STRATUM_FAULT_RANK")) fault_ = std::atoi(fault) == rank_;
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void gather(double* data, const std::vector<distributed::Share>& segments) override {
    check();
    // Broadcasts in chunks: MPI counts are int, a large image is not.
    constexpr std::size_t chunk = std::size_t{1} << 27;
    for (int r = 0; r < size_; ++r) {
      const auto& segment = segments[static_cast<std::size_t>(r)];
      for (std::size_t at = segment.begin; at < segment.end; at += chunk) {
        const int count = static_cast<int>(std::min(chunk, segment.end - at));
        MPI_Bcast(data + at, count, MPI_DOUBLE, r, MPI_COMM_WORLD);
      }
    }
  }

  bool any(bool flag) override {
    check();
    int value = flag ? 1 : 0, result = 0;
    MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return result != 0;
  }

  /// The terminal status exchange: the lowest failed rank, or size() when
  /// none failed. Called once per rank (from check() or from finish()).
  int exchange_status(bool failed) {
    if (!status_exchanged_) {
      int mine = failed ? rank_ : size_;
      MPI_Allreduce(&mine, &lowest_failed_, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
      status_exchanged_ = true;
    }
    return lowest_failed_;
  }

 private:
  void check() {
    if (fault_) {
      fault_ = false;
      throw std::runtime_error(fmt::format("fault injected on rank {} (STRATUM_FAULT_RANK)", rank_));
    }
    if (status_exchanged_) throw distributed::PeerFailure("the job has already failed");
    int mine = size_, lowest = 0;
    MPI_Allreduce(&mine, &lowest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (lowest < size_) {
      status_exchanged_ = true;
      lowest_failed_ = lowest;
      throw distributed::PeerFailure(fmt::format("rank {} failed", lowest));
    }
  }

  int rank_ = 0, size_ = 1, lowest_failed_ = std::numeric_limits<int>::max();
  bool fault_ = false, status_exchanged_ = false;
};
#endif

}  // namespace

struct DistributedJob::Impl {
  int saved_stderr = STDERR_FILENO;
#ifdef STRATUM_MPI
  std::unique_ptr<MpiGroup> group;
#endif
};

DistributedJob::DistributedJob([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv)
    : impl_(std::make_unique<Impl>()) {
#ifdef STRATUM_MPI
  if (!launched_by_mpi()) return;
  MPI_Init(&argc, &argv);
  impl_->group = std::make_unique<MpiGroup>();
  distributed::set_group(impl_->group.get());
  if (impl_->group->rank() != 0) {
    // Rank 0 alone prints and writes; the others keep stderr for their own error.
    impl_->saved_stderr = ::dup(STDERR_FILENO);
    const int sink = ::open("/dev/null", O_WRONLY);
    if (sink >= 0) {
      ::dup2(sink, STDOUT_FILENO);
      ::dup2(sink, STDERR_FILENO);
      ::close(sink);
    }
  }
#endif
}

DistributedJob::~DistributedJob() {
#ifdef STRATUM_MPI
  if (impl_->group) {
    distributed::set_group(nullptr);
    impl_->group.reset();
    MPI_Finalize();
  }
#endif
}

int DistributedJob::finish(int code, const std::string& message) {
#ifdef STRATUM_MPI
  if (impl_->group) {
    const int rank = impl_->group->rank();
    const int lowest = impl_->group->exchange_status(code != 0);
    if (lowest == rank && !message.empty())
      print_error(impl_->saved_stderr, rank == 0 ? message : fmt::format("rank {}: {}", rank, message));
    return code != 0 ? code : (lowest < impl_->group->size() ? 1 : 0);
  }
#endif
  if (!message.empty()) print_error(STDERR_FILENO, message);
  return code;
}

}  // namespace stratum::cli
