// Rolling contact element (seed 000 Sec. 3): kinematics checks and the consistent tangent
// against central finite differences of the residual, for stick and slip, with rolling and
// with the "no rolling" switch.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>

#include "kernels/rolling/contact_element.hpp"
#include "kernels/rolling/rotation.hpp"

using namespace rollspec::rolling;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

Mat6 fd_tangent(const Plane& pl, const ContactLaw& law, const ContactState& st, const Vector3d& xs, const Vec6& q,
                double h) {
  Mat6 K;
  for (int j = 0; j < 6; ++j) {
    Vec6 qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    const ContactEval ep = evaluate_contact(pl, law, st, xs, qp.head<3>(), qp.tail<3>());
    const ContactEval em = evaluate_contact(pl, law, st, xs, qm.head<3>(), qm.tail<3>());
    K.col(j) = (ep.residual - em.residual) / (2.0 * h);
  }
  return K;
}

double rel_err(const Mat6& a, const Mat6& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("Rodrigues rotation D-12: orthogonal, angle 2 atan(|a|/2), Xi is the spin map") {
  const Vector3d a(0.3, -0.2, 0.5);
  const Matrix3d Q = rodrigues_q(a);
  CHECK((Q * Q.transpose() - Matrix3d::Identity()).norm() < 1e-14);
  CHECK(Q.determinant() == doctest::Approx(1.0).epsilon(1e-14));
  const Eigen::AngleAxisd aa(Q);
  CHECK(aa.angle() == doctest::Approx(2.0 * std::atan(0.5 * a.norm())).epsilon(1e-13));
  // d(Q v)/da = -skew(Q v) Xi  (seed 000 Eq. 2-3)
  const Vector3d v(0.2, 0.7, -0.4);
  const double h = 1e-6;
  Matrix3d J;
  for (int j = 0; j < 3; ++j) {
    Vector3d ap = a, am = a;
    ap(j) += h;
    am(j) -= h;
    J.col(j) = (rodrigues_q(ap) * v - rodrigues_q(am) * v) / (2 * h);
  }
  CHECK((J + skew(Q * v) * rodrigues_xi(a)).norm() < 1e-9);
  // operator O1 (seed 000 Eq. 25): d(Xi^T m)/da
  const Vector3d m(1.0, -2.0, 0.5);
  for (int j = 0; j < 3; ++j) {
    Vector3d ap = a, am = a;
    ap(j) += h;
    am(j) -= h;
    J.col(j) = (rodrigues_xi(ap).transpose() * m - rodrigues_xi(am).transpose() * m) / (2 * h);
  }
  CHECK((J - d_xi_transpose_m(a, m)).norm() < 1e-9);
}

TEST_CASE("pure rolling of a sphere gives zero tangential gap (D-13, D-14 check)") {
  const Plane pl = make_plane(Vector3d::Zero(), Vector3d::UnitZ());
  ContactLaw law{0.2, 0.3, 1e8, 1e7, true};
  ContactState st;
  st.active = true;
  st.x_f = Vector3d(1.0, 2.0, 0.0);
  const Vector3d xs(1.0, 2.0, 0.2 - 1e-5);
  // roll by a small angle phi about +y: centre moves +x by r sin(phi) (chord, seed 000 Sec. 3)
  const double phi = 0.01;
  const Vector3d a = rodrigues_from_rotation_vector(Vector3d(0, phi, 0));
  const Vector3d x = xs + Vector3d(0.2 * std::sin(phi), 0, 0);
  const ContactEval e = evaluate_contact(pl, law, st, xs, x, a);
  CHECK(e.active);
  CHECK(!e.slip);
  CHECK(e.g_t.norm() < 1e-15);
  CHECK(e.g_n == doctest::Approx(-1e-5).epsilon(1e-9));
  // the same motion without rotation is a 2 mm slide: f = -eps_t g_t
  const ContactEval s = evaluate_contact(pl, law, st, xs, x, Vector3d::Zero());
  CHECK(s.g_t.x() == doctest::Approx(0.2 * std::sin(phi)).epsilon(1e-12));
}

TEST_CASE("contact tangent = central differences of the residual (stick, slip, rolling, no rolling)") {
  const Plane pl = make_plane(Vector3d(0.1, -0.3, 0.2), Vector3d(0.2, -0.1, 1.0));
  ContactState st;
  st.active = true;
  st.x_f = pl.point + 0.05 * pl.t1 - 0.02 * pl.t2;
  st.g_st = 0.003 * pl.t1 + 0.001 * pl.t2;
  const Vector3d xs = st.x_f + (0.2 - 1e-4) * pl.normal;
  const Vector3d alpha(0.12, -0.2, 0.07);
  for (const bool rolling : {true, false}) {
    for (const double dtan : {2e-5, 3e-3}) {  // small tangential motion -> stick, large -> slip
      ContactLaw law{0.2, 0.3, 1e8, 1e7, rolling};
      Vec6 q;
      q.tail<3>() = alpha;
      // place the centre so that the elastic gap (D-14) is dtan along (t1 + 0.4 t2)
      const Matrix3d P = Matrix3d::Identity() - pl.normal * pl.normal.transpose();
      const double rr = rolling ? 0.2 : 0.0;
      const Vector3d roll = rr * P * (rodrigues_q(alpha) * pl.normal - pl.normal);
      q.head<3>() = st.x_f + st.g_st + roll + dtan * (pl.t1 + 0.4 * pl.t2) + (0.2 - 1.2e-4) * pl.normal;
      const ContactEval e = evaluate_contact(pl, law, st, xs, q.head<3>(), q.tail<3>());
      REQUIRE(e.active);
      // without the tangent (residual-only assembly, R-44a): everything else the same bits
      const ContactEval e0 = evaluate_contact(pl, law, st, xs, q.head<3>(), q.tail<3>(), NormalForce::EndPoint, false);
      CHECK(e0.residual == e.residual);
      CHECK(e0.force == e.force);
      CHECK(e0.moment == e.moment);
      CHECK(e0.next.x_f == e.next.x_f);
      CHECK(e0.next.g_st == e.next.g_st);
      CHECK(e0.slip == e.slip);
      CHECK(e0.dissipation == e.dissipation);
      CHECK(e0.tangential_energy == e.tangential_energy);
      CHECK(e0.tangent.isZero(0.0));
      const bool expect_slip = dtan > 1e-3;
      CHECK(e.slip == expect_slip);
      const Mat6 Kfd = fd_tangent(pl, law, st, xs, q, 1e-7);
      const double err = rel_err(e.tangent, Kfd);
      INFO("rolling=" << rolling << " slip=" << e.slip << " rel err=" << err);
      CHECK(err < 1e-6);
      if (!rolling) CHECK(e.moment.norm() == 0.0);
      if (rolling) CHECK(std::abs(e.moment.dot(pl.normal)) < 1e-9 * e.moment.norm());
      // slip: friction magnitude is mu * eps_n * |g_n| (Coulomb)
      if (e.slip) CHECK(e.friction.norm() == doctest::Approx(0.3 * 1e8 * (-e.g_n)).epsilon(1e-12));
    }
  }
}
