"""The catalog's rules beyond single fields: against each other, mechmodel and the book.

Every problem is one ``Problem`` line (file, claim id, field). ``validate`` returns them all;
``checked_catalog`` raises ``CatalogError`` if there is any; checks/test_catalog_errors.py feeds
each rule a bad entry. The rules for each entry on its own are ``reference.claim_rules``
(re-exported here: ``parsed``, ``occurrences``, ...); here are those across claims: references
to known claims that state a value, no cycles, a restatement's unit, ``same_error`` naming the
first erratum of its error, givens that some claim uses, no unmodeled claim in a complete chapter.
"""

from __future__ import annotations

from collections.abc import Iterator
from importlib.resources.abc import Traversable
from pathlib import Path

from reference.book import Book
from reference.catalog import Catalog, ChapterFile, read_catalog
from reference.claim_rules import (
    HEDGES,
    ClaimRules,
    occurrences,
    parsed,
    short_exact,
    superscript_ok,
)
from reference.schema import CatalogError, Claim, ClaimRef, Problem
from reference.tables import NO_CONVERSION

__all__ = [
    "HEDGES",
    "checked_catalog",
    "claim_refs",
    "occurrences",
    "parsed",
    "references",
    "short_exact",
    "superscript_ok",
    "validate",
]


def claim_refs(value: object) -> Iterator[str]:
    """Every ``{ claim = ID }`` inside an ``args`` value."""
    if isinstance(value, ClaimRef):
        yield value.claim
    elif isinstance(value, list):
        for item in value:
            yield from claim_refs(item)


def references(claim: Claim) -> list[str]:
    """The ids a claim uses: in ``args`` and ``restates``."""
    out = [ref for value in claim.args.values() for ref in claim_refs(value)]
    if claim.restates:
        out.append(claim.restates)
    return out


class _Checker(ClaimRules):
    """All the rules: each entry's own (``ClaimRules``) and those across the catalog."""

    # -- across the catalog ---------------------------------------------------------------
    def unknown(self, ref: str) -> str:
        """The problem of a reference to no claim: in a catalog directory that lacks the file
        of the claim's chapter (a draft of some chapters), say which file to add."""
        stem = ref.split(".", 1)[0]
        if stem not in {f.stem for f in self.catalog.files}:
            return (
                f"refers to {ref!r} of {stem}.toml, a file this catalog directory does not "
                f"hold (a draft needs the files its claims refer to: copy {stem}.toml too)"
            )
        return f"refers to an unknown claim {ref!r}"

    def check_links(self) -> None:
        by_id = self.catalog.by_id()
        file_of = self.catalog.file_of()
        used: set[str] = set()
        for f, c in self.catalog.claims():
            for ref in references(c):
                used.add(ref)
                if ref not in by_id and ref not in self.catalog.rejected:
                    field = "restates" if ref == c.restates else "args"
                    self.add(f, c.id, field, self.unknown(ref))
                elif ref == c.id:
                    self.add(f, c.id, "args", "a claim cannot refer to itself")
                elif ref in by_id and ref != c.restates and by_id[ref].relation != "=":
                    self.add(
                        f,
                        c.id,
                        "args",
                        f"refers to {ref}, a bound ({by_id[ref].relation!r}), not a value: model "
                        "the bounded quantity from its own inputs (design 3a)",
                    )
            restated = by_id.get(c.restates or "")
            if restated is not None and restated.unit != c.unit:
                dimensionless = sorted({c.unit, restated.unit} & set(NO_CONVERSION))
                if dimensionless:
                    self.add(
                        f,
                        c.id,
                        "unit",
                        f"is {c.unit!r} but the restated {restated.id} is in "
                        f"{restated.unit!r}: {'/'.join(dimensionless)} values cannot be "
                        "converted to or from a physical unit",
                    )
            if c.same_error is not None:
                self.check_same_error(f, c, by_id.get(c.same_error))
            for dep in c.depends_on:
                if dep not in by_id and dep not in self.catalog.rejected:
                    self.add(f, c.id, "depends_on", f"unknown claim {dep!r}")
        for f, c in self.catalog.claims():
            # a rejected entry may be the one that references a given: judge only a whole catalog
            unreferenced = c.id not in used and not self.catalog.rejected
            if c.kind == "given" and unreferenced and c.restates is None:
                self.add(f, c.id, "kind", "a given that no claim references (args or restates)")
            if (
                f.meta.complete
                and c.kind in ("derived", "identity", "count")
                and c.model is None
                and c.restates is None
            ):
                self.add(f, c.id, "model", "unmodeled claim in a chapter marked complete")
        self.check_cycles(by_id, file_of)

    def check_same_error(self, f: ChapterFile, c: Claim, first: Claim | None) -> None:
        """``same_error`` names the first erratum of the error: an erratum of an earlier line
        (or the same line), itself naming no other (no chains)."""
        add = lambda msg: self.add(f, c.id, "same_error", msg)  # noqa: E731
        if first is None:
            if c.same_error is not None and c.same_error not in self.catalog.rejected:
                add(self.unknown(c.same_error))
        elif first.expect != "erratum" or first.id == c.id:
            add(f"{first.id} is not another erratum")
        elif first.same_error is not None:
            add(f"{first.id} names {first.same_error} in turn: name the first claim, no chains")
        elif (first.line, first.id) > (c.line, c.id) and first.line != c.line:
            add(f"{first.id} is later in the book (line {first.line}): the first claim names none")

    def check_cycles(self, by_id: dict[str, Claim], file_of: dict[str, ChapterFile]) -> None:
        state: dict[str, int] = {}

        def visit(ident: str, trail: list[str]) -> None:
            if state.get(ident) == 2 or ident not in by_id:
                return
            if state.get(ident) == 1:
                cycle = " -> ".join([*trail[trail.index(ident) :], ident])
                self.add(file_of[ident], ident, "args", f"circular references: {cycle}")
                return
            state[ident] = 1
            for ref in references(by_id[ident]):
                visit(ref, [*trail, ident])
            state[ident] = 2

        for ident in by_id:
            visit(ident, [])

    def run(self) -> list[Problem]:
        for f in self.catalog.files:
            if not self.check_file(f):
                continue
            for c in f.claims:
                self.check_claim(f, c)
            for e in f.excluded:
                self.check_excluded(f, e)
            for s in f.slips:
                self.check_slip(f, s)
        self.check_links()
        return sorted(set(self.problems))


def validate(catalog: Catalog, book: Book | None) -> list[Problem]:
    """Every problem of ``catalog``; text checks (quotes, tokens) only when ``book`` is given."""
    return _Checker(catalog, book).run()


def checked_catalog(book: Book | None, directory: Traversable | Path | None = None) -> Catalog:
    """Read and validate the catalog; ``CatalogError`` with one line per problem, the schema's
    and the rules' together."""
    catalog, problems = read_catalog(directory)
    problems = problems + validate(catalog, book)
    if problems:
        raise CatalogError(problems)
    return catalog
