// A measured signal in a MATLAB .mat file, through matio (v4, v5 and, since Debian's matio is built
// with HDF5, v7.3). Each real numeric vector is a channel named by its variable; an N×C matrix holds C
// channels <name>_1..<name>_C, one sample per row (MATLAB's convention; a matrix wider than tall is
// skipped as probably transposed). A scalar fs / fs_hz / sample_rate / sampling_rate gives the rate, a
// vector named like a time column (t, time, time_s, t_ms, ...) gives it from the stamps. Complex,
// logical, char, struct, cell, sparse and N-d variables are not channels (skipped, listed if asked for).
#include <matio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <unordered_map>
#include <utility>

#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/io/mat_v5_layout.hpp"
#include "src/io/signal_file.hpp"
#include "src/io/time_column.hpp"

namespace rollspec::io {

namespace {
// matio reports through a log function; its messages go into our error instead of to stderr.
thread_local std::string matio_messages;

void matio_log(int level, char* message) {
  if (level > 4 || message == nullptr) return;  // errors, critical errors and warnings, not debug chatter
  if (!matio_messages.empty()) matio_messages += "; ";
  // HDF5 error stacks (v7.3) come as indented multi-line text: one line in ours.
  bool blank = false;
  for (const char* c = message; *c != '\0'; ++c) {
    const bool space = std::isspace(static_cast<unsigned char>(*c)) != 0;
    if (!space)
      matio_messages += *c;
    else if (!blank)
      matio_messages += ' ';
    blank = space;
  }
}

std::string matio_says() {
  std::string m = matio_messages;
  matio_messages.clear();
  return m.empty() ? "" : " (matio: " + clip(m, 300) + ")";
}

struct MatCloser {
  void operator()(mat_t* m) const { Mat_Close(m); }
};
struct VarFree {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};

bool is_rate_name(std::string n) {
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return n == "fs" || n == "fs_hz" || n == "sample_rate" || n == "sample_rate_hz" || n == "sampling_rate" ||
         n == "samplerate";
}

bool is_numeric(matio_classes c) { return c >= MAT_C_DOUBLE && c <= MAT_C_UINT64; }

struct VarInfo {
  std::string name;
  matio_classes cls;
  bool complex, logical;
  std::vector<std::size_t> dims;
  std::size_t rows() const { return dims.size() == 2 ? dims[0] : 0; }
  std::size_t cols() const { return dims.size() == 2 ? dims[1] : 0; }
  std::string shape() const {
    std::string s;
    for (auto d : dims) s += (s.empty() ? "" : "x") + std::to_string(d);
    return s;
  }
};

// Why a variable is not numeric data at all ("" if it is a real numeric 2-D array with elements).
std::string not_numeric(const VarInfo& v) {
  switch (v.cls) {
    case MAT_C_CELL:
      return "a cell array";
    case MAT_C_STRUCT:
      return "a struct";
    case MAT_C_OBJECT:
    case MAT_C_OPAQUE:
    case MAT_C_FUNCTION:
      return "an object";
    case MAT_C_CHAR:
      return "text (char)";
    case MAT_C_SPARSE:
      return "sparse";
    case MAT_C_EMPTY:
      return "empty";
    default:
      break;
  }
  if (!is_numeric(v.cls)) return "not numeric";
  if (v.complex) return "complex";
  if (v.logical) return "logical";
  if (v.dims.size() != 2) return std::to_string(v.dims.size()) + "-dimensional (" + v.shape() + ")";
  if (v.rows() * v.cols() == 0) return "empty (" + v.shape() + ")";
  return "";
}

template <class T>
void copy_as_double(const void* data, std::size_t n, std::vector<double>& out) {
  const T* p = static_cast<const T*>(data);
  out.assign(p, p + n);
}

// All elements, column-major, as doubles.
std::vector<double> read_values(mat_t* m, const SignalTable& s, const VarInfo& v) {
  const std::unique_ptr<matvar_t, VarFree> var(Mat_VarRead(m, v.name.c_str()));
  const std::size_t n = v.rows() * v.cols();
  if (!var || var->data == nullptr)
    throw data_error(s.file + ": cannot read variable '" + v.name + "'" + matio_says() +
                     "; allowed: an undamaged .mat file");
  std::vector<double> out;
  // The element types matio stores, each read by its own copy (a table: one row a type).
  using Copy = void (*)(const void*, std::size_t, std::vector<double>&);
  static const std::pair<matio_types, Copy> kCopies[] = {
      {MAT_T_DOUBLE, copy_as_double<double>},      {MAT_T_SINGLE, copy_as_double<float>},
      {MAT_T_INT8, copy_as_double<std::int8_t>},   {MAT_T_UINT8, copy_as_double<std::uint8_t>},
      {MAT_T_INT16, copy_as_double<std::int16_t>}, {MAT_T_UINT16, copy_as_double<std::uint16_t>},
      {MAT_T_INT32, copy_as_double<std::int32_t>}, {MAT_T_UINT32, copy_as_double<std::uint32_t>},
      {MAT_T_INT64, copy_as_double<std::int64_t>}, {MAT_T_UINT64, copy_as_double<std::uint64_t>},
  };
  const auto copy = std::find_if(std::begin(kCopies), std::end(kCopies),
                                 [&](const auto& row) { return row.first == var->data_type; });
  if (copy == std::end(kCopies))
    throw data_error(s.file + ": variable '" + v.name + "' holds data of matio type " + std::to_string(var->data_type) +
                     "; allowed: double, single or integer data");
  copy->second(var->data, n, out);
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(out[i]))
      throw data_error(s.file + ": variable '" + v.name + "' element (" + std::to_string(i % v.rows() + 1) + "," +
                       std::to_string(i / v.rows() + 1) + ") is not finite; allowed: finite samples");
  return out;
}

std::string version_name(mat_ft v) {
  switch (v) {
    case MAT_FT_MAT73:
      return "MATLAB v7.3 .mat (HDF5)";
    case MAT_FT_MAT5:
      return "MATLAB v5 .mat";
    case MAT_FT_MAT4:
      return "MATLAB v4 .mat";
    default:
      return "MATLAB .mat";
  }
}
}  // namespace

