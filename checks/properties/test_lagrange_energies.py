"""Laws of L(v), E(V) and H(p) (mechmodel.lagrange.energies): chapter 12, (12.1)-(12.9).

The kinetic energy in velocities, quasi-velocities and momenta, the root-mass maps,
the slopes and radii of the energy ellipses (Figs. 12.1-12.2).

Floats are compared within 1e-12 of the sum of the magnitudes involved; Fraction results
must be exact. Tolerances shared by the lagrange modules are in ``_lagrange_helpers``.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties._lagrange_helpers import FLOOR
from checks.properties.closeness import assert_close
from checks.properties.strategies import exact_masses, exact_square_mass_ratios, exact_velocities
from mechmodel import lagrange

pytestmark = pytest.mark.properties


@given(st.lists(st.tuples(exact_masses(), exact_velocities()), min_size=1, max_size=4))
def test_l_e_and_h_are_one_energy(pairs: list[tuple[Fraction, Fraction]]) -> None:
    """L(v), E(V) and H(p) take the same value (12.3)-(12.5): the quasi-velocities V = sqrt(m) v
    and momenta p = m v rescale one kinetic energy; exact where roots are not needed."""
    masses = [m for m, _ in pairs]
    velocities = [v for _, v in pairs]
    lag = lagrange.kinetic_energy(masses, velocities)
    ham = lagrange.hamiltonian_free(masses, lagrange.momenta(masses, velocities))
    assert lag == ham
    est = lagrange.estrangian(
        lagrange.quasi_velocities([float(m) for m in masses], [float(v) for v in velocities])
    )
    assert_close(est, float(lag), rel=1e-12, abs=FLOOR)


@given(exact_square_mass_ratios())
@example(Fraction(16))  # Fig. 12.1
def test_collision_line_is_normal_to_the_bisector_only_in_v_space(ratio: Fraction) -> None:
    """In the Estrangian V plane the energy ellipse is a circle, so the collision line (tangent
    at the COM point) is perpendicular to the COM bisector: their slopes multiply to -1
    (Fig. 12.1b); the tangent is the collision line in all three planes; in the p plane the
    collision line has slope -1 whatever the masses (Fig. 12.1c). Exact."""
    s = lagrange.ke_ellipse_slopes(-ratio)
    assert s.quasi_collision * s.quasi_bisector == -1
    assert s.velocity_tangent == s.velocity_collision == -ratio
    assert s.quasi_tangent == s.quasi_collision
    assert s.momentum_tangent == s.momentum_collision == -1
    assert s.momentum_bisector == 1 / ratio
    assert s.quasi_bisector**2 == s.momentum_bisector
    assert all(isinstance(x, Fraction) for x in (s.quasi_collision, s.quasi_bisector))
    # a float slope gives the same lines in floats
    f = lagrange.ke_ellipse_slopes(-float(ratio))
    assert_close(f.mass_ratio, float(ratio), abs=FLOOR)
    assert_close(f.velocity_collision, -float(ratio), abs=FLOOR)
    assert_close(f.velocity_tangent, -float(ratio), abs=FLOOR)
    assert_close(f.quasi_collision * f.quasi_bisector, -1.0, abs=FLOOR)
    assert_close(f.quasi_bisector**2, f.momentum_bisector, abs=FLOOR)
    assert_close(f.momentum_tangent, -1.0, abs=FLOOR)
    assert_close(f.momentum_bisector, 1 / float(ratio), abs=FLOOR)


@given(st.lists(exact_masses(), min_size=1, max_size=3), st.floats(min_value=0.01, max_value=1e3))
def test_h_ellipse_radius_is_mass_times_l_ellipse_radius(masses: list[Fraction], e: float) -> None:
    """On each axis the H(p) = E ellipse reaches m_k times as far as the L(v) = E ellipse, and
    both radii lie on their ellipses (Fig. 12.2)."""
    ms = [float(m) for m in masses]
    radii = lagrange.energy_ellipse_radii(ms, e)
    for m, rv, rp in zip(ms, radii.velocity, radii.momentum, strict=True):
        assert_close(rp, m * rv, abs=FLOOR)
        assert_close(m * rv**2 / 2, e, abs=FLOOR)
        assert_close(rp**2 / (2 * m), e, abs=FLOOR)


# -- formula models: energies in scaled coordinates, root mass ---------------------------------


@given(st.lists(st.tuples(exact_masses(), exact_velocities()), min_size=1, max_size=3))
@example([(Fraction(4), Fraction(3)), (Fraction(9), Fraction(-2))])
def test_energy_is_the_same_in_every_scaled_coordinate(
    pairs: list[tuple[Fraction, Fraction]],
) -> None:
    """The kinetic energy of bodies given by u = m^s v is m v^2/2 whatever the scale s: in
    momenta (s = 1) it is H(p) = sum p^2/(2m) exactly (12.2), (12.4); in quasi-velocities
    (s = 1/2) it is E(V) = sum V^2/2, mass-free (12.1), (12.5); at s = 0 it is L(v) (12.3)."""
    masses = [m for m, _ in pairs]
    velocities = [v for _, v in pairs]
    lag = lagrange.kinetic_energy(masses, velocities)
    p = lagrange.momenta(masses, velocities)
    assert lagrange.scaled_coordinate_energy(masses, p, 1) == lagrange.hamiltonian_free(masses, p)
    assert lagrange.scaled_coordinate_energy(masses, p, 1) == lag
    assert lagrange.scaled_coordinate_energy(masses, velocities, 0) == lag
    fm = [float(m) for m in masses]
    quasi = lagrange.quasi_velocities(fm, [float(v) for v in velocities])
    got = lagrange.scaled_coordinate_energy(fm, quasi, Fraction(1, 2))
    assert_close(got, float(lag), abs=FLOOR)
    assert_close(got, lagrange.estrangian(quasi), abs=FLOOR)
    heavier = lagrange.scaled_coordinate_energy([2 * m for m in fm], quasi, Fraction(1, 2))
    assert_close(heavier, got, abs=FLOOR)  # E(V) has no mass in it


@given(exact_masses())
@example(Fraction(3))
def test_root_mass_maps_compose_to_the_mass_and_its_inverse(root: Fraction) -> None:
    """Two root-mass scalings make the mass, M = R^2, and two inverse ones its inverse,
    M^-1 = R^-2 (12.9): the two maps are mutual inverses, exactly."""
    maps = lagrange.root_mass_maps(root)
    assert maps.mass == root * root
    assert maps.mass * maps.inverse_mass == 1
    assert isinstance(maps.inverse_mass, Fraction)
    assert lagrange.root_mass_maps(int(root.numerator)).mass == root.numerator**2
    with pytest.raises(ValueError, match="positive"):
        lagrange.root_mass_maps(-root)


@given(st.floats(min_value=1e-3, max_value=1e3), st.floats(min_value=1e-3, max_value=1e3))
@example(0.5, 1.0)  # Fig. 12.2(d): less mass, the velocity ellipse is twice the momentum one
def test_ellipse_radius_ratio_is_one_over_the_mass(mass: float, energy: float) -> None:
    """On each axis the L(v) = E ellipse reaches 1/m times as far as the H(p) = E ellipse,
    whatever the energy (Fig. 12.2): ratio times mass is 1."""
    ratio = lagrange.ellipse_radius_ratio(mass, energy)
    assert_close(ratio * mass, 1.0, abs=FLOOR)
    assert_close(ratio, lagrange.ellipse_radius_ratio(mass), abs=FLOOR)
