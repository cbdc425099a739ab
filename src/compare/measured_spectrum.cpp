#include "src/compare/measured_spectrum.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>

#include "kernels/spectral/band_dof.hpp"
#include "kernels/spectral/band_noise_covariance.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/time_column.hpp"

namespace rollspec::compare {

using io::number_text;

std::optional<ModelEstimator> read_model_estimator(const io::Hdf5Reader& r) {
  for (const char* a : {"sample_rate", "welch_segment", "welch_overlap", "welch_window", "record_samples"})
    if (!r.has_attribute("/psd", a)) return std::nullopt;
  ModelEstimator m;
  m.welch.sample_rate = r.double_attribute("/psd", "sample_rate");
  const double segment = r.double_attribute("/psd", "welch_segment"),
               overlap = r.double_attribute("/psd", "welch_overlap");
  const double record = r.double_attribute("/psd", "record_samples");
  const std::string window = r.string_attribute("/psd", "welch_window");
  if (!(m.welch.sample_rate > 0.0 && std::isfinite(m.welch.sample_rate)) || !(segment >= 4.0 && segment < 1e9) ||
      segment != std::floor(segment) || !(overlap >= 0.0 && overlap < segment) || overlap != std::floor(overlap) ||
      !(record >= segment && record < 1e15) || (window != "hann" && window != "rect"))
    throw data_error(r.path() + ": /psd@sample_rate, welch_segment, welch_overlap, record_samples, welch_window = " +
                     number_text(m.welch.sample_rate) + ", " + number_text(segment) + ", " + number_text(overlap) +
                     ", " + number_text(record) + ", " + window +
                     "; allowed: a rate > 0, a segment >= 4 samples, 0 <= overlap < segment <= record, hann or rect "
                     "(the file was altered or damaged)");
  m.welch.segment = static_cast<std::size_t>(segment);
  m.welch.overlap = static_cast<std::size_t>(overlap);
  m.welch.window = window == "hann" ? spectral::Window::hann : spectral::Window::rectangular;
  m.welch.detrend = r.has_attribute("/psd", "welch_detrend") && r.string_attribute("/psd", "welch_detrend") == "none"
                        ? spectral::Detrend::none
                        : spectral::Detrend::constant;
  m.record_samples = static_cast<std::size_t>(record);
  return m;
}

bool is_psd_table(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(512, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  for (const char* magic : {"RIFF", "FORM", "fLaC", "OggS", ".snd", "MATLAB", "\x89HDF"})
    if (head.rfind(magic, 0) == 0) return false;
  // A header naming a frequency or a PSD (frequency_hz, psd, a title in (m/s^2)^2/Hz or g^2/Hz) marks a
  // PSD table; a signal's header names channels and perhaps a time column.
  std::ifstream text(path);
  std::string line;
  for (int n = 0; n < 200 && std::getline(text, line); ++n) {
    if (n == 0 && line.rfind("# rollspec-psd-csv", 0) == 0) return true;
    std::string low;
    for (const char c : line) low += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* mark : {"frequency_hz", "/hz]", "/hz)", "frequency (hz)", "frequency [hz]"})
      if (low.find(mark) != std::string::npos) return true;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= low.size(); ++i)
      if (i == low.size() || low[i] == ',' || low[i] == ';' || low[i] == '\t') {
        std::string cell = low.substr(start, i - start);
        cell.erase(0, cell.find_first_not_of(" \t\r\""));
        cell.erase(cell.find_last_not_of(" \t\r\"") + 1);
        if (cell == "psd") return true;
        start = i + 1;
      }
  }
  return false;
}

namespace {

// A rate fitted to rounded time stamps (6 printed decimals: 25599.99994 Hz for 25600) differs from the true
// rate in its last digits. Two rates that place the highest bin of a segment less than this share of a bin
// apart give the same bins: a recording at such a rate is on the model's grid, and rolls at such rates agree.
constexpr double kSameBinShare = 0.01;

bool same_grid(double a, double b, std::size_t segment) {
  return std::fabs(a - b) / b * (static_cast<double>(segment) / 2.0) < kSameBinShare;
}

}  // namespace

spectral::WelchConfig estimator_at(const ModelEstimator& model, double sample_rate, std::string& note) {
  spectral::WelchConfig c = model.welch;
  note.clear();
  if (same_grid(sample_rate, model.welch.sample_rate, model.welch.segment)) {
    if (sample_rate != model.welch.sample_rate)
      note = "sampled at " + io::rate_text(sample_rate) + " Hz, taken as the model's " +
             number_text(model.welch.sample_rate) + " Hz (the difference moves no bin by a hundredth of a bin)";
    return c;
  }
  const double ratio = sample_rate / model.welch.sample_rate;
  c.sample_rate = sample_rate;
  c.segment = static_cast<std::size_t>(std::lround(static_cast<double>(model.welch.segment) * ratio));
  c.overlap = static_cast<std::size_t>(std::lround(static_cast<double>(model.welch.overlap) * ratio));
  if (c.segment < 4) c.segment = 4;
  if (c.overlap >= c.segment) c.overlap = c.segment / 2;
  const double df = sample_rate / static_cast<double>(c.segment), dfm = model.frequency_step();
  note = "sampled at " + number_text(sample_rate) + " Hz, the model at " + number_text(model.welch.sample_rate) +
         " Hz: Welch segment " + std::to_string(c.segment) + " samples (the model's " +
         number_text(static_cast<double>(model.welch.segment) / model.welch.sample_rate) + " s), bins of " +
         number_text(df) + " Hz" +
         (std::fabs(df - dfm) <= 1e-9 * dfm ? "" : " against the model's " + number_text(dfm) + " Hz");
  return c;
}

