#include "src/fit/fit_answer.hpp"

#include <cstdio>

#include "kernels/spectral/fit_search.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::fit {

namespace {

// Fisher's combination of the points' p-values, or the one point's, with its verdict line.
void combine(const std::vector<bool>& defined, const std::vector<double>& p_values,
             const std::vector<std::string>& verdicts, bool& out_defined, double& out_p, std::string& out_verdict) {
  if (p_values.size() == 1) {
    out_defined = defined[0], out_p = p_values[0], out_verdict = verdicts[0];
    return;
  }
  for (std::size_t i = 0; i < p_values.size(); ++i)
    if (!defined[i]) {
      out_verdict = "none (point " + std::to_string(i + 1) + ": " + verdicts[i] + ")";
      return;
    }
  out_defined = true;
  out_p = spectral::fisher_combined_p(p_values);
  const std::string buf = io::formatted("%s at level 0.05: p = %.3g (Fisher's combination of the %zu points' tests)",
                                        out_p < 0.05 ? "REJECTED" : "not rejected", out_p, p_values.size());
  out_verdict = buf;
}

}  // namespace

void combine_point_tests(FitReport& r) {
  std::vector<bool> d, du;
  std::vector<double> p, pu;
  std::vector<std::string> v, vu;
  for (const auto& x : r.points) {
    d.push_back(x.fitted.defined), p.push_back(x.fitted.p_value), v.push_back(x.fitted_verdict);
    du.push_back(x.test.result.defined), pu.push_back(x.test.result.p_value), vu.push_back(x.test.verdict);
  }
  combine(d, p, v, r.test_defined, r.p_value, r.verdict);
  combine(du, pu, vu, r.uncorrected_defined, r.p_value_uncorrected, r.verdict_uncorrected);
}

}  // namespace rollspec::fit
