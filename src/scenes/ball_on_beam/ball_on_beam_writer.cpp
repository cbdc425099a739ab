#include "src/scenes/ball_on_beam/ball_on_beam_writer.hpp"

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/linear_reference.hpp"
#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/time_signal.hpp"
#include "src/ensemble/progress.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/psd_result.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_plausibility.hpp"
#include "src/io/run_warning.hpp"

namespace rollspec::scenes {

void BallOnBeamWriter::write_loss_of_contact(io::Hdf5Writer& w, double share, const io::LossEffect& effect, bool sized,
                                             std::size_t bands) const {
  // D-35's shifts whenever the run sizes a loss, zero where the contact never opened (the run with a closed
  // contact is then the same bits): every point of a sweep holds the same datasets.
  if (sized) {
    const std::size_t n = rows() * bands;
    const std::vector<double> zero(n, 0.0);
    const bool measured = effect.measured && effect.shift_db.size() == n;
    w.write("/bands/loss_of_contact_shift_db", {rows(), bands}, measured ? effect.shift_db.data() : zero.data(), "dB",
            "band level as run minus with a contact that never opens, the same realisations (kernels/spectral D-35)");
    w.write("/bands/loss_of_contact_shift_se_db", {rows(), bands}, measured ? effect.shift_se_db.data() : zero.data(),
            "dB", "standard error of loss_of_contact_shift_db from the pairs of realisations");
    for (const char* d : {"/bands/loss_of_contact_shift_db", "/bands/loss_of_contact_shift_se_db"}) {
      w.attach_scale(d, "/bands/sensor", 0);
      w.attach_scale(d, "/bands/centre_frequency", 1);
      w.attribute(d, "coordinates", std::string("nominal_frequency"));
    }
  }
  if (!(share > 0.0)) return;
  bool warning = false;
  std::string text;
  if (linearised() && effect.measured) {
    text = io::loss_effect_sentence(share, effect, warning);
  } else {
    text = loss_of_contact_warning(share, linearised());  // a law that models the loss: a note of its share
  }
  if (text.empty()) return;
  if (warning) {  // printed even when quiet: the result's validity, not progress
    io::warn(text, true);
    w.attribute("/contact", "loss_of_contact_warning", text);
  } else {
    if (!quiet_) std::fprintf(stderr, "rollspec: note: %s\n", text.c_str());
    w.attribute("/contact", "loss_of_contact_note", text);
  }
}

// The blocked-force table's own estimated error at the answer (contact BF-9): each band's F0 level and
// k0, against their targets; a warning where a band or k0 exceeds it. The exhaustive table has none.
void BallOnBeamWriter::write_blocked_force_error(io::Hdf5Writer& w, const std::vector<spectral::Band>& bands) const {
  const stiffness::BlockedForceTable& t = c_.blocked;
  if (t.check_position.empty()) return;
  const std::vector<double> err = blocked_force_band_error_db(b_, t, bands);
  w.write("/contact/blocked_force_band_error_db", {err.size()}, err.data(), "dB",
          "estimated rms error of F0's band level from the table's own checks (contact BF-9c), per result band");
  w.attach_scale("/contact/blocked_force_band_error_db", "/bands/centre_frequency", 0);
  const double k0_rel = t.k0_error / t.k0;
  w.attribute("/contact", "blocked_force_k0_error", k0_rel);
  w.attribute("/contact", "blocked_force_band_target_db", kBlockedForceBandTarget);
  w.attribute("/contact", "blocked_force_k0_target", kBlockedForceK0Target);
  double worst = 0.0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < err.size(); ++i)
    if (err[i] > worst) worst = err[i], at = i;
  std::string text;
  if (worst > kBlockedForceBandTarget)
    text = io::formatted("F0's level at %g Hz has an estimated error of %.3g dB, above the %g dB target",
                         bands[at].nominal, worst, kBlockedForceBandTarget);
  if (k0_rel > kBlockedForceK0Target)
    text += (text.empty() ? "" : "; ") + io::formatted("k0's estimated error is %.3g %%, above the %g %% target",
                                                       100.0 * k0_rel, 100.0 * kBlockedForceK0Target);
  if (text.empty()) return;
  text = "blocked-force table: " + text +
         " (its checks at the full tolerance, contact BF-9); a smaller [blocked_force] answer_tolerance, or 0 for the "
         "exhaustive search, lowers it";
  io::warn(text, true);
  w.attribute("/contact", "blocked_force_error_warning", text);
}

