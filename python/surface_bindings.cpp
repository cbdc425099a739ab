// rollspec.surfaces: line textures from a tabulated PSD (kernels/texture/line_texture.hpp, D-3, README
// Eq. 12-14), drawn from the streams `rollspec texture` draws its lines from, so a seed and an index give the
// command's bits.
#include <cmath>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/tabulated_psd.hpp"
#include "python/bindings.hpp"
#include "src/io/number_text.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/study/sections/amplitudes_choice.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::python {

namespace {

template <class E, std::size_t N>
E choice(const study::ChoiceTable<E, N>& table, const std::string& name, const std::string& text) {
  std::string allowed;
  for (const auto& c : table) {
    if (text == c.spelling) return c.value;
    allowed += (allowed.empty() ? "" : ", ") + std::string(c.spelling);
  }
  refuse(name, "'" + text + "'", "unknown", allowed);
}

py::dict line(const py::handle& wavenumber, const py::handle& psd, double spacing, long long samples,
              unsigned long long seed, unsigned long long index, const std::string& amplitudes,
              const std::string& extension) {
  const Array k = finite_array(wavenumber, "wavenumber", 1, 2, "a 1-D array of increasing wavenumbers > 0 (rad/m)");
  const Array g = finite_array(psd, "psd", 1, 2, "a 1-D array of one-sided PSD values >= 0 (m^3), one per wavenumber");
  if (k.size() != g.size())
    refuse("psd", io::counted(static_cast<unsigned long long>(g.size()), "value"),
           "not one per wavenumber (" + std::to_string(k.size()) + ")", "as many values as wavenumbers");
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    refuse("spacing", io::number_text(spacing), "not a spacing", "a finite number > 0 (m)");
  if (samples < 8 || samples > (1LL << 26))
    refuse("samples", std::to_string(samples), "out of range",
           "a whole number in [8, 2^26] ([lines] length / spacing)");
  texture::LineTextureSpec spec;
  spec.spacing = spacing;
  spec.samples = static_cast<std::size_t>(samples);
  spec.amplitudes = choice(study::kAmplitudes, "amplitudes", amplitudes);
  const texture::Extension ext = choice(study::kTableExtensions, "extension", extension);
  std::vector<double> heights(spec.samples);
  std::unique_ptr<texture::LineTextureGenerator> lines;
  try {  // the table's and the sampling check's refusals (std::invalid_argument, std::domain_error)
    lines = std::make_unique<texture::LineTextureGenerator>(
        texture::TabulatedPsd({k.data(), k.data() + k.size()}, {g.data(), g.data() + g.size()}, ext).to_psd(), spec);
  } catch (const std::logic_error& e) {
    throw py::value_error(std::string("wavenumber, psd: ") + e.what());
  }
  {
    py::gil_scoped_release unlocked;
    std::vector<double> up(lines->harmonics()), ua(lines->harmonics());
    // `rollspec texture`'s streams for line `index` (cli/texture_command.cpp).
    rng::PhiloxStream(seed, index, rng::Stream::roughness_phase).uniform_open(up.data(), up.size());
    rng::PhiloxStream(seed, index, rng::Stream::roughness_amplitude).uniform_open(ua.data(), ua.size());
    lines->generate(up.data(), ua.data(), heights.data());
  }
  py::dict d;
  const auto n = static_cast<py::ssize_t>(heights.size());
  d["heights"] = to_numpy(std::move(heights), {n});
  d["spacing"] = spacing;
  std::vector<double> kj = lines->wavenumbers(), gj = lines->target_psd();
  const auto h = static_cast<py::ssize_t>(kj.size());
  d["wavenumber"] = to_numpy(std::move(kj), {h});
  d["target_psd"] = to_numpy(std::move(gj), {h});
  d["target_rms"] = std::sqrt(lines->target_variance());
  d["period"] = lines->period();
  d["seed"] = seed;
  d["index"] = index;
  return d;
}

const char* const kLineDoc = R"(A line texture h(x_i), x_i = i * spacing, with a given one-sided PSD (D-3).

h(x) = sum_j A_j cos(k_j x + phi_j), k_j = j dk, dk = 2 pi / (P spacing), A_j = sqrt(2 G(k_j) dk)
(deterministic) or that times sqrt(-ln u_j) (rayleigh: Gaussian heights), phi_j = 2 pi v_j, by one
inverse FFT of period P (the smallest even 2^a 3^b 5^c 7^d >= samples); the first `samples` values.
G is the table (wavenumber, psd) with log-log interpolation (a [texture] table). The uniforms u, v are
Philox streams keyed by (seed, index), the ones `rollspec texture` draws its line `index` from with
[study] seed = seed: the same table, spacing and length give the command's heights bit for bit.

Parameters
----------
wavenumber : array_like, 1-D
    Table wavenumbers k (rad/m), increasing, > 0.
psd : array_like, 1-D
    One-sided PSD G(k) (m^3, i.e. m^2 per rad/m), >= 0.
spacing : float
    Sample spacing dx (m); dx <= pi / k_max unless the table ends below.
samples : int
    Number of heights, 8 to 2^26.
seed, index : int
    The stream's key: [study] seed and the line's index.
amplitudes : str
    'rayleigh' or 'deterministic' ([texture] amplitudes).
extension : str
    The PSD outside the table: 'error', 'constant', 'power_law', 'zero' ([texture] table_extension).

Returns
-------
dict
    heights (m), spacing (m), wavenumber (rad/m, the harmonics j dk), target_psd (m^3, G(j dk)),
    target_rms (m), period (P, samples), seed, index.
)";

}  // namespace

void bind_surfaces(py::module_& m) {
  using py::arg;
  m.def("line", &line, kLineDoc, arg("wavenumber"), arg("psd"), arg("spacing"), arg("samples"), py::kw_only(),
        arg("seed"), arg("index") = 0, arg("amplitudes") = "rayleigh", arg("extension") = "error");
}

}  // namespace rollspec::python
