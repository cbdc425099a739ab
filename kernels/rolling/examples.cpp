#include "kernels/rolling/examples.hpp"

#include <algorithm>
#include <cmath>

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {
Matrix3d disc_inertia(double m, double r, double L) {
  const double Ia = 0.5 * m * r * r, It = m * (3.0 * r * r + L * L) / 12.0;
  return Vector3d(It, It, Ia).asDiagonal();
}
}  // namespace

Model disc_model(const DiscParams& p) {
  Model m;
  const double pen = p.mass * p.g / p.eps_n;
  const int n = m.add_node(Vector3d(0.0, p.radius - pen, 0.0));
  m.v0 = {Vector3d(p.V0, 0, 0)};
  m.w0 = {Vector3d(0, 0, -p.omega0)};
  m.bodies.push_back(RigidBody{n, p.mass, disc_inertia(p.mass, p.radius, p.length)});
  m.planes.push_back(make_plane(Vector3d::Zero(), Vector3d::UnitY()));
  m.contacts.push_back(ContactPair{n, 0, ContactLaw{p.radius, p.mu, p.eps_n, p.eps_t, p.rolling}});
  m.gravity = Vector3d(0, -p.g, 0);
  return m;
}

DiscSummary summarize_disc(const DiscParams& p, const History& h) {
  DiscSummary s;
  const double I = 0.5 * p.mass * p.radius * p.radius;
  s.t_roll_exact = (p.radius * p.omega0 - p.V0) / (3.0 * p.mu * p.g);  // Eq. 50
  s.final_speed_exact = (p.V0 + p.radius * p.omega0 / 2.0) / 1.5;      // momentum about C
  s.energy_loss_exact = 0.5 * p.mass * p.V0 * p.V0 + 0.5 * I * p.omega0 * p.omega0 -
                        0.5 * (p.mass + I / (p.radius * p.radius)) * s.final_speed_exact * s.final_speed_exact;
  s.penetration_exact = p.mass * p.g / p.eps_n;
  std::size_t k_roll = 0;
  for (std::size_t k = 1; k < h.time.size(); ++k)
    if (h.contact[k - 1][0].slip && h.contact[k][0].active && !h.contact[k][0].slip) {
      k_roll = k;
      s.t_roll = h.time[k];
      break;
    }
  const std::size_t e = h.time.size() - 1;
  s.final_speed = h.velocity[e][0].norm();
  s.final_omega = h.angular_velocity[e][0].norm();
  auto mech = [&](std::size_t k) {
    const Energies& E = h.energy[k];
    return E.kinetic + E.penalty + E.tangential_elastic - E.external_work;  // gravity work = -potential change
  };
  s.energy_loss = mech(0) - mech(e);
  s.dissipation = h.energy[e].friction_dissipation;
  s.friction_work = h.energy[e].friction_work - h.energy[e].tangential_elastic;
  s.slip_after_roll = s.dissipation - h.energy[k_roll].friction_dissipation;
  int n = 0;
  for (std::size_t k = 0; k < h.time.size(); ++k)
    if (h.time[k] >= h.time[e] - 1.0) {
      s.mean_speed += h.velocity[k][0].norm();
      s.mean_roll_speed += p.radius * h.angular_velocity[k][0].norm();
      ++n;
    }
  s.mean_speed /= n;
  s.mean_roll_speed /= n;
  s.penetration = -h.contact[e][0].g_n;
  return s;
}

Model incline_model(const InclineParams& p) {
  Model m;
  // the normal part of gravity acts from t = 0 on a cylinder resting at its static
  // penetration; the down-slope part (+x) is ramped in over t_ramp as a nodal load, so
  // that the start-up transient of the undamped penalty springs stays small.
  const double gn = p.g * std::cos(p.theta);
  const int n = m.add_node(Vector3d(0.0, p.radius - p.mass * gn / p.eps_n, 0.0));
  m.bodies.push_back(RigidBody{n, p.mass, disc_inertia(p.mass, p.radius, 1.0)});
  m.planes.push_back(make_plane(Vector3d::Zero(), Vector3d::UnitY()));
  m.contacts.push_back(ContactPair{n, 0, ContactLaw{p.radius, p.mu, p.eps_n, p.eps_t, true}});
  m.gravity = Vector3d(0.0, -gn, 0.0);
  m.loads.push_back(NodalLoad{n, Vector3d(p.mass * p.g * std::sin(p.theta), 0, 0), Vector3d::Zero(),
                              TimeSeries::ramp(0.0, p.t_ramp)});
  return m;
}

