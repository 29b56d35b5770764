"""Detection power: would a verdict have caught a misprint? (design section 3a)

Every claim with relation ``=`` that is expected ``verified`` is misprinted the way a
typesetter would, one misprint at a time, and each misprint is judged exactly as the real
number was: with the claim's declared precision, in the claim's ``Context`` (so no model is
called again). A misprint is caught when its verdict is ``erratum``. A miss has a reason from a
closed list, or none: a miss without a reason is a hole in the judge or the catalog.

Misprint classes, per form of the printed number (or of its ``means``):

- decimals: ``last-digit`` (the last printed digit d replaced by d+1 or d-1, within 0-9),
  ``digit-swap`` (two adjacent different digits exchanged), ``decimal-shift`` (the point moved
  one place: x10, /10), ``sign`` (flipped);
- explicit powers (E-notation, "m·10-27", a bare "10-25"): the same on the mantissa, and
  ``power-of-ten`` (the exponent +1 or -1);
- fractions, multiples of pi, roots and caret powers: ``last-digit`` on the last run of
  digits, ``digit-swap`` within a run, ``sign``.

A printed "±a" has no sign misprint. A misprint must be another string with another value.
"""

from __future__ import annotations

import itertools
from collections import Counter, defaultdict
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Literal

from reference.compare import SLACK, Context, Judgement, judge
from reference.grammar import FORM_BARE_POWER, FORM_DECIMAL, FORM_DOT_POWER, FORM_E, normalize
from reference.numbers import NumberFormatError, Printed, parse_number
from reference.schema import Claim

MisprintClass = Literal["last-digit", "digit-swap", "decimal-shift", "sign", "power-of-ten"]
CLASSES: tuple[MisprintClass, ...] = (
    "last-digit",
    "digit-swap",
    "decimal-shift",
    "sign",
    "power-of-ten",
)
Reason = Literal[
    "input-interval",
    "declared-truncation",
    "declared-precision",
    "constant-uncertainty",
    "tie",
    "model-error",
    "matches-edition",
]
REASONS: tuple[Reason, ...] = (
    "input-interval",
    "declared-truncation",
    "declared-precision",
    "constant-uncertainty",
    "tie",
    "model-error",
    "matches-edition",
)
TARGETS: dict[MisprintClass, float] = {
    "last-digit": 0.97,
    "digit-swap": 0.995,
    "decimal-shift": 0.995,
    "sign": 0.995,
    "power-of-ten": 0.995,
}
MIN_MISPRINTS = 200  # a class this large meets its ratio; a smaller one has no unexplained miss

Form = Literal["decimal", "power", "fraction", "pi", "root", "caret"]


@dataclass(frozen=True)
class Misprint:
    """One misprint of a number: its class and the string the reader would see."""

    cls: MisprintClass
    text: str


@dataclass(frozen=True)
class Outcome:
    """A misprint judged: its verdict, and why a miss was let through (None if caught, or
    if no reason explains the miss)."""

    misprint: Misprint
    verdict: str
    reason: Reason | None

    @property
    def caught(self) -> bool:
        return self.verdict == "erratum"


# -- misprints ---------------------------------------------------------------------------------


def _split_sign(s: str) -> tuple[str, str, str]:
    """(sign, body, mark): "±", "-", "+" or ""; the number; a trailing % or °."""
    sign = ""
    if s[:1] in ("±", "-", "+"):
        sign, s = s[0], s[1:]
    mark = ""
    if s[-1:] in ("%", "°"):
        mark, s = s[-1], s[:-1]
    return sign, s, mark


def _digit_positions(s: str) -> list[int]:
    return [i for i, c in enumerate(s) if c.isdigit()]


def _last_digit(s: str, runs: Sequence[int] | None = None) -> list[str]:
    """``s`` with its last digit (of those at ``runs``, default all) one up and one down."""
    positions = list(runs) if runs is not None else _digit_positions(s)
    if not positions:
        return []
    i = positions[-1]
    d = int(s[i])
    return [s[:i] + str(n) + s[i + 1 :] for n in (d + 1, d - 1) if 0 <= n <= 9]


