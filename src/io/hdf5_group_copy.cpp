#include "src/io/hdf5_group_copy.hpp"

#include <H5DSpublic.h>

#include <set>
#include <vector>

#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"

namespace rollspec::io {

namespace {

void check(bool ok, const std::string& what) {
  if (!ok) throw cannot_create("cannot write the sweep result: copying " + what);
}

herr_t collect(hid_t group, const char* name, const H5L_info_t*, void* out) {
  Hdf5Handle o(H5Oopen(group, name, H5P_DEFAULT));
  if (o.valid() && H5Iget_type(o.get()) == H5I_DATASET) static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

herr_t scale_path(hid_t, unsigned, hid_t scale, void* out) {
  char name[1024] = {0};
  H5Iget_name(scale, name, sizeof name);
  *static_cast<std::string*>(out) = name;
  return 1;
}

bool is_variable(hid_t type) { return H5Tis_variable_str(type) > 0 || H5Tdetect_class(type, H5T_VLEN) > 0; }

herr_t copy_attribute(hid_t from, const char* name, const H5A_info_t*, void* to_ptr) {
  static const std::set<std::string> kept_by_scales = {"DIMENSION_LIST", "REFERENCE_LIST", "CLASS", "NAME"};
  if (kept_by_scales.count(name)) return 0;
  Hdf5Handle a(H5Aopen(from, name, H5P_DEFAULT));
  Hdf5Handle type(H5Aget_type(a.get())), space(H5Aget_space(a.get()));
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get()));
  std::vector<char> buf(n * H5Tget_size(type.get()) + 1);
  if (H5Aread(a.get(), type.get(), buf.data()) < 0) return -1;
  Hdf5Handle b(H5Acreate2(*static_cast<hid_t*>(to_ptr), name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  const herr_t w = b.valid() ? H5Awrite(b.get(), type.get(), buf.data()) : -1;
  if (is_variable(type.get())) H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, buf.data());
  return w < 0 ? -1 : 0;
}

void copy_dataset(hid_t from, const std::string& source, hid_t to, const std::string& target) {
  Hdf5Handle a(H5Dopen2(from, source.c_str(), H5P_DEFAULT));
  Hdf5Handle type(H5Dget_type(a.get())), space(H5Dget_space(a.get()));
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get()));
  std::vector<char> buf(n * H5Tget_size(type.get()) + 1);
  check(H5Dread(a.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) >= 0, source);
  Hdf5Handle lcpl(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(lcpl.get(), 1);
  Hdf5Handle b(H5Dcreate2(to, target.c_str(), type.get(), space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT));
  const herr_t w = b.valid() ? H5Dwrite(b.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) : -1;
  if (is_variable(type.get())) H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, buf.data());
  check(w >= 0, source);
  check(copy_attributes(a.get(), b.get()), source);
}

}  // namespace

bool copy_attributes(hid_t from, hid_t to) {
  return H5Aiterate2(from, H5_INDEX_NAME, H5_ITER_INC, nullptr, copy_attribute, &to) >= 0;
}

std::string attached_scale(hid_t d, unsigned dim) {
  std::string scale;
  H5DSiterate_scales(d, dim, nullptr, scale_path, &scale);
  return scale;
}

void copy_group(hid_t from, const std::string& group, hid_t to, const std::string& to_group) {
  Hdf5Handle g(H5Gopen2(from, group.c_str(), H5P_DEFAULT));
  check(g.valid(), group);
  std::vector<std::string> names;
  H5Lvisit(g.get(), H5_INDEX_NAME, H5_ITER_INC, collect, &names);
  for (const auto& n : names) copy_dataset(from, group + "/" + n, to, to_group + "/" + n);
  // Scales first, then the attachments (a scale may be attached to datasets listed before it).
  for (const auto& n : names) {
    Hdf5Handle a(H5Dopen2(from, (group + "/" + n).c_str(), H5P_DEFAULT));
    if (H5DSis_scale(a.get()) <= 0) continue;
    char label[256] = {0};
    H5DSget_scale_name(a.get(), label, sizeof label);
    Hdf5Handle b(H5Dopen2(to, (to_group + "/" + n).c_str(), H5P_DEFAULT));
    check(H5DSset_scale(b.get(), label) >= 0, group + "/" + n);
  }
  for (const auto& n : names) {
    Hdf5Handle a(H5Dopen2(from, (group + "/" + n).c_str(), H5P_DEFAULT));
    if (H5DSis_scale(a.get()) > 0) continue;
    Hdf5Handle space(H5Dget_space(a.get()));
    const int rank = H5Sget_simple_extent_ndims(space.get());
    for (int d = 0; d < rank; ++d) {
      const std::string scale = attached_scale(a.get(), static_cast<unsigned>(d));
      if (scale.rfind(group + "/", 0) != 0) continue;  // a scale outside the group is not copied
      Hdf5Handle b(H5Dopen2(to, (to_group + "/" + n).c_str(), H5P_DEFAULT));
      Hdf5Handle s(H5Dopen2(to, (to_group + scale.substr(group.size())).c_str(), H5P_DEFAULT));
      check(H5DSattach_scale(b.get(), s.get(), static_cast<unsigned>(d)) >= 0, group + "/" + n);
    }
  }
}

}  // namespace rollspec::io
