# Type stub of rollspec.contact (python/contact_bindings.cpp); units in the docstrings.
import os
from typing import Any, Dict, List, Optional, Union

import numpy as np
import numpy.typing as npt

def solve(
    gap: npt.ArrayLike,
    dx: float,
    *,
    e_star: float,
    dy: Optional[float] = None,
    approach: Optional[float] = None,
    force: Optional[float] = None,
    hardness: float = 0.0,
    tolerance: float = 1e-08,
    max_iterations: int = 20000,
    stiffness: bool = True,
) -> Dict[str, Any]: ...
def ball_gap(
    radius: float, dx: float, nx: int, ny: int, *, dy: Optional[float] = None, shape: str = "sphere"
) -> npt.NDArray[np.float64]: ...
def effective_modulus(e1: float, nu1: float, e2: float, nu2: float) -> float: ...
def stiffness_table(
    study: Union[str, "os.PathLike[str]"],
    *,
    set: List[str] = [],
    rebuild: bool = False,
    quiet: bool = True,
    threads: Optional[int] = None,
) -> Table: ...
def tables(
    study: Union[str, "os.PathLike[str]"],
    *,
    set: List[str] = [],
    rebuild: bool = False,
    quiet: bool = True,
    threads: Optional[int] = None,
) -> Dict[str, Table]: ...

class Table:
    """A cached stage table (python/table_bindings.cpp): columns and scalars are also attributes."""

    @staticmethod
    def read(path: str) -> Table: ...
    @property
    def status(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def path(self) -> str: ...
    @property
    def input_hash(self) -> str: ...
    @property
    def inputs(self) -> str: ...
    @property
    def data_checksum(self) -> str: ...
    @property
    def kernel_version(self) -> float: ...
    @property
    def provenance(self) -> Dict[str, Any]: ...
    @property
    def columns(self) -> Dict[str, npt.NDArray[np.float64]]: ...
    @property
    def scalars(self) -> Dict[str, float]: ...
    def __getattr__(self, name: str) -> Any: ...
