#include "src/scenes/ball_on_beam/ball_on_beam_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "kernels/beam/modal_beam.hpp"
#include "kernels/beam/quadratic_hold_step.hpp"
#include "kernels/contact/hertz.hpp"
#include "kernels/integrators/exact_oscillator_step.hpp"
#include "kernels/texture/contact_filtered_psd.hpp"
#include "src/io/number_text.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_plausibility.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_sections.hpp"
#include "src/scenes/study_welch.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

namespace {

std::vector<double> sensor_positions(const study::SensorsSection& sensors, double length) {
  const std::vector<double>& v = sensors.positions;
  if (v.empty()) sensors.origin(sensors.positions).refuse("lists no position; allowed: comma-separated positions in m");
  for (double x : v)
    if (x < 0.0 || x > length)
      sensors.origin(sensors.positions)
          .refuse("position " + std::to_string(x) + " m lies outside the span [0, length]");
  return v;
}

ContactModel contact_model(const study::ContactSection& c) {
  switch (c.law) {
    case study::ContactLaw::table:
      return ContactModel::table;
    case study::ContactLaw::literal:
      return ContactModel::literal;
    case study::ContactLaw::hertz:
      return ContactModel::hertz;
    case study::ContactLaw::path:
      return ContactModel::path;
    case study::ContactLaw::linearised:
      break;
  }
  switch (c.blocked_force) {
    case study::BlockedForceSource::solver:
      return ContactModel::linearised_solver;
    case study::BlockedForceSource::spring:
      break;
  }
  return ContactModel::linearised_spring;
}

beam::LossOfContact loss_of_contact(study::ContactLoss loss) {
  switch (loss) {
    case study::ContactLoss::zero:
      return beam::LossOfContact::zero_force;
    case study::ContactLoss::damping_only:
    case study::ContactLoss::closed:  // the linear law in tension (allow_tension); never opens
      break;
  }
  return beam::LossOfContact::damping_only;
}

beam::ContactLawKind law_kind(const BallOnBeamSettings& b) {
  if (b.linearised()) return beam::ContactLawKind::linearised;
  if (b.contact == ContactModel::table) return beam::ContactLawKind::table;
  if (b.contact == ContactModel::literal) return beam::ContactLawKind::literal_stiffness;
  if (b.path_law()) return beam::ContactLawKind::path;
  return beam::ContactLawKind::hertz;
}

// The exact modal step of very high modes (omega h in the thousands) overflows double precision:
// every realisation would be non-finite. Refused before any work, with the largest mode count
// whose step is finite.
void check_step_coefficients(const BallOnBeamSettings& b) {
  if (b.dopri) return;
  const double h = b.integration_step();
  const beam::ModalBeam& m = b.model.beam;
  for (int i = 0; i < m.modes(); ++i) {
    const auto f = integrators::ExactOscillatorStep::make(m.omega(i), m.zeta(i), h);
    bool ok = std::isfinite(f.a00) && std::isfinite(f.a01) && std::isfinite(f.a10) && std::isfinite(f.a11) &&
              std::isfinite(f.b0) && std::isfinite(f.b1) && std::isfinite(f.c0) && std::isfinite(f.c1);
    if (ok && b.step.hold == beam::ForceHold::quadratic) {
      const auto q = beam::QuadraticHoldStep::make(m.omega(i), m.zeta(i), h);
      for (double v : {q.a00, q.a01, q.a10, q.a11, q.bm, q.b0, q.b1, q.cm, q.c0, q.c1}) ok = ok && std::isfinite(v);
    }
    if (ok) continue;
    const std::string buf = io::formatted(
        "keeps %d modes, but the exact step of mode %d (%.4g Hz, omega h = %.4g) overflows double precision", m.modes(),
        i + 1, m.frequency(i), m.omega(i) * h);
    (b.beam.selection.count > 0 ? b.beam.origin(b.beam.selection.count) : b.beam.origin(b.beam.selection.max_frequency))
        .refuse(std::string(buf) + "; allowed: at most " + std::to_string(i) +
                " modes at this step (or signal.integrator = dopri5)");
  }
}

// [contact] filter and the contact radius a it uses: Hertz under the weight (kernels/beam B35).
void read_contact_filter(const study::EquivalentRoughnessSection& er, BallOnBeamSettings& b, double a) {
  const study::KeyOrigin& filter_origin = b.contact_section.origin(b.contact_section.filter);
  b.filter = b.contact_section.filter;
  b.filter_name = study::spelling_of(study::kContactFilters, b.filter);
  b.contact_half_width = a;
  b.patch_half_width = b.filter == ContactFilter::patch ? a : 0.0;
  // law = path and blocked_force = solver resolve the contact on a strip themselves: a patch filter
  // is accepted there but not applied, and the result says so (/contact@filter is what was applied).
  b.filter_applied = b.filter == ContactFilter::patch && (b.path_law() || b.blocked_solver()) ? "none" : b.filter_name;
  if (b.filter_applied != b.filter_name &&
      b.contact_section.was_set(b.contact_section.filter))  // said, not silently dropped
    b.warnings.push_back(filter_origin.where + ": not applied: " +
                         (b.path_law() ? std::string("law = path") : std::string("blocked_force = solver")) +
                         " resolves the contact on its strip itself, so the line texture is not filtered (the "
                         "result records /contact@filter = none); allowed without this note: filter = none");
  // iso2d and solver filter the line texture (solver: h_eq enters the point law as the line does, ER-2);
  // the blocked-force solver and the path law resolve the rough contact on their strip instead.
  if (b.filter == ContactFilter::iso2d || b.filter == ContactFilter::solver) {
    const bool iso2d = b.filter == ContactFilter::iso2d;
    const std::string filters = std::string(iso2d ? "iso2d" : "solver") + " filters the line texture, which ";
    if (b.blocked_solver())
      filter_origin.refuse(filters +
                           "blocked_force = solver does not use (its strip resolves the contact itself); allowed "
                           "with " +
                           (iso2d ? "solver" : "blocked_force = solver") + ": none or patch (both ignored)");
    if (b.path_law())
      filter_origin.refuse(filters +
                           "law = path does not use (its strip is the roughness); allowed with path: none or patch "
                           "(both ignored)");
  }
  b.strip_line = er.line == study::EquivalentLine::strip;
  // ER-7 corrects a smooth contact's stiffness; a table law from rough surfaces ([stiffness] surface =
  // rough, seed 001's chain) carries the rough contact's compliance already.
  b.equivalent_stiffness = b.filter == ContactFilter::solver && er.stiffness == study::EquivalentStiffness::strip &&
                           !(b.uses_table() && b.stiffness.rough);
  b.equivalent_roughness_strips = er.strips;
  b.equivalent_roughness_leave_out = er.leave_out;
  if (er.leave_out >= 0 && !(b.filter == ContactFilter::solver && !b.strip_line))
    er.origin(er.leave_out)
        .refuse(
            "leaves a strip out of the table [contact] filter = solver synthesises its lines from; allowed with filter "
            "= " +
            b.filter_name + (b.strip_line ? " and line = strip" : "") + ": -1");
  if (er.answer_tolerance > 0.0 && !(b.filter == ContactFilter::solver && !b.strip_line))
    er.origin(er.answer_tolerance)
        .refuse(
            "sets the tolerance of the table [contact] filter = solver synthesises its lines from (contact ER-8); "
            "allowed with filter = " +
            b.filter_name + (b.strip_line ? " and line = strip" : "") + ": 0");
  if (b.strip_line && b.filter != ContactFilter::solver)
    er.origin(er.line).refuse(
        "= strip is the line of [contact] filter = solver; allowed with filter = " + b.filter_name + ": synthesised");
  if (b.filter == ContactFilter::solver && b.linearised())
    filter_origin.refuse(
        "solver gives the equivalent roughness of the nonlinear point laws; allowed with law = "
        "linearised: none, patch or iso2d (or law = hertz, table or literal with solver)");
}

texture::Psd iso2d_study_psd(const BallOnBeamSettings& b) {
  try {
    return iso2d_line_psd(b);
  } catch (const std::exception& e) {
    b.contact_section.origin(b.contact_section.filter)
        .refuse(std::string("cannot filter the [texture] PSD: ") + e.what());
  }
}

}  // namespace

