// Moving constant force on a simply supported beam against Frýba's closed form (README B29–B30).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "kernels/beam/modal_beam.hpp"
#include "kernels/beam/moving_force.hpp"

using namespace rollspec::beam;

namespace {
constexpr double kPi = 3.14159265358979323846;

// A 0.4 m simply supported beam (30 modes) crossed by a constant force at speed parameter
// alpha = pi v / (l omega_1), sampled at three points every 2e-7 s.
struct MovingForceRun {
  double v = 0.0, dt = 2e-7;
  long steps = 0;
  std::vector<double> xs;
  std::vector<std::vector<double>> w;
};
MovingForceRun run_moving_force(const ModalBeam& beam, double l, double load, double alpha) {
  MovingForceRun r;
  r.v = alpha * beam.omega(0) * l / kPi;
  r.steps = static_cast<long>(std::floor(l / r.v / r.dt));
  const std::vector<double> force(static_cast<std::size_t>(r.steps + 1), load);
  r.xs = {0.25 * l, 0.5 * l, 0.8 * l};
  r.w = moving_force_deflection(beam, 0.0, r.v, force, r.dt, r.xs);
  return r;
}

// Every 7th sample of each point of a run: f(point x, time t, computed deflection w).
template <class F>
void for_samples(const MovingForceRun& r, F&& f) {
  for (std::size_t i = 0; i < r.xs.size(); ++i)
    for (long k = 0; k <= r.steps; k += 7) f(r.xs[i], static_cast<double>(k) * r.dt, r.w[i][k]);
}

// The beam both tests cross: 0.4 m, simply supported, 30 modes (the closed forms' terms too), modal `damping`,
// crossed by 100 N; l, EI and mu for the closed forms.
struct CrossedBeam {
  static constexpr int modes = 30;
  static constexpr double load = 100.0;
  ModalBeam beam;
  double l, ei, mu;
  explicit CrossedBeam(const ModalDamping& damping)
      : beam(properties(), {modes, 0.0}, damping),
        l(beam.properties().length),
        ei(beam.bending_stiffness()),
        mu(beam.mass_per_length()) {}
  // At speed parameter alpha = pi v / (l omega_1).
  MovingForceRun run(double alpha) const { return run_moving_force(beam, l, load, alpha); }

 private:
  static BeamProperties properties() {
    BeamProperties p;
    p.support = Support::simply_supported;
    p.length = 0.4;
    return p;
  }
};
}  // namespace

TEST_CASE("moving constant force on a simply supported beam matches Frýba's closed form") {
  const CrossedBeam crossed({});  // undamped, as Frýba's series
  const double l = crossed.l, ei = crossed.ei, mu = crossed.mu;
  const int modes = CrossedBeam::modes;
  const double load = CrossedBeam::load;
  for (double alpha : {0.1, 0.5, 1.3}) {
    const MovingForceRun r = crossed.run(alpha);
    double worst = 0.0, peak = 0.0;
    for_samples(r, [&](double x, double t, double w) {
      const double ref = -fryba_moving_force(l, ei, mu, load, r.v, x, t, modes);
      worst = std::max(worst, std::abs(w - ref));
      peak = std::max(peak, std::abs(ref));
    });
    MESSAGE("alpha " << alpha << ": max |w - w_Fryba| / max |w_Fryba| = " << worst / peak
                     << ", peak midspan / static P l^3/(48 EI) = " << peak / (load * l * l * l / (48.0 * ei)));
    CHECK(worst <= 1e-6 * peak);
  }
  // A wrong modal mass or a wrong sign is caught: the dynamic peak differs from the static one.
  const double v = 0.5 * crossed.beam.omega(0) * l / kPi;
  CHECK(std::abs(fryba_moving_force(l, ei, mu, load, v, 0.5 * l, 0.5 * l / v, 60) / (load * l * l * l / (48.0 * ei)) -
                 1.0) > 0.05);
}

namespace {
// The damped beam's closed form (Frýba 1972, §1.3, with modal damping; the test's own reference): each simply
// supported mode j obeys q'' + 2 zeta w_j q' + w_j^2 q = (2P/(mu l)) sin(j w t) from rest, so
// q = A sin(Wt) + B cos(Wt) + e^(-zeta w_j t)(C1 cos(w_d t) + C2 sin(w_d t)), W = j w, w = pi v / l;
// deflection positive down, w = sum_j q_j sin(j pi x / l).
double damped_moving_force(double l, double ei, double mu, double load, double v, double x, double t, int terms,
                           double zeta) {
  const double pi = 3.14159265358979323846, w1 = pi * pi / (l * l) * std::sqrt(ei / mu), om = pi * v / l;
  const double f = 2.0 * load / (mu * l);
  double s = 0.0;
  for (int j = 1; j <= terms; ++j) {
    const double wj = j * j * w1, big_w = j * om, d2 = wj * wj - big_w * big_w, c = 2.0 * zeta * wj * big_w;
    const double a = f * d2 / (d2 * d2 + c * c), b = -f * c / (d2 * d2 + c * c);
    const double wd = wj * std::sqrt(1.0 - zeta * zeta), c1 = -b, c2 = (zeta * wj * c1 - a * big_w) / wd;
    s += (a * std::sin(big_w * t) + b * std::cos(big_w * t) +
          std::exp(-zeta * wj * t) * (c1 * std::cos(wd * t) + c2 * std::sin(wd * t))) *
         std::sin(j * pi * x / l);
  }
  return s;
}
}  // namespace

// A damped beam (loss factor 0.01, the studies' beams have 0.005-0.01) departs from Frýba's undamped series by
// a few 1e-3 of the peak: the damping the series leaves out, not an error of the modal steps, which follow the
// damped closed form as closely as the undamped one.
TEST_CASE("moving constant force on a damped simply supported beam matches the damped modal closed form") {
  const double loss_factor = 0.01;
  const CrossedBeam crossed({loss_factor, {}});
  const double l = crossed.l, ei = crossed.ei, mu = crossed.mu;
  const int modes = CrossedBeam::modes;
  const double load = CrossedBeam::load;
  for (double alpha : {0.1, 0.5, 1.3}) {
    const MovingForceRun r = crossed.run(alpha);
    double worst = 0.0, undamped = 0.0, peak = 0.0;
    for_samples(r, [&](double x, double t, double w) {
      const double ref = -damped_moving_force(l, ei, mu, load, r.v, x, t, modes, 0.5 * loss_factor);
      worst = std::max(worst, std::abs(w - ref));
      undamped = std::max(undamped, std::abs(w + fryba_moving_force(l, ei, mu, load, r.v, x, t, modes)));
      peak = std::max(peak, std::abs(ref));
    });
    MESSAGE("loss factor " << loss_factor << ", alpha " << alpha << ": max |w - w_damped| / peak = " << worst / peak
                           << ", max |w - w_Fryba,undamped| / peak = " << undamped / peak);
    CHECK(worst <= 1e-6 * peak);
    CHECK(undamped > 1e-3 * peak);  // the undamped series is not what a damped beam does
  }
}