Model cantilever_model(const CantileverParams& p) {
  Model m;
  m.sections.push_back(circular_section(p.E, p.nu, p.rho, p.D));
  const std::vector<int> ids =
      add_straight_beam(m, Vector3d::Zero(), Vector3d(p.L, 0, 0), p.n_elements, 0, Vector3d::UnitY());
  m.planes.push_back(make_plane(Vector3d(0, 0, -0.5 * p.D), Vector3d::UnitZ()));
  for (int id : ids) m.contacts.push_back(ContactPair{id, 0, ContactLaw{0.5 * p.D, p.mu, p.eps_n, p.eps_t, p.rolling}});
  m.gravity = Vector3d(0, 0, -p.g);
  m.gravity_series = TimeSeries::ramp(0.0, 1.0);
  for (int d = 0; d < 6; ++d) m.imposed.push_back(ImposedDof{ids.front(), d, 0.0, TimeSeries::constant()});
  m.imposed.push_back(ImposedDof{ids.back(), 1, 1.0, TimeSeries{{0, 1, 2, 3, 4}, {0, 0, 5, 0, 5}}});
  return m;
}

CantileverRun run_cantilever(const CantileverParams& p, double t_end, double dt,
                             const std::vector<double>& snapshot_times) {
  SolverOptions o;
  o.analysis = Analysis::QuasiStatic;
  o.force_tol = 1e-6 * p.rho * 0.25 * 3.14159265358979 * p.D * p.D * p.L * p.g;  // relative to the weight
  o.disp_tol = 1e-10;
  o.max_iterations = 60;  // stick/slip fronts move about one node per iteration
  o.max_cuts = 12;
  o.max_line_search = 12;
  Solver S(cantilever_model(p), o);
  CantileverRun out;
  const long n = std::lround(t_end / dt);
  std::size_t next = 0;
  for (long k = 1; k <= n; ++k) {
    const StepReport rep = S.advance(double(k) * dt);
    out.newton_iterations += rep.iterations;
    out.cuts += rep.cuts;
    if (!rep.converged) {
      out.completed = false;
      out.failed_at = S.time();
      break;
    }
    ++out.steps;
    while (next < snapshot_times.size() && snapshot_times[next] <= S.time() + 1e-9) {
      CantileverSnapshot s;
      s.time = S.time();
      const int tip = S.model().beams.back().nodes[2];
      s.tip = S.nodes()[static_cast<std::size_t>(tip)].x;
      s.reaction_y = S.reactions().back();
      for (int d = 0; d < 3; ++d) s.root_reaction(d) = S.reactions()[static_cast<std::size_t>(d)];
      for (const BeamResultant& r : S.beam_resultants()) {
        s.x_ref.push_back(r.reference_position.x());
        s.torsion.push_back(r.moment.x());
        s.max_abs_torsion = std::max(s.max_abs_torsion, std::abs(r.moment.x()));
      }
      for (const ContactOutput& c : S.contacts()) {
        s.contact_force_sum += c.force;
        if (!c.active)
          ++s.n_open;
        else if (c.slip)
          ++s.n_slip;
        else
          ++s.n_stick;
      }
      out.snapshots.push_back(s);
      ++next;
    }
  }
  out.friction_dissipation = S.energies().friction_dissipation;
  out.friction_work = S.energies().friction_work;
  return out;
}

double puck_axial_inertia(const PuckParams& p) { return 0.5 * p.mass * p.radius * p.radius; }

