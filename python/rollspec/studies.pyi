# Type stub of rollspec.studies (python/study_bindings.cpp, python/compare_bindings.cpp).
from os import PathLike
from typing import Any, Dict, Optional, Sequence, Union

def run(
    study: Union[str, PathLike[str]],
    out: Optional[Union[str, PathLike[str]]] = None,
    *,
    set: Sequence[str] = [],
    resume: bool = False,
    restart: bool = False,
    force: bool = False,
    rebuild: bool = False,
    quiet: bool = True,
    threads: Optional[int] = None,
) -> str: ...

def compare(
    result: Union[str, PathLike[str]],
    recordings: Union[str, PathLike[str], Sequence[Union[str, PathLike[str]]]],
    *,
    noise: Optional[Union[str, PathLike[str]]] = None,
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
