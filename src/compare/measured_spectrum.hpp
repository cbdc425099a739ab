#pragma once
// The measurement end of a comparison (kernels/spectral D-32): recordings put through the model's own
// estimator, or a PSD table, as one object with its unit, its number of independent rolls M, its
// resolution and what was chosen for it. Recordings are read by io::prepare_signal (units from the file,
// one line per choice) and go through Welch with the model's segment (in seconds), overlap, window and
// detrending: the measured bands then average the same bins the model's do, and the measurement's
// equivalent degrees of freedom are known exactly.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kernels/spectral/welch.hpp"
#include "src/io/signal_file.hpp"

namespace rollspec::io {
class Hdf5Reader;
}

namespace rollspec::compare {

// The estimator of a result's realisations (/psd@sample_rate, welch_segment, welch_overlap, welch_window,
// welch_detrend, record_samples); empty for results written before they were recorded.
struct ModelEstimator {
  spectral::WelchConfig welch;
  std::size_t record_samples = 0;
  double frequency_step() const { return welch.sample_rate / static_cast<double>(welch.segment); }
  double record_seconds() const { return static_cast<double>(record_samples) / welch.sample_rate; }
};
std::optional<ModelEstimator> read_model_estimator(const io::Hdf5Reader& r);

struct MeasuredSpectrum {
  std::string source;                              // the file(s), for messages and the JSON
  std::vector<double> frequency;                   // Hz
  std::vector<double> psd;                         // mean over the rolls, (m/s^2)^2/Hz
  std::vector<std::vector<double>> rolls;          // each roll's PSD (recordings; empty for a PSD table)
  double records = 0.0;                            // M, independent rolls (0: the file cannot say)
  std::string records_source;                      // how M was found ("3 recordings", "--measured-averages")
  bool model_grid = false;                         // on the model's own bins: bands average them as the model's do
  double welch_dof = 0.0;                          // D-16 dof of one roll's Welch estimate (0: unknown)
  double seconds = 0.0;                            // one roll's length (0: unknown)
  std::vector<std::string> notes;                  // every choice made without being asked, one line each
  std::optional<spectral::WelchConfig> estimator;  // the Welch estimator every roll went through (recordings)
  std::vector<std::size_t> roll_samples;           // each roll's length in samples (recordings)
  std::vector<std::vector<double>> roll_signals;   // each roll's samples where a roll is one channel (D-33e)
};

struct RecordingOptions {
  io::SignalRequest signal;       // --column, --unit, --scale, --fs, --time-column, --skip-rows
  bool roll_per_channel = false;  // each channel is a roll of one sensor (default: a file is a roll, its
                                  // channels the sensors)
  std::size_t model_sensors = 1;  // the rows the compared row averages (sensor_mean: every sensor; else 1)
};

// A file that holds a PSD table (a `frequency_hz` column, or rollspec psd's output) rather than a signal.
bool is_psd_table(const std::string& path);

// Recordings, each one roll (or each channel one roll with roll_per_channel), through the model's
// estimator at each file's own sample rate (segment = the model's segment in seconds). Channels of one
// roll are the model's sensors and are averaged when the compared row averages sensors. Refuses (exit
// 64/65) files of different units or rates where the rolls must agree, channel counts that do not match
// the row, and recordings shorter than one segment.
MeasuredSpectrum measure_recordings(const std::vector<std::string>& paths, const RecordingOptions& options,
                                    const ModelEstimator& model);

// D-33c a: the equivalent degrees of freedom of the band [lower, upper] Hz of the rolls' mean PSD for white
// Gaussian noise, R^2 / sum_r 1/nu_r over its R rolls (kernels/spectral/band_dof.hpp); 0 where the estimator is not
// known (a PSD table).
double band_dof_of_mean(const MeasuredSpectrum& m, double lower, double upper);

// D-33e: the logger noise's log covariance (p x p, row-major) between the bands [lower_b, upper_b] of the rolls'
// mean, from the rolls' own samples: ln(1 + sum_r cov_r(P_b, P_c | s_r) / (R^2 (m_b + N_b)(m_c + N_c))), model
// powers m_b > 0, the noise's band levels N_b >= 0 (white within each band pair's bins). Empty where a roll's
// samples are not kept (channels averaged, a PSD table) or the estimator is unknown.
std::vector<double> noise_log_covariance(const MeasuredSpectrum& m, const std::vector<double>& lower,
                                         const std::vector<double>& upper, const std::vector<double>& model_power,
                                         const std::vector<double>& noise_power);

// Welch D-15 of one signal with the model's estimator scaled to `sample_rate`; the segment rounded to
// whole samples (the resolution differs from the model's by that rounding, said in `note`).
spectral::WelchConfig estimator_at(const ModelEstimator& model, double sample_rate, std::string& note);

}  // namespace rollspec::compare
