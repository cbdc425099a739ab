// Rough rigid surfaces (README Sec. 10, R-60..R-62): Catmull-Rom height field derivatives,
// closest-point contact tangent against central differences, single-point validity, and a
// sphere node moved over a sinusoidal bump following the offset curve of the bump.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "kernels/rolling/examples.hpp"
#include "kernels/rolling/solver.hpp"
#include "tangent_check.hpp"

using namespace rollspec::rolling;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {
const double kPi = 3.141592653589793;

HeightField wavy_grid() {
  return grid_height_field(make_plane(Vector3d(0.1, -0.2, 0.05), Vector3d(0.1, 0.2, 1.0)), {-0.4, 0.02, 40},
                           {-0.35, 0.025, 30}, [](double s1, double s2) {
                             return 0.01 * std::sin(7.0 * s1 + 1.0) * std::cos(5.0 * s2) + 0.004 * std::sin(11.0 * s2);
                           });
}

HeightField bump_line(double H, double lambda, double ds) {
  return line_height_field(
      make_plane(Vector3d::Zero(), Vector3d::UnitZ()), -0.3, 0.5, static_cast<int>(std::lround(0.8 / ds)) + 1,
      [&](double s) { return (s >= 0.0 && s <= lambda) ? 0.5 * H * (1.0 - std::cos(2.0 * kPi * s / lambda)) : 0.0; });
}
}  // namespace

TEST_CASE("height field: gradient and Hessian consistent with the interpolated height") {
  const HeightField f = wavy_grid();
  const double hstep = 1e-6;
  double eg = 0.0, eh = 0.0;
  for (const Vector2d& s : {Vector2d(-0.111, 0.013), Vector2d(0.207, -0.19), Vector2d(0.33, 0.31)}) {
    const HeightSample c = sample_height(f, s);
    for (int k = 0; k < 2; ++k) {
      Vector2d d = Vector2d::Zero();
      d(k) = hstep;
      const HeightSample p = sample_height(f, s + d), m = sample_height(f, s - d);
      eg = std::max(eg, std::abs((p.h - m.h) / (2 * hstep) - c.grad(k)) / c.grad.norm());
      eh = std::max(eh, ((p.grad - m.grad) / (2 * hstep) - c.hess.col(k)).norm() / c.hess.norm());
    }
  }
  std::printf("height field FD: gradient %.2e, Hessian %.2e (relative)\n", eg, eh);
  CHECK(eg < 1e-7);
  CHECK(eh < 1e-6);
  // interpolating: the samples are reproduced
  CHECK(std::abs(sample_height(f, Vector2d(f.s1_0 + 7 * f.ds1, f.s2_0 + 11 * f.ds2)).h - f.h[11 * 40 + 7]) < 1e-15);
}

