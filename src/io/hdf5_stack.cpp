#include "src/io/hdf5_stack.hpp"

#include <hdf5.h>  // before its high-level interfaces

#include <H5DSpublic.h>
#include <H5LTpublic.h>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>

#include "src/io/long_name.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/hdf5_group_copy.hpp"
#include "src/io/temp_files.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::io {

namespace fs = std::filesystem;

namespace {

// One dataset of one input: shape, kind and contents (bytes in the native type, or the strings).
struct Data {
  std::vector<hsize_t> dims;
  bool scale = false, vlen = false;
  std::vector<char> bytes;
  std::vector<std::string> strings;
  bool same_values(const Data& o) const { return bytes == o.bytes && strings == o.strings; }
};

void check(bool ok, const std::string& what) {
  if (!ok) throw cannot_create("cannot write the sweep result: " + what);
}

herr_t collect_dataset(hid_t group, const char* name, const H5L_info_t*, void* out) {
  Hdf5Handle o(H5Oopen(group, name, H5P_DEFAULT));
  if (o.valid() && H5Iget_type(o.get()) == H5I_DATASET)
    static_cast<std::vector<std::string>*>(out)->push_back(std::string("/") + name);
  return 0;
}

herr_t collect_group(hid_t group, const char* name, const H5L_info_t*, void* out) {
  Hdf5Handle o(H5Oopen(group, name, H5P_DEFAULT));
  if (o.valid() && H5Iget_type(o.get()) == H5I_GROUP)
    static_cast<std::vector<std::string>*>(out)->push_back(std::string("/") + name);
  return 0;
}

std::vector<std::string> objects(hid_t file, H5L_iterate_t op) {
  std::vector<std::string> out;
  H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, op, &out);
  return out;
}

Hdf5Handle open_file(const std::string& path, unsigned flags) {
  Hdf5Handle f(H5Fopen(path.c_str(), flags, H5P_DEFAULT));
  if (!f.valid()) throw data_error("cannot open sweep point result " + path);
  return f;
}

Data read_data(hid_t file, const std::string& path) {
  Data d;
  Hdf5Handle set(H5Dopen2(file, path.c_str(), H5P_DEFAULT));
  if (!set.valid()) return d;
  Hdf5Handle type(H5Dget_type(set.get())), space(H5Dget_space(set.get()));
  d.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), d.dims.data(), nullptr);
  d.scale = H5DSis_scale(set.get()) > 0;
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get()));
  if (H5Tget_class(type.get()) == H5T_STRING && H5Tis_variable_str(type.get()) > 0) {
    d.vlen = true;
    Hdf5Handle mem(H5Tcopy(H5T_C_S1));
    H5Tset_size(mem.get(), H5T_VARIABLE);
    // In the file's character set (rollspec writes UTF-8), as Hdf5Reader reads strings: with an ASCII
    // memory type HDF5 1.10 read the first file and then refused the next ("no appropriate function for
    // conversion path") in a process that had run a fit in-process, and the names looked changed.
    H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
    std::vector<char*> ptrs(n, nullptr);
    if (n && H5Dread(set.get(), mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) >= 0) {
      for (char* p : ptrs) d.strings.emplace_back(p ? p : "");
      H5Dvlen_reclaim(mem.get(), space.get(), H5P_DEFAULT, ptrs.data());
    }
    return d;
  }
  Hdf5Handle mem(H5Tget_native_type(type.get(), H5T_DIR_ASCEND));
  d.bytes.resize(n * H5Tget_size(mem.get()));
  if (n) H5Dread(set.get(), mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, d.bytes.data());
  return d;
}

std::string top_group(const std::string& path) { return path.substr(0, path.find('/', 1)); }

// Why `b` cannot be stacked with `a` (naming the dataset), or "". A dataset whose shape, coordinate
// or names change outside the groups that must stack puts its top-level group in `per_point`.
std::string difference(hid_t a, hid_t b, const std::string& name_b, const std::vector<std::string>& must_stack,
                       std::set<std::string>* per_point) {
  const auto sa = objects(a, collect_dataset), sb = objects(b, collect_dataset);
  if (sa != sb) return name_b + " holds other datasets than the first point";
  for (const auto& p : sa) {
    const Data x = read_data(a, p), y = read_data(b, p);
    std::string why;
    if (x.dims != y.dims) why = "changes the shape of " + p + " (not one array over the points)";
    if (why.empty() && x.scale && !x.same_values(y))
      why = "changes the coordinate " + p + " (its values differ between points)";
    if (why.empty() && x.vlen && !x.same_values(y)) why = "changes the names in " + p;
    if (why.empty()) continue;
    const std::string g = top_group(p);
    bool must = g == p;
    for (const auto& m : must_stack) must = must || m == g;
    if (must) return why;
    if (per_point) per_point->insert(g);
  }
  return "";
}

