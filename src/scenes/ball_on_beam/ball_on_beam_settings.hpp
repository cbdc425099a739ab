#pragma once
// Scene `ball-on-beam`'s sections (ball_on_beam_sections.hpp) made into one value, with the checks that span several
// keys (the record against the span, the step against the contact's bounce and the modes, the
// Welch segment against the record). The scene (ball_on_beam.cpp) builds from this value and the
// sections' table input (stiffness::TableStudy) only.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "kernels/beam/ball_on_beam.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/texture/psd.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/key_origin.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/sections/path_table_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/strip_surface_section.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

struct BallOnBeamSections;

// One value for the contact law and the blocked force's source ([contact] law, blocked_force).
enum class ContactModel { hertz, table, literal, linearised_spring, linearised_solver, path };

// [contact] filter: what the contact does to the roughness it rolls over (kernels/beam README B35;
// kernels/texture README Eq. 36-40): none (point contact), patch (1D average over the Hertz width,
// B35), iso2d (the line synthesised from G_eq, the path PSD a Hertz disc sees on an isotropic surface)
// or solver (the line synthesised from the strip-mean PSD of h_eq, kernels/contact ER-1..ER-7, a table stage).
using ContactFilter = study::ContactFilter;

struct BallOnBeamSettings {
  explicit BallOnBeamSettings(beam::BallOnBeamModel m) : model(std::move(m)) {}
  std::uint64_t seed = 0;
  study::ModalBeamSection beam;           // [beam] as read
  study::BallSection ball;                // [ball] as read
  study::ContactSection contact_section;  // [contact] as read
  study::KeyOrigin substeps_origin, sample_rate_origin, band_max_origin;
  study::KeyOrigin roughness_origin;  // the key that sets the line's height: [texture] rms, else its source
  // The strip stages' grids where the study sets them (blocked force, equivalent roughness, path table).
  study::BlockedForceSection blocked_force;
  study::PathTableSection path_table;
  study::StripSurfaceSection strip_surface;
  study::StiffnessSection stiffness;        // [stiffness]: the table law's surface and approach range
  texture_io::LineGeneratorKeys line_keys;  // the line texture's amplitudes; errors at [roughness] spacing  // [signal]
                                            // substeps, for the step checks of the table stages
  // Beam, ball, traverse, sensors, output rate and the contact law as far as the keys fix it;
  // the table stages complete the law (compression table, or k0 of the blocked force) in the scene's
  // ResolvedContact (ball_on_beam_contact.hpp): the settings stay as read.
  beam::BallOnBeamModel model;
  ContactModel contact = ContactModel::hertz;
  std::string law_name;      // [contact] law as written, for the result file
  texture::Psd texture_psd;  // [texture] as given: the surface iso2d filters (no band limit across the path)
  texture::Psd psd;          // [texture], band-limited by [roughness] band_limit
  double band_limit_wavenumber = std::numeric_limits<double>::infinity();  // rad/m; B40
  // What the line samples are drawn from: psd (none), psd B40a-compensated (patch on a band-limited
  // line), or G_eq of texture_psd, band-limited (iso2d); for solver, psd until the equivalent-roughness
  // table stage gives the PSD of h_eq, band-limited (in ResolvedContact).
  texture::Psd line_psd;
  ContactFilter filter = ContactFilter::patch;
  std::string filter_name;     // [contact] filter as written
  std::string filter_applied;  // the filter the roughness actually passes through
  // filter = solver with [equivalent_roughness] line = strip: the line is h_eq of strip 0 along the path
  // (the path table's strip and grid), the same for every realisation, not synthesised.
  bool strip_line = false;
  // filter = solver with [equivalent_roughness] stiffness = strip: the point law carries the weight with
  // the strips' mean contact stiffness (kernels/contact ER-7).
  bool equivalent_stiffness = false;
  // filter = solver: [equivalent_roughness] leave_out, the strip the table is used without (-1: none; D-30).
  long long equivalent_roughness_leave_out = -1;
  long long equivalent_roughness_strips = 0;
  double contact_half_width = 0.0;  // Hertz contact radius a at the weight (what the filters use)
  double spacing = 0.0;             // line texture sample spacing, m
  std::size_t line_samples = 0;     // over the whole span
  double patch_half_width = 0.0;    // contact_half_width for filter = patch, else 0 (no patch average)
  double contact_stiffness = 0.0;   // the point law's tangent stiffness at the weight (0: tables, solver)
  double static_compression = 0.0;  // the keys' law at the weight: Hertz (or weight / k0); tables resolve theirs
  beam::ExactStepOptions step;
  bool dopri = false;  // Dormand-Prince reference instead of the exact step
  double rtol = 1e-8;
  std::size_t samples = 0, skip = 0;  // output samples per record, left out at its start
  spectral::WelchConfig welch;
  bool sensor_mean = true;
  double confidence = 0.95, band_min = 0.0, band_max = 0.0;
  std::size_t time_histories = 0;
  bool reference = true;              // [output] reference (written for the linearised law only)
  std::vector<std::string> warnings;  // legal but suspect physics (ball_on_beam_plausibility)

  bool linearised() const {
    return contact == ContactModel::linearised_spring || contact == ContactModel::linearised_solver;
  }
  bool uses_table() const { return contact == ContactModel::table || contact == ContactModel::literal; }
  bool blocked_solver() const { return contact == ContactModel::linearised_solver; }
  bool path_law() const { return contact == ContactModel::path; }  // law = path: the strip is the roughness
  double weight() const { return model.ball.mass * model.ball.gravity; }
  double integration_step() const { return 1.0 / (model.sample_rate * static_cast<double>(step.substeps)); }
};

BallOnBeamSettings read_ball_on_beam_settings(const BallOnBeamSections& s);

// The [contact] filter line of the plan text: which filter, over what half width.
std::string contact_filter_description(const BallOnBeamSettings& b);

// G_eq of b.psd for the Hertz radius b.contact_half_width (filter = iso2d), over the line's
// wavenumbers; throws std::invalid_argument where the PSD has no isotropic form.
texture::Psd iso2d_line_psd(const BallOnBeamSettings& b);
// The same G_eq at the wavenumbers k directly (for /roughness when the study uses another filter).
std::vector<double> iso2d_line_psd_at(const BallOnBeamSettings& b, const std::vector<double>& k);

// Refuses (at [signal] substeps) a step that does not resolve the ball's bounce on a contact
// stiffness k_contact at the weight; the table laws call it again once their stiffness is known.
void check_contact_resolution(const BallOnBeamSettings& b, double k_contact);

// B37b: above it the free contact bounce's growth over the record is refused (10 % in amplitude).
constexpr double kFreeBounceGrowthLimit = 1.1;
// The amplitude factor of the ball's free bounce on k_contact over the record under the step
// (kernels/beam README B37b); 1 with the linear hold or Dormand-Prince.
double free_bounce_growth(const BallOnBeamSettings& b, double k_contact);
// The traverse's duration (s): (end - start) / speed, or the still ball's duration.
double record_duration(const BallOnBeamSettings& b);

}  // namespace rollspec::scenes
