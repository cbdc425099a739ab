#include "src/texture/texture_keys.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "kernels/texture/iso3095_rail_psd.hpp"
#include "kernels/texture/iso8608_psd.hpp"
#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/psd_smoothing.hpp"
#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/tabulated_psd.hpp"
#include "src/error.hpp"
#include "src/io/input_file.hpp"
#include "src/io/csv_table.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/study/key_reader.hpp"

namespace fs = std::filesystem;

namespace rollspec::texture_io {

using namespace study;

namespace {
const double inf = std::numeric_limits<double>::infinity();

texture::Extension extension_of(const std::string& s) {
  if (s == "constant") return texture::Extension::constant;
  if (s == "power_law") return texture::Extension::power_law;
  if (s == "zero") return texture::Extension::zero;
  return texture::Extension::error;
}

std::string study_relative(const KeyReader& s, const std::string& p) {
  if (fs::path(p).is_absolute()) return p;
  return (fs::path(s.file()).parent_path() / p).string();
}

// PSD table: first column wavenumber_rad_per_m or spatial_frequency_cycles_per_m, second column
// psd_m3 or psd_um2_m (one-sided, per unit of the first column).
texture::Psd read_psd_table(const KeyReader& s) {
  const std::string path = s.path("texture.table");
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
    return texture::TabulatedPsd(k, g, extension_of(s.text("texture.table_extension"))).to_psd();
  } catch (const std::invalid_argument& e) {
    throw data_error(path + ": " + e.what());
  }
}

texture::Profile read_profile(const std::string& path) {
  const io::CsvTable t = io::read_csv(path);
  texture::Profile p;
  const bool micrometres = t.columns.size() == 2 && t.columns[1] == "height_um";
  if (t.columns.size() != 2 || t.columns[0] != "position_m" || (t.columns[1] != "height_m" && !micrometres))
    throw data_error(path + ":1: a profile has the columns position_m,height_m (or position_m,height_um)");
  io::require_increasing(t, 0);
  p.x = t.values[0];
  p.z = t.values[1];
  if (micrometres)
    for (double& z : p.z) z *= 1e-6;
  return p;
}

// Eq. 15-17 of the study's measured profiles.
texture::EstimatedPsd profile_estimate(const KeyReader& s) {
  const auto files = s.list("texture.profiles");
  if (files.size() < 2)
    s.refuse("texture.profiles", "names " + std::to_string(files.size()) +
                                     " profile file(s); allowed: at least 2 comma-separated CSV files");
  std::vector<texture::Profile> profiles;
  for (const auto& f : files) {
    const std::string p = study_relative(s, f);
    io::require_regular_input(p, "profile file (" + s.where("texture.profiles") + ")");
    if (!fs::is_regular_file(p)) throw missing_input(s.where("texture.profiles") + ": no such profile file " + p);
    profiles.push_back(read_profile(p));
    if (profiles.back().z.size() < 8)
      throw data_error(p + ": " + std::to_string(profiles.back().z.size()) + " samples; a profile needs at least 8");
  }
  try {
    texture::ProfilePsdOptions opt;
    opt.median_filter = s.boolean("texture.median_filter");
    return texture::profile_psd(profiles, opt);
  } catch (const std::invalid_argument& e) {
    throw data_error(s.where("texture.profiles") + ": " + e.what());
  }
}

// The estimate band-averaged in log k (kernels/texture/README.md Eq. 33-35): the raw periodogram's
// bin-to-bin scatter would make isotropic surfaces far too rough (inverse Abel transform, Eq. 19).
texture::Psd profile_psd(const KeyReader& s) {
  const texture::EstimatedPsd est = profile_estimate(s);
  try {
    texture::Psd psd = texture::smoothed_psd_table(est, extension_of(s.text("texture.table_extension"))).to_psd();
    psd.cell_average = true;  // Eq. 14b: every synthesis grid keeps the table's variance
    return psd;
  } catch (const std::invalid_argument& e) {
    throw data_error(s.where("texture.profiles") + ": " + e.what());
  }
}
}  // namespace

