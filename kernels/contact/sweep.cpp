#include "kernels/contact/sweep.hpp"

#include <algorithm>
#include <stdexcept>

namespace rollspec::contact {

std::vector<ContactResult> sweep(ContactSolver& solver, const std::vector<double>& gap,
                                 const std::vector<double>& approaches, const SolverOptions& options,
                                 std::vector<double>* pressure) {
  for (std::size_t j = 1; j < approaches.size(); ++j)
    if (!(approaches[j] > approaches[j - 1])) throw std::invalid_argument("sweep: approaches must increase strictly");
  std::vector<double> local;
  std::vector<double>& p = pressure != nullptr ? *pressure : local;
  p.assign(solver.grid().size(), 0.0);
  std::vector<ContactResult> out;
  out.reserve(approaches.size());
  for (std::size_t j = 0; j < approaches.size(); ++j) {
    const std::vector<double>& rate = solver.pressure_rate();
    if (j > 0 && out.back().converged && rate.size() == p.size()) {
      // Eq. 12: p ← Π_[0,H](p + (w_j − w_{j−1}) dp/dw); the solver projects into [0, H].
      const double dw = approaches[j] - approaches[j - 1];
      for (std::size_t i = 0; i < p.size(); ++i) p[i] += dw * rate[i];
    }
    out.push_back(solver.solve(gap, approaches[j], p, options));
  }
  return out;
}

bool all_converged(const std::vector<ContactResult>& results) {
  return std::all_of(results.begin(), results.end(), [](const ContactResult& r) { return r.converged; });
}

}  // namespace rollspec::contact