TEST_CASE("height field: the paired tap sums = the plain tap loop, bit for bit (grid and line, edges, outside)") {
  const HeightField fields[2] = {wavy_grid(), bump_line(0.01, 0.2, 0.01)};
  std::uint64_t x = 12345;
  auto uni = [&]() {  // splitmix64, portable
    x += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = x;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  int differ = 0, n = 0;
  for (const HeightField& f : fields) {
    const double lo1 = f.s1_0 - 2.5 * f.ds1, hi1 = f.s1_0 + (f.n1 + 1.5) * f.ds1;
    const double lo2 = f.n2 > 1 ? f.s2_0 - 2.5 * f.ds2 : -1.0, hi2 = f.n2 > 1 ? f.s2_0 + (f.n2 + 1.5) * f.ds2 : 1.0;
    for (int k = 0; k < 4000; ++k) {
      Vector2d s(lo1 + (hi1 - lo1) * uni(), lo2 + (hi2 - lo2) * uni());
      if (k % 10 == 0) s(0) = f.s1_0 + std::floor((hi1 - lo1) / f.ds1 * uni() - 2.0) * f.ds1;  // on a sample line
      const HeightSample a = sample_height(f, s), b = sample_height_reference(f, s);
      differ += a.h != b.h || a.grad != b.grad || a.hess != b.hess;
      ++n;
    }
  }
  CHECK(n == 8000);
  CHECK(differ == 0);
}

TEST_CASE("rough-surface contact: force = -eps_n g grad g, tangent vs central differences") {
  for (int kind = 0; kind < 2; ++kind) {
    const HeightField f = kind == 0 ? wavy_grid() : bump_line(0.01, 0.2, 0.01);
    const SurfaceContactLaw law{0.05, 1e6};
    const Vector3d xs[3] = {Vector3d(0.05, 0.02, 0.045), Vector3d(-0.07, 0.1, 0.04), Vector3d(0.16, -0.04, 0.048)};
    double et = 0.0, eg = 0.0;
    for (const Vector3d& x0 : xs) {
      const Vector3d x = f.base.point + x0(0) * f.base.t1 + x0(1) * f.base.t2 + x0(2) * f.base.normal;
      const SurfaceContactEval c = evaluate_surface_contact(f, law, x);
      REQUIRE(c.active);
      REQUIRE(c.converged);
      const double h = 1e-7;
      Matrix3d Kfd;
      Vector3d gfd;
      for (int k = 0; k < 3; ++k) {
        Vector3d d = Vector3d::Zero();
        d(k) = h;
        const SurfaceContactEval p = evaluate_surface_contact(f, law, x + d),
                                 m = evaluate_surface_contact(f, law, x - d);
        Kfd.col(k) = -(p.force - m.force) / (2 * h);
        gfd(k) = (p.g_n - m.g_n) / (2 * h);
      }
      et = std::max(et, (Kfd - c.tangent).norm() / c.tangent.norm());
      eg = std::max(eg, (gfd - c.normal).norm());
      // the normal is the surface normal at the contact point: (-grad h, 1)/|.|
      const HeightSample hs = sample_height(f, c.s);
      const Vector3d ns = (f.base.normal - hs.grad(0) * f.base.t1 - hs.grad(1) * f.base.t2).normalized();
      CHECK((ns - c.normal).norm() < 1e-10);
    }
    std::printf("surface contact (%s): tangent vs FD %.2e, grad g vs nu %.2e\n", kind == 0 ? "grid" : "line", et, eg);
    CHECK(et < 1e-6);
    CHECK(eg < 1e-7);
  }
}

TEST_CASE("rough-surface contact: a search started with the sample at its start = sampling there again, bit for bit") {
  for (int kind = 0; kind < 2; ++kind) {
    const HeightField f = kind == 0 ? wavy_grid() : bump_line(0.01, 0.2, 0.01);
    const SurfaceContactLaw law{0.05, 1e6};
    Vector3d x = f.base.point + 0.05 * f.base.t1 + 0.02 * f.base.t2 + 0.045 * f.base.normal;
    SurfaceContactEval last = evaluate_surface_contact(f, law, x);
    REQUIRE(last.converged);
    CHECK(last.sample.h == sample_height(f, last.s).h);
    for (int k = 0; k < 20; ++k) {  // a node moving on, each search from the last closest point
      x += Vector3d(1e-4, -3e-5, 2e-5 * std::sin(k));
      const SurfaceContactEval cached = evaluate_surface_contact(f, law, x, &last.s, &last.sample);
      const SurfaceContactEval plain = evaluate_surface_contact(f, law, x, &last.s);
      CHECK(cached.s == plain.s);
      CHECK(cached.g_n == plain.g_n);
      CHECK(cached.force == plain.force);
      CHECK(cached.tangent == plain.tangent);
      CHECK(cached.sample.grad == plain.sample.grad);
      // without the tangent (residual-only assembly, R-44a): the same point, gap and force
      const SurfaceContactEval bare = evaluate_surface_contact(f, law, x, &last.s, &last.sample, false);
      CHECK(bare.s == plain.s);
      CHECK(bare.g_n == plain.g_n);
      CHECK(bare.normal == plain.normal);
      CHECK(bare.force == plain.force);
      CHECK(bare.tangent.isZero(0.0));
      last = cached;
    }
  }
}

TEST_CASE("single-point contact validity: r kappa_max < 1") {
  // smooth sinusoid h = H/2 cos(2 pi s/lambda): valley curvature H/2 (2 pi/lambda)^2 = 4.935
  const double H = 0.01, lambda = 0.2;
  const double kappa = 0.5 * H * std::pow(2.0 * kPi / lambda, 2);
  const HeightField f = line_height_field(make_plane(Vector3d::Zero(), Vector3d::UnitZ()), -0.4, 0.4, 1601,
                                          [&](double s) { return 0.5 * H * std::cos(2.0 * kPi * s / lambda); });
  const ContactValidity ok = check_single_point_contact(f, 0.05), bad = check_single_point_contact(f, 0.25);
  // the cosine bump of the path test joins the flat with a jump of h'' (0 -> kappa); the
  // Catmull-Rom interpolant overshoots there, and the check reports the interpolant's value
  const ContactValidity kink = check_single_point_contact(bump_line(H, lambda, 0.002), 0.05);
  std::printf(
      "sinusoid H = %.3f, lambda = %.2f: kappa_max %.4f (analytic %.4f), radius limit %.4f; "
      "bump with curvature jump: kappa_max %.4f\n",
      H, lambda, ok.max_concave_curvature, kappa, ok.radius_limit, kink.max_concave_curvature);
  CHECK(ok.valid);
  CHECK_FALSE(bad.valid);
  CHECK(kink.valid);
  CHECK(std::abs(ok.max_concave_curvature / kappa - 1.0) < 0.01);
}

TEST_CASE("single-point contact validity: screened grid points = every point's eigenvalues, bit for bit") {
  HeightField rough = wavy_grid();
  std::uint64_t x = 777;
  for (double& h : rough.h) {  // add white noise: many valleys, the maximum far from the first point
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    h += 2e-4 * (static_cast<double>(x >> 11) * 0x1.0p-53 - 0.5);
  }
  const HeightField smooth = wavy_grid();
  const HeightField* fields[2] = {&rough, &smooth};
  for (const HeightField* g : fields) {
    for (const double r : {0.001, 0.05}) {
      const ContactValidity a = check_single_point_contact(*g, r), b = check_single_point_contact_reference(*g, r);
      CHECK(a.max_concave_curvature == b.max_concave_curvature);
      CHECK(a.where == b.where);
      CHECK(a.valid == b.valid);
      CHECK(a.radius_limit == b.radius_limit);
    }
  }
}

TEST_CASE("sphere node moved over a sinusoidal bump follows the offset curve") {
  // variant 0: eps_n = 1e7, dt = 1e-4 (contact period 2e-3 s resolved); variant 1: eps_n = 1e9
  // with output steps of 1e-3 and the impact step limit T_c/10 = 2e-5 s: unlimited, the
  // unresolved 2e-4 s penalty oscillation is pumped by the imposed motion and the ball jumps off
  for (int variant = 0; variant < 2; ++variant) {
    // Rigid ball (m = 1 kg) pressed by F = 10 N, x imposed at 0.4 m/s (dynamic, dt = 1e-4, the
    // contact period 2 pi sqrt(m/eps_n) = 2e-3 s resolved):
    // frictionless, so it slides rather than rolls; the centre must follow the offset curve
    // z(x) = max_s h(s) + sqrt(r^2 - (s - x)^2) of the analytic bump. The centripetal force
    // m v^2 kappa_path <= 0.7 N < F keeps the contact closed; penetration F/eps_n = 1e-6 m.
    const double H = 0.01, lambda = 0.2, r = 0.05, F = 10.0, v = 0.4;
    const double eps_n = variant == 0 ? 1e7 : 1e9;
    auto bump = [&](double s) {
      return (s >= 0.0 && s <= lambda) ? 0.5 * H * (1.0 - std::cos(2.0 * kPi * s / lambda)) : 0.0;
    };
    Model m;
    const int n = m.add_node(Vector3d(-0.1, 0.0, r - F / eps_n));
    m.bodies.push_back(RigidBody{n, 1.0, Matrix3d::Identity() * 1e-3});
    m.v0 = {Vector3d(v, 0, 0)};
    m.surfaces.push_back(bump_line(H, lambda, 0.002));
    m.surface_contacts.push_back(SurfaceContactPair{n, 0, SurfaceContactLaw{r, eps_n}});
    m.imposed.push_back(ImposedDof{n, 0, v, TimeSeries{{0.0, 1.0}, {0.0, 1.0}}});  // x: -0.1 -> 0.3
    m.loads.push_back(NodalLoad{n, Vector3d(0, 0, -F), Vector3d::Zero(), TimeSeries::constant(1.0)});
    SolverOptions o;
    o.force_tol = variant == 0 ? 1e-8 : 1e-6;
    if (variant == 1) o.impact_step_fraction = 0.1;
    Solver S(m, o);
    double worst = 0.0, zmax = 0.0;
    const int steps = variant == 0 ? 10000 : 1000;
    int limited = 0, substeps = 0;
    for (int k = 1; k <= steps; ++k) {
      const StepReport rep = S.advance(double(k) / steps);
      REQUIRE(rep.converged);
      limited += rep.limited_steps;
      substeps += rep.steps;
      const Vector3d x = S.nodes()[0].x;
      double zc = 0.0;
      for (int i = 0; i <= 2000; ++i) {
        const double s = x.x() - r + 2.0 * r * i / 2000.0;
        zc = std::max(zc, bump(s) + std::sqrt(std::max(0.0, r * r - (s - x.x()) * (s - x.x()))));
      }
      worst = std::max(worst, std::abs(x.z() - zc));
      zmax = std::max(zmax, x.z());
      CHECK(S.surface_contacts()[0].active);
    }
    std::printf(
        "bump path eps_n = %.0e, %d output steps, %d sub-steps: max |z - z_offset| = %.3e m (%.2e of H), "
        "top of path %.6f (r + H = %.6f)\n",
        eps_n, steps, substeps, worst, worst / H, zmax, r + H);
    CHECK(worst <= 1e-3 * H);
    CHECK(std::abs(zmax - (r + H)) <= 1e-3 * H);
    if (variant == 1) {  // every output step split into ceil(1e-3 / (0.1 T_c)) = 51 equal sub-steps
      const double Tc = 2.0 * kPi * std::sqrt(1.0 / eps_n);
      CHECK(limited == substeps - steps);  // the last sub-step of each output step is not shortened
      CHECK(substeps == steps * static_cast<int>(std::ceil(1e-3 / (0.1 * Tc))));
    }
  }
}

TEST_CASE("beam pressed on a rough grid surface: full-model tangent = central differences; pipe dragged over it") {
  Model m;
  m.sections.push_back(circular_section(2e9, 0.3, 7800.0, 0.1, 0.08));
  const double r = 0.05;
  const HeightField f = grid_height_field(
      make_plane(Vector3d::Zero(), Vector3d::UnitZ()), {-0.1, 0.02, 60}, {-0.2, 0.02, 20},
      [](double s1, double s2) { return 0.002 * std::sin(13.0 * (s1 + 0.1)) * std::cos(9.0 * (s2 + 0.2) + 0.4); });
  const ContactValidity val = check_single_point_contact(f, r);
  REQUIRE(val.valid);
  m.surfaces.push_back(f);
  const std::vector<int> ids = add_straight_beam(m, Vector3d(0.0, 0.0, r + 0.001), Vector3d(0.8, 0.0, r + 0.001), 2, 0);
  for (int id : ids) m.surface_contacts.push_back(SurfaceContactPair{id, 0, SurfaceContactLaw{r, 1e7}});
  m.gravity = Vector3d(0, 0, -9.81);
  m.gravity_series = TimeSeries::ramp(0.0, 0.05);
  m.v0.assign(m.X.size(), Vector3d(0.5, 0.0, 0.0));
  m.imposed.push_back(ImposedDof{ids[0], 0, 0.5, TimeSeries{{0.0, 1.0}, {0.0, 1.0}}});  // dragged at 0.5 m/s
  m.imposed.push_back(ImposedDof{ids[0], 1, 0.0, TimeSeries::constant()});
  m.loads.push_back(NodalLoad{ids[2], Vector3d(0, 0, -3000.0), Vector3d::Zero(), TimeSeries::ramp(0.0, 0.05)});
  SolverOptions o;
  o.force_tol = 1e-6;
  o.max_line_search = 8;
  Solver S(m, o);
  for (int k = 1; k <= 20; ++k) REQUIRE(S.advance(1e-3 * k).converged);
  int active = 0;
  for (const ContactOutput& c : S.surface_contacts()) active += c.active ? 1 : 0;
  CHECK(active >= 2);  // the stiff pipe rests on the highest asperities
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6 * static_cast<long>(m.X.size()));
  for (long i = 0; i < q.size(); ++i) q(i) = (i % 6 < 3 ? 2e-4 : 0.01) * std::sin(1.3 * double(i) + 0.2);
  const double err = test::tangent_check(S, q, 0.021, 1e-3, 1e-8).error;
  // drag the pipe on to t = 0.3 s: Newton converges with the rough contacts, balance R-43 holds
  for (int k = 21; k <= 300; ++k) REQUIRE(S.advance(1e-3 * k).converged);
  const Energies e = S.energies();
  std::printf(
      "beam on rough grid: %d of 5 nodes in contact, tangent rel. error %.2e; after 0.3 s dragged: "
      "balance error %.3e J (kinetic %.3f J, imposed work %.3f J)\n",
      active, err, e.balance_error(), e.kinetic, e.imposed_work);
  CHECK(err < 1e-6);
  CHECK(std::abs(e.balance_error()) < 1e-2 * (e.kinetic + std::abs(e.imposed_work) + std::abs(e.external_work)));
}

