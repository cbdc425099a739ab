// rollspec.surfaces.profile_psd, read_profiles, read_profile and ProfilePsd: the PSD of measured short
// profiles ([texture] source = profiles; kernels/texture README Eq. 15-17 and 42-46) and the line
// textures and isotropic surfaces `rollspec texture` draws from it, from numpy arrays or from the
// profile files the command reads (texture_io::read_profile), with the engine's estimator and PSD.
#include <cmath>
#include <optional>

#include "kernels/texture/measured_psd.hpp"
#include "kernels/texture/profile_psd.hpp"
#include "python/bindings.hpp"
#include "python/surface_draws.hpp"
#include "src/io/number_text.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/profile_source.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::python {

namespace {

// The estimate of Eq. 15-17 and 44 and the PSD the generators take from it (Eq. 44-46).
struct ProfilePsd {
  texture::EstimatedPsd estimate;
  texture::Psd psd;
  double short_wavelength_cut = 0.0;  // m; 0: none
};

// [texture] median_filter, table_extension and short_wavelength acting on `profiles` as
// texture_io::profile_estimate and profile_psd make them act; `who` prefixes the kernels' refusals.
ProfilePsd estimate(const std::vector<texture::Profile>& profiles, bool median_filter, const std::string& extension,
                    const std::optional<double>& short_wavelength, const std::string& who) {
  const texture::Extension ext = choice(study::kTableExtensions, "extension", extension);
  if (short_wavelength && !(*short_wavelength > 0.0 && std::isfinite(*short_wavelength)))
    refuse("short_wavelength", io::number_text(*short_wavelength), "not a wavelength", "a finite length > 0 (m)");
  ProfilePsd out;
  {
    py::gil_scoped_release unlocked;
    try {
      texture::ProfilePsdOptions opt;
      opt.median_filter = median_filter;
      out.estimate = texture::profile_psd(profiles, opt);
      out.psd = texture::measured_line_psd(out.estimate, ext);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(who + ": " + e.what());
    }
  }
  if (!short_wavelength) return out;
  // Eq. 46: the cut must fall inside the resolved band, else it cuts nothing or the unresolved rest.
  const texture::EstimatedPsd& e = out.estimate;
  const double k_cut = 2.0 * M_PI / *short_wavelength;
  const double k_r = (static_cast<double>(e.first_resolved) - 0.5) * e.dk, k_n = M_PI / e.spacing;
  if (!(k_cut > k_r && k_cut < k_n))
    refuse("short_wavelength", io::length_text(*short_wavelength),
           "cuts the measured PSD at 2 pi / short_wavelength, which must lie in its resolved band",
           "between " + io::length_text(2.0 * e.spacing) +
               " (twice the scans' spacing: a shorter cut leaves every wave) and " + io::length_text(2.0 * M_PI / k_r) +
               " (the longest wavelength the scans resolve)");
  out.psd = texture::band_limited(out.psd, k_cut);
  out.short_wavelength_cut = *short_wavelength;
  return out;
}

ProfilePsd from_arrays(const py::handle& heights, double spacing, bool median_filter, const std::string& extension,
                       const std::optional<double>& short_wavelength) {
  const std::string what = "heights (m) of one profile (1-D) or of profiles of equal length (2-D, one per row)";
  const py::array raw = py::array::ensure(heights);
  const py::ssize_t ndim = raw && raw.ndim() == 1 ? 1 : 2;
  const Array z = finite_array(heights, "heights", ndim, 1, what);
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    refuse("spacing", io::number_text(spacing), "not a spacing", "a finite number > 0 (m)");
  const auto rows = static_cast<std::size_t>(ndim == 1 ? 1 : z.shape(0));
  const auto n = static_cast<std::size_t>(ndim == 1 ? z.shape(0) : z.shape(1));
  // Positions x_i = i * spacing, the grid read_profile puts a file's scan on (from x_0 = 0).
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = spacing * static_cast<double>(i);
  std::vector<texture::Profile> profiles(rows);
  for (std::size_t r = 0; r < rows; ++r)
    profiles[r] = {x, std::vector<double>(z.data() + r * n, z.data() + (r + 1) * n)};
  return estimate(profiles, median_filter, extension, short_wavelength, "heights");
}

ProfilePsd from_files(const std::vector<std::string>& paths, bool median_filter, const std::string& extension,
                      const std::optional<double>& short_wavelength) {
  if (paths.empty())
    refuse("paths", "[]", "names no profile file", "one or more CSV files (position_m,height_m), each a whole scan");
  std::vector<texture::Profile> profiles;
  for (const auto& p : paths) profiles.push_back(texture_io::read_profile(file_name(p, "paths")));
  return estimate(profiles, median_filter, extension, short_wavelength, "profiles");
}

py::dict read_one(const std::string& path) {
  texture::Profile p = texture_io::read_profile(file_name(path, "path"));
  py::dict d;
  const auto n = static_cast<py::ssize_t>(p.x.size());
  d["spacing"] = (p.x.back() - p.x.front()) / static_cast<double>(p.x.size() - 1);  // the estimator's dx
  d["x"] = to_numpy(std::move(p.x), {n});
  d["heights"] = to_numpy(std::move(p.z), {n});
  return d;
}

// A read-only view of a vector `self` holds: no copy, alive as long as `self`.
py::array_t<double> view(const std::vector<double>& v, const py::object& self) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size())}, {sizeof(double)}, v.data(), self);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::dict line(const ProfilePsd& self, double spacing, long long samples, unsigned long long seed,
              unsigned long long index, const std::string& amplitudes) {
  return draw_line(self.psd, spacing, samples, seed, index, amplitudes, "spacing = " + io::number_text(spacing) + ": ");
}