namespace {
// A checked table's estimated error per result band (`/contact/<name>_band_error_db`, BF-9c) against
// kBlockedForceBandTarget, and a warning naming the worst band where one exceeds it: "<table>: <what>'s level
// at f Hz has an estimated error of e dB, above the target (<why>)".
void write_checked_band_errors(io::Hdf5Writer& w, const std::vector<spectral::Band>& bands,
                               const std::vector<double>& err, const std::string& name, const std::string& description,
                               const std::string& table, const std::string& what, const std::string& why) {
  const std::string dataset = "/contact/" + name + "_band_error_db";
  w.write(dataset, {err.size()}, err.data(), "dB", description);
  w.attach_scale(dataset, "/bands/centre_frequency", 0);
  w.attribute("/contact", name + "_band_target_db", kBlockedForceBandTarget);
  double worst = 0.0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < err.size(); ++i)
    if (err[i] > worst) worst = err[i], at = i;
  if (!(worst > kBlockedForceBandTarget)) return;
  const std::string text =
      io::formatted("%s: %s's level at %g Hz has an estimated error of %.3g dB, above the %g dB target (%s)",
                    table.c_str(), what.c_str(), bands[at].nominal, worst, kBlockedForceBandTarget, why.c_str());
  io::warn(text, true);
  w.attribute("/contact", name + "_error_warning", text);
}
}  // namespace

// The equivalent-roughness table's own estimated error at the answer (contact ER-8, BF-9c): each band's
// level of the h_eq PSD the lines are drawn from. The reference table has none.
void BallOnBeamWriter::write_equivalent_roughness_error(io::Hdf5Writer& w,
                                                        const std::vector<spectral::Band>& bands) const {
  if (!c_.equivalent || c_.equivalent->check_residual.empty()) return;
  write_checked_band_errors(
      w, bands, equivalent_roughness_band_error_db(b_, *c_.equivalent, bands), "equivalent_roughness",
      "estimated rms error of the h_eq PSD's band level from the table's own checks (contact ER-8, BF-9c), per "
      "result band",
      "equivalent-roughness table", "the h_eq PSD",
      "its checks at the full tolerance, contact ER-8; a smaller [equivalent_roughness] answer_tolerance, or 0 for "
      "every solve at [stiffness] tolerance, lowers it");
}

// The path table's own estimated error at the answer (kernels/beam B47, BF-9c): each band's level of the
// static approach delta_W(xi) the law holds, as the run reads the table. A table without checks has none.
void BallOnBeamWriter::write_path_table_error(io::Hdf5Writer& w, const std::vector<spectral::Band>& bands) const {
  if (!c_.path_check || c_.path_check->residual.size() < 2) return;
  write_checked_band_errors(
      w, bands, path_table_band_error_db(b_, *c_.path_check, bands), "path_table",
      "estimated rms error of the band level of the path law's static approach delta_W(xi) from the table's own "
      "checks (kernels/beam B47, contact BF-9c), per result band",
      "path table", "delta_W",
      "its checks by load-controlled solves between positions, kernels/beam B47; a smaller [path_table] step or "
      "more [path_table] approaches lowers it");
}

io::PsdEnsemble BallOnBeamWriter::spectra(const ensemble::EnsembleSums& sums) const {
  io::PsdEnsemble e = rows_->welch_ensemble(sums, *welch_, b_.samples - b_.skip, b_.confidence);
  e.sensor_position = b_.model.sensors;
  e.position_meaning = "sensor position along the span";
  if (b_.path_law() || b_.strip_line)  // one strip, and nothing else random
    e.no_interval = std::string("every realisation rolls over the one strip of the ") +
                    (b_.path_law() ? "path table" : "equivalent-roughness table (line = strip)") +
                    ", so the realisations are the same run and the strip's own variability is not sampled: "
                    "the result is one strip's";
  return e;
}

