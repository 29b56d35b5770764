"""Every printed number of a line, as one token each.

The rules (each is a test in ``checks/test_tokens.py`` on a real line of the book):

- **sign**: ``-``, Unicode minus ``−``, en dash ``–`` or ``+`` directly before a digit belongs to
  the token when it stands at the start of the line or after a space, ``(``, ``[``, ``{``, ``=``,
  ``,`` or ``;``; inside a word ("Bang-11", "tan-1", "ms-2") it does not. ``±`` always does.
- **thousands**: groups of three digits after commas ("7,250"); a chain of three or more groups
  may hold one four-digit group, a doubled glyph of the extraction
  ("60,200,000,000,0000,000,000,000"). "(60,10)" is two tokens.
- **decimal**: digits, a point, digits ("0.0100"); a point and digits at the start of a line or
  after a space, a sign, ``(`` or ``=`` (".5mile", "-.5"; not "Ch.4").
- **E-notation**: a mantissa, ``E`` and an exponent, with or without one space ("6.282 E6",
  "1.67E-27"); not after an integer glued to a letter ("E1E2" is two basis vectors).
- **power of ten**: a mantissa, a multiplication dot and ``10`` with a signed exponent are one
  token ("2·10-27", "(2/3)·10-27", "9·10+9"); so is a bare "10-25" (10, a minus and one or two
  digits, not after a digit, point or colon). The catalog still says what a power means.
- **percent and degree** marks belong to their number ("64.2%", "45°").
- **fraction** "p/q" of two integers ("30/10", "1/720"), unless the numerator is glued to a
  letter ("x2/2" is a symbol with an exponent, then a 2).
- **pi and roots**: "π/2", "2π/3", "5π", "180/π", "√3/2", "√8", "2√2", "1/√2" are one token each.
  A bare π with no digit is not a number token.
- **range**: "1285-1349" is two tokens (a hyphen after a digit is never a sign).

The patterns are in ``reference.grammar``, beside those that read a token's value.
"""

from __future__ import annotations

from dataclasses import dataclass

from reference.grammar import (
    MINUS_SIGNS,
    SCAN_BARE_POWER,
    SCAN_DECIMAL,
    SCAN_DOT_POWER,
    SCAN_E_SUFFIX,
    SCAN_FRACTION,
    SCAN_FRACTION_POWER,
    SCAN_MARK,
    SCAN_PI,
    SCAN_POINT_DECIMAL,
    SCAN_ROOT,
    normalize,
)

_SIGN_CONTEXT = " \t([{=,;"
_POINT_CONTEXT = " \t([{=~"


@dataclass(frozen=True, slots=True)
class Token:
    """One printed number: its line, its [start, end) span on that line, and its text as printed."""

    line: int
    start: int
    end: int
    text: str

    @property
    def norm(self) -> str:
        """The text with every minus and en dash written as ``-`` (for matching catalog strings)."""
        return normalize(self.text)


def _glued_to_letter(line: str, pos: int) -> bool:
    return pos > 0 and line[pos - 1].isalpha()


def _sign_at(line: str, pos: int) -> bool:
    """Whether ``line[pos]`` is a sign of the number that follows it."""
    char = line[pos]
    if char == "±":
        return True
    if char not in MINUS_SIGNS + "+":
        return False
    return pos == 0 or line[pos - 1] in _SIGN_CONTEXT


def _body_end(line: str, pos: int) -> int | None:
    """End of the number body starting at ``pos`` (a digit, π, √ or "("), or None."""
    glued = _glued_to_letter(line, pos)
    if line[pos] == "(":
        m = SCAN_FRACTION_POWER.match(line, pos)
        return m.end() if m else None
    for pattern in (SCAN_PI, SCAN_ROOT):
        m = pattern.match(line, pos)
        if m and any(c.isdigit() for c in m.group()):
            return m.end()
    if line[pos] in "π√":
        return None
    before = line[pos - 1] if pos else ""
    if not glued and not (before and (before in ".:" or before.isdigit())):
        m = SCAN_BARE_POWER.match(line, pos)
        if m:
            return m.end()
    if not glued:
        m = SCAN_FRACTION.match(line, pos)
        if m:
            return m.end()
    m = SCAN_DECIMAL.match(line, pos)
    if not m:
        return None
    end = m.end()
    mantissa_has_point = "." in m.group()
    power = SCAN_DOT_POWER.match(line, end)
    if power:
        end = power.end()
    elif mantissa_has_point or not glued:
        e_suffix = SCAN_E_SUFFIX.match(line, end)
        if e_suffix:
            end = e_suffix.end()
    mark = SCAN_MARK.match(line, end)
    return mark.end() if mark else end


def _starts_number(text: str, pos: int) -> bool:
    nxt = text[pos + 1 : pos + 2]
    return bool(nxt) and (nxt.isdigit() or nxt in ".π√")


def tokenize_line(text: str, line: int) -> list[Token]:
    """Every number token of one line of the book, left to right."""
    tokens: list[Token] = []
    pos = 0
    while pos < len(text):
        start = pos
        if _sign_at(text, pos) and _starts_number(text, pos):
            pos += 1
        end: int | None = None
        if text[pos] == "." and pos + 1 < len(text) and text[pos + 1].isdigit():
            if pos == 0 or text[pos - 1] in _POINT_CONTEXT + MINUS_SIGNS + "+±":
                m = SCAN_POINT_DECIMAL.match(text, pos)
                end = m.end() if m else None
        elif text[pos].isdigit() or text[pos] in "π√(":
            end = _body_end(text, pos)
        if end is None:
            pos = start + 1
            continue
        tokens.append(Token(line, start, end, text[start:end]))
        pos = end
    return tokens


def tokenize(lines: tuple[str, ...] | list[str], first_line: int = 1) -> list[Token]:
    """Tokens of consecutive lines, numbering the first one ``first_line``."""
    out: list[Token] = []
    for offset, text in enumerate(lines):
        out.extend(tokenize_line(text, first_line + offset))
    return out
