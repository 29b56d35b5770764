"""Formula claims (design 2a): the book's printed formula against the model's.

The book's formula is a string in a small subset of Python/sympy syntax ("A/4", "omega**5*v",
"m*omega**2*r", "sqrt(2*g*h)"). It is read by walking its syntax tree, never evaluated as code:
only numbers, declared symbols, the constants ``pi``, ``E`` and ``I``, the operators
``+ - * / **`` and a fixed set of functions are accepted. A decimal literal ("0.577") carries
the precision of its digits: it becomes a symbol of its own, held at its printed value, and
the comparison allows what its half-width can change.

The model gives the correct formula: a mechmodel function that returns a sympy expression of
the claim's symbols (given sympy symbols for its ``{ symbol = NAME }`` arguments), or a numeric
function, evaluated at the same points. Both agree symbolically where the expanded difference of
two expressions is zero; else they are compared at a fixed list of generic points inside each
symbol's domain.
"""

from __future__ import annotations

import ast
import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from functools import cache, cached_property
from typing import Any

import sympy

FUNCTIONS: dict[str, Callable[..., Any]] = {
    "sqrt": sympy.sqrt,
    "sin": sympy.sin,
    "cos": sympy.cos,
    "tan": sympy.tan,
    "cot": sympy.cot,
    "sec": sympy.sec,
    "csc": sympy.csc,
    "asin": sympy.asin,
    "acos": sympy.acos,
    "atan": sympy.atan,
    "sinh": sympy.sinh,
    "cosh": sympy.cosh,
    "tanh": sympy.tanh,
    "exp": sympy.exp,
    "log": sympy.log,
    "ln": sympy.log,
    "Abs": sympy.Abs,
    "conjugate": sympy.conjugate,
    "re": sympy.re,
    "im": sympy.im,
    "factorial": sympy.factorial,
    "binomial": sympy.binomial,
}
CONSTANTS: dict[str, sympy.Expr] = {"pi": sympy.pi, "E": sympy.E, "I": sympy.I}
ASSUMPTIONS = frozenset(
    {"real", "positive", "negative", "nonnegative", "nonzero", "integer", "complex"}
)

# Generic values, none special (no 0, 1, 2, no simple fraction): each symbol takes the k-th
# value of its own rotation at point k, scaled into its domain.
_GENERIC = (0.3817, 1.2913, 0.7331, 1.8629, 0.5471, 2.4163, 0.9187)
POINTS = 5
REL_TOL = 1e-9
ABS_TOL = 1e-20  # an exact zero against 30-digit evaluation noise


class FormulaError(ValueError):
    """An expression this module cannot read; the message says what and where."""


@dataclass(frozen=True)
class Literal:
    """A decimal literal of a formula: its symbol, printed text, value and half-width."""

    symbol: sympy.Symbol
    text: str
    value: Fraction
    half_width: Fraction


@dataclass(frozen=True)
class Formula:
    """A parsed formula: the sympy expression and its decimal literals."""

    text: str
    expr: sympy.Expr
    literals: tuple[Literal, ...]

    @cached_property
    def nominal(self) -> sympy.Expr:
        """The expression with each decimal literal at its printed value (computed once: a
        comparison evaluates it at every generic point)."""
        return self.expr.subs({lit.symbol: sympy.Rational(lit.value) for lit in self.literals})


def make_symbol(name: str, spec: Mapping[str, Any] | None = None) -> sympy.Symbol:
    """The sympy symbol ``name`` with the assumptions of ``spec`` (``domain`` is not one)."""
    flags = {k: bool(v) for k, v in (spec or {}).items() if k in ASSUMPTIONS}
    return sympy.Symbol(name, **flags)


