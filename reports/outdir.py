"""The report's output directory: written only when it is the report's own, and swapped whole.

A directory is the report's own when it is missing, empty, or holds nothing but a previous
report: every entry other than the manifest ``.bangcheck-report`` is a regular file named in
that manifest, or, for a report written before the manifest existed, every entry is a regular
file of ``LEGACY_NAMES`` whose content is what the report writes there (a user's own
``index.html`` is not a report's). Any other directory, and a file or device, is refused and
left untouched: the report never deletes what it did not write.

The files are written into ``.NAME.new-*`` beside the target (the manifest first), which then
replaces the target in two renames; the old report, moved to ``.NAME.old-*``, is checked once
more and removed file by file (the manifest last), never as a tree, so that a file that appeared
in it meanwhile stops the removal instead of going with it. All of this happens under an
exclusive ``flock`` on the parent directory, so that two runs into one place take turns, and
each judges the target only under it (a listing caught between another run's two renames would
look foreign); under the lock, once the target is admitted, what a run that crashed left is
cleaned up (``recover``) before anything is written. Every failure is an ``OutputError`` with a
one-line message, and leaves the previous report as it was.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import os
import secrets
import stat
import sys
import tempfile
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path

MANIFEST = ".bangcheck-report"
MANIFEST_HEADER = (
    "# bangcheck report: the files below were written by `bangcheck report`, "
    "which replaces this directory on its next run"
)
# What a report written before the manifest existed holds, and how its first bytes begin
LEGACY_SIGNS = {
    "index.html": "<title>bangcheck",
    "errata.csv": "id,chapter,line,quantity,printed,correct",
    "claims.json": '"bangcheck":',
    "properties.json": '"invariants":',
}
LEGACY_NAMES = frozenset(LEGACY_SIGNS)
SHOWN_FOREIGN = 3  # foreign entries named in a refusal

Log = Callable[[str], None]


class OutputError(Exception):
    """The report cannot be written where asked; the message is one line for the user."""


def _stderr(message: str) -> None:
    print(f"bangcheck: {message}", file=sys.stderr)


def shown(name: object) -> str:
    """A path or name as a message shows it: as is, or quoted where it holds a line break or
    another character that could make one message look like two."""
    text = str(name)
    return text if text.isprintable() else repr(text)


def manifest_text(names: list[str]) -> str:
    """The manifest listing ``names``, the files a report wrote."""
    return "\n".join([MANIFEST_HEADER, *names]) + "\n"


def _regular(path: Path) -> bool:
    try:
        return stat.S_ISREG(path.lstat().st_mode)
    except OSError:
        return False


def manifest_names(directory: Path) -> frozenset[str] | None:
    """The names ``directory``'s manifest lists, or None where it has no manifest of ours (a
    file of that name that bangcheck did not write, or anything but a regular file)."""
    path = directory / MANIFEST
    if not _regular(path):
        return None
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None
    first, _, rest = text.partition("\n")
    if first != MANIFEST_HEADER:
        return None
    names = frozenset(line for line in rest.splitlines() if line)
    if any("/" in n or n in (".", "..", MANIFEST) or not n.isprintable() for n in names):
        return None
    return names


def _looks_like_legacy(path: Path) -> bool:
    """Whether ``path`` is a regular file whose first bytes are what an old report wrote."""
    if not _regular(path):
        return False
    try:
        with path.open("rb") as handle:
            head = handle.read(4096).decode("utf-8", errors="replace")
    except OSError:
        return False
    return LEGACY_SIGNS[path.name] in head


def foreign_entries(directory: Path) -> list[str]:
    """The entries of an existing ``directory`` that no report wrote, sorted; empty when the
    directory is empty or holds only a previous report. ``OSError`` if it cannot be listed."""
    entries = set(os.listdir(directory))
    if MANIFEST in entries:
        listed = manifest_names(directory)
        if listed is None:
            return sorted(entries)  # a manifest we cannot read vouches for nothing
        ours = {e for e in entries if e in listed and _regular(directory / e)}
        return sorted(entries - ours - {MANIFEST})
    return sorted(
        e for e in entries if not (e in LEGACY_NAMES and _looks_like_legacy(directory / e))
    )


def carries_manifest(directory: Path) -> bool:
    """Whether ``directory`` holds a manifest of ours and nothing it does not list."""
    try:
        return manifest_names(directory) is not None and not foreign_entries(directory)
    except OSError:
        return False


def _kind(mode: int) -> str:
    if stat.S_ISREG(mode):
        return "a file"
    if stat.S_ISCHR(mode):
        return "a character device"
    if stat.S_ISBLK(mode):
        return "a block device"
    if stat.S_ISFIFO(mode):
        return "a named pipe"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a directory"


def _nearest_existing(path: Path) -> Path:
    while not os.path.lexists(path) and path != path.parent:
        path = path.parent
    return path


def _refusal(out: Path, foreign: list[str], why: str) -> OutputError:
    names = ", ".join(shown(n) for n in foreign[:SHOWN_FOREIGN])
    more = len(foreign) - SHOWN_FOREIGN
    if more > 0:
        names += f" and {more} more"
    return OutputError(
        f"--out {shown(out)} {why} ({names}): refused, nothing was changed; give a new or empty "
        "directory, or move those files elsewhere"
    )


def check_target(out: Path) -> None:
    """Raise ``OutputError`` unless the report may write ``out`` (an absolute path): missing
    with a parent that can be made, or an empty or previous-report directory the report can
    replace. Touches nothing."""
    if out == out.parent:
        raise OutputError(f"--out {shown(out)}: the root directory is not an output directory")
    try:
        mode = out.lstat().st_mode
    except (FileNotFoundError, NotADirectoryError):
        ancestor = _nearest_existing(out.parent)
        if not ancestor.is_dir():
            kind = _kind(ancestor.lstat().st_mode)
            raise OutputError(
                f"--out {shown(out)}: cannot be made, {shown(ancestor)} is {kind}"
            ) from None
        if not os.access(ancestor, os.W_OK | os.X_OK):
            raise OutputError(
                f"--out {shown(out)}: cannot be made, {shown(ancestor)} is not writable"
            ) from None
        return
    except OSError as err:
        raise OutputError(f"--out {shown(out)}: {err.strerror}") from err
    if not stat.S_ISDIR(mode):
        raise OutputError(
            f"--out {shown(out)} is {_kind(mode)}: refused, nothing was changed; "
            "give a new or empty directory"
        )
    if os.path.ismount(out):
        raise OutputError(
            f"--out {shown(out)} is a mount point, which cannot be replaced: give a directory "
            "inside it"
        )
    try:
        foreign = foreign_entries(out)
    except OSError as err:
        raise OutputError(f"--out {shown(out)}: cannot list it: {err.strerror}") from err
    if foreign:
        raise _refusal(out, foreign, "holds files the report did not write")
    for place in (out, out.parent):
        if not os.access(place, os.W_OK | os.X_OK):
            raise OutputError(
                f"--out {shown(out)}: {shown(place)} is not writable, so the previous report "
                "cannot be replaced"
            )


def check_target_now(out: Path, log: Log = _stderr) -> None:
    """``check_target`` as a run's first word: under the lock where ``out``'s parent exists,
    so that another run's report being swapped in is not mistaken for foreign files; and
    there, whether a directory can be made beside ``out`` as the write will (a read-only file
    system or a denied permission is said before the work, not after it)."""
    if not out.parent.is_dir():
        check_target(out)
        _probe(out, _nearest_directory(out.parent), ".bangcheck-probe-")
        return
    try:
        with locked(out.parent, log):
            check_target(out)
            # named as a write's staging directory, so that a run killed at this instant
            # leaves nothing the next run's clean-up does not remove
            _probe(out, out.parent, f".{out.name}.new-")
    except OSError as err:  # the parent cannot be opened to lock it
        raise _unwritable(out, err) from err


def _nearest_directory(path: Path) -> Path:
    """``path`` or its nearest ancestor that exists (where the write will make directories)."""
    while not path.is_dir() and path != path.parent:
        path = path.parent
    return path


def _probe(out: Path, directory: Path, prefix: str) -> None:
    """Make and remove an empty directory in ``directory``, as the write will: an
    ``OutputError`` naming ``directory`` (not the probe) where that cannot be done."""
    try:
        os.rmdir(tempfile.mkdtemp(prefix=prefix, dir=directory))
    except OSError as err:
        reason = err.strerror or str(err)
        if err.errno == errno.ENOENT:  # e.g. /proc: it exists, and nothing can be made in it
            reason = "no directory can be made there"
        raise _unwritable(out, OSError(err.errno, reason, str(directory))) from err


@contextlib.contextmanager
def locked(directory: Path, log: Log = _stderr) -> Iterator[None]:
    """An exclusive ``flock`` on ``directory``'s own descriptor for the block: no lock file is
    left behind, and a run that dies releases it. Where the file system cannot lock a
    directory (NFS), the block runs unlocked, with a warning."""
    fd = os.open(directory, os.O_RDONLY | os.O_DIRECTORY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            log(f"waiting for another report being written in {shown(directory)}")
            fcntl.flock(fd, fcntl.LOCK_EX)
        except OSError as err:
            log(
                f"warning: cannot lock {shown(directory)} ({err.strerror}): do not run two "
                "reports into it at once"
            )
        yield
    finally:
        os.close(fd)  # releases the lock


def _debris(parent: Path, name: str, kind: str) -> list[Path]:
    prefix = f".{name}.{kind}-"
    return sorted(
        parent / e
        for e in os.listdir(parent)
        if e.startswith(prefix) and stat.S_ISDIR((parent / e).lstat().st_mode)
    )


def remove_report(directory: Path) -> list[str]:
    """Remove a report's directory file by file: the files it lists, then the manifest, then
    the directory. Returns the entries that are not the report's (then nothing more is
    removed than the report's own files, and the directory stays)."""
    listed = manifest_names(directory)
    names = listed if listed is not None else LEGACY_NAMES
    for name in sorted(names):
        path = directory / name
        if _regular(path) and (listed is not None or _looks_like_legacy(path)):
            path.unlink()
    if listed is not None:
        (directory / MANIFEST).unlink()
    left = sorted(os.listdir(directory))
    if not left:
        directory.rmdir()
    return left


