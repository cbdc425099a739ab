#pragma once
// Study keys of the roughness PSD ([texture]) and of isotropic surfaces ([surface]), shared by
// every scene that needs them, and their translation into texture-kernel objects. Input files
// (PSD tables, measured profiles) are read and checked here, with messages naming file, line,
// column and value.
#include <memory>
#include <string>
#include <vector>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/psd.hpp"
#include "kernels/texture/seed_surface.hpp"
#include "kernels/texture/spectral_surface.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::texture_io {

// The functions taking a KeyReader parse the sections and forward to the section-taking ones.

// [texture]: PSD source and amplitudes (the line geometry comes from the scene); TextureSection::keys().
std::vector<study::KeySpec> psd_keys();
// [surface]: grid and method of isotropic surfaces; SurfaceSection::keys().
std::vector<study::KeySpec> surface_keys();

// The roughness PSD a study describes (table, measured profiles, self-affine, ISO 8608, ISO 3095).
texture::Psd study_psd(const study::TextureSection& s);
texture::Psd study_psd(const study::KeyReader& s);
spectral::Amplitudes study_amplitudes(const study::TextureSection& s);
spectral::Amplitudes study_amplitudes(const study::KeyReader& s);

// What a line-texture generator takes from the study: the [texture] amplitudes, and where the
// spacing key and [texture] table_extension were set (for the generator's errors).
struct LineGeneratorKeys {
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;
  std::string spacing_where, extension_where;
  // For the advice of grid errors: the spacing key ("[lines] spacing"), the [texture] source and
  // table_extension, and the rolling speed where the scene has one (0: none).
  std::string spacing_key;
  std::optional<study::TextureSource> source;  // none: the scene has no [texture]
  texture::Extension extension = texture::Extension::error;
  double speed = 0.0;
  std::string speed_key;
  static LineGeneratorKeys of(const study::TextureSection& t, const study::KeyOrigin& spacing,
                              const std::string& spacing_key);
};
// Line-texture generator of `samples` samples at `spacing` from the PSD and those keys; truncate:
// harmonics above pi/spacing are dropped instead of refused. Errors name the spacing key.
std::unique_ptr<texture::LineTextureGenerator> line_generator(const LineGeneratorKeys& keys, const texture::Psd& psd,
                                                              double spacing, std::size_t samples,
                                                              bool truncate = true);

// The measured profile files of [texture] profiles (empty for other sources or scenes without [texture]).
std::vector<std::string> profile_files(const study::TextureSection& s);
std::vector<std::string> profile_files(const study::KeyReader& s);

// Seed-method [surface] keys (sigma, correlation_x, correlation_y) that are not set and so take the
// measured profiles' values (seed 001 §3.1, Eq. 10); empty unless source = profiles and method = seed.
// Cached tables hash this list: the canonical text shows such a key at its default.
std::vector<std::string> profile_derived_surface_keys(const study::TextureSection& t, const study::SurfaceSection& f);
std::vector<std::string> profile_derived_surface_keys(const study::KeyReader& s);

// Contents of every input file the PSD depends on, for hashes of cached tables.
std::string psd_input_fingerprint(const study::TextureSection& s);
std::string psd_input_fingerprint(const study::KeyReader& s);

// Surface generator of a study's [surface] section: exactly one of the two is set.
struct SurfaceGenerator {
  std::unique_ptr<texture::SpectralSurfaceGenerator> spectral;
  std::unique_ptr<texture::SeedSurfaceGenerator> seed;
  std::size_t random_count() const;  // U(0,1) numbers per surface
  // Draws from Philox (seed, realisation, surface streams) and fills out.
  // Draws from the realisation surface streams, or with `table` from the contact tables' own family.
  void generate(std::uint64_t seed_value, std::uint64_t realisation, texture::Surface& out, bool table = false) const;
};
// [surface] with the seed-method keys it leaves at their default resolved from the measured profiles
// (profile_derived_surface_keys; the profiles are read here), so a generator made from it reads no file.
study::SurfaceSection with_profile_values(const study::TextureSection& t, study::SurfaceSection s);
// `s` as with_profile_values gives it.
SurfaceGenerator surface_generator(const study::TextureSection& t, const study::SurfaceSection& s,
                                   const texture::Psd& psd);
SurfaceGenerator study_surface_generator(const study::KeyReader& s, const texture::Psd& psd);

}  // namespace rollspec::texture_io
