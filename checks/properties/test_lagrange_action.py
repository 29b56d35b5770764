"""Laws of action and phase (mechmodel.lagrange.action): chapter 12, (12.38)-(12.48),
Figs. 12.12-12.15, exercise 1.12.3.

Bohr's phase, the action of oscillator loops (by the trapezoid rule) and of uniform motion,
the refocusing oscillator paths, palette hues, the common speed of fragments and the
turning sequence.

Floats are compared within 1e-12 of the sum of the magnitudes involved, or within the
error of the trapezoid rule. Tolerances shared by the lagrange modules are in
``_lagrange_helpers``.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from checks.properties._lagrange_helpers import FLOOR, REL
from checks.properties.closeness import assert_close
from mechmodel import lagrange

pytestmark = pytest.mark.properties


@given(st.integers(0, 50))
def test_bohr_phase_factor_is_one(n: int) -> None:
    """e^(i 2 pi upsilon) = 1 for every integer quantum number upsilon (12.45)."""
    z = lagrange.phase_factor(lagrange.bohr_phase(n))
    assert abs(z - 1) <= 1e-15 * (1 + 2 * math.pi * n)


@settings(max_examples=50)
@given(
    st.floats(min_value=0.1, max_value=3),
    st.floats(min_value=-3, max_value=3),
    st.floats(min_value=0, max_value=3),
    st.floats(min_value=0, max_value=6.283),
    st.floats(min_value=0.2, max_value=5),
    st.floats(min_value=0.2, max_value=5),
)
@example(1.0, 0.0, 1.0, 0.0, 1.0, 1.0)  # the book's scaled units omega = M = 1
def test_oscillator_loop_action_is_two_pi_energy_over_omega(
    x0: float, y0: float, speed: float, angle: float, omega: float, mass: float
) -> None:
    """Over one period 2 pi/omega of the 2-D oscillator U = M omega^2 r^2/2 the reduced action
    S_H = integral p . dr = integral 2T dt is 2 pi E/omega (virial theorem: mean T = E/2), the
    loop action Bohr quantizes in (12.45); omega = M = 1 are the defaults. Along the way
    S_H(t) = integral L dt + E t (12.46) with integral L dt = M (r.v - r0.v0)/2 (as
    d(r.v)/dt = v^2 - omega^2 r^2), so a quarter period in S_H = E T/4 - M r0.v0."""
    if speed == 0:
        speed = 1e-3
    period = 2 * math.pi / omega
    start = (x0, y0)
    paths = lagrange.oscillator_paths(
        start, speed, [angle], period, samples=2001, omega=omega, mass=mass
    )
    e = mass * (speed**2 + omega**2 * (x0**2 + y0**2)) / 2
    assert abs(paths.action[0, -1] - 2 * math.pi * e / omega) <= 1e-9 * (1 + e) * period
    r0_v0 = x0 * speed * math.cos(angle) + y0 * speed * math.sin(angle)
    quarter = e * period / 4 - mass * r0_v0
    assert abs(paths.action[0, 500] - quarter) <= 1e-5 * (e * period + mass * abs(r0_v0) + 1e-3)
    if omega == mass == 1:
        default = lagrange.oscillator_paths(start, speed, [angle], period, samples=2001)
        assert (default.action == paths.action).all()


@given(
    st.floats(min_value=-3, max_value=3),
    st.floats(min_value=-3, max_value=3),
    st.floats(min_value=0.1, max_value=3),
    st.floats(min_value=0, max_value=6.283),
    st.floats(min_value=0.2, max_value=5),
)
def test_oscillator_paths_refocus_every_half_period(
    x0: float, y0: float, speed: float, angle: float, omega: float
) -> None:
    """r(t) = r0 cos(omega t) + (v0/omega) sin(omega t) (the starlet blast of exercise 1.12.3,
    U = M omega^2 r^2/2): every fragment starts at r0, is at v0/omega a quarter period later,
    at -r0 (the blast refocuses at the antipode) after half a period, and back at r0 after a
    whole one, whatever its direction."""
    period = 2 * math.pi / omega
    angles = [angle, angle + math.pi / 2]
    paths = lagrange.oscillator_paths((x0, y0), speed, angles, period, samples=5, omega=omega)
    assert paths.times.tolist() == pytest.approx([k * period / 4 for k in range(5)], rel=REL)
    scale = abs(x0) + abs(y0) + speed / omega
    for k, a in enumerate(angles):
        reach = (speed * math.cos(a) / omega, speed * math.sin(a) / omega)
        want = [(x0, y0), reach, (-x0, -y0), (-reach[0], -reach[1]), (x0, y0)]
        for j, (wx, wy) in enumerate(want):
            assert abs(paths.x[k, j] - wx) <= 1e-12 * scale
            assert abs(paths.y[k, j] - wy) <= 1e-12 * scale
    half = lagrange.oscillator_paths((x0, y0), speed, angles, period / 2, samples=2, omega=omega)
    assert half.x[:, -1] == pytest.approx([-x0, -x0], abs=1e-12 * scale)  # two samples suffice
    assert half.y[:, -1] == pytest.approx([-y0, -y0], abs=1e-12 * scale)


@given(st.floats(min_value=-5, max_value=5), st.floats(min_value=0.1, max_value=5))
def test_path_action_of_uniform_motion(v: float, duration: float) -> None:
    """S = integral L dt of a free particle at constant speed is m v^2 T / 2 (12.38)."""
    times = [duration * k / 10 for k in range(11)]
    lag = [v**2 / 2] * 11
    assert_close(lagrange.path_action(lag, times), v**2 * duration / 2, abs=FLOOR)
    assert_close(lagrange.path_action(lag[:2], [0.0, duration]), v**2 * duration / 2, abs=FLOOR)
    with pytest.raises(ValueError, match="at least two"):
        lagrange.path_action(lag[:1], [0.0])


@given(st.integers(0, 100), st.integers(1, 32))
@example(1, 8)  # the first hue step of the book's eight-colour wheel (line 16324)
@example(3, 1)  # a one-colour palette
def test_palette_hues_are_roots_of_unity(step: int, colours: int) -> None:
    """The n hues of a colour circle are the phases 2 pi k/n (12.45), (line 16324): the phase
    factor of every hue raised to the n-th power is 1, and n steps on make one whole turn."""
    phase = lagrange.palette_phase(step, colours)
    turn = lagrange.palette_phase(step + colours, colours) - phase
    assert abs(turn - 2 * math.pi) <= 1e-12 * (1 + abs(phase))
    z = lagrange.phase_factor(phase)
    assert abs(z**colours - 1) <= 1e-12 * colours * (1 + abs(phase))
    assert abs(lagrange.palette_amplitude(step, colours) - z.real) <= 1e-15


@given(
    st.floats(min_value=-3, max_value=6).map(lambda k: 10.0**k),
    st.lists(st.floats(min_value=-7, max_value=7), min_size=1, max_size=6),
)
@example(1e6, [0.0, 1.0])
def test_common_speed_is_the_speed_of_every_fragment(speed: float, angles: list[float]) -> None:
    """Fragments flying off with one speed in any directions (exercise 1.12.3) share that speed:
    common_speed returns it at any scale, exactly when every |v| is the same float (3-4-5
    triangles, or all at rest); speeds differing by rounding (1e-12) are one speed, speeds
    differing by 1% are not, whatever the units: a list of different speeds is an error, not
    an average."""
    velocities = [(speed * math.cos(a), speed * math.sin(a)) for a in angles]
    assert_close(lagrange.common_speed(velocities), speed, abs=FLOOR)
    assert lagrange.common_speed([(3, 4), (-4, 3), (0, 5), (5, 0)]) == 5
    assert lagrange.common_speed([[0, 1], [1, 0], [-(2**-0.5), 2**-0.5]]) == pytest.approx(1)
    assert lagrange.common_speed([(0, 0), (0.0, 0.0)]) == 0
    rounded = lagrange.common_speed([(speed, 0.0), (0.0, speed * (1 + 1e-12))])
    assert_close(rounded, speed, rel=1e-11, abs=FLOOR)
    with pytest.raises(ValueError, match="different speeds"):
        lagrange.common_speed([(speed, 0.0), (0.0, speed * 1.01)])


# -- exercise 1.12.3: the turning sequence -----------------------------------------------------


@given(
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=-7, max_value=7),
    st.floats(min_value=-7, max_value=7),
    st.integers(0, 16),
)
@example(1.0, math.pi / 2, math.pi / 4, 2)  # exercise 1.12.3: (0,1), (1/sqrt 2, 1/sqrt 2), (1,0)
def test_turning_sequence_turns_by_one_step(
    length: float, start: float, second: float, k: int
) -> None:
    """Each vector of the sequence is the last turned by the angle from the first to the
    second: the angle grows by one step per index and, for equal lengths, the length stays."""
    first = (length * math.cos(start), length * math.sin(start))
    nxt = (length * math.cos(second), length * math.sin(second))
    x, y = lagrange.turning_sequence(first, nxt, k)
    angle = start + k * (second - start)
    assert abs(x - length * math.cos(angle)) <= 1e-12 * length * (k + 1)
    assert abs(y - length * math.sin(angle)) <= 1e-12 * length * (k + 1)
    assert lagrange.turning_sequence(first, nxt, 0) == pytest.approx(first, abs=1e-15 * length)
    assert lagrange.turning_sequence(first, nxt, 1) == pytest.approx(nxt, rel=1e-12, abs=1e-12)
    with pytest.raises(ValueError, match="non-zero"):
        lagrange.turning_sequence((0, 0), nxt, k)
