// arrangements/tools/memory_budget.cpp: see memory_budget.h.
#include "memory_budget.h"

#include <gmp.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include "arrangements/memory_budget.h"

namespace arrangements::tools {
namespace {

// Signed: a GMP number made before install_gmp_counting and released after it is
// subtracted without having been added.
std::atomic<long long> budget{0};
std::atomic<long long> live{0};
std::atomic<long long> peak{0};

// Counts p (just allocated); past the budget, signals the pipeline to stop.
void admit(void* p) {
  const auto n = static_cast<long long>(malloc_usable_size(p));
  const long long now = live.fetch_add(n, std::memory_order_relaxed) + n;
  const long long limit = budget.load(std::memory_order_relaxed);
  if (limit != 0 && now > limit) arrangements::signal_memory_budget_exhausted();
  long long seen = peak.load(std::memory_order_relaxed);
  while (now > seen && !peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {
  }
}

void release(void* p) noexcept {
  if (!p) return;
  live.fetch_sub(static_cast<long long>(malloc_usable_size(p)), std::memory_order_relaxed);
  std::free(p);
}

void* allocate(std::size_t size, std::size_t alignment, bool throwing) {
  if (size == 0) size = 1;
  void* p = nullptr;
  if (alignment <= alignof(std::max_align_t)) {
    p = std::malloc(size);
  } else {
    // aligned_alloc needs a size that is a multiple of the alignment.
    const std::size_t rounded = (size + alignment - 1) / alignment * alignment;
    p = rounded >= size ? std::aligned_alloc(alignment, rounded) : nullptr;
  }
  if (p) {
    admit(p);
    return p;
  }
  if (!throwing) return nullptr;
  throw std::bad_alloc();
}

void* gmp_allocate(std::size_t size) {
  void* p = std::malloc(size);
  if (!p) return nullptr;  // GMP reports it and aborts: the system refused
  admit(p);
  return p;
}
void* gmp_reallocate(void* old, std::size_t, std::size_t size) {
  const auto before = static_cast<long long>(old ? malloc_usable_size(old) : 0);
  void* p = std::realloc(old, size);
  if (!p) return nullptr;
  live.fetch_sub(before, std::memory_order_relaxed);
  admit(p);
  return p;
}
void gmp_free(void* p, std::size_t) { release(p); }

}  // namespace

void set_memory_budget(std::size_t bytes) { budget.store(static_cast<long long>(bytes), std::memory_order_relaxed); }
std::size_t peak_counted_memory() { return static_cast<std::size_t>(std::max(0LL, peak.load(std::memory_order_relaxed))); }
void install_gmp_counting() { mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free); }

}  // namespace arrangements::tools

// The replaceable global allocation functions ([new.delete]): every form routes to
// allocate / release above.
using arrangements::tools::allocate;
using arrangements::tools::release;

void* operator new(std::size_t n) { return allocate(n, 0, true); }
void* operator new[](std::size_t n) { return allocate(n, 0, true); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, 0, false); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, 0, false); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a), true); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a), true); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, static_cast<std::size_t>(a), false);
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, static_cast<std::size_t>(a), false);
}
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