namespace {
// The seed 000 disc (sliding with backspin, then rolling) with its plane replaced by a height
// field over the same plane: `bump` = 0 gives a flat field.
Model disc_on_field(const DiscParams& p, double bump_height, double lambda) {
  Model m = disc_model(p);
  const Plane base = m.planes[0];
  m.surfaces.push_back(line_height_field(base, -1.0, 6.0, 3501, [&](double s) {
    return (s >= 1.0 && s <= 1.0 + lambda) ? 0.5 * bump_height * (1.0 - std::cos(2.0 * kPi * (s - 1.0) / lambda)) : 0.0;
  }));
  const ContactLaw& c = m.contacts[0].law;
  m.surface_contacts.push_back(
      SurfaceContactPair{m.contacts[0].node, 0, SurfaceContactLaw{c.radius, c.eps_n, c.mu, c.eps_t, c.rolling}});
  m.contacts.clear();
  m.planes.clear();
  return m;
}
}  // namespace

TEST_CASE("rolling friction on a height field (R-63): a flat field reproduces the plane contact") {
  // Seed 000 example 4.1: slip, then rolling at t_roll. The rough-surface element on a flat
  // field runs the plane element on the same plane, so the two runs agree to round-off.
  DiscParams p;
  RunOptions ro;
  ro.t_end = 2.0;
  ro.dt = 1e-3;
  SolverOptions o;
  o.force_tol = 1e-6 * p.mass * p.g;
  o.max_line_search = 8;
  const History hp = run(disc_model(p), o, ro), hs = run(disc_on_field(p, 0.0, 0.2), o, ro);
  REQUIRE(hp.completed);
  REQUIRE(hs.completed);
  double dx = 0.0, dv = 0.0, dw = 0.0, dslip = 0;
  for (std::size_t k = 0; k < hp.time.size(); ++k) {
    dx = std::max(dx, (hp.position[k][0] - hs.position[k][0]).norm());
    dv = std::max(dv, (hp.velocity[k][0] - hs.velocity[k][0]).norm());
    dw = std::max(dw, (hp.angular_velocity[k][0] - hs.angular_velocity[k][0]).norm());
    dslip += hp.contact[k][0].slip != hs.surface_contact[k][0].slip;
  }
  const double ediff = std::abs(hp.energy.back().friction_dissipation - hs.energy.back().friction_dissipation);
  std::printf(
      "flat field vs plane, disc 2 s: max |dx| %.2e m, |dv| %.2e m/s, |dw| %.2e rad/s, dissipation %.3e vs %.3e J\n",
      dx, dv, dw, hp.energy.back().friction_dissipation, hs.energy.back().friction_dissipation);
  CHECK(dx < 1e-9);
  CHECK(dv < 1e-8);
  CHECK(dw < 1e-7);
  CHECK(dslip == 0);
  CHECK(ediff < 1e-8 * hp.energy.back().friction_dissipation);
}

