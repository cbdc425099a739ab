// Newton-Raphson solver for rolling-beam models: quasi-static load stepping or Newmark
// trapezoidal dynamics (README Sec. 4), consistent tangent of beams, inertia, loads and
// rolling contact, Eigen SparseLU with the sparsity pattern analysed once, step cutting
// (halving) when Newton fails. Updated Lagrangian: the unknowns of a step are the nodal
// incremental displacements du and incremental Rodrigues parameters a (D-12), updated
// additively during the Newton iterations of the step. The parts: time_rule (the integrator),
// assembly (residual and tangent, R-40), contact_set (plane and rough-surface pairs), newton (the
// iteration of a step); solver.cpp sets up, steps, cuts and commits.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <vector>

#include "kernels/rolling/beam_element.hpp"
#include "kernels/rolling/contact_element.hpp"
#include "kernels/rolling/model.hpp"

namespace rollspec::rolling {

enum class Analysis { QuasiStatic, Dynamic };

// Dynamic time integrator. Newmark: trapezoidal rule, forces at t_{n+1}.
// EnergyConsistent: implicit midpoint for translations and rotations with the
// discrete-gradient normal penalty force, loads averaged over the step and friction at
// t_{n+1}; the discrete energy balance then holds to the Newton tolerance. Rigid-body
// models only (beam strain energy has no discrete gradient here): the Solver refuses beams.
enum class Integrator { Newmark, EnergyConsistent };

// Linear solver of the Newton steps (README R-44): a band LU with partial pivoting when the
// tangent's band holds few zeros (beams numbered along their length), else SparseLU.
enum class LinearSolver { Automatic, Band, Sparse };

struct SolverOptions {
  Analysis analysis = Analysis::Dynamic;
  int max_iterations = 30;
  double force_tol = 1e-6;                      // converged when ||R_free||_2 <= force_tol (N, N m)
  double disp_tol = 1e-12;                      // ... or when the last Newton correction ||d||_inf <= disp_tol
  int max_cuts = 10;                            // step halvings allowed below the nominal step
  int max_line_search = 0;                      // backtracking halvings per Newton iteration (0: pure Newton)
  bool consistent_initial_acceleration = true;  // dynamic: solve M a0 = f(0) at t0
  Integrator integrator = Integrator::Newmark;
  // Impact step control (README R-54), both off when 0:
  // impact_step_fraction > 0: while a contact is closed, or predicted to close within the step
  // from the current normal velocity, the step is limited to fraction * 2 pi sqrt(m_node/eps_n)
  // (m_node: rigid-body mass plus lumped beam mass of the node).
  double impact_step_fraction = 0.0;
  // max_new_penetration > 0: a converged step in which a contact closes with -g_n larger than
  // this is rejected and halved (counts as a cut; accepted once max_cuts is reached).
  double max_new_penetration = 0.0;
  LinearSolver linear_solver = LinearSolver::Automatic;
  // R-44a: iterates expected to end the Newton iteration are assembled without the tangent first
  // (again with it only when another direction is needed): the same iterates and bits, fewer
  // tangents. false: the tangent at every iterate (the plain reference).
  bool residual_only_checks = true;
};

struct NodeState {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  // position
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d v = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
  Eigen::Vector3d W = Eigen::Vector3d::Zero(), A = Eigen::Vector3d::Zero();  // body frame
};

struct Energies {
  double kinetic = 0.0;              // kinetic_translation + kinetic_rotation
  double kinetic_translation = 0.0;  // sum m v^2 / 2 (consistent beam mass, rigid bodies)
  double kinetic_rotation = 0.0;     // sum W . J W / 2 (beam mass points, rigid bodies)
  double strain = 0.0;
  double penalty = 0.0;             // normal penalty energy eps_n g_n^2 / 2
  double tangential_elastic = 0.0;  // energy in the stick springs |f_t|^2 / (2 eps_t)
  double external_work = 0.0;       // gravity and nodal loads (trapezoidal, R-43)
  double imposed_work = 0.0;        // work of the reactions at imposed DOFs
  // Mechanical energy removed by the friction forces and moments, trapezoidal in time
  // as the Newmark energy identity requires; includes what the stick springs store.
  double friction_work = 0.0;
  // Return-mapping dissipation: sum of f_max * slip increment (>= 0, seed 000 Eq. 13-14).
  double friction_dissipation = 0.0;
  // Energy removed by the normal contact dampers of rough-surface pairs (trapezoidal, R-64).
  double damping_work = 0.0;
  // kinetic + strain + penalty - external_work - imposed_work + friction_work + damping_work: constant up to
  // the normal-penalty kink at opening/closing and the O(dt^2) rotation terms.
  double balance() const {
    return kinetic + strain + penalty - external_work - imposed_work + friction_work + damping_work;
  }
  double initial_balance = 0.0;  // balance() at the solver's start time
  // balance() - initial_balance: 0 for an exact discrete energy balance
  double balance_error() const { return balance() - initial_balance; }
};

struct ContactOutput {
  bool active = false, slip = false;
  double g_n = 0.0;
  double penalty = 0.0;                             // normal penalty energy eps_n <-g_n>^2 / 2 of this pair
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // on the node, normal + friction
  Eigen::Vector3d friction = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();   // (C - x_o) x f
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // C
  Eigen::Vector3d damping = Eigen::Vector3d::Zero();  // normal damper force (rough surfaces, R-64)
};

struct StepReport {
  bool converged = false;
  int iterations = 0;                  // Newton iterations (line-search trials and failed attempts included)
  int cuts = 0;                        // halvings used to reach the target time (penetration cuts included)
  int steps = 0;                       // converged sub-steps taken to reach the target time
  int limited_steps = 0;               // sub-steps shortened by impact_step_fraction
  int penetration_cuts = 0;            // steps rejected for a new contact deeper than max_new_penetration
  double new_penetration = 0.0;        // deepest -g_n of contacts that closed in the accepted sub-steps
  std::vector<double> residual_norms;  // Newton history of the last sub-step
};

// Material stress resultants at a beam stiffness point (section frame, e1 = axis).
struct BeamResultant {
  int element = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d reference_position = Eigen::Vector3d::Zero();  // X(xi) of the undeformed beam
  Eigen::Vector3d force = Eigen::Vector3d::Zero();               // N = C_N Gamma
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();              // M = C_M K (moment(0) = torsion)
};

class Solver {
 public:
  Solver(Model model, SolverOptions options, double t0 = 0.0);
  ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  // Advance to t_target with one step of (t_target - t), halving on Newton failure.
  StepReport advance(double t_target);