py::dict isotropic(const ProfilePsd& self, double spacing, long long nx, const std::optional<long long>& ny_arg,
                   unsigned long long seed, unsigned long long index, const std::string& method,
                   const std::string& amplitudes, double anisotropy, const std::optional<double>& sigma_arg,
                   const std::optional<double>& cx_arg, const std::optional<double>& cy_arg) {
  // Seed 001 §3.1, Eq. 10 (texture_io::with_profile_values): sigma and the correlation lengths the
  // keys leave unset are the profiles', a correlation length they never reach the key's default.
  static const auto keys = study::SurfaceSection::keys();
  const auto measured = [&](const std::optional<double>& v, const std::string& k, double profiles) {
    if (v) return surface_key(k, *v);
    return std::isfinite(profiles) ? profiles : key_default(key_spec(keys, "surface." + k));
  };
  IsotropicDraw k;
  k.spacing = spacing, k.nx = nx, k.ny = ny_arg, k.seed = seed, k.index = index, k.method = method;
  k.amplitudes = amplitudes, k.anisotropy = anisotropy;
  k.sigma = measured(sigma_arg, "sigma", self.estimate.sigma);
  k.correlation_x = measured(cx_arg, "correlation_x", self.estimate.correlation_length);
  k.correlation_y = measured(cy_arg, "correlation_y", self.estimate.correlation_length);
  py::dict d = draw_isotropic(self.psd, k, "spacing = " + io::number_text(spacing) + ": ");
  if (!d.contains("target_rms")) {  // the seed method: the sigma and lengths it was given
    d["sigma"] = k.sigma;
    d["correlation"] = py::make_tuple(k.correlation_x, k.correlation_y);
  }
  return d;
}

const char* const kClassDoc = R"(The PSD of measured short profiles, as [texture] source = profiles makes it.

Per profile of N samples at spacing dx (kernels/texture README Eq. 15-17): the least-squares line
removed, an optional 3-point median filter, the Hann-windowed periodogram scaled so that
sum_j G_j dk = variance, k_j = 2 pi j / (N dx); the mean over the profiles. The resolved band starts
at bin j_r (Eq. 42); the variance below it (unresolved, Eq. 44) goes to the scans' longest cell, and
the generators take the band-averaged table of Eq. 44-45 (cut at 2 pi / short_wavelength when one is
given, Eq. 46). The attributes are those `rollspec texture` writes under /profiles; line() and
isotropic() draw from `rollspec texture`'s streams, so the same profiles and keys give its bits.
Made by rollspec.surfaces.profile_psd (arrays) or rollspec.surfaces.read_profiles (files).
)";

const char* const kProfilePsdDoc = R"(The PSD of measured profiles given as arrays ([texture] source = profiles).

