"""Hand exclusions that point at a claim, checked against it (design 3a, "Restatements").

- ``restates ID``: the excluded token repeats claim ID's number. It holds where the token
  (read through the exclusion's ``means`` if given, converted from the exclusion's ``unit`` if
  given, else taken in the claim's unit) agrees with the claim's stated value within the
  token's own precision. A repetition that differs is a claim of its own.
- ``part-of ID``: the token is a piece of a number stated whole (the 2 of π/2, the exponent
  of 10^-43). The piece's digits occur in the exclusion's ``means`` (the whole number as
  printed), else in the claim's printed string, ``means`` or formula expression; a ``means``,
  converted, agrees with the claim's value.

A disagreement is not a catalog error (a draft catalog with one edited value still evaluates):
``bangcheck scan`` lists it as a conflict, and an integrity test asserts there is none.
"""

from __future__ import annotations

from collections.abc import Collection, Iterator
from fractions import Fraction

from reference.catalog import Catalog
from reference.compare import inside
from reference.numbers import NumberFormatError, Printed, parse_number, significant_digits
from reference.schema import Claim, Excluded
from reference.tables import NO_CONVERSION, unit_factor
from reference.validate import parsed


def pointed_claim(excluded: Excluded) -> tuple[str, str] | None:
    """("restates" or "part-of", claim id) of an exclusion that names a claim, else None."""
    word, _, rest = excluded.reason.partition(" ")
    if word in ("restates", "part-of") and rest.strip():
        return word, rest.split()[0]
    return None


def _scale(excluded: Excluded, claim: Claim) -> Fraction | None:
    """The factor from the exclusion's unit to the claim's (None where they cannot meet)."""
    unit = excluded.unit or claim.unit
    if unit == claim.unit:
        return Fraction(1)
    if unit in NO_CONVERSION or claim.unit in NO_CONVERSION:
        return None
    return Fraction(unit_factor(unit)) / Fraction(unit_factor(claim.unit))


def _digits(text: str) -> str:
    return "".join(c for c in text if c.isdigit())


def restatement_problem(excluded: Excluded, claim: Claim) -> str | None:
    """Why a ``restates`` or ``part-of`` exclusion does not hold for ``claim``, or None."""
    pointed = pointed_claim(excluded)
    assert pointed is not None
    word = pointed[0]
    if claim.kind == "formula":  # a formula has no one value: the digits must be in it
        piece = significant_digits(excluded.means or excluded.token or "")
        if piece not in _digits(claim.expression or ""):
            return f"its digits {piece!r} are not in the formula {claim.expression!r}"
        return None
    scale = _scale(excluded, claim)
    if scale is None:
        return f"unit {excluded.unit or claim.unit!r} cannot be converted to {claim.unit!r}"
    try:
        stated = parsed(claim)
    except NumberFormatError as err:
        return f"{claim.id} has no value to compare with: {err}"
    if word == "restates":
        try:
            token = parse_number(excluded.means or excluded.token or "")
        except NumberFormatError as err:
            return f"the token is no number: {err}"
        return _disagreement(token, scale, stated, "the token")
    piece = significant_digits(excluded.token or "")
    wholes = [excluded.means] if excluded.means else [claim.printed or "", claim.means or ""]
    if not any(piece in _digits(whole) for whole in wholes):
        return f"its digits {piece!r} are not in {' or '.join(repr(w) for w in wholes if w)}"
    if excluded.means:
        try:
            whole = parse_number(excluded.means)
        except NumberFormatError as err:
            return f"means is no number: {err}"
        return _disagreement(whole, scale, stated, "its means")
    return None


def _disagreement(token: Printed, scale: Fraction, stated: Printed, what: str) -> str | None:
    value = token.value * scale
    target = abs(stated.value) if token.absolute else stated.value  # "±1": the magnitude
    if inside(abs(value - target), token.tolerance * abs(scale)):
        return None
    return (
        f"{what} {token.text!r} is {float(value):.6g} in the claim's unit, the claim states "
        f"{stated.text!r} ({float(stated.value):.6g})"
    )


def restatement_conflicts(
    catalog: Catalog, chapters: Collection[str] | None = None
) -> Iterator[str]:
    """One line per ``restates``/``part-of`` exclusion (of ``chapters``, default all) that does
    not hold: the scan's conflicts."""
    by_id = catalog.by_id()
    for f in catalog.files:
        if chapters is not None and f.meta.chapter not in chapters:
            continue
        for e in f.excluded:
            pointed = pointed_claim(e)
            if pointed is None or e.token is None or pointed[1] not in by_id:
                continue
            problem = restatement_problem(e, by_id[pointed[1]])
            if problem is not None:
                yield f"line {e.line} token {e.token!r}: {pointed[0]} {pointed[1]}, but {problem}"
