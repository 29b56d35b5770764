"""Validation of physical inputs shared by the mechmodel modules.

A mass is in (0, inf]: an infinite mass (wall, floor, ceiling, Earth) is allowed where a model
says so and takes its own branch. NaN is never a value.

Each validator takes any object and returns it with the type it has been checked to have: the
argument's own type where that is already known (a ``Fraction`` stays a ``Fraction``), else the
narrowed alias (``Real`` for ``real`` and ``positive``, ``Symbolic`` for ``mass``: a positive
sympy symbol passes as a mass, so that a formula claim can call a model with symbols).
"""

from __future__ import annotations

import math
import operator
from collections.abc import Sequence
from typing import Protocol, SupportsFloat, SupportsIndex, TypeGuard, TypeVar, overload

from mechmodel.typing import Real, Symbolic

R = TypeVar("R", bound=Real)
S = TypeVar("S", bound=Symbolic)


class _Ordered(Protocol):
    """An object that compares with a number. Every object has ``__gt__``, so this only tells
    the type checker; an unorderable one raises TypeError when compared."""

    def __gt__(self, other: int, /) -> object: ...


def _numeric(x: object) -> TypeGuard[SupportsFloat | SupportsIndex]:
    """Whether ``x``'s type converts to a float or is an integer type: what
    ``isinstance(x, SupportsFloat | SupportsIndex)`` asks, 50 times faster (a runtime protocol
    check costs about 4 us, and the validators run on every model call)."""
    return hasattr(type(x), "__float__") or _integral(x)


def _integral(x: object) -> TypeGuard[SupportsIndex]:
    return hasattr(type(x), "__index__")


def _ordered(x: object) -> TypeGuard[_Ordered]:
    return hasattr(type(x), "__gt__")


def is_nan(x: object) -> bool:
    """True for a NaN of any numeric type (float, numpy, mpmath); a Fraction never is."""
    return x != x  # NaN is the only value unequal to itself


def is_infinite(x: object) -> bool:
    """True for +inf or -inf of any numeric type."""
    if not _numeric(x):
        return False  # what math.isinf refuses
    try:
        return math.isinf(x)
    except (TypeError, OverflowError):
        return False


@overload
def real(x: R, name: str) -> R: ...
@overload
def real(x: object, name: str) -> Real: ...
def real(x: object, name: str) -> object:
    """``x`` if it is a finite real number, else ``ValueError`` naming ``name``."""
    if isinstance(x, bool | complex):
        raise ValueError(f"{name} must be a real number, got {x!r}")
    try:
        if is_nan(x) or is_infinite(x):
            raise ValueError(f"{name} must be finite, got {x!r}")
        if not _numeric(x):
            raise TypeError("not a number")  # a str is not one, although float() reads it
        float(x)
    except TypeError as err:
        raise ValueError(f"{name} must be a real number, got {x!r}") from err
    return x


@overload
def mass(m: S, name: str = "mass", *, infinite_ok: bool = False) -> S: ...
@overload
def mass(m: object, name: str = "mass", *, infinite_ok: bool = False) -> Symbolic: ...
def mass(m: object, name: str = "mass", *, infinite_ok: bool = False) -> object:
    """``m`` if it is a mass in (0, inf) (or inf when ``infinite_ok``), else ``ValueError``.
    A sympy symbol declared positive is a mass."""
    if isinstance(m, bool | complex) or is_nan(m) or not _ordered(m):
        raise ValueError(f"{name} must be a positive number, got {m!r}")
    if is_infinite(m):
        if m > 0 and infinite_ok:
            return m
        raise ValueError(f"{name} must be finite here, got {m!r}")
    try:
        positive = m > 0  # for a sympy symbol, sympy's relation
    except TypeError as err:
        raise ValueError(f"{name} must be a positive number, got {m!r}") from err
    if not positive:
        raise ValueError(f"{name} must be positive, got {m!r}")
    return m


@overload
def positive(x: R, name: str) -> R: ...
@overload
def positive(x: object, name: str) -> Real: ...
def positive(x: object, name: str) -> object:
    """``x`` if it is finite and > 0, else ``ValueError``."""
    value = real(x, name)
    if not value > 0:
        raise ValueError(f"{name} must be positive, got {x!r}")
    return value


def integer(n: object, name: str) -> int:
    """``n`` as an ``int`` if it is an integer of either sign (any integer type), else
    ``ValueError``."""
    try:
        if not _integral(n):
            raise TypeError("not an integer")  # what operator.index refuses
        return operator.index(n)
    except TypeError as err:
        raise ValueError(f"{name} must be an integer, got {n!r}") from err


def count(n: object, name: str, minimum: int = 0) -> int:
    """``n`` as an ``int`` if it is an integer >= ``minimum``, else ``ValueError``."""
    value = integer(n, name)
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return value


@overload
def bodies(masses: Sequence[S], velocities: Sequence[R]) -> list[tuple[S, R]]: ...
@overload
def bodies(
    masses: Sequence[object], velocities: Sequence[object]
) -> list[tuple[Symbolic, Real]]: ...
def bodies(
    masses: Sequence[object], velocities: Sequence[object]
) -> Sequence[tuple[object, object]]:
    """The (mass, velocity) pairs of at least one body with one velocity per mass, each mass
    finite and positive and each velocity finite; else ``ValueError`` naming the entry."""
    if len(masses) != len(velocities) or not masses:
        raise ValueError("give one velocity per mass (and at least one mass)")
    for i, (m, v) in enumerate(zip(masses, velocities, strict=True)):
        mass(m, f"masses[{i}]")
        real(v, f"velocities[{i}]")
    return list(zip(masses, velocities, strict=True))
