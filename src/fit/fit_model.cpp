#include "src/fit/fit_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/covariance_shrinkage.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "src/fit/fit_journal.hpp"
#include "src/run/run_phases.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"
#include "src/io/run_warning.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::fit {

using run::run_request;
using run::RunRequest;

using io::number_text;

namespace {

// The result's mean PSD in the row named `sensor` and its bin width (empty: the result lacks them).
std::vector<double> mean_psd_row(const io::Hdf5Reader& r, const std::string& sensor, double& df) {
  if (!r.exists("/psd/sensor") || !r.exists("/psd/mean") || !r.exists("/psd/frequency")) return {};
  std::vector<std::size_t> dims;
  const auto mean = r.read("/psd/mean", &dims);
  const auto names = r.read_strings("/psd/sensor");
  const auto f = r.read("/psd/frequency");
  if (dims.size() != 2 || dims[0] != names.size() || dims[1] != f.size() || f.size() < 2) return {};
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == sensor) {
      df = f[1] - f[0];
      return {mean.begin() + static_cast<std::ptrdiff_t>(i * f.size()),
              mean.begin() + static_cast<std::ptrdiff_t>((i + 1) * f.size())};
    }
  return {};
}

}  // namespace

double VaryRange::value(double u) const { return log ? lo * std::pow(hi / lo, u) : lo + u * (hi - lo); }

double VaryRange::unit(double v) const { return log ? std::log(v / lo) / std::log(hi / lo) : (v - lo) / (hi - lo); }

VaryRange parse_vary(const std::string& spec) {
  const std::string where = "--vary " + clip(spec);
  const auto eq = spec.find('=');
  const std::string key = spec.substr(0, eq);
  if (eq == std::string::npos || key.find('.') == std::string::npos || key.front() == '.' || key.back() == '.')
    throw usage_error(where + ": allowed: section.key=lo:hi or section.key=lo:hi:log, e.g. force.level=0.1:10:log");
  std::vector<std::string> parts;
  std::size_t start = eq + 1;
  for (std::size_t c; (c = spec.find(':', start)) != std::string::npos; start = c + 1)
    parts.push_back(spec.substr(start, c - start));
  parts.push_back(spec.substr(start));
  if (parts.size() < 2 || parts.size() > 3 || (parts.size() == 3 && parts[2] != "log"))
    throw usage_error(where + ": allowed: section.key=lo:hi or section.key=lo:hi:log (the third field is `log`)");
  VaryRange r;
  r.key = key;
  r.log = parts.size() == 3;
  for (int i = 0; i < 2; ++i) {
    double& end = i == 0 ? r.lo : r.hi;
    std::size_t used = 0;
    try {
      end = std::stod(parts[static_cast<std::size_t>(i)], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != parts[static_cast<std::size_t>(i)].size() || !std::isfinite(end))
      throw usage_error(where + ": '" + clip(parts[static_cast<std::size_t>(i)]) +
                        "' is not a finite number; allowed: lo:hi with finite numbers");
  }
  if (!(r.lo < r.hi))
    throw usage_error(where + ": lo " + number_text(r.lo) + " >= hi " + number_text(r.hi) + "; allowed: lo < hi");
  if (r.log && !(r.lo > 0.0)) throw usage_error(where + ": a log range needs lo > 0 (it is " + number_text(r.lo) + ")");
  return r;
}

std::vector<std::string> parse_at(const std::string& at) {
  std::vector<std::string> sets;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = at.find(',', start);
    const std::string kv = at.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto eq = kv.find('=');
    const auto dot = kv.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 >= eq || eq + 1 == kv.size())
      throw usage_error("--at " + clip(at) + ": '" + clip(kv) +
                        "' is not section.key=value; allowed: section.key=value[,section.key=value ...], e.g. "
                        "ball.speed=3");
    for (const auto& earlier : sets)
      if (earlier.substr(0, earlier.find('=')) == kv.substr(0, eq))
        throw usage_error("--at " + clip(at) + ": " + clip(kv.substr(0, eq)) +
                          " given twice; allowed: each key once per --at");
    sets.push_back(kv);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return sets;
}

FitModel::FitModel(const FitInputs& in, std::string temp_dir, FitJournal* journal)
    : in_(in),
      temp_dir_(std::move(temp_dir)),
      journal_(journal),
      band_(in.points.size()),
      measured_db_(in.points.size()),
      table_(in.points.size()),
      last_warnings_(in.points.size()) {}

std::size_t FitModel::bands() const {
  std::size_t n = 0;
  for (const auto& b : band_) n += b.size();
  return n;
}

