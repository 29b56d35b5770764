"""Laws of generalized coordinates (mechmodel.lagrange.coordinates): chapter 12,
(12.18)-(12.25), (12.31), (12.36)-(12.37).

The gradient potential of M.v, the Hamiltonian of one coordinate, the slope of a quadratic
and the kinetic energy of a metric.

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
from checks.properties.strategies import (
    exact_masses,
    exact_plane_vectors,
    exact_symmetric_matrices,
    exact_velocities,
)
from mechmodel import lagrange

pytestmark = pytest.mark.properties


@given(exact_symmetric_matrices(), exact_plane_vectors(), exact_plane_vectors())
def test_gradient_potential_has_gradient_m_dot_v(
    matrix: tuple[tuple[Fraction, ...], ...],
    v: tuple[Fraction, Fraction],
    w: tuple[Fraction, Fraction],
) -> None:
    """F(v) = integral_0^1 (M.(t v)).v dt has the directional derivative (M.v).w along any w
    (line 15022: d/dq of it is M_ij v^i dv^j/dq), vanishes at 0 and is homogeneous of degree
    two; exact (a central difference is exact for a quadratic). A non-symmetric matrix has
    no potential."""
    f = lagrange.gradient_potential
    h = Fraction(1, 7)
    plus = [v[k] + h * w[k] for k in range(2)]
    minus = [v[k] - h * w[k] for k in range(2)]
    slope = (f(matrix, plus) - f(matrix, minus)) / (2 * h)
    mv = [sum(matrix[i][j] * v[j] for j in range(2)) for i in range(2)]
    assert slope == sum(mv[i] * w[i] for i in range(2))
    assert f(matrix, [0, 0]) == 0
    assert f(matrix, [2 * v[0], 2 * v[1]]) == 4 * f(matrix, list(v))
    if matrix[0][1] != 0:
        skew = [[matrix[0][0], matrix[0][1]], [-matrix[0][1], matrix[1][1]]]
        with pytest.raises(ValueError, match="symmetric"):
            f(skew, list(v))


@given(
    exact_masses(),
    exact_masses(),
    exact_velocities(),
    exact_velocities(),
)
@example(Fraction(1), Fraction(1), Fraction(2), Fraction(0))  # a free particle: H = T
def test_coordinate_hamiltonian_is_the_energy_both_ways(
    mass: Fraction, metric: Fraction, rate: Fraction, potential: Fraction
) -> None:
    """H = p q' - L of L = M g q'^2/2 - U is the energy T + U (12.37b) with p = M g q'; in
    momenta, with the contravariant metric 1/g, it is the same H at the same rate (12.37c).
    Exact."""
    h = lagrange.hamiltonian_of_rate(mass, metric, rate, potential)
    assert h.momentum == mass * metric * rate
    assert h.hamiltonian == mass * metric * rate * rate / 2 + potential
    back = lagrange.hamiltonian_of_momentum(mass, 1 / metric, h.momentum, potential)
    assert (back.rate, back.hamiltonian) == (rate, h.hamiltonian)
    whole = lagrange.hamiltonian_of_momentum(mass, 1, h.momentum, potential)
    assert whole.hamiltonian == h.momentum**2 / (2 * mass) + potential


@given(exact_velocities(), exact_velocities())
@example(Fraction(2), Fraction(-4))  # line 15832: S = q^2 - 4q is stationary at q = 2
def test_quadratic_slope_is_the_central_difference(q: Fraction, b: Fraction) -> None:
    """dS/dq of S = q^2 + b q equals its central difference (exact for a quadratic) and
    vanishes at the extremum of ``quadratic_extremum`` (line 15832)."""
    h = Fraction(1, 3)

    def s(x: Fraction) -> Fraction:
        return x * x + b * x

    assert lagrange.quadratic_function_slope(q, b) == (s(q + h) - s(q - h)) / (2 * h)
    assert lagrange.quadratic_function_slope(lagrange.quadratic_extremum(b).point, b) == 0


@given(
    st.lists(st.floats(min_value=-3, max_value=3), min_size=4, max_size=4),
    st.tuples(st.floats(min_value=-3, max_value=3), st.floats(min_value=-3, max_value=3)),
    st.floats(min_value=0.1, max_value=10),
)
def test_metric_energy_is_the_cartesian_energy_of_any_jacobian(
    entries: list[float], rates: tuple[float, float], mass: float
) -> None:
    """For any invertible Jacobian J the kinetic energy of the metric g = J^T J at the rates q'
    is M |J q'|^2/2 (12.31): the energy depends on the coordinates only through g. In polar
    coordinates it is the polar Lagrangian M (r'^2 + r^2 phi'^2)/2 (12.32). A metric that is
    not positive definite is refused."""
    j = [entries[:2], entries[2:]]
    det = j[0][0] * j[1][1] - j[0][1] * j[1][0]
    if abs(det) < 1e-2:
        return
    g = [[sum(j[k][m] * j[k][n] for k in range(2)) for n in range(2)] for m in range(2)]
    g[1][0] = g[0][1]
    v = [sum(j[k][m] * rates[m] for m in range(2)) for k in range(2)]
    want = mass * (v[0] ** 2 + v[1] ** 2) / 2
    size = mass * sum(x * x for x in entries) * sum(x * x for x in rates)
    assert abs(lagrange.metric_kinetic_energy(mass, g, rates) - want) <= 1e-9 * (size + 1e-12)
    r, phi = 0.5 + abs(entries[0]), entries[1]
    polar = lagrange.metric_kinetic_energy(mass, lagrange.polar_metric(r, phi), rates)
    assert_close(polar, lagrange.polar_lagrangian(mass, r, rates[0], rates[1], 0, phi), abs=FLOOR)
    with pytest.raises(ValueError, match="positive definite"):
        lagrange.metric_kinetic_energy(mass, [[1.0, 2.0], [2.0, 1.0]], rates)
