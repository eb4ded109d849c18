#pragma once
// Counts heap allocations made by the running program while a counter is alive, so a test can
// forbid allocation in a hot loop (in the spirit of Drake's LimitMalloc). allocation_counter.cpp
// replaces the global operator new and delete (every variant) for the whole test program; they
// forward to malloc / free and only count when asked to.
//
//   {
//     AllocationCounter counter;   // starts counting
//     integrator.step(t_end);
//     EXPECT_EQ(counter.count(), 0);
//   }                              // stops counting
//
// Counting is global (all threads); counters must not be nested.
namespace tumble::test {

class AllocationCounter {
 public:
  AllocationCounter();
  ~AllocationCounter();
  AllocationCounter(const AllocationCounter&) = delete;
  AllocationCounter& operator=(const AllocationCounter&) = delete;

  // Allocations (calls of any operator new) since construction.
  long count() const;
};

}  // namespace tumble::test