io::BandLevels FitModel::run_at(std::size_t point, const std::vector<double>& u, const std::vector<std::string>& extra,
                                std::vector<double>* psd, double* df) {
  const std::string out = temp_dir_ + "/run-" + std::to_string(runs_) + ".h5";
  RunRequest request;
  request.study.file = in_.study;
  request.out = out;
  request.quiet = true;
  request.spectra_only = true;  // the bands are all a fit reads
  auto& sets = request.study.sets;
  sets = in_.sets;
  sets.insert(sets.end(), in_.points[point].sets.begin(), in_.points[point].sets.end());
  for (std::size_t i = 0; i < in_.vary.size(); ++i) {
    const std::string buf = io::formatted("%.17g", in_.vary[i].value(u[i]));
    sets.push_back(in_.vary[i].key + "=" + buf);
  }
  sets.insert(sets.end(), extra.begin(), extra.end());
  ++runs_;
  {
    const io::RunWarningCapture capture;  // said once, for the run at the estimate (fit_command)
    run_request(request);
    last_warnings_[point] = capture.lines();
  }
  if (!last_warnings_[point].empty()) ++warned_runs_;
  io::BandLevels b;
  {
    const io::Hdf5Reader r(out);
    io::check_filetype(r, io::kResultFileType, io::kResultSchemaMajor);
    b = io::read_band_levels(r, in_.sensor);
    if (psd) *psd = mean_psd_row(r, b.sensor, *df);
    if (psd) seed_ = static_cast<std::uint64_t>(r.double_attribute("/", "seed"));
  }
  std::filesystem::remove(out);
  return b;
}

// The point's first run, at the start: its bands, and its table term (D-31), estimated here if the
// study leaves it out, held for the whole fit.
io::BandLevels FitModel::first_run(std::size_t point, const std::vector<double>& u) {
  std::vector<double> psd;
  double df = 0.0;
  io::BandLevels b = run_at(point, u, {}, &psd, &df);
  if (!b.pick_note.empty()) std::fprintf(stderr, "rollspec fit: %s\n", b.pick_note.c_str());
  choose_bands(point, b);
  check_band_rules(point, b, psd, df);
  std::string refused;
  if (b.table_error_missing && !in_.same_surface) {
    try {
      b = run_at(point, u, {study::StiffnessSection::table_error_setting(study::TableError::jackknife)});
    } catch (const UserError& e) {
      if (e.exit_code() != EX_CONFIG) throw;
      refused = e.what();
    }
  }
  hold_table(point, b, refused);
  return b;
}

void FitModel::hold_table(std::size_t point, const io::BandLevels& b, const std::string& refused) {
  PointTable& t = table_[point];
  t.random = b.table_units >= 2 || b.table_error_missing;
  t.held = b;
  if (!t.random) return;
  const std::string units = std::to_string(b.table_units) + " units";
  if (b.table_units >= 2 && !in_.same_surface) {
    t.factor = compare::kNewSurfaceTableFactor;
    t.covariance = io::table_log_covariance(b, band_[point]);
    spectral::shrink_toward_diagonal(t.covariance.data(), band_[point].size(), io::table_shrinkage(b, band_[point]));
    for (double& x : t.covariance) x *= t.factor;
    t.question =
        "a rig with another surface of this roughness: V = G S G + 2 Sigma_T (kernels/spectral D-31), "
        "Sigma_T the " +
        b.table + "'s error by the start point's jackknife over " + units +
        ", held for the whole fit (every later run with stiffness.table_error = none); --same-surface "
        "for the table's own surface";
  } else if (in_.same_surface) {
    t.question = "the very surface the model's " + b.table + " was built on (--same-surface: no table term)";
  } else {
    t.question = "the very surface the model's " + b.table + " was built on: its error could not be estimated (" +
                 clip(refused) + "), so the fit leaves it out";
  }
}

// The bands inside [fmin, fmax] that the point's measurement covers with power, as compare takes them.
void FitModel::choose_bands(std::size_t point, const io::BandLevels& b) {
  const FitPoint& pt = in_.points[point];
  const Measurement& m = pt.measurement;
  auto& band = band_[point];
  for (std::size_t k = 0; k < b.level_db.size(); ++k) {
    if (b.lower[k] < in_.fmin || b.upper[k] > in_.fmax) continue;
    if (m.frequency.size() < 2 || m.frequency.front() > b.lower[k] || m.frequency.back() < b.upper[k]) continue;
    const double meas =
        spectral::band_average_irregular(m.frequency.data(), m.psd.data(), m.frequency.size(), b.lower[k], b.upper[k]);
    if (!(meas > 0.0) || !std::isfinite(meas)) continue;
    band.push_back(k);
    measured_db_[point].push_back(10.0 * std::log10(meas));
  }
  realisations_ = b.realisations;
  const std::size_t needed = band.size() + spectral::kExtraRealisations;
  const std::string at = pt.at.empty() ? "" : " (at " + pt.at + ")";
  if (band.empty()) throw data_error(pt.path + ": covers none of the result's bands inside [fmin, fmax]" + at);
  if (b.log_covariance.empty())
    throw data_error(in_.study + ": its result has no /bands/log_level_covariance; fit needs it");
  if (b.realisations < needed)
    throw config_error(in_.study + at + ": " + std::to_string(band.size()) +
                       " bands need K >= " + std::to_string(needed) +
                       " realisations for the band covariance, the study runs " + std::to_string(b.realisations) +
                       "; raise study.realisations (--set) or choose fewer bands with --fmin/--fmax");
}

