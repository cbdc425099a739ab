// The Python module rollspec._core (imported by the package rollspec): its submodules, the errors it
// raises, and the array and key helpers of bindings.hpp.
#include <cmath>
#include <cstdlib>

#include "python/bindings.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::python {

Array finite_array(const py::handle& value, const std::string& name, py::ssize_t ndim, py::ssize_t min_side,
                   const std::string& what) {
  const std::string allowed = "; allowed: " + what;
  const py::array raw = py::array::ensure(value);
  if (!raw) throw py::value_error(name + ": not an array of numbers" + allowed);
  const char kind = raw.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error(name + ": an array of dtype " + py::str(raw.dtype()).cast<std::string>() + allowed);
  if (raw.ndim() != ndim) throw py::value_error(name + ": " + std::to_string(raw.ndim()) + " dimension(s)" + allowed);
  for (py::ssize_t d = 0; d < ndim; ++d)
    if (raw.shape(d) < min_side)
      throw py::value_error(
          name + ": shape " +
          py::str(py::tuple(py::cast(std::vector<py::ssize_t>(raw.shape(), raw.shape() + ndim)))).cast<std::string>() +
          ", a side under " + std::to_string(min_side) + allowed);
  Array a = Array::ensure(raw);
  if (!a) throw py::value_error(name + ": cannot be read as float64" + allowed);
  const double* p = a.data();
  std::size_t bad = 0;
  for (py::ssize_t i = 0; i < a.size(); ++i) bad += !std::isfinite(p[i]);
  if (bad) throw py::value_error(name + ": " + io::counted(bad, "value") + " NaN or infinite" + allowed);
  return a;
}

std::string file_name(const py::handle& value, const std::string& name) {
  if (!py::isinstance<py::str>(value) && !py::isinstance<py::bytes>(value) && !py::hasattr(value, "__fspath__"))
    throw py::type_error(name + ": " + py::repr(value).cast<std::string>() + " of type " +
                         py::type::of(value).attr("__name__").cast<std::string>() +
                         "; allowed: a file name (str, bytes or os.PathLike)");
  return file_name(py::module_::import("os").attr("fsdecode")(value).cast<std::string>(), name);
}

const std::string& file_name(const std::string& file, const std::string& name) {
  if (file.find('\0') != std::string::npos)
    throw py::value_error(name + ": a name with an embedded null byte; allowed: a file name");
  return file;
}

py::array_t<double> to_numpy(std::vector<double>&& values, const std::vector<py::ssize_t>& shape) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule free_when_done(owned, [](void* v) { delete static_cast<std::vector<double>*>(v); });
  return py::array_t<double>(shape, owned->data(), free_when_done);
}

void refuse(const std::string& name, const std::string& value, const std::string& problem, const std::string& allowed) {
  throw py::value_error(name + " = " + value + ": " + problem + "; allowed: " + allowed);
}

void check_threads(std::optional<int> threads, const std::string& what) {
  if (threads && *threads < 1)
    refuse("threads", std::to_string(*threads), "fewer than one",
           "a thread count >= 1 (None: OMP_NUM_THREADS, else every core); " + what + " does not depend on it");
}

const study::KeySpec& key_spec(const std::vector<study::KeySpec>& keys, const std::string& key) {
  for (const auto& k : keys)
    if (k.full_name() == key) return k;
  throw std::logic_error("no study key " + key);  // a binding names a key the table lost: a build-time slip
}

double key_default(const study::KeySpec& spec) { return std::strtod(spec.default_value.value().c_str(), nullptr); }

double key_value(const study::KeySpec& spec, double value) {
  const std::string name = spec.key + " ([" + spec.section + "] " + spec.key + ")";
  if (std::isnan(value)) refuse(name, "nan", "NaN is not a value", spec.allowed());
  if (spec.type == study::KeyType::integer && value != std::floor(value))
    refuse(name, io::exact_text(value), "not a whole number", spec.allowed());
  const bool below = spec.min_inclusive ? value < spec.min : value <= spec.min;
  const bool above = spec.max_inclusive ? value > spec.max : value >= spec.max;
  if (below || above || !std::isfinite(value))
    refuse(name, io::significant_text(value, 12), "out of range", spec.allowed());
  return value;
}

}  // namespace rollspec::python

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  m.doc() =
      "rollspec's kernels and engine functions on numpy arrays: rollspec.spectra (Welch PSD and third-octave "
      "bands, as `rollspec psd` and the studies compute them, and the measurement files they read), "
      "rollspec.contact (the elastic and elastic-plastic half-space solve of the stiffness tables, and the "
      "tables a study writes), rollspec.surfaces (line textures and isotropic surfaces from a PSD or from measured "
      "profiles, as `rollspec texture` draws them) and "
      "rollspec.studies (a study planned and run in-process, as `rollspec plan` and `rollspec run` do, and a "
      "result compared with a measurement, as `rollspec compare` compares them). "
      "SI units throughout.";
  m.attr("__version__") = ROLLSPEC_VERSION_TEXT;
  // The engine's errors the user can act on: bad values and data are ValueError, a missing or
  // unwritable file OSError; the message is the command's one line, exit_code its exit code.
  py::register_exception_translator([](std::exception_ptr e) {
    try {
      if (e) std::rethrow_exception(e);
    } catch (const rollspec::UserError& u) {
      PyObject* type = u.exit_code() == EX_NOINPUT || u.exit_code() == EX_CANTCREAT ? PyExc_OSError : PyExc_ValueError;
      // exit_code: the command's, for a caller that stands in for it (rollspec_post.run).
      py::object error = py::reinterpret_borrow<py::object>(type)(u.what());
      error.attr("exit_code") = u.exit_code();
      PyErr_SetObject(type, error.ptr());
    }
  });
  py::module_ spectra = m.def_submodule(
      "spectra", "Welch PSD and third-octave bands of sampled signals, and the measurement reader of `rollspec psd`.");
  rollspec::python::bind_spectra(spectra);
  py::module_ contact =
      m.def_submodule("contact",
                      "Elastic and elastic-plastic contact of a rough surface on a half-space, and the stiffness, "
                      "blocked-force, equivalent-roughness and path tables a study builds.");
  rollspec::python::bind_contact(contact);
  rollspec::python::bind_tables(contact);
  py::module_ surfaces = m.def_submodule(
      "surfaces",
      "Line textures and isotropic surfaces from a roughness PSD or from measured profiles, and their PSD.");
  rollspec::python::bind_surfaces(surfaces);
  rollspec::python::bind_profiles(surfaces);
  py::module_ studies =
      m.def_submodule("studies",
                      "Studies (a file, text or a dict: Study) planned and run in-process, with the command's "
                      "bits (plan, run), their results opened as xarray (open) and compared with a measurement "
                      "(compare), and a study's keys fitted to measurements (fit).");
  rollspec::python::bind_studies(studies);
  rollspec::python::bind_compare(studies);
  rollspec::python::bind_fit(studies);
}
