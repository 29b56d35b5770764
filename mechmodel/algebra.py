"""Exact algebra: Gaussian rationals, Laurent polynomials in named variables, coefficient lists.

The book derives its formulas by hand: the 1/2 of a trajectory from integrating g twice
(12.14), the 2 of the Coriolis term from differentiating M r^2 phi' (12.33), the factors 1/2 of
d/dz and d/dz* from inverting z = x + i y (10.31), the potentials of the power fields
(10.35), (10.51)-(10.56). The models repeat those derivations exactly instead of writing the
results in, with one algebra:

- ``Gaussian``: an exact complex number with rational parts.
- ``Laurent``: a finite sum of exact coefficients times products of integer (possibly
  negative) powers of named variables, x^i y^j or z^a z*^b or M g q'^2; differentiated,
  integrated, substituted, evaluated, and for the cosine and sine of an angle reduced with
  sin^2 = 1 - cos^2. A coefficient is a ``Fraction`` when it is real and a ``Gaussian``
  otherwise, so that two equal polynomials have equal ``terms``.
- ``polynomial_derivative`` and ``polynomial_integral``: the power rule on a plain list of
  coefficients c_k of sum c_k x^k (the potentials and contact laws of chapters 6-7, the
  Maclaurin series of chapter 10), which also works on floats and sympy symbols.

Everything is dimensionless: the variables carry whatever units the caller gives them.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import TypeAlias, TypeVar, overload

from mechmodel import inputs
from mechmodel.typing import Real, Scalar, Symbolic

# what a plain-operator polynomial keeps: Real in, Real out; complex (the complex step), complex;
# symbols, expressions (a constrained variable: mypy checks the function once with each)
_Number = TypeVar("_Number", Real, Scalar, Symbolic)


@dataclass(frozen=True, slots=True, eq=False)
class Gaussian:
    """An exact complex number ``re + i im`` with rational parts."""

    re: Fraction | int = 0
    im: Fraction | int = 0

    @staticmethod
    def of(value: Gaussian | Scalar) -> Gaussian:
        """``value`` (an int, Fraction, Gaussian or complex) as exact. Integer parts stay
        ``int`` (faster; they mix exactly with Fraction), floats become their exact Fraction."""
        if isinstance(value, Gaussian):
            return value
        if isinstance(value, complex):
            return Gaussian(Fraction(value.real), Fraction(value.imag))
        if isinstance(value, bool) or not isinstance(value, int | Fraction):
            return Gaussian(Fraction(value), 0)
        return Gaussian(value, 0)

    def __add__(self, other: Gaussian | Scalar) -> Gaussian:
        if not _is_number(other):
            return NotImplemented  # a polynomial adds a Gaussian itself
        o = Gaussian.of(other)
        return Gaussian(self.re + o.re, self.im + o.im)

    __radd__ = __add__

    def __neg__(self) -> Gaussian:
        return Gaussian(-self.re, -self.im)

    def __sub__(self, other: Gaussian | Scalar) -> Gaussian:
        if not _is_number(other):
            return NotImplemented
        return self + (-Gaussian.of(other))

    def __rsub__(self, other: Gaussian | Scalar) -> Gaussian:
        return Gaussian.of(other) + (-self)

    def __mul__(self, other: Gaussian | Scalar) -> Gaussian:
        if not _is_number(other):
            return NotImplemented
        o = Gaussian.of(other)
        return Gaussian(self.re * o.re - self.im * o.im, self.re * o.im + self.im * o.re)

    __rmul__ = __mul__

    def __truediv__(self, other: Gaussian | Scalar) -> Gaussian:
        if not _is_number(other):
            return NotImplemented
        o = Gaussian.of(other)
        norm = Fraction(o.re * o.re + o.im * o.im)
        if norm == 0:
            raise ZeroDivisionError("division by the Gaussian zero")
        return self * Gaussian(o.re / norm, -o.im / norm)

    def __rtruediv__(self, other: Gaussian | Scalar) -> Gaussian:
        return Gaussian.of(other) / self

    def __pow__(self, n: int) -> Gaussian:
        n = inputs.integer(n, "exponent")
        base = self if n >= 0 else 1 / self
        out = Gaussian(1, 0)
        for _ in range(abs(n)):
            out = out * base
        return out

    def __eq__(self, other: object) -> bool:
        """Equal to a Gaussian with equal parts, or to the real number it is (im = 0)."""
        if isinstance(other, Gaussian):
            return self.re == other.re and self.im == other.im
        if isinstance(other, _NUMBERS):
            return self == Gaussian.of(other)
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.re) if self.im == 0 else hash((self.re, self.im))

    def conjugate(self) -> Gaussian:
        return Gaussian(self.re, -self.im)

    def is_zero(self) -> bool:
        return self.re == 0 and self.im == 0

    def __complex__(self) -> complex:
        return complex(float(self.re), float(self.im))

    def __str__(self) -> str:
        return f"({self.re} + {self.im}*I)"


I_UNIT = Gaussian(0, 1)
_NUMBERS = (Gaussian, int, Fraction, float, complex)


def _is_number(value: object) -> bool:
    """Whether a Gaussian's operator can take ``value``; else it returns NotImplemented, so
    that Python asks the other operand (a ``Laurent`` adds a Gaussian itself)."""
    return isinstance(value, _NUMBERS)


Coefficient: TypeAlias = Gaussian | Scalar  # what a polynomial's coefficient is made from


def exact(value: Coefficient) -> Fraction | Gaussian:
    """``value`` as an exact coefficient: a ``Fraction`` when it is real, else a ``Gaussian``
    with a non-zero imaginary part. Floats and complex numbers convert exactly."""
    if isinstance(value, Gaussian | complex):
        g = Gaussian.of(value)
        return g if g.im != 0 else Fraction(g.re)
    return Fraction(value)


def _is_exact(value: object) -> bool:
    return isinstance(value, int | Fraction | Gaussian) and not isinstance(value, bool)


# -- Laurent polynomials in named variables -----------------------------------------------------
Monomial = tuple[tuple[str, int], ...]  # (variable, non-zero exponent) pairs, sorted by name


def monomial(powers: Mapping[str, int]) -> Monomial:
    """The monomial with these exponents (zero exponents dropped), as ``Laurent.terms`` keys it."""
    return tuple(sorted((name, int(e)) for name, e in powers.items() if e != 0))


class Laurent:
    """A Laurent polynomial: a sum of exact multiples of products of integer (possibly
    negative) powers of named variables. ``terms`` maps monomials to coefficients, a
    ``Fraction`` when real and a ``Gaussian`` otherwise; zero terms are dropped, so two equal
    polynomials have equal ``terms``.
    """

    __slots__ = ("terms",)

    def __init__(self, terms: Mapping[Monomial, Coefficient] | None = None) -> None:
        self.terms: dict[Monomial, Fraction | Gaussian] = {}
        for key, value in (terms or {}).items():
            c = exact(value)
            if c != 0:
                self.terms[key] = c

    # construction ---------------------------------------------------------------------------
    @staticmethod
    def constant(value: Coefficient) -> Laurent:
        return Laurent({(): value})

    @staticmethod
    def var(name: str, power: int = 1) -> Laurent:
        """The monomial name^power."""
        return Laurent({monomial({name: power}): 1})

    @staticmethod
    def term(coefficient: Coefficient, **powers: int) -> Laurent:
        """The single term coefficient * x^i y^j ... (``Laurent.term(3, x=2, y=-1)``)."""
        return Laurent({monomial(powers): coefficient})

    @staticmethod
    def from_powers(names: Sequence[str], terms: Mapping[tuple[int, ...], Coefficient]) -> Laurent:
        """The polynomial whose coefficients ``terms`` are keyed by the exponents of the
        variables ``names``, in that order (``{(2, 1): c}`` is c x^2 y for names x, y)."""
        return Laurent(
            {monomial(dict(zip(names, key, strict=True))): c for key, c in terms.items()}
        )

    @staticmethod
    def of(value: Laurent | Coefficient) -> Laurent:
        return value if isinstance(value, Laurent) else Laurent.constant(value)

    # arithmetic -----------------------------------------------------------------------------
    def __add__(self, other: Laurent | Coefficient) -> Laurent:
        out = dict(self.terms)
        for key, value in Laurent.of(other).terms.items():
            out[key] = out.get(key, Fraction(0)) + value
        return Laurent(out)

    __radd__ = __add__

    def __neg__(self) -> Laurent:
        return Laurent({k: -v for k, v in self.terms.items()})

    def __sub__(self, other: Laurent | Coefficient) -> Laurent:
        return self + (-Laurent.of(other))

    def __rsub__(self, other: Laurent | Coefficient) -> Laurent:
        return Laurent.of(other) - self

    def __mul__(self, other: Laurent | Coefficient) -> Laurent:
        o = Laurent.of(other)
        out: dict[Monomial, Fraction | Gaussian] = {}
        for a, u in self.terms.items():
            for b, v in o.terms.items():
                powers = dict(a)
                for name, e in b:
                    powers[name] = powers.get(name, 0) + e
                key = monomial(powers)
                out[key] = out.get(key, Fraction(0)) + u * v
        return Laurent(out)

    __rmul__ = __mul__

    def monomial_inverse(self) -> Laurent:
        """1 / self for a single term; ``ValueError`` for a sum (not a Laurent polynomial)."""
        if len(self.terms) != 1:
            raise ValueError("only a single term has a Laurent-polynomial inverse")
        ((key, c),) = self.terms.items()
        return Laurent({tuple((name, -e) for name, e in key): 1 / c})

    def __truediv__(self, other: Laurent | Coefficient) -> Laurent:
        return self * Laurent.of(other).monomial_inverse()

    def __pow__(self, n: int) -> Laurent:
        n = inputs.integer(n, "exponent")
        base = self if n >= 0 else self.monomial_inverse()
        out = Laurent.constant(1)
        for _ in range(abs(n)):
            out = out * base
        return out

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Laurent) and self.terms == other.terms

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        if not self.terms:
            return "0"
        parts = []
        for key, c in sorted(self.terms.items()):
            factors = "*".join(f"{n}^{e}" if e != 1 else n for n, e in key)
            parts.append(f"{c}*{factors}" if factors else f"{c}")
        return " + ".join(parts)

    # coefficients ---------------------------------------------------------------------------
    def is_zero(self) -> bool:
        return not self.terms

    def powers(self, *names: str) -> dict[tuple[int, ...], Fraction | Gaussian]:
        """The coefficients keyed by the exponents of ``names``, in that order;
        ``ValueError`` if another variable appears."""
        out = {}
        for key, c in self.terms.items():
            exponents = dict(key)
            if set(exponents) - set(names):
                raise ValueError(f"{self!r} is not a polynomial in {', '.join(names)} alone")
            out[tuple(exponents.get(name, 0) for name in names)] = c
        return out

    def coefficient(self, **powers: int) -> Fraction | Gaussian:
        """The coefficient of the monomial with these exponents (all others zero)."""
        return self.terms.get(monomial(powers), Fraction(0))

    def power(self, name: str) -> int:
        """The exponent of ``name`` in a single term; ``ValueError`` for a sum."""
        if len(self.terms) != 1:
            raise ValueError(f"{self!r} is not a single term")
        ((key, _),) = self.terms.items()
        return dict(key).get(name, 0)

    def only_coefficient(self) -> Fraction | Gaussian:
        """The coefficient of a single term."""
        if len(self.terms) != 1:
            raise ValueError(f"{self!r} is not a single term")
        return next(iter(self.terms.values()))

    def part(self, name: str, exponent: int) -> Laurent:
        """The terms in which ``name`` has exactly ``exponent``."""
        return Laurent({k: c for k, c in self.terms.items() if dict(k).get(name, 0) == exponent})

    def is_constant(self) -> bool:
        return all(key == () for key in self.terms)

    def value(self) -> Fraction | Gaussian:
        """The value of a constant polynomial."""
        if not self.is_constant():
            raise ValueError(f"{self!r} is not a constant")
        return self.terms.get((), Fraction(0))

    def conjugate_coefficients(self) -> Laurent:
        """Every coefficient conjugated: the complex conjugate of the function of real
        variables."""
        return Laurent({k: Gaussian.of(c).conjugate() for k, c in self.terms.items()})

    def real_part(self) -> Laurent:
        """The real part of the function of real variables: the coefficients' real parts."""
        return Laurent({k: Gaussian.of(c).re for k, c in self.terms.items()})

    def imag_part(self) -> Laurent:
        """The imaginary part of the function of real variables."""
        return Laurent({k: Gaussian.of(c).im for k, c in self.terms.items()})

    # calculus and evaluation ----------------------------------------------------------------
    def diff(self, name: str) -> Laurent:
        """Partial derivative with respect to the variable ``name`` (the power rule)."""
        out: dict[Monomial, Fraction | Gaussian] = {}
        for key, c in self.terms.items():
            powers = dict(key)
            e = powers.get(name, 0)
            if e == 0:
                continue
            powers[name] = e - 1
            k = monomial(powers)
            out[k] = out.get(k, Fraction(0)) + c * e
        return Laurent(out)

    def integrate(self, name: str) -> Laurent:
        """An antiderivative in ``name`` with zero constant (power rule backwards)."""
        out: dict[Monomial, Fraction | Gaussian] = {}
        for key, c in self.terms.items():
            powers = dict(key)
            e = powers.get(name, 0)
            if e == -1:
                raise ValueError(f"1/{name} has a logarithmic antiderivative")
            powers[name] = e + 1
            k = monomial(powers)
            out[k] = out.get(k, Fraction(0)) + c / (e + 1)
        return Laurent(out)

    def substitute(self, name: str, value: Laurent | Coefficient) -> Laurent:
        """Replace the variable ``name`` by ``value`` (a number or Laurent polynomial; a
        negative power needs a single-term ``value``)."""
        value = Laurent.of(value)
        out = Laurent()
        for key, c in self.terms.items():
            powers = dict(key)
            e = powers.pop(name, 0)
            out = out + Laurent({monomial(powers): c}) * value**e
        return out

    def evaluate(self, values: Mapping[str, Coefficient]) -> Coefficient:
        """The number this polynomial takes at ``values``: exact where every value is exact
        (``int``, ``Fraction`` or ``Gaussian``), else a float (a complex number where a
        coefficient or a value is complex), with plain operators."""
        terms = []
        for key, c in self.terms.items():
            term: Coefficient = c
            if not all(_is_exact(values[n]) for n, _ in key):
                term = complex(c) if isinstance(c, Gaussian) else float(c)
            for name, e in key:
                term = term * values[name] ** e
            terms.append(term)
        if not all(_is_exact(t) for t in terms):  # an exact complex term joins inexact ones
            terms = [complex(t) if isinstance(t, Gaussian) else t for t in terms]
        total: Coefficient = 0
        for term in terms:
            total = total + term
        return total

    def evaluate_real(self, values: Mapping[str, Real]) -> Real:
        """``evaluate`` for a polynomial with real coefficients at real ``values``: a real
        number (exact where every value is exact); ``ValueError`` for a complex coefficient."""
        for c in self.terms.values():
            Laurent.rational(c)
        value = self.evaluate(values)
        if isinstance(value, Gaussian | complex):  # not reached: real terms sum to a real
            raise ValueError(f"{self!r} is not real at {values}")
        return value

    @staticmethod
    def rational(c: Fraction | Gaussian) -> Fraction:
        """A real coefficient of a ``Laurent`` polynomial (stored as a ``Fraction``: a
        ``Gaussian`` there has a non-zero imaginary part); ``ValueError`` for a complex one."""
        if isinstance(c, Gaussian):
            raise ValueError(f"the coefficient {c} is not real")
        return c

    def reduce_trig(self, cos: str, sin: str) -> Laurent:
        """Rewrite with sin^2 = 1 - cos^2 until sin appears at most to the first power."""
        out = Laurent()
        one_minus_cos2 = 1 - Laurent.var(cos, 2)
        for key, c in self.terms.items():
            powers = dict(key)
            e = powers.pop(sin, 0)
            if e < 0:
                raise ValueError("negative powers of the sine are not reduced")
            rest = Laurent({monomial(powers): c}) * Laurent.var(sin, e % 2)
            out = out + rest * one_minus_cos2 ** (e // 2)
        return out


# -- polynomials as coefficient lists -----------------------------------------------------------
@overload
def polynomial_derivative(coefficients: Sequence[float]) -> list[float]: ...
@overload
def polynomial_derivative(coefficients: Sequence[Real]) -> list[Real]: ...
@overload
def polynomial_derivative(coefficients: Sequence[Symbolic]) -> Sequence[Symbolic]: ...
def polynomial_derivative(coefficients: Sequence[Symbolic]) -> Sequence[Symbolic]:
    """Coefficients of dp/dx for p(x) = sum c_k x^k (index k = power), by the power rule
    (10.8b): k c_k moves to index k - 1. Plain operators: symbols give expressions."""
    return [k * c for k, c in enumerate(coefficients)][1:]


@overload
def polynomial_integral(coefficients: Sequence[float], x: float) -> float: ...
@overload
def polynomial_integral(coefficients: Sequence[_Number], x: _Number) -> _Number: ...
def polynomial_integral(coefficients: Sequence[_Number], x: _Number) -> _Number:
    """The integral from 0 to ``x`` of p(x) = sum c_k x^k: sum c_k x^(k+1) / (k+1).

    Exact with Fraction coefficients and ``x``.
    """
    return sum(c * x ** (k + 1) / (k + 1) for k, c in enumerate(coefficients))