void BallOnBeamWriter::write(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums, const io::TableError& table_error,
                             bool spectra_only, const io::LossEffect& loss_effect) const {
  const std::size_t nf = welch_->n_freq();
  const double K = static_cast<double>(sums.count);
  auto mean_of = [&](std::size_t i) { return sums.mean(i); };
  auto std_of = [&](std::size_t i) { return sums.std_dev(i); };
  io::PsdEnsemble e = spectra(sums);
  e.table_error = table_error;
  io::write_psd_result(w, e);

  std::vector<double> force(nf), ball(nf);
  for (std::size_t k = 0; k < nf; ++k) {
    force[k] = mean_of(rows_->extra_index(k));
    ball[k] = mean_of(rows_->extra_index(nf + k));
  }
  w.write("/contact/force_psd", {nf}, force.data(), "N^2/Hz", "ensemble mean PSD of the contact force");
  w.write("/ball/acceleration_psd", {nf}, ball.data(), "(m/s^2)^2/Hz", "ensemble mean PSD of the ball acceleration");
  io::write_frequency_scale(w, "/contact", e.frequency);
  io::write_frequency_scale(w, "/ball", e.frequency);
  w.attach_scale("/contact/force_psd", "/contact/frequency", 0);
  w.attach_scale("/ball/acceleration_psd", "/ball/frequency", 0);
  const double share = mean_of(rows_->extra_index(2 * nf)), share_std = std_of(rows_->extra_index(2 * nf));
  w.write("/contact/loss_of_contact_share", {1}, &share, "1", "mean share of the time in loss of contact");
  w.write("/contact/loss_of_contact_share_std", {1}, &share_std, "1", "its standard deviation over realisations");
  w.attribute("/contact", "law", b_.law_name);
  const bool sized = linearised() && b_.contact_section.loss != study::ContactLoss::closed && !spectra_only;
  write_loss_of_contact(w, share, loss_effect, sized, io::result_bands(e.frequency, e.band_min, e.band_max).size());
  w.attribute("/contact", "static_compression", c_.static_compression);
  if (c_.contact_stiffness > 0.0) {  // what the step was checked against (D-23, B37b)
    w.attribute("/contact", "contact_period", 2.0 * M_PI * std::sqrt(b_.model.ball.mass / c_.contact_stiffness));
    w.attribute("/contact", "free_bounce_growth", free_bounce_growth(b_, c_.contact_stiffness));
  }
  w.attribute("/contact", "patch_half_width", b_.patch_half_width);
  w.attribute("/contact", "filter", b_.filter_applied);
  if (b_.filter_applied != b_.filter_name)
    w.attribute("/contact", "filter_requested", b_.filter_name + " (not applied: the contact is solved on the strip)");
  w.attribute("/contact", "contact_half_width", b_.contact_half_width);
  w.attribute("/contact", "effective_modulus", c_.law.effective_modulus);
  if (linearised()) w.attribute("/contact", "k0", c_.law.k0);
  if (blocked_solver()) {
    w.attribute("/contact", "blocked_force_approach", c_.blocked.approach);
    w.attribute("/contact", "blocked_force_input_hash", c_.blocked.input_hash);
    // The F0 PSD the realisations were drawn from: the table's, or its sub-table's under
    // [blocked_force] leave_out (D-30d); below the table's third bin the run scales the texture's shape.
    const std::vector<double>& k = c_.blocked.psd_wavenumber;
    w.write("/contact/blocked_force_wavenumber", {k.size()}, k.data(), "rad/m", "wavenumber along the path");
    w.make_scale("/contact/blocked_force_wavenumber", "wavenumber");
    w.write("/contact/blocked_force_psd", {k.size()}, c_.blocked.psd.data(), "N^2 m/rad",
            "one-sided PSD of F0 along the path (Welch over the table's strip), as the realisations used it");
    w.attach_scale("/contact/blocked_force_psd", "/contact/blocked_force_wavenumber", 0);
    write_blocked_force_error(w, io::result_bands(e.frequency, e.band_min, e.band_max));
  }
  write_equivalent_roughness_error(w, io::result_bands(e.frequency, e.band_min, e.band_max));
  write_path_table_error(w, io::result_bands(e.frequency, e.band_min, e.band_max));

  const auto& b = b_.model.beam;
  std::vector<double> fm(static_cast<std::size_t>(b.modes()));
  for (int i = 0; i < b.modes(); ++i) fm[static_cast<std::size_t>(i)] = b.frequency(i);
  w.write("/beam/modal_frequency", {fm.size()}, fm.data(), "Hz", "undamped modal frequencies");
  const auto& p = b.properties();
  w.attribute("/beam", "length", p.length);
  w.attribute("/beam", "effective_length", b.effective_length());
  w.attribute("/beam", "width", p.width);
  w.attribute("/beam", "thickness", p.thickness);
  w.attribute("/beam", "youngs_modulus", p.youngs_modulus);
  w.attribute("/beam", "density", p.density);
  w.attribute("/beam", "static_correction", static_cast<std::int64_t>(b.static_correction()));
  w.write("/sensors/position", {b_.model.sensors.size()}, b_.model.sensors.data(), "m",
          "sensor positions along the span");
  w.attribute("/ball", "mass", b_.model.ball.mass);
  w.attribute("/ball", "speed", b_.model.traverse.speed);

  if (spectra_only) return;
  write_roughness(w);
  if (writes_reference()) write_linear_reference(w, e.frequency, e.sensors, K);
}

