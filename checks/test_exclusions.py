"""The exclusion rules: positive and negative cases on real lines, and the guards over the book.

Each case names a real line; ``test_cases_are_real_lines`` checks the fragment is printed there.
"""

from __future__ import annotations

import re

import pytest

from reference.book import Book
from reference.exclusions import RULES, RULES_BY_NAME, excluded_by, rule_spans
from reference.scan import ScanResult
from reference.tables import units
from reference.tokens import tokenize, tokenize_line

# (rule, line, fragment, token, occurrence of the token in the fragment, excluded by the rule?)
CASES = [
    ("equation-tag", 7512, "const.=- mg        (9.6)", "9.6", 1, True),
    ("equation-tag", 2077, "Newton’s equation (2.1) repeated", "2.1", 1, True),
    ("equation-tag", 1603, "angles that equal tan-1(0.5).", "0.5", 1, False),
    ("equation-tag", 10137, "  (10. 41b)", "41", 1, True),
    ("ref-figure", 6528, "as shown in Fig. 8.1(b) so each", "8.1", 1, True),
    ("ref-figure", 1364, "straight lines in Fig. 1.1-2. For", "2", 1, True),
    ("ref-figure", 6527, "An even better final speed of V3=3.62 is had", "3.62", 1, False),
    ("ref-table", 3238, " Table 3.1 of kinetic rel", "3.1", 1, True),
    ("ref-table", 8576, "up the 10th row of Table 1.)", "10", 1, False),
    ("ref-chapter", 3335, "Exercise 1.3.2. Ch. 1-5 contains", "5", 1, True),
    ("ref-chapter", 6482, "“Bang-Bang” models of Ch.4 ignored", "4", 1, True),
    ("ref-chapter", 6510, " Chapter 8 N-Body Collisions", "8", 1, True),
    ("ref-chapter", 125, "Euclid (~300BC) in Ch. 1-11 and", "300", 1, False),
    ("ref-chapter", 9552, "products in Appendix 1.A of this Unit.", "1", 1, True),
    ("ref-section", 12854, "rods are treated in Sec. 6.4 of the", "6.4", 1, True),
    ("ref-section", 938, " -30 sec. 30 sec.", "30", 1, False),
    ("ref-unit", 11, "Topics in Units 1-8", "8", 1, True),
    ("ref-unit", 139, "(in Ch. 3 Unit 1 sketched↓below)", "1", 1, True),
    ("ref-unit", 1100, "on unit circle (r=1) (Fig. 1.3a)", "1", 1, False),
    ("ref-unit", 152, "preview of topics in Units 2 thru 8 that go", "8", 1, True),
    ("ref-page", 466, "using Occam’s Razor (See p. 16) to produce", "16", 1, True),
    ("ref-page", 8224, "A binomial expansion (See page 119) turns", "119", 1, True),
    ("ref-page", 7490, "That is 100·10-27=10-25 kg packed", "100·10-27", 1, False),
    ("exercise-number", 6925, "Exercise 1.8.2 Absolute Maximum", "1.8", 1, True),
    ("exercise-number", 6925, "Exercise 1.8.2 Absolute Maximum", "2", 1, True),
    ("exercise-number", 5213, "Exercise 1.5.1 Gameover 49:1", "49", 1, False),
    ("exercise-number", 4712, "(See exercise 5.1.) Matrix group", "5.1", 1, True),
    ("citation", 6544, "Am. J. Phys. 39, 656 (1971).", "656", 1, True),
    ("citation", 6544, "Am. J. Phys. 39, 656 (1971).", "1971", 1, True),
    ("citation", 780, "Scripture(Joshua 10:10-15.) tells", "15", 1, True),
    ("citation", 4083, "The 4:1 mass ratio", "4", 1, False),
    ("citation", 1358, "Descartes (1620), the complex", "1620", 1, False),
    ("list-number", 1426, "1. Construct whirling square diagrams", "1", 1, True),
    ("list-number", 5323, "(1) Bang rate B w", "1", 1, True),
    ("list-number", 2407, "1 1⋅102=7,250  2", "1", 1, False),
    ("symbol-index", 4097, "big mass m1=49 bang", "1", 1, True),
    ("symbol-index", 1602, "two angles σ1=π/3 and", "1", 1, True),
    ("symbol-index", 928, "VW (going10mph)", "10", 1, False),
    ("symbol-index", 5949, "speed vFIN2=vIN2+2V1.", "2", 1, False),
    ("symbol-index", 6527, "speed of V3=3.62 is had", "3.62", 1, False),
    ("symbol-index", 11671, " k=mω 2= m6.282 E6  (N/m)", "6.282 E6", 1, False),
    ("formula-notation", 1603, "angles that equal tan-1(0.5).", "1", 1, True),
    ("formula-notation", 3410, "(1D-2-body) collision", "1", 1, True),
    ("formula-notation", 3410, "(1D-2-body) collision", "2", 1, False),
    ("formula-notation", 7781, "(b) 2-D Oscillator Phasor Plot", "2", 1, True),
    ("formula-notation", 4334, "After Bang-11(02) big", "11", 1, False),
]


