"""Laws of the stereographic map (mechmodel.complexfields.maps): chapter 10, Fig. 10.15.

Float geometry is compared within 1e-9 of the lengths involved (1e-12 for the chords).

Shared helpers of the complexfields modules are in ``_complexfields_helpers``.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given

from checks.properties._complexfields_helpers import RADII
from checks.properties.closeness import assert_close
from checks.properties.strategies import sphere_angles, sphere_diameters
from mechmodel import complexfields as cf

pytestmark = pytest.mark.properties


@given(sphere_angles(off_equator=True), sphere_diameters())
def test_the_stereographic_map_inverts_radii_through_half_angles(
    theta: float, diameter: float
) -> None:
    """The centre O is halfway up the sphere (radius D/2, exact for an exact D);
    |z| |w| = D^2 (w = 1/z on the unit-diameter sphere), |z| = D tan(theta/2), and the image
    of |z| through the sphere is |w|; the angles at the poles, the chords SP = D cos(theta/2),
    NP = D sin(theta/2) and the depths D sin^2(theta/2), D cos^2(theta/2) all use the half
    angle (Fig. 10.15). The poles (theta = 0, pi) and the equator (|z| = |w|) have no such
    construction."""
    p = cf.stereographic_projection(theta, diameter)
    for pole_or_equator in (0.0, math.pi / 2, math.pi):
        with pytest.raises(ValueError, match="theta"):
            cf.stereographic_projection(pole_or_equator, diameter)
    assert p.radius == diameter / 2
    assert cf.stereographic_projection(theta, Fraction(diameter)).radius == Fraction(diameter) / 2
    assert_close(p.z_radius * p.w_radius, diameter**2, rel=0, abs=1e-9 * diameter**2)
    assert_close(p.z_radius, diameter * math.tan(theta / 2), rel=0, abs=1e-9 * max(1, p.z_radius))
    image = cf.stereographic_image_radius(p.z_radius, diameter)
    assert_close(image, p.w_radius, rel=0, abs=1e-9 * max(1, p.w_radius))
    for divisor in (
        p.tan_angle_divisor,
        p.cot_angle_divisor,
        p.south_chord_angle_divisor,
        p.north_chord_angle_divisor,
        p.north_depth_angle_divisor,
        p.south_height_angle_divisor,
    ):
        assert_close(divisor, 2, rel=0, abs=1e-6)
    assert_close(p.north_depth_exponent, 2, rel=0, abs=1e-6)
    assert_close(p.south_height_exponent, 2, rel=0, abs=1e-6)


# --- formulas at a point (the models of the formula claims) -----------------------------------


@given(sphere_angles(), sphere_diameters(), RADII)
def test_stereographic_lengths_obey_thales_and_invert_radii(
    theta: float, diameter: float, rho: float
) -> None:
    """The angle NPS is right (Thales): SP^2 + NP^2 = D^2, the depth of P below N is NP^2/D and
    its height above S is SP^2/D; |z| |w| = D^2, |z| = D tan(NSP) with the inscribed angle NSP
    half the central angle (Fig. 10.15); the image of a z-radius through the sphere and back is
    that radius."""
    s = cf.stereographic_lengths(theta, diameter)
    d2 = diameter * diameter
    assert_close(s.south_chord**2 + s.north_chord**2, d2, rel=0, abs=1e-12 * d2)
    assert_close(s.north_depth * diameter, s.north_chord**2, rel=0, abs=1e-12 * d2)
    assert_close(s.south_height * diameter, s.south_chord**2, rel=0, abs=1e-12 * d2)
    assert_close(s.z_radius * s.w_radius, d2, rel=0, abs=1e-9 * d2)
    assert_close(
        s.z_radius, diameter * math.tan(s.south_angle), rel=0, abs=1e-9 * max(1, s.z_radius)
    )
    assert_close(2 * s.south_angle, theta, rel=0, abs=1e-12)
    back = cf.stereographic_preimage_radius(cf.stereographic_image_radius(rho, diameter), diameter)
    assert_close(back, rho, rel=0, abs=1e-9 * rho)
    with pytest.raises(ValueError, match="theta"):
        cf.stereographic_lengths(0.0, diameter)
