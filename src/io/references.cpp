#include "src/io/references.hpp"

#include <algorithm>
#include <stdexcept>

#include "src/io/hdf5_file.hpp"

namespace rollspec::io {

// Seed papers: the seed documents the top-level README lists; DOIs only where the paper
// prints one (seed 000) or a public library cites it (ContactMechanics' @doi for Polonsky–Keer and
// Johnson; Welch as the signal-processing literature cites him). Equations: the theory notes in kernels/.
const std::vector<Reference>& reference_table() {
  static const std::vector<Reference> rows = {
      {"seed 000",
       "A. Gay Neto, P. M. Pimenta, P. Wriggers: Contact between rolling beams and flat surfaces. Int. J. Numer. "
       "Meth. Engng 97 (2014) 683-706",
       "10.1002/nme.4611"},
      {"seed 001",
       "O. Lundberg, S. Finnveden, I. Lopez, S. Bjorklund: Non-linear contact forces for beam/ball-interaction and "
       "its influence on the dynamic response of the beam (KTH)",
       ""},
      {"seed 002",
       "The dynamic response caused by the rolling contact of rough surfaces: a steel ball on a steel beam test "
       "rig, linearised blocked-force model (KTH; authors and venue not in the seed text)",
       ""},
      {"Johnson 1985", "K. L. Johnson: Contact Mechanics. Cambridge University Press, 1985",
       "10.1017/CBO9781139171731"},
      {"Polonsky-Keer 1999",
       "I. A. Polonsky, L. M. Keer: A numerical method for solving rough contact problems based on the multi-level "
       "multi-summation and conjugate gradient techniques. Wear 231 (1999) 206-219",
       "10.1016/S0043-1648(99)00113-1"},
      {"Welch 1967",
       "P. D. Welch: The use of fast Fourier transform for the estimation of power spectra: a method based on time "
       "averaging over short, modified periodograms. IEEE Trans. Audio Electroacoust. 15(2) (1967) 70-73",
       "10.1109/TAU.1967.1161901"},
      {"D-1", "rollspec theory notes: compression at the contact (kernels/README.md)", ""},
      {"D-3", "rollspec theory notes: line texture by spectral representation (kernels/README.md)", ""},
      {"D-4",
       "rollspec theory notes: isotropic surface as sums of line textures, seed 001 Eq. 9-10 (kernels/README.md)", ""},
      {"D-5", "rollspec theory notes: isotropic surface by 2D Fourier filtering (kernels/README.md)", ""},
      {"D-6", "rollspec theory notes: Boussinesq half-space displacement (kernels/README.md)", ""},
      {"D-7", "rollspec theory notes: elastic-plastic contact conditions with hardness H (kernels/README.md)", ""},
      {"D-8", "rollspec theory notes: clamped-clamped Euler-Bernoulli modes (kernels/README.md)", ""},
      {"D-9", "rollspec theory notes: modal beam under a moving contact force (kernels/README.md)", ""},
      {"D-10", "rollspec theory notes: nonlinear contact force P(delta), seed 001 Eq. 7-8 (kernels/README.md)", ""},
      {"D-11", "rollspec theory notes: linearised contact with a blocked force, seed 002 Eq. 4, 14 (kernels/README.md)",
       ""},
      {"D-12..D-14",
       "rollspec theory notes: rotations, rolling contact point and gaps of geometrically exact beams "
       "(kernels/README.md, kernels/rolling/README.md)",
       ""},
      {"D-15", "rollspec theory notes: Welch PSD (kernels/README.md)", ""},
      {"D-16", "rollspec theory notes: Welch degrees of freedom (kernels/spectral/README.md)", ""},
      {"D-17", "rollspec theory notes: third-octave bands (kernels/spectral/README.md)", ""},
      {"D-18", "rollspec theory notes: exact oscillator step (kernels/spectral/README.md)", ""},
      {"D-19", "rollspec theory notes: random oscillator exact PSD (kernels/spectral/README.md)", ""},
      {"D-21", "rollspec theory notes: interval of an ensemble mean (kernels/spectral/README.md)", ""},
      {"D-22", "rollspec theory notes: prediction interval for a measurement (kernels/spectral/README.md)", ""},
      {"D-26", "rollspec theory notes: combined test over bands, Hotelling T2 (kernels/spectral/README.md)", ""},
      {"D-31",
       "rollspec theory notes: the verdict with the table's own error, parametric bootstrap "
       "(kernels/spectral/README.md)",
       ""},
      {"D-32", "rollspec theory notes: the measurement as an object (kernels/spectral/README.md)", ""},
      {"D-33", "rollspec theory notes: the noise floor (kernels/spectral/README.md)", ""},
      {"D-34", "rollspec theory notes: one level offset (kernels/spectral/README.md)", ""},
      {"B35", "rollspec theory notes: contact-patch filter (kernels/beam/README.md)", ""},
      {"B41..B46", "rollspec theory notes: path table of one rough strip, law = path (kernels/beam/README.md)", ""},
      {"BF-1..BF-7", "rollspec theory notes: blocked force of a rough strip (kernels/contact/README.md)", ""},
      {"ER-1..ER-7", "rollspec theory notes: equivalent roughness (kernels/contact/README.md)", ""},
      {"texture Eq. 36-40",
       "rollspec theory notes: contact filter on an isotropic surface, iso2d (kernels/texture/README.md)", ""},
  };
  return rows;
}

const Reference& find_reference(const std::string& id) {
  const auto& rows = reference_table();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const Reference& r) { return id == r.id; });
  if (it == rows.end()) throw std::logic_error("reference '" + id + "' is not in io::reference_table()");
  return *it;
}

std::vector<std::string> reference_lines(const std::vector<std::string>& ids) {
  std::vector<std::string> seen, out;
  for (const auto& id : ids) {
    if (std::find(seen.begin(), seen.end(), id) != seen.end()) continue;
    seen.push_back(id);
    const Reference& r = find_reference(id);
    out.push_back(std::string(r.id) + " | " + r.citation + " | " + r.doi);
  }
  return out;
}

std::vector<std::string> read_reference_lines(const Hdf5Reader& r) {
  return r.exists("/provenance/references") ? r.read_strings("/provenance/references") : std::vector<std::string>{};
}

void write_references(Hdf5Writer& w, const std::vector<std::string>& ids) {
  w.write_strings("/provenance/references", reference_lines(ids),
                  "papers and theory-note equations this computation used: id | citation | doi");
}

}  // namespace rollspec::io
