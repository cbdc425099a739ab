// A tube of beam elements rolling with friction over a sinusoidal floor of small amplitude
// (contact always closed, linear regime): the steady vertical acceleration at the tube's middle
// and end against the frequency-domain solution (K + i w C - w^2 M) U = (eps_n + i w c) A
// with M, C, K taken from the solver's own tangent at three step sizes
// (K_eff(s) = K + 2 s C + 4 s^2 M, s = 1/dt, for the trapezoidal rule ).
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "kernels/rolling/solver.hpp"

using namespace rollspec::rolling;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {
const double kPi = 3.141592653589793;

struct Pipe {
  Model model;
  std::vector<int> ids;
  std::vector<double> damping;  // per node
};

Pipe pipe_on_sinusoid(double amplitude, double wavelength, double speed) {
  Pipe p;
  Model& m = p.model;
  m.sections.push_back(circular_section(210e9, 0.3, 7850.0, 0.06, 0.052));
  const double r = 0.03, L = 0.5, eps_n = 2e6, g = 9.81;
  m.surfaces.push_back(line_height_field(make_plane(Vector3d::Zero(), Vector3d::UnitZ()), -0.1, 0.8, 18001,
                                         [&](double s) { return amplitude * std::sin(2.0 * kPi * s / wavelength); }));
  const int elements = 2, nn = 2 * elements + 1;
  const double m_e = m.sections[0].rhoA * L / elements;
  // start on the floor at its static penetration (lumped node weights m_e (1/6, 2/3, 1/6))
  p.ids = add_straight_beam(m, Vector3d(0.0, -0.5 * L, r), Vector3d(0.0, 0.5 * L, r), elements, 0, Vector3d::UnitX());
  for (int i = 0; i < nn; ++i) {
    const double mn = i % 2 == 1 ? 2.0 * m_e / 3.0 : (i == 0 || i == nn - 1 ? m_e / 6.0 : m_e / 3.0);
    m.X[static_cast<std::size_t>(p.ids[static_cast<std::size_t>(i)])].z() -= mn * g / eps_n;
    SurfaceContactLaw law{r, eps_n, 0.3, 4e5, true};
    law.damping = 2.0 * 0.1 * std::sqrt(eps_n * mn);
    p.damping.push_back(law.damping);
    m.surface_contacts.push_back(SurfaceContactPair{p.ids[static_cast<std::size_t>(i)], 0, law});
  }
  m.v0.assign(m.X.size(), Vector3d(speed, 0.0, 0.0));
  m.w0.assign(m.X.size(), Vector3d(0.0, speed / r, 0.0));
  m.gravity = Vector3d(0.0, 0.0, -g);
  return p;
}

// Amplitude of the f0 component of x(t) over [t_from, end] (least squares: a cos + b sin + c).
double harmonic_amplitude(const std::vector<double>& t, const std::vector<double>& x, double f0, double t_from) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < t_from) continue;
    const Eigen::Vector3d phi(std::cos(2 * kPi * f0 * t[k]), std::sin(2 * kPi * f0 * t[k]), 1.0);
    A += phi * phi.transpose();
    b += phi * x[k];
  }
  const Eigen::Vector3d c = A.ldlt().solve(b);
  return std::hypot(c(0), c(1));
}
}  // namespace

