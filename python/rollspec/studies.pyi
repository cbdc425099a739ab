# Type stub of rollspec.studies (python/study_bindings.cpp; open: python/rollspec/__init__.py).
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
def plan(study: Union[_Path, Study], *, set: _Sets = [], probe: bool = False) -> Dict[str, Any]: ...
@overload
def open(path: _Path, group: None = None) -> Dict[str, xarray.Dataset]: ...
@overload
def open(path: _Path, group: str) -> xarray.Dataset: ...
