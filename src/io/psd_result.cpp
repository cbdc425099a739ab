#include "src/io/psd_result.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernels/spectral/ensemble_interval.hpp"
#include "src/io/band_tail_check.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::io {

std::vector<spectral::Band> result_bands(const std::vector<double>& frequency, double band_min, double band_max) {
  if (frequency.size() < 2) return {};
  const double df = frequency[1] - frequency[0];
  return spectral::third_octave_bands(std::max(band_min, df), std::min(band_max, frequency.back()));
}

std::string interval_method(std::uint64_t realisations, const std::string& no_interval) {
  if (!no_interval.empty()) return "none (" + no_interval + ")";
  if (realisations < spectral::kMinRealisationsForInterval)
    return "none (" + counted(realisations, "realisation") + ", fewer than the " +
           std::to_string(spectral::kMinRealisationsForInterval) + " that an interval from their scatter needs)";
  return "realisation scatter: union of a chi-square law (Satterthwaite dof 2 K mean^2 / std^2) and a lognormal "
         "law (Cox), both with Student t on K - 1 dof";
}

void write_frequency_scale(Hdf5Writer& w, const std::string& group, const std::vector<double>& frequency) {
  w.write(group + "/frequency", {frequency.size()}, frequency.data(), "Hz", "frequency of the one-sided PSD bins");
  w.make_scale(group + "/frequency", "frequency");
}

void write_sensor_scale(Hdf5Writer& w, const std::string& group, const std::vector<std::string>& sensors) {
  w.write_strings(group + "/sensor", sensors, "sensor names");
  w.make_scale(group + "/sensor", "sensor");
}

void write_exact_reference(Hdf5Writer& w, const PsdEnsemble& e, const std::vector<double>& exact,
                           const std::string& long_name) {
  w.write("/reference/psd", {1, exact.size()}, exact.data(), e.units, long_name);
  w.attribute("/reference/psd", "label", std::string("exact"));
  write_frequency_scale(w, "/reference", e.frequency);
  write_sensor_scale(w, "/reference", e.sensors);
  w.attach_scale("/reference/psd", "/reference/sensor", 0);
  w.attach_scale("/reference/psd", "/reference/frequency", 1);
}

void write_sensor_positions(Hdf5Writer& w, const std::string& group, const std::vector<double>& positions,
                            std::size_t rows, const std::string& long_name) {
  std::vector<double> p(rows, NAN);  // the sensor mean is at no one place
  std::copy_n(positions.begin(), std::min(rows, positions.size()), p.begin());
  w.write(group + "/sensor_position", {rows}, p.data(), "m", long_name);
  w.attribute(group + "/sensor_position", "_FillValue", static_cast<double>(NAN));  // CF: NaN marks "no position"
  w.attach_scale(group + "/sensor_position", group + "/sensor", 0);
  w.attribute(group, "coordinates", std::string("sensor_position"));
}

