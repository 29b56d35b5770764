"""Geometry and physics of common potential fields (chapter 9).

The chapter's fields, each as pure functions of the book's inputs, one submodule per family
(re-exported here: the catalog names them ``fields.function``):

- ``parabola``: power laws and their geometric constructions: the parabola U = a x^2 drawn by
  similar triangles (Fig. 9.1), its Hooke force F = -dU/dx, the staircase of slopes s and -1/s
  (Fig. 9.2), and the focus-directrix geometry of the parabola (Figs. 9.3, 9.4);
- ``inverse_square_laws``: Coulomb's force and potential (9.1)-(9.2), the calculus of r^n, the
  ratios of sizes and energies that the book's estimates use, Newton's gravity (9.3) and the
  units of G and k; the density of nuclear matter and the neutron starlet;
- ``earth``: a uniform Earth of radius R and surface gravity g: the linear field inside and the
  inverse-square field outside (9.4), the parabolic potential inside that meets -1/x outside
  (Fig. 9.7), the shells that cancel inside (Fig. 9.6), the three equal energy steps to escape
  (9.11), the orbit and escape speeds and the black-hole radius (9.12);
- ``orbits``: the tunnel through any chord and the grazing orbit (Fig. 9.8), and the isotropic
  two-dimensional oscillator that every starlet inside the Earth is (9.8)-(9.15): its orbits,
  energies and angular momentum, and the clock phases of Figs. 9.10-9.11.

Units: SI in, SI out (or any consistent units); the "scaled" functions use the book's units of
Fig. 9.7 (x in Earth radii, forces in mg, potentials in mgR, so that GM = 1). Angles are in
radians. Floats throughout; where a function uses only + - * / (parabola geometry, powers, the
scaled potential, the clock), ``fractions.Fraction`` inputs give exact results, and those the
formula claims call with sympy symbols (the parabola's height, the units of G and k, the
oscillator's energy) take ``Symbolic`` arguments.
"""

from __future__ import annotations

from mechmodel.fields.earth import EscapeLadder as EscapeLadder
from mechmodel.fields.earth import InteriorCurve as InteriorCurve
from mechmodel.fields.earth import InteriorPotential as InteriorPotential
from mechmodel.fields.earth import SurfaceSpeeds as SurfaceSpeeds
from mechmodel.fields.earth import black_hole_radius as black_hole_radius
from mechmodel.fields.earth import centre_speed_squared as centre_speed_squared
from mechmodel.fields.earth import circular_orbit_speed as circular_orbit_speed
from mechmodel.fields.earth import escape_ladder as escape_ladder
from mechmodel.fields.earth import escape_speed as escape_speed
from mechmodel.fields.earth import escape_speed_from_orbit_speed as escape_speed_from_orbit_speed
from mechmodel.fields.earth import escape_speed_gm as escape_speed_gm
from mechmodel.fields.earth import escape_speed_of_orbit as escape_speed_of_orbit
from mechmodel.fields.earth import gravity_field as gravity_field
from mechmodel.fields.earth import gravity_potential as gravity_potential
from mechmodel.fields.earth import interior_parabola as interior_parabola
from mechmodel.fields.earth import interior_potential as interior_potential
from mechmodel.fields.earth import interior_potential_at as interior_potential_at
from mechmodel.fields.earth import potential_energy as potential_energy
from mechmodel.fields.earth import schwarzschild_radius as schwarzschild_radius
from mechmodel.fields.earth import shell_pair_pull as shell_pair_pull
from mechmodel.fields.earth import starlet_energy as starlet_energy
from mechmodel.fields.earth import surface_speeds as surface_speeds
from mechmodel.fields.inverse_square_laws import PowerLawCalculus as PowerLawCalculus
from mechmodel.fields.inverse_square_laws import ball_density as ball_density
from mechmodel.fields.inverse_square_laws import coulomb_constant_unit as coulomb_constant_unit
from mechmodel.fields.inverse_square_laws import coulomb_energy as coulomb_energy
from mechmodel.fields.inverse_square_laws import coulomb_energy_ratio as coulomb_energy_ratio
from mechmodel.fields.inverse_square_laws import coulomb_force as coulomb_force
from mechmodel.fields.inverse_square_laws import (
    coulomb_force_from_potential as coulomb_force_from_potential,
)
from mechmodel.fields.inverse_square_laws import (
    coulomb_potential_from_force as coulomb_potential_from_force,
)
from mechmodel.fields.inverse_square_laws import density as density
from mechmodel.fields.inverse_square_laws import force_constant_ratio as force_constant_ratio
from mechmodel.fields.inverse_square_laws import (
    gravitational_constant_unit as gravitational_constant_unit,
)
from mechmodel.fields.inverse_square_laws import gravitational_force as gravitational_force
from mechmodel.fields.inverse_square_laws import inside_gravity_force as inside_gravity_force
from mechmodel.fields.inverse_square_laws import inside_mass as inside_mass
from mechmodel.fields.inverse_square_laws import inverse_square as inverse_square
from mechmodel.fields.inverse_square_laws import mass_as_dense_as as mass_as_dense_as
from mechmodel.fields.inverse_square_laws import mass_of as mass_of
from mechmodel.fields.inverse_square_laws import nucleus_mass as nucleus_mass
from mechmodel.fields.inverse_square_laws import power_law_calculus as power_law_calculus
from mechmodel.fields.inverse_square_laws import sphere_area as sphere_area
from mechmodel.fields.inverse_square_laws import sphere_volume as sphere_volume
from mechmodel.fields.inverse_square_laws import uniform_surface_gravity as uniform_surface_gravity
from mechmodel.fields.inverse_square_laws import weight as weight
from mechmodel.fields.orbits import OscillatorState as OscillatorState
from mechmodel.fields.orbits import PhaseLag as PhaseLag
from mechmodel.fields.orbits import PhaseState as PhaseState
from mechmodel.fields.orbits import chord_acceleration as chord_acceleration
from mechmodel.fields.orbits import chord_length as chord_length
from mechmodel.fields.orbits import chord_tunnel_period as chord_tunnel_period
from mechmodel.fields.orbits import chord_tunnel_position as chord_tunnel_position
from mechmodel.fields.orbits import circular_orbit_period as circular_orbit_period
from mechmodel.fields.orbits import clock_hour as clock_hour
from mechmodel.fields.orbits import orbit_meeting_fraction as orbit_meeting_fraction
from mechmodel.fields.orbits import oscillator_amplitude as oscillator_amplitude
from mechmodel.fields.orbits import oscillator_initial_phase as oscillator_initial_phase
from mechmodel.fields.orbits import oscillator_orbit as oscillator_orbit
from mechmodel.fields.orbits import oscillator_phase_state as oscillator_phase_state
from mechmodel.fields.orbits import oscillator_total_energy as oscillator_total_energy
from mechmodel.fields.orbits import phase_lag as phase_lag
from mechmodel.fields.orbits import phase_velocity as phase_velocity
from mechmodel.fields.orbits import points_per_orbit as points_per_orbit
from mechmodel.fields.orbits import round_trip_time as round_trip_time
from mechmodel.fields.orbits import time_zones as time_zones
from mechmodel.fields.orbits import tunnel_period as tunnel_period
from mechmodel.fields.orbits import tunnel_transit_time as tunnel_transit_time
from mechmodel.fields.parabola import ForceTriangle as ForceTriangle
from mechmodel.fields.parabola import ParabolaGeometry as ParabolaGeometry
from mechmodel.fields.parabola import UnitSlopePoint as UnitSlopePoint
from mechmodel.fields.parabola import angle_between_lines as angle_between_lines
from mechmodel.fields.parabola import equidistant_height as equidistant_height
from mechmodel.fields.parabola import equidistant_height_for_latus as equidistant_height_for_latus
from mechmodel.fields.parabola import focal_drop_angle as focal_drop_angle
from mechmodel.fields.parabola import force_triangle as force_triangle
from mechmodel.fields.parabola import normal_slope as normal_slope
from mechmodel.fields.parabola import parabola_for_focus as parabola_for_focus
from mechmodel.fields.parabola import parabola_for_latus as parabola_for_latus
from mechmodel.fields.parabola import parabola_geometry as parabola_geometry
from mechmodel.fields.parabola import parabola_height_for_focus as parabola_height_for_focus
from mechmodel.fields.parabola import parabola_height_for_latus as parabola_height_for_latus
from mechmodel.fields.parabola import parabola_point as parabola_point
from mechmodel.fields.parabola import parabola_slope_for_focus as parabola_slope_for_focus
from mechmodel.fields.parabola import parabola_unit_slope_point as parabola_unit_slope_point
from mechmodel.fields.parabola import power_law_force as power_law_force
from mechmodel.fields.parabola import power_law_force_slope as power_law_force_slope
from mechmodel.numeric import clock_angle as clock_angle  # the catalog's fields.clock_angle
from mechmodel.numeric import line_angle as line_angle  # and fields.line_angle

