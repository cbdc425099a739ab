# Type stub of rollspec.surfaces (python/surface_bindings.cpp); units in the docstrings.
from typing import Any, Dict

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
