"""The book's identity (reference/book.toml) against the text, and clear errors for a wrong book."""

from __future__ import annotations

import hashlib
import itertools
import os
from pathlib import Path

import pytest

from reference.book import (
    LINE_DIGEST_SIZE,
    Book,
    BookError,
    book_path,
    chapter_keys,
    identity,
    known_line_digests,
    line_digests,
    load_book,
)
from reference.evaluation import evaluate


@pytest.mark.integrity
def test_identity_matches_the_text(book: Book) -> None:
    ident = identity()
    data = book.path.read_bytes()
    assert hashlib.sha256(data).hexdigest() == ident.sha256
    assert len(data.decode("utf-8").split("\n")) == ident.lines == 16964
    assert not data.endswith(b"\n")


@pytest.mark.integrity
def test_the_shipped_line_digests_are_the_books(book: Book) -> None:
    """``reference/book-lines.b2``, which tells a user which lines of their file differ, is the
    digest of every line of the book, in order."""
    assert known_line_digests() == tuple(
        line_digests([line])[:LINE_DIGEST_SIZE] for line in book.lines
    )
    assert len(set(known_line_digests())) == len(set(book.lines))  # no two lines share one


@pytest.mark.integrity
def test_section_headings_are_on_their_lines(book: Book) -> None:
    """The section table of book.toml (the errata's locations) against the text: each heading
    is on its line, in book order, and every chapter opens with one."""
    sections = identity().sections
    assert len(sections) > 150
    assert [s.line for s in sections] == sorted({s.line for s in sections})
    for section in sections:
        assert section.heading in book.line(section.line), (section.line, section.heading)
    starts = {s.line for s in sections}
    assert all(c.start in starts for c in identity().chapters if c.key != "0")
    found = identity().section_of(6562)
    assert found is not None
    assert found.heading == "Geometric properties of N-stage collisions"


@pytest.mark.integrity
def test_chapter_starts_are_their_headings(book: Book) -> None:
    for chapter in identity().chapters:
        first = book.line(chapter.start).strip()
        assert first.startswith(chapter.heading), (chapter.key, first)
        after = first[len(chapter.heading) : len(chapter.heading) + 1]
        assert not after.isdigit(), (chapter.key, first)


def test_chapters_tile_the_book() -> None:
    chapters = identity().chapters
    assert chapters[0].start == 1
    assert chapters[-1].end == identity().lines
    for before, after in itertools.pairwise(chapters):
        assert before.end + 1 == after.start


def test_a_changed_book_is_refused(book: Book, tmp_path: Path) -> None:
    copy = tmp_path / "bang-unit1.txt"
    copy.write_bytes(book.path.read_bytes().replace(b"V3=3.62", b"V3=3.65", 1))
    with pytest.raises(BookError, match="not the book the catalog cites"):
        load_book(copy)


def test_a_missing_book_is_refused(tmp_path: Path) -> None:
    with pytest.raises(BookError, match="cannot read the book"):
        load_book(tmp_path / "nowhere.txt")


def test_no_book_given(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("BANGCHECK_BOOK", raising=False)
    with pytest.raises(BookError, match="--book PATH or set BANGCHECK_BOOK"):
        book_path(None)


def test_evaluate_without_a_book_says_how_from_python(monkeypatch: pytest.MonkeyPatch) -> None:
    """``reference.evaluate()`` is called from Python: its error names its argument, not the
    command line's ``--book``."""
    monkeypatch.delenv("BANGCHECK_BOOK", raising=False)
    with pytest.raises(BookError, match=r"evaluate\(book=PATH\) or set BANGCHECK_BOOK"):
        evaluate()


def test_a_relative_path_is_made_absolute(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("BANGCHECK_BOOK", "book.txt")
    assert book_path(None) == Path("book.txt").resolve()
    assert book_path("other.txt") == Path("other.txt").resolve()


@pytest.mark.parametrize(
    ("spec", "keys"),
    [
        ("8", ("8",)),
        ("0-3", ("0", "1", "2", "3")),
        ("4,5", ("4", "5")),
        ("A1", ("A1",)),
        ("12-A1", ("12", "A1")),
        ("a1", ("A1",)),
        ("04", ("4",)),
        (" 08 - 09 ", ("8", "9")),
        ("12-a1", ("12", "A1")),
        (None, tuple(c.key for c in identity().chapters)),
        (["7", "0", "04"], ("0", "4", "7")),
        (("0-2", "a1"), ("0", "1", "2", "A1")),
        ([8, 12], ("8", "12")),
        (8, ("8",)),
    ],
)
def test_chapter_specs(
    spec: str | int | list[str] | tuple[str, ...] | list[int] | None, keys: tuple[str, ...]
) -> None:
    assert chapter_keys(spec) == keys


@pytest.mark.parametrize(
    "spec", ["13", "3-1", "x", "1-B2", "", "  ", "4,", "-3", [], ["4", ""], 13, -3]
)
def test_bad_chapter_specs(spec: str | int | list[str]) -> None:
    with pytest.raises(ValueError, match="chapter") as error:
        chapter_keys(spec)
    assert "['" not in str(error.value)  # the chapters listed as people write them, no repr


@pytest.mark.parametrize("spec", [8.0, True, object()])
def test_a_chapter_that_is_no_spec_number_or_list_is_a_type_error(spec: object) -> None:
    with pytest.raises(TypeError, match="chapters: give a spec"):
        chapter_keys(spec)  # type: ignore[arg-type]  # on purpose


def test_a_pipe_or_a_device_is_no_book(tmp_path: Path) -> None:
    pipe = tmp_path / "pipe"
    os.mkfifo(pipe)
    with pytest.raises(BookError, match="not a regular file"):
        load_book(pipe)  # refused at once, never opened (reading it would wait forever)
    with pytest.raises(BookError, match="not a regular file"):
        load_book(Path("/dev/zero"))  # never read (it would fill the memory)