Parameters
----------
heights : array_like, 1-D or 2-D
    Heights (m) of one profile (1-D, N >= 8) or of P profiles of N samples each (2-D, one per row).
spacing : float
    Sample spacing dx (m); the positions are x_i = i * dx.
median_filter : bool
    3-point median filter after the trend removal ([texture] median_filter).
extension : str
    The PSD outside the measured band: 'error', 'constant', 'power_law', 'zero' ([texture]
    table_extension).
short_wavelength : float or None
    Cut the PSD at 2 pi / short_wavelength (m), inside the resolved band ([texture]
    short_wavelength, Eq. 46); None: no cut.

Returns
-------
ProfilePsd
)";

const char* const kReadProfilesDoc = R"(The PSD of measured profile files, as [texture] profiles = ... reads them.

Each file is a CSV of the columns position_m,height_m (or position_m,height_um), at least 8 rows,
positions uniformly spaced within the rounding of their printed digits (regularised to that grid,
as `rollspec texture` does). Every file is one whole scan; all of the same length and spacing.

Parameters
----------
paths : list of str
    The profile files.
median_filter, extension, short_wavelength
    As for profile_psd.

Returns
-------
ProfilePsd
)";

const char* const kReadProfileDoc = R"(One measured profile file as `rollspec texture` reads it.

Returns
-------
dict
    x (m, the positions regularised to x_0 + i dx), heights (m, height_um converted), spacing (m,
    (x[-1] - x[0]) / (N - 1), the spacing the estimator uses).
)";

const char* const kLineDoc = R"(A line texture of this PSD, as `rollspec texture` draws its line `index`.

h(x) = sum_j A_j cos(k_j x + phi_j) (D-3), harmonics j dk carrying the PSD's power in their cells
(Eq. 14b); no harmonic above pi / spacing may carry power (as the command: [lines] spacing at most
pi over the PSD's last wavenumber, or a short_wavelength cut).

Parameters
----------
spacing : float
    Sample spacing (m) ([lines] spacing).
samples : int
    Number of heights, 8 to 2^26 (floor([lines] length / [lines] spacing)).
seed, index : int
    [study] seed and the line's index (realisation).
amplitudes : str
    'rayleigh' or 'deterministic' ([texture] amplitudes).

Returns
-------
dict
    heights (m), spacing (m), wavenumber (rad/m), target_psd (m^3), target_rms (m), period, seed,
    index: as rollspec.surfaces.line.
)";

const char* const kIsotropicDoc = R"(An isotropic surface of this PSD, as `rollspec texture` draws its surface `index`.

method 'spectral' (D-5) or 'seed' (D-4), as rollspec.surfaces.isotropic; with 'seed', sigma and the
correlation lengths left at None are the profiles' (their mean rms and 1/e correlation length, seed
001 Eq. 10), as a study that does not set them.

Parameters
----------
spacing : float
    Grid spacing (m) ([surface] spacing).
nx, ny : int
    Grid points, even ([surface] nx, ny); ny defaults to nx.
seed, index : int
    [study] seed and the surface's index (realisation).
method, amplitudes, anisotropy
    [surface] method, [texture] amplitudes, [surface] anisotropy.
sigma, correlation_x, correlation_y : float or None
    Seed method: rms height (m) and 1/e correlation lengths (m); None: the profiles'.

Returns
-------
dict
    heights (m, shape (ny, nx)), spacing, method, seed, index; spectral: target_rms (m); seed: box,
    expected_correlation (m), sigma (m) and correlation (m, x and y) used.
)";

}  // namespace