def recover(out: Path, log: Log = _stderr) -> None:
    """Clean up what an interrupted run left beside ``out``; call it under ``locked``.

    A ``.NAME.new-*`` that is empty or carries the manifest is an unfinished write: removed. If
    ``out`` is missing and exactly one ``.NAME.old-*`` carries the manifest, the run died
    between its two renames: that previous report is renamed back. Every other ``.NAME.old-*``
    carrying the manifest is removed; anything else of these names is left, and named.
    """
    parent, name = out.parent, out.name
    for staging in _debris(parent, name, "new"):
        if not os.listdir(staging):
            staging.rmdir()
        elif carries_manifest(staging):
            remove_report(staging)
            log(f"removed {shown(staging)}, an unfinished report of an earlier run")
        else:
            log(f"left {shown(staging)}: it is not recognisably a report (remove it by hand)")
    olds = _debris(parent, name, "old")
    ours = [p for p in olds if carries_manifest(p)]
    if not os.path.lexists(out) and len(ours) == 1:
        ours.pop().rename(out)
        log(f"restored {shown(out)}, the previous report, which an interrupted run moved aside")
    for old in ours:
        remove_report(old)
        log(f"removed {shown(old)}, a previous report an earlier run had moved aside")
    for old in olds:
        if old.exists() and not carries_manifest(old):
            log(
                f"left {shown(old)}: an earlier run's leftover that is not recognisably a "
                "report (remove it by hand)"
            )


