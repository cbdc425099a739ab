#include "src/io/free_dimensions.hpp"

#include <H5DSpublic.h>
#include <H5LTpublic.h>

#include <string>
#include <vector>

namespace rollspec::io {

namespace {

herr_t collect_dataset(hid_t, const char* name, const H5O_info_t* info, void* out) {
  if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(out)->push_back(std::string("/") + name);
  return 0;
}

struct Closer {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Closer() {
    if (id >= 0) close(id);
  }
};

}  // namespace

bool name_free_dimensions(hid_t file) {
  std::vector<std::string> datasets;
  if (H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_NATIVE, collect_dataset, &datasets, H5O_INFO_BASIC) < 0) return false;
  for (const auto& path : datasets) {
    const Closer d{H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose};
    if (d.id < 0) return false;
    if (H5DSis_scale(d.id) > 0) continue;
    const Closer space{H5Dget_space(d.id), H5Sclose};
    const int rank = H5Sget_simple_extent_ndims(space.id);
    if (rank <= 0) continue;  // a true scalar has no axis to name
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
    const std::size_t slash = path.rfind('/');
    const std::string group = path.substr(0, slash), base = path.substr(slash + 1);
    for (int k = 0; k < rank; ++k) {
      if (H5DSget_num_scales(d.id, static_cast<unsigned>(k)) > 0) continue;
      const std::string name = base + (rank == 1 ? "_index" : "_dim" + std::to_string(k));
      const std::string scale = group + "/" + name;
      std::vector<double> index(dims[static_cast<std::size_t>(k)]);
      for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<double>(i);
      const hsize_t n = index.size();
      if (H5LTmake_dataset_double(file, scale.c_str(), 1, &n, index.data()) < 0 ||
          H5LTset_attribute_string(file, scale.c_str(), "units", "1") < 0 ||
          H5LTset_attribute_string(file, scale.c_str(), "description",
                                   ("index along axis " + std::to_string(k) + " of " + base).c_str()) < 0 ||
          H5LTset_attribute_string(file, scale.c_str(), "long_name",
                                   ("index along axis " + std::to_string(k) + " of " + base).c_str()) < 0)
        return false;
      const Closer s{H5Dopen2(file, scale.c_str(), H5P_DEFAULT), H5Dclose};
      if (s.id < 0 || H5DSset_scale(s.id, name.c_str()) < 0 ||
          H5DSattach_scale(d.id, s.id, static_cast<unsigned>(k)) < 0)
        return false;
    }
  }
  return true;
}

}  // namespace rollspec::io
