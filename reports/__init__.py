"""The errata report (HTML, CSV, JSON), its figures and the ``bangcheck`` command."""

from importlib.metadata import PackageNotFoundError, version


def bangcheck_version() -> str:
    """The installed bangcheck version ("unknown" in a tree that was never installed)."""
    try:
        return version("bangcheck")
    except PackageNotFoundError:
        return "unknown"
