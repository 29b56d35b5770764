"""``bangcheck report --out``: a user's files are never lost (``reports/outdir.py``).

The report writes a directory that is missing, empty or a previous report (one written before
the manifest included), keeps its permissions, removes a previous report file by file, and writes
unlocked where the file system cannot lock.
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

import pytest

from checks._output_dir_helpers import FILES, report, tree
from reference.book import Book
from reports import outdir
from reports.outdir import MANIFEST, manifest_text, write_report_dir

pytestmark = pytest.mark.integrity


# -- what the report may replace --------------------------------------------------------------


def test_a_new_an_empty_and_a_previous_report_directory_are_written(tmp_path: Path) -> None:
    new = tmp_path / "a" / "b" / "new"
    write_report_dir(new, FILES, log=lambda m: None)
    assert tree(new) == {**FILES, MANIFEST: manifest_text(list(FILES))}
    empty = tmp_path / "empty"
    empty.mkdir()
    write_report_dir(empty, FILES, log=lambda m: None)
    assert tree(empty) == tree(new)
    smaller = {"index.html": "<p>second</p>\n"}
    write_report_dir(new, smaller, log=lambda m: None)  # what the first wrote goes
    assert tree(new) == {**smaller, MANIFEST: manifest_text(["index.html"])}


LEGACY = {
    "index.html": "<!doctype html>\n<html>\n<head>\n<title>bangcheck: errata report</title>\n",
    "errata.csv": "id,chapter,line,quantity,printed,correct,model_value,diagnosis_kind\n",
    "claims.json": '{\n "meta": {\n  "bangcheck": "0.1.0",\n',
    "properties.json": '{\n "date": "2026-11-22", "profile": "ci",\n "invariants": []}\n',
}


def test_a_report_written_before_the_manifest_is_replaced(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    for name, text in LEGACY.items():
        (out / name).write_text(text, encoding="utf-8")
    write_report_dir(out, FILES, log=lambda m: None)
    assert tree(out) == {**FILES, MANIFEST: manifest_text(list(FILES))}


def test_the_directory_keeps_its_permissions(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    out.chmod(0o750)
    write_report_dir(out, FILES, log=lambda m: None)
    assert stat.S_IMODE(out.stat().st_mode) == 0o750
    fresh = tmp_path / "fresh"
    write_report_dir(fresh, FILES, log=lambda m: None)
    assert stat.S_IMODE(fresh.stat().st_mode) & 0o055 == 0o055 & ~_umask()  # not mkdtemp's 0700


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_the_command_writes_the_manifest_and_reads_no_properties_in_its_output(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """The report's own directory holds only what it wrote: the invariants the tests record
    live in ``.bangcheck/`` (found from the working directory up), not in ``--out``."""
    monkeypatch.chdir(tmp_path)
    code, _ = report(capsys, book, tmp_path / "out")
    assert code == 0
    names = sorted(os.listdir(tmp_path / "out"))
    assert names == sorted([MANIFEST, "index.html", "errata.csv", "errata.md", "claims.json"])
    assert sorted(os.listdir(tmp_path)) == ["out"]


# -- removal, and a file system that cannot lock -----------------------------------------------


def test_a_report_is_removed_file_by_file(tmp_path: Path) -> None:
    """Only the files a report lists go, the manifest last: anything else stops the removal
    of the directory, and is kept."""
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    (out / "notes.txt").write_text("n", encoding="utf-8")
    assert outdir.remove_report(out) == ["notes.txt"]
    assert sorted(os.listdir(out)) == ["notes.txt"]


def test_a_file_system_that_cannot_lock_still_gets_its_report(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """NFS cannot ``flock`` a directory opened for reading: warn and write unlocked."""

    def no_locks(fd: int, operation: int) -> None:
        raise OSError(errno.EBADF, os.strerror(errno.EBADF))

    monkeypatch.setattr(outdir.fcntl, "flock", no_locks)
    said: list[str] = []
    write_report_dir(tmp_path / "out", FILES, log=said.append)
    assert tree(tmp_path / "out")["index.html"] == FILES["index.html"]
    assert any("cannot lock" in line for line in said)
