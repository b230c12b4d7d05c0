// arrangements/tools/memory_budget.cpp: see memory_budget.h.
#include "memory_budget.h"

#include <gmp.h>
#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "arrangements/memory_budget.h"

namespace arrangements::tools {
namespace {

// Signed: a block allocated before the budget was set (or a GMP number made before
// install_gmp_counting) and released after it is subtracted without having been added.
std::atomic<long long> budget{0};
std::atomic<long long> live{0};

// Each thread gathers its allocations and releases and adds them to `live` once they
// amount to a mebibyte either way: one shared atomic per allocation made arrange 25% slower
// on two threads (the cache line moves between the cores). The count is exact to a
// mebibyte per thread.
constexpr long long kGrain = 1 << 20;
thread_local long long pending = 0;

void account(long long bytes) {
  pending += bytes;
  if (pending < kGrain && pending > -kGrain) return;
  const long long now = live.fetch_add(pending, std::memory_order_relaxed) + pending;
  pending = 0;
  if (now > budget.load(std::memory_order_relaxed)) arrangements::signal_memory_budget_exhausted();
}

// Counting only with a budget: without one, operator new is malloc.
bool counting() { return budget.load(std::memory_order_relaxed) != 0; }

void admit(void* p) {
  if (counting()) account(static_cast<long long>(malloc_usable_size(p)));
}

void release(void* p) noexcept {
  if (!p) return;
  if (counting()) account(-static_cast<long long>(malloc_usable_size(p)));
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
  const auto before = static_cast<long long>(old && counting() ? malloc_usable_size(old) : 0);
  void* p = std::realloc(old, size);
  if (!p) return nullptr;
  if (counting()) account(static_cast<long long>(malloc_usable_size(p)) - before);
  return p;
}
void gmp_free(void* p, std::size_t) { release(p); }

}  // namespace

void set_memory_budget(std::size_t bytes) { budget.store(static_cast<long long>(bytes), std::memory_order_relaxed); }
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
