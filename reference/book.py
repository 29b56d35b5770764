"""The book under test: where it is, whether it is the right file, and its chapters.

The identity (sha256, line count, chapter starts) is data in ``reference/book.toml``. Line N is
the N-th element of the text split on "\\n" (the file ends without a newline), so line numbers
here are the citation keys of the catalog.
"""

from __future__ import annotations

import bisect
import hashlib
import os
import stat
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cache
from importlib.resources import files
from pathlib import Path

import tomli

BOOK_ENV = "BANGCHECK_BOOK"
LINE_DIGESTS = "book-lines.b2"  # package data: the known book's line digests
LINE_DIGEST_SIZE = 4  # bytes per line: a chance changed line goes unseen once in 4 billion
MAX_BOOK_BYTES = 16 * 2**20  # the book is 0.4 MB: a file this large is read no further


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
class Section:
    """A section heading of the book: its line, its text and its level."""

    line: int
    heading: str
    level: str


@dataclass(frozen=True)
class Identity:
    """What ``reference/book.toml`` says the book is."""

    sha256: str
    lines: int
    title: str
    chapters: tuple[Chapter, ...]
    sections: tuple[Section, ...] = ()

    def chapter(self, key: str) -> Chapter:
        for chapter in self.chapters:
            if chapter.key == key:
                return chapter
        raise KeyError(key)

    def section_of(self, line: int) -> Section | None:
        """The section a line is in: the last heading at or before it (None before the
        first)."""
        index = bisect.bisect_right([s.line for s in self.sections], line) - 1
        return self.sections[index] if index >= 0 else None


@cache
def identity() -> Identity:
    """The book's identity, read once from the package data ``reference/book.toml``."""
    data = tomli.loads(files("reference").joinpath("book.toml").read_text(encoding="utf-8"))
    rows = data["chapter"]
    chapters = []
    for i, row in enumerate(rows):
        end = rows[i + 1]["start"] - 1 if i + 1 < len(rows) else data["lines"]
        chapters.append(Chapter(row["key"], row["start"], end, row["title"], row["heading"]))
    sections = tuple(
        Section(row["line"], row["heading"], row["level"]) for row in data.get("section", [])
    )
    return Identity(data["sha256"], data["lines"], data["title"], tuple(chapters), sections)


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


def book_path(
    cli_value: str | os.PathLike[str] | None = None, given_as: str = "pass --book PATH"
) -> Path:
    """The book's path from ``--book`` or else ``$BANGCHECK_BOOK``, made absolute once;
    ``given_as`` is how the caller's user gives it, for the error when neither is set."""
    value = cli_value if cli_value else os.environ.get(BOOK_ENV)
    if not value:
        raise BookError(f"no book given: {given_as} or set {BOOK_ENV}")
    return Path(value).expanduser().resolve()


def line_digests(lines: Sequence[str]) -> bytes:
    """Each line's ``LINE_DIGEST_SIZE``-byte BLAKE2b digest, concatenated: the form in which the
    package ships the known book's lines (``reference/book-lines.b2``), so that a different file
    can be told apart line by line without shipping the text."""
    return b"".join(
        hashlib.blake2b(line.encode("utf-8"), digest_size=LINE_DIGEST_SIZE).digest()
        for line in lines
    )


@cache
def known_line_digests() -> tuple[bytes, ...]:
    """The known book's line digests (package data ``reference/book-lines.b2``), one per line."""
    data = files("reference").joinpath(LINE_DIGESTS).read_bytes()
    size = LINE_DIGEST_SIZE
    return tuple(data[i : i + size] for i in range(0, len(data), size))


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _line_list(numbers: Sequence[int], shown: int = 5) -> str:
    listed = ", ".join(str(n) for n in numbers[:shown])
    more = len(numbers) - shown
    return f"{listed} and {more} more" if more > 0 else listed


