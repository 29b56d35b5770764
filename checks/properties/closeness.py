"""One closeness check for the property tests: ``assert_close``; and ``real``, ``reals``.

The tolerance is ``abs + rel * scale``. ``scale`` is the size the relative tolerance is taken
of: by default the magnitudes involved, |actual| + |expected| (design section 5); a test passes
its own when other magnitudes set the size of the rounding (the terms of a sum, a coordinate
range, the model's declared error), and ``magnitude`` adds magnitudes up. ``abs`` is an
absolute floor for values whose rounding no relative tolerance describes (subnormal products),
or the whole tolerance with ``rel=0``.

Numbers of any kind (int, Fraction, float, complex, mpmath) are compared by |actual -
expected|; sequences of equal shape (vectors, matrices) entry by entry, each against the same
tolerance. A failure names both values, their difference and the tolerance.

``real`` and ``reals`` assert that a model typed ``Symbolic`` (it also takes sympy symbols)
gave real numbers when called with real numbers, and say so to the type checker.
"""

from __future__ import annotations

import builtins
from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction
from typing import Any

from mechmodel.typing import Real

REL = 1e-12  # design section 5: about 1e-12 of the magnitudes involved


def real(value: object) -> Real:
    """``value``, asserted a real number (int, float or Fraction), not a sympy expression."""
    assert isinstance(value, int | float | Fraction), f"not a real number: {value!r}"
    return value


def reals(values: Iterable[object]) -> tuple[Real, ...]:
    """The values, each asserted a real number (``real``)."""
    return tuple(real(v) for v in values)


def _entries(value: Any, where: str = "") -> Iterator[tuple[str, Any]]:
    if isinstance(value, Sequence) and not isinstance(value, str):
        for k, item in enumerate(value):
            yield from _entries(item, f"{where}[{k}]")
    else:
        yield where, value


def largest(*values: Any) -> Any:
    """The largest |entry| of the values (numbers, or sequences of them)."""
    return max((builtins.abs(x) for v in values for _, x in _entries(v)), default=0)


def magnitude(*values: Any) -> Any:
    """The sum of the magnitudes of the values; a sequence counts by its largest |entry|."""
    return sum((largest(v) for v in values), start=0)


def _pairs(actual: Any, expected: Any) -> Iterator[tuple[str, Any, Any]]:
    got, want = list(_entries(actual)), list(_entries(expected))
    if [w for w, _ in got] != [w for w, _ in want]:
        raise AssertionError(f"different shapes: actual {actual!r}, expected {expected!r}")
    for (where, a), (_, e) in zip(got, want, strict=True):
        yield where, a, e


def assert_close(
    actual: Any,
    expected: Any,
    *,
    rel: float = REL,
    abs: Any = 0.0,  # as pytest.approx names it (the builtin is builtins.abs)
    scale: Any = None,
) -> None:
    """Assert |actual - expected| <= abs + rel * scale (entry by entry for sequences).

    ``scale`` defaults to ``magnitude(actual, expected)``; with ``rel=0`` it plays no part.
    """
    if rel and scale is None:
        scale = magnitude(actual, expected)
    tolerance = abs + rel * scale if rel else abs
    for where, a, e in _pairs(actual, expected):
        difference = builtins.abs(a - e)
        if not difference <= tolerance:
            entry = f" at {where}" if where else ""
            raise AssertionError(
                f"not close{entry}: actual {a!r}, expected {e!r}, difference {difference!r} > "
                f"tolerance {tolerance!r} (abs {abs!r} + rel {rel!r} * scale {scale!r})"
            )
