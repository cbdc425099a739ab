// rollspec.spectra: the Welch PSD of `rollspec psd` (kernels/spectral/welch.hpp, D-15) and the third-octave
// bands of a result (io::result_bands, band_average, D-17) with their chi-square intervals (BandDof D-33c a,
// chi_square_interval D-16), on numpy arrays.
#include <cmath>
#include <limits>
#include <optional>

#include "kernels/spectral/band_dof.hpp"
#include "kernels/spectral/confidence.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "python/bindings.hpp"
#include "src/io/psd_options.hpp"
#include "src/io/number_text.hpp"
#include "src/io/signal_file.hpp"
#include "src/io/psd_result.hpp"
#include "src/study/sections/spectrum_section.hpp"

namespace rollspec::python {

namespace {

struct Estimate {
  spectral::WelchConfig config;
  std::size_t samples = 0, channels = 0;
  bool one_channel = true;
  std::vector<double> frequency, psd;  // psd: channels x bins, row-major
};

// `rollspec psd`'s options, checked by the command's own rules (cli/psd_options.hpp).
spectral::WelchConfig welch_config(double fs, long long segment, double overlap, const std::string& window,
                                   const std::string& detrend) {
  io::SignalOptions signal;
  signal.fs = fs;
  const double rate = io::signal_request(signal, io::OptionSpelling::python).fs;
  spectral::WelchConfig c = io::welch_options({segment, overlap, window, detrend}, io::OptionSpelling::python);
  c.sample_rate = rate;
  return c;
}

Estimate estimate(const py::handle& x, double fs, long long segment, double overlap, const std::string& window,
                  const std::string& detrend) {
  Estimate e;
  e.config = welch_config(fs, segment, overlap, window, detrend);
  const py::array raw = py::array::ensure(x);
  e.one_channel = !raw || raw.ndim() != 2;
  const Array a = finite_array(x, "x", e.one_channel ? 1 : 2, 1,
                               "samples (m/s^2 or any unit), 1-D, or 2-D with one channel per row");
  e.channels = e.one_channel ? 1 : static_cast<std::size_t>(a.shape(0));
  e.samples = static_cast<std::size_t>(a.shape(e.one_channel ? 0 : 1));
  if (e.samples < e.config.segment)
    refuse("x", io::counted(e.samples, "sample") + " per channel", "fewer than one segment",
           "at least segment = " + std::to_string(e.config.segment) + " samples");
  {
    py::gil_scoped_release unlocked;
    const spectral::WelchPlan plan(e.config);
    spectral::WelchWorkspace ws(e.config.segment);
    e.frequency = plan.frequencies();
    e.psd.assign(e.channels * plan.n_freq(), 0.0);
    for (std::size_t c = 0; c < e.channels; ++c)
      plan.psd(a.data() + c * e.samples, e.samples, e.psd.data() + c * plan.n_freq(), ws);
  }
  for (const double v : e.psd)
    if (!std::isfinite(v))
      refuse("x", "an array", "its PSD overflows a double",
             "samples whose squares stay finite, e.g. |value| < 1e100 (rescale the unit)");
  return e;
}

py::dict choices(const Estimate& e) {
  const spectral::WelchPlan plan(e.config);
  py::dict d;
  d["sample_rate"] = e.config.sample_rate;
  d["segment"] = e.config.segment;
  d["overlap"] = e.config.overlap;
  d["window"] = e.config.window == spectral::Window::hann ? "hann" : "rectangular";
  d["detrend"] = e.config.detrend == spectral::Detrend::constant ? "constant" : "none";
  d["samples"] = e.samples;
  d["segments"] = plan.segments(e.samples);
  d["equivalent_dof"] = plan.equivalent_dof(e.samples);
  return d;
}

py::dict welch(const py::handle& x, double fs, long long segment, double overlap, const std::string& window,
               const std::string& detrend) {
  Estimate e = estimate(x, fs, segment, overlap, window, detrend);
  py::dict d = choices(e);
  const auto bins = static_cast<py::ssize_t>(e.frequency.size());
  d["frequency"] = to_numpy(std::move(e.frequency), {bins});
  d["psd"] = e.one_channel ? to_numpy(std::move(e.psd), {bins})
                           : to_numpy(std::move(e.psd), {static_cast<py::ssize_t>(e.channels), bins});
  return d;
}

py::dict bands(const py::handle& x, double fs, long long segment, double overlap, const std::string& window,
               const std::string& detrend, double band_min, double band_max, double confidence) {
  const auto keys = study::SpectrumSection::keys();
  key_value(key_spec(keys, "spectrum.band_min"), band_min);
  key_value(key_spec(keys, "spectrum.band_max"), band_max);
  key_value(key_spec(keys, "spectrum.confidence"), confidence);
  const Estimate e = estimate(x, fs, segment, overlap, window, detrend);
  const auto list = io::result_bands(e.frequency, band_min, band_max);
  if (list.empty())
    refuse("band_min, band_max", io::number_text(band_min) + ", " + io::number_text(band_max) + " Hz",
           "no third-octave band between them and inside the PSD's bins (" + io::number_text(e.frequency[1]) + " .. " +
               io::number_text(e.frequency.back()) + " Hz)",
           "a range that holds a whole band");
  const std::size_t nb = list.size(), nf = e.frequency.size();
  std::vector<double> centre(nb), nominal(nb), lower(nb), upper(nb), dof(nb), level(nb * e.channels),
      ci_lower(nb * e.channels), ci_upper(nb * e.channels);
  const spectral::BandDof band_dof(e.config);
  const double df = e.frequency[1] - e.frequency[0];
  for (std::size_t b = 0; b < nb; ++b) {
    centre[b] = list[b].centre, nominal[b] = list[b].nominal, lower[b] = list[b].lower, upper[b] = list[b].upper;
    dof[b] = band_dof(e.samples, list[b].lower, list[b].upper);
    const spectral::IntervalFactors f = spectral::chi_square_interval(dof[b], confidence);
    for (std::size_t c = 0; c < e.channels; ++c) {
      const double v = spectral::band_average(e.psd.data() + c * nf, nf, df, list[b].lower, list[b].upper);
      level[c * nb + b] = v, ci_lower[c * nb + b] = v * f.lower, ci_upper[c * nb + b] = v * f.upper;
    }
  }
  py::dict d = choices(e);
  d["confidence"] = confidence;
  const auto n = static_cast<py::ssize_t>(nb);
  const std::vector<py::ssize_t> shape =
      e.one_channel ? std::vector<py::ssize_t>{n} : std::vector<py::ssize_t>{static_cast<py::ssize_t>(e.channels), n};
  d["centre"] = to_numpy(std::move(centre), {n});
  d["nominal"] = to_numpy(std::move(nominal), {n});
  d["lower"] = to_numpy(std::move(lower), {n});
  d["upper"] = to_numpy(std::move(upper), {n});
  d["dof"] = to_numpy(std::move(dof), {n});
  d["level"] = to_numpy(std::move(level), shape);
  d["ci_lower"] = to_numpy(std::move(ci_lower), shape);
  d["ci_upper"] = to_numpy(std::move(ci_upper), shape);
  return d;
}

// A Python argument that is None, or a value of type T; another type is a TypeError naming it.
template <class T>
std::optional<T> optional_arg(const py::object& value, const std::string& name, const std::string& allowed) {
  if (value.is_none()) return std::nullopt;
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error(name + ": a " + py::type::of(value).attr("__name__").cast<std::string>() +
                         "; allowed: " + allowed + ", or None");
  }
}

// `column`: None (every channel), a name, or a sequence of names (each may hold several, comma-separated,
// as --column does).
std::vector<std::string> column_names(const py::object& column) {
  if (py::isinstance<py::str>(column)) return {column.cast<std::string>()};
  return optional_arg<std::vector<std::string>>(column, "column", "a channel name or a sequence of names")
      .value_or(std::vector<std::string>{});
}

const char* origin_name(io::UnitOrigin origin) {
  switch (origin) {
    case io::UnitOrigin::name:
      return "name";
    case io::UnitOrigin::units_row:
      return "units_row";
    case io::UnitOrigin::option:
      return "unit";
    case io::UnitOrigin::assumed:
      return "assumed";
    case io::UnitOrigin::none:
      break;
  }
  return "none";
}

py::dict read_measurement(const py::object& path, const py::object& column, const py::object& unit,
                          const py::object& time_column, const py::object& fs, const py::object& scale,
                          const py::object& skip_rows) {
  const std::string file = file_name(path, "path");
  io::SignalOptions o;
  o.fs = optional_arg<double>(fs, "fs", "a sample rate (Hz)");
  o.columns = column_names(column);
  o.unit = optional_arg<std::string>(unit, "unit", "a unit, or one per channel, comma-separated").value_or("");
  o.scale = optional_arg<double>(scale, "scale", "a number");
  o.time_column = optional_arg<std::string>(time_column, "time_column", "a column name, or 'none'");
  o.skip_rows = optional_arg<long long>(skip_rows, "skip_rows", "a whole number of lines");
  const io::SignalRequest request = io::signal_request(o, io::OptionSpelling::python);
  io::SignalTable t;
  std::vector<double> samples;
  std::size_t length = 0;
  {
    py::gil_scoped_release unlocked;
    t = io::prepare_signal(file, request);
    length = t.samples();
    samples.reserve(t.channels.size() * length);
    for (auto& v : t.values) {  // channels of one length (prepare_signal), each freed once copied
      samples.insert(samples.end(), v.begin(), v.end());
      std::vector<double>().swap(v);
    }
  }
  py::dict d;
  d["samples"] =
      to_numpy(std::move(samples), {static_cast<py::ssize_t>(t.channels.size()), static_cast<py::ssize_t>(length)});
  d["sample_rate"] = t.sample_rate;
  d["rate_source"] = t.rate_source;
  d["channels"] = t.channels;
  py::list units;
  for (const auto& u : t.units) {
    py::dict c;
    c["unit"] = u.text, c["written"] = u.written, c["factor"] = u.factor, c["origin"] = origin_name(u.origin);
    c["where"] = u.where;
    units.append(c);
  }
  d["units"] = units;
  d["scale"] = t.scale;
  d["time_column"] = t.time_column.empty() ? py::object(py::none()) : py::str(t.time_column);
  d["format"] = t.format;
  d["file"] = t.file;
  d["notes"] = t.notes;
  return d;
}

const char* const kWelchDoc = R"(Welch PSD of a sampled signal, as `rollspec psd` computes it.

One-sided power spectral density (density scaling, D-15): segments of `segment` samples overlapping
by floor(overlap * segment) samples, each detrended and windowed (periodic window), their periodograms
averaged (scipy.signal.welch's defaults give the same estimator).

Parameters
----------
x : array_like, 1-D (samples) or 2-D (channels, samples)
    The signal, in any unit U (e.g. m/s^2). Converted to C-contiguous float64 if it is not.
fs : float
    Sample rate (Hz).
segment : int
    Segment length L (samples), >= 4. Default 1024, the command's.
overlap : float
    Overlap as a fraction of the segment, in [0, 0.95]. Default 0.5.
window : str
    'hann' or 'rectangular' ('rect').
detrend : str
    'mean' or 'constant' (the segment's mean removed; the command's) or 'none'.

Returns
-------
dict
    frequency (Hz, L/2 + 1 bins from 0 to fs/2), psd (U^2/Hz; one row per channel for 2-D x),
    and the choices made: sample_rate (Hz), segment and overlap (samples), window, detrend, samples,
    segments (averaged), equivalent_dof (D-16, of one bin for Gaussian noise with a flat spectrum).

Raises
------
ValueError
    A bad option or array, one line naming it, its value and what is allowed.
)";

const char* const kBandsDoc = R"(Third-octave band levels of a sampled signal's Welch PSD, with chi-square intervals.

The PSD is `welch`'s (same options). The bands are the IEC 61260-1 base-ten bands (D-17) whose edges
lie in [max(band_min, df), min(band_max, fs/2)], as a study's result chooses them; each level is the
mean of the PSD over the band, each bin covering [f - df/2, f + df/2] (band_average). The interval
for the true band level is the chi-square one (D-16) with the band average's equivalent degrees of
freedom for white Gaussian noise (D-33c a), at level `confidence`.

Parameters
----------
x, fs, segment, overlap, window, detrend
    As for `welch`.
band_min, band_max : float
    Lowest and highest band edge (Hz); defaults and ranges those of the study keys
    [spectrum] band_min and band_max.
confidence : float
    Interval level; default and range those of [spectrum] confidence.

Returns
-------
dict
    centre, nominal, lower, upper (Hz, per band), dof (per band), level, ci_lower, ci_upper
    (U^2/Hz, per band, one row per channel for 2-D x), confidence, and welch's choices.
)";

