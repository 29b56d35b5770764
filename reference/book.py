"""The book under test: where it is, whether it is the right file, and its chapters.

The identity (sha256, line count, chapter starts) is data in ``reference/book.toml``. Line N is
the N-th element of the text split on "\\n" (the file ends without a newline), so line numbers
here are the citation keys of the catalog.
"""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass
from functools import cache
from importlib.resources import files
from pathlib import Path

import tomli

BOOK_ENV = "BANGCHECK_BOOK"


class BookError(Exception):
    """The book is missing, unreadable or not the file the catalog cites."""


@dataclass(frozen=True)
class Chapter:
    """One chapter of the book: its catalog key ("0".."12", "A1") and its line range."""

    key: str
    start: int
    end: int
    title: str
    heading: str

    @property
    def file_stem(self) -> str:
        """The catalog file of this chapter without suffix: ``ch00`` ... ``ch12``, ``chA1``."""
        return f"ch{self.key.zfill(2)}" if self.key.isdigit() else f"ch{self.key}"

    def __contains__(self, line: int) -> bool:
        return self.start <= line <= self.end


@dataclass(frozen=True)
class Identity:
    """What ``reference/book.toml`` says the book is."""

    sha256: str
    lines: int
    title: str
    chapters: tuple[Chapter, ...]

    def chapter(self, key: str) -> Chapter:
        for chapter in self.chapters:
            if chapter.key == key:
                return chapter
        raise KeyError(key)


@cache
def identity() -> Identity:
    """The book's identity, read once from the package data ``reference/book.toml``."""
    data = tomli.loads(files("reference").joinpath("book.toml").read_text(encoding="utf-8"))
    rows = data["chapter"]
    chapters = []
    for i, row in enumerate(rows):
        end = rows[i + 1]["start"] - 1 if i + 1 < len(rows) else data["lines"]
        chapters.append(Chapter(row["key"], row["start"], end, row["title"], row["heading"]))
    return Identity(data["sha256"], data["lines"], data["title"], tuple(chapters))


@dataclass(frozen=True, eq=False)  # compared and hashed by identity: one Book per file read
class Book:
    """The verified text of the book, one string per line (index 0 is line 1)."""

    path: Path
    lines: tuple[str, ...]
    identity: Identity

    def line(self, number: int) -> str:
        """Line ``number`` (1-based), as printed."""
        if not 1 <= number <= len(self.lines):
            raise IndexError(f"line {number} is outside the book (1..{len(self.lines)})")
        return self.lines[number - 1]


def book_path(cli_value: str | os.PathLike[str] | None = None) -> Path:
    """The book's path from ``--book`` or else ``$BANGCHECK_BOOK``, made absolute once."""
    value = cli_value if cli_value else os.environ.get(BOOK_ENV)
    if not value:
        raise BookError(f"no book given: pass --book PATH or set {BOOK_ENV}")
    return Path(value).expanduser().resolve()


@cache
def load_book(path: Path) -> Book:
    """Read the book at ``path`` and check it is the file ``reference/book.toml`` describes."""
    ident = identity()
    try:
        data = path.read_bytes()
    except OSError as err:
        raise BookError(f"cannot read the book at {path}: {err.strerror or err}") from err
    digest = hashlib.sha256(data).hexdigest()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as err:
        raise BookError(f"{path} is not UTF-8 text, so not the book: {err}") from err
    lines = tuple(text.split("\n"))
    if digest != ident.sha256 or len(lines) != ident.lines:
        raise BookError(
            f"{path} is not the book the catalog cites: sha256 {digest[:12]}... with "
            f"{len(lines)} lines, expected {ident.sha256[:12]}... with {ident.lines} lines"
        )
    return Book(path, lines, ident)


def chapter_keys(spec: str | None) -> tuple[str, ...]:
    """The chapter keys selected by a ``--chapter`` spec ("8", "0-3", "4,5", "A1"; None: all).

    Raises ``ValueError`` naming the part of the spec it cannot read.
    """
    keys = [c.key for c in identity().chapters]
    if spec is None or not spec.strip():
        return tuple(keys)
    chosen: list[str] = []
    for part in spec.split(","):
        part = part.strip()
        lo, sep, hi = part.partition("-")
        if sep:
            if lo not in keys or hi not in keys or keys.index(lo) > keys.index(hi):
                raise ValueError(f"bad chapter range {part!r}: use e.g. 0-3 (chapters {keys})")
            chosen.extend(keys[keys.index(lo) : keys.index(hi) + 1])
        elif part in keys:
            chosen.append(part)
        else:
            raise ValueError(f"unknown chapter {part!r}: chapters are {', '.join(keys)}")
    return tuple(k for k in keys if k in chosen)
