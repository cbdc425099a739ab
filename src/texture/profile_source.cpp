#include "src/texture/profile_source.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "kernels/texture/measured_psd.hpp"
#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/input_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/uniform_grid.hpp"

namespace fs = std::filesystem;

namespace rollspec::texture_io {

using study::SurfaceSection;
using study::TextureSection;

namespace {
// The [texture] keys that act on measured profiles; any other one set with source = profiles is refused.
bool acts_on_profiles(const TextureSection& s, const study::KeyValue& v) {
  return s.is_of(v, s.source) || s.is_of(v, s.profile_paths) || s.is_of(v, s.median_filter) ||
         s.is_of(v, s.table_extension) || s.is_of(v, s.short_wavelength) || s.is_of(v, s.amplitudes);
}

void refuse_idle_keys(const TextureSection& s) {
  for (const auto& v : s.key_values()) {
    if (v.set && !acts_on_profiles(s, v))
      v.origin.refuse(
          "does not act on measured profiles ([texture] source = profiles); allowed with profiles: profiles, "
          "median_filter, table_extension, short_wavelength (cuts the measured PSD) and amplitudes; remove it");
  }
}

// A step fitted to positions rounded by up to `half_unit` is known to its standard error
// (half_unit / sqrt(3)) / sqrt(n (n^2 - 1) / 12): 1e-7 um for 9600 positions of 0.156 um printed to
// 0.1 um. The shortest decimal within it is the step the instrument used (0.15625 um, fitted
// 0.1562499957 um), so a study's [lines] spacing equal to it resolves the scans' Nyquist wavenumber.
double nominal_step(double fitted, std::size_t n, double half_unit) {
  const double nn = static_cast<double>(n);
  const double error = half_unit / std::sqrt(3.0) / std::sqrt(nn * (nn * nn - 1.0) / 12.0);
  for (int digits = 1; digits <= 17; ++digits) {
    const std::string text = io::formatted("%.*e", digits - 1, fitted);
    const double shortest = std::strtod(text.c_str(), nullptr);  // the double nearest that decimal
    if (std::fabs(shortest - fitted) <= error) return shortest;
  }
  return fitted;
}

std::string percent(double share) { return io::four_digits(100.0 * share) + " %"; }
}  // namespace

io::GridNames profile_position_names() {
  io::GridNames names;
  names.column = "column 'position_m'";
  names.values = "positions";
  names.previous = "previous position";
  names.interval = "step";
  names.record = "profile";
  names.grid = "x_0 + i*dx";
  names.step = "dx";
  names.allowed = "strictly increasing, uniformly spaced positions (each within 0.1 step of x_0 + i*dx)";
  names.uneven = "the spacing is not constant";
  names.text = [](double v) { return io::length_text(v); };
  return names;
}

texture::Profile read_profile(const std::string& path) {
  const io::CsvTable t = io::read_csv(path);
  const bool micrometres = t.columns.size() == 2 && t.columns[1] == "height_um";
  if (t.columns.size() != 2 || t.columns[0] != "position_m" || (t.columns[1] != "height_m" && !micrometres))
    throw data_error(path + ":1: a profile has the columns position_m,height_m (or position_m,height_um)");
  if (t.rows() < 8) throw data_error(path + ": " + std::to_string(t.rows()) + " samples; a profile needs at least 8");
  // The positions as printed: a stylus export rounds them (0.156 um steps to 0.1 um), which the grid
  // rule allows; the profile takes the grid they lie on (the least-squares step when rounded).
  const io::GridNames names = profile_position_names();
  const std::vector<double>& x = t.values[0];
  bool fitted = false;
  double dx = io::uniform_grid_step(
      x, [&](std::size_t i) { return t.where(i); }, names, io::PrintedDigits{t.decimals[0], t.significant[0]}, &fitted);
  if (fitted)
    dx = nominal_step(dx, x.size(), io::PrintedDigits{t.decimals[0], t.significant[0]}.printed_half_unit(x.back()));
  texture::Profile p;
  p.x.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) p.x[i] = x.front() + dx * static_cast<double>(i);
  p.z = t.values[1];
  if (micrometres)
    for (double& z : p.z) z *= 1e-6;
  return p;
}

texture::EstimatedPsd profile_estimate(const TextureSection& s) {
  const auto& files = s.profile_paths;
  if (files.empty())
    s.origin(s.profile_paths)
        .refuse(
            "names no profile file; allowed: one or more comma-separated CSV files "
            "(position_m,height_m), each a whole scan");
  std::vector<texture::Profile> profiles;
  for (const auto& p : files) {
    io::require_regular_input(p, "profile file (" + s.origin(s.profile_paths).where + ")");
    if (!fs::is_regular_file(p)) throw missing_input(s.origin(s.profile_paths).where + ": no such profile file " + p);
    try {
      profiles.push_back(read_profile(p));
    } catch (const UserError& e) {  // the file's line and the study's key both
      throw UserError(e.exit_code(), s.origin(s.profile_paths).where + ": " + e.what());
    }
  }
  try {
    texture::ProfilePsdOptions opt;
    opt.median_filter = s.median_filter;
    return texture::profile_psd(profiles, opt);
  } catch (const std::invalid_argument& e) {
    throw data_error(s.origin(s.profile_paths).where + ": " + e.what());
  }
}