// /roughness: the path PSD raw (the study's [texture], no band limit) and what the contact sees
// under each filter, band limit (B40) included, on a log grid from the line's fundamental to its
// Nyquist wavenumber (python-post roughness_filter_plot). psd_patch: the patch line (B40a-compensated
// where it applies) through B35a on the samples; psd_iso2d: Eq. 38 (absent where the PSD has no
// isotropic form and the study does not ask for iso2d).
void BallOnBeamWriter::write_roughness(io::Hdf5Writer& w) const {
  if (blocked_solver() || b_.path_law() || b_.strip_line) return;
  const double k0 = line_fundamental_, k1 = M_PI / b_.spacing;
  std::vector<double> k;
  for (std::size_t i = 0;; ++i) {
    const double v = k0 * std::pow(10.0, static_cast<double>(i) / 100.0);
    if (v > k1) break;
    k.push_back(v);
  }
  const double a = b_.contact_half_width;
  std::vector<double> raw(k.size()), patch(k.size()), iso(k.size()), solver(k.size());
  bool have_iso = true;
  if (b_.filter == ContactFilter::iso2d) {
    for (std::size_t i = 0; i < k.size(); ++i) iso[i] = c_.line_psd(k[i]);  // what the line was synthesised from
  } else {
    try {  // Eq. 38 at these k only: cheaper than the synthesis table
      iso = iso2d_line_psd_at(b_, k);
    } catch (const std::exception&) {
      have_iso = false;
    }
  }
  // The patch line is drawn compensated for the linear interpolant (B40a) when band-limited below pi/dx.
  const texture::Psd patch_line =
      b_.band_limit_wavenumber * b_.spacing < M_PI ? texture::interpolation_compensated(b_.psd, b_.spacing) : b_.psd;
  for (std::size_t i = 0; i < k.size(); ++i) {
    try {
      raw[i] = b_.texture_psd(k[i]);
    } catch (const std::domain_error&) {  // a table without extension, beyond the band limit: no power known
      raw[i] = 0.0;
    }
    const double t = beam::contact_patch_transfer(k[i], a, b_.spacing);
    patch[i] = patch_line(k[i]) * t * t;  // (B35a, B40a)
  }
  w.write("/roughness/wavenumber", {k.size()}, k.data(), "rad/m", "wavenumber along the rolling path (log grid)");
  w.make_scale("/roughness/wavenumber", "wavenumber");
  if (solver_filter()) {
    for (std::size_t i = 0; i < k.size(); ++i) solver[i] = c_.line_psd(k[i]);  // what the line was synthesised from
    w.write("/roughness/psd_solver", {k.size()}, solver.data(), "m^3",
            "band-limited strip-mean PSD of the equivalent roughness h_eq (kernels/contact ER-2) the line was "
            "synthesised from");
    w.attach_scale("/roughness/psd_solver", "/roughness/wavenumber", 0);
  }
  w.write("/roughness/psd_raw", {k.size()}, raw.data(), "m^3", "one-sided line PSD of [texture] along the path");
  w.write("/roughness/psd_patch", {k.size()}, patch.data(), "m^3",
          "band-limited psd_raw x T(k)^2 / sinc^4(k dx/2) (B40a, where compensated), T the 1D patch average over 2a "
          "on the line's samples (kernels/beam B35a)");
  if (have_iso)
    w.write("/roughness/psd_iso2d", {k.size()}, iso.data(), "m^3",
            "G_eq: path PSD of the isotropic surface under a Hertz disc of radius a (kernels/texture Eq. 38)");
  for (const char* d : {"/roughness/psd_raw", "/roughness/psd_patch", "/roughness/psd_iso2d"})
    if (have_iso || std::string(d) != "/roughness/psd_iso2d") w.attach_scale(d, "/roughness/wavenumber", 0);
  w.attribute("/roughness", "filter", b_.filter_applied);
  w.attribute("/roughness", "contact_half_width", a);
  w.attribute("/roughness", "spacing", b_.spacing);
  w.attribute("/roughness", "band_limit_wavenumber", b_.band_limit_wavenumber);
}

