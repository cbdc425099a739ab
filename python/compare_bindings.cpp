// rollspec.studies.compare and fit: a result against a measurement through the engine's own compare_result
// (src/compare/comparison.hpp, what `rollspec compare` calls after reading its options), and a study's keys
// fitted to measurements through fit_study (src/fit/fit_study.hpp, what `rollspec fit` calls), each
// returned as the object the command's `--format json` prints, parsed by Python's json: the same keys and
// values. The work runs with the interpreter lock released; a fit's Ctrl-C is KeyboardInterrupt.
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "python/bindings.hpp"
#include "src/compare/comparison.hpp"
#include "src/compare/comparison_json.hpp"
#include "src/fit/fit_json.hpp"
#include "src/fit/fit_study.hpp"

namespace rollspec::python {

namespace {

// A path (str or os.PathLike) or a sequence of them, as strings.
std::vector<std::string> path_list(const py::handle& value, const std::string& name) {
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) return {file_name(value, name)};
  std::vector<std::string> out;
  if (py::isinstance<py::sequence>(value))
    for (const auto& item : value.cast<py::sequence>()) {
      if (!py::isinstance<py::str>(item) && !py::hasattr(item, "__fspath__"))
        throw py::type_error(name + ": an item of type " + py::str(py::type::of(item)).cast<std::string>() +
                             "; allowed: a path (str or os.PathLike) or a sequence of paths");
      out.push_back(file_name(item, name));
    }
  else
    throw py::type_error(name + ": of type " + py::str(py::type::of(value)).cast<std::string>() +
                         "; allowed: a path (str or os.PathLike) or a sequence of paths");
  return out;
}

// --column: one name (or comma-separated names) or a sequence of them.
std::vector<std::string> column_list(const py::handle& value) {
  if (value.is_none()) return {};
  if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
  try {
    return value.cast<std::vector<std::string>>();
  } catch (const py::cast_error&) {
    throw py::type_error("column: " + py::repr(value).cast<std::string>() +
                         "; allowed: a channel name or a sequence of names, or None");
  }
}

py::object compare_study(const std::filesystem::path& result, const py::object& recordings,
                         const std::optional<std::filesystem::path>& noise, const std::optional<std::string>& sensor,
                         std::optional<double> measured_position, const std::optional<std::string>& point,
                         const py::object& column, const std::optional<std::string>& unit, std::optional<double> scale,
                         std::optional<double> fs, const std::optional<std::string>& time_column,
                         std::optional<long long> skip_rows, bool roll_per_channel,
                         std::optional<double> measured_averages, double noise_margin, bool keep_floor_bands,
                         bool same_surface, double fmin, std::optional<double> fmax, double test_level) {
  compare::CompareRequest q;
  q.result = result.string();
  q.measurements = path_list(recordings, "recordings");
  q.noise = noise ? noise->string() : std::string();
  q.sensor = sensor.value_or("");
  q.measured_position = measured_position;
  q.point = point.value_or("");
  q.columns = column_list(column);
  q.unit = unit.value_or("");
  q.scale = scale, q.fs = fs, q.skip_rows = skip_rows;
  q.time_column = time_column.value_or("");
  q.roll_per_channel = roll_per_channel;
  q.measured_averages = measured_averages;
  q.noise_margin_db = noise_margin;
  q.keep_floor_bands = keep_floor_bands, q.same_surface = same_surface;
  q.fmin = fmin, q.fmax = fmax.value_or(INFINITY), q.test_level = test_level;
  std::string text;
  std::vector<std::string> messages;
  {
    py::gil_scoped_release release;
    const compare::Comparison c = compare::compare_result(q);
    text = compare::comparison_json(c).dump();
    messages = c.messages;
  }
  // The command's WARNING lines on stderr are Python warnings here; its other lines are the choices made
  // reading the files (the recordings' are in measurement_notes).
  const std::string warning = "WARNING: ";
  for (const auto& line : messages)
    if (line.rfind(warning, 0) == 0 && PyErr_WarnEx(PyExc_UserWarning, line.substr(warning.size()).c_str(), 1) != 0)
      throw py::error_already_set();  // warnings turned into errors
  return py::module_::import("json").attr("loads")(text);
}

// --vary / --at / --measured-averages: one value or a sequence of them, each a str (T = std::string) or a
// real number (T = double); another type is a TypeError naming the argument.
template <class T>
std::vector<T> one_or_many(const py::handle& value, const std::string& name) {
  constexpr bool text = std::is_same_v<T, std::string>;
  const auto item = [&](const py::handle& v) {
    const bool ok = text ? py::isinstance<py::str>(v)
                         : !py::isinstance<py::str>(v) && !py::isinstance<py::bool_>(v) && PyNumber_Check(v.ptr());
    if (!ok)
      throw py::type_error(name + ": " + py::repr(v).cast<std::string>() + " of type " +
                           py::type::of(v).attr("__name__").cast<std::string>() +
                           "; allowed: " + (text ? "a str or a sequence of them" : "a number or a sequence of them"));
    return v.cast<T>();
  };
  if (value.is_none()) return {};
  if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value)) return {item(value)};
  std::vector<T> out;
  for (const auto& v : value.cast<py::sequence>()) out.push_back(item(v));
  return out;
}

