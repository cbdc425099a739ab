#include "src/texture/texture_keys.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "kernels/texture/iso3095_rail_psd.hpp"
#include "kernels/texture/iso8608_psd.hpp"
#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/tabulated_psd.hpp"
#include "src/error.hpp"
#include "src/io/input_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/run_warning.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/profile_source.hpp"

namespace fs = std::filesystem;

namespace rollspec::texture_io {

using namespace study;

namespace {
// PSD table: first column wavenumber_rad_per_m or spatial_frequency_cycles_per_m, second column
// psd_m3 or psd_um2_m (one-sided, per unit of the first column).
texture::Psd read_psd_table(const TextureSection& s) {
  const std::string& path = s.table_path;
  const io::CsvTable t = io::read_csv(path);
  if (t.columns.size() != 2)
    throw data_error(path + ":1: a PSD table has 2 columns (abscissa, psd), found " + std::to_string(t.columns.size()));
  const std::string& a = t.columns[0];
  const std::string& p = t.columns[1];
  bool cycles = false;
  if (a == "spatial_frequency_cycles_per_m")
    cycles = true;
  else if (a != "wavenumber_rad_per_m")
    throw data_error(path + ":1: first column '" + a +
                     "' does not state its unit; allowed: wavenumber_rad_per_m or spatial_frequency_cycles_per_m");
  double scale = 1.0;
  if (p == "psd_um2_m")
    scale = 1e-12;
  else if (p != "psd_m3")
    throw data_error(path + ":1: second column '" + p + "' does not state its unit; allowed: psd_m3 or psd_um2_m");
  io::require_increasing(t, 0);
  std::vector<double> k(t.rows()), g(t.rows());
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double x = t.values[0][r], v = t.values[1][r] * scale;
    if (!(x > 0.0)) throw data_error(t.where(r) + ": " + a + " value " + std::to_string(x) + " must be > 0");
    if (v < 0.0)
      throw data_error(t.where(r) + ": " + p + " value " + std::to_string(t.values[1][r]) +
                       " is negative; allowed: >= 0");
    k[r] = cycles ? texture::wavenumber_from_spatial_frequency(x) : x;
    g[r] = cycles ? texture::psd_k_from_psd_n(v) : v;
  }
  if (t.rows() < 2) throw data_error(path + ": a PSD table needs at least 2 rows");
  try {
    return texture::TabulatedPsd(k, g, s.table_extension).to_psd();
  } catch (const std::invalid_argument& e) {
    throw data_error(path + ": " + e.what());
  }
}

}  // namespace

std::vector<KeySpec> psd_keys() { return TextureSection::keys(); }

std::vector<KeySpec> surface_keys() { return SurfaceSection::keys(); }

texture::Psd study_psd(const KeyReader& s) { return study_psd(TextureSection::parse(s)); }

texture::Psd study_psd(const TextureSection& s) {
  try {
    switch (s.source) {
      case TextureSource::table:
        if (!s.has_table) s.origin(s.source).refuse("needs [texture] table = a PSD table file");
        return read_psd_table(s);
      case TextureSource::profiles:
        return profile_psd(s);
      case TextureSource::iso8608: {
        texture::Iso8608Spec spec;
        spec.road_class = s.road_class;
        return texture::iso8608_psd(spec);
      }
      case TextureSource::iso3095:
        return texture::iso3095_rail_psd(s.table_extension).to_psd();
      case TextureSource::self_affine:
        break;
    }
    texture::SelfAffineSpec spec;
    spec.hurst = s.hurst;
    const double lw = s.long_wavelength;
    spec.k_rolloff = 2.0 * M_PI / s.rolloff_wavelength;
    spec.k_long = lw > 0.0 ? 2.0 * M_PI / lw : 0.0;
    spec.k_short = 2.0 * M_PI / s.short_wavelength;
    if (spec.k_long > spec.k_rolloff) s.origin(s.long_wavelength).refuse("must be at least the roll-off wavelength");
    if (spec.k_short <= spec.k_rolloff)
      s.origin(s.short_wavelength).refuse("must be shorter than the roll-off wavelength");
    spec.target = s.rms_kind;
    spec.rms = s.rms;
    return texture::SelfAffinePsd(spec).to_psd();
  } catch (const std::invalid_argument& e) {
    throw config_error(s.origin(s.source).where + ": " + e.what());
  }
}

spectral::Amplitudes study_amplitudes(const KeyReader& s) { return study_amplitudes(TextureSection::parse(s)); }

spectral::Amplitudes study_amplitudes(const TextureSection& s) { return s.amplitudes; }

