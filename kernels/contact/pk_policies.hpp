#pragma once
// The two constraint policies of the Polonsky–Keer core (polonsky_keer.hpp): the imposed approach
// (ContactSolver::solve, and the periodic mean pressure of solve_load; README Eq. 6–10, 6a, 7a,
// 7b) and the imposed total load on the open half-space (solve_at_force; Eq. 17, 17a, 17b).
// Internal to the kernel; the solver hands them its work arrays.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "kernels/contact/box_product.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/polonsky_keer.hpp"

namespace rollspec::contact::detail {

// The solver's work arrays (one set per solver): u = C p, g, t, r = C t, x (preconditioned
// gradient or a product's scratch), the block partial sums and the CG set marks.
struct PkArrays {
  std::vector<double>& u;
  std::vector<double>& g;
  std::vector<double>& t;
  std::vector<double>& r;
  std::vector<double>& x;
  std::vector<double>& part;
  std::vector<unsigned char>& set;
};

// Imposed approach w (`load` false: the cells A = {s < w}, Eq. 6a) or, on the periodic grid, the
// imposed mean pressure (`load` true: every cell, w the multiplier, Σ p rescaled after each step).
class ApproachPolicy final : public PkPolicy {
 public:
  // C v on `cells`; true if the product was the full one (u then exact on every cell).
  using Product = std::function<bool(const double*, double*)>;
  ApproachPolicy(const PkArrays& a, Product product, const std::vector<double>& s, std::vector<double>& p,
                 const std::vector<std::uint32_t>& cells, double target, bool load, double g_ref, double c,
                 std::size_t active, std::size_t nx, const SolverOptions& opt, ContactResult& res);
  // The cold start when p is all zero (one line search on the interference, Eq. 7; uniform in load
  // control), then the load balance in load control. Returns true if u = C p holds after it.
  bool start(bool all_zero);
  void refresh() override;
  void evaluate() override;
  bool prepare() override { return false; }
  void direction(double& num, double& den) override;
  void release(double& num, double& den) override;
  bool step(double tau, bool released) override;
  double approach() const { return w_; }
  bool u_full() const { return u_full_; }  // u = C p on every cell (not only on A, not carried)

 private:
  void direction_and_step(double& num, double& den);
  void enforce_load();
  PkArrays a_;
  Product product_;
  const std::vector<double>& s_;
  std::vector<double>& p_;
  const std::vector<std::uint32_t>& cells_;
  const double target_, hardness_, c_, g_ref_, gamma_;
  const bool load_, precondition_;
  const std::size_t n_, nx_;
  ContactResult& res_;
  double w_;
  bool u_full_ = false;
  double g_old_ = 1.0;
  bool conjugate_ = false;  // δ of Polonsky & Keer: restart after a set change
  double gg_ = 0.0;         // Σ_S g_i² on the CG set of this iteration
  std::size_t free_count_ = 0;
};

// Imposed total load Σ p = total on the open half-space, w the multiplier (Eq. 17): the listed
// cells L = {s < w_L} ∪ {p > 0} with products on their box (Eq. 3c), zero-sum directions (17a),
// the free cells rescaled after a step (17b) and u carried through clips by direct sums (Eq. 3b).
class ForcePolicy final : public PkPolicy {
 public:
  // The lists and `delta` are the solver's (kept between solves for their capacity).
  struct Lists {
    std::vector<std::uint32_t>& listed;
    std::vector<std::uint32_t>& free;
    std::vector<std::uint32_t>& touched;
    std::vector<double>& delta;
  };
  ForcePolicy(const PkArrays& a, const Lists& lists, HalfSpaceOperator& op, BoxProduct& box,
              const std::vector<double>& s, std::vector<double>& p, double total, double hint, const SolverOptions& opt,
              ContactResult& res);
  // The start: the warm start clipped into [0, H], cold from the interference at the hint (or
  // uniform), L listed, Σ p brought to the total (Eq. 17b).
  void start();
  void refresh() override { box_.apply(p_.data(), a_.u.data()); }
  void evaluate() override;
  bool prepare() override;
  void direction(double& num, double& den) override;
  void release(double& num, double& den) override;
  bool step(double tau, bool released) override;
  double approach() const { return w_; }
  const std::vector<std::uint32_t>& cells() const { return l_.listed; }

 private:
  double margin(double w) const;
  void build_list();
  void collect_free();
  void direction_and_step(bool project, double& num, double& den);
  bool rescale(bool carry_u, double free_sum, double capped_sum);
  bool carry(bool changed);
  PkArrays a_;
  Lists l_;
  HalfSpaceOperator& op_;
  BoxProduct& box_;
  const std::vector<double>& s_;
  std::vector<double>& p_;
  const double total_, hint_, hardness_, c_, s_min_;
  const bool precondition_;
  const std::size_t nx_;
  ContactResult& res_;
  double w_list_;
  double gamma_ = 0.0;
  double g_old_ = 1.0, w_ = 0.0, g_ref_ = 1.0;
  bool conjugate_ = false;
  double gg_ = 0.0, g_sum_ = 0.0;
};

}  // namespace rollspec::contact::detail