class _Reader(ast.NodeVisitor):
    def __init__(self, text: str, symbols: Mapping[str, sympy.Symbol]) -> None:
        self.text = text
        self.symbols = symbols
        self.literals: list[Literal] = []

    def fail(self, node: ast.AST, what: str) -> FormulaError:
        segment = ast.get_source_segment(self.text, node) or ""
        return FormulaError(f"{what} at {segment!r} in {self.text!r}")

    def read(self, node: ast.AST) -> sympy.Expr:
        if isinstance(node, ast.Expression):
            return self.read(node.body)
        if isinstance(node, ast.BinOp):
            left, right = self.read(node.left), self.read(node.right)
            ops: dict[type, Callable[[Any, Any], Any]] = {
                ast.Add: lambda a, b: a + b,
                ast.Sub: lambda a, b: a - b,
                ast.Mult: lambda a, b: a * b,
                ast.Div: lambda a, b: a / b,
                ast.Pow: lambda a, b: a**b,
            }
            op = ops.get(type(node.op))
            if op is None:
                raise self.fail(node, f"operator {type(node.op).__name__} is not allowed")
            return op(left, right)
        if isinstance(node, ast.UnaryOp):
            operand = self.read(node.operand)
            if isinstance(node.op, ast.USub):
                return -operand
            if isinstance(node.op, ast.UAdd):
                return operand
            raise self.fail(node, "only + and - may precede a term")
        if isinstance(node, ast.Constant):
            return self.number(node)
        if isinstance(node, ast.Name):
            if node.id in self.symbols:
                return self.symbols[node.id]
            if node.id in CONSTANTS:
                return CONSTANTS[node.id]
            raise self.fail(node, f"undeclared symbol {node.id!r}")
        if isinstance(node, ast.Call):
            if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
                raise self.fail(node, "unknown function")
            if node.keywords:
                raise self.fail(node, "keyword arguments are not allowed")
            return FUNCTIONS[node.func.id](*(self.read(a) for a in node.args))
        raise self.fail(node, f"{type(node).__name__} is not allowed")

    def number(self, node: ast.Constant) -> sympy.Expr:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.fail(node, "only numbers are allowed as literals")
        if isinstance(value, int):
            return sympy.Integer(value)
        text = ast.get_source_segment(self.text, node) or repr(value)
        dec = Decimal(text)
        exponent = dec.as_tuple().exponent
        assert isinstance(exponent, int)
        symbol = sympy.Symbol(f"_lit{len(self.literals)}", real=True)
        half = Fraction(10) ** exponent / 2
        self.literals.append(Literal(symbol, text, Fraction(dec), half))
        return symbol


def parse_formula(text: str, symbols: Mapping[str, sympy.Symbol]) -> Formula:
    """Read ``text`` into a ``Formula`` over ``symbols``; ``FormulaError`` for anything else
    (the text is never evaluated: its syntax tree is walked). Read once per text and symbols:
    validation and evaluation read the same formulas."""
    return _parsed(text, tuple(sorted(symbols.items())))


@cache
def _parsed(text: str, symbols: tuple[tuple[str, sympy.Symbol], ...]) -> Formula:
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as err:
        raise FormulaError(f"not a formula: {text!r} ({err.msg})") from err
    reader = _Reader(text.strip(), dict(symbols))
    expr = reader.read(tree)
    return Formula(text, sympy.sympify(expr), tuple(reader.literals))


def generic_points(
    symbols: Mapping[str, sympy.Symbol], domains: Mapping[str, Sequence[float]]
) -> list[dict[sympy.Symbol, float]]:
    """A fixed list of ``POINTS`` generic points: each symbol at its own rotation of generic
    values, scaled into its domain (default (0, 3] for positive symbols, else about [-2.4, 2.4]
    with both signs), integers rounded to generic integers (inside a declared domain)."""
    out = []
    names = sorted(symbols)
    for k in range(POINTS):
        point = {}
        for j, name in enumerate(names):
            sym = symbols[name]
            g = _GENERIC[(k + 3 * j) % len(_GENERIC)]
            lo, hi = domains.get(name, (None, None)) or (None, None)
            if lo is not None and hi is not None:
                value = lo + (hi - lo) * (g / 2.5)
            elif sym.is_positive or sym.is_nonnegative:
                value = g
            else:
                value = g if (k + j) % 2 == 0 else -g
            if sym.is_integer and lo is not None and hi is not None:
                value = min(max(round(value), math.ceil(lo)), math.floor(hi))
            elif sym.is_integer:
                value = round(value * 3) + 3 if sym.is_positive else round(value * 3)
            point[sym] = value
        out.append(point)
    return out


@dataclass(frozen=True)
class Comparison:
    """How the book's formula compared with the model's: agreeing or not, and where."""

    agrees: bool
    how: str  # "symbolic" or "points"
    worst: float | None = None  # the largest difference over tolerance at the points


def _numeric(expr: sympy.Expr, point: Mapping[sympy.Symbol, float]) -> complex:
    """``expr`` at ``point``, evaluated with 30 significant digits."""
    value = complex(expr.evalf(30, subs=dict(point)))
    if not (math.isfinite(value.real) and math.isfinite(value.imag)):
        raise FormulaError(f"{expr} is not finite at {point}")
    return value


