#include "model/mem/way_search.h"

#ifdef __x86_64__
#include <immintrin.h>
#endif

namespace rtsim {
namespace {

#ifdef __x86_64__
[[gnu::target("avx2")]] uint32_t search_avx2(const uint64_t* tags, uint32_t count, uint64_t tag) {
  const __m256i key = _mm256_set1_epi64x(int64_t(tag));
  uint64_t hits = 0;  // bit i: tag i is equal (the first 64 tags)
  uint32_t i = 0;
  for (; i + 4 <= count && i < 64; i += 4) {
    __m256i equal =
        _mm256_cmpeq_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(tags + i)), key);
    hits |= uint64_t(_mm256_movemask_pd(_mm256_castsi256_pd(equal))) << i;
  }
  uint32_t found = hits ? uint32_t(__builtin_ctzll(hits)) : ~0u;
  for (; i < count; ++i) found = tags[i] == tag && found == ~0u ? i : found;
  return found;
}
#endif

}  // namespace

uint32_t find_way_portable(const uint64_t* tags, uint32_t count, uint64_t tag) {
  uint32_t found = ~0u;
  for (uint32_t i = count; i-- > 0;) found = tags[i] == tag ? i : found;
  return found;
}

WaySearch find_way_avx2() {
#ifdef __x86_64__
  __builtin_cpu_init();  // a cache may be built before libgcc has initialised the CPU model
  if (__builtin_cpu_supports("avx2")) return search_avx2;
#endif
  return nullptr;
}

WaySearch way_search() {
  WaySearch avx2 = find_way_avx2();
  return avx2 ? avx2 : find_way_portable;
}

}  // namespace rtsim
