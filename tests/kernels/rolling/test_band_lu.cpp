// Band LU with partial pivoting (kernels/rolling/band_lu, README R-44) against Eigen's dense
// PartialPivLU and the SparseLU it replaces for beams: random band matrices that need row
// interchanges, the band assembly against the sparse one, and whole runs with either solver.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/rolling/assembly.hpp"
#include "kernels/rolling/band_lu.hpp"
#include "kernels/rolling/contact_set.hpp"
#include "kernels/rolling/newton.hpp"
#include "kernels/rolling/solver.hpp"
#include "initial_tangent.hpp"
#include "run_options.hpp"

using namespace rollspec::rolling;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using rollspec::rolling::test::InitialTangent;
using rollspec::rolling::test::run_options;

TEST_CASE("band LU: solves random band matrices as dense partial-pivoting LU does, pivoting included") {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int shapes[][3] = {{1, 0, 0}, {5, 1, 1}, {12, 0, 3}, {20, 4, 0}, {54, 17, 17}, {60, 5, 11}, {200, 17, 17}};
  for (const auto& sh : shapes) {
    const int n = sh[0], kl = sh[1], ku = sh[2];
    for (const bool weak_diagonal : {false, true}) {        // weak: the pivots come from below the diagonal
      if (weak_diagonal && (kl == 0 || ku == 0)) continue;  // a triangular band with a weak diagonal is singular
      MatrixXd A = MatrixXd::Zero(n, n);
      BandLU lu(n, kl, ku);
      for (int j = 0; j < n; ++j)
        for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i) {
          double v = u(rng);
          if (i == j) v = weak_diagonal ? 1e-3 * v : v + (v < 0 ? -(kl + ku + 1.0) : kl + ku + 1.0);
          A(i, j) = v;
          lu.at(i, j) = v;
        }
      VectorXd b(n);
      for (int i = 0; i < n; ++i) b(i) = u(rng);
      REQUIRE(lu.factorize());
      VectorXd x = b;
      lu.solve(x.data());
      const VectorXd xd = A.partialPivLu().solve(b);
      // normwise backward error (a triangular band with a weak diagonal is ill-conditioned)
      const double rel = (x - xd).norm() / xd.norm(), res = (A * x - b).norm() / (A.norm() * x.norm() + b.norm());
      CAPTURE(n);
      CAPTURE(kl);
      CAPTURE(ku);
      CAPTURE(weak_diagonal);
      // forward error within the condition number times round-off (threshold pivoting, R-44, may
      // take other rows than dense partial pivoting; a weak triangular band is ill-conditioned)
      const Eigen::VectorXd sv = Eigen::JacobiSVD<MatrixXd>(A).singularValues();
      const double cond = sv(0) / sv(n - 1);
      CAPTURE(cond);
      CHECK(rel < 1e-13 * std::max(1.0, cond));
      if (!weak_diagonal) CHECK(rel < 1e-12);
      CHECK(res < 1e-14);
    }
  }
  BandLU singular(3, 1, 1);  // a zero column is refused
  singular.at(0, 0) = 1.0;
  singular.at(2, 2) = 1.0;
  CHECK_FALSE(singular.factorize());
}

TEST_CASE("band LU: the profile-skipping factorisation and solve = the plain band loops, bit for bit") {
  // beam-like block profile (18 x 18 element blocks overlapping by 6, R-44) and full random bands,
  // diagonals strong and weak (weak: row interchanges, fill above ku)
  std::mt19937_64 rng(45);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int pivoted = 0;
  for (const int n : {18, 54, 102}) {
    for (const bool profile : {true, false}) {
      for (const bool weak_diagonal : {false, true}) {
        const int kl = 17, ku = 17;
        BandLU fast(n, kl, ku), plain(n, kl, ku);
        for (int j = 0; j < n; ++j)
          for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i) {
            // element e couples equations 12 e .. 12 e + 17
            if (profile && std::max(i, j) > 12 * (std::min(i, j) / 12) + 17) continue;
            double v = u(rng);
            if (i == j) v = weak_diagonal ? 1e-3 * v : v + (v < 0 ? -(kl + ku + 1.0) : kl + ku + 1.0);
            fast.at(i, j) = v;
            plain.at(i, j) = v;
          }
        REQUIRE(fast.factorize());
        REQUIRE(plain.factorize_reference());
        int differ = 0;
        for (int j = 0; j < n; ++j)
          for (int i = std::max(0, j - kl - ku); i <= std::min(n - 1, j + kl); ++i)
            differ += fast.at(i, j) != plain.at(i, j);
        CAPTURE(n);
        CAPTURE(profile);
        CAPTURE(weak_diagonal);
        CHECK(differ == 0);
        VectorXd b(n);
        for (int i = 0; i < n; ++i) b(i) = u(rng);
        VectorXd xf = b, xp = b, xr = b;
        fast.solve(xf.data());
        plain.solve_reference(xp.data());
        plain.solve(xr.data());  // after the reference factorisation solve runs over the whole band
        CHECK(xf == xp);
        CHECK(xr == xp);
        if (weak_diagonal) ++pivoted;
      }
    }
  }
  CHECK(pivoted == 6);
}

