"""``bangcheck report --out``: a user's files are never lost (``reports/outdir.py``).

Two runs at once take turns under a lock and leave no debris; a run that died is cleaned up
after, by ``recover`` and by the next run, which restore or remove only what carries the
manifest and follow no symlink.
"""

from __future__ import annotations

import multiprocessing
import os
from collections.abc import Callable
from multiprocessing.connection import Connection
from pathlib import Path

import pytest

from checks._output_dir_helpers import FILES, tree
from reports import outdir
from reports.outdir import MANIFEST, manifest_text, recover, write_report_dir

pytestmark = pytest.mark.integrity


# -- concurrent runs and crashes ----------------------------------------------------------


def _write_many(out: str, tag: int, rounds: int) -> None:
    files = {name: f"{tag}:{name}\n" * 20_000 for name in FILES}
    for _ in range(rounds):
        write_report_dir(Path(out), files, log=lambda m: None)


def test_concurrent_runs_leave_one_good_report_and_no_debris(tmp_path: Path) -> None:
    out = tmp_path / "out"
    context = multiprocessing.get_context("fork")
    workers = [context.Process(target=_write_many, args=(str(out), tag, 15)) for tag in range(4)]
    for w in workers:
        w.start()
    for w in workers:
        w.join(timeout=120)
    assert [w.exitcode for w in workers] == [0, 0, 0, 0]
    assert sorted(os.listdir(tmp_path)) == ["out"]  # no .out.new-* or .out.old-*
    written = tree(out)
    assert set(written) == {*FILES, MANIFEST}
    tags = {text.split(":", 1)[0] for name, text in written.items() if name != MANIFEST}
    assert len(tags) == 1  # all three files from one run, never a mix


def _write_mine(out: Path, log: outdir.Log) -> None:
    write_report_dir(out, {"index.html": "mine\n"}, log=log)


def _say_after_go(
    act: Callable[[Path, outdir.Log], None], out: str, go: Connection, said: Connection
) -> None:
    """In the child: wait for the word, then ``act`` on ``out``, saying each log line."""
    go.recv()
    try:
        act(Path(out), said.send)
    except outdir.OutputError as err:
        said.send(f"refused: {err}")
        os._exit(1)


@pytest.mark.parametrize("act", [_write_mine, outdir.check_target_now], ids=["write", "cli-check"])
def test_a_run_judges_the_directory_only_under_the_lock(
    tmp_path: Path, act: Callable[[Path, outdir.Log], None]
) -> None:
    """While another run holds the lock, the directory may look foreign (a listing caught
    between that run's two renames): a run waits for the lock before judging it, here with a
    stray file that the lock's holder removes before it lets go."""
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    context = multiprocessing.get_context("fork")
    go_end, go = context.Pipe(duplex=False)
    listen, said = context.Pipe(duplex=False)
    child = context.Process(target=_say_after_go, args=(act, str(out), go_end, said), daemon=True)
    child.start()  # before the lock is taken, so that the child holds no copy of it
    try:
        with outdir.locked(tmp_path):
            (out / "half-listed").write_text("x", encoding="utf-8")
            go.send("go")
            spoke = listen.poll(30)
            first = listen.recv() if spoke else "nothing within 30 s"
            (out / "half-listed").unlink()
        child.join(timeout=60)
    finally:
        if child.is_alive():  # a failure above must not leave the session waiting for it
            child.kill()
            child.join()
    assert first.startswith("waiting for another report"), first
    assert child.exitcode == 0
    if act is _write_mine:
        assert (out / "index.html").read_text(encoding="utf-8") == "mine\n"


def _die_between_the_renames(out: str) -> None:
    def first_rename_only(staging: Path, target: Path, log: object) -> None:
        target.rename(target.parent / f".{target.name}.old-dead")
        os._exit(3)

    outdir._swap_in = first_rename_only  # type: ignore[assignment]
    write_report_dir(Path(out), {"index.html": "new\n"}, log=lambda m: None)


def test_a_crash_between_the_two_renames_is_recovered(tmp_path: Path) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    before = tree(out)
    child = multiprocessing.get_context("fork").Process(
        target=_die_between_the_renames, args=(str(out),)
    )
    child.start()
    child.join(timeout=60)
    assert child.exitcode == 3
    left = sorted(os.listdir(tmp_path))
    assert "out" not in left
    assert [n for n in left if n.startswith(".out.new-")]
    assert ".out.old-dead" in left
    said: list[str] = []
    with outdir.locked(tmp_path):
        recover(out, said.append)
    assert tree(out) == before  # the previous report is back
    assert sorted(os.listdir(tmp_path)) == ["out"]
    assert any("restored" in line for line in said)
    assert any("unfinished report" in line for line in said)


def test_recovery_removes_only_what_carries_the_manifest(tmp_path: Path) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    ours = tmp_path / ".out.old-1"
    write_report_dir(ours, FILES, log=lambda m: None)
    theirs = tmp_path / ".out.old-2"  # an earlier version's leftover, or the user's
    theirs.mkdir()
    (theirs / "index.html").write_text("x", encoding="utf-8")
    staging = tmp_path / ".out.new-3"
    staging.mkdir()
    (staging / "thesis.txt").write_text("t", encoding="utf-8")
    said: list[str] = []
    recover(out, said.append)
    assert sorted(os.listdir(tmp_path)) == [".out.new-3", ".out.old-2", "out"]
    assert any(".out.old-2" in line and "by hand" in line for line in said)


def test_a_missing_report_is_restored_only_from_a_single_candidate(tmp_path: Path) -> None:
    out = tmp_path / "out"
    for name in (".out.old-1", ".out.old-2"):
        write_report_dir(tmp_path / name, FILES, log=lambda m: None)
    recover(out, lambda m: None)
    assert sorted(os.listdir(tmp_path)) == []  # two candidates: neither is the report


def test_the_next_run_cleans_up_after_a_crash(tmp_path: Path) -> None:
    """What the crash left is cleaned up by the next ``write_report_dir`` itself."""
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    child = multiprocessing.get_context("fork").Process(
        target=_die_between_the_renames, args=(str(out),)
    )
    child.start()
    child.join(timeout=60)
    assert child.exitcode == 3
    (tmp_path / ".out.new-empty").mkdir()  # a crash before the manifest was written
    said: list[str] = []
    write_report_dir(out, {"index.html": "after\n"}, log=said.append)
    assert tree(out) == {"index.html": "after\n", MANIFEST: manifest_text(["index.html"])}
    assert sorted(os.listdir(tmp_path)) == ["out"]
    assert any("restored" in line for line in said)


def test_recovery_follows_no_symlink(tmp_path: Path) -> None:
    """A ``.out.old-*`` that is a link (to a user's folder holding a forged manifest) is no
    report of an earlier run: neither restored nor removed."""
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / MANIFEST).write_text(manifest_text(["thesis.txt"]), encoding="utf-8")
    (mine / "thesis.txt").write_text("t", encoding="utf-8")
    (tmp_path / ".out.old-1").symlink_to(mine)
    (tmp_path / ".out.new-2").symlink_to(mine)
    recover(tmp_path / "out", lambda m: None)
    assert tree(mine) == {MANIFEST: manifest_text(["thesis.txt"]), "thesis.txt": "t"}
    assert not (tmp_path / "out").exists()
