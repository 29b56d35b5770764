"""Action, phase and Bohr quantization: (12.38)-(12.48), Figs. 12.12-12.15, and the starlet
blast of exercise 1.12.3.

The action S = integral L dt (12.38) of legs and of a sampled path, the phase S/hbar and its
factor e^(i S/hbar) (12.42c), the Bohr condition S_H/hbar = 2 pi upsilon (12.45), the colour
circle of the phase figures, and the paths of a 2-D isotropic oscillator from one point with one
speed in several directions with their reduced action S_H = integral p . dr (12.46); the common
speed and the turning sequence of the exercise's velocity list. Action in J s, angles in radians.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from mechmodel import inputs
from mechmodel.typing import Matrix, Real, Vector


def action_sum(legs: Vector) -> Real:
    """Action accumulated along a path made of legs, J s: the sum of the legs' actions (Fig.
    12.12: 10 to the first wave front and 10 more to the wavelet around it make 20)."""
    return sum(inputs.real(a, "action") for a in legs)


def path_action(lagrangian_values: Sequence[float], times: Sequence[float]) -> float:
    """Action S = integral L dt (12.38) of a sampled path by the trapezoid rule, J s."""
    lv, t = np.asarray(lagrangian_values, float), np.asarray(times, float)
    if lv.shape != t.shape or lv.ndim != 1 or lv.size < 2:
        raise ValueError("need matching 1-D samples of L and t, at least two")
    return float(np.sum((lv[1:] + lv[:-1]) * np.diff(t)) / 2)


def phase_turn() -> float:
    """The phase angle after which e^(i theta) first returns to 1: 2 pi, twice the angle of
    -1 (a full colour circle of Fig. 12.13)."""
    return 2 * cmath.phase(-1)


def bohr_phase(quantum_number: int) -> float:
    """Phase S_H/hbar of a Bohr-quantized closed loop, 2 pi upsilon (12.45)."""
    n = inputs.count(quantum_number, "quantum_number")
    return phase_turn() * n


def phase_factor(angle: Real) -> complex:
    """The quantum phase factor e^(i angle) (12.42c); 1 after a whole number of turns (12.45)."""
    return cmath.exp(1j * inputs.real(angle, "angle"))


@dataclass(frozen=True)
class PhaseFactorParts:
    real: float
    imag: float


def phase_factor_parts(angle: Real) -> PhaseFactorParts:
    """Real and imaginary parts of e^(i angle): the standing-wave amplitude of a phase."""
    z = phase_factor(angle)
    return PhaseFactorParts(real=z.real, imag=z.imag)


def palette_phase(step: int, colours: int) -> float:
    """Phase angle of hue ``step`` on a colour circle of ``colours`` equal hues:
    2 pi step / colours (line 16324: eight hues from red at 0 through pi/4 steps)."""
    k = inputs.count(step, "step")
    n = inputs.count(colours, "colours", minimum=1)
    return phase_turn() * k / n


def palette_amplitude(step: int, colours: int) -> float:
    """Real standing-wave amplitude cos(phase) of hue ``step`` (red 1, cyan -1: line 16340)."""
    return phase_factor_parts(palette_phase(step, colours)).real


@dataclass(frozen=True)
class OscillatorPaths:
    """Sampled trajectories of a 2-D isotropic oscillator and their accumulated reduced
    action S_H(t) = integral p . dr (12.46), for phase colouring."""

    times: np.ndarray
    x: np.ndarray  # shape (paths, samples)
    y: np.ndarray
    action: np.ndarray


def oscillator_paths(
    start: Sequence[float],
    speed: float,
    angles: Iterable[float],
    duration: float,
    samples: int = 400,
    omega: float = 1,
    mass: float = 1,
) -> OscillatorPaths:
    """Paths r(t) = r0 cos(w t) + (v0/w) sin(w t) of the oscillator U = M w^2 r^2/2 from one
    point with one speed in several directions (the starlet blast of exercise 1.12.3), and
    S_H = integral p . v dt along each by the trapezoid rule."""
    inputs.positive(speed, "speed")
    inputs.positive(duration, "duration")
    inputs.positive(omega, "omega")
    inputs.mass(mass)
    n = inputs.count(samples, "samples", minimum=2)
    t = np.linspace(0.0, duration, n)
    xs, ys, acts = [], [], []
    for a in angles:
        vx, vy = speed * math.cos(a), speed * math.sin(a)
        x = start[0] * np.cos(omega * t) + vx / omega * np.sin(omega * t)
        y = start[1] * np.cos(omega * t) + vy / omega * np.sin(omega * t)
        ux = -start[0] * omega * np.sin(omega * t) + vx * np.cos(omega * t)
        uy = -start[1] * omega * np.sin(omega * t) + vy * np.cos(omega * t)
        integrand = mass * (ux**2 + uy**2)
        s = np.concatenate([[0.0], np.cumsum((integrand[1:] + integrand[:-1]) * np.diff(t) / 2)])
        xs.append(x)
        ys.append(y)
        acts.append(s)
    return OscillatorPaths(times=t, x=np.array(xs), y=np.array(ys), action=np.array(acts))


def common_speed(velocities: Matrix) -> float:
    """The speed |v| shared by all the listed velocity vectors (exercise 1.12.3: fragments
    flying off with one speed in various directions); ``ValueError`` if they differ."""
    speeds = [math.hypot(*(float(inputs.real(c, "component")) for c in v)) for v in velocities]
    if not speeds:
        raise ValueError("no velocities")
    if max(speeds) - min(speeds) > 1e-9 * max(speeds):
        raise ValueError(f"the velocities have different speeds {speeds}")
    return sum(speeds) / len(speeds)


def turning_sequence(first: Vector, second: Vector, index: int) -> tuple[float, float]:
    """The plane vector number ``index`` (0 for ``first``) of the sequence that starts with
    ``first`` and ``second`` and turns (and scales) each next vector from the last as
    ``second`` is turned from ``first``: first * (second / first)^index as complex numbers
    (exercise 1.12.3 lists unit velocities 45 degrees apart). Floats."""
    k = inputs.count(index, "index")
    a = complex(*(float(inputs.real(c, "component")) for c in first))
    b = complex(*(float(inputs.real(c, "component")) for c in second))
    if a == 0:
        raise ValueError("the first vector must be non-zero")
    z = a * (b / a) ** k
    return z.real, z.imag
