#pragma once
// One rank's failure, told to every rank: each takes part in the vote (any_rank is collective), so a
// failure on one rank never leaves the others waiting in a later collective.
#include <exception>
#include <string>

#include "src/ensemble/mpi_context.hpp"
#include "src/error.hpp"

namespace rollspec::ensemble {

// Rethrows this rank's own `failure`; where only another rank failed, stops with `message` (EX_SOFTWARE:
// that rank has printed its own error).
inline void rethrow_on_every_rank(const std::exception_ptr& failure, const std::string& message) {
  const bool failed_somewhere = any_rank(failure != nullptr);
  if (failure) std::rethrow_exception(failure);
  if (failed_somewhere) throw UserError(EX_SOFTWARE, message);
}

}  // namespace rollspec::ensemble