namespace {
// ISO 3095 covers 400 mm down to 3.15 mm: say so, and the frequency of its shortest wavelength.
std::string iso3095_note(const LineGeneratorKeys& k) {
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
  for (const auto& b : texture::iso3095_rail_roughness_limit()) {
    shortest = std::min(shortest, b.wavelength_nominal);
    longest = std::max(longest, b.wavelength_nominal);
  }
  std::string m = "; the ISO 3095 spectrum stops at " + io::four_digits(shortest * 1e3) +
                  " mm wavelength (its longest is " + io::four_digits(longest * 1e3) + " mm)";
  if (k.speed > 0.0)
    m += ": " + io::four_digits(shortest * 1e3) + " mm is " + io::four_digits(k.speed / shortest) + " Hz at " +
         k.speed_key + " = " + io::four_digits(k.speed) + " m/s";
  return m;
}

// A grid error of the kernels in study keys: which key to change and to what. spacing: the grid's
// dx; stretch: how much finer than pi/k_max the grid must be (the anisotropy of spectral surfaces).
std::string grid_message(const LineGeneratorKeys& k, const std::exception& e, double spacing, double stretch) {
  std::string m = k.spacing_where + ": " + e.what();
  if (dynamic_cast<const std::domain_error*>(&e)) {  // a table PSD asked outside its range
    m += "; allowed: [texture] table_extension set to zero, constant or power_law (now " + k.extension_where +
         "), or a grid inside the table's range (longer wavelengths need a longer table or profiles, shorter ones "
         "a coarser spacing)";
    if (k.source == TextureSource::iso3095) m += iso3095_note(k);
  }
  if (const auto* u = dynamic_cast<const texture::UnresolvedPsd*>(&e)) {
    if (!std::isfinite(u->k_max)) {  // a table extended beyond its last wavenumber
      m += "; allowed: [texture] table_extension = zero or error (now " + spelling_of(kTableExtensions, k.extension) +
           "), so that the PSD ends at " + "the table's last wavenumber, with " + k.spacing_key +
           " at most pi over that wavenumber";
    } else {
      m += "; allowed: " + k.spacing_key + " at most " + io::four_digits(M_PI / (u->k_max * stretch)) + " m";
      if (k.source == TextureSource::self_affine || k.source == TextureSource::profiles)
        m += ", or [texture] short_wavelength at least " + io::four_digits(2.0 * spacing * stretch) + " m";
      if (k.source == TextureSource::iso3095) m += iso3095_note(k);
    }
  }
  return m;
}
}  // namespace

LineGeneratorKeys LineGeneratorKeys::of(const TextureSection& t, const KeyOrigin& spacing,
                                        const std::string& spacing_key) {
  LineGeneratorKeys k;
  k.amplitudes = study_amplitudes(t);
  k.spacing_where = spacing.where;
  k.extension_where = t.present ? t.origin(t.table_extension).where : "";
  k.spacing_key = spacing_key;
  if (t.present) k.source = t.source;
  k.extension = t.table_extension;
  return k;
}

std::unique_ptr<texture::LineTextureGenerator> line_generator(const LineGeneratorKeys& k, const texture::Psd& psd,
                                                              double spacing, std::size_t samples, bool truncate) {
  texture::LineTextureSpec ls;
  ls.spacing = spacing;
  ls.samples = samples;
  ls.amplitudes = k.amplitudes;
  ls.allow_truncation = truncate;
  try {
    return std::make_unique<texture::LineTextureGenerator>(psd, ls);
  } catch (const std::exception& e) {
    throw config_error(grid_message(k, e, spacing, 1.0));
  }
}

std::vector<std::string> profile_files(const KeyReader& s) { return profile_files(TextureSection::parse(s)); }

std::vector<std::string> profile_files(const TextureSection& s) {
  if (!s.present || s.source != TextureSource::profiles) return {};
  return s.profile_paths;
}

std::string psd_input_fingerprint(const KeyReader& s) { return psd_input_fingerprint(TextureSection::parse(s)); }

std::string psd_input_fingerprint(const TextureSection& s) {
  std::ostringstream out;
  auto add_file = [&](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    out << "file " << fs::path(p).filename().string() << "\n" << in.rdbuf() << "\n";
  };
  if (s.source == TextureSource::table) add_file(s.table_path);
  if (s.source == TextureSource::profiles) {
    for (const auto& p : s.profile_paths) add_file(p);
    // How a PSD is made from them: the estimator (whole scans, measured level, unresolved variance
    // apart: kernels/texture Eq. 42-45), and a short-wavelength cut only where the study sets one
    // (Eq. 46; the canonical text shows the key's default either way).
    out << "profile estimator = periodogram level, unresolved variance apart (Eq. 42-45)\n";
    out << "short_wavelength cut = " << (s.was_set(s.short_wavelength) ? io::exact_text(s.short_wavelength) : "none")
        << "\n";
  }
  return out.str();
}