TEST_CASE("rolling pipe over a sinusoidal floor: steady acceleration = frequency-domain solution" *
          doctest::test_suite("long")) {
  const double A = 2e-7, v = 2.0;
  for (double f0 : {120.0, 450.0, 1500.0}) {
    const double lambda = v / f0;
    Pipe p = pipe_on_sinusoid(A, lambda, v);
    // M, C, K from the tangent at q = 0 (the resting, rolling tube) for s = 1/dt in {1e4, 2e4, 4e4}
    SolverOptions o;
    o.force_tol = 1e-10;
    o.max_line_search = 8;
    const int n = 6 * static_cast<int>(p.model.X.size());
    MatrixXd Ks[3];
    const double s[3] = {1e4, 2e4, 4e4};
    {
      Pipe flat = pipe_on_sinusoid(0.0, lambda, v);  // equilibrium geometry: contact normals along z
      Solver S(flat.model, o);
      VectorXd r;
      for (int i = 0; i < 3; ++i) S.residual_and_tangent(VectorXd::Zero(n), 1.0 / s[i], 1.0 / s[i], r, &Ks[i]);
    }
    // K_eff(s) = K + 2 s C + 4 s^2 M: second differences give M, first differences C
    const MatrixXd M = ((Ks[2] - Ks[1]) / (s[2] - s[1]) - (Ks[1] - Ks[0]) / (s[1] - s[0])) / (4.0 * (s[2] - s[0]));
    const MatrixXd C = ((Ks[1] - Ks[0]) / (s[1] - s[0]) - 4.0 * M * (s[1] + s[0])) / 2.0;
    const MatrixXd K = Ks[0] - 2.0 * s[0] * C - 4.0 * s[0] * s[0] * M;
    const double w = 2.0 * kPi * f0;
    Eigen::MatrixXcd D = K.cast<std::complex<double>>() +
                         std::complex<double>(0.0, w) * C.cast<std::complex<double>>() -
                         w * w * M.cast<std::complex<double>>();
    Eigen::VectorXcd F = Eigen::VectorXcd::Zero(n);
    for (std::size_t i = 0; i < p.ids.size(); ++i)
      F(6 * p.ids[i] + 2) = (2e6 + std::complex<double>(0.0, w) * p.damping[i]) * A;  // floor h = A e^{i w t}
    const Eigen::VectorXcd U = D.partialPivLu().solve(F);
    // The trapezoidal rule's own steady state: velocity and acceleration of a
    // sampled harmonic are s_d U and s_d^2 U with s_d = i (2/dt) tan(w dt/2); the floor's rate in
    // the damper is the exact one (nu . v sees the slope at the node).
    const double dt = 2.5e-5;
    const std::complex<double> sd(0.0, 2.0 / dt * std::tan(0.5 * w * dt));
    Eigen::MatrixXcd Dd =
        K.cast<std::complex<double>>() + sd * C.cast<std::complex<double>>() + sd * sd * M.cast<std::complex<double>>();
    const Eigen::VectorXcd Ud = Dd.partialPivLu().solve(F);
    // time domain: 0.3 s at dt = 2.5e-5 (contact period of the lightest node 2.1e-3 s)
    RunOptions ro;
    ro.dt = dt;
    ro.t_end = 0.3;
    ro.record_nodes = {p.ids[2], p.ids[0]};  // middle and end
    ro.record_energies = false;
    const History h = run(p.model, o, ro);
    REQUIRE(h.completed);
    for (int j = 0; j < 2; ++j) {
      std::vector<double> az;
      for (const auto& a : h.acceleration) az.push_back(a[static_cast<std::size_t>(j)].z());
      const double td = harmonic_amplitude(h.time, az, f0, 0.15);
      const int dof = 6 * ro.record_nodes[static_cast<std::size_t>(j)] + 2;
      const double fd = w * w * std::abs(U(dof)), fdd = std::norm(sd) * std::abs(Ud(dof));
      std::printf(
          "rolling pipe on a sinusoid, f0 = %6.0f Hz, %s node: acceleration amplitude %.5e (time domain) vs %.5e "
          "(discrete frequency domain) %+.2e; continuous frequency domain %.5e (%+.2e)\n",
          f0, j == 0 ? "middle" : "end", td, fdd, td / fdd - 1.0, fd, td / fd - 1.0);
      CHECK(std::abs(td / fdd - 1.0) < 3e-3);
      if (f0 < 1000.0) CHECK(std::abs(td / fd - 1.0) < 3e-3);  // w dt < 0.1: the rule's warp is below 1e-3
    }
    bool closed = true;
    for (std::size_t k = 0; k < h.time.size(); ++k)
      for (const auto& e : h.surface_contact[k]) closed = closed && (h.time[k] < 0.15 || e.active);
    CHECK(closed);  // the linear regime the comparison needs, over the fitted window
  }
}