// The step must resolve the ball's bounce on the contact spring: h <= T_c / 20 with
// T_c = 2 pi sqrt(m_ball / k_contact) at the static load (kernels/README.md D-23). Coarser steps stay
// finite but misstate loss of contact and the high-frequency levels, so they are refused.
// With the quadratic hold the ball's step (B37) lets that bounce grow by (w_c h)^4 / 48 per step
// (kernels/beam README B37a): over a long record a bounce that D-23 resolves can grow from rounding
// to loss of contact. Refused unless the contact damper outweighs it (B37b).
void check_contact_resolution(const BallOnBeamSettings& b, double k_contact) {
  const double tc = 2.0 * M_PI * std::sqrt(b.model.ball.mass / k_contact);
  const double h = b.integration_step();
  const double w = 2.0 * M_PI / tc, duration = record_duration(b), m2 = b.model.ball.mass;
  const double decay = b.contact_section.damping / (2.0 * m2);
  // The largest step whose free-bounce growth stays within the limit (B37b), and its substeps.
  const double h_max = std::cbrt(48.0 * (std::log(kFreeBounceGrowthLimit) / duration + decay) / std::pow(w, 4));
  const auto need_growth = free_bounce_growth(b, k_contact) > 1.0 || h > tc / 20.0
                               ? static_cast<long long>(std::ceil(1.0 / (h_max * b.model.sample_rate)))
                               : 0LL;
  const bool grows = !b.dopri && b.step.hold == beam::ForceHold::quadratic;
  if (h > tc / 20.0) {
    // The substeps suggested satisfy B37b too, so following the advice is not refused again.
    const auto need_d23 = static_cast<long long>(std::ceil(20.0 / (tc * b.model.sample_rate)));
    const long long need = grows ? std::max(need_d23, need_growth) : need_d23;
    b.substeps_origin.refuse("the integration step 1 / (sample_rate x substeps) = " + io::four_digits(h) +
                             " s exceeds the contact resolution limit dt <= T_c / 20 = " + io::four_digits(tc / 20.0) +
                             " s (T_c = 2 pi sqrt(m_ball / k_contact), k_contact = " + io::four_digits(k_contact) +
                             " N/m at the ball's weight); allowed: substeps >= " + std::to_string(need) +
                             " at this sample rate" +
                             (need > need_d23 ? " (the quadratic hold's growth limit, kernels/beam README B37b, "
                                                "asks for more than T_c / 20)"
                                              : ""));
  }
  const double growth = free_bounce_growth(b, k_contact);
  if (!(growth > kFreeBounceGrowthLimit)) return;
  const long long need = need_growth;
  const double c_min = 2.0 * m2 * (std::pow(w * h, 4) / (48.0 * h) - std::log(kFreeBounceGrowthLimit) / duration);
  b.substeps_origin.refuse(
      "with the quadratic hold ([signal] hold = quadratic) the step h = " + io::four_digits(h) +
      " s lets the ball's free bounce on the contact spring (T_c = " + io::four_digits(tc) +
      " s, k_contact = " + io::four_digits(k_contact) +
      " N/m at the weight) grow by (2 pi h / T_c)^4 / 48 per step, less the contact "
      "damping's c / (2 m_ball) = " +
      io::four_digits(decay) + " 1/s (kernels/beam README B37a, B37b): a factor " + io::four_digits(growth) +
      " over the record's " + io::four_digits(duration) +
      " s, so rounding grows into spurious loss of contact; allowed: substeps >= " + std::to_string(need) +
      " at this sample rate (growth <= " + io::four_digits(kFreeBounceGrowthLimit) +
      "), [signal] hold = linear (no growth), or [contact] damping >= " + io::four_digits(c_min) + " N s/m");
}

