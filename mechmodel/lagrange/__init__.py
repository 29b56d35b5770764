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

This package re-exports every public name (``__all__``), so the catalog's
``lagrange.function`` resolves.
"""

from __future__ import annotations

from mechmodel.ellipse import kinetic_energy  # L(v) of free bodies (12.3)
from mechmodel.lagrange.action import (
    OscillatorPaths,
    PhaseFactorParts,
    action_sum,
    bohr_phase,
    common_speed,
    oscillator_paths,
    palette_amplitude,
    palette_phase,
    path_action,
    phase_factor,
    phase_factor_parts,
    phase_turn,
    turning_sequence,
)
from mechmodel.lagrange.calculus import angle_derivative, time_derivative
from mechmodel.lagrange.coordinates import (
    CoordinateHamiltonian,
    QuadraticExtremum,
    coordinate_differential,
    gradient_potential,
    hamiltonian_of_momentum,
    hamiltonian_of_rate,
    metric_kinetic_energy,
    quadratic_extremum,
    quadratic_function_slope,
)
from mechmodel.lagrange.energies import (
    EllipseRadii,
    EllipseSlopes,
    RootMassMaps,
    RootMassPowers,
    ellipse_radius_ratio,
    energy_ellipse_radii,
    estrangian,
    hamiltonian_free,
    ke_ellipse_slopes,
    momenta,
    quasi_velocities,
    root_mass_maps,
    root_mass_powers,
    scaled_coordinate_energy,
)
from mechmodel.lagrange.legendre import (
    LegendreResult,
    LegendreStationarity,
    LegendreTangent,
    QuadraticLegendrePair,
    legendre_stationarity,
    legendre_tangent,
    legendre_transform,
    quadratic_legendre_pair,
)
from mechmodel.lagrange.polar import (
    PolarForces,
    PolarGeneralizedForces,
    PolarMechanics,
    PolarState,
    euler_lagrange_residual,
    polar_forces,
    polar_generalized_forces,
    polar_hamiltonian,
    polar_inverse_metric,
    polar_jacobian,
    polar_kajobian,
    polar_lagrangian,
    polar_mechanics,
    polar_metric,
    polar_state,
    polar_terms,
)
from mechmodel.lagrange.projectiles import (
    ProjectileFamily,
    contact_distance,
    contact_point,
    contact_tangent,
    envelope_by_maximum,
    envelope_height,
    generating_angle_derivative,
    generating_solution,
    projectile_family,
    trajectory_height,
    trajectory_position,
)

__all__ = [
    "CoordinateHamiltonian",
    "EllipseRadii",
    "EllipseSlopes",
    "LegendreResult",
    "LegendreStationarity",
    "LegendreTangent",
    "OscillatorPaths",
    "PhaseFactorParts",
    "PolarForces",
    "PolarGeneralizedForces",
    "PolarMechanics",
    "PolarState",
    "ProjectileFamily",
    "QuadraticExtremum",
    "QuadraticLegendrePair",
    "RootMassMaps",
    "RootMassPowers",
    "action_sum",
    "angle_derivative",
    "bohr_phase",
    "common_speed",
    "contact_distance",
    "contact_point",
    "contact_tangent",
    "coordinate_differential",
    "ellipse_radius_ratio",
    "energy_ellipse_radii",
    "envelope_by_maximum",
    "envelope_height",
    "estrangian",
    "euler_lagrange_residual",
    "generating_angle_derivative",
    "generating_solution",
    "gradient_potential",
    "hamiltonian_free",
    "hamiltonian_of_momentum",
    "hamiltonian_of_rate",
    "ke_ellipse_slopes",
    "kinetic_energy",
    "legendre_stationarity",
    "legendre_tangent",
    "legendre_transform",
    "metric_kinetic_energy",
    "momenta",
    "oscillator_paths",
    "palette_amplitude",
    "palette_phase",
    "path_action",
    "phase_factor",
    "phase_factor_parts",
    "phase_turn",
    "polar_forces",
    "polar_generalized_forces",
    "polar_hamiltonian",
    "polar_inverse_metric",
    "polar_jacobian",
    "polar_kajobian",
    "polar_lagrangian",
    "polar_mechanics",
    "polar_metric",
    "polar_state",
    "polar_terms",
    "projectile_family",
    "quadratic_extremum",
    "quadratic_function_slope",
    "quadratic_legendre_pair",
    "quasi_velocities",
    "root_mass_maps",
    "root_mass_powers",
    "scaled_coordinate_energy",
    "time_derivative",
    "trajectory_height",
    "trajectory_position",
    "turning_sequence",
]
