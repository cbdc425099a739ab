// Builders and drivers for the seed 000 examples and the verification problems (README
// Sec. 6). Plain structs in, plain results out; the engine's scenes wrap these.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "kernels/rolling/model.hpp"
#include "kernels/rolling/solver.hpp"

namespace rollspec::rolling {

// ---- seed 000 example 4.1: disc sliding, then rolling --------------------------------
struct DiscParams {
  double radius = 0.2, omega0 = 127.03, V0 = 2.355, mu = 0.25, g = 9.81;
  double mass = 1e3, length = 1.0;  // inertia about the axis m r^2/2 (solid disc/cylinder)
  double eps_n = 1e8, eps_t = 1e7;
  bool rolling = true;
};
// Plane y = 0 (normal +y), disc axis z, gravity -y, V0 along +x, angular velocity -omega0 z
// (contact point initially sliding backwards), centre at the static penetration m g/eps_n.
Model disc_model(const DiscParams& p);

struct DiscSummary {
  double t_roll = -1.0;          // first step at which sliding stops (slip -> stick)
  double final_speed = 0.0;      // |v| at the end
  double final_omega = 0.0;      // |w| at the end
  double mean_speed = 0.0;       // mean |v| over the last second (stick-spring oscillation averaged)
  double mean_roll_speed = 0.0;  // mean r |w| over the last second
  double slip_after_roll = 0.0;  // friction work after t_roll (chatter at the spring peaks)
  double energy_loss = 0.0;      // mechanical energy lost (kinetic + penalty + gravity)
  double dissipation = 0.0;      // accumulated return-mapping dissipation
  double friction_work = 0.0;    // mechanical energy removed by friction (trapezoidal)
  double penetration = 0.0;      // -g_n at the end
  // analytic references (seed 000 Eq. 48-50)
  double t_roll_exact = 0.0, final_speed_exact = 0.0, energy_loss_exact = 0.0, penetration_exact = 0.0;
};
DiscSummary summarize_disc(const DiscParams& p, const History& h);

// ---- cylinder on an incline: plane y = 0, gravity tilted by theta (down-slope part
// ramped in over t_ramp) --------------------------------------------------------------
struct InclineParams {
  double theta = 0.5235987755982988;  // 30 deg
  double mu = 0.2;
  double radius = 0.2, mass = 1e3, g = 9.81, eps_n = 1e8, eps_t = 1e7, t_ramp = 0.5;
};
Model incline_model(const InclineParams& p);

// ---- seed 000 example 4.2: cantilever rolling and sliding on a plane ----------------
struct CantileverParams {
  double D = 0.3, L = 10.0, E = 1e7, nu = 0.0, rho = 1e5, g = 9.81, mu = 0.5;
  double eps_n = 1e9, eps_t = 1e7;
  int n_elements = 100;
  bool rolling = true;
};
// Beam A=(0,0,0) to B=(L,0,0), plane z = -D/2 (normal +z) with every node in contact,
// gravity -z ramped over t in [0,1]; A clamped; B: y = 0,0,+5,0,+5 at t = 0..4 (Table I).
Model cantilever_model(const CantileverParams& p);

struct CantileverSnapshot {
  double time = 0.0;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  double reaction_y = 0.0;                                      // reaction at B in y
  Eigen::Vector3d root_reaction = Eigen::Vector3d::Zero();      // reaction force at A
  Eigen::Vector3d contact_force_sum = Eigen::Vector3d::Zero();  // sum of contact forces on the beam
  double max_abs_torsion = 0.0;                                 // max |M_1| over the Gauss points
  std::vector<double> x_ref, torsion;                           // torsion M_1 along the reference x coordinate
  int n_slip = 0, n_stick = 0, n_open = 0;
};
struct CantileverRun {
  std::vector<CantileverSnapshot> snapshots;  // at the requested times
  bool completed = true;
  double failed_at = 0.0;
  int steps = 0, newton_iterations = 0, cuts = 0;
  double friction_dissipation = 0.0;  // return mapping
  double friction_work = 0.0;         // trapezoidal work of friction forces and moments
};
// Quasi-static run to t_end with steps dt, snapshots at the given times.
CantileverRun run_cantilever(const CantileverParams& p, double t_end, double dt,
                             const std::vector<double>& snapshot_times);

// ---- seed 000 example 4.3: puck sliding between walls ------------------------------
// Rigid puck (one rigid-body node, sphere radius r, axis y, height h) in the plane y = 0:
// y displacement and the x, z rotations imposed (the floor is frictionless and never
// opens, as in the seed); four walls x = +-half_width, z = +-half_width (normals inward),
// one rolling contact pair per wall. Optional seed-style start: force (0, 0, Fz) and moment
// (0, My, 0) with a triangular pulse 0 -> peak at pulse/2 -> 0 at pulse (seed Fig. 19 gives
// the peaks 3 x 1e4 N and 3 x 5e3 N m over 0.1 s; the pulse shape is our reading of it).
struct PuckParams {
  double radius = 0.25, mass = 1e3, height = 1.0, half_width = 1.0;
  double mu = 0.0, eps_n = 1e8, eps_t = 1e7;
  Eigen::Vector3d v0 = Eigen::Vector3d::Zero();  // initial velocity (x, 0, z)
  double omega0 = 0.0;                           // initial spin about y
  double force_peak = 0.0, moment_peak = 0.0, pulse = 0.1;
};
Model puck_model(const PuckParams& p);
double puck_axial_inertia(const PuckParams& p);  // m r^2 / 2

// Impacts found in a history recorded every step: maximal runs of records with at least
// one active contact. Values just before the first and just after the last contact record.
struct Impact {
  double t_start = 0.0, t_end = 0.0;
  int pair = -1;                                   // contact pair of the first active record
  double energy_before = 0.0, energy_after = 0.0;  // kinetic + penalty + tangential_elastic
  Eigen::Vector3d v_before = Eigen::Vector3d::Zero(), v_after = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_before = Eigen::Vector3d::Zero(), w_after = Eigen::Vector3d::Zero();
  double max_penetration = 0.0;
};
std::vector<Impact> find_impacts(const History& h, int node = 0);

// ---- seed 000 example 4.4: flying beam ----------------------------------------------
// Straight beam of length L along x centred at (0, 0, r) lying on the plane z = 0 (normal +z),
// a second plane through (0, wall_distance, 0) with normal (-1, -1, 0) (seed: 1000), gravity
// -g z, every node a rolling contact sphere of radius r with both planes. Seed data: EA = 3.6e8,
// EI = GJ = 9.2e9, GA = 1.8e8, mass 1.3e-3 per length, r = 25, L = 1000, mu = 0.8,
// eps_n = eps_t = 1e3, 10 elements, dt = 1e-3, t = 0..20, lateral force F_y at the centre node
// ramped 0 -> force_peak over ramp (seed Fig. 25: 1e3 at t = 1). Rotary inertia per length from
// the mass per length and a solid circular section (rho I = m r^2 / 4, rho J = m r^2 / 2).
struct FlyingBeamParams {
  double EA = 3.6e8, EI = 9.2e9, GJ = 9.2e9, GA = 1.8e8, mass_per_length = 1.3e-3;
  double radius = 25.0, length = 1000.0, g = 9.81, wall_distance = 1000.0;
  double mu = 0.8, eps_n = 1e3, eps_t = 1e3;
  int n_elements = 10;
  // F_y(t): 0 -> force_peak linearly over [0, ramp], back to 0 at force_end (> ramp; seed Fig. 25
  // shows the rise to 1e3 at t = 1; that it is then removed within one step is our reading)
  double force_peak = 1e3, ramp = 1.0, force_end = 1.001;
  double start_penetration = -1.0;  // < 0: the static value (mass per node) g / eps_n
};
Model flying_beam_model(const FlyingBeamParams& p);

}  // namespace rollspec::rolling
