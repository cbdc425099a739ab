#include "src/cli/fit_model.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "src/cli/fit_journal.hpp"
#include "src/cli/run_phases.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"
#include "src/io/run_warning.hpp"

namespace rollspec::cli {

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
      last_warnings_(in.points.size()) {}

std::size_t FitModel::bands() const {
  std::size_t n = 0;
  for (const auto& b : band_) n += b.size();
  return n;
}

io::BandLevels FitModel::run_at(std::size_t point, const std::vector<double>& u) {
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
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", in_.vary[i].value(u[i]));
    sets.push_back(in_.vary[i].key + "=" + buf);
  }
  ++runs_;
  {
    const io::RunWarningCapture capture;  // said once, for the run at the estimate (fit_command)
    run_request(request);
    last_warnings_[point] = capture.lines();
  }
  if (!last_warnings_[point].empty()) ++warned_runs_;
  io::BandLevels b;
  std::vector<double> psd;  // the row's mean PSD, for the point's first run only (check_band_rules)
  double df = 0.0;
  {
    const io::Hdf5Reader r(out);
    io::check_filetype(r, io::kResultFileType, io::kResultSchemaMajor);
    b = io::read_band_levels(r, in_.sensor);
    if (band_[point].empty()) psd = mean_psd_row(r, b.sensor, df);
  }
  std::filesystem::remove(out);
  if (band_[point].empty() && !b.pick_note.empty()) std::fprintf(stderr, "rollspec fit: %s\n", b.pick_note.c_str());
  if (band_[point].empty()) {
    choose_bands(point, b);
    check_band_rules(point, b, psd, df);
  }
  return b;
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

double FitModel::negative_log_likelihood(const std::vector<double>& u) {
  const auto hit = cache_.find(u);
  if (hit != cache_.end()) return hit->second;
  double value = 0.0;
  if (journal_ && journal_->find(u, value)) {
    ++reused_;
    cache_.emplace(u, value);
    return value;
  }
  for (std::size_t point = 0; point < in_.points.size(); ++point) {
    const io::BandLevels b = run_at(point, u);
    const ChosenBands c = chosen_bands(b, band_[point], measured_db_[point]);
    try {
      value -= spectral::band_log_likelihood(c.y.data(), c.mean.data(), c.cov.data(), band_[point].size(),
                                             b.realisations, in_.points[point].records);
    } catch (const std::invalid_argument&) {
      value = INFINITY;  // a point where the model has no power in a band: impossible
      break;
    }
  }
  cache_.emplace(u, value);
  if (journal_) journal_->record(u, value);
  return value;
}

std::vector<CombinedTest> FitModel::tests_at(const std::vector<double>& u) {
  std::vector<CombinedTest> tests;
  for (std::size_t point = 0; point < in_.points.size(); ++point) {
    const io::BandLevels b = run_at(point, u);
    tests.push_back(combined_test(b, band_[point], measured_db_[point], in_.points[point].records, 0.05));
  }
  return tests;
}

}  // namespace rollspec::cli