  double time() const { return t_; }
  const Model& model() const { return model_; }
  const std::vector<NodeState>& nodes() const { return nodes_; }
  const std::vector<ContactOutput>& contacts() const;
  const std::vector<ContactState>& contact_states() const;
  // Rough-surface contacts (model.surface_contacts order); friction fields zero when mu = 0.
  const std::vector<ContactOutput>& surface_contacts() const;
  Energies energies() const;
  // Reactions at the imposed DOFs (model.imposed order), from the last converged step.
  const std::vector<double>& reactions() const { return reactions_; }
  std::vector<BeamResultant> beam_resultants() const;
  // Analyses of the tangent's pattern so far (SparseLU::analyzePattern or the band LU set up; 1
  // after the first iteration).
  int pattern_analyses() const;
  // Residual-only passes that had to be assembled again with the tangent (R-44a).
  long residual_only_repeats() const;
  // Lumped node masses (rigid-body mass + row sums of the consistent beam mass), R-54.
  const std::vector<double>& node_masses() const { return node_mass_; }
  // Largest step allowed by impact_step_fraction for a step of length dt from the current
  // state (dt itself when no contact is closed or closing), R-54.
  double impact_step_limit(double dt) const;

  // Residual and tangent of the full model (6 DOFs per node, [du, a] per node) for the
  // given increments from the committed state; for tests (finite-difference checks).
  void residual_and_tangent(const Eigen::VectorXd& q, double t_next, double dt, Eigen::VectorXd& r, Eigen::MatrixXd* K);

 private:
  struct Impl;  // equations, beam Gauss points, contact set, time rule, Newton driver
  std::unique_ptr<Impl> impl_;
  Model model_;
  SolverOptions opt_;
  double t_ = 0.0;
  std::vector<NodeState> nodes_;
  std::vector<double> reactions_;
  Energies acc_;  // accumulated works and dissipation
  std::vector<double> node_mass_;

  bool try_step(double t_next, double dt, StepReport& rep, bool allow_penetration_cut);
  void commit_step(const Eigen::VectorXd& q, const Eigen::VectorXd& R, double t_next, double dt, StepReport& rep);
  void initial_acceleration();
};

// A run: output every `record_every` steps (and the initial state).
struct RunOptions {
  double t_end = 1.0;
  double dt = 1e-3;
  int record_every = 1;
  std::vector<int> record_nodes;  // empty: all nodes
  bool record_energies = true;    // false: History::energy stays empty (saves a strain-energy pass per record)
};

struct History {
  std::vector<double> time;
  std::vector<std::vector<Eigen::Vector3d>> position, velocity, angular_velocity;  // [record][node], spatial
  std::vector<std::vector<Eigen::Vector3d>> acceleration, angular_acceleration;    // spatial (R A for the latter)
  std::vector<std::vector<Eigen::Matrix3d>> rotation;
  std::vector<std::vector<ContactOutput>> contact;          // [record][contact pair]
  std::vector<std::vector<ContactOutput>> surface_contact;  // [record][surface contact pair]
  std::vector<Energies> energy;
  std::vector<std::vector<double>> reactions;  // [record][imposed dof]
  int steps = 0, newton_iterations = 0, cuts = 0;
  int substeps = 0, limited_steps = 0, penetration_cuts = 0;  // sums of the StepReport fields
  double new_penetration = 0.0;                               // max of StepReport::new_penetration
  bool completed = true;
  double failed_at = 0.0;
};

History run(const Model& model, const SolverOptions& options, const RunOptions& run_options);

}  // namespace rollspec::rolling
