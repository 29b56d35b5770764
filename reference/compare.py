"""Verdicts: how a printed value compares with the model's (design sections 3 and 3a).

All arithmetic is on exact rationals: the printed string's exact value, the model's float taken
exactly. ``h`` is half a unit of the last counted digit; "inside" means ``|model - printed| <=
h (1 + 1e-9)`` so that a float such as 5.749999999999999 still rounds to "5.8".

A verdict depends on the printed value and on a ``Context``: what the model said (its value,
its range over the box of rounded inputs, its declared error) and what the claim declares (its
relation, a truncation, a constant's uncertainty). The context is fixed once the model has been
called, so that ``judge`` can judge any other printed string exactly as the real one was judged:
``reference.power`` misprints every claim that way, without calling a model again.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Literal

from reference.numbers import Printed

Verdict = Literal["verified", "rounding", "erratum", "dated", "given", "unmodeled", "indeterminate"]
VERDICTS: tuple[Verdict, ...] = (
    "verified",
    "rounding",
    "erratum",
    "dated",
    "given",
    "unmodeled",
    "indeterminate",
)
# "other-way" (within 2h) stays in the vocabulary for old outputs; it is no longer produced
RoundingReason = Literal["truncation", "other-way", "input-rounding"]

SLACK = Fraction(1, 10**9)


@dataclass(frozen=True)
class Judgement:
    """A verdict, the rounding reason where it is ``rounding``, and the tolerance applied."""

    verdict: Verdict
    reason: RoundingReason | None
    tolerance: Fraction | None
    edition: str | None = None  # the older edition of a constant a ``dated`` value matches


@dataclass(frozen=True)
class Edition:
    """An older edition of a constant: its short name, value (printed unit) and widening of h
    (twice its uncertainty)."""

    name: str
    value: Fraction
    extra: Fraction


@dataclass(frozen=True)
class Context:
    """What a claim's verdict depends on besides its printed value.

    ``model`` is the model's value in the printed unit (the real part, with ``imag`` the
    imaginary part that must vanish); ``interval`` its range over the box of rounded inputs;
    ``error`` its declared numerical error; ``extra`` widens h (twice a constant's standard
    uncertainty); ``exact_only`` admits no rounding at all (a count, a whole datum printed
    whole); ``truncation`` is a truncation the claim declares; ``editions`` are a constant's
    older editions, which a value today's misses may match (``dated``).
    """

    model: Fraction
    relation: str = "="
    imag: Fraction = Fraction(0)
    interval: tuple[Fraction, Fraction] | None = None
    error: Fraction | None = None
    extra: Fraction = Fraction(0)
    exact_only: bool = False
    truncation: bool = False
    rel_tol: Fraction | None = None
    bounds: tuple[Printed, Printed] | None = None
    editions: tuple[Edition, ...] = ()


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


def inside(diff: Fraction, tol: Fraction) -> bool:
    """Whether a difference lies within a tolerance (with the 1e-9 slack for floats)."""
    return diff <= tol * (1 + SLACK)


def is_truncation(printed: Printed, model: Fraction) -> bool:
    """Whether the printed value is the model cut toward zero at the printed digit (with the
    model's sign; a cut to zero has either sign)."""
    q = printed.quantum
    if q is None:
        return False
    cut = Fraction(math.trunc(abs(model) / q)) * q
    return cut == abs(printed.value) and model * printed.value >= 0


def _in_interval(printed: Printed, interval: tuple[Fraction, Fraction], tol: Fraction) -> bool:
    lo, hi = interval
    if printed.absolute:
        lo, hi = sorted((abs(lo), abs(hi))) if lo * hi >= 0 else (Fraction(0), max(-lo, hi))
    slack = tol * (1 + SLACK)
    return lo - slack <= printed.value <= hi + slack


def judge_equal(printed: Printed, ctx: Context, model: Fraction | None = None) -> Judgement:
    """Verdict of the relation ``=`` (at ``model``, default the context's).

    Verified within h (widened by ``extra``); else ``rounding`` only for a value inside the
    input interval widened by h (``input-rounding``) or a truncation the claim declares;
    otherwise ``erratum``. An exact model value therefore admits no rounding but a declared
    truncation.
    """
    value = ctx.model if model is None else model
    if printed.absolute:
        value = abs(value)
    diff = abs(value - printed.value)
    tol = printed.tolerance + ctx.extra
    if ctx.exact_only:
        return Judgement("verified" if diff == 0 else "erratum", None, Fraction(0))
    if inside(diff, tol):
        return Judgement("verified", None, tol)
    if ctx.interval is not None and _in_interval(printed, ctx.interval, tol):
        return Judgement("rounding", "input-rounding", tol)
    if ctx.truncation and is_truncation(printed, value):
        return Judgement("rounding", "truncation", tol)
    return Judgement("erratum", None, tol)


def judge_relation(printed: Printed, ctx: Context, model: Fraction | None = None) -> Judgement:
    """Verdict of ``~``, ``<``, ``>``, ``<=``, ``>=``, ``between`` and ``order`` (read: model REL
    printed). These give only ``verified`` or ``erratum``."""
    value = ctx.model if model is None else model
    target = printed.value
    relation = ctx.relation
    if relation == "~":
        assert ctx.rel_tol is not None
        tol = ctx.rel_tol * abs(target)
        return Judgement("verified" if abs(value - target) <= tol else "erratum", None, tol)
    if relation == "between":
        assert ctx.bounds is not None
        ok = ctx.bounds[0].value <= value <= ctx.bounds[1].value
    elif relation == "order":
        ok = in_order_of(value, target)
    else:
        ok = {
            "<": value < target,
            ">": value > target,
            "<=": value <= target,
            ">=": value >= target,
        }[relation]
    return Judgement("verified" if ok else "erratum", None, None)


def _judge_at(printed: Printed, ctx: Context, model: Fraction) -> Judgement:
    if ctx.relation == "=":
        judgement = judge_equal(printed, ctx, model)
    else:
        judgement = judge_relation(printed, ctx, model)
    if judgement.verdict != "erratum" and ctx.imag and abs(ctx.imag) > printed.tolerance:
        # a complex model value meets a real printed one: its imaginary part must vanish
        return Judgement("erratum", None, judgement.tolerance)
    return judgement


def judge(printed: Printed, ctx: Context) -> Judgement:
    """The verdict of ``printed`` in ``ctx``; ``indeterminate`` where it would change within
    the model's declared error; ``dated`` where today's value misses and an older edition of
    the constant matches (the one closest to the printed value)."""
    judgement = _judge_at(printed, ctx, ctx.model)
    if ctx.error:
        for sign in (-1, 1):
            if _judge_at(printed, ctx, ctx.model + sign * ctx.error).verdict != judgement.verdict:
                return Judgement("indeterminate", None, judgement.tolerance)
    if judgement.verdict == "erratum" and ctx.editions and ctx.relation == "=":
        matching = [
            e
            for e in ctx.editions
            if judge_equal(printed, Context(e.value, extra=e.extra)).verdict == "verified"
        ]
        if matching:
            best = min(matching, key=lambda e: abs(e.value - printed.value))
            return Judgement("dated", None, judgement.tolerance, best.name)
    return judgement


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
