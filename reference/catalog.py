"""Reading the catalog: ``reference/claims/chNN.toml`` and ``chA1.toml``, one file per chapter.

``read_catalog`` parses every file and checks each entry against the schema (it does not need
the book), keeping the entries that pass with a list of the problems of those that do not.
``reference.validate`` then checks the entries against each other, the model and the text, and
``checked_catalog`` raises every problem found, one line each (file, claim id, field), in a
``CatalogError``.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from functools import cached_property, lru_cache
from importlib.resources import files
from importlib.resources.abc import Traversable
from pathlib import Path
from typing import Any

import tomli
from pydantic import BaseModel, ValidationError

from reference.schema import Claim, Excluded, Meta, Problem, Slip

CLAIMS_PACKAGE_DIR = "claims"


@dataclass(frozen=True)
class ChapterFile:
    """One catalog file: its name, header, claims, hand exclusions and slips."""

    name: str
    stem: str
    meta: Meta
    claims: tuple[Claim, ...]
    excluded: tuple[Excluded, ...]
    slips: tuple[Slip, ...]


@dataclass(frozen=True)
class Catalog:
    """All chapter files, in book order; ``rejected`` holds the ids of entries that failed the
    schema (so that references to them are not reported a second time as unknown)."""

    files: tuple[ChapterFile, ...]
    rejected: frozenset[str] = frozenset()

    @property
    def chapters(self) -> tuple[str, ...]:
        """The chapters the catalog has files for, in book order (a draft may hold some)."""
        return tuple(f.meta.chapter for f in self.files)

    def claims(self) -> Iterator[tuple[ChapterFile, Claim]]:
        """Every claim with the file that holds it, in file order then line order."""
        for chapter_file in self.files:
            for claim in chapter_file.claims:
                yield chapter_file, claim

    @cached_property
    def _claims_by_id(self) -> dict[str, Claim]:
        return {claim.id: claim for _, claim in self.claims()}

    @cached_property
    def _files_by_id(self) -> dict[str, ChapterFile]:
        return {claim.id: f for f, claim in self.claims()}

    def by_id(self) -> dict[str, Claim]:
        """Claims by id (ids are unique in a valid catalog; a shared dict: do not modify)."""
        return self._claims_by_id

    def file_of(self) -> dict[str, ChapterFile]:
        """The file of each claim id (a shared dict: do not modify)."""
        return self._files_by_id


def default_directory() -> Traversable:
    """The catalog shipped with the package: ``reference/claims``."""
    return files("reference").joinpath(CLAIMS_PACKAGE_DIR)


class CatalogDirectoryError(ValueError):
    """A catalog directory given by the user that is missing or holds no catalog files."""


def display_name(path: Traversable | Path, packaged: bool) -> str:
    """How problem lines name a catalog file: ``reference/claims/ch08.toml`` for the packaged
    catalog, else the path as the user gave its directory (``draft/ch08.toml``)."""
    return f"reference/{CLAIMS_PACKAGE_DIR}/{path.name}" if packaged else str(path)


def catalog_paths(directory: Traversable | Path | None = None) -> list[Traversable | Path]:
    """The ``ch*.toml`` files of ``directory`` (default: the packaged catalog), by name.

    A directory given by the user that is missing, not a directory or holds no such file raises
    ``CatalogDirectoryError`` (a draft catalog needs at least one chapter file).
    """
    root = directory if directory is not None else default_directory()
    if directory is not None and not root.is_dir():
        raise CatalogDirectoryError(f"--catalog {directory}: not a directory")
    paths = sorted(
        (p for p in root.iterdir() if p.name.startswith("ch") and p.name.endswith(".toml")),
        key=lambda p: p.name,
    )
    if not paths and directory is not None:
        hint = ""
        if isinstance(root, Path) and (root / CLAIMS_PACKAGE_DIR).is_dir():
            hint = f" (did you mean {root / CLAIMS_PACKAGE_DIR}?)"
        raise CatalogDirectoryError(
            f"--catalog {directory}: holds no catalog files (ch00.toml ... ch12.toml, "
            f"chA1.toml){hint}"
        )
    return paths


def _entry_problems(name: str, ident: str, err: ValidationError) -> list[Problem]:
    out = []
    for e in err.errors():
        field = ".".join(str(part) for part in e["loc"] if not isinstance(part, int)) or "-"
        if e["type"] == "missing":
            message = "required field is missing"
        elif e["type"] == "extra_forbidden":
            message = "unknown field (not in schema 1)"
        else:
            message = e["msg"]
        out.append(Problem(name, ident, field, message))
    return out


def _entries(
    name: str,
    raw: dict[str, Any],
    table: str,
    model: type[BaseModel],
    problems: list[Problem],
    rejected: set[str],
) -> tuple:
    rows = raw.get(table, [])
    if not isinstance(rows, list):
        problems.append(Problem(name, "-", table, f"[[{table}]] must be an array of tables"))
        return ()
    out = []
    for i, row in enumerate(rows, start=1):
        ident = row.get("id") if isinstance(row.get("id"), str) else None
        if ident is None:
            line = row.get("line", row.get("lines", "?"))
            ident = f"{table} #{i} (line {line})"
        try:
            out.append(model.model_validate(row))
        except ValidationError as err:
            problems.extend(_entry_problems(name, ident, err))
            rejected.add(ident)
    return tuple(out)


@dataclass(frozen=True)
class ParsedFile:
    """What one catalog file's text gives: the file (None when it cannot be read at all), its
    schema problems and the ids of the entries that failed."""

    chapter_file: ChapterFile | None
    problems: tuple[Problem, ...]
    rejected: frozenset[str]


def _read_text(path: Traversable | Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as err:
        raise CatalogDirectoryError(f"cannot read the catalog file {path}: {err}") from err


@lru_cache(maxsize=64)
def parse_file(name: str, text: str) -> ParsedFile:
    """Parse one catalog file's text and check each entry against the schema.

    Cached on the text itself, so a run that reads the catalog many times (the tests, each
    command they call) parses and builds each unchanged file once; an edited file is parsed
    anew. The result is immutable.
    """
    problems: list[Problem] = []
    rejected: set[str] = set()
    try:
        raw = tomli.loads(text)
    except tomli.TOMLDecodeError as err:
        problems.append(Problem(name, "-", "-", f"not valid TOML: {err}"))
        return ParsedFile(None, tuple(problems), frozenset())
    unknown = set(raw) - {"meta", "claim", "excluded", "slip"}
    for table in sorted(unknown):
        problems.append(
            Problem(name, "-", table, "unknown table (schema 1 has meta, claim, excluded, slip)")
        )
    try:
        meta = Meta.model_validate(raw.get("meta"))
    except ValidationError as err:
        problems.extend(_entry_problems(name, "meta", err))
        return ParsedFile(None, tuple(problems), frozenset())
    claims = _entries(name, raw, "claim", Claim, problems, rejected)
    excluded = _entries(name, raw, "excluded", Excluded, problems, rejected)
    slips = _entries(name, raw, "slip", Slip, problems, rejected)
    stem = name.rsplit("/", 1)[-1].removesuffix(".toml")
    chapter_file = ChapterFile(name, stem, meta, claims, excluded, slips)
    return ParsedFile(chapter_file, tuple(problems), frozenset(rejected))


def read_catalog(
    directory: Traversable | Path | None = None,
) -> tuple[Catalog, list[Problem]]:
    """Parse every ``ch*.toml`` of ``directory`` (default: the packaged catalog), keeping the
    entries that pass the schema, and return them with the schema problems found; problems
    name each file as ``display_name`` does. ``CatalogDirectoryError`` as ``catalog_paths``."""
    packaged = directory is None
    parsed = [
        parse_file(display_name(p, packaged), _read_text(p)) for p in catalog_paths(directory)
    ]
    problems = [problem for f in parsed for problem in f.problems]
    rejected = frozenset().union(*(f.rejected for f in parsed))
    chapter_files = tuple(f.chapter_file for f in parsed if f.chapter_file is not None)
    return Catalog(chapter_files, rejected), problems
