#pragma once
// One point of a sweep result. `rollspec run` of a study with [sweep] stacks its points' /psd and
// /bands with leading axes: one per swept key (crossed) or one for all (zipped), whose values /sweep
// holds (src/io/hdf5_stack.hpp). A reader of one point's spectra or bands picks the point by its
// number in run order or by its swept values, and takes that point's block of each stacked dataset.
#include <cstddef>
#include <string>
#include <vector>

#include "src/io/hdf5_file.hpp"

namespace rollspec::io {

struct SweepPoint {
  std::vector<std::size_t> shape;  // lengths of the leading axes (empty: the result is no sweep)
  std::size_t offset = 0;          // the point's number in run order, from 0 (row-major over `shape`)
  std::string label;               // "oscillator.mass=2.5", or "" for a result that is no sweep
  std::size_t points() const;
};

// The point of `r` named by `spec`: K (1 to the number of points, in run order) or
// section.key=value[,section.key=value ...] (values as /sweep holds them; numbers compared as numbers;
// a zipped sweep needs one of its keys, a crossed one each). For a result that is no sweep, `spec`
// must be empty; for a sweep result it must name a point: refused otherwise (exit 64), the message
// listing the swept keys, their values and the number of points.
SweepPoint sweep_point(const Hdf5Reader& r, const std::string& spec);

// Dataset `name` of `r`, of `rank` dimensions in one result, read at the point: a stacked one (the
// sweep's leading axes in front) as the point's block, one equal at every point (kept once) as it is;
// `dims` without the leading axes. Refused (exit 65) when it is neither.
std::vector<double> read_at_point(const Hdf5Reader& r, const SweepPoint& p, const std::string& name, std::size_t rank,
                                  std::vector<std::size_t>* dims = nullptr);

}  // namespace rollspec::io
