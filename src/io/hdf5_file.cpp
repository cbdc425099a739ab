#include "src/io/hdf5_file.hpp"

#include <H5DSpublic.h>
#include <H5LTpublic.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "src/io/long_name.hpp"
#include "src/error.hpp"
#include "src/io/free_dimensions.hpp"
#include "src/io/available_memory.hpp"
#include "src/io/input_file.hpp"
#include "src/io/temp_files.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::io {

namespace {
void close_id(hid_t id) {
  if (id < 0) return;
  switch (H5Iget_type(id)) {
    case H5I_FILE:
      H5Fclose(id);
      break;
    case H5I_GROUP:
      H5Gclose(id);
      break;
    case H5I_DATASET:
      H5Dclose(id);
      break;
    case H5I_DATASPACE:
      H5Sclose(id);
      break;
    case H5I_DATATYPE:
      H5Tclose(id);
      break;
    case H5I_ATTR:
      H5Aclose(id);
      break;
    default:
      break;
  }
}

// Opens an attribute and returns its number of elements (1 for a scalar); -1 if it cannot be read.
hssize_t attribute_elements(hid_t file, const std::string& object, const std::string& name, Hdf5Handle& attr) {
  attr = Hdf5Handle(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attr.valid()) return -1;
  const Hdf5Handle space(H5Aget_space(attr.get()));
  return space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
}

herr_t collect_error(unsigned, const H5E_error2_t* e, void* text) {
  auto* s = static_cast<std::string*>(text);
  if (e->desc) *s += std::string(e->desc) + "\n";
  return 0;
}

bool g_write_failed = false;

// Why a write failed: "no space left on device" when the file system is full (the HDF5 error
// stack carries the system error), else the failing call.
std::string failure_reason(const std::string& what) {
  g_write_failed = true;
  const int saved = errno;
  std::string stack;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_error, &stack);
  if (saved == ENOSPC || stack.find("No space left on device") != std::string::npos)
    return what + ": no space left on device; free some space (or choose another --out) and rerun";
  if (saved == EDQUOT || stack.find("quota exceeded") != std::string::npos)
    return what + ": disk quota exceeded; free some space and rerun";
  if (saved == EIO) return what + ": input/output error (" + std::strerror(saved) + ")";
  return what;
}

Hdf5Handle open_object(hid_t file, const std::string& path) {
  Hdf5Handle h(H5Oopen(file, path.c_str(), H5P_DEFAULT));
  return h;
}
}  // namespace

Hdf5Handle::~Hdf5Handle() { close_id(id_); }

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& o) noexcept {
  if (this != &o) {
    close_id(id_);
    id_ = o.id_;
    o.id_ = -1;
  }
  return *this;
}

void quiet_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

bool hdf5_write_failed() { return g_write_failed; }

