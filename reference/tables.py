"""The units and constants tables (``reference/units.toml``, ``reference/constants.toml``).

Like astropy.constants: the tables are data kept as written; this parser turns each row into a
frozen dataclass and raises a plain ``ValueError`` naming the file and row on anything it cannot
read. Derived constants are computed here, each from the entries it names.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import cache
from importlib.resources import files

import tomli

NO_CONVERSION = ("scaled", "1")


@dataclass(frozen=True)
class Unit:
    """A unit a claim may be printed in: its factor to SI and the symbols the book uses."""

    name: str
    si: float
    symbols: tuple[str, ...]


@dataclass(frozen=True)
class Edition:
    """One edition of a constant's value: the current one or an older one, with its source."""

    edition: str
    value: float
    uncertainty: float
    source: str = ""


@dataclass(frozen=True)
class Constant:
    """A physical constant, datum, conversion or date, with its source and editions."""

    key: str
    value: float
    unit: str
    uncertainty: float
    exact: bool
    source: str
    edition: str
    codata: str | None
    derived: str | None
    older: tuple[Edition, ...]
    date: bool = False

    @property
    def editions(self) -> tuple[Edition, ...]:
        """The current edition first, then the older ones as listed."""
        return (Edition(self.edition, self.value, self.uncertainty, self.source), *self.older)


def _read(name: str) -> dict:
    return tomli.loads(files("reference").joinpath(name).read_text(encoding="utf-8"))


@cache
def units() -> Mapping[str, Unit]:
    """Every unit of ``units.toml`` by name."""
    table: dict[str, Unit] = {}
    for name, row in _read("units.toml").get("unit", {}).items():
        si = row.get("si")
        if not isinstance(si, int | float) or not si > 0 or not math.isfinite(si):
            raise ValueError(f"units.toml: unit {name!r}: field 'si' must be a positive number")
        symbols = row.get("symbols", [])
        if not isinstance(symbols, list) or not all(isinstance(s, str) for s in symbols):
            raise ValueError(f"units.toml: unit {name!r}: field 'symbols' must be a list of text")
        table[name] = Unit(name, float(si), tuple(symbols))
    return table


def unit_factor(name: str) -> float:
    """The SI factor of a claim's unit (1 for ``scaled`` and ``1``)."""
    if name in NO_CONVERSION:
        return 1.0
    return units()[name].si


# Derived entries: each computes (value, standard uncertainty) from the table.
def _earth_mass(c: Mapping[str, Constant]) -> tuple[float, float]:
    # M = GM / G; GM is exact (IAU 2015 B3), so the relative uncertainty is that of G.
    gm, g = c["earth-gm"], c["gravitational-constant"]
    value = gm.value / g.value
    return value, value * g.uncertainty / g.value


def _coulomb_constant(c: Mapping[str, Constant]) -> tuple[float, float]:
    # k = 1 / (4 pi epsilon_0) (SI), relative uncertainty that of epsilon_0.
    eps = c["vacuum-permittivity"]
    value = 1 / (4 * math.pi * eps.value)
    return value, value * eps.uncertainty / eps.value


DERIVED: dict[str, Callable[[Mapping[str, Constant]], tuple[float, float]]] = {
    "earth-mass": _earth_mass,
    "coulomb-constant": _coulomb_constant,
}


def _number(key: str, row: dict, field: str) -> float:
    value = row.get(field)
    if not isinstance(value, int | float) or isinstance(value, bool) or not math.isfinite(value):
        raise ValueError(f"constants.toml: constant {key!r}: field {field!r} must be a number")
    return float(value)


def _text(key: str, row: dict, field: str, required: bool = True) -> str | None:
    value = row.get(field)
    if value is None and not required:
        return None
    if not isinstance(value, str) or not value.strip():
        raise ValueError(f"constants.toml: constant {key!r}: field {field!r} must be text")
    return value


@cache
def constants() -> Mapping[str, Constant]:
    """Every constant of ``constants.toml`` by key."""
    table: dict[str, Constant] = {}
    for key, row in _read("constants.toml").get("constant", {}).items():
        exact = row.get("exact", False)
        if exact is True and "uncertainty" in row:
            raise ValueError(f"constants.toml: constant {key!r}: exact and an uncertainty")
        uncertainty = 0.0 if exact is True else _number(key, row, "uncertainty")
        if uncertainty < 0:
            raise ValueError(f"constants.toml: constant {key!r}: negative uncertainty")
        older = tuple(
            Edition(
                _text(key, old, "edition") or "",
                _number(key, old, "value"),
                _number(key, old, "uncertainty") if "uncertainty" in old else 0.0,
                _text(key, old, "source") or "",
            )
            for old in row.get("older", [])
        )
        date = row.get("date", False)
        if not isinstance(date, bool):
            raise ValueError(f"constants.toml: constant {key!r}: field 'date' must be a boolean")
        derived = _text(key, row, "derived", required=False)
        if derived is not None and key not in DERIVED:
            raise ValueError(f"constants.toml: constant {key!r}: derived, but no computation")
        table[key] = Constant(
            key=key,
            value=_number(key, row, "value"),
            unit=_text(key, row, "unit") or "",
            uncertainty=uncertainty,
            exact=exact is True,
            source=_text(key, row, "source") or "",
            edition=_text(key, row, "edition") or "",
            codata=_text(key, row, "codata", required=False),
            derived=derived,
            older=older,
            date=date,
        )
    return table
