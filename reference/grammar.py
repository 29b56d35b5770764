"""The grammar of printed numbers, in one place: how the tokenizer finds a number in a line of
the book (``SCAN_*``, matched at a position, with the context rules of ``reference.tokens``) and
how a token or a catalog string is read as a value (``FORM_*``, matched whole, with named groups
for ``reference.numbers`` and ``reference.power``).

The forms: decimals with thousands commas ("7,250", "0.0100", ".5"); E-notation ("6.282 E6",
"1.67e-27"); powers of ten after a multiplication dot ("2·10-27", "(2/3)·10-27") and bare
("10-25"); caret powers in ``means`` strings ("60^2", "6.28^2e6"); fractions "p/q"; multiples
and fractions of pi ("2π/3", "180/π") and roots ("√3/2", "1/√2"); a % or ° mark.
"""

from __future__ import annotations

import re

MINUS_SIGNS = "-−–"
DOT = "·⋅"

# -- finding a number in a line (reference.tokens) ---------------------------------------------
# an integer with thousands commas; a chain of three or more groups may hold one four-digit
# group (a doubled glyph of the extraction: "60,200,000,000,0000,000,000,000")
SCAN_INT = r"(?:\d{1,3}(?:,\d{3,4}){3,}(?!\d)|\d{1,3}(?:,\d{3})+(?!\d)|\d+)"
SCAN_FRACTION_POWER = re.compile(rf"\(\d+/\d+\)[{DOT}]10[{MINUS_SIGNS}+]\d+")
SCAN_PI = re.compile(r"\d*π/\d+|\d+π|\d+/π")
SCAN_ROOT = re.compile(r"\d*√\d+(?:/\d+)?|\d+/√\d+")
SCAN_BARE_POWER = re.compile(rf"10[{MINUS_SIGNS}]\d{{1,2}}(?!\d|[.,]\d)")
SCAN_FRACTION = re.compile(r"\d+/\d+(?!\d|\.\d)")
SCAN_DECIMAL = re.compile(rf"{SCAN_INT}(?:\.\d+)?")
SCAN_DOT_POWER = re.compile(rf"[{DOT}]10[{MINUS_SIGNS}+]\d+")
SCAN_E_SUFFIX = re.compile(r" ?E[-+−]?\d+")
SCAN_POINT_DECIMAL = re.compile(r"\.\d+[%°]?")
SCAN_MARK = re.compile(r"[%°]")

# -- reading a whole token or catalog string (reference.numbers, reference.power) --------------
DECIMAL = r"\d[\d,]*(?:\.\d+)?|\.\d+"
FORM_DECIMAL = re.compile(rf"(?:{DECIMAL})")
FORM_DOT_POWER = re.compile(rf"(?P<mant>{DECIMAL}|\(\d+/\d+\))(?P<dot>[{DOT}]10)(?P<exp>[-+]\d+)")
FORM_BARE_POWER = re.compile(r"10(?P<exp>-\d{1,2})")
FORM_E = re.compile(rf"(?P<mant>{DECIMAL})(?P<e> ?[Ee])(?P<exp>[-+]?\d+)")
FORM_CARET = re.compile(rf"(?P<base>{DECIMAL})\^(?P<exp>[-+]?\d+)(?:e(?P<scale>[-+]?\d+))?")
FORM_FRACTION = re.compile(r"(?P<p>\d+)/(?P<q>\d+)")
FORM_PI = re.compile(r"(?P<a>\d*)π(?:/(?P<b>\d+))?|(?P<c>\d+)/π")
FORM_ROOT = re.compile(r"(?P<a>\d*)√(?P<r>\d+)(?:/(?P<b>\d+))?|(?P<c>\d+)/√(?P<s>\d+)")


def normalize(text: str) -> str:
    """``text`` with the Unicode minus and the en dash written as ASCII ``-``."""
    return text.replace("−", "-").replace("–", "-")
