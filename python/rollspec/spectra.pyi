# Type stub of rollspec.spectra (python/spectra_bindings.cpp); units in the docstrings.
import os
from typing import Any, Dict, Optional, Sequence, Union

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
def read_measurement(
    path: Union[str, bytes, os.PathLike],
    *,
    column: Optional[Union[str, Sequence[str]]] = None,
    unit: Optional[str] = None,
    time_column: Optional[str] = None,
    fs: Optional[float] = None,
    scale: Optional[float] = None,
    skip_rows: Optional[int] = None,
) -> Dict[str, Any]: ...
