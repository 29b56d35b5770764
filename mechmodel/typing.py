"""What mechmodel's functions take and return: type aliases, ``Estimate``, ``@not_monotonic``.

The evaluator calls a model with the numbers of the catalog: ``int`` and ``Fraction`` for a
printed number read exactly (design 3a), ``float`` for one read as a rounded decimal, ``complex``
for the fields of chapter 10, and, for a formula claim (design 2a), sympy symbols. The aliases
say which of these a function accepts:

- ``Exact``: an exact rational, ``int`` or ``Fraction``; + - * / keep it exact.
- ``Real``: a real number, ``Exact`` or ``float`` (numpy's float64 is a float).
- ``Scalar``: a ``Real`` or a ``complex`` number.
- ``Symbolic``: a ``Real`` or a sympy expression: a function written with plain operators,
  which a formula claim calls with sympy symbols and compares with the book's formula.
  sympy ships no type information, so the expression is the Protocol ``Expression``: what
  a sympy expression offers such a function, the operators + - * / ** and unary minus.
- ``Num``: a type variable over ``Real`` and ``Symbolic`` for a function of plain operators
  that gives back what it was given: ``Real`` in, ``Real`` out; ``Symbolic`` in, ``Symbolic``
  out (a constrained variable: mypy checks the function once with each).
- ``Vector`` and ``Matrix``: a list of numbers (velocities of n balls, a state) and a list of
  rows (a collision or bang matrix); the plane's fixed pairs are ``planar.Vector`` and
  ``planar.Matrix``.

A numerical model (an ODE run, a contour integral) returns an ``Estimate``: its value and a
bound on its numerical error, both read by the evaluator. A model whose result is not monotonic
in its inputs (a count that jumps) is marked ``@not_monotonic``: the evaluator then brackets a
claim's rounded inputs on a grid (corners, centre and points between), not at the corners of
their box alone (design 3a).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Protocol, TypeAlias, TypeVar

__all__ = [
    "Estimate",
    "Exact",
    "Expression",
    "Matrix",
    "Num",
    "Real",
    "Scalar",
    "Symbolic",
    "Vector",
    "is_monotonic",
    "not_monotonic",
]

Exact: TypeAlias = int | Fraction
Real: TypeAlias = float | int | Fraction
Scalar: TypeAlias = Real | complex


class Expression(Protocol):
    """A sympy expression as a plain-operator function sees it: each operator with a number
    (real or complex: sympy reads 1j as I) or another expression gives an expression (sympy
    ships no type information)."""

    def __add__(self, other: Scalar | Expression, /) -> Expression: ...
    def __radd__(self, other: Scalar | Expression, /) -> Expression: ...
    def __sub__(self, other: Scalar | Expression, /) -> Expression: ...
    def __rsub__(self, other: Scalar | Expression, /) -> Expression: ...
    def __mul__(self, other: Scalar | Expression, /) -> Expression: ...
    def __rmul__(self, other: Scalar | Expression, /) -> Expression: ...
    def __truediv__(self, other: Scalar | Expression, /) -> Expression: ...
    def __rtruediv__(self, other: Scalar | Expression, /) -> Expression: ...
    def __pow__(self, other: Scalar | Expression, /) -> Expression: ...
    def __rpow__(self, other: Scalar | Expression, /) -> Expression: ...
    def __neg__(self) -> Expression: ...
    def __pos__(self) -> Expression: ...


Symbolic: TypeAlias = Real | Expression
Num = TypeVar("Num", Real, Symbolic)  # Real in, Real out; Symbolic in, Symbolic out
Vector: TypeAlias = Sequence[Real]
Matrix: TypeAlias = Sequence[Sequence[Real]]

F = TypeVar("F", bound=Callable[..., Any])  # any function: the decorator returns it unchanged

_MONOTONIC = "monotonic"  # the attribute @not_monotonic sets; read only by is_monotonic


@dataclass(frozen=True)
class Estimate:
    """A numerically computed real value and a bound on its numerical error, in the value's
    unit (an ODE run's tolerance-halving difference, a quadrature rule against a coarser one)."""

    value: float
    error: float

    def __float__(self) -> float:
        return float(self.value)


def not_monotonic(func: F) -> F:
    """Mark ``func`` as not monotonic in its inputs (a count of bangs jumps as a mass ratio
    crosses a threshold): no interval follows from the corners of a box of rounded inputs."""
    setattr(func, _MONOTONIC, False)
    return func


def is_monotonic(func: Callable[..., object]) -> bool:
    """False for a function marked ``@not_monotonic``, else True."""
    return getattr(func, _MONOTONIC, True) is not False
