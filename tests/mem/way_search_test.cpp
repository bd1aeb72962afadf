// The tag search (model/mem/way_search.h): the portable and the AVX2 search (where the host has
// it) find the same way in sets of every size a cache allows, with the tag in each way or in none,
// tags that differ from the one looked for in one 32-bit half only, and more than 64 ways.
#include "model/mem/way_search.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace rtsim {
namespace {

std::vector<WaySearch> searches() {
  std::vector<WaySearch> all{find_way_portable};
  if (WaySearch avx2 = find_way_avx2()) all.push_back(avx2);
  return all;
}

TEST(WaySearch, FindsTheWayHoldingTheTagOrNone) {
  std::mt19937_64 random(7);
  const uint64_t tag = 0x1234'5678'9abc'def0ull;
  for (uint32_t ways : {1u, 2u, 3u, 4u, 5u, 7u, 8u, 12u, 16u, 31u, 32u, 64u, 65u, 96u, 1024u}) {
    std::vector<uint64_t> tags(ways);
    for (uint64_t& t : tags) {
      // Equal in one half: a search must compare whole tags.
      switch (random() % 3) {
        case 0: t = tag ^ (uint64_t(1) << (random() % 32)); break;
        case 1: t = tag ^ (uint64_t(1) << (32 + random() % 32)); break;
        default: t = ~uint64_t(0); break;  // an empty way
      }
    }
    for (WaySearch search : searches()) {
      EXPECT_EQ(search(tags.data(), ways, tag), ~0u) << ways << " ways";
      for (uint32_t w = 0; w < ways; ++w) {
        uint64_t kept = tags[w];
        tags[w] = tag;
        EXPECT_EQ(search(tags.data(), ways, tag), w) << ways << " ways";
        tags[w] = kept;
      }
    }
  }
}

TEST(WaySearch, TheHostsSearchIsOneOfThem) {
  WaySearch chosen = way_search();
  WaySearch avx2 = find_way_avx2();
  EXPECT_EQ(chosen, avx2 ? avx2 : find_way_portable);
}

}  // namespace
}  // namespace rtsim
