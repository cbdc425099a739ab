#pragma once
// Version of the contact kernel's numerical results. Bump it whenever a change can alter any
// number a stiffness table stores (discretisation, stopping rule, outputs' definitions), so cached
// tables built by an older kernel are refused (issue 4, `kernel_version` / `input_hash`).
namespace rollspec::contact {

// 2: sub-cell contact edge in the stiffness (README Eq. 13–15). 3: blocked half-space product and
// cell sums, carried displacement, coarse start (README Eq. 3a, 7a, 16): the same solutions to the
// stopping rule, other last bits.
inline constexpr int kernel_version = 3;

}  // namespace rollspec::contact
