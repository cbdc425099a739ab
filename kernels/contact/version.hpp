#pragma once
// Version of the contact kernel's numerical results. Bump it whenever a change can alter any
// number a stiffness table stores (discretisation, stopping rule, outputs' definitions), so cached
// tables built by an older kernel are refused (issue 4, `kernel_version` / `input_hash`).
namespace rollspec::contact {

// 2: sub-cell contact edge in the stiffness (README Eq. 13–15). 3: blocked half-space product and
// cell sums, carried displacement, coarse start (README Eq. 3a, 7a, 16): the same solutions to the
// stopping rule, other last bits. 4: open padding to the smallest 2^a 3^b 5^c 7^d >= 2n - 1 (README
// Eq. 3) instead of 2n: the same sums, other last bits. 5: displacement control's products on A and
// E on the box that holds them (Eq. 3c), the frozen-set CG from a given rate (Eq. 11a), chunked paths.
// 6: the outputs' gap and u' = C dp on the box around A and E (Eq. 3d): other last bits of the
// plastic volume and the stiffness's sub-cell edge. 7: the blocked-force load search's cold path
// solved loosely (BF-4''), its stop at the solves' accuracy and its stiffness CG to the solver
// tolerance: another d0 within the solver tolerance. 8: the answer's method (BF-9) on a strip too long
// for every check_stride-th loose field in memory checks every 2^j check_stride-th instead of none (its
// k0 by the control variate, its error recorded): the seed 002 route's 0.35 m strip; other tables the same.
inline constexpr int kernel_version = 8;

}  // namespace rollspec::contact
