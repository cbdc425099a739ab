#pragma once
// Copying a group of HDF5 datasets from one file into another with their attributes and dimension
// scales. H5Ocopy across files drops the scales' object references (h5netcdf then fails); here each
// scale is made again in the copy and attached to the copied datasets.
#include <hdf5.h>

#include <string>

namespace rollspec::io {

// Copies every dataset under `group` of `from` (an absolute path) to `to_group` of `to` (made with
// its parents). Throws cannot_create if HDF5 refuses a step.
void copy_group(hid_t from, const std::string& group, hid_t to, const std::string& to_group);

// Copies the attributes of object `from` to object `to`, except those the dimension-scale API keeps
// (DIMENSION_LIST, REFERENCE_LIST, CLASS, NAME). False if HDF5 refuses one.
bool copy_attributes(hid_t from, hid_t to);

// The path of the first dimension scale attached to axis `dim` of dataset `d` ("" if none).
std::string attached_scale(hid_t d, unsigned dim);

}  // namespace rollspec::io