TEST_CASE("rolling friction on a height field (R-63): a disc rolls over a bump without slipping") {
  // Disc rolling (v = r w) at 1 m/s over a cosine bump H = 2 mm, lambda = 0.2 m (r kappa = 0.2):
  // stick throughout, r |w| = |v| (the contact point is the instantaneous centre), the centre on
  // the offset curve lowered by the penetration N/eps_n, and friction removes no energy.
  DiscParams p;
  p.mu = 0.5;
  p.eps_n = 1e10;
  p.eps_t = 1e9;
  p.V0 = 1.0;
  p.omega0 = p.V0 / p.radius;  // disc_model spins at -omega0 about z: v + w x (C - x) = 0
  const double H = 0.002, lambda = 0.2;
  Model m = disc_on_field(p, H, lambda);
  m.X[0].x() = 0.5;
  RunOptions ro;
  ro.t_end = 1.2;
  ro.dt = 2e-4;  // contact period 2 pi sqrt(m/eps_n) = 2e-3 s
  SolverOptions o;
  o.force_tol = 1e-7 * p.mass * p.g;
  o.max_line_search = 8;
  const History h = run(m, o, ro);
  REQUIRE(h.completed);
  auto bump = [&](double s) {
    return (s >= 1.0 && s <= 1.0 + lambda) ? 0.5 * H * (1.0 - std::cos(2.0 * kPi * (s - 1.0) / lambda)) : 0.0;
  };
  double worst_path = 0.0, worst_roll = 0.0, top = 0.0;
  int slips = 0;
  for (std::size_t k = 1; k < h.time.size(); ++k) {
    const Vector3d x = h.position[k][0];
    double zc = 0.0;
    for (int i = 0; i <= 4000; ++i) {
      const double s = x.x() - p.radius + 2.0 * p.radius * i / 4000.0;
      zc = std::max(zc, bump(s) + std::sqrt(std::max(0.0, p.radius * p.radius - (s - x.x()) * (s - x.x()))));
    }
    const double pen = -h.surface_contact[k][0].g_n;
    worst_path = std::max(worst_path, std::abs(x.y() - (zc - pen)));
    worst_roll =
        std::max(worst_roll, std::abs(p.radius * h.angular_velocity[k][0].norm() / h.velocity[k][0].norm() - 1.0));
    top = std::max(top, x.y());
    slips += h.surface_contact[k][0].slip;
    CHECK(h.surface_contact[k][0].active);
  }
  const Energies& E = h.energy.back();
  std::printf(
      "disc over bump with friction: centre vs offset curve %.2e m (%.2e of H), max |r w/v - 1| %.2e, slip steps %d, "
      "friction dissipation %.2e J of kinetic %.1f J, balance error %.2e J, top %.6f (r + H = %.6f)\n",
      worst_path, worst_path / H, worst_roll, slips, E.friction_dissipation, E.kinetic, E.balance_error(), top,
      p.radius + H);
  CHECK(top > p.radius + 0.99 * H);  // the disc went over the bump
  CHECK(worst_path <= 1e-3 * H);
  CHECK(worst_roll < 2e-3);
  CHECK(slips == 0);
  CHECK(E.friction_dissipation < 1e-9 * E.kinetic);
  CHECK(std::abs(E.balance_error()) < 1e-4 * E.kinetic);
}

