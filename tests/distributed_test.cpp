// The share arithmetic of stratum/distributed.hpp, and its one-process
// behaviour (the MPI runs themselves: tests/apps/mpi_runs.sh).
#include "stratum/distributed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

/// A group of `size` processes seen from `rank`, recording what it is asked to gather.
class RecordingGroup final : public stratum::distributed::Group {
 public:
  RecordingGroup(int rank, int size) : rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void gather(double*, const std::vector<stratum::distributed::Share>& segments) override { gathered = segments; }
  bool any(bool flag) override { return flag; }
  std::vector<stratum::distributed::Share> gathered;

 private:
  int rank_, size_;
};

struct Installed {
  explicit Installed(stratum::distributed::Group* group) { stratum::distributed::set_group(group); }
  ~Installed() { stratum::distributed::set_group(nullptr); }
};

TEST(Distributed, AloneEveryShareIsEverything) {
  EXPECT_EQ(stratum::distributed::rank(), 0);
  EXPECT_EQ(stratum::distributed::size(), 1);
  EXPECT_TRUE(stratum::distributed::is_root());
  const auto share = stratum::distributed::share(17);
  EXPECT_EQ(share.begin, 0u);
  EXPECT_EQ(share.end, 17u);
}

TEST(Distributed, SharesAreContiguousDisjointAndCoverEveryItem) {
  for (int size : {1, 2, 3, 7, 64}) {
    RecordingGroup group(0, size);
    Installed installed(&group);
    for (std::size_t count : {0u, 1u, 2u, 5u, 63u, 64u, 65u, 1000u}) {
      std::size_t next = 0, largest = 0, smallest = count;
      for (int r = 0; r < size; ++r) {
        const auto share = stratum::distributed::share_of(count, r);
        EXPECT_EQ(share.begin, next) << "count " << count << " size " << size << " rank " << r;
        EXPECT_LE(share.begin, share.end);
        largest = std::max(largest, share.end - share.begin);
        smallest = std::min(smallest, share.end - share.begin);
        next = share.end;
      }
      EXPECT_EQ(next, count) << "count " << count << " size " << size;
      EXPECT_LE(largest - smallest, 1u) << "shares differ by more than one item";
    }
  }
}

TEST(Distributed, GatherAsksForEachRanksSegmentOfVariableWidthItems) {
  RecordingGroup group(1, 3);
  Installed installed(&group);
  // Items 0..4 of widths 1, 2, 3, 4, 5: offsets 0, 1, 3, 6, 10, 15.
  const std::vector<std::size_t> offsets = {0, 1, 3, 6, 10, 15};
  std::vector<double> data(15);
  stratum::distributed::gather_shares(data, 5, [&](std::size_t i) { return offsets[i]; });
  ASSERT_EQ(group.gathered.size(), 3u);
  // shares of 5 items on 3 ranks: [0,1), [1,3), [3,5)
  EXPECT_EQ(group.gathered[0].begin, 0u);
  EXPECT_EQ(group.gathered[0].end, 1u);
  EXPECT_EQ(group.gathered[1].begin, 1u);
  EXPECT_EQ(group.gathered[1].end, 6u);
  EXPECT_EQ(group.gathered[2].begin, 6u);
  EXPECT_EQ(group.gathered[2].end, 15u);
  EXPECT_THROW(stratum::distributed::gather_shares(data, 4, [&](std::size_t i) { return offsets[i]; }),
               std::logic_error);
}

/// A group that plays the other processes: it fills their segments with 1000 + position.
class FillingGroup final : public stratum::distributed::Group {
 public:
  FillingGroup(int rank, int size) : rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void gather(double* data, const std::vector<stratum::distributed::Share>& segments) override {
    for (int r = 0; r < size_; ++r)
      if (r != rank_)
        for (std::size_t at = segments[std::size_t(r)].begin; at < segments[std::size_t(r)].end; ++at)
          data[at] = 1000.0 + double(at);
  }
  bool any(bool flag) override { return flag; }

 private:
  int rank_, size_;
};

TEST(Distributed, DealtItemsAreRoundRobinAndGatheredIntoPlace) {
  FillingGroup group(1, 3);
  Installed installed(&group);
  const auto mine = stratum::distributed::dealt(7);
  ASSERT_EQ(mine.size(), 2u);  // items 1 and 4 of 0..6
  EXPECT_EQ(mine[0], 1u);
  EXPECT_EQ(mine[1], 4u);
  std::vector<double> data(14, -1.0);  // 7 items of width 2
  for (std::size_t j = 0; j < mine.size(); ++j) data[2 * mine[j]] = 10.0 * double(mine[j]), data[2 * mine[j] + 1] = 0.5;
  stratum::distributed::gather_dealt(data, 7);
  // Packed by process: rank 0's items 0, 3, 6 at positions 0–5, rank 1's 1, 4 at 6–9, rank 2's 2, 5 at 10–13.
  const std::size_t position[7] = {0, 6, 10, 2, 8, 12, 4};
  for (std::size_t i = 0; i < 7; ++i) {
    if (i == 1 || i == 4) {
      EXPECT_EQ(data[2 * i], 10.0 * double(i));
      EXPECT_EQ(data[2 * i + 1], 0.5);
    } else {
      EXPECT_EQ(data[2 * i], 1000.0 + double(position[i])) << "item " << i;
      EXPECT_EQ(data[2 * i + 1], 1001.0 + double(position[i])) << "item " << i;
    }
  }
  EXPECT_EQ(stratum::distributed::dealt(1).size(), 0u);  // fewer items than processes: rank 1 has none
}

TEST(Distributed, DealtItemsOfVariableWidthAreGatheredIntoPlace) {
  // The render's tile rows: the last is short. 5 items of widths 3, 3, 3, 3, 1 on 2 processes, seen from rank 0.
  FillingGroup group(0, 2);
  Installed installed(&group);
  const std::vector<std::size_t> offsets = {0, 3, 6, 9, 12, 13};
  const auto offset = [&](std::size_t i) { return offsets[i]; };
  std::vector<double> data(13, -1.0);
  for (std::size_t item : {0u, 2u, 4u})  // rank 0's
    for (std::size_t at = offsets[item]; at < offsets[item + 1]; ++at) data[at] = double(at);
  stratum::distributed::gather_dealt(data, 5, offset);
  // Packed: rank 0's items 0, 2, 4 at 0–2, 3–5, 6; rank 1's items 1, 3 at 7–9, 10–12.
  for (std::size_t at = 0; at < 13; ++at) {
    const bool mine = at < 3 || (at >= 6 && at < 9) || at == 12;
    if (mine) {
      EXPECT_EQ(data[at], double(at)) << at;
    }
  }
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(data[3 + j], 1000.0 + double(7 + j));   // item 1
    EXPECT_EQ(data[9 + j], 1000.0 + double(10 + j));  // item 3
  }
  EXPECT_THROW(stratum::distributed::gather_dealt(data, 4, offset), std::logic_error);
}

}  // namespace
