#pragma once
/// Work split over the processes of one job (MPI ranks, or this process
/// alone). Every result of stratum is a pure function of (seed, index,
/// dimension), so a job's independent items (runs, row blocks, tile rows)
/// can be computed anywhere: each process computes its share (a contiguous
/// block, or items dealt round-robin where the cost varies along the list)
/// and the shares are gathered, after which every process holds
/// the same array the one-process run fills, and reduces it in the same
/// fixed order. The result is therefore identical, bit for bit, to one
/// process for any number of processes (docs/distributed.md).
///
/// Without a group installed (the library, Python, a plain `stratum` run)
/// this process is rank 0 of 1 and every function here is trivial.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <span>
#include <stdexcept>
#include <vector>

namespace stratum::distributed {

/// Items [begin, end) of a job's list.
struct Share {
  std::size_t begin = 0, end = 0;
};

/// The processes of a job: the MPI implementation lives with the CLI
/// (apps/stratum/distributed_job.cpp), so the libraries need no MPI.
class Group {
 public:
  virtual ~Group() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Every process has filled `segments[rank()]` of `data`; afterwards every
  /// process holds every segment.
  virtual void gather(double* data, const std::vector<Share>& segments) = 0;
  /// Whether `flag` is true on any process (the same answer on all).
  virtual bool any(bool flag) = 0;
};

/// Thrown on the other processes when one process of the job failed: that
/// process reports its own error, these leave quietly with a non-zero code.
class PeerFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {
/// The installed group (nullptr: this process alone); one per program.
inline std::atomic<Group*> installed_group{nullptr};
}  // namespace detail

/// Installs the job's group (nullptr: this process alone). Not owned.
inline void set_group(Group* group) { detail::installed_group.store(group); }

inline int rank() {
  const Group* group = detail::installed_group.load();
  return group ? group->rank() : 0;
}

inline int size() {
  const Group* group = detail::installed_group.load();
  return group ? group->size() : 1;
}

/// Rank 0: the process that writes the job's output (the writers of io,
/// render, plot and report do nothing on the other ranks).
inline bool is_root() { return rank() == 0; }

/// The contiguous share of `count` items that `rank` computes:
/// [⌊count·rank/size⌋, ⌊count·(rank+1)/size⌋), empty when count < size.
inline Share share_of(std::size_t count, int rank) {
  const auto processes = static_cast<unsigned __int128>(size());
  const auto r = static_cast<unsigned __int128>(rank);
  return {static_cast<std::size_t>(count * r / processes), static_cast<std::size_t>(count * (r + 1) / processes)};
}

/// This process's share.
inline Share share(std::size_t count) { return share_of(count, rank()); }

/// After this process filled its share of `count` items in `data`, item i
/// occupying [offset(i), offset(i + 1)) (offset(count) = data.size()),
/// fills in the other processes' shares.
inline void gather_shares(std::span<double> data, std::size_t count,
                          const std::function<std::size_t(std::size_t)>& offset) {
  Group* group = detail::installed_group.load();
  if (!group || group->size() == 1) return;
  if (offset(count) != data.size()) throw std::logic_error("gather_shares: the items do not cover the data");
  std::vector<Share> segments(static_cast<std::size_t>(group->size()));
  for (int r = 0; r < group->size(); ++r) {
    const Share items = share_of(count, r);
    segments[static_cast<std::size_t>(r)] = {offset(items.begin), offset(items.end)};
  }
  group->gather(data.data(), segments);
}

/// The same for items of equal width (data.size() / count values each).
inline void gather_shares(std::span<double> data, std::size_t count) {
  if (count == 0) return;
  if (data.size() % count != 0) throw std::logic_error("gather_shares: items of unequal width");
  const std::size_t width = data.size() / count;
  gather_shares(data, count, [width](std::size_t i) { return i * width; });
}

/// Items dealt round-robin: this process takes items rank, rank + size,
/// rank + 2·size, … of `count`. For lists whose cost varies along the list
/// (runs at growing N, samplers of different cost), where contiguous shares
/// would leave one process most of the work.
struct Dealt {
  std::size_t first = 0, stride = 1, count = 0;
  /// How many items this process takes, and the j-th of them.
  std::size_t size() const { return count > first ? (count - first + stride - 1) / stride : 0; }
  std::size_t operator[](std::size_t j) const { return first + j * stride; }
};
inline Dealt dealt(std::size_t count) { return {std::size_t(rank()), std::size_t(size()), count}; }

/// After this process filled its dealt items of `data`, item i occupying
/// [offset(i), offset(i + 1)) (offset(count) = data.size()), fills in the
/// other processes' items.
inline void gather_dealt(std::span<double> data, std::size_t count,
                         const std::function<std::size_t(std::size_t)>& offset) {
  Group* group = detail::installed_group.load();
  if (!group || group->size() == 1 || count == 0) return;
  if (offset(count) != data.size()) throw std::logic_error("gather_dealt: the items do not cover the data");
  const std::size_t processes = std::size_t(group->size()), me = std::size_t(group->rank());
  const auto width = [&](std::size_t i) { return offset(i + 1) - offset(i); };
  // Packed by process (process r's items r, r + K, … side by side), gathered, unpacked.
  std::vector<Share> segments(processes);
  std::vector<double> packed(data.size());
  std::size_t at = 0;
  for (std::size_t r = 0; r < processes; ++r) {
    segments[r].begin = at;
    for (std::size_t i = r; i < count; i += processes) {
      if (r == me) std::copy_n(data.data() + offset(i), width(i), packed.data() + at);
      at += width(i);
    }
    segments[r].end = at;
  }
  group->gather(packed.data(), segments);
  for (std::size_t r = 0, from = 0; r < processes; ++r)
    for (std::size_t i = r; i < count; i += processes) {
      std::copy_n(packed.data() + from, width(i), data.data() + offset(i));
      from += width(i);
    }
}

/// The same for items of equal width (data.size() / count values each).
inline void gather_dealt(std::span<double> data, std::size_t count) {
  if (count == 0) return;
  if (data.size() % count != 0) throw std::logic_error("gather_dealt: items of unequal width");
  const std::size_t width = data.size() / count;
  gather_dealt(data, count, [width](std::size_t i) { return i * width; });
}

/// Whether `flag` is true on any process: a decision every process must
/// take alike (stop after this pass?) from values that may differ.
inline bool any(bool flag) {
  Group* group = detail::installed_group.load();
  return group ? group->any(flag) : flag;
}

}  // namespace stratum::distributed