// Frequency-domain solution of the linearised model made exact for what the Monte-Carlo
// simulates (kernels/beam/linear_reference.hpp; README B34, B34a-c, B35a; D-20).
void BallOnBeamWriter::write_linear_reference(io::Hdf5Writer& w, const std::vector<double>& f,
                                              const std::vector<std::string>& sensors, double realisations) const {
  beam::LinearReferenceInput in;
  in.beam = &b_.model.beam;
  in.ball_mass = b_.model.ball.mass;
  in.damping = c_.law.damping;
  in.sensors = b_.model.sensors;
  in.sensor_mean = rows() > b_.model.sensors.size();
  in.welch = welch_;
  in.sample_rate = b_.model.sample_rate;
  beam::ReferenceExcitation& ex = in.excitation;
  if (blocked_solver()) {
    ex.time_psd = [this](double fi) { return blocked_force_time_psd(fi); };
  } else {
    ex.time_psd = texture::time_psd(c_.line_psd, b_.model.traverse.speed);
  }
  ex.blocked_force = blocked_solver();
  ex.k0 = c_.law.k0;
  ex.speed = b_.model.traverse.speed;
  ex.spacing = b_.spacing;
  ex.patch_half_width = b_.patch_half_width;
  ex.x_start = b_.model.traverse.x_start;
  ex.step = b_.integration_step();
  in.positions = beam::welch_position_blocks(*welch_, b_.samples - b_.skip, b_.skip, b_.model.traverse.x_start,
                                             b_.model.traverse.speed, b_.model.sample_rate);
  in.realisations = realisations;
  in.confidence = b_.confidence;
  // The reference runs after the ensemble and can take longer than it: shown when over a second.
  ensemble::Progress progress("linearised reference", beam::linear_reference_steps(in), quiet_);
  progress.show_after(1.0);
  const beam::LinearReference ref = beam::linear_reference(in, [&progress] { progress.advance(); });
  progress.finish();
  w.write("/reference/psd", {rows(), f.size()}, ref.psd.data(), "(m/s^2)^2/Hz",
          "expected Welch estimate of the linearised model's frequency-domain PSD, averaged over ball positions");
  w.write("/reference/psd_raw", {rows(), f.size()}, ref.raw.data(), "(m/s^2)^2/Hz",
          "the frequency-domain PSD itself at the bin frequencies (not window-smoothed)");
  w.write("/reference/degrees_of_freedom", {rows(), f.size()}, ref.dof.data(), "1",
          "chi-square dof of the ensemble mean per bin for the non-stationary record, from the Welch window "
          "and the ball's positions (/psd/degrees_of_freedom comes from the realisations' scatter)");
  w.write("/reference/mean_lower", {rows(), f.size()}, ref.mean_lower.data(), "(m/s^2)^2/Hz",
          "lower end of the range that holds the ensemble mean with the study's confidence if /reference/psd is right");
  w.write("/reference/mean_upper", {rows(), f.size()}, ref.mean_upper.data(), "(m/s^2)^2/Hz",
          "upper end of that range");
  w.attribute("/reference/psd", "label",
              std::string("linear, quasi-stationary (no moving-weight response, no loss of contact)"));
  io::write_frequency_scale(w, "/reference", f);
  io::write_sensor_scale(w, "/reference", sensors);
  for (const char* d : {"/reference/psd", "/reference/psd_raw", "/reference/degrees_of_freedom",
                        "/reference/mean_lower", "/reference/mean_upper"}) {
    w.attach_scale(d, "/reference/sensor", 0);
    w.attach_scale(d, "/reference/frequency", 1);
  }
}

}  // namespace rollspec::scenes
