"""Automatic diagnosis of an erratum from its printed and correct strings (design section 3).

Tried in order: sign, decimal-shift (ratio a power of ten), digit-swap (two adjacent digits
exchanged), last-digit (one unit of the last digit away), dropped or extra digit, factor (a
simple ratio such as 2, 1/2, pi), otherwise none.
It is shown beside the curator's diagnosis, never instead of it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from reference.numbers import Printed, significant_digits

_FACTORS: tuple[tuple[str, float], ...] = (
    ("2", 2.0),
    ("1/2", 0.5),
    ("3", 3.0),
    ("1/3", 1 / 3),
    ("4", 4.0),
    ("1/4", 0.25),
    ("π", math.pi),
    ("1/π", 1 / math.pi),
    ("2π", 2 * math.pi),
    ("1/(2π)", 1 / (2 * math.pi)),
    ("√2", math.sqrt(2)),
    ("1/√2", 1 / math.sqrt(2)),
)


_LOOSEST = 0.1  # a printed value less precise than this (relative) says nothing of a factor


@dataclass(frozen=True)
class AutoDiagnosis:
    """The kind found (a design-section-2 diagnosis kind) and a short human reading."""

    kind: str
    detail: str


def _relative_width(p: Printed) -> float:
    if p.value == 0:
        return 0.0
    return float(p.tolerance / abs(p.value))


def _one_adjacent_swap(a: str, b: str) -> bool:
    if len(a) != len(b) or a == b:
        return False
    diff = [i for i in range(len(a)) if a[i] != b[i]]
    return (
        len(diff) == 2
        and diff[1] == diff[0] + 1
        and a[diff[0]] == b[diff[1]]
        and a[diff[1]] == b[diff[0]]
    )


def _one_deleted(longer: str, shorter: str) -> bool:
    if len(longer) != len(shorter) + 1:
        return False
    return any(longer[:i] + longer[i + 1 :] == shorter for i in range(len(longer)))


def diagnose(printed: Printed, correct: Printed) -> AutoDiagnosis | None:
    """What most likely went wrong between ``correct`` and ``printed``, or None."""
    p, c = printed.value, correct.value
    if c == 0 or p == 0:
        return None
    if p == -c:
        return AutoDiagnosis("sign", "printed with the wrong sign")
    ratio = p / c
    exponent = round(math.log10(abs(float(ratio))))
    if exponent != 0 and ratio == Fraction(10) ** exponent:
        return AutoDiagnosis("decimal-shift", f"printed = correct x 10^{exponent}")
    pd, cd = significant_digits(printed.text), significant_digits(correct.text)
    if (p > 0) == (c > 0):
        if _one_adjacent_swap(pd, cd):
            return AutoDiagnosis("digit-swap", f"digits {cd} printed as {pd}")
        unit = printed.quantum
        if unit is not None and correct.quantum == unit and abs(p - c) == unit:
            return AutoDiagnosis(
                "last-digit", f"the last digit is one unit off ({cd} printed as {pd})"
            )
        if _one_deleted(cd, pd):
            return AutoDiagnosis("dropped-digit", f"digits {cd} printed as {pd}")
        if _one_deleted(pd, cd):
            return AutoDiagnosis("extra-digit", f"digits {cd} printed as {pd}")
    # the simple factor closest to the ratio, if the printed digits pin the ratio down that
    # closely (a printed 4 for 5 is not a factor of 1/sqrt(2)); a sign flip is not a factor
    r = float(ratio)
    tol = _relative_width(printed) + 1e-12
    if r <= 0 or tol > _LOOSEST:
        return None
    name, factor = min(_FACTORS, key=lambda f: abs(math.log(r / f[1])))
    if abs(math.log(r / factor)) <= math.log1p(tol):
        return AutoDiagnosis("factor", f"printed = {name} x correct")
    return None
