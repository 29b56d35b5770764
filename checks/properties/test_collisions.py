"""Laws of the one-dimensional collision (mechmodel.collisions): chapters 2-4.

Floats are compared within 1e-12 of the sum of the magnitudes involved; Fraction inputs must
give exact equality.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given, target

from checks.properties.strategies import (
    fraction_masses,
    fraction_restitutions,
    fraction_velocities,
    masses,
    restitutions,
    velocities,
)
from mechmodel.collisions import center_of_mass_velocity, collide

pytestmark = pytest.mark.properties
REL = 1e-12


@given(masses(), masses(), velocities(), velocities(), restitutions())
@example(4.0, 1.0, 60.0, 10.0, 0.0)  # the SUV/VW Ka-runch of Fig. 2.1
@example(4.0, 1.0, 60.0, 10.0, 1.0)  # and its Ka-bong
def test_momentum_is_conserved_for_any_restitution(
    m1: float, m2: float, v1: float, v2: float, e: float
) -> None:
    """P = m1 v1 + m2 v2 is the same after any collision (2.1), whatever the restitution."""
    hit = collide(m1, m2, v1, v2, e)
    before = m1 * v1 + m2 * v2
    scale = abs(m1 * v1) + abs(m2 * v2) + abs(m1 * hit.v1) + abs(m2 * hit.v2)
    error = abs(hit.momentum - before)
    target(error / scale if scale else 0.0, label="relative momentum error")
    assert error <= REL * scale


@given(
    fraction_masses(),
    fraction_masses(),
    fraction_velocities(),
    fraction_velocities(),
    fraction_restitutions(),
)
def test_momentum_is_conserved_exactly(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, e: Fraction
) -> None:
    """With exact inputs the momentum balance (2.1) holds exactly."""
    hit = collide(m1, m2, v1, v2, e)
    assert hit.momentum == m1 * v1 + m2 * v2


@given(fraction_masses(), fraction_masses(), fraction_velocities(), fraction_velocities())
def test_elastic_collision_conserves_kinetic_energy_exactly(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """An elastic bang (4.1) keeps 1/2 m1 v1^2 + 1/2 m2 v2^2 (3.5b): same energy ellipse."""
    hit = collide(m1, m2, v1, v2, 1)
    assert hit.ke_after == hit.ke_before


@given(masses(), masses(), velocities(), velocities())
def test_elastic_collision_conserves_kinetic_energy(
    m1: float, m2: float, v1: float, v2: float
) -> None:
    """The float elastic bang keeps the kinetic energy to rounding error."""
    hit = collide(m1, m2, v1, v2)
    scale = hit.ke_before + hit.ke_after
    error = abs(hit.ke_after - hit.ke_before)
    target(error / scale if scale else 0.0, label="relative energy error")
    assert error <= REL * scale


@given(masses(), masses(), velocities(), velocities(), restitutions())
def test_kinetic_energy_is_never_gained(
    m1: float, m2: float, v1: float, v2: float, e: float
) -> None:
    """No collision gains energy: IN and FIN lie on or inside the KE ellipse (Fig. 3.1)."""
    hit = collide(m1, m2, v1, v2, e)
    assert hit.ke_after <= hit.ke_before * (1 + REL) + REL * (hit.ke_before + hit.ke_after)


@given(
    fraction_masses(),
    fraction_masses(),
    fraction_velocities(),
    fraction_velocities(),
    fraction_restitutions(),
)
def test_energy_lost_is_the_restitution_share_of_the_com_energy(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, e: Fraction
) -> None:
    """The loss is (1 - e^2) of the energy seen in the COM frame, 1/2 mu (v1 - v2)^2 (Fig. 3.1)."""
    hit = collide(m1, m2, v1, v2, e)
    reduced = m1 * m2 / (m1 + m2)
    assert hit.ke_lost == (1 - e * e) * reduced * (v1 - v2) ** 2 / 2


@given(masses(), masses(), velocities(), velocities(), restitutions())
def test_center_of_mass_velocity_is_unchanged(
    m1: float, m2: float, v1: float, v2: float, e: float
) -> None:
    """V_COM = (m1 v1 + m2 v2)/(m1 + m2) is the same before and after (2.5b)."""
    hit = collide(m1, m2, v1, v2, e)
    before = center_of_mass_velocity((m1, m2), (v1, v2))
    after = center_of_mass_velocity((m1, m2), hit.after)
    assert math.isclose(after, before, rel_tol=REL, abs_tol=REL * (abs(v1) + abs(v2)))


@given(velocities(), velocities(), restitutions(), masses())
def test_a_wall_keeps_its_velocity(u: float, v: float, e: float, m: float) -> None:
    """An infinite mass keeps its velocity; the ball leaves at u + e (u - v)."""
    hit = collide(math.inf, m, u, v, e)
    assert hit.v1 == u
    assert math.isclose(hit.v2, u + e * (u - v), rel_tol=REL, abs_tol=REL * (abs(u) + abs(v)))
