#include "kernels/rolling/assembly.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/rolling/contact_set.hpp"
#include "kernels/rolling/rotary_inertia.hpp"
#include "kernels/rolling/rotation.hpp"

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

void SparseSink::begin() {
  k = 0;
  mismatch = false;
  if (recording) {
    trip.clear();
  } else {
    std::fill(A.valuePtr(), A.valuePtr() + A.nonZeros(), 0.0);
  }
}

void SparseSink::add(int i, int j, double v) {
  const int r = (*eq)[static_cast<std::size_t>(i)], c = (*eq)[static_cast<std::size_t>(j)];
  if (r < 0 || c < 0) return;
  if (recording) {
    trip.emplace_back(r, c, v);
    return;
  }
  if (k >= slot.size() || srow[k] != r || scol[k] != c) {
    mismatch = true;
    return;
  }
  A.valuePtr()[slot[k++]] += v;
}

void SparseSink::finish() {
  if (!recording) {
    if (k != slot.size()) mismatch = true;
    return;
  }
  A.resize(neq, neq);
  A.setFromTriplets(trip.begin(), trip.end());
  A.makeCompressed();
  slot.clear();
  srow.clear();
  scol.clear();
  for (const auto& t : trip) {
    const int c = t.col();
    const int* b = A.innerIndexPtr() + A.outerIndexPtr()[c];
    const int* e = A.innerIndexPtr() + A.outerIndexPtr()[c + 1];
    const int* p = std::lower_bound(b, e, t.row());
    slot.push_back(static_cast<int>(p - A.innerIndexPtr()));
    srow.push_back(t.row());
    scol.push_back(c);
  }
  recording = false;
  new_pattern = true;
}

namespace {
// K (M x M, column-major) added onto the band's rows and columns e0 ... e0 + M - 1.
template <int M>
void add_columns(BandLU& lu, int e0, const double* K) {
  for (int j = 0; j < M; ++j) {
    double* col = lu.column(e0 + j) + e0;
    const double* k = K + M * j;
    for (int i = 0; i < M; ++i) col[i] += k[i];
  }
}
}  // namespace

void BandSink::add_dense(const int* dofs, int m, const double* K) {
  if (m > 18) {
    Sink::add_dense(dofs, m, K);
    return;
  }
  int e[18], lo = 1 << 30, hi = -1;
  for (int i = 0; i < m; ++i) {
    e[i] = (*eq)[static_cast<std::size_t>(dofs[i])];
    if (e[i] >= 0) {
      lo = std::min(lo, e[i]);
      hi = std::max(hi, e[i]);
    }
  }
  // free equations e[0], e[0] + 1, ...: whole columns of the block at once (a fixed first dof, e = -1,
  // followed by equations 0, 1, ... is not such a run)
  bool run = m > 0 && e[0] >= 0;
  for (int i = 0; i < m; ++i) run = run && e[i] == e[0] + i;
  if (run && lu->in_band(lo, hi) && lu->in_band(hi, lo)) {
    switch (m) {  // the usual sizes with fixed loop lengths
      case 18:
        add_columns<18>(*lu, e[0], K);
        return;
      case 6:
        add_columns<6>(*lu, e[0], K);
        return;
      case 3:
        add_columns<3>(*lu, e[0], K);
        return;
      default:
        for (int j = 0; j < m; ++j) {
          double* col = lu->column(e[j]) + e[0];
          const double* k = K + m * j;
          for (int i = 0; i < m; ++i) col[i] += k[i];
        }
        return;
    }
  }
  for (int j = 0; j < m; ++j) {
    const int c = e[j];
    if (c < 0) continue;
    if (!lu->in_band(lo, c) || !lu->in_band(hi, c)) {  // part of the block outside the band
      mismatch = true;
      continue;
    }
    double* col = lu->column(c);  // col[r] = A(r, c) within the band
    const double* k = K + m * j;
    for (int i = 0; i < m; ++i)
      if (e[i] >= 0) col[e[i]] += k[i];
  }
}

Matrix3d section_inertia(const BeamSection& s) { return Eigen::Vector3d(s.rhoJ1, s.rhoI2, s.rhoI3).asDiagonal(); }

std::vector<NodeState> initial_nodes(const Model& m) {
  std::vector<NodeState> nodes(m.X.size());
  for (std::size_t a = 0; a < m.X.size(); ++a) {
    nodes[a].x = m.X[a];
    nodes[a].R = m.frames[a];
    if (!m.v0.empty()) nodes[a].v = m.v0[a];
    if (!m.w0.empty()) nodes[a].W = m.frames[a].transpose() * m.w0[a];
  }
  return nodes;
}