std::vector<KeySpec> psd_keys() {
  return {
      choice_key("texture", "source", "where the roughness PSD comes from", std::string("self-affine"),
                 {"self-affine", "table", "profiles", "iso8608", "iso3095"}),
      path_key("texture", "table",
               "PSD table CSV: header wavenumber_rad_per_m or spatial_frequency_cycles_per_m, then psd_m3 or psd_um2_m",
               std::string("none")),
      choice_key("texture", "table_extension", "PSD outside the table or measured band", std::string("error"),
                 {"error", "constant", "power_law", "zero"}),
      text_key("texture", "profiles", "measured profiles: comma-separated CSV files (position_m,height_m)",
               std::string("")),
      bool_key("texture", "median_filter", "3-point median filter on measured profiles", std::string("false")),
      real_key("texture", "hurst", "-", "Hurst exponent H of the self-affine PSD", std::string("0.8"), 0.0, 1.0, false,
               true),
      real_key("texture", "long_wavelength", "m", "long-wavelength cut-off (0: none)", std::string("0"), 0.0, inf),
      real_key("texture", "rolloff_wavelength", "m", "roll-off wavelength (plateau above it)", std::string("1e-3"), 0.0,
               inf, false),
      real_key("texture", "short_wavelength", "m", "short-wavelength cut-off", std::string("1e-5"), 0.0, inf, false),
      choice_key("texture", "rms_kind", "what `rms` sets for the self-affine PSD", std::string("height"),
                 {"height", "slope"}),
      real_key("texture", "rms", "m (height) or - (slope)", "rms height or rms slope of the self-affine PSD",
               std::string("1e-6"), 0.0, inf, false),
      choice_key("texture", "road_class", "ISO 8608 road class", std::string("A"),
                 {"A", "B", "C", "D", "E", "F", "G", "H"}),
      choice_key("texture", "amplitudes",
                 "harmonic amplitudes: rayleigh (Gaussian) or deterministic (the target PSD exactly)",
                 std::string("rayleigh"), {"rayleigh", "deterministic"}),
  };
}

std::vector<KeySpec> surface_keys() {
  return {
      choice_key("surface", "method",
                 "isotropic surfaces: spectral (2D Fourier filter of the isotropic PSD) or seed (seed 001 Eq. 9-10: "
                 "sums of line textures)",
                 std::string("spectral"), {"spectral", "seed"}),
      integer_key("surface", "nx", "grid points along x (even)", std::string("128"), 4, 1 << 14),
      integer_key("surface", "ny", "grid points along y (even)", std::string("128"), 4, 1 << 14),
      real_key("surface", "spacing", "m", "grid spacing dx = dy", std::string("1e-6"), 0.0, inf, false),
      real_key("surface", "anisotropy", "-", "correlation length ratio x/y (spectral method)", std::string("1"), 0.0,
               inf, false),
      real_key(
          "surface", "correlation_x", "m",
          "correlation length along x (seed method, 1/e; unset with [texture] source = profiles: the profiles' mean)",
          std::string("1e-5"), 0.0, inf, false),
      real_key(
          "surface", "correlation_y", "m",
          "correlation length along y (seed method, 1/e; unset with [texture] source = profiles: the profiles' mean)",
          std::string("1e-5"), 0.0, inf, false),
      real_key("surface", "sigma", "m",
               "rms height of seed-method surfaces (unset with [texture] source = profiles: the profiles' mean "
               "standard deviation)",
               std::string("3e-7"), 0.0, inf, false),
  };
}

texture::Psd study_psd(const KeyReader& s) {
  const std::string source = s.text("texture.source");
  try {
    if (source == "table") {
      if (s.text("texture.table") == "none") s.refuse("texture.source", "needs [texture] table = a PSD table file");
      return read_psd_table(s);
    }
    if (source == "profiles") return profile_psd(s);
    if (source == "iso8608") {
      texture::Iso8608Spec spec;
      spec.road_class = s.text("texture.road_class")[0];
      return texture::iso8608_psd(spec);
    }
    if (source == "iso3095") return texture::iso3095_rail_psd(extension_of(s.text("texture.table_extension"))).to_psd();
    texture::SelfAffineSpec spec;
    spec.hurst = s.real("texture.hurst");
    const double lw = s.real("texture.long_wavelength");
    spec.k_rolloff = 2.0 * M_PI / s.real("texture.rolloff_wavelength");
    spec.k_long = lw > 0.0 ? 2.0 * M_PI / lw : 0.0;
    spec.k_short = 2.0 * M_PI / s.real("texture.short_wavelength");
    if (spec.k_long > spec.k_rolloff) s.refuse("texture.long_wavelength", "must be at least the roll-off wavelength");
    if (spec.k_short <= spec.k_rolloff)
      s.refuse("texture.short_wavelength", "must be shorter than the roll-off wavelength");
    spec.target = s.text("texture.rms_kind") == "slope" ? texture::RmsTarget::slope : texture::RmsTarget::height;
    spec.rms = s.real("texture.rms");
    return texture::SelfAffinePsd(spec).to_psd();
  } catch (const std::invalid_argument& e) {
    throw config_error(s.where("texture.source") + ": " + e.what());
  }
}

spectral::Amplitudes study_amplitudes(const KeyReader& s) {
  return s.text("texture.amplitudes") == "rayleigh" ? spectral::Amplitudes::rayleigh
                                                    : spectral::Amplitudes::deterministic;
}

namespace {
// A table PSD asked for a wavenumber outside its range: name the key that allows it.
std::string grid_message(const LineGeneratorKeys& k, const std::exception& e) {
  std::string m = k.spacing_where + ": " + e.what();
  if (dynamic_cast<const std::domain_error*>(&e))
    m += "; allowed: a grid inside the table's range (longer wavelengths need a longer table or profiles, shorter ones "
         "a coarser spacing), or " +
         k.extension_where + " set to zero, constant or power_law";
  return m;
}
}  // namespace

