# Type stub of rollspec.studies (python/study_bindings.cpp).
from os import PathLike
from typing import Optional, Sequence, Union

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