def compare(
    book: Formula,
    model: sympy.Expr | Callable[[Mapping[sympy.Symbol, float]], complex],
    points: list[dict[sympy.Symbol, float]],
) -> Comparison:
    """Whether the book's formula equals the model's: symbolically where both are expressions,
    the book has no decimal literal and their expanded difference is zero, else at ``points``,
    within what the literals' half-widths can change (first order), a relative ``REL_TOL`` and
    an absolute ``ABS_TOL`` (far below any printed difference, far above the noise of 30-digit
    evaluation)."""
    if isinstance(model, sympy.Expr) and not book.literals:
        difference = book.expr - model
        # expanding shows equal polynomials and products in milliseconds (every symbolic
        # agreement of the catalog); what it leaves is decided at the generic points, where
        # sympy's simplify, 50 times dearer, found no agreement the points would miss
        if sympy.expand(difference) == 0:
            return Comparison(True, "symbolic")
    nominal = {x.symbol: sympy.Rational(x.value) for x in book.literals}
    partials = [
        (sympy.diff(book.expr, lit.symbol).subs(nominal), float(lit.half_width))
        for lit in book.literals
    ]
    worst = 0.0
    for point in points:
        b = _numeric(book.nominal, point)
        m = _numeric(model, point) if isinstance(model, sympy.Expr) else complex(model(point))
        slack = REL_TOL * (abs(b) + abs(m)) + ABS_TOL
        for partial, half_width in partials:
            slack += abs(_numeric(partial, point)) * half_width
        worst = max(worst, abs(b - m) / slack)
    return Comparison(worst <= 1, "points", worst)


@cache
def _unicode_names() -> dict[str, str]:
    greek = [
        "alpha",
        "beta",
        "gamma",
        "delta",
        "epsilon",
        "zeta",
        "eta",
        "theta",
        "iota",
        "kappa",
        "lambda",
        "mu",
        "nu",
        "xi",
        "omicron",
        "pi",
        "rho",
        "sigma",
        "tau",
        "upsilon",
        "phi",
        "chi",
        "psi",
        "omega",
    ]
    names = {name: chr(0x3B1 + i + (1 if i >= 17 else 0)) for i, name in enumerate(greek)}
    names["lamda"] = names["lambda"]  # sympy's spelling (lambda is a Python keyword)
    capitals = {
        name.capitalize(): chr(0x391 + i + (1 if i >= 17 else 0)) for i, name in enumerate(greek)
    }
    names.update(capitals)
    return names


_SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def unicode_formula(text: str) -> str:
    """A formula in sympy syntax as the book would print it ("omega**2*r" -> "ω²·r"): Greek
    letters, superscript powers, a middle dot for a product, √ for a square root, k! for
    factorial(k), i and e for sympy's I and E, ln for log, e^(...) for exp(...), an index as a
    subscript ("omega0" -> "ω₀", "am3" -> "a₋₃" for a_-3), z, z* and w for x + iy, x - iy and
    u + iv, and a true minus sign."""
    supers = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
    out = text.replace(" ", "")
    for name, letter in sorted(_unicode_names().items(), key=lambda kv: -len(kv[0])):
        out = _replace_word(out, name, letter)
    out = _replace_word(out, "sqrt", "√")

    def power(match: re.Match[str]) -> str:
        return (match[1] or match[2]).translate(supers)

    out = re.sub(r"\*\*(?:\((-?\d+)\)|(-?\d+)(?![\d.]))", power, out)
    out = re.sub(r"factorial\((\w+)\)", r"\1!", out)
    out = re.sub(r"(?<![\w.])I(?!\w)", "i", out)  # sympy's imaginary unit
    out = re.sub(r"(?<![\w.])E(?!\w)", "e", out)  # and Euler's number
    out = re.sub(r"(?<!\w)log\(", "ln(", out)
    out = re.sub(r"(?<!\w)exp\(", "e^(", out)
    out = out.replace("**", "^").replace("*", "·")
    out = re.sub(r"(?<!\w)am(\d+)(?!\w)", lambda m: "a₋" + m[1].translate(_SUBSCRIPTS), out)
    out = re.sub(
        r"(?<!\w)([^\W\d_]+)(\d+)(?!\w)", lambda m: m[1] + m[2].translate(_SUBSCRIPTS), out
    )
    for pair, name in (("x+i·y", "z"), ("x-i·y", "z*"), ("u+i·v", "w")):
        out = out.replace(f"(({pair}))", f"({name})").replace(f"({pair})", name)
    return out.replace("-", "−")


def _replace_word(text: str, word: str, by: str) -> str:
    # a Greek name may carry an index or a capital label ("omega0", "thetaB"), not more letters
    return re.sub(rf"(?<![A-Za-z_]){word}(?![a-z_])", by, text)