void string_attribute(hid_t file, const std::string& object, const std::string& name, const std::string& value) {
  if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) > 0)
    H5Adelete_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT);
  if (value.size() < 32768) {
    check(H5LTset_attribute_string(file, object.c_str(), name.c_str(), value.c_str()) >= 0, object + "@" + name);
    return;
  }
  Hdf5Handle type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  Hdf5Handle space(H5Screate(H5S_SCALAR));
  Hdf5Handle attr(H5Acreate_by_name(file, object.c_str(), name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT));
  const char* p = value.c_str();
  check(attr.valid() && H5Awrite(attr.get(), type.get(), &p) >= 0, object + "@" + name);
}

// A one-dimensional dataset of an axis' values with units and description.
void write_values(hid_t file, const std::string& path, const StackAxis& axis) {
  const bool numbers = !axis.numbers.empty();
  const hsize_t n = numbers ? axis.numbers.size() : axis.texts.size();
  Hdf5Handle space(H5Screate_simple(1, &n, nullptr));
  Hdf5Handle type(numbers ? H5Tcopy(H5T_IEEE_F64LE) : H5Tcopy(H5T_C_S1));
  if (!numbers) H5Tset_size(type.get(), H5T_VARIABLE);
  Hdf5Handle set(H5Dcreate2(file, path.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  std::vector<const char*> ptrs;
  for (const auto& t : axis.texts) ptrs.push_back(t.c_str());
  const herr_t w = numbers ? H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, axis.numbers.data())
                           : H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data());
  check(set.valid() && w >= 0, "dataset " + path);
  string_attribute(file, path, "units", axis.units);
  string_attribute(file, path, "description", axis.description);
  string_attribute(file, path, "long_name", long_name_of(axis.description));
}

herr_t attribute_name(hid_t, const char* name, const H5A_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

// One scalar attribute of one input: a number, a text, absent (NaN / ""), or something else.
struct AttributeValue {
  enum Kind { absent, is_number, is_text, other } kind = absent;
  double number = std::numeric_limits<double>::quiet_NaN();
  std::string text;
};

AttributeValue read_attribute(hid_t file, const std::string& object, const std::string& name) {
  AttributeValue v;
  if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return v;
  Hdf5Handle a(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
  Hdf5Handle type(H5Aget_type(a.get())), space(H5Aget_space(a.get()));
  const H5T_class_t c = H5Tget_class(type.get());
  v.kind = AttributeValue::other;
  if (H5Sget_simple_extent_npoints(space.get()) != 1) return v;
  if (c == H5T_FLOAT || c == H5T_INTEGER) {
    if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v.number) >= 0) v.kind = AttributeValue::is_number;
  } else if (c == H5T_STRING && H5Tis_variable_str(type.get()) > 0) {
    char* p = nullptr;
    if (H5Aread(a.get(), type.get(), &p) >= 0) v.kind = AttributeValue::is_text, v.text = p ? p : "";
    H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, &p);
  } else if (c == H5T_STRING) {
    std::vector<char> buf(H5Tget_size(type.get()) + 1, '\0');
    if (H5Aread(a.get(), type.get(), buf.data()) >= 0) v.kind = AttributeValue::is_text, v.text = buf.data();
  }
  return v;
}

struct Stacker {
  const StackRequest& q;
  hid_t file;
  std::set<std::string> made;  // axis scales and coordinates written so far

  std::vector<hsize_t> lead() const {
    std::vector<hsize_t> n;
    for (const auto& a : q.axes) n.push_back(a.numbers.empty() ? a.texts.size() : a.numbers.size());
    return n;
  }

  // group/name holding the axis (or coordinate) values, made once per group.
  std::string values_in(const std::string& group, const StackAxis& axis, bool scale) {
    const std::string path = (group == "/" ? "" : group) + "/" + axis.name;
    if (made.insert(path).second) {
      if (H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0)
        throw data_error("cannot stack the sweep: " + path + " exists in the point results; the sweep axis " +
                         axis.name + " needs that name");
      write_values(file, path, axis);
      if (scale) {
        Hdf5Handle s(H5Dopen2(file, path.c_str(), H5P_DEFAULT));
        check(H5DSset_scale(s.get(), axis.name.c_str()) >= 0, "dimension scale " + path);
      }
    }
    return path;
  }

