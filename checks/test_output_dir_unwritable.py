"""``bangcheck report --out``: a user's files are never lost (``reports/outdir.py``).

An unwritable place is one line and exit 2, with the previous report intact and no parents
left behind.
"""

from __future__ import annotations

import errno
import os
import tempfile
from pathlib import Path

import pytest

from checks._output_dir_helpers import FILES, report, tree
from reference.book import Book
from reports import outdir
from reports.outdir import OutputError, write_report_dir

pytestmark = pytest.mark.integrity


# -- unwritable output ------------------------------------------------------------------------


def test_a_parent_that_cannot_be_made_is_one_line(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "file.txt").write_text("t", encoding="utf-8")
    code, err = report(capsys, book, tmp_path / "file.txt" / "out")
    assert code == 2
    assert err.splitlines() == [
        f"bangcheck: error: --out {tmp_path / 'file.txt' / 'out'}: cannot be made, "
        f"{tmp_path / 'file.txt'} is a file"
    ]


@pytest.mark.parametrize(
    ("where", "code", "shown"),
    [
        ("mkdtemp", errno.EROFS, "read-only file system"),
        ("mkdtemp", errno.EACCES, "Permission denied"),
        ("write", errno.ENOSPC, "No space left on device"),
        ("rename", errno.EACCES, "Permission denied"),
    ],
)
def test_unwritable_output_is_one_line_and_keeps_the_previous_report(
    tmp_path: Path,
    book: Book,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    where: str,
    code: int,
    shown: str,
) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    before = tree(out)

    def fail(*args: object, **kwargs: object) -> None:
        raise OSError(code, os.strerror(code), str(out))

    if where == "mkdtemp":
        monkeypatch.setattr(tempfile, "mkdtemp", fail)
    elif where == "write":
        monkeypatch.setattr(outdir, "_fsync", fail)
    else:
        monkeypatch.setattr(outdir, "_swap_in", lambda staging, target, log: fail())
    exit_code, err = report(capsys, book, out)
    assert exit_code == 2
    assert err.splitlines()[-1].startswith(f"bangcheck: error: cannot write the report to {out}")
    assert shown in err.splitlines()[-1]
    assert "Traceback" not in err
    assert tree(out) == before
    assert sorted(os.listdir(tmp_path)) == ["out"]
    if where == "mkdtemp":  # found before the work: the catalog was not even evaluated
        assert err.splitlines() == [err.splitlines()[-1]]


@pytest.mark.parametrize(
    ("code", "shown"),
    [(errno.EACCES, "Permission denied"), (errno.ENOENT, "no directory can be made there")],
)
def test_an_unwritable_place_under_missing_parents_is_said_before_the_work(
    tmp_path: Path,
    book: Book,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    code: int,
    shown: str,
) -> None:
    """``--out`` under directories still to be made, in a place where none can be made: one
    line naming the nearest directory that exists (not a probe's name), before the catalog is
    evaluated, and nothing made."""

    def fail(*args: object, dir: str = "", **kwargs: object) -> None:
        raise OSError(code, os.strerror(code), os.path.join(dir, ".bangcheck-probe-x"))

    monkeypatch.setattr(tempfile, "mkdtemp", fail)
    out = tmp_path / "a" / "b" / "out"
    exit_code, err = report(capsys, book, out)
    assert exit_code == 2
    assert err.splitlines() == [
        f"bangcheck: error: cannot write the report to {out}: {shown} ({tmp_path}); the "
        "previous report, if any, is unchanged"
    ]
    assert os.listdir(tmp_path) == []


def test_a_failed_second_rename_puts_the_previous_report_back(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    before = tree(out)
    real = Path.rename
    calls = []

    def second_fails(self: Path, target: Path) -> Path:
        calls.append(self.name)
        if len(calls) == 2:
            raise OSError(errno.EIO, "I/O error", str(self))
        return real(self, target)

    monkeypatch.setattr(Path, "rename", second_fails)
    with pytest.raises(OutputError, match="I/O error"):
        write_report_dir(out, {"index.html": "new"}, log=lambda m: None)
    monkeypatch.undo()
    assert tree(out) == before
    assert sorted(os.listdir(tmp_path)) == ["out"]


def test_parents_made_for_a_failed_write_are_removed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def fail(*args: object, **kwargs: object) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(tmp_path))

    monkeypatch.setattr(tempfile, "mkdtemp", fail)
    with pytest.raises(OutputError, match="No space left"):
        write_report_dir(tmp_path / "a" / "b" / "out", FILES, log=lambda m: None)
    assert os.listdir(tmp_path) == []


def test_parents_made_by_another_run_meanwhile_are_theirs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Another run makes ``a`` between this run's look and its ``mkdir``: this run goes on, and
    when its write fails it removes only the parent it made itself (``b``), not theirs."""
    real = Path.mkdir

    def raced(self: Path, *args: object, **kwargs: object) -> None:
        if self == tmp_path / "a" and not self.exists():
            real(self)  # the other run's
            raise FileExistsError(errno.EEXIST, os.strerror(errno.EEXIST), str(self))
        real(self)

    def fail(*args: object, **kwargs: object) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(tmp_path))

    monkeypatch.setattr(Path, "mkdir", raced)
    monkeypatch.setattr(tempfile, "mkdtemp", fail)
    with pytest.raises(OutputError, match="No space left"):
        write_report_dir(tmp_path / "a" / "b" / "out", FILES, log=lambda m: None)
    assert os.listdir(tmp_path) == ["a"]
    assert os.listdir(tmp_path / "a") == []


def test_a_parent_that_cannot_be_locked_is_one_line_before_any_work(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A parent that cannot be opened to lock it (searchable but not readable): the command's
    first check says so in one line, exit 2, before it evaluates anything."""

    def unopenable(directory: Path, log: object = None) -> None:  # as os.open would fail
        raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(directory))

    monkeypatch.setattr(outdir, "locked", unopenable)
    monkeypatch.setattr("reports.cli.evaluate_catalog", lambda *a, **k: pytest.fail("evaluated"))
    code, err = report(capsys, book, tmp_path / "out")
    assert code == 2
    assert err.splitlines() == [
        f"bangcheck: error: cannot write the report to {tmp_path / 'out'}: Permission denied "
        f"({tmp_path}); the previous report, if any, is unchanged"
    ]
