// arrangements/memory_budget.h: ending a run cleanly when a memory budget is exhausted.
//
// The library does not count memory: a program that does (arrange --max-memory counts its
// heap in a replaced operator new, arrangements/tools/memory_budget.cpp) calls
// signal_memory_budget_exhausted() when the budget is passed. The pipeline's stages look
// at that signal between units of work (a candidate pair, a classified pair, a triangle
// to triangulate, a point or constraint inserted, a pair checked, a rounding round, a
// stage) and end the run by throwing MemoryBudgetExhausted, from their own code: never from
// inside an allocation, where a third-party type (CGAL::Mpzf, GMP) could be left broken.
// A run therefore stops within one unit of work after the budget is passed.
//
// Thread safety: the signal is one atomic flag; set it from any thread. Cost of a check: one
// relaxed atomic load.
#pragma once

#include <atomic>
#include <stdexcept>

namespace arrangements {

struct MemoryBudgetExhausted : std::runtime_error {
  MemoryBudgetExhausted() : std::runtime_error("the memory budget is exhausted") {}
};

namespace detail {
inline std::atomic<bool> memory_budget_exhausted{false};
}  // namespace detail

inline void signal_memory_budget_exhausted() noexcept {
  detail::memory_budget_exhausted.store(true, std::memory_order_relaxed);
}
inline void clear_memory_budget_signal() noexcept {
  detail::memory_budget_exhausted.store(false, std::memory_order_relaxed);
}

namespace detail {
// Throws MemoryBudgetExhausted once the signal is set (the stages' check between units).
inline void memory_checkpoint() {
  if (memory_budget_exhausted.load(std::memory_order_relaxed)) [[unlikely]]
    throw MemoryBudgetExhausted();
}
}  // namespace detail

}  // namespace arrangements