double record_duration(const BallOnBeamSettings& b) {
  const beam::Traverse& t = b.model.traverse;
  return t.speed > 0.0 ? (t.x_end - t.x_start) / t.speed : t.duration;
}

// B37b: the amplitude factor of the free contact bounce over the record, exp(T (w^4 h^3 / 48 - c / 2 m)),
// at least 1; 1 where the step does not grow it (linear hold, Dormand-Prince).
double free_bounce_growth(const BallOnBeamSettings& b, double k_contact) {
  if (b.dopri || b.step.hold != beam::ForceHold::quadratic || !(k_contact > 0.0)) return 1.0;
  const double m2 = b.model.ball.mass, h = b.integration_step();
  const double w = std::sqrt(k_contact / m2);
  const double rate = std::pow(w * h, 4) / (48.0 * h) - b.contact_section.damping / (2.0 * m2);
  return std::exp(std::max(0.0, rate) * record_duration(b));
}

namespace {
// A PSD without upper end is cut where the flat-punch weight (Eq. 37) has fallen below 1e-6 in
// power, or at ten times the line's Nyquist wavenumber if that is further.
double iso2d_q_cap(const BallOnBeamSettings& b) {
  return std::max(1e3 / b.contact_half_width, 10.0 * M_PI / b.spacing);
}
}  // namespace

std::vector<double> iso2d_line_psd_at(const BallOnBeamSettings& b, const std::vector<double>& k) {
  std::vector<double> g = texture::contact_filtered_psd_at(b.texture_psd, b.contact_half_width, k, iso2d_q_cap(b));
  for (std::size_t i = 0; i < k.size(); ++i)
    if (k[i] > b.band_limit_wavenumber) g[i] = 0.0;  // B40 along the path
  return g;
}