def _fsync(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _fsync_directory(path: Path) -> None:
    try:
        _fsync(path)
    except OSError as err:
        if err.errno not in (errno.EINVAL, errno.EBADF, errno.ENOTSUP):
            raise  # some file systems cannot sync a directory; others must


def _write_staging(staging: Path, files: Mapping[str, str | bytes]) -> None:
    (staging / MANIFEST).write_text(manifest_text(list(files)), encoding="utf-8")
    for name, content in files.items():
        path = staging / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")
        _fsync(path)
    _fsync(staging / MANIFEST)
    _fsync_directory(staging)


def _default_mode() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return 0o777 & ~mask


def _swap_in(staging: Path, out: Path, log: Log) -> None:
    """Replace ``out`` (if any) by ``staging``. The old report, once moved aside, is checked
    again: a file that appeared in it meanwhile puts it back and refuses. If the second rename
    fails, the old report is put back too."""
    old = None
    if os.path.lexists(out):
        old = out.parent / f".{out.name}.old-{secrets.token_hex(4)}"
        out.rename(old)
        foreign = foreign_entries(old)
        if foreign:
            old.rename(out)
            raise _refusal(out, foreign, "received files while the report was written")
    try:
        staging.rename(out)
    except OSError:
        if old is not None:
            old.rename(out)
        raise
    _fsync_directory(out.parent)
    if old is not None:
        left = remove_report(old)
        if left:
            names = ", ".join(shown(n) for n in left)
            log(f"left {shown(old)}: it holds {names}, which the report did not write")


def _make_parents(directory: Path) -> list[Path]:
    """Make ``directory`` and its missing parents; the ones made, outermost first."""
    missing = []
    while not os.path.lexists(directory):
        missing.append(directory)
        directory = directory.parent
    made = []
    for path in reversed(missing):
        try:
            path.mkdir()
        except FileExistsError:
            if not path.is_dir():
                raise
            continue  # another run made it meanwhile: theirs, not ours to remove
        made.append(path)
    return made


def _unwritable(out: Path, err: OSError) -> OutputError:
    """The one-line error of a write (or its lock) that failed with ``err``."""
    where = shown(err.filename or out)
    reason = "read-only file system" if err.errno == errno.EROFS else err.strerror or err
    if err.errno == errno.EBUSY:
        reason = "device or resource busy (a mount point cannot be replaced)"
    return OutputError(
        f"cannot write the report to {shown(out)}: {reason} ({where}); the previous "
        "report, if any, is unchanged"
    )


def write_report_dir(out: Path, files: Mapping[str, str | bytes], log: Log = _stderr) -> None:
    """Make ``out`` a directory holding exactly ``files`` (name to content) and the manifest.

    Refuses (``OutputError``, nothing touched) unless ``check_target`` admits ``out``; any
    failure while writing is an ``OutputError`` too, and leaves the previous report in place
    (and no directory the run made).
    """
    out = Path(os.path.abspath(out))
    if any("/" in name or name in ("", ".", "..", MANIFEST) for name in files):
        raise ValueError(f"report file names must be plain names: {sorted(files)}")
    if not out.parent.is_dir():
        check_target(out)  # before making its parents (no other run is in there yet)
    staging: Path | None = None
    made: list[Path] = []
    try:
        made = _make_parents(out.parent)
        with locked(out.parent, log):
            # judged under the lock only: a run swapping its report in meanwhile would show
            # this one a directory half listed, or gone between its stat and its listing; and
            # before the clean-up, so that a refusal changes nothing
            check_target(out)
            recover(out, log)
            mode = out.stat().st_mode if out.is_dir() else _default_mode()
            staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.new-", dir=out.parent))
            _write_staging(staging, files)
            staging.chmod(stat.S_IMODE(mode))  # mkdtemp's is private; keep the old one's
            _swap_in(staging, out, log)
            staging = None
    except OSError as err:
        raise _unwritable(out, err) from err
    finally:
        if staging is not None and staging.is_dir():
            with contextlib.suppress(OSError):
                remove_report(staging)
                if staging.exists():
                    staging.rmdir()
        if staging is not None or not out.exists():
            for path in reversed(made):
                with contextlib.suppress(OSError):
                    path.rmdir()  # only if still empty
