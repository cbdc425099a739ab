// rollspec.surfaces: line textures (kernels/texture/line_texture.hpp, D-3, README Eq. 12-14) and isotropic
// surfaces (spectral D-5 and seed line-sum D-4, the engine's texture_io::SurfaceGenerator) from a tabulated
// PSD, drawn from the streams `rollspec texture` draws its lines and surfaces from, so a seed and an index
// give the command's bits.
#include <cmath>
#include <optional>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/tabulated_psd.hpp"
#include "python/bindings.hpp"
#include "python/surface_draws.hpp"
#include "src/io/number_text.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/study/sections/amplitudes_choice.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::python {

namespace {

// The table (wavenumber, psd) as a [texture] table: log-log interpolation, `extension` outside. The
// arrays are checked here; the table's own refusals come back from `make`.
struct TablePsd {
  Array k, g;
  texture::Extension extension;
};

TablePsd table_arrays(const py::handle& wavenumber, const py::handle& psd, const std::string& extension) {
  TablePsd t{finite_array(wavenumber, "wavenumber", 1, 2, "a 1-D array of increasing wavenumbers > 0 (rad/m)"),
             finite_array(psd, "psd", 1, 2, "a 1-D array of one-sided PSD values >= 0 (m^3), one per wavenumber"),
             choice(study::kTableExtensions, "extension", extension)};
  if (t.k.size() != t.g.size())
    refuse("psd", io::counted(static_cast<unsigned long long>(t.g.size()), "value"),
           "not one per wavenumber (" + std::to_string(t.k.size()) + ")", "as many values as wavenumbers");
  return t;
}

// `make(psd)` with the table's PSD: the table's and the generator's refusals (std::invalid_argument,
// std::domain_error) as ValueError.
template <class Make>
auto with_table_psd(const TablePsd& t, Make make) {
  try {
    return make(
        texture::TabulatedPsd({t.k.data(), t.k.data() + t.k.size()}, {t.g.data(), t.g.data() + t.g.size()}, t.extension)
            .to_psd());
  } catch (const std::logic_error& e) {
    throw py::value_error(std::string("wavenumber, psd: ") + e.what());
  }
}

// The table's PSD, its refusals (std::invalid_argument, std::domain_error) as ValueError.
texture::Psd table_psd(const TablePsd& t) {
  return with_table_psd(t, [](const texture::Psd& g) { return g; });
}

py::dict line(const py::handle& wavenumber, const py::handle& psd, double spacing, long long samples,
              unsigned long long seed, unsigned long long index, const std::string& amplitudes,
              const std::string& extension) {
  const TablePsd table = table_arrays(wavenumber, psd, extension);
  return draw_line(table_psd(table), spacing, samples, seed, index, amplitudes, "wavenumber, psd: ");
}

py::dict isotropic(const py::handle& wavenumber, const py::handle& psd, double spacing, long long nx,
                   const std::optional<long long>& ny_arg, unsigned long long seed, unsigned long long index,
                   const std::string& method, const std::string& amplitudes, const std::string& extension,
                   double anisotropy, double sigma, double correlation_x, double correlation_y) {
  const TablePsd table = table_arrays(wavenumber, psd, extension);
  IsotropicDraw k;
  k.spacing = spacing, k.nx = nx, k.ny = ny_arg, k.seed = seed, k.index = index, k.method = method;
  k.amplitudes = amplitudes, k.anisotropy = anisotropy;
  k.sigma = surface_key("sigma", sigma);
  k.correlation_x = surface_key("correlation_x", correlation_x);
  k.correlation_y = surface_key("correlation_y", correlation_y);
  return draw_isotropic(table_psd(table), k, "wavenumber, psd: ");
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

const char* const kIsotropicDoc =
    R"(An isotropic rough surface z(x, y) on an nx x ny grid from a line PSD, as [surface] makes it.

method 'spectral' (D-5, README Eq. 26-28): the 2D Fourier filter of the isotropic PSD C(q) that
projects to the line PSD G (inverse Abel transform, Eq. 18-21), stretched by `anisotropy` (the
correlation length ratio x / y, area preserving, Eq. 27); one inverse FFT; mean square
(2 pi)^-2 sum_q C dqx dqy (target_rms^2; exact with deterministic amplitudes). method 'seed' (D-4,
seed 001 Eq. 9-10, README Eq. 29-32): sums of line textures from G over boxes whose lengths put the
1/e correlation lengths nearest `correlation_x`, `correlation_y`, rescaled to rms `sigma` exactly.
G is the table (wavenumber, psd) with log-log interpolation (a [texture] table). The uniforms are
Philox streams keyed by (seed, index), the ones `rollspec texture` draws its surface `index` from with
[study] seed = seed: the same table and keys give the command's heights bit for bit.

Parameters
----------
wavenumber : array_like, 1-D
    Table wavenumbers k (rad/m), increasing, > 0.
psd : array_like, 1-D
    One-sided line PSD G(k) (m^3), >= 0.
spacing : float
    Grid spacing dx = dy (m) ([surface] spacing); the grid must resolve the PSD's last wavenumber
    (stretched by the anisotropy) unless the table ends below.
nx, ny : int
    Grid points along x and y, even ([surface] nx, ny); ny defaults to nx.
seed, index : int
    The stream's key: [study] seed and the surface's index (realisation).
method : str
    'spectral' or 'seed' ([surface] method).
amplitudes : str
    'rayleigh' or 'deterministic' ([texture] amplitudes).
extension : str
    The PSD outside the table: 'error', 'constant', 'power_law', 'zero' ([texture] table_extension).
anisotropy : float
    Correlation length ratio x / y, spectral method ([surface] anisotropy).
sigma, correlation_x, correlation_y : float
    Seed method: rms height (m) and 1/e correlation lengths (m) ([surface] sigma, correlation_x,
    correlation_y); defaults those of the keys.

Returns
-------
dict
    heights (m, shape (ny, nx): heights[iy, ix] = z(ix dx, iy dy), a realisation of
    /surface/heights), spacing (m), method, seed, index; spectral: target_rms (m); seed: box (the box
    lengths n, m in samples) and expected_correlation (m, Eq. 31 at those lengths).
)";

}  // namespace

