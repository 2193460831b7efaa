# SPDX-License-Identifier: BSD-3-Clause
"""A batch result: named NumPy arrays as attributes, with a short repr; pickles as a dict."""
from __future__ import annotations

from typing import Any, Dict

import numpy as np


class ArrayResult:
    """Arrays of a batch query, one attribute each; ``fields()`` lists them in order."""

    _rows_field = ""

    def __init__(self, arrays: Dict[str, np.ndarray]) -> None:
        self.__dict__.update(arrays)
        self._names = tuple(arrays)

    def fields(self) -> tuple:
        """The array attributes, in order."""
        return self._names

    def as_dict(self) -> Dict[str, np.ndarray]:
        """The arrays as a dict (no copies)."""
        return {name: getattr(self, name) for name in self._names}

    def __len__(self) -> int:
        return len(getattr(self, self._rows_field))

    def __eq__(self, other: Any) -> bool:
        """Same fields and arrays equal element by element (NaN equal to NaN)."""
        if type(other) is not type(self) or self._names != other._names:
            return NotImplemented
        return all(np.array_equal(getattr(self, f), getattr(other, f),
                                  equal_nan=np.issubdtype(getattr(self, f).dtype, np.floating))
                   for f in self._names)

    def __reduce__(self) -> Any:
        return (type(self), (self.as_dict(),))

    def __repr__(self) -> str:
        return f"{type(self).__name__}({len(self)} rows: {', '.join(self._names)})"