namespace {

// A tube of four quadratic elements on a wavy grid with rolling friction and dampers at every node
// (the rolling-pipe scene's model at a smaller scale), rolling at 0.5 m/s.
Model rolling_tube() {
  Model m;
  m.sections.push_back(circular_section(2.1e11, 0.3, 7850, 0.06, 0.052));
  const double r = 0.03;
  const std::vector<int> ids =
      add_straight_beam(m, Vector3d(0.0, -0.5, r - 2e-5), Vector3d(0.0, 0.5, r - 2e-5), 4, 0, Vector3d::UnitX());
  m.surfaces.push_back(grid_height_field(
      make_plane(Vector3d::Zero(), Vector3d::UnitZ()), {-0.1, 0.01, 60}, {-0.6, 0.01, 120},
      [](double s1, double s2) { return 2e-5 * std::sin(40.0 * s1 + 30.0 * (s2 + 0.6)) * std::cos(13.0 * s2); }));
  for (int id : ids) {
    SurfaceContactLaw law;
    law.radius = r;
    law.eps_n = 5e6;
    law.mu = 0.3;
    law.eps_t = 1e6;
    law.damping = 60.0;
    m.surface_contacts.push_back(SurfaceContactPair{id, 0, law});
  }
  m.v0.assign(m.X.size(), Vector3d(0.5, 0.0, 0.0));
  m.w0.assign(m.X.size(), Vector3d(0.0, 0.5 / r, 0.0));
  m.gravity = Vector3d(0, 0, -9.81);
  return m;
}

}  // namespace

TEST_CASE("band LU: the rolling tube's tangent, assembled into the band, solves as SparseLU does") {
  const Model m = rolling_tube();
  const InitialTangent tangent(m);
  const int n = tangent.n, kl = tangent.kl, ku = tangent.ku;
  const SparseSink& ss = tangent.sparse;
  const VectorXd& Rs = tangent.r;
  CHECK(kl == 17);  // an element couples three neighbouring nodes
  CHECK(ku == 17);
  CHECK(band_pays(n, kl, ku, ss.A.nonZeros()));
  BandLU band(n, kl, ku);
  BandSink bs;
  bs.eq = &tangent.eq;
  bs.lu = &band;
  bs.begin();
  ContactSet fresh(m, tangent.nodes);  // the closest-point searches start as the first pass's did
  VectorXd Rb;
  assemble(tangent.state(), TimeRule(TimeRule::Kind::Newmark), fresh, tangent.q, InitialTangent::kStep,
           InitialTangent::kStep, false, Rb, &bs);
  CHECK_FALSE(bs.mismatch);
  const MatrixXd Ks = MatrixXd(ss.A);
  int differ = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) differ += band.in_band(i, j) ? (band.at(i, j) != Ks(i, j)) : (Ks(i, j) != 0.0);
  CHECK(differ == 0);  // the same sums in the same order
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> slu(ss.A);
  REQUIRE(slu.info() == Eigen::Success);
  const VectorXd xs = slu.solve(-Rs);
  REQUIRE(band.factorize());
  VectorXd xb = -Rb;
  band.solve(xb.data());
  MESSAGE("band vs SparseLU on the tube tangent: " << (xb - xs).norm() / xs.norm());
  CHECK((xb - xs).norm() < 1e-12 * xs.norm());
}