double surface_key(const std::string& name, double value) {
  static const auto keys = study::SurfaceSection::keys();
  return key_value(key_spec(keys, "surface." + name), value);
}

std::size_t even_side(const std::string& name, long long n) {
  surface_key(name, static_cast<double>(n));
  if (n % 2) refuse(name, std::to_string(n), "odd", "an even number of grid points ([surface] " + name + ")");
  return static_cast<std::size_t>(n);
}

py::dict draw_line(const texture::Psd& psd, double spacing, long long samples, unsigned long long seed,
                   unsigned long long index, const std::string& amplitudes, const std::string& refused_as) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    refuse("spacing", io::number_text(spacing), "not a spacing", "a finite number > 0 (m)");
  if (samples < 8 || samples > (1LL << 26))
    refuse("samples", std::to_string(samples), "out of range",
           "a whole number in [8, 2^26] ([lines] length / spacing)");
  // `rollspec texture`'s generator: no harmonic above pi / spacing dropped (texture_command.cpp).
  texture::LineTextureSpec spec;
  spec.spacing = spacing;
  spec.samples = static_cast<std::size_t>(samples);
  spec.amplitudes = choice(study::kAmplitudes, "amplitudes", amplitudes);
  spec.allow_truncation = false;
  std::unique_ptr<texture::LineTextureGenerator> lines;
  std::vector<double> heights(spec.samples);
  {
    py::gil_scoped_release unlocked;
    try {
      lines = std::make_unique<texture::LineTextureGenerator>(psd, spec);
    } catch (const std::logic_error& e) {
      throw py::value_error(refused_as + e.what());
    }
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

py::dict draw_isotropic(const texture::Psd& psd, const IsotropicDraw& k, const std::string& refused_as) {
  const double h = surface_key("spacing", k.spacing);
  const std::size_t sx = even_side("nx", k.nx), sy = even_side("ny", k.ny.value_or(k.nx));
  const study::SurfaceMethod m = choice(study::kSurfaceMethods, "method", k.method);
  const spectral::Amplitudes a = choice(study::kAmplitudes, "amplitudes", k.amplitudes);
  surface_key("anisotropy", k.anisotropy);
  // The engine's generator, built as texture_io::surface_generator builds it from [surface], and drawing
  // from the streams `rollspec texture` draws its surface `index` from (SurfaceGenerator::generate).
  texture_io::SurfaceGenerator g;
  texture::Surface out;
  {
    py::gil_scoped_release unlocked;  // FFTW's planner has its own lock
    try {
      if (m == study::SurfaceMethod::spectral) {
        texture::SpectralSurfaceSpec spec;
        spec.nx = sx, spec.ny = sy, spec.dx = spec.dy = h, spec.amplitudes = a, spec.anisotropy = k.anisotropy;
        g.spectral = std::make_unique<texture::SpectralSurfaceGenerator>(psd, spec);
      } else {
        texture::SeedSurfaceRequest r;
        r.nx = sx, r.ny = sy, r.dx = r.dy = h, r.amplitudes = a;
        r.correlation_x = k.correlation_x, r.correlation_y = k.correlation_y, r.sigma = k.sigma;
        g.seed = std::make_unique<texture::SeedSurfaceGenerator>(psd, r);
      }
    } catch (const std::logic_error& e) {
      throw py::value_error(refused_as + e.what());
    }
    g.generate(k.seed, k.index, out);
  }
  py::dict d;
  d["heights"] = to_numpy(std::move(out.heights), {static_cast<py::ssize_t>(sy), static_cast<py::ssize_t>(sx)});
  d["spacing"] = h;
  d["method"] = k.method;
  if (g.spectral) {
    d["target_rms"] = std::sqrt(g.spectral->target_variance());
  } else {
    const texture::SeedBoxLengths& box = g.seed->box();
    d["box"] = py::make_tuple(box.box_x, box.box_y);
    d["expected_correlation"] = py::make_tuple(box.expected.x, box.expected.y);
  }
  d["seed"] = k.seed;
  d["index"] = k.index;
  return d;
}

void bind_surfaces(py::module_& m) {
  using py::arg;
  m.def("line", &line, kLineDoc, arg("wavenumber"), arg("psd"), arg("spacing"), arg("samples"), py::kw_only(),
        arg("seed"), arg("index") = 0, arg("amplitudes") = "rayleigh", arg("extension") = "error");
  const auto keys = study::SurfaceSection::keys();
  const auto key = [&](const std::string& k) { return key_default(key_spec(keys, "surface." + k)); };
  m.def("isotropic", &isotropic, kIsotropicDoc, arg("wavenumber"), arg("psd"), arg("spacing"), arg("nx"),
        arg("ny") = py::none(), py::kw_only(), arg("seed"), arg("index") = 0, arg("method") = "spectral",
        arg("amplitudes") = "rayleigh", arg("extension") = "error", arg("anisotropy") = key("anisotropy"),
        arg("sigma") = key("sigma"), arg("correlation_x") = key("correlation_x"),
        arg("correlation_y") = key("correlation_y"));
}

}  // namespace rollspec::python