BeamPoints make_beam_points(const Model& m) {
  BeamPoints out;
  const double gs = 1.0 / std::sqrt(3.0), gm = std::sqrt(0.6);
  for (const BeamElement& be : m.beams) {
    auto frame_at = [&](double xi, double& jac) {
      double N[3], dN[3];
      quadratic_shape(xi, N, dN);
      Vector3d Xp = Vector3d::Zero();
      for (int k = 0; k < 3; ++k) Xp += dN[k] * m.X[static_cast<std::size_t>(be.nodes[k])];
      jac = Xp.norm();
      const Vector3d e1 = Xp / jac;
      Vector3d e2 = m.frames[static_cast<std::size_t>(be.nodes[0])].col(1);
      e2 = (e2 - e2.dot(e1) * e1).normalized();
      Matrix3d Rf;
      Rf.col(0) = e1;
      Rf.col(1) = e2;
      Rf.col(2) = e1.cross(e2);
      return Rf;
    };
    std::array<BeamStiffPoint, 2> sp;
    for (int k = 0; k < 2; ++k) {
      sp[k].xi = k == 0 ? -gs : gs;
      sp[k].weight = 1.0;
      sp[k].R = frame_at(sp[k].xi, sp[k].jac);
    }
    out.stiffness.push_back(sp);
    std::array<MassPoint, 3> mp;
    const double xis[3] = {-gm, 0.0, gm}, ws[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    for (int k = 0; k < 3; ++k) {
      mp[k].xi = xis[k];
      mp[k].weight = ws[k];
      mp[k].R = frame_at(xis[k], mp[k].jac);
      if (!m.w0.empty()) {
        double N[3], dN[3];
        quadratic_shape(xis[k], N, dN);
        Vector3d w = Vector3d::Zero();
        for (int j = 0; j < 3; ++j) w += N[j] * m.w0[static_cast<std::size_t>(be.nodes[j])];
        mp[k].W = mp[k].R.transpose() * w;
      }
    }
    out.mass.push_back(mp);
  }
  return out;
}

void assemble(const AssemblyState& s, const TimeRule& rule, ContactSet& contacts, const VectorXd& q, double t1,
              double dt, bool mass_matrix, VectorXd& R, Sink* K) {
  const Model& m = s.model;
  const auto& nodes = s.nodes;
  const int nn = static_cast<int>(m.X.size());
  R.setZero(6 * nn);
  const bool inertia = !mass_matrix && rule.inertia();
  const double gs = rule.load(m.gravity_series, s.t0, t1);
  const Vector3d grav = gs * m.gravity;
  const double c2 = rule.mass_coefficient(dt);
  auto du = [&](int a) { return Vector3d(q.segment<3>(6 * a)); };
  auto al = [&](int a) { return Vector3d(q.segment<3>(6 * a + 3)); };
  auto acc = [&](int a) { return rule.acceleration(c2, du(a), dt, nodes[a].v, nodes[a].a); };

  if (K && K->wants_pattern_blocks()) {  // every node's diagonal block is part of the pattern
    const Eigen::Matrix<double, 6, 6> Z = Eigen::Matrix<double, 6, 6>::Zero();
    for (int a = 0; a < nn; ++a) add_block<6>(K, dofs6(a), Z);
  }

  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const BeamElement& be = m.beams[e];
    const BeamSection& sec = m.sections[static_cast<std::size_t>(be.section)];
    std::array<Vector3d, 3> x, a;
    std::array<int, 18> dofs{};
    for (int k = 0; k < 3; ++k) {
      const int nd = be.nodes[k];
      x[k] = nodes[nd].x + du(nd);
      a[k] = al(nd);
      for (int i = 0; i < 6; ++i) dofs[6 * k + i] = 6 * nd + i;
    }
    // stiffness (reduced 2-point Gauss)
    BeamElementEval ev = beam_element_internal(sec, s.points.stiffness[e], x, a, K && !mass_matrix);
    for (int k = 0; k < 18; ++k) R(dofs[k]) += ev.force(k);
    // the element's tangent block (zero for the mass matrix); untouched without K
    Eigen::Matrix<double, 18, 18>& Ke = ev.tangent;
    // mass, rotary inertia and gravity (3-point Gauss, exact for the consistent mass)
    const Matrix3d Js = section_inertia(sec);
    for (const MassPoint& p : s.points.mass[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      const double w = p.weight * p.jac;
      for (int k = 0; k < 3; ++k) R.segment<3>(dofs[6 * k]) -= N[k] * w * sec.rhoA * grav;
      if (inertia) {
        Vector3d ag = Vector3d::Zero(), ag_a = Vector3d::Zero();
        for (int k = 0; k < 3; ++k) {
          ag += N[k] * acc(be.nodes[k]);
          ag_a += N[k] * a[k];
        }
        const RotaryInertiaEval ri = rule.rotary(Js, p.R, p.W, p.A, dt, ag_a, K != nullptr);
        for (int k = 0; k < 3; ++k) {
          R.segment<3>(dofs[6 * k]) += N[k] * w * sec.rhoA * ag;
          R.segment<3>(dofs[6 * k + 3]) += N[k] * w * ri.residual;
          if (K)
            for (int l = 0; l < 3; ++l) {
              Ke.block<3, 3>(6 * k, 6 * l).diagonal().array() += N[k] * N[l] * w * sec.rhoA * c2;
              Ke.block<3, 3>(6 * k + 3, 6 * l + 3) += N[k] * N[l] * w * ri.tangent;
            }
        }
      } else if (mass_matrix) {
        const Vector3d gyro = p.R * p.W.cross(Js * p.W);
        const Matrix3d Jsp = p.R * Js * p.R.transpose();
        for (int k = 0; k < 3; ++k) {
          R.segment<3>(dofs[6 * k + 3]) += N[k] * w * gyro;
          for (int l = 0; l < 3; ++l) {
            Ke.block<3, 3>(6 * k, 6 * l).diagonal().array() += N[k] * N[l] * w * sec.rhoA;
            Ke.block<3, 3>(6 * k + 3, 6 * l + 3) += N[k] * N[l] * w * Jsp;
          }
        }
      }
    }
    add_block<18>(K, dofs, Ke);
  }

  for (const RigidBody& b : m.bodies) {
    const int nd = b.node;
    R.segment<3>(6 * nd) -= b.mass * grav;
    Eigen::Matrix<double, 6, 6> Kb = Eigen::Matrix<double, 6, 6>::Zero();
    if (inertia) {
      const RotaryInertiaEval ri =
          rule.rotary(b.inertia, nodes[nd].R, nodes[nd].W, nodes[nd].A, dt, al(nd), K != nullptr);
      R.segment<3>(6 * nd) += b.mass * acc(nd);
      R.segment<3>(6 * nd + 3) += ri.residual;
      Kb.block<3, 3>(0, 0).diagonal().array() += b.mass * c2;
      Kb.block<3, 3>(3, 3) = ri.tangent;
    } else if (mass_matrix) {
      const NodeState& ns = nodes[nd];
      R.segment<3>(6 * nd + 3) += ns.R * ns.W.cross(b.inertia * ns.W);
      Kb.block<3, 3>(0, 0).diagonal().array() += b.mass;
      Kb.block<3, 3>(3, 3) = ns.R * b.inertia * ns.R.transpose();
    }
    add_block<6>(K, dofs6(nd), Kb);
  }

  for (const NodalLoad& L : m.loads) {
    const double f = rule.load(L.series, s.t0, t1);
    const int nd = L.node;
    R.segment<3>(6 * nd) -= f * L.force;
    // pseudo-moment Xi^T m of a fixed-axis spatial moment and its load stiffness
    const Vector3d a = al(nd);
    R.segment<3>(6 * nd + 3) -= f * rodrigues_xi(a).transpose() * L.moment;
    const Matrix3d Kl = mass_matrix ? Matrix3d::Zero() : Matrix3d(-f * d_xi_transpose_m(a, L.moment));
    add_block<3>(K, dofs3(6 * nd + 3), Kl);
  }

  // plane and rough-surface pairs
  contacts.assemble(nodes, q, dt, rule, mass_matrix, R, K);
}

VectorXd external_loads(const AssemblyState& s, double t) {
  const Model& m = s.model;
  VectorXd f = VectorXd::Zero(6 * static_cast<Eigen::Index>(m.X.size()));
  const Vector3d grav = m.gravity_series(t) * m.gravity;
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const BeamSection& sec = m.sections[static_cast<std::size_t>(m.beams[e].section)];
    for (const MassPoint& p : s.points.mass[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      for (int k = 0; k < 3; ++k) f.segment<3>(6 * m.beams[e].nodes[k]) += N[k] * p.weight * p.jac * sec.rhoA * grav;
    }
  }
  for (const RigidBody& b : m.bodies) f.segment<3>(6 * b.node) += b.mass * grav;
  for (const NodalLoad& L : m.loads) {
    f.segment<3>(6 * L.node) += L.series(t) * L.force;
    f.segment<3>(6 * L.node + 3) += L.series(t) * L.moment;
  }
  return f;
}

}  // namespace rollspec::rolling