Model puck_model(const PuckParams& p) {
  Model m;
  const int n = m.add_node(Vector3d::Zero());
  const double Ia = puck_axial_inertia(p), It = p.mass * (3.0 * p.radius * p.radius + p.height * p.height) / 12.0;
  m.bodies.push_back(RigidBody{n, p.mass, Vector3d(It, Ia, It).asDiagonal()});
  m.v0 = {p.v0};
  m.w0 = {Vector3d(0.0, p.omega0, 0.0)};
  for (int dof : {1, 3, 5}) m.imposed.push_back(ImposedDof{n, dof, 0.0, TimeSeries::constant(1.0)});
  const double a = p.half_width;
  m.planes = {make_plane(Vector3d(a, 0, 0), -Vector3d::UnitX()), make_plane(Vector3d(-a, 0, 0), Vector3d::UnitX()),
              make_plane(Vector3d(0, 0, a), -Vector3d::UnitZ()), make_plane(Vector3d(0, 0, -a), Vector3d::UnitZ())};
  for (int w = 0; w < 4; ++w)
    m.contacts.push_back(ContactPair{n, w, ContactLaw{p.radius, p.mu, p.eps_n, p.eps_t, true}});
  if (p.force_peak != 0.0 || p.moment_peak != 0.0) {
    const TimeSeries pulse{{0.0, 0.5 * p.pulse, p.pulse}, {0.0, 1.0, 0.0}};
    m.loads.push_back(NodalLoad{n, Vector3d(0, 0, p.force_peak), Vector3d(0, p.moment_peak, 0), pulse});
  }
  return m;
}

std::vector<Impact> find_impacts(const History& h, int node) {
  std::vector<Impact> out;
  const std::size_t nd = static_cast<std::size_t>(node);
  auto active = [&](std::size_t k, int* pair) {
    for (std::size_t c = 0; c < h.contact[k].size(); ++c)
      if (h.contact[k][c].active || h.contact[k][c].force.squaredNorm() > 0.0) {
        if (pair) *pair = static_cast<int>(c);
        return true;
      }
    return false;
  };
  auto energy = [&](std::size_t k) {
    const Energies& e = h.energy[k];
    return e.kinetic + e.penalty + e.tangential_elastic;
  };
  std::size_t k = 1;
  while (k < h.time.size()) {
    int pair = -1;
    if (!active(k, &pair)) {
      ++k;
      continue;
    }
    Impact im;
    im.pair = pair;
    im.t_start = h.time[k];
    im.energy_before = energy(k - 1);
    im.v_before = h.velocity[k - 1][nd];
    im.w_before = h.angular_velocity[k - 1][nd];
    while (k < h.time.size() && active(k, nullptr)) {
      for (const ContactOutput& c : h.contact[k]) im.max_penetration = std::max(im.max_penetration, -c.g_n);
      ++k;
    }
    if (k >= h.time.size()) break;  // still in contact at the end: incomplete impact
    im.t_end = h.time[k];
    im.energy_after = energy(k);
    im.v_after = h.velocity[k][nd];
    im.w_after = h.angular_velocity[k][nd];
    out.push_back(im);
  }
  return out;
}

Model flying_beam_model(const FlyingBeamParams& p) {
  Model m;
  BeamSection s;
  s.EA = p.EA;
  s.GA2 = s.GA3 = p.GA;
  s.GJ = p.GJ;
  s.EI2 = s.EI3 = p.EI;
  s.rhoA = p.mass_per_length;
  s.rhoI2 = s.rhoI3 = 0.25 * p.mass_per_length * p.radius * p.radius;
  s.rhoJ1 = 0.5 * p.mass_per_length * p.radius * p.radius;
  s.outer_radius = p.radius;
  m.sections.push_back(s);
  const double node_mass = p.mass_per_length * p.length / (2.0 * p.n_elements);
  const double pen = p.start_penetration >= 0.0 ? p.start_penetration : node_mass * p.g / p.eps_n;
  const double z = p.radius - pen;
  const std::vector<int> ids = add_straight_beam(m, Vector3d(-0.5 * p.length, 0, z), Vector3d(0.5 * p.length, 0, z),
                                                 p.n_elements, 0, Vector3d::UnitY());
  m.planes.push_back(make_plane(Vector3d::Zero(), Vector3d::UnitZ()));
  m.planes.push_back(make_plane(Vector3d(0, p.wall_distance, 0), Vector3d(-1, -1, 0)));
  for (int pl = 0; pl < 2; ++pl)
    for (int id : ids) m.contacts.push_back(ContactPair{id, pl, ContactLaw{p.radius, p.mu, p.eps_n, p.eps_t, true}});
  m.gravity = Vector3d(0, 0, -p.g);
  TimeSeries ts = TimeSeries::ramp(0.0, p.ramp);
  if (p.force_end > p.ramp) ts = TimeSeries{{0.0, p.ramp, p.force_end}, {0.0, 1.0, 0.0}};
  m.loads.push_back(NodalLoad{ids[ids.size() / 2], Vector3d(0, p.force_peak, 0), Vector3d::Zero(), ts});
  return m;
}

}  // namespace rollspec::rolling
