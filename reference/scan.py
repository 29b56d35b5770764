"""The scan: every number token of the selected chapters, catalogued, excluded or missing.

A token is ``catalogued`` when a claim's printed string covers it, else ``excluded`` by a rule
(``reference.exclusions``) or by hand (``[[excluded]]``), else ``missing``. The scan also reports
conflicts: a rule or a hand exclusion that covers a catalogued token, and a hand exclusion of a
token a rule already excludes.
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, field
from typing import Literal

from reference.book import Book
from reference.catalog import Catalog
from reference.exclusions import excluded_by, rule_spans
from reference.locate import find, line_tokens
from reference.restatements import restatement_conflicts
from reference.tokens import Token, normalize

Status = Literal["catalogued", "excluded", "missing"]


@dataclass(frozen=True)
class ScannedToken:
    """One token and what the scan found: its status and by what (claim id, rule, reason)."""

    chapter: str
    line: int
    start: int
    end: int
    text: str
    status: Status
    by: str | None
    hand: bool = False

    def to_json(self) -> dict[str, object]:
        return {
            "chapter": self.chapter,
            "line": self.line,
            "start": self.start,
            "text": self.text,
            "status": self.status,
            "by": self.by,
            "excluded_by": None if self.status != "excluded" else "hand" if self.hand else "rule",
        }


@dataclass
class ChapterCounts:
    """Per-chapter counts: tokens by status, excluded per rule and per hand reason."""

    chapter: str
    tokens: int = 0
    catalogued: int = 0
    excluded_rule: int = 0
    excluded_hand: int = 0
    missing: int = 0
    rules: Counter[str] = field(default_factory=Counter)
    reasons: Counter[str] = field(default_factory=Counter)


@dataclass
class ScanResult:
    """What a scan found, token by token, with counts and conflicts."""

    tokens: list[ScannedToken]
    chapters: dict[str, ChapterCounts]
    conflicts: list[str]

    @property
    def missing(self) -> list[ScannedToken]:
        return [t for t in self.tokens if t.status == "missing"]

    def rule_counts(self) -> Counter[str]:
        total: Counter[str] = Counter()
        for counts in self.chapters.values():
            total.update(counts.rules)
        return total


def _hand_key(reason: str) -> str:
    word = reason.split(":")[0].split()[0]
    return word


def _claimed(
    book: Book, catalog: Catalog, conflicts: list[str], formula_keys: set[tuple[int, int]]
) -> dict[tuple[int, int], str]:
    """(line, token start) of every catalogued token, with the claim id; a token two claims
    cover is a conflict. The tokens a formula claim lists go into ``formula_keys`` too: a rule
    may match them (design 2a)."""
    out: dict[tuple[int, int], str] = {}

    def mark(tok: Token, ident: str) -> None:
        other = out.setdefault((tok.line, tok.start), ident)
        if other != ident:
            conflicts.append(f"line {tok.line} token {tok.text!r}: claimed by {other} and {ident}")

    for _, claim in catalog.claims():
        for listed in claim.tokens:
            found, _ = find(book, listed.line, listed.token, listed.occurrence)
            for tok in found.tokens if found is not None else ():
                mark(tok, claim.id)
                formula_keys.add((tok.line, tok.start))
        if claim.printed is None:
            continue  # a formula, or an error with no number token: anchored by its quote
        match, _ = find(book, claim.line, claim.printed, claim.occurrence)
        if match is None:
            continue  # the validator reports it
        for tok in match.tokens:
            mark(tok, claim.id)
        if claim.line_end is not None:
            spelled = f"{claim.printed} {claim.means or ''}"
            parts = {p for p in re.split(r"[/\s·⋅]+", normalize(spelled)) if p}
            for number in range(claim.line + 1, claim.line_end + 1):
                for tok in line_tokens(book, number):
                    if tok.norm in parts:
                        mark(tok, claim.id)
    return out


def _hand(book: Book, catalog: Catalog) -> tuple[dict[tuple[int, int], str], dict[int, str]]:
    """Hand-excluded tokens by (line, start), and whole lines excluded by range, with reasons."""
    tokens: dict[tuple[int, int], str] = {}
    lines: dict[int, str] = {}
    for f in catalog.files:
        for e in f.excluded:
            if e.lines is not None:
                for number in range(e.lines[0], e.lines[1] + 1):
                    lines[number] = e.reason
            elif e.line is not None and e.token is not None:
                match, _ = find(book, e.line, e.token, e.occurrence)
                if match is not None:
                    for tok in match.tokens:
                        tokens[(tok.line, tok.start)] = e.reason
    return tokens, lines


def scan(book: Book, catalog: Catalog, chapters: tuple[str, ...]) -> ScanResult:
    """Classify every number token of ``chapters`` (keys as in book.toml); conflicts include
    every ``restates``/``part-of`` exclusion of those chapters that disagrees with its claim."""
    result = ScanResult([], {}, [])
    formula_keys: set[tuple[int, int]] = set()
    claimed = _claimed(book, catalog, result.conflicts, formula_keys)
    hand_tokens, hand_lines = _hand(book, catalog)
    for key in chapters:
        chapter = book.identity.chapter(key)
        counts = result.chapters.setdefault(key, ChapterCounts(key))
        for number in range(chapter.start, chapter.end + 1):
            tokens = line_tokens(book, number)
            if not tokens:
                continue
            spans = rule_spans(book.lines, number)
            for tok in tokens:
                counts.tokens += 1
                scanned = _classify(
                    key, tok, spans, claimed, hand_tokens, hand_lines, result, formula_keys
                )
                result.tokens.append(scanned)
                if scanned.status == "catalogued":
                    counts.catalogued += 1
                elif scanned.status == "missing":
                    counts.missing += 1
                elif scanned.hand:
                    counts.excluded_hand += 1
                    counts.reasons[_hand_key(scanned.by or "")] += 1
                else:
                    counts.excluded_rule += 1
                    counts.rules[scanned.by or ""] += 1
    result.conflicts.extend(restatement_conflicts(catalog, chapters))
    return result


def _classify(
    chapter: str,
    tok: Token,
    spans: list,
    claimed: dict[tuple[int, int], str],
    hand_tokens: dict[tuple[int, int], str],
    hand_lines: dict[int, str],
    result: ScanResult,
    formula_keys: set[tuple[int, int]],
) -> ScannedToken:
    key = (tok.line, tok.start)
    rule = excluded_by(spans, tok.start, tok.end)
    hand = hand_tokens.get(key)
    where = f"line {tok.line} token {tok.text!r}"
    if key in claimed:
        if rule and key not in formula_keys:
            result.conflicts.append(
                f"{where}: catalogued ({claimed[key]}) but rule {rule} excludes it"
            )
        if hand:
            result.conflicts.append(f"{where}: catalogued ({claimed[key]}) and excluded by hand")
        return ScannedToken(
            chapter, tok.line, tok.start, tok.end, tok.text, "catalogued", claimed[key]
        )
    if rule:
        if hand:
            result.conflicts.append(f"{where}: excluded by hand, but rule {rule} already does")
        return ScannedToken(chapter, tok.line, tok.start, tok.end, tok.text, "excluded", rule)
    reason = hand or hand_lines.get(tok.line)
    if reason:
        return ScannedToken(
            chapter, tok.line, tok.start, tok.end, tok.text, "excluded", reason, hand=True
        )
    return ScannedToken(chapter, tok.line, tok.start, tok.end, tok.text, "missing", None)