  void attach(const std::string& dataset, const std::string& scale, unsigned dim) {
    Hdf5Handle d(H5Dopen2(file, dataset.c_str(), H5P_DEFAULT)), s(H5Dopen2(file, scale.c_str(), H5P_DEFAULT));
    check(H5DSattach_scale(d.get(), s.get(), dim) >= 0, "scale " + scale + " of " + dataset);
  }

  void restack(const std::string& path, const std::vector<Data>& points) {
    const std::string old = path + "__point0";
    check(H5Lmove(file, path.c_str(), file, old.c_str(), H5P_DEFAULT, H5P_DEFAULT) >= 0, "dataset " + path);
    Hdf5Handle from(H5Dopen2(file, old.c_str(), H5P_DEFAULT));
    const auto rank = points.front().dims.size();
    std::vector<std::string> scales(rank);
    for (unsigned d = 0; d < rank; ++d) scales[d] = attached_scale(from.get(), d);
    std::vector<hsize_t> dims = lead();
    const auto axes = dims.size();
    dims.insert(dims.end(), points.front().dims.begin(), points.front().dims.end());
    std::vector<char> all;
    for (const auto& p : points) all.insert(all.end(), p.bytes.begin(), p.bytes.end());
    Hdf5Handle type(H5Dget_type(from.get())), mem(H5Tget_native_type(type.get(), H5T_DIR_ASCEND));
    Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
    Hdf5Handle to(H5Dcreate2(file, path.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    check(to.valid() && H5Dwrite(to.get(), mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()) >= 0,
          "dataset " + path);
    check(copy_attributes(from.get(), to.get()), "attributes of " + path);
    for (unsigned d = 0; d < rank; ++d)
      if (!scales[d].empty()) {
        Hdf5Handle s(H5Dopen2(file, scales[d].c_str(), H5P_DEFAULT));
        H5DSdetach_scale(from.get(), s.get(), d);
      }
    to = Hdf5Handle();
    from = Hdf5Handle();
    check(H5Ldelete(file, old.c_str(), H5P_DEFAULT) >= 0, "dataset " + old);
    const std::string group = fs::path(path).parent_path().string();
    for (unsigned k = 0; k < axes; ++k) attach(path, values_in(group, q.axes[k], true), k);
    for (unsigned d = 0; d < rank; ++d)
      if (!scales[d].empty()) attach(path, scales[d], d + static_cast<unsigned>(axes));
    std::string coords;
    for (const auto& c : q.coordinates) {
      const std::string p = values_in(group, c, false);
      if (made.insert(p + "@attached").second) attach(p, values_in(group, q.axes[0], true), 0);
      coords += (coords.empty() ? "" : " ") + c.name;
    }
    if (!coords.empty()) {
      if (H5Aexists_by_name(file, path.c_str(), "coordinates", H5P_DEFAULT) > 0) {
        char buf[4096] = {0};
        if (H5LTget_attribute_string(file, path.c_str(), "coordinates", buf) >= 0)
          coords = std::string(buf) + " " + coords;
      }
      string_attribute(file, path, "coordinates", coords);
    }
  }

  // Group attributes that differ between points (a swept key echoed there, a warning of one point)
  // become one value per point, in point order (a number missing at a point: NaN; a text: "").
  // The root's texts (study, command line, creation time) are the sweep's own.
  void group_attributes(const std::vector<Hdf5Handle>& inputs) {
    auto groups = objects(file, collect_group);
    groups.insert(groups.begin(), "/");
    for (const auto& g : groups) {
      std::set<std::string> names;
      for (const auto& in : inputs) {
        std::vector<std::string> here;
        Hdf5Handle grp(H5Gopen2(in.get(), g.c_str(), H5P_DEFAULT));
        if (grp.valid()) H5Aiterate2(grp.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, attribute_name, &here);
        names.insert(here.begin(), here.end());
      }
      Hdf5Handle grp(H5Gopen2(file, g.c_str(), H5P_DEFAULT));
      if (!grp.valid()) continue;
      for (const auto& name : names) point_attribute(grp.get(), g, name, inputs);
    }
  }

  void point_attribute(hid_t grp, const std::string& g, const std::string& name,
                       const std::vector<Hdf5Handle>& inputs) {
    std::vector<double> numbers;
    std::vector<std::string> texts;
    bool numeric = true, text = true;
    for (const auto& in : inputs) {
      const AttributeValue v = read_attribute(in.get(), g, name);
      numeric = numeric && v.kind != AttributeValue::is_text && v.kind != AttributeValue::other;
      text = text && v.kind != AttributeValue::is_number && v.kind != AttributeValue::other;
      numbers.push_back(v.number);
      texts.push_back(v.text);
    }
    bool same = true;
    for (std::size_t i = 1; i < inputs.size(); ++i)
      same = same && texts[i] == texts[0] && std::memcmp(&numbers[i], &numbers[0], sizeof(double)) == 0;
    if (same || (!numeric && !text) || (text && g == "/")) return;
    if (H5Aexists(grp, name.c_str()) > 0) H5Adelete(grp, name.c_str());
    const hsize_t n = inputs.size();
    Hdf5Handle s(H5Screate_simple(1, &n, nullptr));
    Hdf5Handle type(numeric ? H5Tcopy(H5T_IEEE_F64LE) : H5Tcopy(H5T_C_S1));
    if (!numeric) H5Tset_size(type.get(), H5T_VARIABLE);
    Hdf5Handle b(H5Acreate2(grp, name.c_str(), type.get(), s.get(), H5P_DEFAULT, H5P_DEFAULT));
    std::vector<const char*> ptrs;
    for (const auto& t : texts) ptrs.push_back(t.c_str());
    const herr_t w =
        numeric ? H5Awrite(b.get(), H5T_NATIVE_DOUBLE, numbers.data()) : H5Awrite(b.get(), type.get(), ptrs.data());
    check(b.valid() && w >= 0, g + "@" + name);
  }

  void sweep_group() {
    Hdf5Handle g(H5Lexists(file, "/sweep", H5P_DEFAULT) > 0
                     ? H5Gopen2(file, "/sweep", H5P_DEFAULT)
                     : H5Gcreate2(file, "/sweep", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    check(g.valid(), "group /sweep");
    string_attribute(file, "/sweep", "mode", q.mode);
    std::string keys;
    for (const auto& a : q.axes) keys += (keys.empty() ? "" : ", ") + a.name;
    for (const auto& a : q.coordinates) keys += ", " + a.name;
    string_attribute(file, "/sweep", "keys", keys);
    for (const auto& a : q.axes) values_in("/sweep", a, true);
    for (const auto& c : q.coordinates) attach(values_in("/sweep", c, false), values_in("/sweep", q.axes[0], true), 0);
  }
};

std::string point_group(std::size_t i) { return io::formatted("/sweep/point_%04zu", i); }

// Removes the temporary file unless the stacked file was renamed onto the output.
struct TempFile {
  std::string path;
  bool kept = false;
  explicit TempFile(std::string p) : path(std::move(p)) { register_temp(path); }
  ~TempFile() {
    std::error_code ec;
    if (!kept) fs::remove(path, ec);
    unregister_temp(path);
  }
};

}  // namespace

std::string stack_difference(const std::string& first, const std::string& point,
                             const std::vector<std::string>& must_stack) {
  const Hdf5Handle a = open_file(first, H5F_ACC_RDONLY), b = open_file(point, H5F_ACC_RDONLY);
  return difference(a.get(), b.get(), point, must_stack, nullptr);
}

void stack_results(const StackRequest& q, const std::string& out) {
  quiet_hdf5_errors();
  std::vector<Hdf5Handle> inputs;
  for (const auto& p : q.inputs) inputs.push_back(open_file(p, H5F_ACC_RDONLY));
  std::set<std::string> per_point;
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    const std::string why = difference(inputs[0].get(), inputs[i].get(), q.inputs[i], q.must_stack, &per_point);
    if (!why.empty()) throw config_error(q.what + " " + why + "; allowed: keys that keep every dataset's shape");
  }
  TempFile temp(temp_name(out));
  fs::copy_file(q.inputs[0], temp.path, fs::copy_options::overwrite_existing);
  {
    Hdf5Handle file = open_file(temp.path, H5F_ACC_RDWR);
    Stacker s{q, file.get(), {}};
    for (const auto& g : per_point) {
      check(H5Ldelete(file.get(), g.c_str(), H5P_DEFAULT) >= 0, "group " + g);
      for (std::size_t i = 0; i < inputs.size(); ++i) copy_group(inputs[i].get(), g, file.get(), point_group(i) + g);
    }
    for (const auto& path : objects(inputs[0].get(), collect_dataset)) {
      if (per_point.count(top_group(path))) continue;
      std::vector<Data> points;
      for (const auto& in : inputs) points.push_back(read_data(in.get(), path));
      bool same = true;
      for (const auto& p : points) same = same && p.same_values(points.front());
      if (!same) s.restack(path, points);
    }
    s.group_attributes(inputs);
    string_attribute(file.get(), "/", "study", q.study_text);
    s.sweep_group();
    check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL) >= 0, temp.path);
  }
  inputs.clear();
  std::error_code ec;
  fs::rename(temp.path, out, ec);
  if (ec) throw cannot_create("cannot write the sweep result " + out + ": " + ec.message());
  temp.kept = true;
}

}  // namespace rollspec::io
