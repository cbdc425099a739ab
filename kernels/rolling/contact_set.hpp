// The contact pairs of a rolling model behind one interface: node-to-plane pairs (D-13, D-14,
// README Sec. 4, R-50) and node-to-rough-surface pairs (R-61, friction R-63, damper R-64). The
// Solver sets them up, assembles, checks, limits the step and commits through this set only; what
// differs between the kinds lives in the two pair classes of contact_set.cpp.
// Pairs run planes first, then surfaces, each in model order: every sum over pairs (residual,
// sparse entries, works, penalty energy) keeps that order. Internal to kernels/rolling.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "kernels/rolling/model.hpp"
#include "kernels/rolling/solver.hpp"
#include "kernels/rolling/time_rule.hpp"

namespace rollspec::rolling {

struct Sink;

class ContactSet {
 public:
  // Gaps and penalty energy of the pairs at the initial node positions (forces follow in the
  // first step). The model must outlive the set.
  ContactSet(const Model& model, const std::vector<NodeState>& nodes);
  ~ContactSet();
  ContactSet(const ContactSet&) = delete;
  ContactSet& operator=(const ContactSet&) = delete;

  // Adds every pair's residual and tangent for the increments q (6 per node) from the committed
  // nodes; each pair keeps its evaluation for the checks and the commit below. mass_matrix:
  // residual only, zero tangent blocks (the pattern stays the same).
  void assemble(const std::vector<NodeState>& nodes, const Eigen::VectorXd& q, double dt, const TimeRule& rule,
                bool mass_matrix, Eigen::VectorXd& R, Sink* K);
  // Undoes what the last assemble changed in the pairs (the closest-point starts), so that
  // assembling the same q again, e.g. with the tangent after a residual-only pass, gives the same bits.
  void rewind();
  // Every rough-surface closest point was found; otherwise the step is cut.
  bool closest_points_found() const;
  // A pair open at the step start closes with -g_n > depth.
  bool closes_deeper_than(double depth) const;
  // Largest step <= dt allowed by `fraction` of 2 pi sqrt(m_node/eps_n) while a pair is closed or
  // closing within dt at the current normal velocity.
  double step_limit(const std::vector<NodeState>& nodes, const std::vector<double>& node_mass, double dt,
                    double fraction) const;
  // Commit of the last evaluation: histories, outputs, friction and
  // damper works into acc; the deepest newly closed -g_n into new_penetration.
  void commit(const Eigen::VectorXd& q, const TimeRule& rule, Energies& acc, double& new_penetration);

  double penalty_energy() const { return penalty_; }
  double tangential_energy() const { return tangential_; }
  const std::vector<ContactOutput>& plane_outputs() const { return plane_out_; }
  const std::vector<ContactState>& plane_states() const { return plane_state_; }
  const std::vector<ContactOutput>& surface_outputs() const { return surface_out_; }

  class Pair;  // one pair of either kind (the interface the kinds implement, contact_set.cpp)

 private:
  std::vector<ContactOutput> plane_out_, surface_out_;
  std::vector<ContactState> plane_state_, surface_state_;  // friction histories
  std::vector<std::unique_ptr<Pair>> pairs_;
  double penalty_ = 0.0, tangential_ = 0.0;  // committed normal penalty and stick-spring energies
};

}  // namespace rollspec::rolling