TEST_CASE("normal contact damper on a rough surface (R-64): logarithmic decrement and energy balance") {
  // Ball m = 1 kg resting on a flat field with eps_n = 1e6 N/m and c_n = 2 zeta sqrt(eps_n m),
  // zeta = 0.05, kicked downward by 1e-4 m/s (amplitude 1e-7 m << static penetration 9.81e-6 m,
  // so the contact stays closed): successive peaks of the gap decay by exp(-2 pi zeta/sqrt(1-zeta^2)),
  // and the damper's trapezoidal work closes the energy balance.
  const double m = 1.0, k = 1e6, zeta = 0.05, g = 9.81, c = 2.0 * zeta * std::sqrt(k * m);
  Model model;
  const Plane base = make_plane(Vector3d::Zero(), Vector3d::UnitZ());
  model.surfaces.push_back(line_height_field(base, -1.0, 1.0, 201, [](double) { return 0.0; }));
  const int n = model.add_node(Vector3d(0.0, 0.0, 0.05 - m * g / k));
  model.bodies.push_back(RigidBody{n, m, Matrix3d::Identity() * 1e-3});
  model.v0 = {Vector3d(0.0, 0.0, -1e-4)};
  SurfaceContactLaw law{0.05, k};
  law.damping = c;
  model.surface_contacts.push_back(SurfaceContactPair{n, 0, law});
  model.gravity = Vector3d(0, 0, -g);
  const double T = 2.0 * kPi / std::sqrt(k / m);
  RunOptions ro;
  ro.dt = T / 200.0;
  ro.t_end = 6.0 * T;
  SolverOptions o;
  o.force_tol = 1e-12;
  const History h = run(model, o, ro);
  REQUIRE(h.completed);
  std::vector<double> peaks;  // minima of the gap (deepest penetration) per period
  for (std::size_t i = 1; i + 1 < h.time.size(); ++i) {
    const double a = h.surface_contact[i - 1][0].g_n, b = h.surface_contact[i][0].g_n,
                 d = h.surface_contact[i + 1][0].g_n;
    if (b < a && b <= d) peaks.push_back(-(b + m * g / k));
  }
  REQUIRE(peaks.size() >= 4);
  const double expected = std::exp(-2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta));
  double worst = 0.0;
  for (std::size_t i = 1; i < peaks.size(); ++i)
    worst = std::max(worst, std::abs(peaks[i] / peaks[i - 1] / expected - 1.0));
  const Energies& E = h.energy.back();
  std::printf(
      "contact damper zeta = %.2f: %zu peaks, worst peak ratio error %.2e (expected ratio %.4f); damper work %.3e J, "
      "balance error %.2e J\n",
      zeta, peaks.size(), worst, expected, E.damping_work, E.balance_error());
  CHECK(worst < 5e-3);
  CHECK(E.damping_work > 0.9 * 0.5 * m * 1e-8);  // most of the kick's 5e-9 J is gone
  CHECK(std::abs(E.balance_error()) < 1e-3 * 0.5 * m * 1e-8);
}