def _swaps(s: str, runs: Sequence[Sequence[int]]) -> list[str]:
    """``s`` with each pair of adjacent different digits (inside one run) exchanged."""
    out = []
    for run in runs:
        for a, b in itertools.pairwise(run):
            if s[a] != s[b]:
                chars = list(s)
                chars[a], chars[b] = chars[b], chars[a]
                out.append("".join(chars))
    return out


def _decimal_shifts(s: str) -> list[str]:
    """A decimal ("7,250", "0.54") with its point moved one place right and one left."""
    digits = s.replace(",", "")
    whole, _, frac = digits.partition(".")
    all_digits = whole + frac
    out = []
    for point in (len(whole) + 1, len(whole) - 1):
        if point < 0:
            continue
        if point >= len(all_digits):
            text = all_digits + "0" * (point - len(all_digits))
        else:
            text = all_digits[:point] + "." + all_digits[point:]
        head, dot, tail = text.partition(".")
        head = head.lstrip("0") or "0"
        out.append(head + dot + tail)
    return out


def _decimal_misprints(s: str) -> list[Misprint]:
    """Last digit, swaps and shifts of a plain decimal ``s`` (no sign, no mark)."""
    out = [Misprint("last-digit", t) for t in _last_digit(s)]
    out += [Misprint("digit-swap", t) for t in _swaps(s, [_digit_positions(s)])]
    out += [Misprint("decimal-shift", t) for t in _decimal_shifts(s)]
    return out


def _runs(s: str) -> list[list[int]]:
    """The runs of consecutive digits of ``s``, as lists of positions."""
    runs: list[list[int]] = []
    for i, c in enumerate(s):
        if c.isdigit():
            if runs and runs[-1][-1] == i - 1:
                runs[-1].append(i)
            else:
                runs.append([i])
    return runs


def _exact_form_misprints(s: str) -> list[Misprint]:
    """Fractions, pi and root forms, caret powers: +-1 on the last digit run, swaps in runs."""
    runs = _runs(s)
    out = [Misprint("last-digit", t) for t in _last_digit(s, runs[-1] if runs else [])]
    out += [Misprint("digit-swap", t) for t in _swaps(s, runs)]
    return out


def number_form(text: str) -> Form:
    """The form of a printed number or ``means`` string, as the misprint classes see it."""
    _, s, _ = _split_sign(normalize(text).strip())
    if FORM_E.fullmatch(s) or FORM_DOT_POWER.fullmatch(s) or FORM_BARE_POWER.fullmatch(s):
        return "power"
    if "π" in s:
        return "pi"
    if "√" in s:
        return "root"
    if "^" in s:
        return "caret"
    if "/" in s:
        return "fraction"
    return "decimal"


def _body_misprints(s: str) -> list[Misprint]:
    """The misprints of an unsigned number body ``s`` (signs are added by ``misprints``)."""
    if m := FORM_E.fullmatch(s):
        mant, e, exp = m["mant"], m["e"], m["exp"]
        out = [Misprint(x.cls, x.text + e + exp) for x in _decimal_misprints(mant)]
        return out + [Misprint("power-of-ten", mant + e + str(int(exp) + k)) for k in (1, -1)]
    if m := FORM_DOT_POWER.fullmatch(s):
        mant, dot, exp = m["mant"], m["dot"], m["exp"]
        inner = _exact_form_misprints(mant) if mant.startswith("(") else _decimal_misprints(mant)
        out = [Misprint(x.cls, x.text + dot + exp) for x in inner]
        return out + [Misprint("power-of-ten", f"{mant}{dot}{int(exp) + k:+d}") for k in (1, -1)]
    if m := FORM_BARE_POWER.fullmatch(s):
        return [Misprint("power-of-ten", f"10{int(m['exp']) + k:+d}") for k in (1, -1)]
    if FORM_DECIMAL.fullmatch(s):
        return _decimal_misprints(s)
    return _exact_form_misprints(s)


