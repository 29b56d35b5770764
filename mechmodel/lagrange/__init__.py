"""Lagrangian and Hamiltonian mechanics: velocity vs momentum functions (chapter 12).

The kinetic energy written in velocities v is the Lagrangian L(v) = v.M.v/2; in the
quasi-velocities V = R.v (R = M^(1/2), the root-mass matrix) it is the "Estrangian" E(V) = V.V/2,
in momenta p = M.v the Hamiltonian H(p) = p.M^-1.p/2 ((12.1)-(12.9), Fig. 12.1). L and H are
Legendre contact transforms of each other, H(p) = p v - L(v) at p = dL/dv ((12.11)-(12.13),
Figs. 12.3-12.4). A family of projectiles of one speed v0 and all angles has a parabolic
envelope, the "volcanoes of Io" and the atomic fountain ((12.14)-(12.17), Figs. 12.5-12.6). In
polar coordinates the Jacobian, its inverse (the "Kajobian") and the metric give the Lagrangian
L = M (r'^2 + r^2 phi'^2)/2 - U, whose Lagrange equations carry the centrifugal M r phi'^2 and
Coriolis 2 M r r' phi' terms ((12.26)-(12.33)); the Hamiltonian p q' - L is the energy (12.37).
The action S = integral L dt and its phase S/hbar colour the trajectories of Figs. 12.12-12.15.

Three kinds of computation:

- **Exact algebra** for the coefficients and exponents of the formulas the book derives: Laurent
  polynomials in named variables (``mechmodel.algebra.Laurent``), differentiated,
  substituted and, for the cosine and sine of an angle, reduced with sin^2 = 1 - cos^2. Nothing
  is written in: the 1/2 of a trajectory comes from integrating g twice, the 2 of the Coriolis
  term from differentiating M r^2 phi' in time, the envelope from solving dS/d(alpha) = 0.
- **Numbers** for the geometry of the figures (slopes, Legendre tangents, trajectories and their
  envelope, Jacobians, metrics, phases) in plain operators: exact for ``int`` and ``Fraction``
  inputs where no root or trigonometric function is needed, else floats.
- **Numerical transforms**: the Legendre transform of any convex function by a bounded maximum
  (scipy), the envelope of the projectile family as the highest trajectory over all elevations
  (scipy), and the action of a sampled path by the trapezoid rule.

The formula claims of chapter 12 call these with generic numbers: the energy in any scaled
coordinate, the Legendre pair, the generating function S and its angle derivative, the contact
slope and abscissa, the gradient potential of M.v, the polar Lagrangian and forces, the
Hamiltonian of one coordinate and the kinetic energy of a metric (through a Cholesky factor).

Units are SI or the book's scaled units throughout; angles in radians.

The models are split along the chapter's equation groups, one submodule each:

- ``energies``: L(v), E(V) and H(p), the root-mass matrix, ellipse slopes and radii
  ((12.1)-(12.9), Figs. 12.1-12.2);
- ``legendre``: the Legendre contact transformation ((12.10)-(12.13), Figs. 12.3-12.4);
- ``projectiles``: the projectile family, its generating function, contact points and envelope
  ((12.14)-(12.17), Figs. 12.5-12.6);
- ``coordinates``: generalized coordinates in general: differentials, the gradient potential of
  M.v, the metric kinetic energy, the Hamiltonian of one coordinate ((12.18)-(12.25), (12.31),
  (12.36)-(12.37));
- ``polar``: the polar Jacobian, Kajobian, metrics, Lagrangian, momenta and forces
  ((12.26)-(12.37));
- ``action``: action, phase, Bohr quantization and the oscillator paths ((12.38)-(12.48),
  Figs. 12.12-12.15; exercise 1.12.3);
- ``calculus``: angle and time derivatives of Laurent polynomials, used by the above.

This package re-exports every public name, so the catalog's ``lagrange.function`` resolves.
"""

from __future__ import annotations