namespace {

struct Roll {
  std::string file;
  std::vector<double> psd;
  double seconds = 0.0, dof = 0.0, df = 0.0, rate = 0.0;
  spectral::WelchConfig estimator;
  std::size_t samples = 0;
  std::vector<double> signal;  // the roll's samples where it is one channel (D-33e)
};

std::string names(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& n : v) s += (s.empty() ? "" : ", ") + n;
  return clip(s, 300);
}

}  // namespace

MeasuredSpectrum measure_recordings(const std::vector<std::string>& paths, const RecordingOptions& options,
                                    const ModelEstimator& model) {
  MeasuredSpectrum m;
  std::vector<Roll> rolls;
  std::map<std::pair<double, std::size_t>, std::unique_ptr<spectral::WelchPlan>> plans;
  for (const auto& path : paths) {
    const io::SignalTable t = io::prepare_signal(path, options.signal);
    m.notes.insert(m.notes.end(), t.notes.begin(), t.notes.end());
    std::string note;
    const spectral::WelchConfig c = estimator_at(model, t.sample_rate, note);
    if (!note.empty()) m.notes.push_back(path + ": " + note);
    const std::size_t n = t.samples();
    if (n < c.segment)
      throw data_error(path + ": " + std::to_string(n) + " samples (" +
                       number_text(static_cast<double>(n) / t.sample_rate) +
                       " s), fewer than one segment of the model's estimator (" + std::to_string(c.segment) +
                       " samples, " + number_text(static_cast<double>(c.segment) / t.sample_rate) +
                       " s); allowed: a recording of the ball's roll, at least one segment long");
    auto& plan = plans[{c.sample_rate, c.segment}];
    if (!plan) plan = std::make_unique<spectral::WelchPlan>(c);
    spectral::WelchWorkspace ws(c.segment);
    const std::size_t channels = t.channels.size();
    if (!options.roll_per_channel && channels != options.model_sensors)
      throw usage_error(
          path + ": " + io::counted(channels, "channel") + " (" + names(t.channels) + ") for " +
          (options.model_sensors == 1 ? std::string("one sensor")
                                      : "the compared row, which averages the result's " +
                                            std::to_string(options.model_sensors) + " sensors") +
          "; allowed: " +
          (options.model_sensors == 1 ? "one channel (--column NAME picks it)"
                                      : "one channel per sensor, in the order of the study's [sensors] positions "
                                        "(--column picks them)") +
          ", --sensor K or --measured-position X to compare one sensor, or --roll-per-channel when the channels are "
          "rolls of one sensor");
    std::vector<double> sum(plan->n_freq(), 0.0), one(plan->n_freq());
    for (std::size_t ch = 0; ch < channels; ++ch) {
      plan->psd(t.values[ch].data(), n, one.data(), ws);
      for (std::size_t k = 0; k < one.size(); ++k)
        if (!std::isfinite(one[k]))
          throw data_error(path + ": channel '" + t.channels[ch] +
                           "': its PSD overflows a double; allowed: samples whose squares stay finite");
      if (options.roll_per_channel) {
        rolls.push_back({path + " [" + t.channels[ch] + "]", one, static_cast<double>(n) / t.sample_rate,
                         plan->equivalent_dof(n), plan->frequency_step(), c.sample_rate, c, n, t.values[ch]});
      } else {
        for (std::size_t k = 0; k < one.size(); ++k) sum[k] += one[k] / static_cast<double>(channels);
      }
    }
    if (!options.roll_per_channel)
      rolls.push_back({path, sum, static_cast<double>(n) / t.sample_rate, plan->equivalent_dof(n),
                       plan->frequency_step(), c.sample_rate, c, n,
                       channels == 1 ? t.values[0] : std::vector<double>{}});
    if (channels > 1 && !options.roll_per_channel)
      m.notes.push_back(path + ": channels " + names(t.channels) + " taken as the result's sensors 1.." +
                        std::to_string(channels) + " of one roll, their PSDs averaged as the row averages them");
  }
  const Roll& first = rolls.front();
  for (const Roll& r : rolls)
    if (!same_grid(r.rate, first.rate, 2 * (first.psd.size() - 1)) || r.psd.size() != first.psd.size())
      throw usage_error(r.file + ": sampled at " + number_text(r.rate) + " Hz, " + first.file + " at " +
                        number_text(first.rate) + " Hz; allowed: rolls recorded at one sample rate");
  const double dfm = model.frequency_step();
  m.frequency.resize(first.psd.size());
  for (std::size_t k = 0; k < m.frequency.size(); ++k) m.frequency[k] = static_cast<double>(k) * first.df;
  m.model_grid = std::fabs(first.df - dfm) <= 1e-9 * dfm;
  m.psd.assign(first.psd.size(), 0.0);
  double seconds = 0.0, dof = 0.0;
  for (const Roll& r : rolls) {
    for (std::size_t k = 0; k < r.psd.size(); ++k) m.psd[k] += r.psd[k] / static_cast<double>(rolls.size());
    m.rolls.push_back(r.psd);
    m.roll_samples.push_back(r.samples);
    m.roll_signals.push_back(r.signal);
    seconds += r.seconds / static_cast<double>(rolls.size());
    dof += r.dof / static_cast<double>(rolls.size());
  }
  m.estimator = first.estimator;
  m.records = static_cast<double>(rolls.size());
  m.records_source = io::counted(rolls.size(), options.roll_per_channel ? "channel" : "recording") +
                     (options.roll_per_channel ? " taken as rolls" : ", one roll each");
  m.seconds = seconds;
  m.welch_dof = dof;
  m.source = paths.size() == 1 ? paths[0] : paths[0] + " and " + io::counted(paths.size() - 1, "more file");
  m.notes.push_back("measurement: " + m.records_source + " (M = " + number_text(m.records) + "), " +
                    number_text(seconds) + " s each, through the model's estimator (Welch segment " +
                    number_text(static_cast<double>(model.welch.segment) / model.welch.sample_rate) + " s, " +
                    (model.welch.window == spectral::Window::hann ? "Hann" : "rectangular") +
                    " window, the model's overlap and detrending): " + number_text(dof) +
                    " equivalent degrees of freedom per roll (D-16), the model's record " +
                    number_text(model.record_seconds()) + " s");
  return m;
}