const char* const kReadMeasurementDoc = R"(A measured signal as `rollspec psd` and `rollspec compare` read it, in m/s^2.

The file is read by its content, else its extension: CSV/text (delimiter, decimal comma, preamble,
header and units row found from the data; a time column t, time, Time (s), t [ms], ... gives the
sample rate), WAV/FLAC/AIFF/... (libsndfile: the header's rate; integer PCM needs `scale`), or MATLAB
.mat v4/v5/v7.3 (each real vector a channel; a scalar fs or a time vector gives the rate). Each
channel's unit comes from `unit`, else its name (Acc (g), a [m/s^2], acc_g) or the units row, else
m/s^2 is assumed; the values are converted to m/s^2 (g = 9.80665 m/s^2) and multiplied by `scale`.
`rollspec psd --help` says every rule.

Parameters
----------
path : str or os.PathLike
    The signal file.
column : str or sequence of str, optional
    The channels, in the order wanted (a .mat matrix's name picks all its columns); default all.
unit : str, optional
    The values' unit, one for all channels or one per channel ('g,m/s2'): g, m/s2, cm/s2, mm/s2,
    um/s2, in/s2, ft/s2. Default: the file's, else m/s^2.
time_column : str, optional
    The CSV/.mat time column, or 'none'; default the one named like a time.
fs : float, optional
    Sample rate (Hz); needed when the file gives none, overrides a CSV time column, must agree within
    0.1 % with a sound or .mat file's own.
scale : float, optional
    Physical units (of `unit`) per file unit, or per full scale of integer PCM (needed there).
skip_rows : int, optional
    CSV lines before the header; default found from the data.

Returns
-------
dict
    samples (m/s^2, shape (channels, samples): welch and bands take it as it is), sample_rate (Hz),
    rate_source (where the rate came from), channels (names), units (per channel: unit, written,
    factor (m/s^2 per unit), origin ('unit', 'name', 'units_row' or 'assumed'), where), scale,
    time_column (or None), format, file, notes (each choice made from the file, the lines
    `rollspec psd` prints on stderr).

Raises
------
ValueError
    A bad argument or file content: the command's one line (which names the options as the command
    spells them: --column for column, --unit, --scale, --fs).
OSError
    A missing or unreadable file.
)";

}  // namespace

void bind_spectra(py::module_& m) {
  using py::arg;
  const auto keys = study::SpectrumSection::keys();
  m.def("welch", &welch, kWelchDoc, arg("x"), arg("fs"), py::kw_only(), arg("segment") = 1024, arg("overlap") = 0.5,
        arg("window") = "hann", arg("detrend") = "constant");
  m.def("bands", &bands, kBandsDoc, arg("x"), arg("fs"), py::kw_only(), arg("segment") = 1024, arg("overlap") = 0.5,
        arg("window") = "hann", arg("detrend") = "constant",
        arg("band_min") = key_default(key_spec(keys, "spectrum.band_min")),
        arg("band_max") = key_default(key_spec(keys, "spectrum.band_max")),
        arg("confidence") = key_default(key_spec(keys, "spectrum.confidence")));
  m.def("read_measurement", &read_measurement, kReadMeasurementDoc, arg("path"), py::kw_only(),
        arg("column") = py::none(), arg("unit") = py::none(), arg("time_column") = py::none(), arg("fs") = py::none(),
        arg("scale") = py::none(), arg("skip_rows") = py::none());
}

}  // namespace rollspec::python
