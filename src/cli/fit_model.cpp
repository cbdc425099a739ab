#include "src/cli/fit_model.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "src/cli/commands.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"

namespace rollspec::cli {

using io::number_text;

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

FitModel::FitModel(const FitInputs& in, std::string temp_dir) : in_(in), temp_dir_(std::move(temp_dir)) {}

io::BandLevels FitModel::run_at(const std::vector<double>& u) {
  const std::string out = temp_dir_ + "/run-" + std::to_string(runs_) + ".h5";
  Args args{in_.study, "--out", out, "--quiet"};
  for (const auto& s : in_.sets) args.insert(args.end(), {"--set", s});
  for (std::size_t i = 0; i < in_.vary.size(); ++i) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", in_.vary[i].value(u[i]));
    args.insert(args.end(), {"--set", in_.vary[i].key + "=" + buf});
  }
  ++runs_;
  run_command(args);
  io::BandLevels b;
  {
    const io::Hdf5Reader r(out);
    io::check_filetype(r, io::kResultFileType, io::kResultSchemaMajor);
    b = io::read_band_levels(r, in_.sensor);
  }
  std::filesystem::remove(out);
  if (band_.empty() && !b.pick_note.empty()) std::fprintf(stderr, "rollspec fit: %s\n", b.pick_note.c_str());
  if (band_.empty()) choose_bands(b);
  return b;
}

// The bands inside [fmin, fmax] that the measurement covers with power, as compare takes them.
void FitModel::choose_bands(const io::BandLevels& b) {
  const Measurement& m = in_.measurement;
  for (std::size_t k = 0; k < b.level_db.size(); ++k) {
    if (b.lower[k] < in_.fmin || b.upper[k] > in_.fmax) continue;
    if (m.frequency.size() < 2 || m.frequency.front() > b.lower[k] || m.frequency.back() < b.upper[k]) continue;
    const double meas =
        spectral::band_average_irregular(m.frequency.data(), m.psd.data(), m.frequency.size(), b.lower[k], b.upper[k]);
    if (!(meas > 0.0) || !std::isfinite(meas)) continue;
    band_.push_back(k);
    measured_db_.push_back(10.0 * std::log10(meas));
  }
  realisations_ = b.realisations;
  const std::size_t needed = band_.size() + spectral::kExtraRealisations;
  if (band_.empty()) throw data_error(in_.measurement_path + ": covers none of the result's bands inside [fmin, fmax]");
  if (b.log_covariance.empty())
    throw data_error(in_.study + ": its result has no /bands/log_level_covariance; fit needs it");
  if (b.realisations < needed)
    throw config_error(in_.study + ": " + std::to_string(band_.size()) + " bands need K >= " + std::to_string(needed) +
                       " realisations for the band covariance, the study runs " + std::to_string(b.realisations) +
                       "; raise study.realisations (--set) or choose fewer bands with --fmin/--fmax");
}

double FitModel::negative_log_likelihood(const std::vector<double>& u) {
  const auto hit = cache_.find(u);
  if (hit != cache_.end()) return hit->second;
  const io::BandLevels b = run_at(u);
  const ChosenBands c = chosen_bands(b, band_, measured_db_);
  double value = INFINITY;  // a point where the model has no power in a band: impossible
  try {
    value = -spectral::band_log_likelihood(c.y.data(), c.mean.data(), c.cov.data(), band_.size(), b.realisations,
                                           in_.records);
  } catch (const std::invalid_argument&) {
  }
  cache_.emplace(u, value);
  return value;
}

CombinedTest FitModel::test_at(const std::vector<double>& u) {
  const io::BandLevels b = run_at(u);
  return combined_test(b, band_, measured_db_, in_.records, 0.05);
}

}  // namespace rollspec::cli