__all__ = [
    "EscapeLadder",
    "ForceTriangle",
    "InteriorCurve",
    "InteriorPotential",
    "OscillatorState",
    "ParabolaGeometry",
    "PhaseLag",
    "PhaseState",
    "PowerLawCalculus",
    "SurfaceSpeeds",
    "UnitSlopePoint",
    "angle_between_lines",
    "ball_density",
    "black_hole_radius",
    "centre_speed_squared",
    "chord_acceleration",
    "chord_length",
    "chord_tunnel_period",
    "chord_tunnel_position",
    "circular_orbit_period",
    "circular_orbit_speed",
    "clock_angle",
    "clock_hour",
    "coulomb_constant_unit",
    "coulomb_energy",
    "coulomb_energy_ratio",
    "coulomb_force",
    "coulomb_force_from_potential",
    "coulomb_potential_from_force",
    "density",
    "equidistant_height",
    "equidistant_height_for_latus",
    "escape_ladder",
    "escape_speed",
    "escape_speed_from_orbit_speed",
    "escape_speed_gm",
    "escape_speed_of_orbit",
    "focal_drop_angle",
    "force_constant_ratio",
    "force_triangle",
    "gravitational_constant_unit",
    "gravitational_force",
    "gravity_field",
    "gravity_potential",
    "inside_gravity_force",
    "inside_mass",
    "interior_parabola",
    "interior_potential",
    "interior_potential_at",
    "inverse_square",
    "line_angle",
    "mass_as_dense_as",
    "mass_of",
    "normal_slope",
    "nucleus_mass",
    "orbit_meeting_fraction",
    "oscillator_amplitude",
    "oscillator_initial_phase",
    "oscillator_orbit",
    "oscillator_phase_state",
    "oscillator_total_energy",
    "parabola_for_focus",
    "parabola_for_latus",
    "parabola_geometry",
    "parabola_height_for_focus",
    "parabola_height_for_latus",
    "parabola_point",
    "parabola_slope_for_focus",
    "parabola_unit_slope_point",
    "phase_lag",
    "phase_velocity",
    "points_per_orbit",
    "potential_energy",
    "power_law_calculus",
    "power_law_force",
    "power_law_force_slope",
    "round_trip_time",
    "schwarzschild_radius",
    "shell_pair_pull",
    "sphere_area",
    "sphere_volume",
    "starlet_energy",
    "surface_speeds",
    "time_zones",
    "tunnel_period",
    "tunnel_transit_time",
    "uniform_surface_gravity",
    "weight",
]
