"""Quantum and relativistic scales quoted in the front matter (book lines 51-907).

The front matter measures its subject against three scales of modern physics:

- the energy of one photon, E = h nu (the book's E = h upsilon, line 557; a green photon,
  line 904);
- the speed of a particle whose total energy far exceeds its rest energy (the LHC protons
  "above 0.999999c at several TeV", line 902);
- the size of a quantum description of a classical collision (the "10^40 byte computers" of
  line 65): the number of quantum states in the phase-space region a classical motion covers,
  one state per cell of volume h^f for f degrees of freedom (the semiclassical, Weyl count).

SI units in, SI out, or any consistent set (an energy ratio needs only the same unit for both).
Floats and ``fractions.Fraction`` inputs; ``photon_energy`` is exact for Fractions, the others
take square roots in floating point (``math.sqrt``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.typing import Real


def photon_energy(frequency: Real, planck_constant: Real) -> Real:
    """Energy of one photon of light of ``frequency`` (Hz): E = h nu, in J (line 557).

    Linear in the frequency; exact for Fraction inputs.
    """
    inputs.positive(frequency, "frequency")
    inputs.positive(planck_constant, "planck_constant")
    return planck_constant * frequency


def speed_fraction(energy: Real, rest_energy: Real) -> float:
    """Speed as a fraction of c, beta = v/c, of a particle of total ``energy`` and
    ``rest_energy`` (= m c^2, same unit): E = gamma m c^2 with gamma = 1/sqrt(1 - beta^2), so
    beta = sqrt(1 - (m c^2 / E)^2) (line 902).

    The total energy cannot be below the rest energy: ``ValueError``.
    """
    inputs.positive(energy, "energy")
    inputs.positive(rest_energy, "rest_energy")
    if energy < rest_energy:
        raise ValueError(
            f"total energy {energy!r} is below the rest energy {rest_energy!r}: no speed"
        )
    ratio = rest_energy / energy
    return math.sqrt((1 - ratio) * (1 + ratio))


def one_ball_state_count(mass: Real, energy: Real, length: Real, planck_constant: Real) -> float:
    """Number of quantum states of one ball of ``mass`` (kg) moving on a line of ``length``
    (m) with kinetic energy up to ``energy`` (J): the phase-space area 2 L sqrt(2 m E) of the
    classical motion divided by h (one state per cell of area h)."""
    inputs.mass(mass, "mass")
    inputs.positive(energy, "energy")
    inputs.positive(length, "length")
    inputs.positive(planck_constant, "planck_constant")
    return 2 * length * math.sqrt(2 * mass * energy) / planck_constant


@dataclass(frozen=True)
class WavefunctionSize:
    """The quantum description of a two-ball collision on a line.

    ``states``: number of quantum states of the two balls (dimensionless); ``bytes``: memory to
    hold one complex amplitude per state, the wavefunction psi(x1, x2) of the collision.
    """

    states: float
    bytes: float


def two_ball_wavefunction_size(
    mass1: Real,
    mass2: Real,
    energy: Real,
    length: Real,
    planck_constant: Real,
    bytes_per_amplitude: int,
) -> WavefunctionSize:
    """Size of the quantum description of two balls of ``mass1`` and ``mass2`` (kg) colliding on
    a line of ``length`` (m) with total kinetic energy up to ``energy`` (J) (line 65).

    The classical motion fills the phase-space region 0 <= x1, x2 <= L and
    p1^2/2m1 + p2^2/2m2 <= E: a square of side L times an ellipse of semi-axes sqrt(2 m1 E) and
    sqrt(2 m2 E), of volume 2 pi E L^2 sqrt(m1 m2). One quantum state per cell h^2 gives
    ``states``; ``bytes_per_amplitude`` bytes per complex amplitude (16 for two doubles) gives
    ``bytes``.
    """
    inputs.mass(mass1, "mass1")
    inputs.mass(mass2, "mass2")
    inputs.positive(energy, "energy")
    inputs.positive(length, "length")
    inputs.positive(planck_constant, "planck_constant")
    per_state = inputs.count(bytes_per_amplitude, "bytes_per_amplitude", minimum=1)
    volume = 2 * math.pi * energy * length**2 * math.sqrt(mass1 * mass2)
    states = volume / planck_constant**2
    return WavefunctionSize(states=states, bytes=states * per_state)
