#pragma once
// [texture] source = profiles: measured line scans, each used whole and as exported (kernels/texture
// README §4, Eq. 15-17 and 42-46). A scan's positions may be rounded to their printed digits (the
// rule of io/uniform_grid.hpp, shared with measured signals' time stamps); one scan is enough. The
// resolved band keeps the periodogram's level, the variance the scans do not resolve is said apart
// (profile_note) and recorded (write_profile_record). The [texture] keys act on profiles or are
// refused: profiles, median_filter, table_extension, short_wavelength (Eq. 46) and amplitudes act.
#include <string>

#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/psd.hpp"
#include "src/io/uniform_grid.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::io {
class Hdf5Writer;
}

namespace rollspec::texture_io {

// One scan file: columns position_m and height_m (or height_um). Positions on a uniform grid within
// the rounding of their printed digits come back regularised to it; others are refused naming the
// line (data error, exit 65).
texture::Profile read_profile(const std::string& path);

// How read_profile's messages name a profile's positions under the grid rule (io/uniform_grid.hpp).
io::GridNames profile_position_names();

// Eq. 15-17 and 44 of the study's scans (one or more).
texture::EstimatedPsd profile_estimate(const study::TextureSection& s);

// The PSD the generators take (Eq. 44-45), cut at [texture] short_wavelength when it is set
// (Eq. 46). Refuses, with exit 78, a set [texture] key that cannot act on profiles and a cut outside
// the resolved band.
texture::Psd profile_psd(const study::TextureSection& s);

// One line for plan, run and texture: the scans, the share of their variance the resolved band
// holds at its measured level, and the unresolved rest ("" unless source = profiles).
std::string profile_note(const study::TextureSection& s);

// The same figures as attributes of `group` (scans, samples, spacing, variance, resolved_variance,
// unresolved_variance, resolved_wavenumber, short_wavelength_cut) and the scans' mean periodogram
// (`group`/wavenumber, `group`/periodogram), if source = profiles.
void write_profile_record(io::Hdf5Writer& w, const std::string& group, const study::TextureSection& s);

// Spectral [surface] grids from profiles: a warning (with the share of the profiles' variance the
// grid holds and the keys that change it) when the share is below kSurfaceShareWarning; "" otherwise.
constexpr double kSurfaceShareWarning = 0.95;
std::string surface_share_warning(const study::TextureSection& t, const study::SurfaceSection& s,
                                  const texture::Psd& psd, double surface_variance);

}  // namespace rollspec::texture_io
