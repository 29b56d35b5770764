"""The tokenizer's rules, each on a fragment of a real line of the book (line number given).

``test_fragments_are_on_their_lines`` checks that every fragment is printed on its line, so the
cases stay real.
"""

from __future__ import annotations

import pytest

from reference.book import Book
from reference.tokens import normalize, tokenize, tokenize_line

# (line, fragment of that line, tokens expected)
CASES = [
    # signs: after a space, "(", "=", "," or at the start; never inside a word
    (4334, "Bang-11(02)", ["11", "02"]),
    (1603, "tan-1(0.5)", ["1", "0.5"]),
    (7383, "=9.8ms-2)", ["9.8", "2"]),
    (7512, "(12 –3)", ["12", "–3"]),
    (1299, "(-0.9,-0.3)", ["-0.9", "-0.3"]),
    (4685, "−7.071", ["−7.071"]),
    (944, "-.5", ["-.5"]),
    (1603, "(±180°)", ["±180°"]),
    (2926, "12,500 − 10,500", ["12,500", "10,500"]),
    # ranges: a hyphen after a digit is not a sign
    (770, "(~1285-1349)", ["1285", "1349"]),
    (7439, "-0.5-1.5", ["-0.5", "1.5"]),
    (7754, "-4-3", ["-4", "3"]),
    # thousands separators, and pairs that are not
    (2407, "1⋅102=7,250", ["1", "102", "7,250"]),
    (6493, "60,200,000,000,0000,000,000,000", ["60,200,000,000,0000,000,000,000"]),
    (1938, "(60,10)", ["60", "10"]),
    # decimals
    (1697, "(say, sec-13.0)", ["13.0"]),
    (949, ".5mile", [".5"]),
    # E-notation, with or without a space; not for glued integers
    (11671, "m6.282 E6", ["6.282 E6"]),
    (7500, "100(6.7E-11)1E12", ["100", "6.7E-11", "1E12"]),
    (6373, "(0.5E-6m)", ["0.5E-6"]),
    (15382, "F1E1+F2E2", ["1", "1", "2", "2"]),
    # powers of ten
    (5328, "(2/3)·10-27kg", ["(2/3)·10-27"]),
    (7488, "1.67·10-27,", ["1.67·10-27"]),
    (7304, "9·10+9", ["9·10+9"]),
    (7304, "2 ·10−10", ["2", "10−10"]),
    (7490, "100·10-27=10-25 kg", ["100·10-27", "10-25"]),  # after "=", though a digit is before it
    (3537, "0.06/(6·1024)=10-26.", ["0.06", "6", "1024", "10-26"]),
    (3544, "10-26 of", ["10-26"]),  # at the start of a line that ends in a word
    (780, "(Joshua 10:10-15.)", ["10", "10", "15"]),
    # percent and degree marks
    (1389, "cotσ=64.2%.", ["64.2%"]),
    (934, "(45°slope=1/1)", ["45°", "1/1"]),
    # fractions
    (8315, "=1+1+1/2+1/6+1/24+1/120", ["1", "1", "1/2", "1/6", "1/24", "1/120"]),
    (6879, "1/10,1/9,1/8…1/5", ["1/10", "1/9", "1/8", "1/5"]),
    (1080, "1/10 in", ["1/10"]),
    # pi and roots
    (1602, "σ1=π/3", ["1", "π/3"]),
    (1603, "±π/3.", ["±π/3"]),
    (1100, "radian=180/π~57.3°.", ["180/π", "57.3°"]),
    (7490, "4π/3r3=", ["4π/3", "3"]),
    (1504, "a=√3/2", ["√3/2"]),
    # digits glued to words and symbols are still tokens (rules decide what they are)
    (928, "(going10mph)", ["10"]),
    (4097, "m1=49", ["1", "49"]),
    (4694, "N = 5", ["5"]),
    (1732, "30b=4", ["30", "4"]),
]


@pytest.mark.parametrize(
    ("line", "fragment", "expected"), CASES, ids=[f"{n}:{f}" for n, f, _ in CASES]
)
def test_tokens(line: int, fragment: str, expected: list[str]) -> None:
    assert [t.text for t in tokenize_line(fragment, line)] == expected


@pytest.mark.integrity
def test_fragments_are_on_their_lines(book: Book) -> None:
    absent = [(n, f) for n, f, _ in CASES if f not in book.line(n)]
    assert not absent


def test_token_span_and_line() -> None:
    text = "After Bang-11(02) big m1 is nearly stopped and little m2 is coming down at v2=-7.071"
    last = tokenize_line(text, 4334)[-1]
    assert (last.line, last.text, text[last.start : last.end]) == (4334, "-7.071", "-7.071")


def test_minus_variants_normalize() -> None:
    assert normalize("−7.071") == normalize("–7.071") == "-7.071"
    assert tokenize_line("−7.071", 4685)[0].norm == "-7.071"


def test_a_sign_at_the_end_of_a_line_is_no_token() -> None:
    assert tokenize_line("Ka-", 1) == []
    assert tokenize_line("x = -", 1) == []


def test_tokenize_numbers_lines() -> None:
    tokens = tokenize(["no numbers", "v1 = 0.0100"], first_line=4349)
    assert [(t.line, t.text) for t in tokens] == [(4350, "1"), (4350, "0.0100")]


@pytest.mark.integrity
def test_the_book_has_about_nine_thousand_tokens(book: Book) -> None:
    tokens = tokenize(book.lines)
    assert 8000 < len(tokens) < 10000, len(tokens)
    # numbered as the book is, from line 1: each token is where it says
    assert all(book.line(t.line)[t.start : t.end] == t.text for t in tokens)