std::vector<std::string> profile_derived_surface_keys(const KeyReader& s) {
  return profile_derived_surface_keys(TextureSection::parse(s), SurfaceSection::parse(s));
}

std::vector<std::string> profile_derived_surface_keys(const TextureSection& t, const SurfaceSection& f) {
  std::vector<std::string> out;
  if (!t.present || t.source != TextureSource::profiles || f.method != study::SurfaceMethod::seed) return out;
  if (f.sigma_default) out.push_back("sigma");
  if (f.correlation_x_default) out.push_back("correlation_x");
  if (f.correlation_y_default) out.push_back("correlation_y");
  return out;
}

std::size_t SurfaceGenerator::random_count() const { return spectral ? 2 * spectral->modes() : seed->random_count(); }

void SurfaceGenerator::generate(std::uint64_t seed_value, std::uint64_t realisation, texture::Surface& out,
                                bool table) const {
  const rng::Stream phase = table ? rng::Stream::table_surface_phase : rng::Stream::surface_phase;
  const rng::Stream amplitude = table ? rng::Stream::table_surface_amplitude : rng::Stream::surface_amplitude;
  if (spectral) {
    std::vector<double> up(spectral->modes()), ua(spectral->modes());
    rng::PhiloxStream(seed_value, realisation, phase).uniform_open(up.data(), up.size());
    rng::PhiloxStream(seed_value, realisation, amplitude).uniform_open(ua.data(), ua.size());
    spectral->generate(up.data(), ua.data(), out);
  } else {
    std::vector<double> u(seed->random_count());
    rng::PhiloxStream(seed_value, realisation, phase).uniform_open(u.data(), u.size());
    seed->generate(u.data(), out);
  }
}

SurfaceGenerator study_surface_generator(const KeyReader& s, const texture::Psd& psd) {
  const TextureSection t = TextureSection::parse(s);
  return surface_generator(t, with_profile_values(t, SurfaceSection::parse(s)), psd);
}

SurfaceSection with_profile_values(const TextureSection& t, SurfaceSection s) {
  // Seed 001 §3.1 and Eq. 10: sigma and the correlation lengths (isotropic) are the measured
  // profiles' unless [surface] gives them.
  const auto measured = profile_derived_surface_keys(t, s);
  if (measured.empty()) return s;
  const texture::EstimatedPsd est = profile_estimate(t);
  for (const auto& k : measured) {
    if (k == "sigma") s.sigma = est.sigma;
    if (std::isfinite(est.correlation_length)) {
      if (k == "correlation_x") s.correlation_x = est.correlation_length;
      if (k == "correlation_y") s.correlation_y = est.correlation_length;
    }
  }
  s.sigma_default = s.correlation_x_default = s.correlation_y_default = false;  // resolved
  return s;
}

SurfaceGenerator surface_generator(const TextureSection& t, const SurfaceSection& s, const texture::Psd& psd) {
  SurfaceGenerator g;
  const auto nx = static_cast<std::size_t>(s.nx), ny = static_cast<std::size_t>(s.ny);
  if (nx % 2) s.origin(s.nx).refuse("must be even");
  if (ny % 2) s.origin(s.ny).refuse("must be even");
  const double h = s.spacing;
  try {
    if (s.method == study::SurfaceMethod::spectral) {
      texture::SpectralSurfaceSpec spec;
      spec.nx = nx;
      spec.ny = ny;
      spec.dx = spec.dy = h;
      spec.amplitudes = study_amplitudes(t);
      spec.anisotropy = s.anisotropy;
      g.spectral = std::make_unique<texture::SpectralSurfaceGenerator>(psd, spec);
    } else {
      texture::SeedSurfaceRequest r;
      r.nx = nx;
      r.ny = ny;
      r.dx = r.dy = h;
      r.correlation_x = s.correlation_x;
      r.correlation_y = s.correlation_y;
      r.sigma = s.sigma;
      r.amplitudes = study_amplitudes(t);
      g.seed = std::make_unique<texture::SeedSurfaceGenerator>(psd, r);
    }
  } catch (const std::exception& e) {  // invalid_argument from the spec, domain_error from a table PSD
    // The spectral grid must resolve k_max stretched by the anisotropy along x and y.
    const double a = s.method == study::SurfaceMethod::spectral ? std::sqrt(s.anisotropy) : 1.0;
    throw config_error(
        grid_message(LineGeneratorKeys::of(t, s.origin(s.spacing), "[surface] spacing"), e, h, std::max(a, 1.0 / a)));
  }
  if (g.spectral)  // a grid smaller than the measured profiles drops their longer waves: say how much
    if (const std::string w = surface_share_warning(t, s, psd, g.spectral->target_variance()); !w.empty()) io::warn(w);
  return g;
}

}  // namespace rollspec::texture_io
