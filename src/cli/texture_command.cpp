// rollspec texture: line textures and isotropic surfaces of a study's roughness PSD (design §3).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/statistics.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/output_target.hpp"
#include "src/io/provenance.hpp"
#include "src/io/references.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/scenes/memory_estimate.hpp"
#include "src/run/run_phases.hpp"
#include "src/scenes/scene.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/study/sections/lines_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/profile_source.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::cli {

using run::resolve_study;

namespace fs = std::filesystem;

namespace {
void print_statistics(const char* what, std::size_t i, const texture::HeightStatistics& s, bool surface, bool quiet) {
  if (quiet) return;
  std::printf("%-9s %6zu %12.5g %10.4f %10.4f %14.5g", what, i, s.rms, s.skewness, s.kurtosis, s.correlation_length_x);
  if (surface) std::printf(" %14.5g", s.correlation_length_y);
  std::printf("\n");
}
// Heights or statistics that overflowed: the PSD is too large for double precision. Refused,
// naming where the PSD comes from, before anything is written.
void refuse_overflow(const study::TextureSection& s, const char* what, std::size_t i,
                     const texture::HeightStatistics& st, const double* z, std::size_t n) {
  bool finite = std::isfinite(st.rms) && (st.rms == 0.0 || (std::isfinite(st.skewness) && std::isfinite(st.kurtosis)));
  for (std::size_t k = 0; k < n && finite; ++k) finite = std::isfinite(z[k]);
  if (finite) return;
  using study::TextureSource;
  const TextureSource source = s.source;
  std::string where = s.origin(s.source).where;
  if (source == TextureSource::table) where = s.table_path + " (" + where + ")";
  if (source == TextureSource::profiles) where = s.origin(s.profile_paths).where;
  const std::string buf =
      io::formatted(": %s %zu has non-finite heights or statistics (rms %g m, skewness %g, kurtosis %g)", what, i,
                    st.rms, st.skewness, st.kurtosis);
  const std::string m = where + buf +
                        ": the PSD's heights overflow double precision; allowed: a PSD whose heights and their fourth "
                        "powers stay finite (rms height well below 1e50 m)";
  if (source == TextureSource::table || source == TextureSource::profiles) throw data_error(m);
  throw config_error(m);
}
// [texture] source = profiles: what the scans resolve and what they leave unresolved.
void say_profile_note(const study::TextureSection& tex, bool quiet) {
  const std::string note = texture_io::profile_note(tex);
  if (!note.empty() && !quiet) std::fprintf(stderr, "rollspec texture: note: %s\n", note.c_str());
}
// The isotropic surfaces of realisations 0..n_surf-1: their statistics printed, their heights written.
void write_surfaces(io::Hdf5Writer& w, const texture_io::SurfaceGenerator& surfaces, std::uint64_t seed,
                    std::size_t n_surf, const study::TextureSection& tex, const std::string& method, bool list,
                    bool quiet) {
  texture::Surface surf;
  std::vector<double> heights;
  std::vector<texture::HeightStatistics> stats;
  for (std::size_t r = 0; r < n_surf; ++r) {
    surfaces.generate(seed, r, surf);
    heights.insert(heights.end(), surf.heights.begin(), surf.heights.end());
    const auto st = texture::surface_statistics(surf);
    refuse_overflow(tex, "surface", r, st, surf.heights.data(), surf.heights.size());
    print_statistics("surface", r, st, true, !list);
    stats.push_back(st);
  }
  print_statistics("surf_mean", n_surf, texture::mean_statistics(stats), true, quiet);
  if (n_surf >= 2) print_statistics("surf_std", n_surf, texture::std_statistics(stats), true, quiet);
  std::vector<double> xs(surf.nx), ys(surf.ny);
  for (std::size_t i = 0; i < surf.nx; ++i) xs[i] = surf.dx * static_cast<double>(i);
  for (std::size_t i = 0; i < surf.ny; ++i) ys[i] = surf.dy * static_cast<double>(i);
  w.write("/surface/x", {surf.nx}, xs.data(), "m", "grid x");
  w.write("/surface/y", {surf.ny}, ys.data(), "m", "grid y");
  w.write("/surface/heights", {n_surf, surf.ny, surf.nx}, heights.data(), "m",
          "surface heights z(y, x) per realisation");
  w.make_scale("/surface/x", "x");
  w.make_scale("/surface/y", "y");
  w.attach_scale("/surface/heights", "/surface/y", 1);
  w.attach_scale("/surface/heights", "/surface/x", 2);
  w.attribute("/surface", "method", method);
}

}  // namespace

