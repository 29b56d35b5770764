"""Where a catalog string (a claim's ``printed``, an exclusion's ``token``) sits on its line.

A printed string is one token, or several adjacent tokens where one number is printed in parts
("2·1030"). A match starts at a token's start and ends at a token's end; matches are counted left
to right, which is what ``occurrence`` counts. Minus signs and en dashes match ``-``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from reference.book import Book
from reference.tokens import Token, normalize, tokenize_line


@dataclass(frozen=True)
class Match:
    """One place where the string is printed: its span and the tokens it covers."""

    start: int
    end: int
    tokens: tuple[Token, ...]


def matches(text: str, tokens: list[Token], printed: str) -> list[Match]:
    """Every place on ``text`` (a line) where ``printed`` covers whole tokens, left to right."""
    wanted = normalize(printed)
    norm = normalize(text)
    starts = {t.start: i for i, t in enumerate(tokens)}
    found: list[Match] = []
    pos = norm.find(wanted)
    while pos != -1:
        end = pos + len(wanted)
        first = starts.get(pos)
        if first is not None:
            covered = []
            for tok in tokens[first:]:
                if tok.start >= end:
                    break
                covered.append(tok)
            if covered and covered[-1].end == end:
                found.append(Match(pos, end, tuple(covered)))
        pos = norm.find(wanted, pos + 1)
    return found


def pick_occurrence(found: list[Match], occurrence: int | None) -> tuple[Match | None, str]:
    """The match selected by ``occurrence`` (required when there are several), or a reason."""
    if not found:
        return None, "is not a token (or run of tokens) on the line"
    if occurrence is None:
        if len(found) > 1:
            return None, f"occurs {len(found)} times on the line: give 'occurrence'"
        return found[0], ""
    if occurrence > len(found):
        return None, f"occurrence {occurrence} asked, but it occurs {len(found)} time(s)"
    return found[occurrence - 1], ""


@cache
def line_tokens(book: Book, number: int) -> list[Token]:
    """The tokens of line ``number`` of ``book``, tokenized once per run (do not modify)."""
    return tokenize_line(book.line(number), number)


def find(book: Book, number: int, printed: str, occurrence: int | None) -> tuple[Match | None, str]:
    """Where ``printed`` stands on line ``number`` at ``occurrence``, or None and why not."""
    return pick_occurrence(
        matches(book.line(number), line_tokens(book, number), printed), occurrence
    )
