#pragma once
// Reference ball-on-beam integrator: the full first-order system y = [q, q', w2, w2'] (seed 002
// Eq. 10–14) by adaptive Dormand–Prince 5(4) with dense output (dopri5.hpp), README Eq. (B28).
// The contact force is solved from the instantaneous state at every stage (B21 with D = 0; the
// residual flexibility makes delta depend on F), mode shapes are evaluated on the fly. Slow and
// plain: the oracle the exact-step integrator is tested against.
#include "kernels/beam/ball_on_beam.hpp"

namespace rollspec::beam {

struct ReferenceTolerances {
  double rtol = 1e-9;
  double atol_displacement = 1e-15;  // m, for q_n and w2; velocities get atol * omega_max
  double max_step = 0.0;             // s, 0: unlimited
};

BallOnBeamResult simulate_dopri5(const BallOnBeamModel& model, const Realisation& realisation,
                                 const ReferenceTolerances& tolerances = {});

}  // namespace rollspec::beam