def _candidates(text: str) -> list[Misprint]:
    """The misprint strings of ``text`` in a fixed order, not yet read as numbers."""
    original = normalize(text).strip()
    sign, body, mark = _split_sign(original)
    found = [Misprint(m.cls, sign + m.text + mark) for m in _body_misprints(body)]
    if sign != "±":
        flipped = body if sign == "-" else "-" + body
        found.append(Misprint("sign", flipped + mark))
    seen = {original}
    out = []
    for m in found:
        if m.text not in seen:
            seen.add(m.text)
            out.append(m)
    return out


def _read_misprints(
    text: str, sigfigs: int | None = None, exact: bool = False
) -> list[tuple[Misprint, Printed]]:
    """The misprints of ``text`` with their values read at the given precision, each another
    string with another value than ``text``'s (read once: this runs for every claim)."""
    try:
        value = parse_number(text).value
    except NumberFormatError:
        return []
    out = []
    for m in _candidates(text):
        try:
            printed = parse_number(m.text, sigfigs=sigfigs, exact=exact)
        except (NumberFormatError, ZeroDivisionError):
            continue  # "1/0", or no digit left to count under reduced sigfigs
        if printed.value != value:
            out.append((m, printed))
    return out


def misprints(text: str) -> list[Misprint]:
    """Every misprint of ``text`` (a printed token or a ``means`` string) in every class, each
    a different string with a different value, in a fixed order."""
    return [m for m, _ in _read_misprints(text)]


# -- judging -----------------------------------------------------------------------------------


def measured(claim: Claim) -> bool:
    """Whether a claim is in the measure: relation ``=``, expected ``verified``, a printed
    number (not a formula)."""
    return (
        claim.relation == "="
        and claim.expect == "verified"
        and claim.printed is not None
        and claim.kind != "formula"
    )


def _reason(claim: Claim, printed: Printed, ctx: Context, judgement: Judgement) -> Reason | None:
    """Why a misprint with this judgement was not caught, or None if nothing explains it."""
    if judgement.verdict == "indeterminate":
        return "model-error"
    if judgement.verdict == "dated":
        return "matches-edition"
    if judgement.verdict == "rounding":
        return "input-interval" if judgement.reason == "input-rounding" else "declared-truncation"
    value = abs(ctx.model) if printed.absolute else ctx.model
    diff = abs(value - printed.value)
    if ctx.extra:
        return "constant-uncertainty"  # the value itself passes within the datum's uncertainty
    full = parse_number(printed.text, exact=claim.exact)
    if printed.tolerance > full.tolerance:
        return "declared-precision"  # sigfigs, or a date read at its last non-zero digit
    if diff >= printed.tolerance * (1 - SLACK):
        return "tie"
    return None


def judge_misprints(claim: Claim, ctx: Context) -> list[Outcome]:
    """Every misprint of a measured claim, judged in its context with its declared precision."""
    stated = claim.means or claim.printed
    assert stated is not None  # a measured claim prints its number
    out = []
    for m, printed in _read_misprints(stated, claim.sigfigs, claim.exact):
        judgement = judge(printed, ctx)
        verdict = judgement.verdict
        reason = None if verdict == "erratum" else _reason(claim, printed, ctx, judgement)
        out.append(Outcome(m, verdict, reason))
    return out


def catches(outcomes: Iterable[Outcome]) -> list[str]:
    """The classes all of whose misprints were caught (of those that apply to the claim)."""
    by_class: dict[str, bool] = {}
    for o in outcomes:
        by_class[o.misprint.cls] = by_class.get(o.misprint.cls, True) and o.caught
    return [c for c in CLASSES if by_class.get(c)]


# -- the measure -------------------------------------------------------------------------------


