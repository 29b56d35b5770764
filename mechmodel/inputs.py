"""Validation of physical inputs shared by the mechmodel modules.

A mass is in (0, inf]: an infinite mass (wall, floor, ceiling, Earth) is allowed where a model
says so and takes its own branch. NaN is never a value.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Sequence
from typing import Any


def is_nan(x: Any) -> bool:
    """True for a NaN of any numeric type (float, numpy, mpmath); a Fraction never is."""
    return x != x  # NaN is the only value unequal to itself


def is_infinite(x: Any) -> bool:
    """True for +inf or -inf of any numeric type."""
    try:
        return math.isinf(x)
    except (TypeError, OverflowError):
        return False


def real(x: Any, name: str) -> Any:
    """``x`` if it is a finite real number, else ``ValueError`` naming ``name``."""
    if isinstance(x, bool | complex):
        raise ValueError(f"{name} must be a real number, got {x!r}")
    try:
        if is_nan(x) or is_infinite(x):
            raise ValueError(f"{name} must be finite, got {x!r}")
        float(x)
    except TypeError as err:
        raise ValueError(f"{name} must be a real number, got {x!r}") from err
    return x


def mass(m: Any, name: str = "mass", *, infinite_ok: bool = False) -> Any:
    """``m`` if it is a mass in (0, inf) (or inf when ``infinite_ok``), else ``ValueError``."""
    if isinstance(m, bool | complex) or is_nan(m):
        raise ValueError(f"{name} must be a positive number, got {m!r}")
    if is_infinite(m):
        if m > 0 and infinite_ok:
            return m
        raise ValueError(f"{name} must be finite here, got {m!r}")
    try:
        positive = m > 0
    except TypeError as err:
        raise ValueError(f"{name} must be a positive number, got {m!r}") from err
    if not positive:
        raise ValueError(f"{name} must be positive, got {m!r}")
    return m


def positive(x: Any, name: str) -> Any:
    """``x`` if it is finite and > 0, else ``ValueError``."""
    real(x, name)
    if not x > 0:
        raise ValueError(f"{name} must be positive, got {x!r}")
    return x


def integer(n: Any, name: str) -> int:
    """``n`` as an ``int`` if it is an integer of either sign (any integer type), else
    ``ValueError``."""
    try:
        return operator.index(n)
    except TypeError as err:
        raise ValueError(f"{name} must be an integer, got {n!r}") from err


def count(n: Any, name: str, minimum: int = 0) -> int:
    """``n`` as an ``int`` if it is an integer >= ``minimum``, else ``ValueError``."""
    value = integer(n, name)
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return value


def bodies(masses: Sequence[Any], velocities: Sequence[Any]) -> list[tuple[Any, Any]]:
    """The (mass, velocity) pairs of at least one body with one velocity per mass, each mass
    finite and positive and each velocity finite; else ``ValueError`` naming the entry."""
    if len(masses) != len(velocities) or not masses:
        raise ValueError("give one velocity per mass (and at least one mass)")
    for i, (m, v) in enumerate(zip(masses, velocities, strict=True)):
        mass(m, f"masses[{i}]")
        real(v, f"velocities[{i}]")
    return list(zip(masses, velocities, strict=True))
