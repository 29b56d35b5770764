"""Printed numbers as values with the precision their digits carry.

A printed value is a string; its precision comes from its digits (statcheck's rule): "7,250" is
exact to the unit, "0.0100" to 1e-4, "6.282 E6" to 1e3. The half-width ``h`` is half a unit of
the last counted digit. Fractions, multiples of pi and roots are exact values.

Values are held as exact rationals (``fractions.Fraction``), so that the decimal string and a
model's binary float are compared without any rounding of either. Irrational printed forms
("π/3", "√3/2") are held to 50 significant digits, far below any tolerance used.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation
from fractions import Fraction

import mpmath

from reference.grammar import (
    FORM_BARE_POWER,
    FORM_CARET,
    FORM_DECIMAL,
    FORM_DOT_POWER,
    FORM_E,
    FORM_FRACTION,
    FORM_PI,
    FORM_ROOT,
    normalize,
)

_MP_DIGITS = 50

# Exact printed forms are compared within this many units in the last place of a double.
EXACT_ULPS = 16


class NumberFormatError(ValueError):
    """A printed or ``means`` string that is not a number this module can read."""


@dataclass(frozen=True)
class Printed:
    """A printed number: exact value, half-width and the facts the comparison needs.

    ``quantum`` is the unit of the last counted digit (2h); ``None`` for an exact form.
    ``irrational`` marks pi and root forms, whose ``value`` is a 50-digit approximation.
    """

    text: str
    value: Fraction
    half_width: Fraction
    exact: bool
    absolute: bool
    quantum: Fraction | None
    irrational: bool = False

    @property
    def tolerance(self) -> Fraction:
        """Half-width used by the comparison: h, or a few ulp for an exact form."""
        if self.exact:
            return Fraction(EXACT_ULPS * math.ulp(abs(float(self.value)) or 1e-300))
        return self.half_width


def _decimal(text: str) -> Decimal:
    try:
        return Decimal(text.replace(",", ""))
    except InvalidOperation as err:  # pragma: no cover - the patterns admit only digits
        raise NumberFormatError(f"not a number: {text!r}") from err


def _quantum(dec: Decimal, sigfigs: int | None) -> Fraction:
    """The unit of the last counted digit of ``dec`` (all digits, or the first ``sigfigs``)."""
    exponent = dec.as_tuple().exponent
    assert isinstance(exponent, int)
    if sigfigs is not None:
        if dec == 0:
            raise NumberFormatError("sigfigs cannot be applied to a printed zero")
        leading = dec.adjusted()
        exponent = leading - sigfigs + 1
    return Fraction(10) ** exponent


def _mp(value: mpmath.mpf) -> Fraction:
    mantissa, exponent = mpmath.mpf(value).man_exp
    return Fraction(int(mantissa)) * Fraction(2) ** int(exponent)


def _exact(value: Fraction) -> tuple[Fraction, Fraction, bool, Fraction | None]:
    return value, Fraction(0), True, None


def _inexact(value: Fraction, quantum: Fraction) -> tuple[Fraction, Fraction, bool, Fraction]:
    return value, quantum / 2, False, quantum


def parse_number(text: str, *, sigfigs: int | None = None, exact: bool = False) -> Printed:
    """Read a printed token or a ``means`` string.

    Accepts decimals with thousands commas, signs (``-``, ``−``, ``–``, ``+``, ``±``), ``%`` and
    ``°`` marks, E-notation ("6.282 E6", "1.67e-27"), the book's flattened powers of ten
    ("2·10-27", "(2/3)·10-27", "10-25"), powers written with a caret ("60^2", "10^-25"; exact
    when the base is an integer, else the base's half-width propagated; "6.28^2e6" is 6.28^2
    times 10^6, its precision from its base), fractions "p/q",
    multiples and fractions of pi ("2π/3", "180/π") and roots ("√3/2", "1/√2").
    ``sigfigs`` counts fewer significant digits than printed; ``exact`` reads a printed integer
    as an exact amount (the "1" of "1 radian"), not as one rounded to the unit. Raises
    ``NumberFormatError``.
    """
    raw = text
    s = normalize(text).strip()
    absolute = s.startswith("±")
    if absolute:
        s = s[1:]
    negative = s.startswith("-")
    if s[:1] in "+-":
        s = s[1:]
    if s[-1:] in ("%", "°"):  # a mark: part of the text, not of the value
        s = s[:-1]
    if not s:
        raise NumberFormatError(f"not a number: {raw!r}")
    value, half, is_exact, quantum = _body(s, raw, sigfigs)
    if sigfigs is not None and is_exact:
        raise NumberFormatError(f"sigfigs cannot apply to the exact form {raw!r}")
    if exact:
        if sigfigs is not None or quantum != 1:
            raise NumberFormatError(f"only a printed integer can be exact: {raw!r}")
        half, is_exact, quantum = Fraction(0), True, None
    if negative:
        value = -value
    irrational = bool(FORM_PI.fullmatch(s) or FORM_ROOT.fullmatch(s))
    return Printed(raw, value, half, is_exact, absolute, quantum, irrational)


def _body(
    s: str, raw: str, sigfigs: int | None
) -> tuple[Fraction, Fraction, bool, Fraction | None]:
    if FORM_DECIMAL.fullmatch(s):  # the commonest form first: nothing else is only digits
        dec = _decimal(s)
        return _inexact(Fraction(dec), _quantum(dec, sigfigs))
    if m := FORM_DOT_POWER.fullmatch(s):
        scale = Fraction(10) ** int(m["exp"])
        mant = m["mant"]
        if mant.startswith("("):
            p, q = mant[1:-1].split("/")
            return _exact(Fraction(int(p), int(q)) * scale)
        dec = _decimal(mant)
        return _inexact(Fraction(dec) * scale, _quantum(dec, sigfigs) * scale)
    if m := FORM_BARE_POWER.fullmatch(s):
        return _exact(Fraction(10) ** int(m["exp"]))
    if m := FORM_E.fullmatch(s):
        dec = _decimal(m["mant"])
        scale = Fraction(10) ** int(m["exp"])
        return _inexact(Fraction(dec) * scale, _quantum(dec, sigfigs) * scale)
    if m := FORM_CARET.fullmatch(s):
        base_dec = _decimal(m["base"])
        exp = int(m["exp"])
        base = Fraction(base_dec)
        scale = Fraction(10) ** int(m["scale"] or 0)  # "6.28^2e6": 6.28^2 x 10^6
        value = base**exp * scale
        if base_dec.as_tuple().exponent == 0 and sigfigs is None:
            return _exact(value)
        h_base = _quantum(base_dec, sigfigs) / 2
        half = abs(exp) * abs(base) ** (exp - 1) * h_base * scale
        return value, half, False, 2 * half
    if m := FORM_FRACTION.fullmatch(s):
        if int(m["q"]) == 0:
            raise NumberFormatError(f"zero denominator in {raw!r}")
        return _exact(Fraction(int(m["p"]), int(m["q"])))
    with mpmath.workdps(_MP_DIGITS):
        if m := FORM_PI.fullmatch(s):
            if m["c"]:
                return _exact(_mp(mpmath.mpf(int(m["c"])) / mpmath.pi))
            a = int(m["a"]) if m["a"] else 1
            b = int(m["b"]) if m["b"] else 1
            return _exact(_mp(a * mpmath.pi / b))
        if m := FORM_ROOT.fullmatch(s):
            if m["c"]:
                return _exact(_mp(int(m["c"]) / mpmath.sqrt(int(m["s"]))))
            a = int(m["a"]) if m["a"] else 1
            b = int(m["b"]) if m["b"] else 1
            return _exact(_mp(a * mpmath.sqrt(int(m["r"])) / b))
    raise NumberFormatError(f"not a number this catalog can read: {raw!r}")


def significant_digits(text: str) -> str:
    """The digits of a printed decimal without sign, separators, point or leading zeros."""
    digits = "".join(c for c in normalize(text) if c.isdigit())
    return digits.lstrip("0") or "0"