// G_eq of the study's PSD (kernels/texture README Eq. 38, 40) from below the line's fundamental.
texture::Psd iso2d_line_psd(const BallOnBeamSettings& b) {
  const double k_min = M_PI / (static_cast<double>(b.line_samples) * b.spacing);
  const double q_cap = iso2d_q_cap(b);
  // From the unlimited [texture]: the band limit (B40) is along the path, while Eq. 38 integrates
  // across it. The line's harmonics reach pi / spacing at most, the band limit drops what lies
  // beyond k_B: G_eq is tabulated up to the lower of the two (zero above, as band_limited).
  return texture::contact_filtered_psd(b.texture_psd, b.contact_half_width, k_min, q_cap,
                                       std::min(M_PI / b.spacing, b.band_limit_wavenumber));
}

BallOnBeamSettings read_ball_on_beam_settings(const BallOnBeamSections& s) {
  const study::SignalSection& signal = s.signal;
  const study::SensorsSection& sensors = s.sensors;
  BallOnBeamSettings b(
      {s.modal_beam, {}, {}, {}, signal.sample_rate, sensor_positions(sensors, s.beam.properties.length)});
  b.beam = s.beam;
  b.ball = s.ball;
  b.substeps_origin = signal.origin(signal.substeps);
  b.sample_rate_origin = signal.origin(signal.sample_rate);
  b.blocked_force = s.blocked_force;
  b.path_table = s.path_table;
  b.strip_surface = s.strip_surface;
  b.stiffness = s.stiffness;
  b.line_keys =
      texture_io::LineGeneratorKeys::of(s.texture, s.roughness.origin(s.roughness.spacing), "[roughness] spacing");
  b.line_keys.speed = s.ball.speed;  // a rolling ball: its speed turns wavelengths into frequencies
  b.line_keys.speed_key = "[ball] speed";
  b.seed = s.study.seed;
  beam::BallOnBeamModel& m = b.model;
  const double length = b.beam.properties.length;
  b.texture_psd = s.texture_psd;
  b.psd = b.texture_psd;
  b.contact_section = s.contact;
  const study::RoughnessSection& roughness = s.roughness;
  const study::OutputSection& output = s.output;
  b.sensor_mean = sensors.average;
  b.dopri = signal.integrator == study::SignalIntegrator::dopri5;
  b.rtol = signal.rtol;
  const study::SpectrumSection& spectrum = s.spectrum;
  b.confidence = spectrum.confidence;
  b.band_min = spectrum.band_min;
  b.band_max = spectrum.band_max;
  b.band_max_origin = spectrum.origin(spectrum.band_max);
  b.time_histories = static_cast<std::size_t>(output.time_histories);
  b.reference = output.reference;
  // Ball and its traverse.
  const double radius = b.ball.radius;
  m.ball.mass = b.ball.mass();
  m.ball.gravity = b.ball.gravity;
  m.traverse.x_start = b.ball.start;
  m.traverse.x_end = b.ball.end;
  m.traverse.speed = b.ball.speed;
  if (!(m.traverse.x_end > m.traverse.x_start)) b.ball.origin(b.ball.end).refuse("must exceed [ball] start");
  if (m.traverse.x_end > length) b.ball.origin(b.ball.end).refuse("lies beyond the span [0, length]");
  // Anti-alias band limit (kernels/beam B40): the output holds f <= f_s / 2, that is k <= pi f_s / v;
  // roughness beyond it would drive the linear response above f_s / 2, which the sampling aliases in.
  if (roughness.band_limit == study::BandLimit::output) {
    b.band_limit_wavenumber = M_PI * m.sample_rate / m.traverse.speed;
    b.psd = texture::band_limited(std::move(b.psd), b.band_limit_wavenumber);
  }
  // Contact.
  b.law_name = study::spelling_of(study::kContactLaws, b.contact_section.law);
  b.contact = contact_model(b.contact_section);
  beam::ContactLaw& law = m.contact;
  law.kind = law_kind(b);
  law.effective_modulus = b.ball.effective_modulus(b.beam.properties.youngs_modulus, b.beam.poisson);
  law.radius = radius;
  law.k0 = b.contact_section.k0;
  law.damping = b.contact_section.damping;
  law.loss = loss_of_contact(b.contact_section.loss);
  // closed: linearised only (the section refuses it otherwise).
  law.allow_tension = b.contact_section.loss == study::ContactLoss::closed;
  const double hertz_compression = contact::hertz::approach_at_load(radius, law.effective_modulus, b.weight());
  b.static_compression = b.linearised() ? b.weight() / law.k0 : hertz_compression;
  read_contact_filter(s.equivalent_roughness, b, contact::hertz::contact_radius_at_approach(radius, hertz_compression));
  const study::TextureSection& texture = s.texture;
  b.roughness_origin = texture.source == study::TextureSource::self_affine ? texture.origin(texture.rms)
                                                                           : texture.origin(texture.source);
  // Before any step or table check that the values could break.
  for (auto& w : check_ball_on_beam_plausibility(b)) b.warnings.push_back(std::move(w));
  // Integration step.
  b.step.substeps = static_cast<int>(signal.substeps);
  b.step.hold = signal.hold;
  // Roughness line over the whole span, so the patch filter and the traverse never run off it.
  // One roughness sample per integration step by default: the interpolation between samples then
  // low-passes the excitation only near the step's own Nyquist frequency.
  b.spacing = roughness.spacing > 0.0 ? roughness.spacing
                                      : m.traverse.speed / (m.sample_rate * static_cast<double>(b.step.substeps));
  b.line_samples = static_cast<std::size_t>(std::floor(length / b.spacing)) + 1;
  // A spacing that does not divide the span leaves the last sample short of it: the line must still
  // reach the traverse's end and the contact patch around it.
  const double reach = m.traverse.x_end + b.patch_half_width;
  if (static_cast<double>(b.line_samples - 1) * b.spacing < reach)
    b.line_samples = static_cast<std::size_t>(std::ceil(reach / b.spacing)) + 1;
  if (b.line_samples > (1u << 26))
    roughness.origin(roughness.spacing).refuse("gives more than 2^26 samples over the span");
  // The patch average runs on the samples' linear interpolant (B35a: an extra sinc^2(k dx/2));
  // a band-limited line is drawn with that loss undone (B40a), so it sees the continuous texture.
  if (b.filter == ContactFilter::iso2d)
    b.line_psd = iso2d_study_psd(b);  // no patch average on the samples: nothing to compensate (B40a)
  else if (b.filter == ContactFilter::solver)
    b.line_psd = b.psd;  // until the equivalent-roughness stage (no patch average: nothing to compensate, B40a)
  else
    b.line_psd = (b.patch_half_width > 0.0 && b.band_limit_wavenumber * b.spacing < M_PI)
                     ? texture::interpolation_compensated(b.psd, b.spacing)
                     : b.psd;
  if (!b.uses_table() && !b.blocked_solver()) {
    b.contact_stiffness =
        b.linearised() ? law.k0
                       : contact::hertz::stiffness_at_approach(radius, law.effective_modulus, b.static_compression);
    check_contact_resolution(b, b.contact_stiffness);
  }
  check_step_coefficients(b);
  // Record and spectra.
  b.samples = beam::output_samples(m);
  b.skip = static_cast<std::size_t>(std::ceil(spectrum.skip_start * m.sample_rate));
  check_analysed_record(spectrum, b.samples, b.skip, "((end - start) / speed - skip_start) x sample_rate");
  b.welch = study_welch_config(spectrum, m.sample_rate);
  return b;
}