// The measurement's band average joins its points linearly, the model's band level sums its bins: a band of
// a bin or two beside a steep slope reads differently by the two. Measured on the model's own mean PSD, a
// difference above the band's standard deviation would bias the fit by itself (kernels/spectral D-27h).
void FitModel::check_band_rules(std::size_t point, const io::BandLevels& b, const std::vector<double>& psd,
                                double df) const {
  if (psd.empty() || !(df > 0.0)) return;
  const std::size_t nb = b.level_db.size();
  const double K = static_cast<double>(b.realisations), M = in_.points[point].records;
  const std::string at = in_.points[point].at.empty() ? "" : "(at " + in_.points[point].at + ") ";
  for (const std::size_t k : band_[point]) {
    const double shift = spectral::band_rule_shift(psd.data(), psd.size(), df, b.lower[k], b.upper[k]);
    const double s = b.log_covariance[k * nb + k];
    const double sd = std::sqrt(spectral::log_mean_variance(s, M) + spectral::log_mean_variance(s, K));
    if (!(std::fabs(shift) > sd)) continue;
    std::fprintf(stderr,
                 "rollspec fit: WARNING: %sband %.4g .. %.4g Hz spans %.2g bins of the model's %.4g Hz grid: the "
                 "model's mean PSD averaged as the measurement is (its points joined linearly) reads %+.2f dB from "
                 "its band level (its bins), %.2g times the band's standard deviation, a bias of the fit by itself "
                 "(kernels/spectral D-27h); leave the band out (--fmin/--fmax) or refine the model's grid "
                 "(spectrum.segment)\n",
                 at.c_str(), b.lower[k], b.upper[k], (b.upper[k] - b.lower[k]) / df, df, 10.0 / std::log(10.0) * shift,
                 std::fabs(shift) / sd);
  }
}

std::vector<std::string> FitModel::later_sets(std::size_t point) const {
  if (!table_[point].random) return {};
  return {study::StiffnessSection::table_error_setting(
      study::TableError::none)};  // the term is held from the start (D-27, D-31)
}

PointRun FitModel::point_run(std::size_t point, const io::BandLevels& b) const {
  const ChosenBands c = chosen_bands(b, band_[point], measured_db_[point]);
  PointRun r{std::vector<double>(c.mean.size()), c.cov, b.realisations};
  for (std::size_t k = 0; k < c.mean.size(); ++k) r.log_mean[k] = std::log(c.mean[k]);
  return r;
}

std::vector<PointRun> FitModel::crn_runs(const std::vector<double>& u) {
  const auto hit = crn_.find(u);
  if (hit != crn_.end()) return hit->second;
  std::vector<PointRun> runs;
  for (std::size_t point = 0; point < in_.points.size(); ++point)
    runs.push_back(point_run(point, run_at(point, u, later_sets(point))));
  crn_.emplace(u, runs);
  return runs;
}

Coherence FitModel::probe(const std::vector<double>& start, double step) {
  std::vector<PointRun> centre;
  for (std::size_t point = 0; point < in_.points.size(); ++point)
    centre.push_back(point_run(point, first_run(point, start)));
  crn_.emplace(start, centre);
  std::vector<double> up = start, down = start;
  for (std::size_t i = 0; i < start.size(); ++i) up[i] += step, down[i] -= step;
  const std::vector<PointRun> a = crn_runs(up), z = crn_runs(down);
  Coherence c;
  c.step = step;
  for (std::size_t point = 0; point < centre.size(); ++point) {
    const std::size_t p = band_[point].size();
    double share = 0.0;
    for (std::size_t b = 0; b < p; ++b) {
      const auto vk = [&](const PointRun& r) {
        return spectral::log_mean_variance(r.cov[b * p + b], static_cast<double>(r.realisations));
      };
      const double second = a[point].log_mean[b] - 2.0 * centre[point].log_mean[b] + z[point].log_mean[b];
      const double independent = vk(a[point]) + 4.0 * vk(centre[point]) + vk(z[point]);
      share += independent > 0.0 ? second * second / independent / static_cast<double>(p) : 0.0;
    }
    c.incoherent_share = std::max(c.incoherent_share, share);
  }
  c.holds = c.incoherent_share < kCoherenceLimit;
  return c;
}

