# Type stub of rollspec.studies (python/study_bindings.cpp, python/compare_bindings.cpp; open: python/rollspec/__init__.py).
from os import PathLike
from typing import Any, Dict, Mapping, Optional, Sequence, Union, overload

import xarray

_Path = Union[str, PathLike[str]]
_Sets = Union[Sequence[str], Mapping[str, Any]]

class Study:
    @staticmethod
    def from_file(path: _Path) -> Study: ...
    @staticmethod
    def from_text(text: str, path: Optional[_Path] = None) -> Study: ...
    @staticmethod
    def from_dict(sections: Mapping[str, Mapping[str, Any]], path: Optional[_Path] = None) -> Study: ...
    @property
    def path(self) -> Optional[str]: ...
    @property
    def text(self) -> Optional[str]: ...

def run(
    study: Union[_Path, Study],
    out: Optional[_Path] = None,
    *,
    set: _Sets = [],
    resume: bool = False,
    restart: bool = False,
    force: bool = False,
    rebuild: bool = False,
    quiet: bool = True,
    threads: Optional[int] = None,
) -> str: ...

def compare(
    result: _Path,
    recordings: Union[str, PathLike[str], Sequence[_Path]],
    *,
    noise: Optional[_Path] = None,
    sensor: Optional[str] = None,
    measured_position: Optional[float] = None,
    point: Optional[str] = None,
    column: Optional[Union[str, Sequence[str]]] = None,
    unit: Optional[str] = None,
    scale: Optional[float] = None,
    fs: Optional[float] = None,
    time_column: Optional[str] = None,
    skip_rows: Optional[int] = None,
    roll_per_channel: bool = False,
    measured_averages: Optional[float] = None,
    noise_margin: float = 10.0,
    keep_floor_bands: bool = False,
    same_surface: bool = False,
    fmin: float = 0.0,
    fmax: Optional[float] = None,
    test_level: float = 0.05,
) -> Dict[str, Any]: ...

def plan(study: Union[_Path, Study], *, set: _Sets = [], probe: bool = False) -> Dict[str, Any]: ...
@overload
def open(path: _Path, group: None = None) -> Dict[str, xarray.Dataset]: ...
@overload
def open(path: _Path, group: str) -> xarray.Dataset: ...

def fit(
    study: _Path,
    measurements: Union[_Path, Sequence[_Path]],
    *,
    vary: Union[str, Sequence[str]],
    measured_averages: Union[float, Sequence[float]],
    at: Optional[Union[str, Sequence[str]]] = None,
    set: Sequence[str] = [],
    sensor: Optional[str] = None,
    measured_position: Optional[float] = None,
    column: Optional[str] = None,
    fmin: float = 0.0,
    fmax: Optional[float] = None,
    journal: Optional[_Path] = None,
    same_surface: bool = False,
    threads: Optional[int] = None,
) -> Dict[str, Any]: ...
