# Type stub of rollspec.surfaces (python/surface_bindings.cpp); units in the docstrings.
from typing import Any, Dict, Optional

import numpy.typing as npt

def line(
    wavenumber: npt.ArrayLike,
    psd: npt.ArrayLike,
    spacing: float,
    samples: int,
    *,
    seed: int,
    index: int = 0,
    amplitudes: str = "rayleigh",
    extension: str = "error",
) -> Dict[str, Any]: ...
def isotropic(
    wavenumber: npt.ArrayLike,
    psd: npt.ArrayLike,
    spacing: float,
    nx: int,
    ny: Optional[int] = None,
    *,
    seed: int,
    index: int = 0,
    method: str = "spectral",
    amplitudes: str = "rayleigh",
    extension: str = "error",
    anisotropy: float = 1.0,
    sigma: float = 3e-7,
    correlation_x: float = 1e-5,
    correlation_y: float = 1e-5,
) -> Dict[str, Any]: ...
