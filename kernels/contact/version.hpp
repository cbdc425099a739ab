#pragma once
// Version of the contact kernel's numerical results. Bump it whenever a change can alter any
// number a stiffness table stores (discretisation, stopping rule, outputs' definitions), so cached
// tables built by an older kernel are refused (issue 4, `kernel_version` / `input_hash`).
namespace rollspec::contact {

inline constexpr int kernel_version = 2;  // 2: sub-cell contact edge in the stiffness (README Eq. 13–15)

}  // namespace rollspec::contact