py::object fit_study(const std::filesystem::path& study, const py::object& measurements, const py::object& vary,
                     const py::object& measured_averages, const py::object& at, const std::vector<std::string>& sets,
                     const std::optional<std::string>& sensor, std::optional<double> measured_position,
                     const std::optional<std::string>& column, double fmin, std::optional<double> fmax,
                     const std::optional<std::filesystem::path>& journal, bool same_surface,
                     std::optional<int> threads) {
  check_threads(threads, "the fit");
  fit::FitRequest q;
  q.study = study.string();
  q.measurements = path_list(measurements, "measurements");
  q.vary = one_or_many<std::string>(vary, "vary");
  q.averages = one_or_many<double>(measured_averages, "measured_averages");
  q.ats = one_or_many<std::string>(at, "at");
  q.sets = sets;
  q.sensor = sensor.value_or(""), q.measured_position = measured_position, q.column = column.value_or("");
  q.fmin = fmin, q.fmax = fmax.value_or(INFINITY);
  q.journal = journal ? journal->string() : std::string();
  q.same_surface = same_surface;
  fit::FitOutcome answer;
  run_interruptible([&] { answer = fit::fit_study(q); }, threads,
                    " (in Python: give journal= to keep the evaluations, and the same call goes on from them)");
  for (const auto& line : answer.warnings)  // the runs' warnings, which the command prints on stderr
    if (PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) != 0) throw py::error_already_set();
  return py::module_::import("json").attr("loads")(fit::fit_json(answer.report));
}

}  // namespace

