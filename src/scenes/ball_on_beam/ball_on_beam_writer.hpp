#pragma once
// Scene ball-on-beam's result file (besides the time histories, which replay realisations): the
// ensemble's PSDs, the contact and ball PSDs, the contact law as resolved, the beam, /roughness
// (the path PSD under each contact filter) and the linearised law's frequency-domain /reference.
#include <string>
#include <vector>

#include "kernels/spectral/welch.hpp"
#include "src/io/loss_effect.hpp"
#include "src/io/psd_result.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_contact.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_settings.hpp"
#include "src/scenes/psd_rows.hpp"

namespace rollspec::io {
class Hdf5Writer;
}
namespace rollspec::ensemble {
struct EnsembleSums;
}

namespace rollspec::scenes {

class BallOnBeamWriter {
 public:
  // `c`: the contact as the table stages resolved it (law, static compression, line PSD, blocked force).
  BallOnBeamWriter(const BallOnBeamSettings& b, const ResolvedContact& c, const spectral::WelchPlan& welch,
                   const PsdRows& rows, double line_fundamental, bool quiet)
      : b_(b), c_(c), welch_(&welch), rows_(&rows), line_fundamental_(line_fundamental), quiet_(quiet) {}

  // `table_error`: what the intervals include besides the realisations (io/table_error.hpp).
  // `spectra_only` (a fit's evaluation): without /roughness and the linearised reference.
  // `loss`: what loss of contact moved, where it was measured (D-35).
  void write(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums, const io::TableError& table_error,
             bool spectra_only = false, const io::LossEffect& loss = {}) const;
  // The sensors' spectra as write() writes them under /psd and /bands.
  io::PsdEnsemble spectra(const ensemble::EnsembleSums& sums) const;

 private:
  void write_roughness(io::Hdf5Writer& w) const;
  // The loss of contact's warning or note (D-35: with the size it measured, for the linearised law).
  // sized: the run measures what a loss moves (D-35; law = linearised with a contact that can open).
  void write_blocked_force_error(io::Hdf5Writer& w, const std::vector<spectral::Band>& bands) const;
  void write_equivalent_roughness_error(io::Hdf5Writer& w, const std::vector<spectral::Band>& bands) const;
  void write_path_table_error(io::Hdf5Writer& w, const std::vector<spectral::Band>& bands) const;
  void write_loss_of_contact(io::Hdf5Writer& w, double share, const io::LossEffect& effect, bool sized,
                             std::size_t bands) const;
  void write_linear_reference(io::Hdf5Writer& w, const std::vector<double>& f, const std::vector<std::string>& sensors,
                              double realisations) const;
  std::size_t rows() const { return rows_->rows(); }
  bool linearised() const { return b_.linearised(); }
  bool blocked_solver() const { return b_.blocked_solver(); }
  bool solver_filter() const { return b_.filter == ContactFilter::solver; }
  bool writes_reference() const { return b_.linearised() && b_.reference; }
  double blocked_force_time_psd(double f) const { return scenes::blocked_force_time_psd(b_, c_.blocked, f); }

  const BallOnBeamSettings& b_;
  const ResolvedContact& c_;
  const spectral::WelchPlan* welch_;
  const PsdRows* rows_;
  double line_fundamental_;
  bool quiet_;
};

}  // namespace rollspec::scenes