double band_dof_of_mean(const MeasuredSpectrum& m, double lower, double upper) {
  if (!m.estimator || m.roll_samples.empty()) return 0.0;
  const spectral::BandDof dof(*m.estimator);
  std::map<std::size_t, double> inverse;  // 1 / nu_b for each roll length
  double sum = 0.0;
  for (const std::size_t n : m.roll_samples) {
    auto it = inverse.find(n);
    if (it == inverse.end()) {
      const double nu = dof(n, lower, upper);
      it = inverse.emplace(n, nu > 0.0 ? 1.0 / nu : INFINITY).first;
    }
    sum += it->second;
  }
  const double rolls = static_cast<double>(m.roll_samples.size());
  return std::isfinite(sum) ? rolls * rolls / sum : 0.0;
}

std::vector<double> noise_log_covariance(const MeasuredSpectrum& m, const std::vector<double>& lower,
                                         const std::vector<double>& upper, const std::vector<double>& model_power,
                                         const std::vector<double>& noise_power) {
  const std::size_t p = lower.size(), rolls = m.roll_signals.size();
  if (!m.estimator || p == 0 || rolls == 0 || rolls != m.roll_samples.size()) return {};
  for (std::size_t r = 0; r < rolls; ++r)
    if (m.roll_signals[r].size() != m.roll_samples[r]) return {};
  std::map<std::size_t, std::unique_ptr<spectral::BandNoiseCovariance>> forms;  // one per roll length
  std::vector<double> sum(p * p, 0.0);
  for (std::size_t r = 0; r < rolls; ++r) {
    auto& f = forms[m.roll_samples[r]];
    if (!f) f = std::make_unique<spectral::BandNoiseCovariance>(*m.estimator, m.roll_samples[r], lower, upper);
    std::vector<double> sigma2(p);  // the noise's per-sample variance in each band: N_b = sigma^2 tr Q_b
    for (std::size_t b = 0; b < p; ++b) sigma2[b] = noise_power[b] / f->trace()[b];
    const std::vector<double> c = f->covariance(m.roll_signals[r].data(), sigma2);
    for (std::size_t b = 0; b < p; ++b)
      for (std::size_t e = 0; e < p; ++e) {
        // The signal's part is >= 0: a diagonal estimate below the noise's own term is held at it.
        const double floor = 2.0 * sigma2[b] * sigma2[b] * f->trace_product()[b * p + b];
        sum[b * p + e] += b == e ? std::max(c[b * p + b], floor) : c[b * p + e];
      }
  }
  const double r2 = static_cast<double>(rolls) * static_cast<double>(rolls);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t e = 0; e < p; ++e)
      sum[b * p + e] =
          std::log1p(sum[b * p + e] / (r2 * (model_power[b] + noise_power[b]) * (model_power[e] + noise_power[e])));
  return sum;
}

}  // namespace rollspec::compare