void bind_compare(py::module_& m) {
  m.def("compare", &compare_study, py::arg("result"), py::arg("recordings"), py::kw_only(),
        py::arg("noise") = py::none(), py::arg("sensor") = py::none(), py::arg("measured_position") = py::none(),
        py::arg("point") = py::none(), py::arg("column") = py::none(), py::arg("unit") = py::none(),
        py::arg("scale") = py::none(), py::arg("fs") = py::none(), py::arg("time_column") = py::none(),
        py::arg("skip_rows") = py::none(), py::arg("roll_per_channel") = false,
        py::arg("measured_averages") = py::none(), py::arg("noise_margin") = 10.0, py::arg("keep_floor_bands") = false,
        py::arg("same_surface") = false, py::arg("fmin") = 0.0, py::arg("fmax") = py::none(),
        py::arg("test_level") = 0.05,
        R"(Compares the result file `result` with a measurement, as `rollspec compare RESULT RECORDINGS...
--format json` does, and returns the object that command prints (a dict, the same keys and values):
every third-octave band's simulated and measured level (dB re 1 (m/s^2)^2/Hz), the interval of the
simulated mean and the prediction interval for M rolls, whether the measurement is inside, the
combined test (p_value, combined_test), the level offset, warnings and references.

recordings         one path or a list: the recordings, one file per roll (CSV/text, WAV/FLAC, .mat), or
                   one PSD table (frequency_hz and a PSD column in (m/s^2)^2/Hz, e.g. `rollspec psd`'s)
noise              a recording of the rig at rest, or its PSD table: bands near its floor leave the test
sensor             a sensor name, or K of sensor_K (None: sensor_mean if present, else the first)
measured_position  m: the sensor nearest it (instead of sensor)
point              the point of a sweep result: "K" (in run order) or "section.key=value[,...]"
column             the recordings' channel(s), or the PSD table's column (str or list)
unit, scale, fs, time_column, skip_rows
                   how the recordings are read, as `rollspec psd` reads them (None: from the file)
roll_per_channel   each channel of the recordings is one roll of one sensor
measured_averages  M, the independent rolls averaged into the measurement (a PSD table has none)
noise_margin       dB: bands within this of the noise leave the test
keep_floor_bands   keep bands that look like the noise floor (without noise) in the test
same_surface       the measurement was taken on the very surface the model's table was built on
fmin, fmax         Hz: the band edges compared (fmax None: no upper edge)
test_level         the level of the combined test (0 < A < 1)

The interpreter lock is released while the files are read and the verdict computed. The command's
WARNING lines (a likely unit slip, bands left out, the result's loss of contact) are Python warnings
(UserWarning) as well. Errors are the command's one line, naming the option as the command spells it:
ValueError (a bad value or data), OSError (a file missing or unreadable).)");
}

void bind_fit(py::module_& m) {
  m.def("fit", &fit_study, py::arg("study"), py::arg("measurements"), py::kw_only(), py::arg("vary"),
        py::arg("measured_averages"), py::arg("at") = py::none(), py::arg("set") = std::vector<std::string>{},
        py::arg("sensor") = py::none(), py::arg("measured_position") = py::none(), py::arg("column") = py::none(),
        py::arg("fmin") = 0.0, py::arg("fmax") = py::none(), py::arg("journal") = py::none(),
        py::arg("same_surface") = false, py::arg("threads") = py::none(),
        R"(Fits 1 to 3 study keys to measured PSDs, as `rollspec fit STUDY MEASUREMENT --vary ... --format json`
does, and returns the object that command prints (a dict, the same keys and values): each key's
estimate and 95 % profile-likelihood interval, their correlation, the objective (common random numbers
or a response surface, D-27d/D-27i), ln L, the combined test of the best fit corrected for the fitted
keys (p_value) and uncorrected, per measurement point, and the number of study runs.

study              the study file (INI)
measurements       one PSD table or a list of them (as `rollspec compare` reads them), each at its `at`
vary               "section.key=lo:hi" or "section.key=lo:hi:log" (log scale), or a list of 1 to 3
measured_averages  M, the independent records averaged into the measurement: one for all, or a list
at                 "section.key=value[,...]" per measurement: its operating point (None: one measurement)
set                ["section.key=value", ...] for every run
sensor             a sensor name, or K of sensor_K (None: sensor_mean if present, else the first)
measured_position  m: the sensor nearest it (instead of sensor)
column             the PSD column of the measurement tables
fmin, fmax         Hz: the band edges fitted (fmax None: no upper edge)
journal            a file recording every evaluation: a fit interrupted and called again with the same
                   journal reruns none it finished
same_surface       the measurement was taken on the very surface the model's table was built on (D-31)
threads            OpenMP threads of the runs (None: OMP_NUM_THREADS, else every core); the answer does not
                   depend on it

The runs go on with the interpreter lock released. Ctrl-C stops the run in progress and raises
KeyboardInterrupt (with journal=, the finished evaluations are kept). The runs' warnings (loss of contact,
a band's heavy tail) are Python warnings (UserWarning). Errors are the command's one line: ValueError (a
bad value or data), OSError (a file missing or unreadable).)");
}

}  // namespace rollspec::python
