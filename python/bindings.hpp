#pragma once
#include <functional>
#include <optional>
// What the Python module's translation units share: their binders, numpy arrays in and out, and the
// study keys whose names, defaults and ranges the module's options take (one table: the engine's).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "src/study/key_spec.hpp"

namespace rollspec::python {

namespace py = pybind11;

// C-contiguous float64: what the kernels read without a copy.
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

void bind_spectra(py::module_& m);
void bind_contact(py::module_& m);
void bind_surfaces(py::module_& m);
void bind_studies(py::module_& m);
void bind_compare(py::module_& m);
void bind_fit(py::module_& m);

// `work` (an engine call that may run ensembles) in a worker thread with the interpreter lock released, on
// `threads` OpenMP threads (None: the process's); a Ctrl-C stops its ensembles between realisations as the
// command's SIGINT does, and raises KeyboardInterrupt with the engine's line and `hint` (how to go on).
void run_interruptible(const std::function<void()>& work, std::optional<int> threads, const std::string& hint);
void bind_profiles(py::module_& surfaces);
void bind_tables(py::module_& contact);

// `value` as C-contiguous float64 (the same object when it is one already), refused with ValueError
// "NAME: ...; allowed: WHAT" unless it is a real numeric array of `ndim` dimensions (a 1-D `value` where
// `ndim` is 2 is refused too), every side >= `min_side`, every value finite.
Array finite_array(const py::handle& value, const std::string& name, py::ssize_t ndim, py::ssize_t min_side,
                   const std::string& what);

// The file name `value` (str, bytes or os.PathLike) as the C library takes it; a name with a NUL byte,
// which the C library would read cut at the NUL (another file), is a ValueError naming `name`, another
// type a TypeError.
std::string file_name(const py::handle& value, const std::string& name);
// `file` (a str argument pybind11 converted), refused as file_name refuses a NUL byte.
const std::string& file_name(const std::string& file, const std::string& name);

// A numpy array that owns `values` (moved, not copied), of the given shape.
py::array_t<double> to_numpy(std::vector<double>&& values, const std::vector<py::ssize_t>& shape);

// ValueError "NAME = VALUE: PROBLEM; allowed: WHAT", the command's one-line style.
[[noreturn]] void refuse(const std::string& name, const std::string& value, const std::string& problem,
                         const std::string& allowed);

// threads = None or >= 1, else refuse() saying that `what` (the result, the fit, the table) does not depend on it.
void check_threads(std::optional<int> threads, const std::string& what);

// The value of `table` spelled `text`, or refuse() naming `name` and every spelling.
template <class E, std::size_t N>
E choice(const study::ChoiceTable<E, N>& table, const std::string& name, const std::string& text) {
  std::string allowed;
  for (const auto& c : table) {
    if (text == c.spelling) return c.value;
    allowed += (allowed.empty() ? "" : ", ") + std::string(c.spelling);
  }
  refuse(name, "'" + text + "'", "unknown", allowed);
}

// The key `section.key` of a section's key table (StiffnessSection::keys(), ...).
const study::KeySpec& key_spec(const std::vector<study::KeySpec>& keys, const std::string& key);
// Its default as a number.
double key_default(const study::KeySpec& spec);
// `value` checked against the key's range as a study's value is (refuse() naming the key, with the key's
// own `allowed` text); returns it.
double key_value(const study::KeySpec& spec, double value);

}  // namespace rollspec::python
