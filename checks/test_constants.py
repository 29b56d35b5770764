"""The constants and units tables: readable, sourced, and in agreement with scipy.constants."""

from __future__ import annotations

import math
import re

import pytest
import scipy.constants

from reference.tables import DERIVED, constants, units


@pytest.mark.parametrize("key", sorted(k for k, c in constants().items() if c.codata))
def test_codata_entries_agree_with_scipy(key: str) -> None:
    const = constants()[key]
    value, _, uncertainty = scipy.constants.physical_constants[const.codata]
    assert const.value == pytest.approx(value, rel=1e-12)
    assert const.uncertainty == pytest.approx(uncertainty, rel=1e-9, abs=0)


@pytest.mark.parametrize("key", sorted(DERIVED))
def test_derived_entries_are_what_their_computation_gives(key: str) -> None:
    value, uncertainty = DERIVED[key](constants())
    const = constants()[key]
    assert const.derived
    assert const.value == pytest.approx(value, rel=1e-12)
    assert const.uncertainty == pytest.approx(uncertainty, rel=1e-3)


def test_every_constant_is_sourced_and_consistent() -> None:
    for key, const in constants().items():
        assert const.source.strip(), key
        assert const.edition.strip(), key
        assert math.isfinite(const.value), key
        assert (const.uncertainty == 0) if const.exact else (const.uncertainty > 0), key
        for old in const.older:
            assert old.edition, key
            assert old.edition != const.edition, key
            assert old.source.strip(), (key, old.edition)  # a dated value names where it is from
            assert len(old.edition) <= 20, (key, old.edition)  # a short name a claim can cite


def test_no_source_names_a_path_of_one_machine() -> None:
    """A source cites a document, or a file relative to the project, never an absolute path."""
    absolute = re.compile(r"(?<![\w.])/(?:work|home|tmp|root|check|Users)/")
    for key, const in constants().items():
        for edition in const.editions:
            assert not absolute.search(edition.source), (key, edition.edition, edition.source)


def test_dates_are_years() -> None:
    """A constant marked ``date = true`` is a year (read at its last non-zero digit)."""
    dates = {key: c for key, c in constants().items() if c.date}
    assert len(dates) > 30
    for key, const in dates.items():
        assert const.unit == "1", key
        assert key.endswith(("-year", "-year-bce", "-decade")), key
        assert float(const.value).is_integer(), key
        assert 0 < const.value < 2100, key


def test_older_editions_of_g() -> None:
    editions = [e.edition for e in constants()["gravitational-constant"].editions]
    assert editions[0] == "CODATA 2022"
    assert "CODATA 1973" in editions


def test_units_have_positive_factors_and_symbols() -> None:
    for name, unit in units().items():
        assert unit.si > 0, name
        assert unit.symbols, name
    assert units()["mile"].si == 1609.344
    assert units()["min"].si == 60
    assert units()["deg"].si == pytest.approx(math.pi / 180, rel=1e-15)