void bind_profiles(py::module_& m) {
  using py::arg;
  py::class_<ProfilePsd> c(m, "ProfilePsd", kClassDoc);
  const auto array = [&](const char* name, std::vector<double> texture::EstimatedPsd::*member, const char* doc) {
    c.def_property_readonly(
        name, [member](const py::object& self) { return view(self.cast<const ProfilePsd&>().estimate.*member, self); },
        doc);
  };
  array("wavenumber", &texture::EstimatedPsd::wavenumber, "Bins k_j = j dk, j = 0..N/2 (rad/m).");
  array("periodogram", &texture::EstimatedPsd::psd,
        "Mean Hann periodogram G(k_j) of the profiles after their linear trend (m^3, one-sided; Eq. 16-17).");
  c.def_property_readonly(
      "dk", [](const ProfilePsd& p) { return p.estimate.dk; }, "Bin width 2 pi / (N dx) (rad/m).");
  c.def_property_readonly(
      "spacing", [](const ProfilePsd& p) { return p.estimate.spacing; }, "The profiles' spacing dx (m).");
  c.def_property_readonly(
      "samples", [](const ProfilePsd& p) { return p.estimate.samples; }, "Samples N per profile.");
  c.def_property_readonly(
      "scans", [](const ProfilePsd& p) { return p.estimate.profiles; }, "Number of profiles P.");
  c.def_property_readonly(
      "sigma", [](const ProfilePsd& p) { return p.estimate.sigma; },
      "Mean standard deviation of the profiles after the trend (and filter) (m).");
  c.def_property_readonly(
      "correlation_length", [](const ProfilePsd& p) { return p.estimate.correlation_length; },
      "Mean 1/e correlation length of the profiles (m); NaN if none reaches 1/e.");
  c.def_property_readonly(
      "variance", [](const ProfilePsd& p) { return p.estimate.variance; }, "Mean variance V of the profiles (m^2).");
  c.def_property_readonly(
      "resolved_variance", [](const ProfilePsd& p) { return p.estimate.resolved_variance(); },
      "V_r = sum_{j >= j_r} G_j dk (m^2, Eq. 44).");
  c.def_property_readonly(
      "unresolved_variance", [](const ProfilePsd& p) { return p.estimate.unresolved_variance(); },
      "V_u = max(0, V - V_r) (m^2, Eq. 44): waves longer than the scans resolve.");
  c.def_property_readonly(
      "first_resolved", [](const ProfilePsd& p) { return p.estimate.first_resolved; },
      "j_r, the first bin of the resolved band (Eq. 42).");
  c.def_property_readonly(
      "resolved_wavenumber",
      [](const ProfilePsd& p) { return (static_cast<double>(p.estimate.first_resolved) - 0.5) * p.estimate.dk; },
      "k_r = (j_r - 1/2) dk (rad/m), the resolved band's lower edge.");
  c.def_property_readonly(
      "short_wavelength_cut", [](const ProfilePsd& p) { return p.short_wavelength_cut; },
      "The cut's wavelength (m); 0: none.");
  c.def_property_readonly(
      "description", [](const ProfilePsd& p) { return p.psd.description; },
      "The PSD's description (a texture file's attribute psd).");
  c.def(
      "__call__",
      [](const ProfilePsd& p, const py::handle& k) {
        const Array kk = finite_array(k, "wavenumber", 1, 1, "a 1-D array of wavenumbers (rad/m)");
        std::vector<double> g(static_cast<std::size_t>(kk.size()));
        for (std::size_t i = 0; i < g.size(); ++i) g[i] = p.psd(kk.data()[i]);
        return to_numpy(std::move(g), {kk.size()});
      },
      "G(k) (m^3) of the PSD the generators take (Eq. 44-46) at wavenumbers k (rad/m, 1-D array).", arg("wavenumber"));
  c.def("line", &line, kLineDoc, arg("spacing"), arg("samples"), py::kw_only(), arg("seed"), arg("index") = 0,
        arg("amplitudes") = "rayleigh");
  const auto keys = study::SurfaceSection::keys();
  c.def("isotropic", &isotropic, kIsotropicDoc, arg("spacing"), arg("nx"), arg("ny") = py::none(), py::kw_only(),
        arg("seed"), arg("index") = 0, arg("method") = "spectral", arg("amplitudes") = "rayleigh",
        arg("anisotropy") = key_default(key_spec(keys, "surface.anisotropy")), arg("sigma") = py::none(),
        arg("correlation_x") = py::none(), arg("correlation_y") = py::none());
  m.def("profile_psd", &from_arrays, kProfilePsdDoc, arg("heights"), arg("spacing"), py::kw_only(),
        arg("median_filter") = false, arg("extension") = "error", arg("short_wavelength") = py::none());
  m.def("read_profiles", &from_files, kReadProfilesDoc, arg("paths"), py::kw_only(), arg("median_filter") = false,
        arg("extension") = "error", arg("short_wavelength") = py::none());
  m.def("read_profile", &read_one, kReadProfileDoc, arg("path"));
}

}  // namespace rollspec::python
