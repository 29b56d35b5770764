"""The catalog schema 1 (design section 2) as validated models.

pydantic checks each entry's fields, their types and vocabularies, and rejects unknown fields
(a misspelt field is an error, never silently ignored). The rules that tie fields together or
to the book live in ``reference.validate``; both report problems as ``Problem`` lines naming the
file, the claim id and the field.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, StringConstraints
from typing_extensions import TypeAliasType

Kind = Literal["derived", "given", "constant", "identity", "count", "formula"]
Expect = Literal["verified", "rounding", "erratum", "given", "dated"]
Relation = Literal["=", "~", "<", ">", "<=", ">=", "between", "order"]
Garble = Literal[
    "superscript", "root-lost", "fraction-split", "doubled-glyph", "minus-lost", "other"
]
DiagnosisKind = Literal[
    "decimal-shift",
    "digit-swap",
    "last-digit",
    "dropped-digit",
    "extra-digit",
    "sign",
    "factor",
    "swapped-values",
    "arithmetic",
    "wrong-formula",
    "inconsistent",
    "dated",
    "other",
]
HAND_REASONS = (
    "notation",
    "axis-tick",
    "symbolic-matrix",
    "restates",
    "part-of",
    "not-a-claim",
)

Text = Annotated[str, StringConstraints(min_length=1)]
Line = Annotated[int, Field(ge=1)]


@dataclass(frozen=True, order=True)
class Problem:
    """One catalog problem: where (file, claim id, field) and what."""

    file: str
    id: str
    field: str
    message: str

    def __str__(self) -> str:
        """``file: id: field 'name': message``, leaving out an id or field of "-" (none: a
        problem of the whole file, such as its TOML syntax)."""
        where = [self.file]
        if self.id != "-":
            where.append(self.id)
        if self.field != "-":
            where.append(f"field '{self.field}'")
        return ": ".join([*where, self.message])


class CatalogError(Exception):
    """The catalog is invalid; ``problems`` holds one line per problem."""

    def __init__(self, problems: list[Problem]) -> None:
        self.problems = sorted(set(problems))
        super().__init__("\n".join(str(p) for p in self.problems))


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, strict=True, ser_json_inf_nan="strings")


class ClaimRef(_Strict):
    """``{ claim = "ID" }`` in ``args``: that claim's value."""

    claim: Text


class SymbolRef(_Strict):
    """``{ symbol = "A" }`` in a formula claim's ``args``: the formula's symbol A."""

    symbol: Text


ArgValue = TypeAliasType(
    "ArgValue",
    "int | float | str | ClaimRef | SymbolRef | list[ArgValue]",
)


class SymbolSpec(_Strict):
    """A formula symbol's sympy assumptions and, optionally, the domain its generic points
    are drawn from."""

    real: bool | None = None
    positive: bool | None = None
    negative: bool | None = None
    nonnegative: bool | None = None
    nonzero: bool | None = None
    integer: bool | None = None
    complex: bool | None = None
    domain: Annotated[list[float], Field(min_length=2, max_length=2)] | None = None


class TokenRef(_Strict):
    """A number token a formula claim covers: its line, its text and which occurrence."""

    line: Line
    token: Text
    occurrence: Annotated[int, Field(ge=1)] | None = None


class Diagnosis(_Strict):
    """The curator's diagnosis of an erratum."""

    kind: DiagnosisKind
    note: Text


class Assumption(_Strict):
    """An input the book does not state, as a table: its value (a string keeps the digits that
    give a rounded value its precision), whether it is rounded, and why it is what it is."""

    value: int | float | str
    rounded: bool = False
    reason: Text


class Claim(_Strict):
    """One numeric claim of the book."""

    id: Annotated[str, StringConstraints(pattern=r"^ch(\d\d|A1)\.[A-Za-z0-9][\w.\-]*$")]
    line: Line
    quote: Text
    printed: Text | None = None
    quantity: Text
    kind: Kind
    expect: Expect
    occurrence: Annotated[int, Field(ge=1)] | None = None
    line_end: Line | None = None
    means: Text | None = None
    garble: Garble | None = None
    unit: Text = "1"
    model: Annotated[str, StringConstraints(pattern=r"^[a-z_]+\.[a-z_][a-z0-9_]*$")] | None = None
    args: dict[str, ArgValue] = Field(default_factory=dict)
    pick: str = ""
    rounded: bool = False
    constant: Text | None = None
    relation: Relation = "="
    rel_tol: Annotated[float, Field(gt=0, le=0.25)] | None = None
    bounds: Annotated[list[Text], Field(min_length=2, max_length=2)] | None = None
    sigfigs: Annotated[int, Field(ge=1)] | None = None
    precision_reason: Text | None = None
    restates: Text | None = None
    assumptions: dict[str, int | float | str | Assumption] = Field(default_factory=dict)
    rounding: Literal["truncation"] | None = None
    exact: bool = False
    monotonic: bool | None = None
    expression: Text | None = None
    symbols: dict[str, SymbolSpec] = Field(default_factory=dict)
    tokens: list[TokenRef] = Field(default_factory=list)
    edition: Text | None = None
    same_error: Text | None = None
    summary: Text | None = None
    correct: Text | None = None
    reads: Text | None = None  # the quote as it should read, for a correction in words
    diagnosis: Diagnosis | None = None
    figure: Text | None = None
    equation: Text | None = None
    note: Text | None = None
    depends_on: list[Text] = Field(default_factory=list)


class Excluded(_Strict):
    """A hand exclusion: one token (line, token, occurrence) or a symbolic range of lines.

    ``restates ID`` and ``part-of ID`` exclusions may say the unit the token is printed in and,
    with ``means``, the number it stands for (a garbled token, or for ``part-of`` the whole
    number the piece belongs to, as printed: "π/6"); ``checks/`` tests that they agree with the
    claim they name."""

    reason: Text
    line: Line | None = None
    token: Text | None = None
    occurrence: Annotated[int, Field(ge=1)] | None = None
    lines: Annotated[list[Line], Field(min_length=2, max_length=2)] | None = None
    unit: Text | None = None
    means: Text | None = None


class Slip(_Strict):
    """A non-numeric slip: a wrong label or equation reference; listed apart from errata."""

    id: Annotated[str, StringConstraints(pattern=r"^ch(\d\d|A1)\.[A-Za-z0-9][\w.\-]*$")]
    line: Line
    quote: Text
    printed: Text
    correct: Text
    note: Text


class Meta(_Strict):
    """A chapter file's header."""

    chapter: Text
    title: Text
    lines: Annotated[list[Line], Field(min_length=2, max_length=2)]
    complete: bool
    schema_: Literal[1] = Field(alias="schema")


class ChapterFileSchema(_Strict):
    """One catalog file as a whole: its header and its entries (for the JSON Schema)."""

    meta: Meta
    claim: list[Claim] = Field(default_factory=list)
    excluded: list[Excluded] = Field(default_factory=list)
    slip: list[Slip] = Field(default_factory=list)


def json_schema() -> dict[str, object]:
    """The JSON Schema of a catalog file (``reference/claims/chNN.toml`` read as TOML), from
    these models: ``docs/catalog.schema.json`` is this, and a test keeps it so."""
    schema = ChapterFileSchema.model_json_schema(by_alias=True)
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "bangcheck catalog file (schema 1, revision 2)"
    return schema
