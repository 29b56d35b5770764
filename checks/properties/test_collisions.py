"""Laws of the one-dimensional collision (mechmodel.collisions): chapters 2-4.

Floats are compared within 1e-12 of the sum of the magnitudes involved; Fraction inputs must
give exact equality. Chapter 2 adds Galilean frames and reversal (Figs. 2.3-2.5), chapter 3
the energy ellipses, the Ka-whump on a reduced ellipse and the tensor forms (3.9)-(3.14).
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import assume, example, given, target
from hypothesis import strategies as st

from checks.properties.closeness import assert_close, real, reals
from checks.properties.strategies import (
    angles,
    exact_masses,
    exact_restitutions,
    exact_symmetric_matrices,
    exact_velocities,
    exact_velocity_pairs,
    fraction_masses,
    fraction_restitutions,
    fraction_velocities,
    masses,
    restitutions,
    velocities,
)
from mechmodel.collisions import (
    center_of_mass_velocity,
    collide,
    collide_in_frame,
    collide_reversed,
    collide_to_energy,
    collision_tensor_forms,
    com_frame,
    elastic_com_velocity,
    elastic_final_velocity,
    ellipse_radii,
    ellipse_tensor_form,
    energy_ellipse,
    energy_ellipse_form,
    inertia_coefficient_count,
    inertia_tensor,
    kinetic_energy,
    kinetic_energy_change,
    momentum,
    momentum_change,
    momentum_exchange_step,
    momentum_line_partner,
    momentum_line_slope,
    shift_frame,
    tensor_energy_forms,
    tensor_form,
    time_reversed,
    total_mass,
    velocity_in_si,
    velocity_reversed,
)
from mechmodel.ellipse import ellipse_point

pytestmark = pytest.mark.properties
REL = 1e-12
FLOOR = 1e-300  # below this, subnormal products carry no relative precision: an absolute floor


@given(masses(), masses(), velocities(), velocities(), restitutions())
@example(4.0, 1.0, 60.0, 10.0, 0.0)  # the SUV/VW Ka-runch of Fig. 2.1
@example(4.0, 1.0, 60.0, 10.0, 1.0)  # and its Ka-bong
def test_momentum_is_conserved_for_any_restitution(
    m1: float, m2: float, v1: float, v2: float, e: float
) -> None:
    """P = m1 v1 + m2 v2 is the same after any collision (2.1), whatever the restitution."""
    hit = collide(m1, m2, v1, v2, e)
    before = m1 * v1 + m2 * v2
    scale = abs(m1 * v1) + abs(m2 * v2) + abs(m1 * real(hit.v1)) + abs(m2 * real(hit.v2))
    error = abs(hit.momentum - before)
    target(error / scale if scale else 0.0, label="relative momentum error")
    assert error <= REL * scale + FLOOR


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
    assert collide(m2, m1, v2, v1, e).after == (hit.v2, hit.v1)  # the labels 1, 2 are arbitrary


@given(
    st.lists(st.tuples(fraction_masses(), fraction_velocities()), min_size=1, max_size=4),
    st.integers(min_value=0, max_value=3),
)
def test_momentum_and_energy_are_sums_over_the_bodies(
    bodies: list[tuple[Fraction, Fraction]], bad: int
) -> None:
    """P = sum m v (2.5a), KE = sum 1/2 m v^2 (3.5b) and M_TOTAL = sum m (Fig. 2.1): at unit
    velocity the momentum is the total mass; a body with a non-positive mass or a non-finite
    velocity is refused, naming its index."""
    ms = [m for m, _ in bodies]
    vs = [v for _, v in bodies]
    assert momentum(ms, vs) == sum(m * v for m, v in bodies)
    assert kinetic_energy(ms, vs) == sum(m * v * v for m, v in bodies) / 2
    assert total_mass(ms) == momentum(ms, [1] * len(ms)) == sum(ms)
    k = bad % len(bodies)
    with pytest.raises(ValueError, match=rf"masses\[{k}\]"):
        momentum([-m if i == k else m for i, m in enumerate(ms)], vs)
    with pytest.raises(ValueError, match=rf"masses\[{k}\]"):
        total_mass([-m if i == k else m for i, m in enumerate(ms)])
    with pytest.raises(ValueError, match=rf"velocities\[{k}\]"):
        kinetic_energy(ms, [math.inf if i == k else v for i, v in enumerate(vs)])


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
    error = abs(float(hit.ke_after - hit.ke_before))
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
    after = center_of_mass_velocity((m1, m2), reals(hit.after))
    assert math.isclose(after, before, rel_tol=REL, abs_tol=REL * (abs(v1) + abs(v2)))


@given(velocities(), velocities(), restitutions(), masses())
def test_a_wall_keeps_its_velocity(u: float, v: float, e: float, m: float) -> None:
    """An infinite mass keeps its velocity; the ball leaves at u + e (u - v)."""
    hit = collide(math.inf, m, u, v, e)
    assert hit.v1 == u
    assert math.isclose(real(hit.v2), u + e * (u - v), rel_tol=REL, abs_tol=REL * (abs(u) + abs(v)))
    mirrored = collide(m, math.inf, v, u, e)  # the wall as body 2
    assert mirrored.after == (hit.v2, hit.v1)
    assert hit.com_velocity == mirrored.com_velocity == u


def F(*values: int) -> tuple[Fraction, ...]:
    """Exact book values for @example."""
    return tuple(Fraction(v) for v in values)


# -- Galilean frames (Figs. 2.3-2.5) ----------------------------------------------------------


@given(
    exact_masses(),
    exact_masses(),
    exact_velocities(),
    exact_velocities(),
    exact_velocities(),
    exact_restitutions(),
)
@example(*F(4, 1, 60, 10, 50, 1))  # the cop frame of Fig. 2.4
def test_a_collision_is_galilean_covariant_exactly(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, u: Fraction, e: Fraction
) -> None:
    """Shifting every velocity by -u before colliding equals shifting the result by -u: the
    frame view is the Earth view slid down the 45° line (Galilean relativity, Fig. 2.5)."""
    hit = collide(m1, m2, v1, v2, e)
    seen = collide_in_frame(m1, m2, v1, v2, u, e)
    assert (
        seen.after == collide(m1, m2, v1 - u, v2 - u, e).after == shift_frame(reals(hit.after), u)
    )
    assert seen.before == shift_frame(hit.before, u)
    assert collide_in_frame(m1, m2, v1, v2, u) == collide_in_frame(m1, m2, v1, v2, u, 1)


@given(masses(), masses(), velocities(), velocities(), velocities(), restitutions())
def test_a_collision_is_galilean_covariant(
    m1: float, m2: float, v1: float, v2: float, u: float, e: float
) -> None:
    """The float collision commutes with a frame shift v -> v + u to rounding error (Fig. 2.5)."""
    shifted_first = collide(m1, m2, v1 + u, v2 + u, e)
    hit = collide(m1, m2, v1, v2, e)
    w1, w2 = float(real(hit.v1)), float(real(hit.v2))
    scale = abs(v1) + abs(v2) + 2 * abs(u) + abs(w1) + abs(w2)
    assert_close(shifted_first.v1, hit.v1 + u, scale=scale, abs=FLOOR)
    assert_close(shifted_first.v2, hit.v2 + u, scale=scale, abs=FLOOR)


@given(
    exact_masses(),
    exact_masses(),
    exact_velocities(),
    exact_velocities(),
    exact_velocities(),
    exact_restitutions(),
)
@example(*F(4, 1, 60, 10, 50, 0))  # 1,000 lost in the Earth and the COM frame
def test_the_energy_lost_is_the_same_in_every_frame(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, u: Fraction, e: Fraction
) -> None:
    """The crunch energy is frame independent: 1,000 units in the Earth frame and in the COM
    frame for the SUV/VW Ka-runch (line 2415: Galilean symmetry of the "cost" of damage)."""
    assert collide_in_frame(m1, m2, v1, v2, u, e).ke_lost == collide(m1, m2, v1, v2, e).ke_lost


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities())
@example(*F(4, 1, 60, 10))  # ECOM = 1,000 of (3.8)
def test_the_com_frame_holds_no_momentum_and_the_ka_runch_energy(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """In the COM frame P = 0 and the kinetic energy, 1/2 mu (v1 - v2)^2, is KE - IE: all a
    Ka-runch can lose (ECOM = 7,250 - 6,250 = 1,000 of (3.8))."""
    frame = com_frame(m1, m2, v1, v2)
    assert momentum((m1, m2), frame.velocities) == 0
    v = frame.com_velocity
    assert frame.speeds == (abs(v1 - v), abs(v2 - v))
    assert m1 * frame.speeds[0] == m2 * frame.speeds[1]  # equal and opposite momenta
    assert frame.energy == m1 * m2 / (m1 + m2) * (v1 - v2) ** 2 / 2
    assert frame.energy == collide(m1, m2, v1, v2, 0).ke_lost


# -- the IN-FIN balance (3.4), (4.1) and the KE it derives (3.5a) -------------------------------


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities())
@example(*F(4, 1, 60, 10))  # (60, 10) -> (40, 90) about V_COM = 50 (Fig. 2.2)
def test_an_elastic_bang_reflects_each_velocity_about_v_com_exactly(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """An elastic bang takes each body from v to 2 V_COM - v ((4.1), (4.3)), whatever the
    masses, and V_COM is the IN-FIN average of either body (3.4): the wall model of
    ``elastic_final_velocity`` and the root of ``elastic_com_velocity`` agree with the
    collision law."""
    hit = collide(m1, m2, v1, v2, 1)
    v = center_of_mass_velocity((m1, m2), (v1, v2))
    assert elastic_final_velocity(v1, v) == hit.v1
    assert elastic_final_velocity(v2, v) == hit.v2
    assert elastic_com_velocity(v1, real(hit.v1)) == v == elastic_com_velocity(v2, real(hit.v2))


@given(velocities(), velocities())
def test_the_com_velocity_of_a_bounce_undoes_the_bounce(v: float, u: float) -> None:
    """The frame velocity found from (v_in, v_fin) is the one that gives v_fin back (floats,
    to rounding): the two functions are inverse in their second argument."""
    fin = elastic_final_velocity(v, u)
    assert_close(elastic_com_velocity(v, fin), u, scale=4 * (abs(v) + abs(u)), abs=FLOOR)
    assert_close(
        elastic_final_velocity(v, elastic_com_velocity(v, u)),
        u,
        scale=4 * (abs(v) + abs(u)),
        abs=FLOOR,
    )


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities(), exact_restitutions())
@example(*F(4, 1, 60, 10, 1))  # 1/2 4 (40^2 - 60^2) = -4000 = -(1/2 1 (90^2 - 10^2))
def test_the_product_of_3_3_and_3_4_is_the_change_of_kinetic_energy(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, e: Fraction
) -> None:
    """A body's IN-FIN average velocity (3.4) times its momentum change (3.3) is the change
    of its kinetic energy, and the two bodies' changes add up to minus the energy lost:
    nothing for an elastic bang, so the FIN-sum equals the IN-sum (3.5a)."""
    hit = collide(m1, m2, v1, v2, e)
    changes = [
        kinetic_energy_change(m, v_in, v_fin)
        for m, v_in, v_fin in zip(reals(hit.masses), hit.before, reals(hit.after), strict=True)
    ]
    for change, m, v_in, v_fin in zip(changes, hit.masses, hit.before, hit.after, strict=True):
        assert change == (v_in + v_fin) / 2 * (m * v_fin - m * v_in)
    assert sum(changes) == -hit.ke_lost
    if e == 1:
        assert changes[0] == -changes[1]


@given(masses(), masses(), velocities(), velocities(), angles())
@example(4.0, 1.0, 60.0, 10.0, 0.0)  # the KE = 7,250 ellipse of Fig. 3.1
def test_the_ellipse_forms_are_one_on_the_ellipse(
    m1: float, m2: float, v1: float, v2: float, angle: float
) -> None:
    """The left side of (3.7a) is 1 at the point whose energy is KE, and at every point
    (a cos s, b sin s) of the ellipse of radii (3.7b); so is the tensor form r.M.r of (3.15)
    with M = diag(1/a^2, 1/b^2)."""
    ke = kinetic_energy((m1, m2), (v1, v2))
    assume(ke > 0)
    assert_close(energy_ellipse_form(m1, m2, ke, v1, v2), 1, scale=4, abs=FLOOR)
    a, b = ellipse_radii(m1, m2, ke)
    x, y = ellipse_point(a, b, angle)
    assert_close(energy_ellipse_form(m1, m2, ke, x, y), 1, scale=8, abs=FLOOR)
    assert_close(ellipse_tensor_form(x, y, a, b), 1, scale=8, abs=FLOOR)
    assert_close(ellipse_tensor_form(v1, v2, a, b), 1, scale=8, abs=FLOOR)


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities(), exact_masses())
def test_the_ellipse_forms_scale_as_energies_exactly(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, energy: Fraction
) -> None:
    """(3.7a) at a point is its kinetic energy over KE; (3.15) at (x, y) is x^2/a^2 + y^2/b^2,
    1 at (a, 0) and (0, b) and the form of (3.7a) when a^2 = 2 KE/m1, b^2 = 2 KE/m2."""
    ratio = energy_ellipse_form(m1, m2, energy, v1, v2)
    assert ratio == kinetic_energy((m1, m2), (v1, v2)) / energy
    a, b = m1, m2  # any positive radii
    assert ellipse_tensor_form(v1, v2, a, b) == v1 * v1 / (a * a) + v2 * v2 / (b * b)
    assert ellipse_tensor_form(a, 0, a, b) == 1 == ellipse_tensor_form(0, b, a, b)
    square_a, square_b = 2 * energy / m1, 2 * energy / m2
    assert v1 * v1 / square_a + v2 * v2 / square_b == ratio
    with pytest.raises(ValueError, match="positive"):
        energy_ellipse_form(m1, m2, 0, v1, v2)
    with pytest.raises(ValueError, match="positive"):
        ellipse_tensor_form(v1, v2, 0, b)


# -- reversal (Figs. 2.2-2.4) ---------------------------------------------------------------


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities())
@example(*F(4, 1, 10, -40))  # the cop-frame Ka-bong of Fig. 2.4
def test_an_elastic_collision_is_time_reversible_exactly(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """Reversing the outgoing velocities and colliding again gives back the reversed incoming
    ones: the reversed video of an elastic bump is an ordinary bump (Figs. 2.2 and 2.4)."""
    back = time_reversed(collide(m1, m2, v1, v2, 1))
    assert collide(m1, m2, *back.before, 1).after == back.after == (-v1, -v2)


@given(masses(), masses(), velocities(), velocities())
def test_an_elastic_collision_is_time_reversible(
    m1: float, m2: float, v1: float, v2: float
) -> None:
    """The float elastic collision reverses to rounding error (Fig. 2.4)."""
    hit = collide(m1, m2, v1, v2)
    w1, w2 = float(real(hit.v1)), float(real(hit.v2))
    again = collide(m1, m2, -w1, -w2)
    scale = 2 * (abs(v1) + abs(v2) + abs(w1) + abs(w2))
    assert_close(again.v1, -v1, scale=scale, abs=FLOOR)
    assert_close(again.v2, -v2, scale=scale, abs=FLOOR)


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities(), exact_restitutions())
@example(*F(4, 1, 60, 10, 0))  # the Ka-runch of Fig. 2.1
def test_an_inelastic_collision_does_not_reverse(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, e: Fraction
) -> None:
    """With e < 1 and a relative velocity, colliding the reversed outgoing velocities does not
    give back the reversed incoming ones: no "un-crash" (Fig. 2.1, line 1996)."""
    e = e if e < 1 else Fraction(1, 2)  # inelastic, and with a relative velocity
    v2 = v2 if v2 != v1 else v1 + 1
    hit = collide(m1, m2, v1, v2, e)
    assert collide(m1, m2, -real(hit.v1), -real(hit.v2), e).after != (-v1, -v2)


@given(
    exact_masses(),
    exact_masses(),
    exact_velocities(),
    exact_velocities(),
    exact_velocities(),
    exact_restitutions(),
)
@example(*F(4, 1, 60, 10, 50, 1))  # (-10, 40) -> (10, -40), line 2041
def test_reversed_velocities_collide_into_reversed_results(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, u: Fraction, e: Fraction
) -> None:
    """Reflecting IN through the COM point (V -> -V) reflects FIN too, for any restitution: the
    reversed cop-frame Ka-bong (-10, 40) -> (10, -40) of line 2041."""
    forward = collide_in_frame(m1, m2, v1, v2, u, e)
    assert collide_reversed(m1, m2, v1, v2, u, e) == velocity_reversed(forward)
    earth = velocity_reversed(collide(m1, m2, v1, v2))  # the Earth frame, elastic: the defaults
    assert collide_reversed(m1, m2, v1, v2) == earth


# -- the momentum line (Figs. 2.1, 2.6, (2.4), (3.6)) ----------------------------------------


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities(), exact_restitutions())
@example(*F(4, 1, 60, 10, 0))  # slope -4/1 of Fig. 2.1
def test_a_collision_moves_along_the_momentum_line(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, e: Fraction
) -> None:
    """IN -> FIN keeps Delta P_Total = 0 (2.3) and has slope Delta V2/Delta V1 = -m1/m2 (2.4),
    the direction of the zero-sum step (-m2, m1) (the -1:4 of Fig. 2.6a)."""
    v2 = v2 if v2 != v1 else v1 + 1  # a relative velocity: a drawn tie is moved apart
    hit = collide(m1, m2, v1, v2, e)
    assert momentum_change((m1, m2), hit.before, reals(hit.after)) == 0
    d1, d2 = momentum_exchange_step(m1, m2)
    assert m1 * d1 + m2 * d2 == 0
    assert (hit.v2 - v2) / (hit.v1 - v1) == d2 / d1 == momentum_line_slope(m1, m2)


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities(), exact_velocities())
@example(*F(4, 1, 60, 10, 70))  # (70, -30) of Fig. 2.6a
def test_every_point_of_the_momentum_line_has_the_same_weighted_average(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, u1: Fraction
) -> None:
    """The m1:m2-weighted average of each point of the momentum line is V_COM (2.5b): (40,90),
    (50,50), (60,10), (70,-30) all average 50 with weights 4:1 (Fig. 2.6a)."""
    u2 = momentum_line_partner(m1, m2, v1, v2, u1)
    average = center_of_mass_velocity((m1, m2), (v1, v2))
    assert center_of_mass_velocity((m1, m2), (u1, u2)) == average


# -- energy ellipses (Fig. 3.1, (3.7), Exercise Figs. 3.6-3.7) ------------------------------


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities())
@example(*F(4, 1, 60, 10))  # slope -4 at (50, 50), slope 1 on the ECOM(10, 40) ellipse
@example(*F(1, 1, 3, -1))  # the COM point (1, 1)
def test_the_tangents_of_fig_3_1_are_dual(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """The ellipse through the COM point (V, V) is tangent there to the momentum line (slope
    -m1/m2), and the COM-frame ellipse is tangent to the 45° COM line (slope 1) where the
    momentum line cuts it (Fig. 3.1, lines 2419-2421). Where V2 = 0 the tangent is vertical."""
    v2 = v2 if v2 != v1 else v1 + 1  # a relative velocity: a drawn tie is moved apart
    v = center_of_mass_velocity((m1, m2), (v1, v2))
    if v != 0:
        ellipse = energy_ellipse(m1, m2, v, v)
        assert ellipse.tangent_slope == momentum_line_slope(m1, m2) == -m1 / m2
    assert com_frame(m1, m2, v1, v2).ellipse.tangent_slope == 1
    with pytest.raises(ValueError, match="vertical"):
        energy_ellipse(m1, m2, v1, 0).tangent_slope  # noqa: B018 - the property raises


# -- the Ka-whump on a reduced ellipse (Fig. 3.2) --------------------------------------------


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities(), exact_restitutions())
@example(*F(6, 1, 3, -4), Fraction(2, 3))  # Fig. 3.2b: E_whump = 23 1/3, E_loss = 11 2/3
@example(*F(4, 1, 60, 10, 0))  # the Ka-runch of Fig. 2.1: the ellipse shrinks to the COM point
@example(*F(1, 1, 1, -1), Fraction(1, 2))  # ECOM = 1
@example(*F(1, 1, 1, 1), Fraction(1, 2))  # no relative velocity: nothing collides
def test_the_reduced_ellipse_gives_back_the_restitution_exactly(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, e: Fraction
) -> None:
    """A collision of restitution e ends on the ellipse IE + e^2 ECOM; collide_to_energy on that
    ellipse recovers e and the same FIN point, and loses (1 - e^2) ECOM (Fig. 3.2). The
    pass-through point is the rebound's mirror image through the COM point (V, V). Without a
    relative velocity (ECOM = 0) there is no collision to choose."""
    hit = collide(m1, m2, v1, v2, e)
    if v1 == v2:
        with pytest.raises(ValueError, match="no relative velocity"):
            collide_to_energy(m1, m2, v1, v2, hit.ke_after)
        return
    whump = collide_to_energy(m1, m2, v1, v2, hit.ke_after)
    assert whump.restitution == e
    assert whump.rebound == hit
    frame = com_frame(m1, m2, v1, v2)
    assert whump.ke_lost == (1 - e * e) * frame.energy
    assert whump.pass_through.before == (v1, v2)
    v = frame.com_velocity
    assert [r + p for r, p in zip(hit.after, whump.pass_through.after, strict=True)] == [2 * v] * 2


@given(masses(), masses(), velocities(), velocities(), restitutions())
@example(4.0, 1.0, 60.0, 10.0, 0.0)  # the Ka-runch: both points are the COM point
@example(10.0, 1.0, 3.0, 0.0, 1.0)  # all the energy: IE + E_COM rounds to just under KE
def test_both_ka_whump_points_lie_on_the_momentum_line_and_the_reduced_ellipse(
    m1: float, m2: float, v1: float, v2: float, share: float
) -> None:
    """The momentum line cuts the reduced ellipse at F_whump (rebound) and F_pass-thru: both
    keep P_Total and both have the chosen energy (Fig. 3.2b, line 2433)."""
    frame = com_frame(m1, m2, v1, v2)
    assume(frame.energy > 0)
    kept = kinetic_energy((m1, m2), (frame.com_velocity, frame.com_velocity))
    energy = kept + share * frame.energy
    whump = collide_to_energy(m1, m2, v1, v2, energy)
    assert 0 <= whump.restitution <= 1
    p = abs(m1 * v1) + abs(m2 * v2)
    for end in (whump.rebound, whump.pass_through):
        scale = p + abs(m1 * real(end.v1)) + abs(m2 * real(end.v2))
        assert_close(end.momentum, m1 * v1 + m2 * v2, scale=scale, abs=FLOOR)
        assert_close(end.ke_after, energy, scale=4 * whump.ke_before, abs=FLOOR)


# -- tensor forms ((3.9)-(3.14)) -------------------------------------------------------------


@given(st.integers(min_value=1, max_value=12))
def test_a_full_inertia_matrix_has_n_squared_coefficients(n: int) -> None:
    """The inertia matrix of n bodies is n x n: n^2 coefficients M_jk ((3.9a) to (3.9b)), of
    which the diagonal ones are the masses; no dimension below 1."""
    assert inertia_coefficient_count(n) == n * n
    masses = [Fraction(j + 1) for j in range(n)]
    tensor = inertia_tensor(masses)
    assert [tensor[j][j] for j in range(n)] == masses
    with pytest.raises(ValueError, match="at least 1"):
        inertia_coefficient_count(0)


@given(exact_symmetric_matrices(), exact_velocity_pairs(), exact_velocity_pairs())
def test_line_one_of_3_12a_holds_for_any_symmetric_inertia(
    inertia: tuple[tuple[Fraction, ...], ...],
    v_in: tuple[Fraction, Fraction],
    v_fin: tuple[Fraction, Fraction],
) -> None:
    """With V_COM = (V_IN + V_FIN)/2 (3.4) and M_jk = M_kj, V_FIN.M.V_IN = V_IN.M.V_FIN and
    V_COM.M.V_IN - V_FIN.M.V_IN/2 = V_IN.M.V_IN/2 (3.12a): transpose symmetry is what makes
    the energy form work."""
    v_com = tuple((a + b) / 2 for a, b in zip(v_in, v_fin, strict=True))
    forms = tensor_energy_forms(inertia, v_in, v_fin, v_com)
    assert forms.cross == forms.cross_transposed
    assert forms.ke_from_com == forms.ke_in


@given(exact_masses(), exact_masses(), exact_velocities(), exact_velocities())
@example(*F(4, 1, 60, 10))  # 12,500, 10,500, 7,250, 6,250 = 3,625 + 2,625, 1,000
def test_the_tensor_forms_of_an_elastic_collision(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """With the diagonal M of (3.9a), V.M.V = 2 KE and (1, 1).M.V = P; for an elastic collision
    KE is the same at IN and FIN (3.12c), V_COM P/2 = IE = quarter_in + quarter_cross (3.13),
    and KE - IE = quarter_in - quarter_cross = ECOM (3.14)."""
    inertia = inertia_tensor((m1, m2))
    assert tensor_form((v1, v2), inertia, (v1, v2)) == 2 * kinetic_energy((m1, m2), (v1, v2))
    assert tensor_form((1, 1), inertia, (v1, v2)) == momentum((m1, m2), (v1, v2))
    hit = collide(m1, m2, v1, v2, 1)
    v = center_of_mass_velocity((m1, m2), (v1, v2))
    forms = tensor_energy_forms(inertia, hit.before, reals(hit.after), (v, v))
    assert collision_tensor_forms(m1, m2, v1, v2, 1) == forms
    assert collision_tensor_forms(m1, m2, v1, v2) == forms  # elastic by default
    assert forms.ke_in == forms.ke_fin == hit.ke_before
    assert forms.com_momentum == forms.com_momentum_fin == v * momentum((m1, m2), (v1, v2))
    assert forms.half_com_momentum == forms.ie == forms.quarter_in + forms.quarter_cross
    assert forms.crunch == hit.ke_before - forms.ie == com_frame(m1, m2, v1, v2).energy


# -- units ---------------------------------------------------------------------------------


@given(exact_velocities(), exact_masses(), exact_masses())
@example(Fraction(1), Fraction(3048, 10000), Fraction(60))  # a foot per minute (Fig. 2.2)
def test_a_velocity_in_si_scales_with_its_units(
    v: Fraction, length: Fraction, duration: Fraction
) -> None:
    """v lengths per duration is v length/duration metres per second: a longer length unit
    makes it faster in proportion, a longer time unit slower (the rescaled Fig. 2.2)."""
    si = velocity_in_si(v, length, duration)
    assert si * duration == v * length
    assert velocity_in_si(v, 1, 1) == v