SignalTable read_mat_signal(const std::string& path, const SignalRequest& request) {
  // --time-column: the time vector by name, none, or (default) the variable named like a time
  const auto is_time = [&](const std::string& name) {
    if (request.time_column == "none") return false;
    return request.time_column.empty() ? time_column_unit(name) != 0.0 : name == request.time_column;
  };
  static const bool logging = (Mat_LogInitFunc("rollspec", matio_log), true);
  (void)logging;
  matio_messages.clear();
  const std::unique_ptr<mat_t, MatCloser> m(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!m)
    throw data_error(path + ": cannot read it as a MATLAB .mat file" + matio_says() +
                     "; allowed: MAT v4, v5 (scipy.io.savemat, MATLAB -v7) or v7.3 (MATLAB -v7.3)");
  // matio trusts a variable's dimensions over its stored data (uninitialised or cut samples).
  if (Mat_GetVersion(m.get()) == MAT_FT_MAT5) check_mat_v5_layout(path);
  SignalTable s;
  s.file = path;
  s.format = version_name(Mat_GetVersion(m.get()));
  s.unit = "as stored";
  std::vector<VarInfo> vars;
  while (matvar_t* raw = Mat_VarReadNextInfo(m.get())) {
    const std::unique_ptr<matvar_t, VarFree> v(raw);
    VarInfo info{v->name ? v->name : "", v->class_type, v->isComplex != 0, v->isLogical != 0, {}};
    for (int d = 0; d < v->rank; ++d) info.dims.push_back(v->dims[d]);
    vars.push_back(std::move(info));
  }
  if (!matio_messages.empty())
    throw data_error(path + ": cannot read the variables of this " + s.format + matio_says());

  std::string rate_var;
  for (const auto& v : vars) {
    const std::string why = not_numeric(v);
    const bool scalar = why.empty() && v.rows() * v.cols() == 1;
    const bool vector = why.empty() && !scalar && (v.rows() == 1 || v.cols() == 1);
    // A variable named like a rate or a time that cannot be one is listed, not fatal: the file may
    // still be read with --fs, and matio cannot rename variables.
    if (is_rate_name(v.name) && !scalar) {
      s.skipped.emplace_back(v.name,
                             "named like a sample rate, but " + (why.empty() ? v.shape() : why) + ", not a scalar");
    } else if (is_time(v.name) && !vector) {
      s.skipped.emplace_back(v.name,
                             "named like a time vector, but " + (why.empty() ? v.shape() : why) + ", not a vector");
    } else if (is_rate_name(v.name)) {
      const double fs = read_values(m.get(), s, v).front();
      if (!(fs > 0.0)) {
        s.skipped.emplace_back(v.name, "named like a sample rate, but " + number_text(fs) + " Hz");
        continue;
      }
      if (s.sample_rate > 0.0 && std::fabs(fs - s.sample_rate) > kRateTolerance * s.sample_rate)
        throw data_error(path + ": variable '" + v.name + "' = " + rate_text(fs) + " Hz but variable '" + rate_var +
                         "' = " + rate_text(s.sample_rate) + " Hz; allowed: one sample rate");
      s.sample_rate = fs;
      rate_var = v.name;
      s.rate_source = "variable '" + v.name + "'";
    } else if (is_time(v.name)) {
      if (!s.time_column.empty())
        throw data_error(path + ": two time variables, '" + s.time_column + "' and '" + v.name +
                         "'; allowed: at most one");
      s.time_column = v.name;
    } else if (!why.empty()) {
      s.skipped.emplace_back(v.name, why);
    } else if (scalar) {
      s.skipped.emplace_back(v.name, "a scalar");
    } else if (vector) {
      s.channels.push_back(v.name);
      s.groups.push_back(v.name);
      s.values.push_back(read_values(m.get(), s, v));
    } else if (v.cols() > v.rows()) {
      s.skipped.emplace_back(v.name, "a " + v.shape() +
                                         " matrix, wider than tall: columns are channels and rows samples, "
                                         "so it is probably transposed (store x.' in MATLAB, x.T in numpy)");
    } else {
      const auto all = read_values(m.get(), s, v);
      for (std::size_t c = 0; c < v.cols(); ++c) {
        s.channels.push_back(v.name + "_" + std::to_string(c + 1));
        s.groups.push_back(v.name);
        s.values.emplace_back(all.begin() + static_cast<std::ptrdiff_t>(c * v.rows()),
                              all.begin() + static_cast<std::ptrdiff_t>((c + 1) * v.rows()));
      }
    }
  }
  if (s.time_column.empty() && !request.time_column.empty() && request.time_column != "none") {
    std::string names;
    for (const auto& v : vars) names += (names.empty() ? "" : ", ") + v.name;
    throw usage_error("--time-column " + clip(request.time_column) + ": no such vector variable in " + path +
                      "; variables: " + clip(names, 400) + "; allowed: a real numeric vector of time stamps, or none");
  }
  if (!s.time_column.empty()) {
    const auto& tv = *std::find_if(vars.begin(), vars.end(), [&](const VarInfo& v) { return v.name == s.time_column; });
    const auto t = read_values(m.get(), s, tv);
    s.time_samples = t.size();
    // a vector picked by --time-column: the unit in its name (stamp_us), else seconds
    const double unit = time_column_unit(tv.name) != 0.0 ? time_column_unit(tv.name) : time_unit_in_name(tv.name);
    const double fs = rate_from_time_stamps(t, unit == 0.0 ? 1.0 : unit, tv.name, [&](std::size_t i) {
      return path + ": variable '" + tv.name + "' element " + std::to_string(i + 1);
    });
    if (s.sample_rate > 0.0 && std::fabs(fs - s.sample_rate) > kRateTolerance * s.sample_rate)
      throw data_error(path + ": time variable '" + tv.name + "' gives " + rate_text(fs) + " Hz but variable '" +
                       rate_var + "' = " + rate_text(s.sample_rate) + " Hz; allowed: one sample rate (within " +
                       number_text(100 * kRateTolerance) + " %)");
    if (s.sample_rate == 0.0) {
      s.sample_rate = fs;
      s.rate_source = "time variable '" + tv.name + "'";
    }
  }
  std::unordered_map<std::string, std::size_t> seen;
  for (std::size_t i = 0; i < s.channels.size(); ++i) {
    const auto [it, fresh] = seen.emplace(s.channels[i], i);
    if (!fresh)
      throw data_error(path + ": channel name '" + s.channels[i] + "' comes from variables '" + s.groups[it->second] +
                       "' and '" + s.groups[i] + "'; allowed: distinct names (a matrix x gives x_1, x_2, ...)");
  }
  return s;
}

}  // namespace rollspec::io
