#include "src/study/sections/contact_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> ContactSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      choice_key("contact", "law",
                 "contact law: hertz (smooth Hertz P(delta)), table (rough-surface P(delta) from the stiffness stage), "
                 "literal (seed 001 Eq. 7: k_c(delta) delta from the same table), linearised (seed 002: blocked "
                 "force F0 and contact stiffness k0) or path (P(delta, xi) of one rough strip from a cached table of "
                 "contact solves along the ball's path, kernels/beam B41-B46; the strip is the roughness)",
                 std::string("hertz"), {"hertz", "table", "literal", "linearised", "path"}),
      real_key("contact", "damping", "N s/m", "contact damping c_c (c0 for the linearised law)", std::string("100"),
               0.0, inf),
      choice_key("contact", "loss",
                 "force during loss of contact: damping_only (seed 001 Eq. 8) or zero; closed (law = linearised "
                 "only): the contact never opens, the linear law holds in tension too (the counterfactual that "
                 "sizes loss of contact, kernels/spectral D-35)",
                 std::string("damping_only"), {"damping_only", "zero", "closed"}),
      real_key("contact", "k0", "N/m", "linearised contact stiffness k0", std::string("6.8e6"), 0.0, inf, false),
      choice_key(
          "contact", "blocked_force",
          "linearised law's F0(t): spring (W + k0 h_patch(v t), k0 from [contact]) or solver (the contact "
          "solver's blocked force along a rough strip, seed 002 §4.2: k0, d0 and the F0 PSD from a cached table)",
          std::string("spring"), {"spring", "solver"}),
      choice_key("contact", "filter",
                 "what the contact does to the roughness (Hertz radius a at the weight): none (point contact), patch "
                 "(1D average over 2a along the path, B35), iso2d (line synthesised from G_eq, the path PSD a Hertz "
                 "disc sees on an isotropic surface, kernels/texture Eq. 38) or solver (line synthesised from the PSD "
                 "of the equivalent roughness h_eq of half-space solves at the weight on [equivalent_roughness] strips "
                 "rough strips, kernels/contact ER-1..ER-7, a cached table; point laws only)",
                 std::string("patch"), {"none", "patch", "iso2d", "solver"}),
  };
}

ContactSection ContactSection::parse(const KeyReader& s) {
  ContactSection p;
  p.law = s.text("contact.law");
  p.damping = s.real("contact.damping");
  p.loss = s.text("contact.loss");
  p.k0 = s.real("contact.k0");
  p.blocked_force = s.text("contact.blocked_force");
  p.filter = s.text("contact.filter");
  p.filter_origin = {s.where("contact.filter")};
  p.filter_set = s.is_set("contact.filter");
  if (p.loss == "closed" && p.law != "linearised")
    KeyOrigin{s.where("contact.loss")}.refuse(
        "a contact that never opens is the linear law's counterfactual; "
        "allowed with [contact] law = " +
        p.law + ": damping_only or zero");
  return p;
}

}  // namespace rollspec::study
