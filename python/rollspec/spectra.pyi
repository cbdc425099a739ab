# Type stub of rollspec.spectra (python/spectra_bindings.cpp); units in the docstrings.
from typing import Any, Dict

import numpy.typing as npt

def welch(
    x: npt.ArrayLike,
    fs: float,
    *,
    segment: int = 1024,
    overlap: float = 0.5,
    window: str = "hann",
    detrend: str = "constant",
) -> Dict[str, Any]: ...
def bands(
    x: npt.ArrayLike,
    fs: float,
    *,
    segment: int = 1024,
    overlap: float = 0.5,
    window: str = "hann",
    detrend: str = "constant",
    band_min: float = 10.0,
    band_max: float = 1e9,
    confidence: float = 0.95,
) -> Dict[str, Any]: ...