Hdf5Writer::Hdf5Writer(const std::string& final_path) : final_path_(final_path), temp_path_(temp_name(final_path)) {
  quiet_hdf5_errors();
  register_temp(temp_path_);
  file_ = Hdf5Handle(H5Fcreate(temp_path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  if (!file_.valid()) {
    const int saved = errno;
    std::remove(temp_path_.c_str());  // H5Fcreate may leave an empty file behind (a full disk)
    unregister_temp(temp_path_);
    throw cannot_create("cannot create output file '" + temp_path_ + "' (for " + final_path_ + ")" +
                        (saved == ENOSPC ? ": no space left on device"
                         : saved         ? std::string(": ") + std::strerror(saved)
                                         : ""));
  }
}

Hdf5Writer::~Hdf5Writer() {
  if (!committed_) {
    file_ = Hdf5Handle();
    std::remove(temp_path_.c_str());
    unregister_temp(temp_path_);
  }
}

void Hdf5Writer::ensure_parent_groups(const std::string& path) {
  for (std::size_t pos = path.find('/', 1); pos != std::string::npos; pos = path.find('/', pos + 1)) {
    const std::string g = path.substr(0, pos);
    if (H5Lexists(file_.get(), g.c_str(), H5P_DEFAULT) > 0) continue;
    Hdf5Handle h(H5Gcreate2(file_.get(), g.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (!h.valid()) throw cannot_create(failure_reason("cannot create group " + g + " in " + temp_path_));
  }
}

void Hdf5Writer::write(const std::string& path, const std::vector<std::size_t>& dims, const double* data,
                       const std::string& units, const std::string& description) {
  ensure_parent_groups(path);
  std::vector<hsize_t> d(dims.begin(), dims.end());
  if (H5LTmake_dataset_double(file_.get(), path.c_str(), static_cast<int>(d.size()), d.data(), data) < 0)
    throw cannot_create(failure_reason("cannot write dataset " + path + " to " + temp_path_));
  attribute(path, "units", units);
  if (!description.empty()) {
    attribute(path, "description", description);
    attribute(path, "long_name", long_name_of(description));
  }
}

void Hdf5Writer::write_strings(const std::string& path, const std::vector<std::string>& values,
                               const std::string& description) {
  ensure_parent_groups(path);
  Hdf5Handle type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  const hsize_t n = values.size();
  Hdf5Handle space(H5Screate_simple(1, &n, nullptr));
  Hdf5Handle set(H5Dcreate2(file_.get(), path.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  std::vector<const char*> ptrs;
  for (const auto& v : values) ptrs.push_back(v.c_str());
  if (!set.valid() || H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
    throw cannot_create(failure_reason("cannot write dataset " + path + " to " + temp_path_));
  attribute(path, "units", "1");
  if (!description.empty()) {
    attribute(path, "description", description);
    attribute(path, "long_name", long_name_of(description));
  }
}

void Hdf5Writer::make_scale(const std::string& scale, const std::string& name) {
  Hdf5Handle s = open_object(file_.get(), scale);
  if (!s.valid() || H5DSset_scale(s.get(), name.c_str()) < 0)
    throw cannot_create(failure_reason("cannot make dimension scale " + scale + " in " + temp_path_));
}

void Hdf5Writer::attach_scale(const std::string& dataset, const std::string& scale, unsigned dim) {
  Hdf5Handle d = open_object(file_.get(), dataset), s = open_object(file_.get(), scale);
  if (!d.valid() || !s.valid() || H5DSattach_scale(d.get(), s.get(), dim) < 0)
    throw cannot_create(
        failure_reason("cannot attach dimension scale " + scale + " to " + dataset + " in " + temp_path_));
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, const std::string& value) {
  // A fixed-length string attribute lives in the object header, which holds at most 64 KiB; a long
  // text (a command line of many --set, a large study) is a variable-length string in the heap.
  constexpr std::size_t kLongText = 32768;
  if (value.size() < kLongText) {
    if (H5LTset_attribute_string(file_.get(), object.c_str(), name.c_str(), value.c_str()) < 0)
      throw cannot_create(failure_reason("cannot write attribute " + object + "@" + name + " to " + temp_path_));
    return;
  }
  Hdf5Handle type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  Hdf5Handle space(H5Screate(H5S_SCALAR));
  Hdf5Handle attr(H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT));
  const char* p = value.c_str();
  if (!attr.valid() || H5Awrite(attr.get(), type.get(), &p) < 0)
    throw cannot_create(failure_reason("cannot write attribute " + object + "@" + name + " to " + temp_path_));
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, double value) {
  if (H5LTset_attribute_double(file_.get(), object.c_str(), name.c_str(), &value, 1) < 0)
    throw cannot_create(failure_reason("cannot write attribute " + object + "@" + name + " to " + temp_path_));
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, std::int64_t value) {
  long long v = value;
  if (H5LTset_attribute_long_long(file_.get(), object.c_str(), name.c_str(), &v, 1) < 0)
    throw cannot_create(failure_reason("cannot write attribute " + object + "@" + name + " to " + temp_path_));
}

void Hdf5Writer::commit() {
  if (!name_free_dimensions(file_.get()))
    throw cannot_create(
        failure_reason("cannot write " + final_path_ + " (naming the dimensions in " + temp_path_ + ")"));
  errno = 0;
  if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0)
    throw cannot_create(failure_reason("cannot write " + final_path_ + " (flushing " + temp_path_ + ")"));
  const hid_t id = file_.get();
  file_.release();
  if (H5Fclose(id) < 0)
    throw cannot_create(failure_reason("cannot write " + final_path_ + " (closing " + temp_path_ + ")"));
  // The data must be on disk before the rename makes them the result (a full disk or a crash
  // must not leave a complete-looking, empty file).
  const int fd = ::open(temp_path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int saved = errno;
    if (fd >= 0) ::close(fd);
    throw cannot_create("cannot write " + final_path_ + " (syncing " + temp_path_ +
                        "): " + (saved == ENOSPC ? "no space left on device" : std::strerror(saved)));
  }
  ::close(fd);
  // Refuse to rename onto something that is no longer a regular file (it may have changed since
  // the output was checked).
  struct stat st {};
  if (::lstat(final_path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw cannot_create("cannot create output file '" + final_path_ +
                        "': it is no longer a regular file; nothing was replaced");
  std::error_code ec;
  std::filesystem::rename(temp_path_, final_path_, ec);
  if (ec) throw cannot_create("cannot rename " + temp_path_ + " to " + final_path_ + ": " + ec.message());
  unregister_temp(temp_path_);
  committed_ = true;
}

Hdf5Reader::Hdf5Reader(const std::string& path) : path_(path) {
  quiet_hdf5_errors();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw missing_input("cannot read '" + path + "': it is a directory; expected an HDF5 file");
  require_regular_input(path, "HDF5 file");
  if (!std::filesystem::is_regular_file(path, ec)) throw missing_input("cannot open '" + path + "': no such file");
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw data_error(path + ": not an HDF5 file (or truncated); expected an HDF5 file written by rollspec");
  file_ = Hdf5Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file_.valid()) throw data_error(path + ": cannot open as HDF5 (truncated or damaged)");
}

bool Hdf5Reader::exists(const std::string& object) const {
  // Check every link along the path: H5Lexists fails on a missing intermediate group.
  for (std::size_t pos = object.find('/', 1);; pos = object.find('/', pos + 1)) {
    const std::string p = pos == std::string::npos ? object : object.substr(0, pos);
    if (H5Lexists(file_.get(), p.c_str(), H5P_DEFAULT) <= 0) return false;
    if (pos == std::string::npos) return true;
  }
}

std::vector<double> Hdf5Reader::read(const std::string& dataset, std::vector<std::size_t>* dims) const {
  if (!exists(dataset))
    throw data_error(path_ + ": no dataset " + dataset + "; expected it in a complete rollspec file");
  int rank = 0;
  if (H5LTget_dataset_ndims(file_.get(), dataset.c_str(), &rank) < 0)
    throw data_error(path_ + ": cannot read " + dataset);
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  H5T_class_t cls;
  std::size_t size = 0;
  if (H5LTget_dataset_info(file_.get(), dataset.c_str(), d.data(), &cls, &size) < 0 || cls != H5T_FLOAT)
    throw data_error(path_ + ": dataset " + dataset + " is not floating point");
  // The size first: a 1e6 x 1e6 dataset must be refused, not attempted.
  double n_values = 1.0;
  for (auto v : d) n_values *= static_cast<double>(v);
  if (n_values * sizeof(double) > available_memory()) {
    const std::string buf = io::formatted(" holds %.0f values (%.3g GiB)", n_values, n_values * 8.0 / 1073741824.0);
    throw data_error(path_ + ": dataset " + dataset + buf +
                     ", more than the memory available; allowed: a dataset that fits in memory");
  }
  std::size_t n = 1;
  for (auto v : d) n *= v;
  std::vector<double> out(n);
  if (H5LTread_dataset_double(file_.get(), dataset.c_str(), out.data()) < 0)
    throw data_error(path_ + ": cannot read dataset " + dataset + " (truncated or damaged file)");
  if (dims) dims->assign(d.begin(), d.end());
  return out;
}

std::vector<std::string> Hdf5Reader::read_strings(const std::string& dataset) const {
  if (!exists(dataset))
    throw data_error(path_ + ": no dataset " + dataset + "; expected it in a complete rollspec file");
  const Hdf5Handle set(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT));
  const Hdf5Handle ftype(set.valid() ? H5Dget_type(set.get()) : -1);
  const Hdf5Handle space(set.valid() ? H5Dget_space(set.get()) : -1);
  if (!ftype.valid() || !space.valid() || H5Tget_class(ftype.get()) != H5T_STRING ||
      H5Tis_variable_str(ftype.get()) <= 0 || H5Sget_simple_extent_ndims(space.get()) != 1)
    throw data_error(path_ + ": dataset " + dataset + " is not a list of variable-length strings");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.get(), &n, nullptr);
  Hdf5Handle mtype(H5Tcopy(H5T_C_S1));
  H5Tset_size(mtype.get(), H5T_VARIABLE);
  H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
  std::vector<char*> p(static_cast<std::size_t>(n), nullptr);
  if (n > 0 && H5Dread(set.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()) < 0)
    throw data_error(path_ + ": cannot read dataset " + dataset + " (truncated or damaged file)");
  std::vector<std::string> out;
  for (char* c : p) out.emplace_back(c ? c : "");
  if (n > 0) H5Dvlen_reclaim(mtype.get(), space.get(), H5P_DEFAULT, p.data());
  return out;
}

bool Hdf5Reader::has_attribute(const std::string& object, const std::string& name) const {
  if (object != "/" && !exists(object)) return false;
  return H5Aexists_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::string Hdf5Reader::string_attribute(const std::string& object, const std::string& name) const {
  if (!has_attribute(object, name)) throw data_error(path_ + ": missing attribute " + object + "@" + name);
  // Read through the attribute's own type: fixed-length (as rollspec writes) or variable-length
  // strings (as h5py writes), and exactly one of them (an array would overrun the buffer).
  Hdf5Handle attr;
  const hssize_t n = attribute_elements(file_.get(), object, name, attr);
  if (n < 0) throw data_error(path_ + ": cannot read attribute " + object + "@" + name);
  const Hdf5Handle ftype(H5Aget_type(attr.get()));
  if (!ftype.valid() || H5Tget_class(ftype.get()) != H5T_STRING)
    throw data_error(path_ + ": attribute " + object + "@" + name + " is not text");
  if (n != 1)
    throw data_error(path_ + ": attribute " + object + "@" + name + " holds " + std::to_string(n) +
                     " strings; expected one");
  Hdf5Handle mtype(H5Tcopy(H5T_C_S1));
  H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
  std::string s;
  if (H5Tis_variable_str(ftype.get()) > 0) {
    H5Tset_size(mtype.get(), H5T_VARIABLE);
    char* p = nullptr;
    if (H5Aread(attr.get(), mtype.get(), &p) < 0)
      throw data_error(path_ + ": cannot read attribute " + object + "@" + name);
    if (p) s = p;
    H5free_memory(p);
    return s;
  }
  const std::size_t size = H5Tget_size(ftype.get());
  H5Tset_size(mtype.get(), size + 1);
  H5Tset_strpad(mtype.get(), H5T_STR_NULLTERM);
  s.assign(size + 1, '\0');
  if (H5Aread(attr.get(), mtype.get(), s.data()) < 0)
    throw data_error(path_ + ": cannot read attribute " + object + "@" + name);
  s.resize(s.find('\0'));
  return s;
}

double Hdf5Reader::double_attribute(const std::string& object, const std::string& name) const {
  if (!has_attribute(object, name)) throw data_error(path_ + ": missing attribute " + object + "@" + name);
  Hdf5Handle attr;
  const hssize_t n = attribute_elements(file_.get(), object, name, attr);
  const Hdf5Handle ftype(attr.valid() ? H5Aget_type(attr.get()) : -1);
  if (n != 1 || !ftype.valid() || (H5Tget_class(ftype.get()) != H5T_FLOAT && H5Tget_class(ftype.get()) != H5T_INTEGER))
    throw data_error(path_ + ": attribute " + object + "@" + name + " is not one number");
  double v = 0.0;
  if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &v) < 0)
    throw data_error(path_ + ": cannot read attribute " + object + "@" + name);
  return v;
}

}  // namespace rollspec::io