// The [contact] filter line of the plan text, with the half width it averages over.
std::string contact_filter_description(const BallOnBeamSettings& b) {
  if (b.blocked_solver()) return "contact filter: not used (blocked_force = solver)";
  const std::string a = io::formatted("%.4g", b.contact_half_width * 1e6);
  switch (b.filter) {
    case ContactFilter::none:
      return "contact filter: none (point contact)";
    case ContactFilter::patch:
      return std::string("contact filter: patch, 1D average over 2a, a = ") + a + " um (B35)";
    case ContactFilter::iso2d:
      break;
    case ContactFilter::solver:
      return std::string(
                 "contact filter: solver, line PSD of the equivalent roughness h_eq of half-space solves at "
                 "the weight (kernels/contact ER-1..ER-7), Hertz a = ") +
             a + " um" +
             (b.equivalent_stiffness
                  ? "; the point law carries the weight with the strips' mean contact stiffness (ER-7)"
              : b.uses_table() && b.stiffness.rough
                  ? "; the table law's own stiffness (its rough surfaces carry the rough contact's compliance: no "
                    "ER-7)"
                  : "; the point law's own stiffness ([equivalent_roughness] stiffness = law)");
  }
  return std::string("contact filter: iso2d, line PSD G_eq of a Hertz disc of radius a = ") + a +
         " um on the isotropic surface (kernels/texture Eq. 38)";
}

}  // namespace rollspec::scenes