LineGeneratorKeys LineGeneratorKeys::parse(const KeyReader& s, const std::string& key) {
  return {study_amplitudes(s), s.where(key), s.where("texture.table_extension")};
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
    throw config_error(grid_message(k, e));
  }
}

std::unique_ptr<texture::LineTextureGenerator> study_line_generator(const KeyReader& s, const texture::Psd& psd,
                                                                    double spacing, std::size_t samples,
                                                                    const std::string& key, bool truncate) {
  return line_generator(LineGeneratorKeys::parse(s, key), psd, spacing, samples, truncate);
}

std::vector<std::string> profile_files(const KeyReader& s) {
  std::vector<std::string> out;
  if (!s.has("texture.source") || s.text("texture.source") != "profiles") return out;
  for (const auto& f : s.list("texture.profiles")) out.push_back(study_relative(s, f));
  return out;
}

std::string psd_input_fingerprint(const KeyReader& s) {
  std::ostringstream out;
  auto add_file = [&](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    out << "file " << fs::path(p).filename().string() << "\n" << in.rdbuf() << "\n";
  };
  const std::string source = s.text("texture.source");
  if (source == "table") add_file(s.path("texture.table"));
  if (source == "profiles")
    for (const auto& f : s.list("texture.profiles")) add_file(study_relative(s, f));
  return out.str();
}

std::vector<std::string> profile_derived_surface_keys(const KeyReader& s) {
  std::vector<std::string> out;
  if (!s.has("texture.source") || s.text("texture.source") != "profiles" || s.text("surface.method") != "seed")
    return out;
  for (const char* k : {"sigma", "correlation_x", "correlation_y"})
    if (s.entry(std::string("surface.") + k).origin.line == 0) out.push_back(k);  // 0: the documented default, not set
  return out;
}

std::size_t SurfaceGenerator::random_count() const { return spectral ? 2 * spectral->modes() : seed->random_count(); }

void SurfaceGenerator::generate(std::uint64_t seed_value, std::uint64_t realisation, texture::Surface& out) const {
  if (spectral) {
    std::vector<double> up(spectral->modes()), ua(spectral->modes());
    rng::PhiloxStream(seed_value, realisation, rng::Stream::surface_phase).uniform_open(up.data(), up.size());
    rng::PhiloxStream(seed_value, realisation, rng::Stream::surface_amplitude).uniform_open(ua.data(), ua.size());
    spectral->generate(up.data(), ua.data(), out);
  } else {
    std::vector<double> u(seed->random_count());
    rng::PhiloxStream(seed_value, realisation, rng::Stream::surface_phase).uniform_open(u.data(), u.size());
    seed->generate(u.data(), out);
  }
}

SurfaceGenerator study_surface_generator(const KeyReader& s, const texture::Psd& psd) {
  SurfaceGenerator g;
  const auto nx = static_cast<std::size_t>(s.integer("surface.nx")),
             ny = static_cast<std::size_t>(s.integer("surface.ny"));
  if (nx % 2) s.refuse("surface.nx", "must be even");
  if (ny % 2) s.refuse("surface.ny", "must be even");
  const double h = s.real("surface.spacing");
  try {
    if (s.text("surface.method") == "spectral") {
      texture::SpectralSurfaceSpec spec;
      spec.nx = nx;
      spec.ny = ny;
      spec.dx = spec.dy = h;
      spec.amplitudes = study_amplitudes(s);
      spec.anisotropy = s.real("surface.anisotropy");
      g.spectral = std::make_unique<texture::SpectralSurfaceGenerator>(psd, spec);
    } else {
      texture::SeedSurfaceRequest r;
      r.nx = nx;
      r.ny = ny;
      r.dx = r.dy = h;
      r.correlation_x = s.real("surface.correlation_x");
      r.correlation_y = s.real("surface.correlation_y");
      r.sigma = s.real("surface.sigma");
      // Seed 001 §3.1 and Eq. 10: sigma and the correlation lengths (isotropic) are the measured
      // profiles' unless [surface] gives them.
      const auto measured = profile_derived_surface_keys(s);
      if (!measured.empty()) {
        const texture::EstimatedPsd est = profile_estimate(s);
        for (const auto& k : measured) {
          if (k == "sigma") r.sigma = est.sigma;
          if (std::isfinite(est.correlation_length)) {
            if (k == "correlation_x") r.correlation_x = est.correlation_length;
            if (k == "correlation_y") r.correlation_y = est.correlation_length;
          }
        }
      }
      r.amplitudes = study_amplitudes(s);
      g.seed = std::make_unique<texture::SeedSurfaceGenerator>(psd, r);
    }
  } catch (const std::exception& e) {  // invalid_argument from the spec, domain_error from a table PSD
    throw config_error(
        grid_message(LineGeneratorKeys{{}, s.where("surface.spacing"), s.where("texture.table_extension")}, e));
  }
  return g;
}

}  // namespace rollspec::texture_io
