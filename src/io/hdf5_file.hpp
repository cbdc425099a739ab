#pragma once
// Thin RAII layer over the HDF5 C API and its high-level H5LT / H5DS interfaces.
//
// Hdf5Writer writes to "<final>.tmp-<pid>" and renames onto the final name in commit(), so a
// result file either is complete or does not exist; an uncommitted writer removes its
// temporary file. Every dataset carries a `units` attribute. Dimension scales (H5DS) give
// the datasets named dimensions for h5py and xarray (h5netcdf).
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rollspec::io {

// Owns one HDF5 identifier and closes it with the right H5*close.
class Hdf5Handle {
 public:
  Hdf5Handle() = default;
  explicit Hdf5Handle(hid_t id) : id_(id) {}
  ~Hdf5Handle();
  Hdf5Handle(Hdf5Handle&& o) noexcept : id_(o.id_) { o.id_ = -1; }
  Hdf5Handle& operator=(Hdf5Handle&& o) noexcept;
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  hid_t get() const { return id_; }
  hid_t release() {
    const hid_t id = id_;
    id_ = -1;
    return id;
  }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_ = -1;
};

// Silences HDF5's own error printing; rollspec reports errors itself.
void quiet_hdf5_errors();

// True once a write to an HDF5 file failed (e.g. a full disk). The library then still holds the
// file whose close failed, and its exit-time cleanup (H5_term_library) can crash on it, so main()
// leaves with _exit after reporting the error.
bool hdf5_write_failed();

class Hdf5Writer {
 public:
  explicit Hdf5Writer(const std::string& final_path);
  ~Hdf5Writer();
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  void write(const std::string& path, const std::vector<std::size_t>& dims, const double* data,
             const std::string& units, const std::string& description = "");
  void write_strings(const std::string& path, const std::vector<std::string>& values,
                     const std::string& description = "");
  // Makes dataset `scale` a dimension scale named `name` and attaches it to dimension `dim` of `dataset`.
  void make_scale(const std::string& scale, const std::string& name);
  void attach_scale(const std::string& dataset, const std::string& scale, unsigned dim);
  void attribute(const std::string& object, const std::string& name, const std::string& value);
  void attribute(const std::string& object, const std::string& name, double value);
  void attribute(const std::string& object, const std::string& name, std::int64_t value);
  void commit();

 private:
  void ensure_parent_groups(const std::string& path);
  std::string final_path_, temp_path_;
  Hdf5Handle file_;
  bool committed_ = false;
};

class Hdf5Reader {
 public:
  // Opens read-only. Missing file: exit 66; not HDF5 / truncated / unreadable: exit 65.
  explicit Hdf5Reader(const std::string& path);
  const std::string& path() const { return path_; }
  bool exists(const std::string& object) const;
  std::vector<double> read(const std::string& dataset, std::vector<std::size_t>* dims = nullptr) const;
  // A one-dimensional dataset of variable-length strings (as write_strings makes, e.g. sensor names).
  std::vector<std::string> read_strings(const std::string& dataset) const;
  std::string string_attribute(const std::string& object, const std::string& name) const;
  double double_attribute(const std::string& object, const std::string& name) const;
  bool has_attribute(const std::string& object, const std::string& name) const;

 private:
  std::string path_;
  Hdf5Handle file_;
};

}  // namespace rollspec::io
