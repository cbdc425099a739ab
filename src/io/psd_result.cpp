#include "src/io/psd_result.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/spectral/confidence.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "src/io/hdf5_file.hpp"

namespace rollspec::io {

double band_dof(double dof_per_bin, double band_width, double df, double enbw_bins, double record_seconds) {
  return std::max(dof_per_bin, std::min(dof_per_bin * band_width / (df * enbw_bins), 2.0 * band_width * record_seconds));
}

void write_frequency_scale(Hdf5Writer& w, const std::string& group, const std::vector<double>& frequency) {
  w.write(group + "/frequency", {frequency.size()}, frequency.data(), "Hz", "frequency of the one-sided PSD bins");
  w.make_scale(group + "/frequency", "frequency");
}

void write_sensor_scale(Hdf5Writer& w, const std::string& group, const std::vector<std::string>& sensors) {
  w.write_strings(group + "/sensor", sensors, "sensor names");
  w.make_scale(group + "/sensor", "sensor");
}

void write_psd_result(Hdf5Writer& w, const PsdEnsemble& e) {
  const std::size_t nf = e.frequency.size(), ns = e.sensors.size();
  const double df = e.frequency.size() > 1 ? e.frequency[1] - e.frequency[0] : 1.0;
  const auto f = spectral::chi_square_interval(e.dof_per_bin, e.confidence);
  std::vector<double> lo(e.mean.size()), hi(e.mean.size()), nu(e.mean.size(), e.dof_per_bin);
  const double K = static_cast<double>(e.realisations);
  for (std::size_t i = 0; i < e.mean.size(); ++i) {
    if (e.empirical_dof && e.realisations > 1 && e.std_dev[i] > 0.0)
      nu[i] = std::max(1.0, std::min(e.dof_per_bin, 2.0 * K * e.mean[i] * e.mean[i] / (e.std_dev[i] * e.std_dev[i])));
    const auto fi = e.empirical_dof ? spectral::chi_square_interval(nu[i], e.confidence) : f;
    lo[i] = e.mean[i] * fi.lower;
    hi[i] = e.mean[i] * fi.upper;
  }
  write_frequency_scale(w, "/psd", e.frequency);
  write_sensor_scale(w, "/psd", e.sensors);
  w.write("/psd/mean", {ns, nf}, e.mean.data(), e.units, "ensemble mean of the one-sided Welch PSD of the " + e.quantity);
  w.write("/psd/ci_lower", {ns, nf}, lo.data(), e.units, "lower bound of the chi-square confidence interval");
  w.write("/psd/ci_upper", {ns, nf}, hi.data(), e.units, "upper bound of the chi-square confidence interval");
  w.write("/psd/std", {ns, nf}, e.std_dev.data(), e.units, "ensemble standard deviation of one realisation's PSD");
  for (const char* d : {"/psd/mean", "/psd/ci_lower", "/psd/ci_upper", "/psd/std"}) {
    w.attach_scale(d, "/psd/sensor", 0);
    w.attach_scale(d, "/psd/frequency", 1);
  }
  w.attribute("/psd", "realisations", static_cast<std::int64_t>(e.realisations));
  w.attribute("/psd", "degrees_of_freedom", e.dof_per_bin);
  if (e.empirical_dof) {
    w.write("/psd/degrees_of_freedom", {ns, nf}, nu.data(), "1",
            "chi-square dof of each bin's mean: min(K x Welch dof, 2 K mean^2 / std^2) (Satterthwaite)");
    w.attach_scale("/psd/degrees_of_freedom", "/psd/sensor", 0);
    w.attach_scale("/psd/degrees_of_freedom", "/psd/frequency", 1);
  }
  w.attribute("/psd", "degrees_of_freedom_kind", std::string(e.empirical_dof ? "empirical" : "welch"));
  w.attribute("/psd", "confidence_level", e.confidence);
  w.attribute("/psd", "window_enbw_bins", e.window_enbw_bins);
  w.attribute("/psd", "quantity", e.quantity);

  const auto bands = spectral::third_octave_bands(std::max(e.band_min, df), std::min(e.band_max, e.frequency.back()));
  const std::size_t nb = bands.size();
  std::vector<double> centre(nb), nominal(nb), lower(nb), upper(nb), dof(nb), level(ns * nb), cil(ns * nb), ciu(ns * nb);
  for (std::size_t b = 0; b < nb; ++b) {
    centre[b] = bands[b].centre;
    nominal[b] = bands[b].nominal;
    lower[b] = bands[b].lower;
    upper[b] = bands[b].upper;
    dof[b] = band_dof(e.dof_per_bin, bands[b].upper - bands[b].lower, df, e.window_enbw_bins, e.record_seconds);
    for (std::size_t s = 0; s < ns; ++s) {
      double nu_b = dof[b];
      if (e.empirical_dof) {  // mean empirical dof of the band's bins, never above the Welch value
        double sum = 0.0, count = 0.0;
        for (std::size_t k = 0; k < nf; ++k)
          if (e.frequency[k] >= bands[b].lower && e.frequency[k] < bands[b].upper) sum += nu[s * nf + k], count += 1.0;
        if (count > 0.0) nu_b = std::min(dof[b], sum / count);
      }
      const auto fb = spectral::chi_square_interval(nu_b, e.confidence);
      const double avg = spectral::band_average(e.mean.data() + s * nf, nf, df, bands[b].lower, bands[b].upper);
      level[s * nb + b] = 10.0 * std::log10(avg);
      cil[s * nb + b] = 10.0 * std::log10(avg * fb.lower);
      ciu[s * nb + b] = 10.0 * std::log10(avg * fb.upper);
    }
  }
  w.write("/bands/centre_frequency", {nb}, centre.data(), "Hz", "IEC 61260-1 base-ten third-octave midband frequency");
  w.write("/bands/nominal_frequency", {nb}, nominal.data(), "Hz", "IEC 61260-1 nominal midband frequency");
  w.write("/bands/lower_frequency", {nb}, lower.data(), "Hz", "lower band edge");
  w.write("/bands/upper_frequency", {nb}, upper.data(), "Hz", "upper band edge");
  w.write("/bands/degrees_of_freedom", {nb}, dof.data(), "1", "chi-square degrees of freedom of the band level");
  const std::string db = "dB re 1 " + e.units;
  w.write("/bands/level_db", {ns, nb}, level.data(), db, "band-averaged PSD level");
  w.write("/bands/ci_lower_db", {ns, nb}, cil.data(), db, "lower bound of the band level's confidence interval");
  w.write("/bands/ci_upper_db", {ns, nb}, ciu.data(), db, "upper bound of the band level's confidence interval");
  w.make_scale("/bands/centre_frequency", "band");
  write_sensor_scale(w, "/bands", e.sensors);
  for (const char* d : {"/bands/nominal_frequency", "/bands/lower_frequency", "/bands/upper_frequency", "/bands/degrees_of_freedom"})
    w.attach_scale(d, "/bands/centre_frequency", 0);
  for (const char* d : {"/bands/level_db", "/bands/ci_lower_db", "/bands/ci_upper_db"}) {
    w.attach_scale(d, "/bands/sensor", 0);
    w.attach_scale(d, "/bands/centre_frequency", 1);
  }
}

}  // namespace rollspec::io
