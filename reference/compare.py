"""Verdicts: how a printed value compares with the model's (design section 3).

All arithmetic is on exact rationals: the printed string's exact value, the model's float taken
exactly. ``h`` is half a unit of the last counted digit; "inside" means ``|model - printed| <=
h (1 + 1e-9)`` so that a float such as 5.749999999999999 still rounds to "5.8".
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Literal

from reference.numbers import Printed

Verdict = Literal["verified", "rounding", "erratum", "given", "unmodeled", "indeterminate"]
VERDICTS: tuple[Verdict, ...] = (
    "verified",
    "rounding",
    "erratum",
    "given",
    "unmodeled",
    "indeterminate",
)
RoundingReason = Literal["truncation", "other-way", "input-rounding"]

SLACK = Fraction(1, 10**9)


@dataclass(frozen=True)
class Judgement:
    """A verdict, the rounding reason where it is ``rounding``, and the tolerance applied."""

    verdict: Verdict
    reason: RoundingReason | None
    tolerance: Fraction | None


def exact(value: float | int | Fraction) -> Fraction:
    """The exact rational value of a model number (a float is taken bit for bit)."""
    if isinstance(value, Fraction):
        return value
    if isinstance(value, bool):
        raise TypeError("a model returned a bool where a number was expected")
    if isinstance(value, int):
        return Fraction(value)
    f = float(value)
    if not math.isfinite(f):
        raise ValueError(f"model value is not finite: {value!r}")
    return Fraction(f)


def _inside(diff: Fraction, tol: Fraction) -> bool:
    return diff <= tol * (1 + SLACK)


def _is_truncation(printed: Printed, model: Fraction) -> bool:
    """Whether the printed value is the model cut toward zero at the printed digit."""
    q = printed.quantum
    if q is None:
        return False
    cut = Fraction(math.trunc(abs(model) / q)) * q
    return cut == abs(printed.value) and (model >= 0) == (printed.value >= 0)


def judge_equal(
    printed: Printed,
    model: Fraction,
    *,
    extra: Fraction = Fraction(0),
    interval: tuple[Fraction, Fraction] | None = None,
    exact_only: bool = False,
) -> Judgement:
    """Verdict of the relation ``=``.

    ``extra`` widens h (twice a constant's uncertainty). ``interval`` is the model's range over
    the box of input roundings; a value inside it (widened by h) is ``input-rounding``, the
    most telling reason, before truncation and other-way rounding within 2h. ``exact_only`` (a
    count) admits no rounding.
    """
    target = printed.value
    value = abs(model) if printed.absolute else model
    diff = abs(value - target)
    tol = printed.tolerance + extra
    if exact_only:
        return Judgement("verified" if diff == 0 else "erratum", None, Fraction(0))
    if _inside(diff, tol):
        return Judgement("verified", None, tol)
    if interval is not None:
        lo, hi = interval
        if printed.absolute:
            lo, hi = sorted((abs(lo), abs(hi))) if lo * hi >= 0 else (Fraction(0), max(-lo, hi))
        if lo - tol * (1 + SLACK) <= target <= hi + tol * (1 + SLACK):
            return Judgement("rounding", "input-rounding", tol)
    if not printed.exact and _inside(diff, 2 * printed.half_width + extra):
        reason: RoundingReason = "truncation" if _is_truncation(printed, value) else "other-way"
        return Judgement("rounding", reason, tol)
    return Judgement("erratum", None, tol)


def judge_relation(
    relation: str,
    printed: Printed,
    model: Fraction,
    *,
    rel_tol: float | None = None,
    bounds: tuple[Printed, Printed] | None = None,
) -> Judgement:
    """Verdict of ``~``, ``<``, ``>``, ``<=``, ``>=``, ``between`` and ``order`` (read: model REL
    printed). These give only ``verified`` or ``erratum``."""
    target = printed.value
    if relation == "~":
        assert rel_tol is not None
        tol = Fraction(rel_tol) * abs(target)
        ok = abs(model - target) <= tol
        return Judgement("verified" if ok else "erratum", None, tol)
    if relation == "between":
        assert bounds is not None
        ok = bounds[0].value <= model <= bounds[1].value
    elif relation == "order":
        ok = in_order_of(model, target)
    else:
        ok = {
            "<": model < target,
            ">": model > target,
            "<=": model <= target,
            ">=": model >= target,
        }[relation]
    return Judgement("verified" if ok else "erratum", None, None)


def in_order_of(model: Fraction, printed: Fraction) -> bool:
    """Whether ``model`` has the order of magnitude ``printed`` (~10^k): 10^k <= |model| <
    10^(k+1), or within half a decade of ``printed``."""
    if model == 0 or printed == 0:
        return model == printed
    k = math.floor(math.log10(abs(printed)))
    magnitude = abs(model)
    if Fraction(10) ** k <= magnitude < Fraction(10) ** (k + 1):
        return True
    return abs(math.log10(magnitude) - math.log10(abs(printed))) <= 0.5