@dataclass(frozen=True)
class ClassRate:
    """Misprints of one class (over the selection), how many were caught, and the target."""

    cls: str
    misprints: int
    caught: int
    target: float | None = None

    @property
    def rate(self) -> float | None:
        return self.caught / self.misprints if self.misprints else None

    def to_json(self) -> dict[str, object]:
        return {
            "class": self.cls,
            "misprints": self.misprints,
            "caught": self.caught,
            "rate": self.rate,
            "target": self.target,
        }


@dataclass(frozen=True)
class Miss:
    """A misprint a verdict let through."""

    id: str
    chapter: str
    line: int
    cls: str
    printed: str
    misprint: str
    verdict: str
    reason: Reason | None

    def to_json(self) -> dict[str, object]:
        return {
            "id": self.id,
            "line": self.line,
            "class": self.cls,
            "printed": self.printed,
            "misprint": self.misprint,
            "verdict": self.verdict,
            "reason": self.reason,
        }


@dataclass(frozen=True)
class PowerReport:
    """The detection power of a selection of claims: per class, form and chapter, and the
    misses."""

    classes: tuple[ClassRate, ...]
    forms: dict[str, dict[str, ClassRate]]
    chapters: dict[str, dict[str, ClassRate]]
    misses: tuple[Miss, ...]
    claims: int

    @property
    def unexplained(self) -> list[Miss]:
        return [m for m in self.misses if m.reason is None]

    def failures(self) -> list[str]:
        """Which whole-book targets are missed (a class of ``MIN_MISPRINTS`` or more below
        its ratio; a smaller class with a miss without a reason), one line each."""
        out = []
        for c in self.classes:
            if c.misprints >= MIN_MISPRINTS and c.rate is not None and c.target is not None:
                if c.rate < c.target:
                    out.append(f"{c.cls}: {c.rate:.4f} caught, below the target {c.target}")
            elif any(m.cls == c.cls and m.reason is None for m in self.misses):
                out.append(f"{c.cls}: a miss without a reason in a class of {c.misprints}")
        return out

    def to_json(self) -> dict[str, object]:
        return {
            "claims": self.claims,
            "classes": [c.to_json() for c in self.classes],
            "forms": {f: [c.to_json() for c in rates.values()] for f, rates in self.forms.items()},
            "chapters": {
                k: [c.to_json() for c in rates.values()] for k, rates in self.chapters.items()
            },
            "misses": [m.to_json() for m in self.misses],
            "failures": self.failures(),
        }


def _rates(outcomes: Iterable[Outcome], targets: bool) -> dict[str, ClassRate]:
    total: Counter[str] = Counter()
    caught: Counter[str] = Counter()
    for o in outcomes:
        total[o.misprint.cls] += 1
        caught[o.misprint.cls] += o.caught
    return {
        c: ClassRate(c, total[c], caught[c], TARGETS[c] if targets else None)
        for c in CLASSES
        if total[c]
    }


def power_report(
    rows: Iterable[tuple[str, str, int, str, list[Outcome]]],
) -> PowerReport:
    """The measure over ``rows`` of (claim id, chapter, line, stated text, its outcomes)."""
    everything: list[Outcome] = []
    by_form: dict[str, list[Outcome]] = defaultdict(list)
    by_chapter: dict[str, list[Outcome]] = defaultdict(list)
    misses = []
    count = 0
    for ident, chapter, line, stated, outcomes in rows:
        count += 1
        everything += outcomes
        by_form[number_form(stated)] += outcomes
        by_chapter[chapter] += outcomes
        for o in outcomes:
            if not o.caught:
                misses.append(
                    Miss(
                        ident,
                        chapter,
                        line,
                        o.misprint.cls,
                        stated,
                        o.misprint.text,
                        o.verdict,
                        o.reason,
                    )
                )
    all_rates = _rates(everything, targets=True)
    return PowerReport(
        classes=tuple(all_rates.values()),
        forms={f: _rates(o, targets=False) for f, o in by_form.items()},
        chapters={k: _rates(o, targets=False) for k, o in by_chapter.items()},
        misses=tuple(misses),
        claims=count,
    )