namespace {
// One of the table's terms as a standard deviation in dB, rows x (bins or bands), with its scales.
void write_table_std(Hdf5Writer& w, const std::string& group, const std::vector<double>& variance, std::size_t columns,
                     const std::string& name, const std::string& description) {
  const bool bands = group == "/bands";
  std::vector<double> sd(variance.size());
  for (std::size_t i = 0; i < sd.size(); ++i) sd[i] = std::sqrt(variance[i]);
  const std::string path = group + "/" + name;
  w.write(path, {sd.size() / columns, columns}, sd.data(), "dB",
          (bands ? "band level: " : "bin's level: ") + description + " (kernels/spectral D-30; NaN: no power)");
  w.attribute(path, "_FillValue", static_cast<double>(NAN));
  w.attach_scale(path, group + "/sensor", 0);
  w.attach_scale(path, group + (bands ? "/centre_frequency" : "/frequency"), 1);
  if (bands) w.attribute(path, "coordinates", std::string("nominal_frequency"));
}

// What the intervals include, and the table's own term where they include it (D-30).
void write_table_error(Hdf5Writer& w, const PsdEnsemble& e, std::size_t nb) {
  const TableError& t = e.table_error;
  const std::string includes =
      e.no_interval.empty() ? interval_includes(t) : "none (no interval: " + e.no_interval + ")";
  w.attribute("/psd", "interval_includes", includes);
  w.attribute("/bands", "interval_includes", includes);
  if (t.surfaces == 0) return;
  const std::size_t nf = e.frequency.size();
  const std::string table =
      "the " + t.table + "'s own error by a jackknife over its " + t.unit + ", in the intervals (a)";
  const std::string noise = "the part of table_std_db that is the sub-table runs' own noise (c)";
  write_table_std(w, "/psd", t.bin_variance, nf, "table_std_db", table);
  write_table_std(w, "/psd", t.bin_noise, nf, "table_noise_std_db", noise);
  write_table_std(w, "/bands", t.band_variance, nb, "table_std_db", table);
  write_table_std(w, "/bands", t.band_noise, nb, "table_noise_std_db", noise);
  // The sub-table runs' levels themselves: compare and fit form the term's covariance between bands from
  // them (kernels/spectral D-31), which the standard deviations above do not hold.
  const std::size_t rows = t.band_variance.size() / std::max<std::size_t>(nb, 1);
  std::vector<double> index(t.surfaces);
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<double>(i);
  w.write("/bands/table_leave_out", {index.size()}, index.data(), "1",
          "the " + t.unit + " left out of each sub-table of the " + t.table);
  w.make_scale("/bands/table_leave_out", "table_leave_out");
  w.write("/bands/table_leave_out_level_db", {t.surfaces, rows, nb}, t.band_levels.data(), "dB re 1 " + e.units,
          "band level of the run with each leave-one-out sub-table of the " + t.table +
              " (the jackknife of (a), kernels/spectral D-30, D-31)");
  w.attach_scale("/bands/table_leave_out_level_db", "/bands/table_leave_out", 0);
  w.attach_scale("/bands/table_leave_out_level_db", "/bands/sensor", 1);
  w.attach_scale("/bands/table_leave_out_level_db", "/bands/centre_frequency", 2);
  w.attribute("/bands", "table_covariance",
              std::string(t.independent_bands ? "independent bands (a spectral estimate's error; D-31c)"
                                              : "the sub-tables' band-by-band covariance (one curve's error; D-31c)"));
  w.attribute("/bands", "table_jackknife_surfaces", static_cast<std::int64_t>(t.surfaces));
  if (t.realisations > 0)  // D-30f: the sub-table runs' realisations, where they exceed the result's K
    w.attribute("/bands", "table_jackknife_realisations", static_cast<std::int64_t>(t.realisations));
  w.attribute("/bands", "table_jackknife_dof", t.dof);
  w.attribute("/bands", "table_jackknife_variance_factor", t.variance_factor);
  if (!t.noise_warning.empty()) w.attribute("/bands", "table_noise_warning", t.noise_warning);
}
}  // namespace