int texture_command(const Args& args) {
  const std::string usage =
      "usage: rollspec texture STUDY.ini [--out FILE.h5] [--count N] [--list | --quiet] [--set section.key=value ...]\n"
      "\n"
      "Generates the line textures ([lines]) and isotropic surfaces ([surface]) of the study's roughness\n"
      "PSD ([texture]) for realisations 0..N-1 (Philox keyed by seed and realisation) and writes\n"
      "/texture/x, /texture/lines, /texture/psd_wavenumber, /texture/psd_target, /texture/psd_realised,\n"
      "/surface/x, /surface/y, /surface/heights, /profiles (measured scans). Prints the mean and the standard\n"
      "deviation over realisations of rms, skewness, kurtosis and correlation lengths (--list: every one too).\n"
      "The study's scene must be `texture`.";
  StudyCommandOptions cl;
  std::string out;
  long long count = -1;
  cl.options.add_options()("list", "print the statistics of every realisation, not only their mean and spread")(
      "quiet,q", "print nothing but errors")("out,o", po::value(&out),
                                             "texture file (default: the study's name with .h5)")(
      "count,n", po::value(&count), "realisations of lines and of surfaces (overrides [lines] count, [surface] count)")(
      "force",
      "replace an existing --out file even if it is not a rollspec texture file, and run a study whose "
      "memory estimate exceeds the available memory");
  if (!cl.parse(args, usage)) return 0;
  if (out.empty() && cl.vm.count("out")) throw usage_error("--out is empty; allowed: the path of the file to write");
  const bool quiet = cl.vm.count("quiet") > 0, list = cl.vm.count("list") > 0;
  if (quiet && list) throw usage_error("--list and --quiet: allowed: one of them");
  if (cl.vm.count("count") && (count < 0 || count > 1000000))
    throw usage_error("--count " + std::to_string(count) + ": allowed: a whole number in [0, 1000000]");

  const study::Study s = resolve_study(cl.study);
  const auto study_keys = study::StudySection::parse(s);
  const auto texture_scene = [](const scenes::SceneInfo& i) { return i.command == scenes::SceneCommand::texture; };
  if (!texture_scene(scenes::find_scene(study_keys.scene)))
    study_keys.origin(study_keys.scene)
        .refuse("rollspec texture needs a study of scene " + scenes::scenes_with(texture_scene) + " (this one is " +
                study_keys.scene + ")");
  if (out.empty()) out = fs::path(cl.study.file).stem().string() + ".h5";
  if (count >= 0) {  // --count overrides both counts: estimate with it
    cl.study.sets.push_back(study::LinesSection::key(&study::LinesSection::count) + "=" + std::to_string(count));
    cl.study.sets.push_back(study::SurfaceSection::key(&study::SurfaceSection::count) + "=" + std::to_string(count));
  }
  scenes::check_memory(count >= 0 ? resolve_study(cl.study) : s, 1, cl.vm.count("force") > 0);
  const auto seed = study_keys.seed;
  const auto tex = study::TextureSection::parse(s);
  const auto line_keys = study::LinesSection::parse(s);
  const auto surface_keys = study::SurfaceSection::parse(s);
  const std::size_t n_lines = count >= 0 ? static_cast<std::size_t>(count) : static_cast<std::size_t>(line_keys.count);
  const std::size_t n_surf =
      count >= 0 ? static_cast<std::size_t>(count) : static_cast<std::size_t>(surface_keys.count);

  const texture::Psd psd = texture_io::study_psd(tex);
  say_profile_note(tex, quiet);
  const double spacing = line_keys.spacing;
  const double samples = std::floor(line_keys.length / spacing);
  if (samples < 8 || samples > 1 << 26)
    line_keys.origin(line_keys.length)
        .refuse("gives " + std::to_string(samples) + " samples at [lines] spacing; allowed: 8 to 2^26");
  const auto lines = texture_io::line_generator(
      texture_io::LineGeneratorKeys::of(tex, line_keys.origin(line_keys.spacing), "[lines] spacing"), psd, spacing,
      static_cast<std::size_t>(samples), false);
  const texture::LineTextureSpec& ls = lines->spec();
  const texture_io::SurfaceGenerator surfaces =
      n_surf ? texture_io::surface_generator(tex, texture_io::with_profile_values(tex, surface_keys), psd)
             : texture_io::SurfaceGenerator{};

  io::OutputTarget target{out, "rollspec-texture"};
  target.force = cl.vm.count("force") > 0;
  target.inputs = s.input_files();
  for (const auto& p : texture_io::profile_files(tex)) target.inputs.push_back(p);
  target.check_kind = false;  // the file's kind is checked before the commit, after the data are known good
  io::Hdf5Writer w(io::check_output_target(target));
  io::write_provenance(w, "rollspec-texture", "1.0", s.canonical_text(), seed);
  io::write_references(w, scenes::texture_surface_references(s, static_cast<long long>(n_surf)));
  w.attribute("/", "psd", psd.description);
  texture_io::write_profile_record(w, "/profiles", tex);
  // Per-realisation rows name their index; the summary rows, how many realisations they summarise.
  if (!quiet)
    std::printf("%-9s %6s %12s %10s %10s %14s %14s\n", "kind", list ? "index" : "count", "rms_m", "skewness",
                "kurtosis", "corr_len_x_m", "corr_len_y_m");
  if (n_lines) {
    const std::size_t n = ls.samples, nh = lines->harmonics();
    std::vector<double> x(n), all(n_lines * n), up(nh), ua(nh);
    for (std::size_t i = 0; i < n; ++i) x[i] = ls.spacing * static_cast<double>(i);
    std::vector<texture::Profile> profiles(n_lines);
    std::vector<texture::HeightStatistics> stats;
    spectral::SynthesisScratch scratch = lines->make_scratch();
    for (std::size_t r = 0; r < n_lines; ++r) {
      rng::PhiloxStream(seed, r, rng::Stream::roughness_phase).uniform_open(up.data(), nh);
      rng::PhiloxStream(seed, r, rng::Stream::roughness_amplitude).uniform_open(ua.data(), nh);
      lines->generate(up.data(), ua.data(), all.data() + r * n, scratch);
      const auto st = texture::line_statistics(all.data() + r * n, n, ls.spacing);
      refuse_overflow(tex, "line", r, st, all.data() + r * n, n);
      print_statistics("line", r, st, false, !list);
      stats.push_back(st);
      profiles[r].x = x;
      profiles[r].z.assign(all.begin() + static_cast<std::ptrdiff_t>(r * n),
                           all.begin() + static_cast<std::ptrdiff_t>((r + 1) * n));
    }
    // Mean over realisations; a correlation length that never reaches 1/e (NaN) is left out.
    print_statistics("line_mean", n_lines, texture::mean_statistics(stats), false, quiet);
    if (n_lines >= 2) print_statistics("line_std", n_lines, texture::std_statistics(stats), false, quiet);
    w.write("/texture/x", {n}, x.data(), "m", "position along the line");
    w.write("/texture/lines", {n_lines, n}, all.data(), "m", "line texture heights, one realisation per row");
    w.make_scale("/texture/x", "x");
    w.attach_scale("/texture/lines", "/texture/x", 1);
    const auto k = lines->wavenumbers();
    w.write("/texture/psd_wavenumber", {k.size()}, k.data(), "rad/m", "harmonics j dk of the synthesis");
    w.write("/texture/psd_target", {k.size()}, lines->target_psd().data(), "m^3", "target one-sided PSD G(k_j)");
    if (n_lines >= 2) {
      const auto est = texture::profile_psd(profiles);
      w.write("/texture/psd_realised_wavenumber", {est.wavenumber.size()}, est.wavenumber.data(), "rad/m",
              "wavenumbers of the realised PSD (Hann periodogram of each line)");
      w.write("/texture/psd_realised", {est.psd.size()}, est.psd.data(), "m^3",
              "mean Hann-windowed periodogram of the lines (trend removed)");
    }
    w.attribute("/texture", "target_rms", std::sqrt(lines->target_variance()));
  }
  if (n_surf)
    write_surfaces(w, surfaces, seed, n_surf, tex, study::spelling_of(study::kSurfaceMethods, surface_keys.method),
                   list, quiet);
  target.check_kind = true;
  io::check_output_target(target);
  w.commit();
  if (!quiet)
    std::fprintf(stderr, "wrote %s (%zu line%s, %zu surface%s)\n", out.c_str(), n_lines, n_lines == 1 ? "" : "s",
                 n_surf, n_surf == 1 ? "" : "s");
  return 0;
}

}  // namespace rollspec::cli