TEST_CASE("band LU: a rolling tube run with the band solver follows the SparseLU run to round-off") {
  RunOptions ro = run_options(2.5e-5, 0.02, 40);
  ro.record_energies = false;
  SolverOptions band, sparse;
  band.linear_solver = LinearSolver::Band;
  sparse.linear_solver = LinearSolver::Sparse;
  const History hb = run(rolling_tube(), band, ro), hs = run(rolling_tube(), sparse, ro);
  REQUIRE(hb.completed);
  REQUIRE(hs.completed);
  double worst_x = 0.0, worst_a = 0.0, scale_a = 0.0;
  for (std::size_t k = 0; k < hb.time.size(); ++k)
    for (std::size_t j = 0; j < hb.position[k].size(); ++j) {
      worst_x = std::max(worst_x, (hb.position[k][j] - hs.position[k][j]).norm());
      worst_a = std::max(worst_a, (hb.acceleration[k][j] - hs.acceleration[k][j]).norm());
      scale_a = std::max(scale_a, hs.acceleration[k][j].norm());
    }
  MESSAGE("band vs sparse over " << hb.steps << " steps (" << hb.newton_iterations << " / " << hs.newton_iterations
                                 << " Newton iterations): positions " << worst_x << " m, accelerations " << worst_a
                                 << " of " << scale_a << " m/s^2");
  CHECK(worst_x < 1e-12);
  CHECK(worst_a < 1e-6 * scale_a);
  Solver s(rolling_tube(), SolverOptions{});
  REQUIRE(s.advance(2.5e-5).converged);
  CHECK(s.pattern_analyses() == 1);
}

TEST_CASE("Newton with residual-only checks (R-44a): the rolling tube run equals the plain one bit for bit") {
  const RunOptions ro = run_options(2.5e-5, 0.01);  // every step recorded, energies included
  SolverOptions lazy, plain;
  lazy.max_line_search = plain.max_line_search = 8;  // as the rolling-pipe scene
  plain.residual_only_checks = false;
  const History hl = run(rolling_tube(), lazy, ro), hp = run(rolling_tube(), plain, ro);
  REQUIRE(hl.completed);
  REQUIRE(hp.completed);
  CHECK(hl.newton_iterations == hp.newton_iterations);
  CHECK(hl.cuts == hp.cuts);
  int differ = 0;
  for (std::size_t k = 0; k < hp.time.size(); ++k) {
    for (std::size_t j = 0; j < hp.position[k].size(); ++j)
      differ += hl.position[k][j] != hp.position[k][j] || hl.acceleration[k][j] != hp.acceleration[k][j] ||
                hl.rotation[k][j] != hp.rotation[k][j] || hl.angular_velocity[k][j] != hp.angular_velocity[k][j];
    for (std::size_t c = 0; c < hp.surface_contact[k].size(); ++c)
      differ += hl.surface_contact[k][c].force != hp.surface_contact[k][c].force ||
                hl.surface_contact[k][c].g_n != hp.surface_contact[k][c].g_n;
    differ += hl.energy[k].balance() != hp.energy[k].balance();
  }
  MESSAGE("residual-only checks over " << hp.steps << " steps, " << hp.newton_iterations << " Newton iterations");
  CHECK(differ == 0);
  // steps that need more directions than the one before: the residual-only pass is repeated with
  // the tangent (pairs rewound); a tight tolerance and growing steps make the counts vary
  SolverOptions tight_lazy = lazy, tight_plain = plain;
  tight_lazy.force_tol = tight_plain.force_tol = 1e-9;
  Solver sl(rolling_tube(), tight_lazy), sp(rolling_tube(), tight_plain);
  int its_l = 0, its_p = 0, differ_states = 0;
  double t = 0.0;
  for (int k = 0; k < 300; ++k) {
    t += 2.5e-5 * (k % 5 == 0 ? 8.0 : 0.5);
    const StepReport rl = sl.advance(t), rp = sp.advance(t);
    REQUIRE(rl.converged);
    REQUIRE(rp.converged);
    its_l += rl.iterations;
    its_p += rp.iterations;
    for (std::size_t a = 0; a < sl.nodes().size(); ++a)
      differ_states += sl.nodes()[a].x != sp.nodes()[a].x || sl.nodes()[a].R != sp.nodes()[a].R ||
                       sl.nodes()[a].a != sp.nodes()[a].a || sl.nodes()[a].W != sp.nodes()[a].W;
  }
  MESSAGE("varying steps: " << its_p << " Newton iterations, " << sl.residual_only_repeats()
                            << " residual-only passes repeated with the tangent");
  CHECK(its_l == its_p);
  CHECK(differ_states == 0);
  CHECK(sl.residual_only_repeats() > 0);
  CHECK(sp.residual_only_repeats() == 0);
}