def _rule_of(fragment: str, token: str, occurrence: int) -> str | None:
    found = [t for t in tokenize_line(fragment, 1) if t.text == token]
    tok = found[occurrence - 1]
    return excluded_by(rule_spans([fragment], 1), tok.start, tok.end)


@pytest.mark.parametrize(
    ("rule", "line", "fragment", "token", "occurrence", "excluded"),
    CASES,
    ids=[f"{r}:{n}:{tok}:{'yes' if ex else 'no'}" for r, n, _, tok, _, ex in CASES],
)
def test_rule(
    rule: str, line: int, fragment: str, token: str, occurrence: int, excluded: bool
) -> None:
    assert rule in RULES_BY_NAME
    got = _rule_of(fragment, token, occurrence)
    if excluded:
        assert got == rule
    else:
        assert got is None


def test_every_rule_has_positive_and_negative_cases() -> None:
    for rule in RULES:
        if rule.name == "page-footer":
            continue  # on whole lines: test_page_footer_on_the_book
        outcomes = {ex for r, *_, ex in CASES if r == rule.name}
        assert outcomes == {True, False}, rule.name


@pytest.mark.integrity
def test_a_figure_number_after_a_line_ending_in_fig(book: Book) -> None:
    assert book.line(1384).rstrip().endswith("as the triangle in Fig.")
    token = tokenize_line(book.line(1385), 1385)[0]
    assert token.text == "1.4"
    assert excluded_by(rule_spans(book.lines, 1385), token.start, token.end) == "ref-figure"
    tokens = tokenize_line(book.line(1386), 1386)
    assert all(excluded_by(rule_spans(book.lines, 1386), t.start, t.end) is None for t in tokens)


@pytest.mark.integrity
def test_page_footer_on_the_book(book: Book) -> None:
    footer = book.line(1901)
    assert footer.startswith("©2012 W. G. Harter Chapter 1.")
    tokens = tokenize_line(footer, 1901)
    rules = {excluded_by(rule_spans(book.lines, 1901), t.start, t.end) for t in tokens}
    assert rules == {"page-footer"}
    assert book.line(1903) == "36"
    assert rule_spans(book.lines, 1903) == [("page-footer", (0, 2))]
    assert book.line(970) == "10"
    assert rule_spans(book.lines, 970) == []  # a lone number far from any footer


@pytest.mark.integrity
def test_cases_are_real_lines(book: Book) -> None:
    absent = [(n, f) for _, n, f, *_ in CASES if f not in book.line(n)]
    assert not absent


def _unit_after(text: str, end: int) -> bool:
    rest = text[end:].lstrip()
    symbols = sorted({s for u in units().values() for s in u.symbols}, key=len, reverse=True)
    return any(re.match(rf"{re.escape(s)}(?![^\W\d_])", rest) for s in symbols)


@pytest.mark.integrity
def test_guarded_rules_spare_decimals_units_and_values_after_equals(book: Book) -> None:
    guarded = {rule.name for rule in RULES if rule.guarded}
    offending = []
    spans: dict[int, list] = {}  # the rules' spans of each line, found once per line
    for tok in tokenize(book.lines):
        text = book.line(tok.line)
        if tok.line not in spans:
            spans[tok.line] = rule_spans(book.lines, tok.line)
        rule = excluded_by(spans[tok.line], tok.start, tok.end)
        if rule not in guarded:
            continue
        digits = len(tok.text.strip("-−–+±").lstrip("0").replace(",", ""))
        if (
            "." in tok.text
            or text[: tok.start].rstrip().endswith("=")
            or (digits >= 2 and _unit_after(text, tok.end))
        ):
            offending.append((tok.line, tok.text, rule))
    assert not offending


@pytest.mark.integrity
@pytest.mark.xdist_group("evaluation")  # with the other readers of the session's scan
def test_rules_exclude_fewer_than_half_the_tokens(whole_scan: ScanResult) -> None:
    by_rule = sum(c.excluded_rule for c in whole_scan.chapters.values())
    assert by_rule < len(whole_scan.tokens) / 2


@pytest.mark.integrity
@pytest.mark.xdist_group("evaluation")  # with the other readers of the session's scan
def test_no_rule_or_hand_exclusion_conflicts_with_the_catalog(whole_scan: ScanResult) -> None:
    assert whole_scan.conflicts == []
