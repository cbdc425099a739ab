#include "src/io/references.hpp"

#include <algorithm>
#include <stdexcept>

#include "src/io/hdf5_file.hpp"

namespace rollspec::io {

// Seed papers: the seed documents the top-level README lists; DOIs only where the paper
// prints one (seed 000) or a public library cites it (ContactMechanics' @doi for Polonsky–Keer and
// Johnson; Welch as the signal-processing literature cites him). Equations: the theory notes in kernels/.
namespace {
// An equation of rollspec's own theory notes: what it is and the notes that hold it.
Reference theory_note(const char* id, const std::string& what, const std::string& notes) {
  return {id, "rollspec theory notes: " + what + " (" + notes + ")", ""};
}
}  // namespace

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
      theory_note("D-1", "compression at the contact", "kernels/README.md"),
      theory_note("D-3", "line texture by spectral representation", "kernels/README.md"),
      theory_note("D-4", "isotropic surface as sums of line textures, seed 001 Eq. 9-10", "kernels/README.md"),
      theory_note("D-5", "isotropic surface by 2D Fourier filtering", "kernels/README.md"),
      theory_note("D-6", "Boussinesq half-space displacement", "kernels/README.md"),
      theory_note("D-7", "elastic-plastic contact conditions with hardness H", "kernels/README.md"),
      theory_note("D-8", "clamped-clamped Euler-Bernoulli modes", "kernels/README.md"),
      theory_note("D-9", "modal beam under a moving contact force", "kernels/README.md"),
      theory_note("D-10", "nonlinear contact force P(delta), seed 001 Eq. 7-8", "kernels/README.md"),
      theory_note("D-11", "linearised contact with a blocked force, seed 002 Eq. 4, 14", "kernels/README.md"),
      theory_note("D-12..D-14", "rotations, rolling contact point and gaps of geometrically exact beams",
                  "kernels/README.md, kernels/rolling/README.md"),
      theory_note("D-15", "Welch PSD", "kernels/README.md"),
      theory_note("D-16", "Welch degrees of freedom", "kernels/spectral/README.md"),
      theory_note("D-17", "third-octave bands", "kernels/spectral/README.md"),
      theory_note("D-18", "exact oscillator step", "kernels/spectral/README.md"),
      theory_note("D-19", "random oscillator exact PSD", "kernels/spectral/README.md"),
      theory_note("D-21", "interval of an ensemble mean", "kernels/spectral/README.md"),
      theory_note("D-22", "prediction interval for a measurement", "kernels/spectral/README.md"),
      theory_note("D-26", "combined test over bands, Hotelling T2", "kernels/spectral/README.md"),
      theory_note("D-31", "the verdict with the table's own error, parametric bootstrap", "kernels/spectral/README.md"),
      theory_note("D-32", "the measurement as an object", "kernels/spectral/README.md"),
      theory_note("D-33", "the noise floor", "kernels/spectral/README.md"),
      theory_note("D-34", "one level offset", "kernels/spectral/README.md"),
      theory_note("B35", "contact-patch filter", "kernels/beam/README.md"),
      theory_note("B41..B46", "path table of one rough strip, law = path", "kernels/beam/README.md"),
      theory_note("BF-1..BF-7", "blocked force of a rough strip", "kernels/contact/README.md"),
      theory_note("ER-1..ER-7", "equivalent roughness", "kernels/contact/README.md"),
      theory_note("texture Eq. 36-40", "contact filter on an isotropic surface, iso2d", "kernels/texture/README.md"),
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
