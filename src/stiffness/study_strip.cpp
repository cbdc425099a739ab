#include "src/stiffness/study_strip.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <sstream>

#include "kernels/contact/answer_error.hpp"
#include "kernels/contact/version.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/ensemble/checkpoint.hpp"
#include "src/error.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::stiffness {

texture::Surface study_strip(const TableStudy& ts, const StripGrid& grid, std::uint64_t index) {
  texture::SpectralSurfaceSpec spec;
  spec.nx = grid.nx;
  spec.ny = grid.ny;
  spec.dx = spec.dy = grid.cell;
  spec.amplitudes = ts.amplitudes;
  spec.anisotropy = ts.surface.anisotropy;
  // A derived cell may be coarser than half the texture's shortest wavelength: the finer roughness
  // is dropped (the plan says from which wavelength); a cell the study set must resolve it.
  spec.allow_truncation = grid.allow_truncation;
  texture::Surface strip;
  try {
    texture_io::SurfaceGenerator g;
    g.spectral = std::make_unique<texture::SpectralSurfaceGenerator>(ts.psd, spec);
    g.generate(ts.stiffness.table_seed, index, strip, true);
  } catch (const std::exception& e) {
    ts.surface.spacing_origin.refuse(e.what());
  }
  return strip;
}

std::string strip_inputs_text(const TableStudy& ts, const StripGrid& g) {
  std::ostringstream in;
  const study::StiffnessSection& st = ts.stiffness;
  for (const study::KeyValue* v :
       {&st.key_value(st.solver.hardness), &st.key_value(st.solver.tolerance), &st.key_value(st.solver.max_iterations)})
    in << v->key << " = " << v->text << "\n";
  in << "seed = " << st.value_text(st.table_seed) << "\n\n[surface]\nny = " << g.ny
     << "\nspacing = " << io::exact_text(g.cell) << "\nanisotropy = " << ts.surface.text("anisotropy")
     << "\ntruncate = " << (g.allow_truncation ? "allowed" : "refused")
     << "\nmode power = rectangular cell mean (kernels/texture Eq. 26a)"
     << "\n\n[texture]\n";
  for (const auto& [key, value] : ts.surface.texture_texts) in << key << " = " << value << "\n";
  in << "input files fingerprint = " << ts.psd_fingerprint << "\n";
  return in.str();
}

std::string ball_inputs_text(const TableStudy& ts, double radius, double e_star, double load) {
  std::ostringstream in;
  in << "[contact kernel]\nversion = " << contact::kernel_version << "\n\n[ball]\nradius = " << io::exact_text(radius)
     << "\neffective_modulus = " << io::exact_text(e_star) << "\nload = " << io::exact_text(load)
     << "\nshape = " << ts.stiffness.value_text(ts.stiffness.shape);
  return in.str();
}

double path_psd_at(const std::vector<double>& psd_wavenumber, const std::vector<double>& psd, double k) {
  if (psd_wavenumber.size() < 2 || k > psd_wavenumber.back()) return 0.0;
  if (k <= psd_wavenumber[1]) return psd[1];
  if (k == psd_wavenumber.back()) return psd.back();  // upper_bound would point past the end
  const auto it = std::upper_bound(psd_wavenumber.begin(), psd_wavenumber.end(), k);
  const std::size_t j = static_cast<std::size_t>(it - psd_wavenumber.begin());
  const double ka = psd_wavenumber[j - 1], kb = psd_wavenumber[j], ga = psd[j - 1], gb = psd[j];
  if (ga <= 0.0 || gb <= 0.0) return ga + (gb - ga) * (k - ka) / (kb - ka);
  return ga * std::pow(k / ka, std::log(gb / ga) / std::log(kb / ka));
}

double checked_band_error_db(const std::vector<double>& residuals, double step, std::size_t samples,
                             const std::vector<double>& psd_wavenumber, const std::vector<double>& psd, double lower,
                             double upper, std::size_t first_bin) {
  const std::size_t m = residuals.size();
  if (m < 2 || samples < 2 || psd_wavenumber.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean = 0.0, ss = 0.0;
  for (double r : residuals) mean += r / static_cast<double>(m);
  for (double r : residuals) ss += (r - mean) * (r - mean);
  // S_e per rad/m of a white error (BF-9c), on the table's own Welch plan, whose frequency unit is cycles/m.
  const double variance = ss / static_cast<double>(m - 1);
  const double error_psd = 2.0 * variance * step / (2.0 * M_PI);
  spectral::WelchConfig wc;
  wc.sample_rate = 1.0 / step;
  wc.segment = static_cast<std::size_t>(std::lround(2.0 * M_PI / ((psd_wavenumber[1] - psd_wavenumber[0]) * step)));
  wc.overlap = wc.segment / 2;
  return contact::white_error_band_db(wc, samples, psd, std::min(first_bin, psd.size() - 1), error_psd,
                                      lower / (2.0 * M_PI), upper / (2.0 * M_PI));
}

double strip_load_tolerance(const contact::SolverOptions& options) {
  return std::max(1e-10, 100.0 * options.tolerance);
}

}  // namespace rollspec::stiffness
