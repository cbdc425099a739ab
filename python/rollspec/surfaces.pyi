# Type stub of rollspec.surfaces (python/surface_bindings.cpp); units in the docstrings.
from typing import Any, Dict, List, Optional

import numpy as np
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

class ProfilePsd:
    """The PSD of measured profiles (python/profile_bindings.cpp); units in the docstrings."""

    @property
    def wavenumber(self) -> npt.NDArray[np.float64]: ...
    @property
    def periodogram(self) -> npt.NDArray[np.float64]: ...
    @property
    def dk(self) -> float: ...
    @property
    def spacing(self) -> float: ...
    @property
    def samples(self) -> int: ...
    @property
    def scans(self) -> int: ...
    @property
    def sigma(self) -> float: ...
    @property
    def correlation_length(self) -> float: ...
    @property
    def variance(self) -> float: ...
    @property
    def resolved_variance(self) -> float: ...
    @property
    def unresolved_variance(self) -> float: ...
    @property
    def first_resolved(self) -> int: ...
    @property
    def resolved_wavenumber(self) -> float: ...
    @property
    def short_wavelength_cut(self) -> float: ...
    @property
    def description(self) -> str: ...
    def __call__(self, wavenumber: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def line(
        self, spacing: float, samples: int, *, seed: int, index: int = 0, amplitudes: str = "rayleigh"
    ) -> Dict[str, Any]: ...
    def isotropic(
        self,
        spacing: float,
        nx: int,
        ny: Optional[int] = None,
        *,
        seed: int,
        index: int = 0,
        method: str = "spectral",
        amplitudes: str = "rayleigh",
        anisotropy: float = 1.0,
        sigma: Optional[float] = None,
        correlation_x: Optional[float] = None,
        correlation_y: Optional[float] = None,
    ) -> Dict[str, Any]: ...

def profile_psd(
    heights: npt.ArrayLike,
    spacing: float,
    *,
    median_filter: bool = False,
    extension: str = "error",
    short_wavelength: Optional[float] = None,
) -> ProfilePsd: ...
def read_profiles(
    paths: List[str],
    *,
    median_filter: bool = False,
    extension: str = "error",
    short_wavelength: Optional[float] = None,
) -> ProfilePsd: ...
def read_profile(path: str) -> Dict[str, Any]: ...
