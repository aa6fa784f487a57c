#pragma once
/// @file
/// The first exception any thread of an OpenMP loop threw, kept to be rethrown after the loop
/// (an exception may not leave a parallel region).

#include <exception>
#include <memory>

#include "spaces/space.hpp"

namespace iga {

class FirstFailure {
 public:
  /// Call inside a catch block: keeps the exception in flight unless one was kept before.
  void keep() {
#pragma omp critical(iga_first_failure)
    if (!failure_) failure_ = std::current_exception();
  }
  /// Rethrow the kept exception, if any (after the parallel region).
  void rethrow() const {
    if (failure_) std::rethrow_exception(failure_);
  }
  /// One evaluator per thread: a failure to make one is kept like an element's, and the thread's
  /// loop skips its elements (null).
  std::unique_ptr<Space::Evaluator> make_evaluator(const Space& space) {
    try {
      return space.make_evaluator();
    } catch (...) {
      keep();
      return nullptr;
    }
  }

 private:
  std::exception_ptr failure_;
};

}  // namespace iga
