#include "src/io/loss_effect.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <cstdio>

#include "kernels/spectral/ensemble_interval.hpp"
#include "src/io/number_text.hpp"
#include "src/io/psd_result.hpp"

namespace rollspec::io {

LossEffect loss_effect(const PsdEnsemble& open, const PsdEnsemble& closed, const std::vector<double>& products,
                       double level) {
  LossEffect e;
  const auto bands = result_bands(open.frequency, open.band_min, open.band_max);
  const std::size_t nb = bands.size(), n = open.band_scatter.size();
  if (nb == 0 || n != closed.band_scatter.size() || products.size() != n) return e;
  const std::uint64_t K = open.realisations;
  const double k = static_cast<double>(K), db = 10.0 / std::log(10.0);
  const double t = K > 1 ? boost::math::quantile(boost::math::students_t(k - 1.0), 0.5 * (1.0 + level)) : INFINITY;
  e.measured = true;
  e.shift_db.assign(n, NAN);
  e.shift_se_db.assign(n, NAN);
  e.half_width_db.assign(n, NAN);
  double largest = -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const spectral::Scatter &a = open.band_scatter[i], &b = closed.band_scatter[i];
    if (!(a.mean > 0.0) || !(b.mean > 0.0)) continue;
    // Var of ln(m1) - ln(m2) by the delta method, from the pairs' covariance (D-35a).
    const double cov = K > 1 ? (products[i] - k * a.mean * b.mean) / (k - 1.0) : 0.0;
    const double rel = a.std_dev * a.std_dev / (a.mean * a.mean) + b.std_dev * b.std_dev / (b.mean * b.mean) -
                       2.0 * cov / (a.mean * b.mean);
    e.shift_db[i] = db * std::log(a.mean / b.mean);
    e.shift_se_db[i] = db * std::sqrt(std::max(rel, 0.0) / k);
    const auto ci = spectral::mean_interval(a, K, level);
    if (!ci.defined()) {  // no interval (too few realisations): the largest shift is still said
      if (e.judged == 0 && std::fabs(e.shift_db[i]) > largest) {
        largest = std::fabs(e.shift_db[i]);
        e.worst_db = e.shift_db[i];
        e.worst_band = open.sensors[i / nb] + ", " + number_text(bands[i % nb].nominal) + " Hz";
      }
      continue;
    }
    if (e.judged == 0) largest = -1.0;  // the first band with an interval: judged bands only from here
    e.half_width_db[i] = 0.5 * db * std::log(ci.upper / ci.lower);
    ++e.judged;
    const double shift = std::fabs(e.shift_db[i]);
    const bool moved = shift > e.half_width_db[i] && shift > t * e.shift_se_db[i];
    e.moved += moved;
    if ((moved || e.moved == 0) && shift > largest) {
      largest = shift;
      e.worst_db = e.shift_db[i];
      e.worst_band = open.sensors[i / nb] + ", " + number_text(bands[i % nb].nominal) + " Hz";
    }
  }
  return e;
}

std::string loss_effect_sentence(double share, const LossEffect& e, bool& warning) {
  const std::string pct = io::formatted("%.3g %%", 100.0 * share);
  const std::string worst = io::formatted("%+.2f dB", e.worst_db);
  const std::string against =
      "against the same realisations with a contact that never opens ([contact] loss = closed; kernels/spectral "
      "D-35)";
  if (e.judged == 0) {  // nothing to hold a shift against, so nothing is claimed: a note with the shift
    warning = false;
    return "the ball lost contact " + std::string(pct) + " of the time, which shifts the bands by up to " + worst +
           " (" + e.worst_band + ") " + against + "; with fewer than " +
           std::to_string(spectral::kMinRealisationsForInterval) +
           " realisations no band has an interval to judge that by ([study] realisations)";
  }
  warning = e.moved > 0;
  if (!warning)
    return "the ball lost contact " + std::string(pct) + " of the time, which moves none of the " +
           std::to_string(e.judged) + " row-bands by more than its interval (largest shift " + worst + ", " +
           e.worst_band + ") " + against;
  return "the ball lost contact " + std::string(pct) + " of the time, which moves " + std::to_string(e.moved) +
         " of the " + std::to_string(e.judged) + " row-bands by more than their interval (up to " + worst + ", " +
         e.worst_band + ") " + against +
         ": [contact] law = linearised assumes a closed contact and is not valid there; a nonlinear law ([contact] "
         "law = hertz or table) models the loss, or less roughness ([texture]) or speed ([ball] speed) avoids it "
         "(warned when any band moves by more than its interval)";
}

}  // namespace rollspec::io