def describe_difference(data: bytes, ident: Identity) -> str:
    """How ``data`` differs from the known book, in one clause a user can act on: empty, CRLF
    line ends, a final newline, another line count, or which lines differ."""
    if not data:
        return "the file is empty"
    if data.replace(b"\r\n", b"\n") != data:
        crlf = data.count(b"\r\n")
        if _sha256(data.replace(b"\r\n", b"\n")) == ident.sha256:
            return (
                f"it is the book with Windows (CRLF) line ends on {crlf:,} lines; "
                "convert them to LF (e.g. dos2unix)"
            )
        hint = f"it has Windows (CRLF) line ends on {crlf:,} lines, and more differs"
    else:
        hint = ""
    if data.endswith(b"\n") and _sha256(data.rstrip(b"\n")) == ident.sha256:
        return "it is the book with newline(s) added at the end (the book ends without one)"
    if data.startswith(b"\xef\xbb\xbf") and _sha256(data[3:]) == ident.sha256:
        return "it is the book with a byte-order mark added at the start"
    text = data.decode("utf-8").replace("\r\n", "\n")
    lines = text.split("\n")
    if text.endswith("\n"):  # a final newline ends the last line: it starts no new one
        lines.pop()
    known = known_line_digests()
    mine = line_digests(lines)
    size = LINE_DIGEST_SIZE
    differ = [
        i + 1
        for i in range(min(len(lines), len(known)))
        if mine[i * size : (i + 1) * size] != known[i]
    ]
    parts = [hint] if hint else []
    if len(lines) != ident.lines:
        count = f"{len(lines):,} line{'' if len(lines) == 1 else 's'}"
        parts.append(f"it has {count}, the book {ident.lines:,}")
        if differ:
            parts.append(f"the first line that differs is line {differ[0]}")
        elif len(lines) < ident.lines:
            first = (
                "it is the book's first line"
                if len(lines) == 1
                else f"they are the book's first {len(lines):,}"
            )
            parts.append(f"{first}: the rest is missing")
        else:
            parts.append(f"the book's lines are all there, {len(lines) - ident.lines:,} more after")
    elif differ:
        if len(differ) == 1:
            parts.append(f"line {differ[0]} differs from the book's")
        else:
            parts.append(f"{len(differ):,} lines differ from the book's: {_line_list(differ)}")
    return "; ".join(parts) or "its bytes differ from the book's"


@cache
def load_book(path: Path) -> Book:
    """Read the book at ``path`` and check it is the file ``reference/book.toml`` describes;
    ``BookError`` says how a different file differs."""
    ident = identity()
    try:
        mode = path.stat().st_mode
        if not stat.S_ISREG(mode):
            raise BookError(f"{path} is not a regular file, so not the book")
        size = path.stat().st_size
        if size > MAX_BOOK_BYTES:
            raise BookError(f"{path} holds {size:,} bytes, far more than the book: not the book")
        data = path.read_bytes()
    except OSError as err:
        raise BookError(f"cannot read the book at {path}: {err.strerror or err}") from err
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as err:
        raise BookError(f"{path} is not UTF-8 text, so not the book: {err}") from err
    lines = tuple(text.split("\n"))
    if _sha256(data) != ident.sha256 or len(lines) != ident.lines:
        raise BookError(
            f"{path} is not the book the catalog cites: {describe_difference(data, ident)}"
        )
    return Book(path, lines, ident)


def chapter_keys(spec: str | int | Iterable[str | int] | None) -> tuple[str, ...]:
    """The chapter keys selected by a ``--chapter`` spec ("8", "0-3", "4,5", "A1"; None: all),
    or by several specs (["0", "4", "7"]); from Python a chapter number (8) or a list of them
    ([0, 4, 7]) too.

    Leading zeros and the case of "A1" do not matter ("04", "a1"). Raises ``ValueError`` naming
    the part of the spec it cannot read, or for an empty spec, and ``TypeError`` for anything
    that is not a spec, a number or a list of them (8.0).
    """
    keys = [c.key for c in identity().chapters]
    listed = ", ".join(keys)
    if spec is None:
        return tuple(keys)
    if isinstance(spec, int) and not isinstance(spec, bool):
        spec = str(spec)
    elif isinstance(spec, Iterable) and not isinstance(spec, str):
        spec = ",".join(map(str, spec))  # a list of specs, or of chapter numbers [0, 4, 7]
    if not isinstance(spec, str):
        raise TypeError(
            f"chapters: give a spec (8, '0-3', '4,5', 'A1'), a chapter number or a list of them, "
            f"not {spec!r}"
        )
    if not spec.strip():
        raise ValueError(f"empty chapter spec: give e.g. 8, 0-3, 4,5 or A1 (chapters {listed})")
    chosen: list[str] = []
    for part in spec.split(","):
        part = part.strip()
        if not part:
            raise ValueError(
                f"empty part in chapter spec {spec!r}: give e.g. 8, 0-3, 4,5 or A1 "
                f"(chapters {listed})"
            )
        lo, sep, hi = part.partition("-")
        if sep:
            lo, hi = _chapter_key(lo), _chapter_key(hi)
            if lo not in keys or hi not in keys or keys.index(lo) > keys.index(hi):
                raise ValueError(f"bad chapter range {part!r}: use e.g. 0-3 (chapters {listed})")
            chosen.extend(keys[keys.index(lo) : keys.index(hi) + 1])
        elif _chapter_key(part) in keys:
            chosen.append(_chapter_key(part))
        else:
            raise ValueError(f"unknown chapter {part!r}: chapters are {listed}")
    return tuple(k for k in keys if k in chosen)


def _chapter_key(text: str) -> str:
    """A chapter as typed ("04", "a1", " 8") in the catalog's spelling ("4", "A1", "8")."""
    text = text.strip().upper()
    return str(int(text)) if text.isdigit() else text
