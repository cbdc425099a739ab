#pragma once
// Where a cached stage table may be written (stiffness and blocked-force tables):
//   - an existing file at an explicit [stiffness] table path is replaced (even with --rebuild) only
//     if it is a rollspec table of the same kind; at rollspec's own automatic name
//     (<table_dir>/stiffness-<input hash>.h5) a damaged file may be rebuilt; an input of the study,
//     a directory or a device never is;
//   - a missing [stiffness] table_dir is created only below the study's directory (no "..", not
//     absolute); an explicit [stiffness] table path must be in an existing directory.
#include <string>

#include "src/stiffness/cached_table.hpp"

namespace rollspec::stiffness {

// Refuses (exit 73 / 78) a table path rollspec must not write, naming the key; returns the path to
// write (symbolic links to a table followed). Creates the table directory where allowed. Call on
// rank 0 before building the table.
// `automatic`: the path is rollspec's own name in [stiffness] table_dir (else an explicit path).
std::string prepare_table_path(const TableStore& store, const std::string& path, const std::string& filetype,
                               bool automatic);

// prepare_table_path on rank 0, with the decision shared by every rank (collective under MPI), so
// a refused path stops all ranks before the build instead of leaving them at a barrier.
std::string table_write_path(const TableStore& store, const std::string& path, const std::string& filetype,
                             bool automatic);

}  // namespace rollspec::stiffness