from mechmodel.ellipse import kinetic_energy as kinetic_energy  # L(v) of free bodies (12.3)
from mechmodel.lagrange.action import (
    OscillatorPaths as OscillatorPaths,
)
from mechmodel.lagrange.action import (
    PhaseFactorParts as PhaseFactorParts,
)
from mechmodel.lagrange.action import (
    action_sum as action_sum,
)
from mechmodel.lagrange.action import (
    bohr_phase as bohr_phase,
)
from mechmodel.lagrange.action import (
    common_speed as common_speed,
)
from mechmodel.lagrange.action import (
    oscillator_paths as oscillator_paths,
)
from mechmodel.lagrange.action import (
    palette_amplitude as palette_amplitude,
)
from mechmodel.lagrange.action import (
    palette_phase as palette_phase,
)
from mechmodel.lagrange.action import (
    path_action as path_action,
)
from mechmodel.lagrange.action import (
    phase_factor as phase_factor,
)
from mechmodel.lagrange.action import (
    phase_factor_parts as phase_factor_parts,
)
from mechmodel.lagrange.action import (
    phase_turn as phase_turn,
)
from mechmodel.lagrange.action import (
    turning_sequence as turning_sequence,
)
from mechmodel.lagrange.calculus import (
    angle_derivative as angle_derivative,
)
from mechmodel.lagrange.calculus import (
    time_derivative as time_derivative,
)
from mechmodel.lagrange.coordinates import (
    CoordinateHamiltonian as CoordinateHamiltonian,
)
from mechmodel.lagrange.coordinates import (
    QuadraticExtremum as QuadraticExtremum,
)
from mechmodel.lagrange.coordinates import (
    coordinate_differential as coordinate_differential,
)
from mechmodel.lagrange.coordinates import (
    gradient_potential as gradient_potential,
)
from mechmodel.lagrange.coordinates import (
    hamiltonian_of_momentum as hamiltonian_of_momentum,
)
from mechmodel.lagrange.coordinates import (
    hamiltonian_of_rate as hamiltonian_of_rate,
)
from mechmodel.lagrange.coordinates import (
    metric_kinetic_energy as metric_kinetic_energy,
)
from mechmodel.lagrange.coordinates import (
    quadratic_extremum as quadratic_extremum,
)
from mechmodel.lagrange.coordinates import (
    quadratic_function_slope as quadratic_function_slope,
)
from mechmodel.lagrange.energies import (
    EllipseRadii as EllipseRadii,
)
from mechmodel.lagrange.energies import (
    EllipseSlopes as EllipseSlopes,
)
from mechmodel.lagrange.energies import (
    RootMassMaps as RootMassMaps,
)
from mechmodel.lagrange.energies import (
    RootMassPowers as RootMassPowers,
)
from mechmodel.lagrange.energies import (
    ellipse_radius_ratio as ellipse_radius_ratio,
)
from mechmodel.lagrange.energies import (
    energy_ellipse_radii as energy_ellipse_radii,
)
from mechmodel.lagrange.energies import (
    estrangian as estrangian,
)
from mechmodel.lagrange.energies import (
    hamiltonian_free as hamiltonian_free,
)
from mechmodel.lagrange.energies import (
    ke_ellipse_slopes as ke_ellipse_slopes,
)
from mechmodel.lagrange.energies import (
    momenta as momenta,
)
from mechmodel.lagrange.energies import (
    quasi_velocities as quasi_velocities,
)
from mechmodel.lagrange.energies import (
    root_mass_maps as root_mass_maps,
)
from mechmodel.lagrange.energies import (
    root_mass_powers as root_mass_powers,
)
from mechmodel.lagrange.energies import (
    scaled_coordinate_energy as scaled_coordinate_energy,
)
from mechmodel.lagrange.legendre import (
    LegendreResult as LegendreResult,
)
from mechmodel.lagrange.legendre import (
    LegendreStationarity as LegendreStationarity,
)
from mechmodel.lagrange.legendre import (
    LegendreTangent as LegendreTangent,
)
from mechmodel.lagrange.legendre import (
    QuadraticLegendrePair as QuadraticLegendrePair,
)
from mechmodel.lagrange.legendre import (
    legendre_stationarity as legendre_stationarity,
)
from mechmodel.lagrange.legendre import (
    legendre_tangent as legendre_tangent,
)
from mechmodel.lagrange.legendre import (
    legendre_transform as legendre_transform,
)
from mechmodel.lagrange.legendre import (
    quadratic_legendre_pair as quadratic_legendre_pair,
)
from mechmodel.lagrange.polar import (
    PolarForces as PolarForces,
)
from mechmodel.lagrange.polar import (
    PolarGeneralizedForces as PolarGeneralizedForces,
)
from mechmodel.lagrange.polar import (
    PolarMechanics as PolarMechanics,
)
from mechmodel.lagrange.polar import (
    PolarState as PolarState,
)
from mechmodel.lagrange.polar import (
    euler_lagrange_residual as euler_lagrange_residual,
)
from mechmodel.lagrange.polar import (
    polar_forces as polar_forces,
)
from mechmodel.lagrange.polar import (
    polar_generalized_forces as polar_generalized_forces,
)
from mechmodel.lagrange.polar import (
    polar_hamiltonian as polar_hamiltonian,
)
from mechmodel.lagrange.polar import (
    polar_inverse_metric as polar_inverse_metric,
)
from mechmodel.lagrange.polar import (
    polar_jacobian as polar_jacobian,
)
from mechmodel.lagrange.polar import (
    polar_kajobian as polar_kajobian,
)
from mechmodel.lagrange.polar import (
    polar_lagrangian as polar_lagrangian,
)
from mechmodel.lagrange.polar import (
    polar_mechanics as polar_mechanics,
)
from mechmodel.lagrange.polar import (
    polar_metric as polar_metric,
)
from mechmodel.lagrange.polar import (
    polar_state as polar_state,
)
from mechmodel.lagrange.polar import (
    polar_terms as polar_terms,
)
from mechmodel.lagrange.projectiles import (
    ProjectileFamily as ProjectileFamily,
)
from mechmodel.lagrange.projectiles import (
    contact_distance as contact_distance,
)
from mechmodel.lagrange.projectiles import (
    contact_point as contact_point,
)
from mechmodel.lagrange.projectiles import (
    contact_tangent as contact_tangent,
)
from mechmodel.lagrange.projectiles import (
    envelope_by_maximum as envelope_by_maximum,
)
from mechmodel.lagrange.projectiles import (
    envelope_height as envelope_height,
)
from mechmodel.lagrange.projectiles import (
    generating_angle_derivative as generating_angle_derivative,
)
from mechmodel.lagrange.projectiles import (
    generating_solution as generating_solution,
)
from mechmodel.lagrange.projectiles import (
    projectile_family as projectile_family,
)
from mechmodel.lagrange.projectiles import (
    trajectory_height as trajectory_height,
)
from mechmodel.lagrange.projectiles import (
    trajectory_position as trajectory_position,
)