void write_psd_result(Hdf5Writer& w, const PsdEnsemble& e) {
  const std::size_t nf = e.frequency.size(), ns = e.sensors.size();
  const std::uint64_t K = e.realisations;
  std::vector<double> lo(e.mean.size()), hi(e.mean.size()), nu(e.mean.size());
  const auto interval = [&e, K](const spectral::Scatter& s) {
    return e.no_interval.empty() ? spectral::mean_interval(s, K, e.confidence) : spectral::ScatterInterval{};
  };
  for (std::size_t i = 0; i < e.mean.size(); ++i) {
    const auto ci = interval(e.scatter[i]);
    lo[i] = ci.defined() ? e.mean[i] * ci.lower : 0.0;  // no interval: [0, inf), even for a bin without power
    hi[i] = ci.defined() ? e.mean[i] * ci.upper : HUGE_VAL;
    nu[i] = ci.dof;
    if (e.table_error.surfaces > 0)
      widen_bin_interval(e.mean[i], lo[i], hi[i], e.table_error.bin_variance[i], e.table_error.dof, K, e.confidence);
  }
  write_frequency_scale(w, "/psd", e.frequency);
  write_sensor_scale(w, "/psd", e.sensors);
  w.write("/psd/mean", {ns, nf}, e.mean.data(), e.units,
          "ensemble mean of the one-sided Welch PSD of the " + e.quantity);
  w.write("/psd/ci_lower", {ns, nf}, lo.data(), e.units,
          "lower bound of the mean's confidence interval (from the realisations' scatter)");
  w.write("/psd/ci_upper", {ns, nf}, hi.data(), e.units,
          "upper bound of the mean's confidence interval (from the realisations' scatter)");
  w.write("/psd/std", {ns, nf}, e.std_dev.data(), e.units, "ensemble standard deviation of one realisation's PSD");
  w.write("/psd/degrees_of_freedom", {ns, nf}, nu.data(), "1",
          "chi-square dof of each bin's mean from the realisations' scatter, 2 K mean^2 / std^2 (0: no interval)");
  for (const char* d : {"/psd/mean", "/psd/ci_lower", "/psd/ci_upper", "/psd/std", "/psd/degrees_of_freedom"}) {
    w.attach_scale(d, "/psd/sensor", 0);
    w.attach_scale(d, "/psd/frequency", 1);
  }
  if (!e.position_meaning.empty()) write_sensor_positions(w, "/psd", e.sensor_position, ns, e.position_meaning);
  w.attribute("/psd", "realisations", static_cast<std::int64_t>(K));
  w.attribute("/psd", "interval_method", interval_method(K, e.no_interval));
  if (e.welch_dof > 0.0) w.attribute("/psd", "welch_degrees_of_freedom", e.welch_dof);
  w.attribute("/psd", "confidence_level", e.confidence);
  w.attribute("/psd", "window_enbw_bins", e.window_enbw_bins);
  w.attribute("/psd", "quantity", e.quantity);
  if (e.welch.sample_rate > 0.0) {  // the estimator a measurement is put through to be compared (D-32)
    w.attribute("/psd", "sample_rate", e.welch.sample_rate);
    w.attribute("/psd", "welch_segment", static_cast<std::int64_t>(e.welch.segment));
    w.attribute("/psd", "welch_overlap", static_cast<std::int64_t>(e.welch.overlap));
    w.attribute("/psd", "welch_window", std::string(e.welch.window == spectral::Window::hann ? "hann" : "rect"));
    w.attribute("/psd", "welch_detrend", std::string(e.welch.detrend == spectral::Detrend::constant ? "mean" : "none"));
    w.attribute("/psd", "record_samples", static_cast<std::int64_t>(e.record_samples));
  }

  const double df = nf > 1 ? e.frequency[1] - e.frequency[0] : 1.0;
  const auto bands = result_bands(e.frequency, e.band_min, e.band_max);
  const std::size_t nb = bands.size();
  std::vector<double> centre(nb), nominal(nb), lower(nb), upper(nb);
  std::vector<double> level(ns * nb), cil(ns * nb), ciu(ns * nb), dof(ns * nb), sd(ns * nb), log_sd(ns * nb);
  for (std::size_t b = 0; b < nb; ++b) {
    centre[b] = bands[b].centre;
    nominal[b] = bands[b].nominal;
    lower[b] = bands[b].lower;
    upper[b] = bands[b].upper;
    for (std::size_t s = 0; s < ns; ++s) {
      const std::size_t i = s * nb + b;
      const double avg = spectral::band_average(e.mean.data() + s * nf, nf, df, bands[b].lower, bands[b].upper);
      const auto ci = interval(e.band_scatter[i]);
      level[i] = 10.0 * std::log10(avg);
      cil[i] = ci.defined() ? 10.0 * std::log10(avg * ci.lower) : -HUGE_VAL;
      ciu[i] = ci.defined() ? 10.0 * std::log10(avg * ci.upper) : HUGE_VAL;
      dof[i] = ci.dof;
      if (e.table_error.surfaces > 0)
        widen_band_interval(level[i], cil[i], ciu[i], e.table_error.band_variance[i], e.table_error.dof, K,
                            e.confidence);
      sd[i] = e.band_scatter[i].std_dev;
      log_sd[i] = e.band_scatter[i].log_std;
    }
  }
  w.write("/bands/centre_frequency", {nb}, centre.data(), "Hz", "IEC 61260-1 base-ten third-octave midband frequency");
  w.write("/bands/nominal_frequency", {nb}, nominal.data(), "Hz", "IEC 61260-1 nominal midband frequency");
  w.write("/bands/lower_frequency", {nb}, lower.data(), "Hz", "lower band edge");
  w.write("/bands/upper_frequency", {nb}, upper.data(), "Hz", "upper band edge");
  const std::string db = "dB re 1 " + e.units;
  w.write("/bands/level_db", {ns, nb}, level.data(), db, "band-averaged PSD level");
  w.write("/bands/ci_lower_db", {ns, nb}, cil.data(), db,
          "lower bound of the band level's confidence interval (from the realisations' scatter)");
  w.write("/bands/ci_upper_db", {ns, nb}, ciu.data(), db,
          "upper bound of the band level's confidence interval (from the realisations' scatter)");
  w.write("/bands/std", {ns, nb}, sd.data(), e.units,
          "ensemble standard deviation of one realisation's band-averaged PSD");
  w.write("/bands/log_std", {ns, nb}, log_sd.data(), "1",
          "ensemble standard deviation of the natural log of one realisation's band-averaged PSD");
  w.write("/bands/degrees_of_freedom", {ns, nb}, dof.data(), "1",
          "chi-square dof of the band level from the realisations' scatter of their band averages (0: no interval)");
  w.make_scale("/bands/centre_frequency", "band");
  write_sensor_scale(w, "/bands", e.sensors);
  for (const char* d : {"/bands/nominal_frequency", "/bands/lower_frequency", "/bands/upper_frequency"})
    w.attach_scale(d, "/bands/centre_frequency", 0);
  for (const char* d : {"/bands/level_db", "/bands/ci_lower_db", "/bands/ci_upper_db", "/bands/std", "/bands/log_std",
                        "/bands/degrees_of_freedom"}) {
    w.attach_scale(d, "/bands/sensor", 0);
    w.attach_scale(d, "/bands/centre_frequency", 1);
    w.attribute(d, "coordinates", std::string("nominal_frequency"));  // CF: xarray shows the IEC label as a coordinate
  }
  if (!e.position_meaning.empty()) write_sensor_positions(w, "/bands", e.sensor_position, ns, e.position_meaning);
  if (!e.band_log_covariance.empty()) {  // D-26: rows x bands x bands
    w.write("/bands/log_level_covariance", {ns, nb, nb}, e.band_log_covariance.data(), "1",
            "between-band covariance (K - 1) of the natural log of one realisation's band-averaged PSD");
    w.attach_scale("/bands/log_level_covariance", "/bands/sensor", 0);
    w.attach_scale("/bands/log_level_covariance", "/bands/centre_frequency", 1);
    w.attach_scale("/bands/log_level_covariance", "/bands/centre_frequency", 2);
  }
  if (e.band_tail.size() == ns * nb) {  // D-26d: rows x bands, G1 of the band logs (D-29a; 0 where undefined)
    std::vector<double> skew(ns * nb);
    for (std::size_t i = 0; i < skew.size(); ++i) skew[i] = e.band_tail[i].defined ? e.band_tail[i].skewness : 0.0;
    w.write("/bands/log_skewness", {ns, nb}, skew.data(), "1",
            "skewness of the natural log of one realisation's band-averaged PSD (G1, adjusted Fisher-Pearson; "
            "kernels/spectral D-29a, D-26d)");
    w.attach_scale("/bands/log_skewness", "/bands/sensor", 0);
    w.attach_scale("/bands/log_skewness", "/bands/centre_frequency", 1);
  }
  write_band_tail_check(w, e, bands);
  write_table_error(w, e, nb);
  if (K < spectral::kMinRealisationsForInterval || !e.no_interval.empty())
    std::fprintf(stderr, "rollspec: note: confidence intervals: %s\n", interval_method(K, e.no_interval).c_str());
}

}  // namespace rollspec::io