texture::Psd profile_psd(const TextureSection& s) {
  refuse_idle_keys(s);
  const texture::EstimatedPsd est = profile_estimate(s);
  texture::Psd psd;
  try {
    psd = texture::measured_line_psd(est, s.table_extension);
  } catch (const std::invalid_argument& e) {
    throw data_error(s.origin(s.profile_paths).where + ": " + e.what());
  }
  if (!s.was_set(s.short_wavelength)) return psd;
  // Eq. 46: the cut must fall inside the resolved band, else it cuts nothing or the unresolved rest.
  const double k_cut = 2.0 * M_PI / s.short_wavelength;
  const double k_r = (static_cast<double>(est.first_resolved) - 0.5) * est.dk, k_n = M_PI / est.spacing;
  if (!(k_cut > k_r && k_cut < k_n))
    s.origin(s.short_wavelength)
        .refuse(
            "cuts the measured PSD at 2 pi / short_wavelength, which must lie in its resolved band; allowed: between " +
            io::length_text(2.0 * est.spacing) + " (twice the scans' spacing: a shorter cut leaves every wave) and " +
            io::length_text(2.0 * M_PI / k_r) + " (the longest wavelength the scans resolve)");
  return texture::band_limited(psd, k_cut);
}

std::string profile_note(const TextureSection& s) {
  if (!s.present || s.source != study::TextureSource::profiles) return "";
  const texture::EstimatedPsd e = profile_estimate(s);
  const double v = e.variance, vr = e.resolved_variance(), vu = e.unresolved_variance();
  const double length = static_cast<double>(e.samples) * e.spacing;
  const double longest = 2.0 * M_PI / ((static_cast<double>(e.first_resolved) - 0.5) * e.dk);
  std::string m = "[texture] profiles: " + io::counted(e.profiles, "scan") + " of " + io::counted(e.samples, "sample") +
                  " at " + io::length_text(e.spacing) + " (" + io::length_text(length) + "), rms " +
                  io::length_text(std::sqrt(v)) + " after the linear trend; resolved (wavelengths up to " +
                  io::length_text(longest) + "): " + percent(v > 0.0 ? vr / v : 0.0) +
                  " of the variance, at the periodogram's level; unresolved " +
                  "(longer waves): " + percent(v > 0.0 ? vu / v : 0.0) + " (rms " + io::length_text(std::sqrt(vu)) +
                  "), given to the scans' longest wave, not to the resolved octaves (kernels/texture Eq. 44-45)";
  if (s.was_set(s.short_wavelength))
    m += "; cut at [texture] short_wavelength = " + io::length_text(s.short_wavelength) + " (Eq. 46)";
  return m;
}

void write_profile_record(io::Hdf5Writer& w, const std::string& group, const TextureSection& s) {
  if (!s.present || s.source != study::TextureSource::profiles) return;
  const texture::EstimatedPsd e = profile_estimate(s);
  w.write(group + "/wavenumber", {e.wavenumber.size()}, e.wavenumber.data(), "rad/m", "bins k_j = j dk of the scans");
  w.write(group + "/periodogram", {e.psd.size()}, e.psd.data(), "m^3",
          "mean Hann periodogram of the scans after their linear trend (kernels/texture Eq. 16-17)");
  w.make_scale(group + "/wavenumber", "wavenumber");
  w.attach_scale(group + "/periodogram", group + "/wavenumber", 0);
  w.attribute(group, "scans", static_cast<std::int64_t>(e.profiles));
  w.attribute(group, "samples", static_cast<std::int64_t>(e.samples));
  w.attribute(group, "spacing", e.spacing);
  w.attribute(group, "variance", e.variance);
  w.attribute(group, "resolved_variance", e.resolved_variance());
  w.attribute(group, "unresolved_variance", e.unresolved_variance());
  w.attribute(group, "resolved_wavenumber", (static_cast<double>(e.first_resolved) - 0.5) * e.dk);
  w.attribute(group, "short_wavelength_cut", s.was_set(s.short_wavelength) ? s.short_wavelength : 0.0);
}

std::string surface_share_warning(const TextureSection& t, const SurfaceSection& s, const texture::Psd& psd,
                                  double surface_variance) {
  if (!t.present || t.source != study::TextureSource::profiles) return "";
  const texture::EstimatedPsd e = profile_estimate(t);
  // The PSD's variance on the scans' own bins (Eq. 14b cells): the resolved table and the unresolved cells.
  const auto g = texture::psd_at_harmonics(psd, e.dk, e.psd.size());
  double total = 0.0;
  for (double v : g) total += v * e.dk;
  const double share = total > 0.0 ? surface_variance / total : 1.0;
  if (share >= kSurfaceShareWarning) return "";
  const double length = static_cast<double>(e.samples) * e.spacing;
  const auto cells = static_cast<long long>(std::ceil(length / s.spacing / 2.0) * 2.0);
  return s.origin(s.nx).where + ": the spectral surfaces of " + std::to_string(s.nx) + " x " + std::to_string(s.ny) +
         " cells of " + io::length_text(s.spacing) + " hold " + percent(share) +
         " of the measured profiles' variance (rms " + io::four_digits(std::sqrt(share)) +
         " of theirs): the scans are " + io::length_text(length) +
         " long and their longer waves do not fit; to keep it, [surface] nx and ny at least " + std::to_string(cells) +
         " at this spacing (nx * spacing >= the scans' length)";
}

}  // namespace rollspec::texture_io
