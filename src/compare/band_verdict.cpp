#include "src/compare/band_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernels/spectral/band_noise.hpp"
#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/band_test_table.hpp"
#include "kernels/spectral/covariance_shrinkage.hpp"
#include "kernels/spectral/ensemble_interval.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch_expectation.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/io/table_error.hpp"

namespace rollspec::compare {

using io::number_text;

const char* band_use_name(BandUse u) {
  switch (u) {
    case BandUse::test:
      return "test";
    case BandUse::noise_floor:
      return "noise floor";
    case BandUse::floor_flat:
      return "flat floor";
  }
  return "test";
}

namespace {

constexpr double kDb = 10.0 / 2.302585092994046;  // dB per neper of power (10 / ln 10)

// D-33b: without a noise recording, a band is taken for the logger's floor when the measurement lies
// this much above the model's shape (against the median difference) ...
constexpr double kFloorExcessDb = 10.0;
// ... and within this much of its own lowest band level (a flat floor, not a peak the model misses).
constexpr double kFloorFlatDb = 6.0;

// A unit slip shows as one offset in every band: g read as m/s^2 (20 log10 9.80665), mm/s^2 as m/s^2.
struct Slip {
  double db;
  const char* what;
};
constexpr Slip kSlips[] = {{19.83, "a recording in g read as m/s^2 (--unit g)"},
                           {-19.83, "a recording in m/s^2 read as g (--unit m/s2)"},
                           {-60.0, "a recording in mm/s^2 read as m/s^2 (--unit mm/s2)"},
                           {60.0, "a recording in m/s^2 read as mm/s^2 (--unit m/s2)"}};

double measured_band(const MeasuredSpectrum& m, double lower, double upper) {
  if (m.model_grid)
    return spectral::band_average(m.psd.data(), m.psd.size(), m.frequency[1] - m.frequency[0], lower, upper);
  return spectral::band_average_irregular(m.frequency.data(), m.psd.data(), m.frequency.size(), lower, upper);
}

bool covers(const MeasuredSpectrum& m, double lower, double upper) {
  return m.frequency.size() >= 2 && m.frequency.front() <= lower && m.frequency.back() >= upper;
}

std::string question_text(const io::BandLevels& b, const MeasuredSpectrum& m, bool same_surface, bool has_interval,
                          bool noise) {
  const int pct = static_cast<int>(std::lround(100.0 * b.confidence));
  if (!has_interval) return "none: " + b.interval_method;
  if (!(m.records > 0.0))
    return "is the measured level inside the " + std::to_string(pct) +
           " % interval of the simulated mean? (it ignores the measurement's own scatter: give the recordings "
           "themselves, or --measured-averages M, to ask whether a measurement of M rolls agrees with the model)";
  std::string surface;
  if (b.table_units < 2)
    surface = b.table_error_missing
                  ? " of the very surface the model's " + b.table + " was built on (its error was not estimated)"
                  : "";
  else if (same_surface)
    surface = " of the very surface the model's " + b.table + " was built on (--same-surface)";
  else
    surface = " of a rig with another surface of this roughness (the model's " + b.table +
              " and the rig's surface each carry the table's sampling error, jackknife over " +
              std::to_string(b.table_units) + " units; --same-surface for the table's own surface)";
  return "is the measured level inside the " + std::to_string(pct) +
         " % prediction interval of a measurement averaged over M = " + number_text(m.records) + " rolls" + surface +
         (noise ? ", with the logger noise of the noise recording" : "") + "?";
}

// D-33a with a noise recording, D-33b without.
void mark_floor(std::vector<BandRow>& rows, const io::BandLevels& b, const VerdictOptions& o) {
  if (o.noise) {
    for (auto& r : rows) {
      if (!covers(*o.noise, b.lower[r.band], b.upper[r.band])) continue;
      r.noise = 10.0 * std::log10(measured_band(*o.noise, b.lower[r.band], b.upper[r.band]));
      if (!(r.measured - r.noise >= o.noise_margin_db)) r.use = BandUse::noise_floor;
    }
    return;
  }
  if (!o.floor_check || rows.size() < 3) return;
  std::vector<double> d;
  double lowest = INFINITY;
  for (const auto& r : rows) d.push_back(r.measured - r.simulated), lowest = std::min(lowest, r.measured);
  std::vector<double> sorted = d;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (d[i] - median > kFloorExcessDb && rows[i].measured <= lowest + kFloorFlatDb) rows[i].use = BandUse::floor_flat;
}

std::string band_list(const std::vector<BandRow>& rows, BandUse use) {
  std::string s;
  for (const auto& r : rows)
    if (r.use == use) s += (s.empty() ? "" : ", ") + number_text(r.centre);
  return s;
}

// D-32c: a PSD table on coarser bins than the model's reads its bands otherwise; measured on the model's
// own mean PSD put through an estimator of the table's resolution (D-20).
std::string resolution_warning(const io::BandLevels& b, const MeasuredSpectrum& m, const VerdictOptions& o,
                               const std::vector<BandRow>& rows) {
  if (m.model_grid || o.model_psd.size() < 3 || !(o.model_df > 0.0) || m.frequency.size() < 2) return "";
  const double df = m.frequency[1] - m.frequency[0], ratio = df / o.model_df;
  const std::string bins =
      "the measurement's PSD has bins of " + number_text(df) + " Hz, the model's " + number_text(o.model_df) + " Hz";
  const double whole = std::round(ratio);
  if (ratio < 1.0 - 1e-9 || std::fabs(ratio - whole) > 1e-6 * ratio || whole < 2.0) {
    if (std::fabs(ratio - 1.0) <= 1e-9) return "";
    return bins +
           ": its bands average other bins than the model's; give compare the recording itself (it then "
           "uses the model's estimator)";
  }
  const std::size_t refine = static_cast<std::size_t>(whole), segment = 2 * (o.model_psd.size() - 1);
  if (segment % refine != 0 || segment / refine < 4) return "";
  spectral::WelchConfig c;
  c.sample_rate = static_cast<double>(segment) * o.model_df;
  c.segment = segment / refine;
  c.overlap = c.segment / 2;
  const spectral::WelchPlan plan(c);
  const std::vector<double> coarse = spectral::welch_expectation(plan, o.model_psd, refine);
  const std::vector<double> f = plan.frequencies();
  double worst = 0.0, at = 0.0;
  for (const auto& r : rows) {
    const double lo = b.lower[r.band], hi = b.upper[r.band];
    if (f.back() < hi) continue;
    const double shift =
        kDb * std::log(spectral::band_average_irregular(f.data(), coarse.data(), f.size(), lo, hi) /
                       spectral::band_average(o.model_psd.data(), o.model_psd.size(), o.model_df, lo, hi));
    if (std::fabs(shift) > std::fabs(worst)) worst = shift, at = r.centre;
  }
  if (!(std::fabs(worst) > 0.5)) return "";
  const std::string text = io::formatted("%+.1f dB (the %s Hz band)", worst, number_text(at).c_str());
  return bins + ": read on the model's own mean PSD, bins that coarse move its bands by up to " + text +
         " (kernels/spectral D-32c); give compare the recording itself (it then uses the model's estimator), or make "
         "the PSD with the model's segment";
}

// D-27h: a band of a bin or two beside a steep slope reads differently as a PSD table is read (its
// points joined linearly) and as the model's band level is (its bins), measured on the model's own mean
// PSD; a difference above the band's standard deviation in a prediction interval decides the band by
// itself. Nothing where the measurement is on the model's bins (both read them alike).
std::string band_rule_warning(const io::BandLevels& b, const MeasuredSpectrum& m, const VerdictOptions& o,
                              const std::vector<BandRow>& rows) {
  if (m.model_grid || !(m.records > 0.0) || o.model_psd.size() < 2 || !(o.model_df > 0.0)) return "";
  const double K = static_cast<double>(b.realisations);
  std::string bands;
  int count = 0;
  for (const auto& row : rows) {
    const std::size_t k = row.band;
    const double s = b.log_std[k] * b.log_std[k];
    const double sd = std::sqrt(spectral::log_mean_variance(s, K) + spectral::log_mean_variance(s, m.records));
    const double shift =
        spectral::band_rule_shift(o.model_psd.data(), o.model_psd.size(), o.model_df, b.lower[k], b.upper[k]);
    if (!(sd > 0.0) || !(std::fabs(shift) > sd)) continue;
    const std::string one =
        io::formatted("%s%.4g .. %.4g Hz (%.2g bins, %+.2f dB, %.2g sd)", count ? "; " : "", b.lower[k], b.upper[k],
                      (b.upper[k] - b.lower[k]) / o.model_df, kDb * shift, std::fabs(shift) / sd);
    bands += one;
    ++count;
  }
  if (count == 0) return "";
  return std::to_string(count) + (count == 1 ? " band" : " bands") + " of the result's " + number_text(o.model_df) +
         " Hz grid read differently as the measurement is read (its points joined linearly) and as the result's band "
         "levels are (its bins), by more than the band's standard deviation (kernels/spectral D-27h): " +
         bands + "; leave " + (count == 1 ? "it" : "them") +
         " out (--fmin/--fmax), refine the result's grid (spectrum.segment), or give compare the recording itself";
}

// A new surface: the model's table and the rig's surface each add the table's variance (D-31), a spectral
// table's pooled over neighbouring bands with the dof of the estimates pooled (D-31d); then `inside`.
void widen_for_table(Verdict& v, const io::BandLevels& b) {
  std::vector<double> raw;
  for (const auto& r : v.rows) raw.push_back(v.table_factor > 0.0 ? table_band_variance_db(b, r.band) : 0.0);
  std::vector<std::size_t> count(raw.size(), 1);
  if (b.table_independent_bands) raw = spectral::smoothed_variances(raw, kSpectralTableSmoothing, &count);
  for (std::size_t i = 0; i < v.rows.size(); ++i) {
    BandRow& r = v.rows[i];
    if (raw[i] > 0.0)
      io::widen_band_interval(r.simulated, r.pred_lower, r.pred_upper, v.table_factor * raw[i],
                              b.table_dof * static_cast<double>(count[i]), b.realisations, b.confidence);
    r.inside_prediction = r.measured >= r.pred_lower && r.measured <= r.pred_upper;
  }
}

// D-33c: the logger noise in each tested band (kernels/spectral/band_noise.hpp): the noise recording's band power,
// the model's, and the degrees of freedom of the measurement's and the noise recording's band averages (D-33c a).
struct NoiseTerms {
  std::vector<spectral::BandNoise> band;  // the tested bands', in the rows' order
  std::vector<double> power, dof;         // N^_b (0: not covered) and nu_N,b (0: unknown)
  bool scatter_known = true;              // both estimators known (recordings, not PSD tables)
  std::vector<double> cross;              // D-33e: the measured mean's noise log covariance (p x p; empty: D-33c)
};

// D-33e where the rolls' samples are kept: each band's `measured` from the rolls' own signal, and its row of the
// covariance between bands (the pointers set once the terms have their final place).
void link_cross(NoiseTerms& t) {
  const std::size_t p = t.band.size();
  if (t.cross.size() != p * p) return;
  for (std::size_t i = 0; i < p; ++i) {
    t.band[i].measured = t.cross[i * p + i];
    t.band[i].cross = t.cross.data() + i * p;
  }
}

NoiseTerms noise_terms(const std::vector<BandRow>& rows, const io::BandLevels& b, const MeasuredSpectrum& m,
                       const MeasuredSpectrum& quiet) {
  NoiseTerms t;
  for (const auto& r : rows) {
    if (r.use != BandUse::test) continue;
    const double lo = b.lower[r.band], hi = b.upper[r.band], model = std::pow(10.0, b.level_db[r.band] / 10.0);
    const double power = std::isfinite(r.noise) ? measured_band(quiet, lo, hi) : 0.0;
    const double measured_dof = band_dof_of_mean(m, lo, hi), noise_dof = band_dof_of_mean(quiet, lo, hi);
    if (power > 0.0 && !(measured_dof > 0.0 && noise_dof > 0.0)) t.scatter_known = false;
    // A band without model power has no test either (band_test says why): no terms there.
    t.band.push_back(model > 0.0 && std::isfinite(model) && power >= 0.0 && std::isfinite(power)
                         ? spectral::band_noise(model, power, measured_dof, noise_dof)
                         : spectral::BandNoise{});
    t.power.push_back(power);
    t.dof.push_back(noise_dof);
  }
  std::vector<double> lower, upper, model;
  for (const auto& r : rows)
    if (r.use == BandUse::test) {
      lower.push_back(b.lower[r.band]);
      upper.push_back(b.upper[r.band]);
      model.push_back(std::pow(10.0, b.level_db[r.band] / 10.0));
    }
  const bool powered = std::all_of(model.begin(), model.end(), [](double x) { return x > 0.0 && std::isfinite(x); });
  if (powered && t.scatter_known) t.cross = noise_log_covariance(m, lower, upper, model, t.power);
  return t;
}

// D-33c c: each tested band's prediction interval for the measurement, model + noise: the signal's bounds plus the
// noise's band power (exact for the signal's part), widened by the noise's and the cross term's variance as D-30b
// widens by a table's (dof nu_N of the noise recording's estimate).
void add_noise_to_intervals(std::vector<BandRow>& rows, const NoiseTerms& t, const io::BandLevels& b) {
  std::size_t i = 0;
  for (auto& r : rows) {
    if (r.use != BandUse::test) continue;
    const spectral::BandNoise& n = t.band[i];
    const double power = t.power[i], dof = t.dof[i];
    ++i;
    if (!(power > 0.0) || !std::isfinite(r.pred_lower) || !std::isfinite(r.pred_upper)) continue;
    const auto plus = [&](double db) { return 10.0 * std::log10(std::pow(10.0, db / 10.0) + power); };
    r.pred_lower = plus(r.pred_lower);
    r.pred_upper = plus(r.pred_upper);
    io::widen_band_interval(r.simulated + kDb * n.shift, r.pred_lower, r.pred_upper,
                            (n.measured + n.estimate) * kDb * kDb,
                            dof > 0.0 ? dof : static_cast<double>(b.realisations - 1), b.realisations, b.confidence);
    r.inside_prediction = r.measured >= r.pred_lower && r.measured <= r.pred_upper;
  }
}

// D-34 over the tested bands with the test's covariance; with noise (D-33c d) read in the signal's own terms,
// ln(X - N^) against ln m, the noise's variance over a^2 on V's diagonal: a gain of the model's signal, or of the
// whole chain (which scales X and N^ alike), then reads as itself.
std::optional<spectral::LevelOffset> offset_of(const io::BandLevels& b, const MeasuredSpectrum& m, const Verdict& v,
                                               const std::vector<std::size_t>& index, std::vector<double> measured_db,
                                               const NoiseTerms* noise) {
  if (noise)
    for (std::size_t i = 0; i < index.size(); ++i) {
      const double x = std::pow(10.0, measured_db[i] / 10.0) - noise->power[i];
      if (!(x > 0.0)) return std::nullopt;  // the noise's estimate reaches the measurement: no signal level to read
      measured_db[i] = 10.0 * std::log10(x);
    }
  const ChosenBands c = chosen_bands(b, index, measured_db);
  std::vector<double> d, vs;
  try {
    spectral::band_deviation(c.y.data(), c.mean.data(), c.cov.data(), index.size(), static_cast<double>(b.realisations),
                             m.records, d, vs, nullptr, c.cv2_or_null());
    const std::size_t p = index.size();
    if (noise)
      for (std::size_t i = 0; i < p; ++i) {
        const spectral::BandNoise& n = noise->band[i];
        const double extra = (n.measured + n.estimate) / n.signal_share;
        vs[i * p + i] += extra;
        d[i] += 0.5 * extra;  // E ln(X - N^) = ln S - (V_M + extra) / 2
        if (n.cross)          // D-33e: the noise's covariance between bands, in the signal's terms
          for (std::size_t j = 0; j < p; ++j)
            if (j != i) vs[i * p + j] += n.cross[j] / std::sqrt(n.signal_share * noise->band[j].signal_share);
      }
    std::vector<double> vt = v.table_factor > 0.0 ? io::table_log_covariance(b, index) : std::vector<double>{};
    if (!vt.empty()) spectral::shrink_toward_diagonal(vt.data(), p, io::table_shrinkage(b, index));  // D-31e
    double table_dof = b.table_dof;
    if (!vt.empty() && b.table_independent_bands) {  // D-31d: pooled as the test pools them
      std::vector<double> diag(p);
      std::vector<std::size_t> count;
      for (std::size_t i = 0; i < p; ++i) diag[i] = vt[i * p + i];
      diag = spectral::smoothed_variances(diag, kSpectralTableSmoothing, &count);
      double pooled = 0.0;
      for (std::size_t i = 0; i < p; ++i) vt[i * p + i] = diag[i], pooled += static_cast<double>(count[i]);
      table_dof *= pooled / static_cast<double>(p);
    }
    for (auto& x : d) x *= -kDb;  // simulated - measured, dB
    for (auto& x : vs) x *= kDb * kDb;
    for (auto& x : vt) x *= v.table_factor * kDb * kDb;
    return spectral::level_offset(d.data(), vs.data(), vt.empty() ? nullptr : vt.data(), p,
                                  static_cast<double>(b.realisations - 1), table_dof, b.confidence);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a band without power or a singular covariance: no offset, the test says why
  }
}

}  // namespace

Verdict band_verdict(const io::BandLevels& b, const MeasuredSpectrum& m, const VerdictOptions& o) {
  Verdict v;
  const bool has_interval = b.realisations >= spectral::kMinRealisationsForInterval;
  const bool predict = m.records > 0.0 && has_interval;
  v.table_factor = o.same_surface || b.table_units < 2 ? 0.0 : kNewSurfaceTableFactor;
  v.question = question_text(b, m, o.same_surface, has_interval, o.noise != nullptr);
  for (std::size_t k = 0; k < b.level_db.size(); ++k) {
    if (b.lower[k] < o.fmin || b.upper[k] > o.fmax || !covers(m, b.lower[k], b.upper[k])) continue;
    const double meas = measured_band(m, b.lower[k], b.upper[k]);
    if (!std::isfinite(meas))
      throw data_error(m.source + ": the measured PSD averaged over the band " + number_text(b.lower[k]) + " .. " +
                       number_text(b.upper[k]) + " Hz is not finite (overflow); allowed: a finite band average");
    if (meas <= 0.0) continue;
    BandRow r;
    r.band = k;
    r.centre = b.nominal[k];
    r.simulated = b.level_db[k];
    r.measured = 10.0 * std::log10(meas);
    r.delta = r.simulated - r.measured;
    r.ci_lower = b.ci_lower_db[k];
    r.ci_upper = b.ci_upper_db[k];
    r.inside_ci = has_interval && r.measured >= r.ci_lower && r.measured <= r.ci_upper;
    if (predict) {
      const double level = std::pow(10.0, r.simulated / 10.0);
      const spectral::Scatter sc{level, b.std_dev[k], std::log(level), b.log_std[k]};
      const auto p = spectral::prediction_interval(sc, b.realisations, m.records, b.confidence);
      r.pred_lower = r.simulated + 10.0 * std::log10(p.lower);
      r.pred_upper = r.simulated + 10.0 * std::log10(p.upper);
    }
    v.rows.push_back(r);
  }
  if (v.rows.empty()) throw data_error(m.source + ": covers none of the result's bands inside [fmin, fmax]");
  if (predict) widen_for_table(v, b);
  mark_floor(v.rows, b, o);
  std::optional<NoiseTerms> logger;  // D-33c
  if (o.noise) {
    logger = noise_terms(v.rows, b, m, *o.noise);
    link_cross(*logger);
  }
  if (logger && predict) add_noise_to_intervals(v.rows, *logger, b);

  std::vector<std::size_t> index;
  std::vector<double> measured_db;
  double sq = 0.0;
  for (const auto& r : v.rows) {
    if (r.use != BandUse::test) continue;
    index.push_back(r.band);
    measured_db.push_back(r.measured);
    sq += r.delta * r.delta;
    v.inside += predict ? r.inside_prediction : r.inside_ci;
  }
  v.tested = static_cast<int>(index.size());
  v.judged = has_interval ? v.tested : 0;
  if (!has_interval) v.inside = 0;
  if (!index.empty()) v.rms_db = std::sqrt(sq / static_cast<double>(index.size()));
  v.test = combined_test(b, index, measured_db, predict ? m.records : 0.0, o.test_level, v.table_factor,
                         logger ? logger->band.data() : nullptr);
  if (predict && !index.empty() && !b.log_covariance.empty())
    v.offset = offset_of(b, m, v, index, measured_db, logger ? &*logger : nullptr);

  const std::string noise = band_list(v.rows, BandUse::noise_floor), flat = band_list(v.rows, BandUse::floor_flat);
  if (!noise.empty())
    v.warnings.push_back("bands " + noise + " Hz lie within " + number_text(o.noise_margin_db) +
                         " dB of the noise recording's level: left out of the test and the level offset "
                         "(--noise-margin DB sets the margin; kernels/spectral D-33a)");
  if (logger && !logger->scatter_known && v.tested > 0)
    v.warnings.push_back(
        "the noise recording's band power is added to the model's in the tested bands, but not the noise's scatter: "
        "the measurement or the noise recording is a PSD table, whose estimator compare does not know (give the "
        "recordings themselves; kernels/spectral D-33c)");
  if (!flat.empty())
    v.warnings.push_back("bands " + flat + " Hz look like the logger's noise floor: the measurement stays within " +
                         number_text(kFloorFlatDb) + " dB of its lowest band level while the model lies more than " +
                         number_text(kFloorExcessDb) +
                         " dB further below it than in the other bands; left out of the test and the level offset "
                         "(--noise QUIET.csv, a recording of the rig at rest, decides instead; --keep-floor-bands "
                         "keeps them; kernels/spectral D-33b)");
  if (v.offset && v.tested >= 3) {
    double spread = 0.0;
    for (const auto& r : v.rows)
      if (r.use == BandUse::test) spread += (r.delta - v.offset->estimate) * (r.delta - v.offset->estimate);
    spread = std::sqrt(spread / v.tested);
    for (const Slip& s : kSlips)
      if (std::fabs(v.offset->estimate - s.db) < 3.0 && spread < 6.0 &&
          (v.offset->lower > 0.0 || v.offset->upper < 0.0))
        v.warnings.push_back("the model lies " + number_text(std::round(10.0 * v.offset->estimate) / 10.0) +
                             " dB from the measurement in every band (spread " +
                             number_text(std::round(10.0 * spread) / 10.0) + " dB about it): " + s.what + "?");
  }
  const std::string rule = band_rule_warning(b, m, o, v.rows);
  if (!rule.empty()) v.warnings.push_back(rule);
  const std::string resolution = resolution_warning(b, m, o, v.rows);
  if (!resolution.empty()) v.warnings.push_back(resolution);
  return v;
}

}  // namespace rollspec::compare
