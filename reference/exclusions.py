"""The closed list of exclusion rules: number tokens that are not claims, by family.

Each rule has a name, a one-line definition, and positive and negative tests on real lines of
the book (checks/test_exclusions.py). A rule returns the character spans of a line it covers; a
token wholly inside a span is excluded by that rule. Rules are narrow on purpose: a rule that
hides a real claim is worse than a missing token, because nobody will look for it again. Except
for the reference, equation-tag and citation rules, no rule excludes a token that has a decimal
point, has two or more significant digits followed by a unit, or stands right after "=" (a test
asserts this over the whole book).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

Span = tuple[int, int]

_ITEM = r"\d+(?:\.(?:A\.)?\d+)*[a-z]?(?:\([a-z]\))?"
_MORE = rf"(?:\s*[-–]\s*{_ITEM}|\s*(?:,|&|and|or|to)\s*\d+\.(?:A\.)?\d+[a-z]?(?:\([a-z]\))?)*"
_LIST = rf"{_ITEM}{_MORE}"


def _ref(words: str) -> re.Pattern[str]:
    return re.compile(rf"\b(?:{words})\s*{_LIST}")


@dataclass(frozen=True)
class Rule:
    """An exclusion rule: its name, what it covers, and the function finding its spans."""

    name: str
    definition: str
    spans: Callable[[Sequence[str], int], list[Span]]
    guarded: bool  # True: may not exclude decimals, numbers with units, or numbers after "="


def _regex_rule(
    pattern: re.Pattern[str], group: int = 0
) -> Callable[[Sequence[str], int], list[Span]]:
    def spans(lines: Sequence[str], number: int) -> list[Span]:
        return [m.span(group) for m in pattern.finditer(lines[number - 1])]

    return spans


_EQUATION_TAG = re.compile(r"(?<![\w)\]])\((?:1[0-2]|[1-9]|1\.A)\. ?\d{1,2}[a-z]?\)")
_FIGURE_WORDS = r"Figs?\.?|Figures?|Landscapes?"
_FIGURE = _ref(_FIGURE_WORDS)
_FIGURE_AT_END = re.compile(rf"\b(?:{_FIGURE_WORDS})\s*$")
_LIST_AT_START = re.compile(rf"^\s*{_LIST}")
_TABLE = _ref(r"Tables?")
_CHAPTER = _ref(r"Chapters?|Chs?\.|Appendix")
_SECTION = _ref(r"Sections?|Secs?\.|§")
_UNIT = re.compile(r"Units?\s+\d+(?:\s*(?:[-–,&]|and|thru|through|to)\s*\d+)*")
_PAGE = re.compile(r"\b(?:pp?\.|[Pp]ages?)\s*\d+(?:\s*[-–]\s*\d+)?")
_EXERCISE = _ref(r"[Ee]xercises?|Problems?|Ex\.|Solutions? to")
_FOOTER = re.compile(r"^\s*©\s*\d{4}\s+W\.\s*G\.\s*Harter")
_PAGE_NUMBER = re.compile(r"^\s*\d{1,3}\s*$")
_CITATION = re.compile(
    r"(?:\bvol\.\s*\d+,\s*)?\b\d+,\s*\d+\s*\(\d{4}\)"  # journal volume, page (year)
    r"|\b(?:Genesis|Exodus|Joshua|Psalms?|Isaiah|Matthew|Mark|Luke|John)\s+\d+:\d+(?:[-–]\d+)?"
)
_LIST_NUMBER = re.compile(r"^\s*\(?(\d{1,2})[.)]\s+(?=[A-Z])")
_GLUED_DIGIT = re.compile(r"(?<=[^\W\d_])\d(?!\d|\.\d)")
_INVERSE_FUNCTION = re.compile(r"\b(?:arc)?(?:sin|cos|tan|sec|csc|cot)h?[-−](1)(?![\d.])")
_DIMENSION = re.compile(r"\b([1-4])-?D\b")


def _figure(lines: Sequence[str], number: int) -> list[Span]:
    """Figure references on the line, and a figure number that starts the line when the line
    before (blank lines aside) ends with "Fig."."""
    text = lines[number - 1]
    spans = [m.span() for m in _FIGURE.finditer(text)]
    before = number - 1
    while before >= 1 and not lines[before - 1].strip():
        before -= 1
    if before >= 1 and _FIGURE_AT_END.search(lines[before - 1]):
        m = _LIST_AT_START.match(text)
        if m:
            spans.append(m.span())
    return spans


def _footer(lines: Sequence[str], number: int) -> list[Span]:
    text = lines[number - 1]
    if _FOOTER.match(text):
        return [(0, len(text))]
    if _PAGE_NUMBER.match(text):
        for back in range(1, 4):
            if number - back >= 1 and _FOOTER.match(lines[number - back - 1]):
                return [(0, len(text))]
    return []


def _symbol_index(lines: Sequence[str], number: int) -> list[Span]:
    text = lines[number - 1]
    out = []
    for m in _GLUED_DIGIT.finditer(text):
        i = m.start()
        before_symbol = text[i - 2] if i >= 2 else ""
        if not (before_symbol.isalpha() or before_symbol == "_"):
            out.append(m.span())
    return out


def _notation(lines: Sequence[str], number: int) -> list[Span]:
    text = lines[number - 1]
    return [m.span(1) for m in _INVERSE_FUNCTION.finditer(text)] + [
        m.span(1) for m in _DIMENSION.finditer(text)
    ]


RULES: tuple[Rule, ...] = (
    Rule(
        "page-footer",
        "the page footer '©2012 W. G. Harter ...' and a page number alone on "
        "a line up to three lines after it",
        _footer,
        False,
    ),
    Rule(
        "equation-tag",
        "an equation number in parentheses, (3.8), (5.13a), (1.A.7), not "
        "glued to a word or number before it",
        _regex_rule(_EQUATION_TAG),
        False,
    ),
    Rule(
        "ref-figure",
        "a figure reference: Fig. 8.1(b), Figs. 4.6-4.8, Fig. 1.1-2, Fig10.10a, Landscape 1.2, "
        "and a figure number starting a line after a line that ends with 'Fig.'",
        _figure,
        False,
    ),
    Rule("ref-table", "a table reference: Table 1.1", _regex_rule(_TABLE), False),
    Rule(
        "ref-chapter",
        "a chapter reference or heading: Chapter 8, Ch. 1-5, Chapter6., Appendix 1.A",
        _regex_rule(_CHAPTER),
        False,
    ),
    Rule("ref-section", "a section reference: Section 4, Sec. 3.2", _regex_rule(_SECTION), False),
    Rule(
        "ref-unit",
        "a reference to a Unit of the book: Unit 1, Units 1-8, Units 2 thru 8, Units 3 and 7",
        _regex_rule(_UNIT),
        False,
    ),
    Rule(
        "ref-page",
        "a page reference: p. 16, See page 119",
        _regex_rule(_PAGE),
        False,
    ),
    Rule(
        "exercise-number",
        "an exercise or problem number: Exercise 1.8.2, exercise 5.1, Problem 12.3, "
        "Solutions to 1.5.1",
        _regex_rule(_EXERCISE),
        False,
    ),
    Rule(
        "citation",
        "a citation: journal volume, page (year) as in 39, 656 (1971); a "
        "scripture chapter:verse as in Joshua 10:10-15",
        _regex_rule(_CITATION),
        False,
    ),
    Rule(
        "list-number",
        "the number of a numbered list item at the start of a line: '1. Construct', '2) Find'",
        _regex_rule(_LIST_NUMBER, 1),
        True,
    ),
    Rule(
        "symbol-index",
        "one digit glued to a one-letter symbol, an index or flattened exponent: m1, V2, σ1, x2",
        _symbol_index,
        True,
    ),
    Rule(
        "formula-notation",
        "notation, not a quantity: the -1 of an inverse function "
        "(tan-1, cos-1) and dimension labels (1D, 2-D, 3D, 4D)",
        _notation,
        True,
    ),
)

RULES_BY_NAME = {rule.name: rule for rule in RULES}


def rule_spans(lines: Sequence[str], number: int) -> list[tuple[str, Span]]:
    """Every (rule name, span) of line ``number``, in rule order."""
    return [(rule.name, span) for rule in RULES for span in rule.spans(lines, number)]


def excluded_by(spans: list[tuple[str, Span]], start: int, end: int) -> str | None:
    """The first rule whose span holds the token [start, end), or None."""
    for name, (a, b) in spans:
        if a <= start and end <= b:
            return name
    return None