double FitModel::point_log_likelihood(std::size_t point, const PointRun& run, double mean_share, double dof) const {
  const std::size_t p = band_[point].size();
  std::vector<double> y(p), mean(p);
  for (std::size_t k = 0; k < p; ++k)
    y[k] = measured_db_[point][k] * std::log(10.0) / 10.0, mean[k] = std::exp(run.log_mean[k]);
  const PointTable& t = table_[point];
  return spectral::band_log_likelihood(y.data(), mean.data(), run.cov.data(), p, run.realisations,
                                       in_.points[point].records,
                                       {mean_share, dof, t.covariance.empty() ? nullptr : t.covariance.data()});
}

double FitModel::negative_log_likelihood(const std::vector<double>& u) {
  const auto hit = cache_.find(u);
  if (hit != cache_.end()) return hit->second;
  // Runs made outside the search (the start's probe) are neither looked up in nor written to the
  // journal: a resumed fit makes them again.
  const bool journalled = journal_ && crn_.find(u) == crn_.end();
  std::vector<double> values;
  if (journalled && journal_->find(u, values)) {
    ++reused_;
    cache_.emplace(u, values[0]);
    return values[0];
  }
  const std::vector<PointRun> runs = crn_runs(u);
  double value = 0.0;
  for (std::size_t point = 0; point < runs.size(); ++point) {
    try {
      value -= point_log_likelihood(point, runs[point], 1.0, 0.0);
    } catch (const std::invalid_argument&) {
      value = INFINITY;  // a point where the model has no power in a band: impossible
      break;
    }
  }
  cache_.emplace(u, value);
  if (journalled) journal_->record(u, {value});
  return value;
}

std::vector<std::vector<double>> FitModel::log_means(const std::vector<double>& u) {
  std::vector<std::vector<double>> out;
  for (const PointRun& r : crn_runs(u)) out.push_back(r.log_mean);
  return out;
}

std::vector<PointRun> FitModel::replicate(const std::vector<double>& u, std::uint64_t index) {
  std::vector<double> key = u, values;
  key.push_back(static_cast<double>(index));
  std::vector<PointRun> runs;
  if (journal_ && journal_->find(key, values)) {
    ++reused_;
    std::size_t at = 0;
    for (std::size_t point = 0; point < in_.points.size(); ++point) {
      const std::size_t p = band_[point].size();
      if (values.size() < at + 1 + p + p * p) throw data_error("--journal: a replicate's line is cut short");
      PointRun r;
      r.realisations = static_cast<std::uint64_t>(values[at]);
      r.log_mean.assign(values.begin() + static_cast<std::ptrdiff_t>(at + 1),
                        values.begin() + static_cast<std::ptrdiff_t>(at + 1 + p));
      r.cov.assign(values.begin() + static_cast<std::ptrdiff_t>(at + 1 + p),
                   values.begin() + static_cast<std::ptrdiff_t>(at + 1 + p + p * p));
      at += 1 + p + p * p;
      runs.push_back(std::move(r));
    }
    return runs;
  }
  double draw = 0.0;
  rng::PhiloxStream(seed_, index, rng::Stream::fit_replicate_seed).uniform_open(&draw, 1);
  const std::string seed = study::StudySection::seed_setting(static_cast<std::uint64_t>(draw * 9.0e18));
  for (std::size_t point = 0; point < in_.points.size(); ++point) {
    std::vector<std::string> extra = later_sets(point);
    extra.push_back(seed);
    runs.push_back(point_run(point, run_at(point, u, extra)));
    values.push_back(static_cast<double>(runs.back().realisations));
    values.insert(values.end(), runs.back().log_mean.begin(), runs.back().log_mean.end());
    values.insert(values.end(), runs.back().cov.begin(), runs.back().cov.end());
  }
  if (journal_) journal_->record(key, values);
  return runs;
}

std::vector<io::BandLevels> FitModel::runs_at(const std::vector<double>& u) {
  std::vector<io::BandLevels> out;
  for (std::size_t point = 0; point < in_.points.size(); ++point) {
    io::BandLevels b = run_at(point, u, later_sets(point));
    const io::BandLevels& held = table_[point].held;
    if (held.table_units >= 2) {  // the term held from the start (D-31), as the likelihood has it
      b.table_levels_db = held.table_levels_db;
      b.table_units = held.table_units;
      b.table_dof = held.table_dof;
      b.table_variance_factor = held.table_variance_factor;
      b.table = held.table;
      b.table_independent_bands = held.table_independent_bands;
      b.table_error_missing = false;
    }
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace rollspec::fit
