"""
A measured height map on a half-space: contact area and stiffness against load
===============================================================================

An AFM map (600 nm square, 256 × 256 pixels; SurfaceTopography's test file ``top-1.top``, MIT
licence, converted by ``studies/data/measured-profiles/make_measured_profiles.py``) pressed by a rigid
flat into steel, in-process with the module ``rollspec``: ``rollspec.contact.solve`` in displacement
control at a series of approaches, elastic and with a 5 GPa pressure cap. Each solve returns the force,
the true contact area and the contact stiffness dF/dw of its contact set. For one smooth asperity
Hertz gives area ~ F^(2/3) and stiffness ~ F^(1/3); for a self-affine surface with roughness over many
decades of wavelength, the theories of Persson and of Pastewka et al. (2013) give both nearly proportional
to F at light loads. This map spans two decades (2.3 to 600 nm), and the printed log-log slopes at its
five lightest loads show where it stands between the two; a pressure cap lets the area grow faster.
"""
import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from rollspec_post.script_main import one_line_errors

one_line_errors()  # run as python3 FILE: a failure is one line, not a traceback
import rollspec.contact as contact  # noqa: E402 (the module: README's first command, or BUILD/python on PYTHONPATH)

# The repository: $ROLLSPEC_SOURCE when the site is built, else this file's checkout.
REPO = Path(os.environ.get("ROLLSPEC_SOURCE") or Path(__file__).resolve().parents[2])
heights = np.load(REPO / "studies" / "data" / "measured-profiles" / "top-1-map.npy")  # m, (256, 256)
dx = 600e-9 / heights.shape[1]  # the scan's 600 nm over 256 pixels
gap = heights.max() - heights  # a rigid flat first touches the highest pixel
e_star = contact.effective_modulus(210e9, 0.3, 210e9, 0.3)  # steel on steel (Pa)
approaches = np.geomspace(0.02, 0.5, 10) * np.ptp(heights)  # m past first contact

fig, (ax_area, ax_stiff) = plt.subplots(1, 2, figsize=(8, 3.6))
for hardness, label in [(0.0, "elastic"), (5e9, "hardness 5 GPa")]:
    solves = [contact.solve(gap, dx, e_star=e_star, approach=w, hardness=hardness) for w in approaches]
    force = np.array([s["force"] for s in solves])  # N
    area = np.array([s["contact_area"] for s in solves]) / (600e-9) ** 2  # share of the map in contact
    stiffness = np.array([s["stiffness"] for s in solves])  # N/m
    ax_area.loglog(force, area, "o-", label=label)
    ax_stiff.loglog(force, stiffness, "o-", label=label)
    light = slice(0, 5)  # the five lightest loads
    print(f"{label}: area ~ F^{np.polyfit(np.log(force[light]), np.log(area[light]), 1)[0]:.2f}, "
          f"stiffness ~ F^{np.polyfit(np.log(force[light]), np.log(stiffness[light]), 1)[0]:.2f} "
          f"at the five lightest loads; CG iterations {min(s['iterations'] for s in solves)} to "
          f"{max(s['iterations'] for s in solves)}")
ax_area.set_xlabel("force (N)")
ax_area.set_ylabel("contact area / map area")
ax_stiff.set_xlabel("force (N)")
ax_stiff.set_ylabel("contact stiffness dF/dw (N/m)")
ax_area.legend()
fig.tight_layout()
