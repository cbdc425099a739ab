#include "src/stiffness/study_strip.hpp"

#include <exception>
#include <limits>
#include <memory>
#include <sstream>

#include "src/ensemble/checkpoint.hpp"
#include "src/error.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/study/study.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::stiffness {

texture::Surface study_strip(const study::Study& s, const StripGrid& grid, std::uint64_t index) {
  texture::SpectralSurfaceSpec spec;
  spec.nx = grid.nx;
  spec.ny = grid.ny;
  spec.dx = spec.dy = grid.cell;
  spec.amplitudes = texture_io::study_amplitudes(s);
  spec.anisotropy = s.real("surface.anisotropy");
  // A derived cell may be coarser than half the texture's shortest wavelength: the finer roughness
  // is dropped (the plan says from which wavelength); a cell the study set must resolve it.
  spec.allow_truncation = grid.allow_truncation;
  texture::Surface strip;
  try {
    texture_io::SurfaceGenerator g;
    g.spectral = std::make_unique<texture::SpectralSurfaceGenerator>(texture_io::study_psd(s), spec);
    g.generate(static_cast<std::uint64_t>(s.integer("study.seed")), index, strip);
  } catch (const std::exception& e) {
    throw config_error(s.where("surface.spacing") + ": " + e.what());
  }
  return strip;
}

std::string strip_inputs_text(const study::Study& s, const StripGrid& g) {
  std::ostringstream in;
  for (const char* k : {"hardness", "tolerance", "max_iterations"}) in << k << " = " << s.text(std::string("stiffness.") + k) << "\n";
  in << "seed = " << s.text("study.seed") << "\n\n[surface]\nny = " << g.ny << "\nspacing = " << num(g.cell)
     << "\nanisotropy = " << s.text("surface.anisotropy") << "\ntruncate = " << (g.allow_truncation ? "allowed" : "refused")
     << "\n\n[texture]\n";
  for (const auto& k : texture_io::psd_keys())
    if (k.key != "table" && k.key != "profiles") in << k.key << " = " << s.text(k.full_name()) << "\n";
  in << "input files fingerprint = " << hex16(ensemble::fnv1a64(texture_io::psd_input_fingerprint(s))) << "\n";
  return in.str();
}

contact::SolverOptions strip_solver_options(const study::Study& s) {
  contact::SolverOptions opts;
  const double h = s.real("stiffness.hardness");
  opts.hardness = h > 0.0 ? h : std::numeric_limits<double>::infinity();
  opts.tolerance = s.real("stiffness.tolerance");
  opts.max_iterations = static_cast<int>(s.integer("stiffness.max_iterations"));
  return opts;
}

contact::BallShape strip_ball_shape(const study::Study& s) {
  return s.text("stiffness.shape") == "sphere" ? contact::BallShape::Sphere : contact::BallShape::Paraboloid;
}

}  // namespace rollspec::stiffness
