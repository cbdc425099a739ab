#pragma once
// Adaptive Dormand–Prince 5(4) with dense output (Dormand & Prince 1980; Hairer, Nørsett & Wanner,
// Solving ODEs I, §II.4–II.6, the code DOPRI5), README Eq. (B27): the seeds' ode45. FSAL, local
// extrapolation, error norm sqrt(mean((err_i / (atol_i + rtol max(|y0_i|, |y1_i|)))^2)), step
// factor 0.9 err^{-1/5} limited to [0.2, 10], fourth-order continuous extension for outputs.
#include <cstddef>
#include <functional>
#include <vector>

namespace rollspec::beam {

struct Dopri5Options {
  double rtol = 1e-8;
  std::vector<double> atol;   // per component (size n), required
  double initial_step = 0.0;  // 0: h0 = 1e-3 of the interval... chosen by Hairer's starting rule
  double max_step = 0.0;      // 0: unlimited
  long max_steps = 100'000'000;
};

struct Dopri5Stats {
  long accepted = 0, rejected = 0, evaluations = 0;
};

using OdeRhs = std::function<void(double t, const double* y, double* dydt)>;
using OdeObserver = std::function<void(std::size_t index, double t, const double* y)>;

// Integrates y' = f(t, y) from t0 with y(t0) = y0 up to the last output time; calls observe(j, t_j,
// y(t_j)) for every t_j in `outputs` (nondecreasing, >= t0), y from the dense output.
Dopri5Stats dopri5(const OdeRhs& f, std::vector<double> y0, double t0, const std::vector<double>& outputs,
                   const OdeObserver& observe, const Dopri5Options& options);

}  // namespace rollspec::beam
