#pragma once
// netCDF / xarray access to every group: h5netcdf refuses a dataset axis that has no dimension
// scale ("phony dims"). name_free_dimensions() gives each such axis its own index scale in the
// dataset's group, named "<dataset>_index" (one axis) or "<dataset>_dim<k>", with values 0..n-1.
// Axes that already have a scale (frequency, sensor, band, ...) keep it.
#include <hdf5.h>

namespace rollspec::io {

// Returns false if HDF5 refused a step (the caller reports it as a write failure).
bool name_free_dimensions(hid_t file);

}  // namespace rollspec::io
