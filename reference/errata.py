"""Errata as errors: one error, however many claims print it (design 2a).

An erratum claim names the first claim of its error with ``same_error`` (the earliest line; no
chains), or restates an erratum, which makes it part of that one's error; the first claim
carries the error's one-sentence ``summary``. Each error has a class, derived in this order:
a formula claim is ``formula``; a sign diagnosis ``sign``; a date (a constant with ``date =
true``) ``date``; another constant ``constant``; diagnosis ``inconsistent`` ``inconsistent``;
else ``value``. Its location is the chapter, the section (``book.toml``), the equation (the
claim's own, else the nearest equation tag in the same section, at or below the line first)
and the figure.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from reference.book import Identity
from reference.schema import Claim
from reference.tables import constants

ERROR_CLASSES = ("formula", "sign", "date", "constant", "inconsistent", "value")
# an equation's own tag ends its line ("... = 250   (2.2)"); a tag inside prose is a reference
_TAG = re.compile(r"(?<![\w)\]])\(((?:1[0-2]|[1-9]|1\.A)\. ?\d{1,2}[a-z]?)\)\s*$")


@dataclass(frozen=True)
class Error:
    """One error of the book: its claims in line order (the first names it), its class,
    summary and location."""

    claims: tuple[Claim, ...]
    error_class: str
    summary: str | None
    chapter: str
    section: str | None
    equation: str | None
    figure: str | None

    @property
    def first(self) -> Claim:
        return self.claims[0]


def error_class(claim: Claim) -> str:
    """The class of the error whose first claim is ``claim``."""
    if claim.kind == "formula":
        return "formula"
    if claim.diagnosis is not None and claim.diagnosis.kind == "sign":
        return "sign"
    if claim.constant is not None:
        entry = constants().get(claim.constant)
        return "date" if entry is not None and entry.date else "constant"
    if claim.diagnosis is not None and claim.diagnosis.kind == "inconsistent":
        return "inconsistent"
    return "value"


def error_of(claim: Claim, by_id: Mapping[str, Claim]) -> str:
    """The id of the first claim of the error ``claim`` belongs to."""
    if claim.same_error is not None:
        return claim.same_error
    restated = by_id.get(claim.restates or "")
    if restated is not None and restated.expect == "erratum":
        return error_of(restated, by_id)
    return claim.id


def equation_near(lines: Sequence[str], identity: Identity, line: int) -> str | None:
    """The nearest equation tag to ``line`` in its section: at or below it first (a tag ends
    the equation it labels), then above."""
    section = identity.section_of(line)
    start = section.line if section is not None else 1
    following = [s.line for s in identity.sections if s.line > line]
    end = (following[0] - 1) if following else len(lines)
    for number in [*range(line, end + 1), *range(line - 1, start - 1, -1)]:
        found = _TAG.findall(lines[number - 1])
        if found:
            return f"({found[0].replace(' ', '')})"
    return None


def errors(
    claims: Iterable[tuple[Claim, str]],
    by_id: Mapping[str, Claim],
    lines: Sequence[str],
    identity: Identity,
) -> list[Error]:
    """The errors of the given erratum claims (with their chapters), in book order."""
    groups: dict[str, list[tuple[Claim, str]]] = {}
    for claim, chapter in claims:
        groups.setdefault(error_of(claim, by_id), []).append((claim, chapter))

    def place(member: tuple[Claim, str]) -> tuple[int, int, str]:
        claim = member[0]
        return claim.line, max(lines[claim.line - 1].find(claim.quote), 0), claim.id

    out = []
    for members in groups.values():
        members.sort(key=place)
        first, chapter = members[0]
        head = by_id.get(error_of(first, by_id), first)
        section = identity.section_of(first.line)
        out.append(
            Error(
                claims=tuple(m[0] for m in members),
                error_class=error_class(head),
                summary=head.summary,
                chapter=chapter,
                section=section.heading if section is not None else None,
                equation=first.equation or equation_near(lines, identity, first.line),
                figure=next((m[0].figure for m in members if m[0].figure), None),
            )
        )
    out.sort(key=lambda e: (e.first.line, e.first.id))
    return out
