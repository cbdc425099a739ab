#pragma once
// [contact] (scene ball-on-beam): the contact law, its damping and loss of contact, the linearised
// law's blocked force and the filter on the roughness, read once; the checks across sections stay
// with the scene's settings (ball_on_beam_settings), named by the origins kept here.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class ContactLaw { hertz, table, literal, linearised, path };
enum class ContactLoss { damping_only, zero, closed };
enum class BlockedForceSource { spring, solver };
// What the contact does to the roughness it rolls over (kernels/beam README B35; kernels/texture
// README Eq. 36-40).
enum class ContactFilter { none, patch, iso2d, solver };

inline constexpr ChoiceTable<ContactLaw, 5> kContactLaws{{
    {ContactLaw::hertz, "hertz", "smooth Hertz P(delta)"},
    {ContactLaw::table, "table", "rough-surface P(delta) from the stiffness stage"},
    {ContactLaw::literal, "literal", "seed 001 Eq. 7: k_c(delta) delta from the same table"},
    {ContactLaw::linearised, "linearised", "seed 002: blocked force F0 and contact stiffness k0"},
    {ContactLaw::path, "path",
     "P(delta, xi) of one rough strip from a cached table of contact solves along the ball's path, "
     "kernels/beam B41-B46; the strip is the roughness"},
}};
inline constexpr ChoiceTable<ContactLoss, 3> kContactLosses{{
    {ContactLoss::damping_only, "damping_only", "seed 001 Eq. 8"},
    {ContactLoss::zero, "zero", ""},
    {ContactLoss::closed, "closed",
     "law = linearised only: the contact never opens, the linear law holds in tension too (the "
     "counterfactual that sizes loss of contact, kernels/spectral D-35)"},
}};
inline constexpr ChoiceTable<BlockedForceSource, 2> kBlockedForceSources{{
    {BlockedForceSource::spring, "spring", "W + k0 h_patch(v t), k0 from [contact]"},
    {BlockedForceSource::solver, "solver",
     "the contact solver's blocked force along a rough strip, seed 002 §4.2: k0, d0 and the F0 PSD from a "
     "cached table"},
}};
inline constexpr ChoiceTable<ContactFilter, 4> kContactFilters{{
    {ContactFilter::none, "none", "point contact"},
    {ContactFilter::patch, "patch", "1D average over 2a along the path, B35"},
    {ContactFilter::iso2d, "iso2d",
     "line synthesised from G_eq, the path PSD a Hertz disc sees on an isotropic surface, kernels/texture Eq. 38"},
    {ContactFilter::solver, "solver",
     "line synthesised from the PSD of the equivalent roughness h_eq of half-space solves at the weight on "
     "[equivalent_roughness] strips rough strips, kernels/contact ER-1..ER-7, a cached table; point laws only"},
}};

struct ContactSection : DeclaredSection<ContactSection> {
  ContactLaw law = ContactLaw::hertz;
  ContactLoss loss = ContactLoss::damping_only;
  BlockedForceSource blocked_force = BlockedForceSource::spring;
  ContactFilter filter = ContactFilter::patch;
  double damping = 0.0, k0 = 0.0;
  // The laws that read a stiffness table (table: the fitted curve; literal: seed 001 Eq. 7 from it).
  bool uses_stiffness_table() const { return law == ContactLaw::table || law == ContactLaw::literal; }
  // The linearised law with the contact solver's blocked force (a blocked-force table).
  bool blocked_solver() const { return law == ContactLaw::linearised && blocked_force == BlockedForceSource::solver; }

  static SectionKeys<ContactSection> declare();
  void finish();                                   // checks across its keys, once they are read
  static std::string loss_setting(ContactLoss v);  // "contact.loss=<spelling>", a --set text
};

}  // namespace rollspec::study
