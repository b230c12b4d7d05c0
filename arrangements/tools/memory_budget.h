// arrangements/tools/memory_budget.h: the heap budget of the command-line tools
// (arrange --max-memory MB).
//
// memory_budget.cpp replaces the global operator new / delete of the program it is linked
// into and, once a budget is set, counts the live bytes of every C++ allocation
// (malloc_usable_size, to a mebibyte per thread), and of
// GMP's (mp_set_memory_functions, installed by install_gmp_counting). When the live total
// passes the budget it calls arrangements::signal_memory_budget_exhausted(); the
// pipeline's stages then end the run with arrangements::MemoryBudgetExhausted at their next
// check (arrangements/memory_budget.h). Allocations themselves are never refused for the
// budget: a bad_alloc thrown inside CGAL::Mpzf or GMP can leave them broken (a crash
// instead of an error).
//
// What is counted: heap blocks as allocated (capacity that is never touched counts, so
// the resident size can stay below the budget; thread stacks, the program and
// fragmentation do not, so it can also pass it by some megabytes).
// Only for executables: a library must not replace a program's operator new.
// Cost: without a budget none (operator new is malloc); with one, a thread-local sum per
// allocation and a shared atomic add per mebibyte.
#pragma once

#include <cstddef>

namespace arrangements::tools {

// The budget in bytes; 0 (the default) for none. Set it before the work starts.
void set_memory_budget(std::size_t bytes);
// Routes GMP's allocations through the counter (call once, before any GMP number exists).
void install_gmp_counting();

}  // namespace arrangements::tools
