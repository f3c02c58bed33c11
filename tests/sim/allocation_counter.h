/// @file allocation_counter.h
/// @brief Test support: replaces global operator new/delete to count allocations, so a test can assert that a
/// per-frame call allocates nothing. Include it in exactly ONE translation unit of a test executable (a unit
/// that only reads the counters defines LUNGAR_ALLOCATION_COUNTERS_ONLY first: GCC warns of mismatched new and
/// free where the replacements are inlined into code that allocates). Under AddressSanitizer (which owns operator new) nothing is replaced; such tests skip when __SANITIZE_ADDRESS__.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

#if !defined(__SANITIZE_ADDRESS__)
namespace lungar::testing {
inline std::atomic<long> g_allocations{0};
/// This thread's allocations only: for a frame-side call while other threads (DDS, a tracker) allocate.
inline thread_local long g_thread_allocations = 0;
}  // namespace lungar::testing

#if !defined(LUNGAR_ALLOCATION_COUNTERS_ONLY)
void* operator new(std::size_t n) {
  lungar::testing::g_allocations.fetch_add(1, std::memory_order_relaxed);
  ++lungar::testing::g_thread_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
// Not inlined: GCC would otherwise see free() applied to what the replaced operator new returned and warn
// (-Wmismatched-new-delete), although the pair is consistent (malloc and free).
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif
#endif
