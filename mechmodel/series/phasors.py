"""Euler's formula, phasors and complex products (chapter 10, (10.17)-(10.30), Fig. 10.5).

The powers of i repeat after four; their series is e^(i theta) = cos theta + i sin theta
(10.17). Unit phasors, their clockwise and opposite angles (radians, in [0, 2 pi)), the modulus
of a phasor, the derivatives of x(0) e^(-i w t) (10.22) and 2-D rotations as the complex
product e^(i phi)(x + i y) (10.27). Python ``complex`` throughout; ``phasor_rate`` takes
``Symbolic`` arguments (a formula claim calls it with sympy symbols).
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.typing import Real, Symbolic


def imaginary_unit_power(k: int) -> complex:
    """i^k by repeated multiplication by i = sqrt(-1) (exact in floating point)."""
    k = inputs.count(k, "k")
    value = complex(1, 0)
    for _ in range(k):
        value = complex(-value.imag, value.real)  # times i
    return value


def imaginary_unit_period() -> int:
    """The smallest k > 0 with i^k = 1: the repeat-after-4 pattern of the powers of i."""
    k = 1
    while imaginary_unit_power(k) != 1:
        k += 1
    return k


def euler_series(theta: Real, order: int) -> complex:
    """Partial sum of e^(i theta) = sum_k (i theta)^k / k! to ``order`` (10.17)."""
    inputs.real(theta, "theta")
    order = inputs.count(order, "order")
    return sum(imaginary_unit_power(k) * theta**k / math.factorial(k) for k in range(order + 1))


def unit_phasor(angle: Real = 0, pi_multiple: Real = 0) -> complex:
    """e^(i phi) = cos phi + i sin phi (10.17) for phi = angle + pi_multiple * pi (radians)."""
    inputs.real(angle, "angle")
    inputs.real(pi_multiple, "pi_multiple")
    phi = float(angle) + float(pi_multiple) * math.pi
    return complex(math.cos(phi), math.sin(phi))


def phasor_divisor(
    numerator_re: Real, numerator_im: Real, angle: Real, angle_sign: Real = 1, sign: Real = 1
) -> complex:
    """The d of e^(i s phi) = sign (a + i b)/d: d = sign (a + i b) / e^(i s phi)
    ((10.21): e^(i pi/4) = (1 + i)/sqrt 2). Real where the identity holds."""
    z = complex(float(numerator_re), float(numerator_im)) * float(sign)
    return z / unit_phasor(float(angle) * float(angle_sign))


def opposite_phasor_angle(angle: Real = 0, pi_multiple: Real = 0, exponent_sign: int = -1) -> float:
    """The angle psi in [0, 2 pi) with -e^(s i psi) = e^(i phi), s = ``exponent_sign`` (-1 or +1):
    the "-e^(-i 3pi/4)" and "-e^(+i 5pi/4)" forms of e^(i pi/4) in (10.21). Radians."""
    if exponent_sign not in (-1, 1):
        raise ValueError(f"exponent_sign must be -1 or +1, got {exponent_sign!r}")
    phi = float(angle) + float(pi_multiple) * math.pi
    target = -unit_phasor(phi)  # e^(s i psi) = -e^(i phi)
    psi = cmath.phase(target) * exponent_sign
    return psi % (2 * math.pi)


def clockwise_angle(angle: Real = 0, pi_multiple: Real = 0) -> float:
    """The clockwise angle psi in [0, 2 pi) with e^(-i psi) = e^(i phi) (e^(i5pi/4) = e^(-i3pi/4),
    Fig. 10.5a). Radians."""
    phi = float(angle) + float(pi_multiple) * math.pi
    return cmath.phase(unit_phasor(phi).conjugate()) % (2 * math.pi)


def phasor_modulus(x: Real, y: Real) -> float:
    """The modulus r = A = |psi| of the phasor with Cartesian parts psi_x = ``x``, psi_y = ``y``
    (the polar form of (10.19b), Fig. 10.5): the radius of x + i y in polar coordinates."""
    inputs.real(x, "x")
    inputs.real(y, "y")
    return cmath.polar(complex(float(x), float(y)))[0]


def phasor_quarter_cycle() -> float:
    """Fraction s of a cycle by which Re psi runs behind Im psi for psi = A e^(-i w t)
    (the "gonna-be" of Fig. 10.5b): Re psi(t + s T) = Im psi(t), i.e. e^(-2 pi i s) = -i."""
    target = complex(0, -1)  # Im psi = Re(-i psi)
    return (-cmath.phase(target) / (2 * math.pi)) % 1


@dataclass(frozen=True)
class PhasorDerivative:
    """d^n/dt^n x(0) e^(-i w t) = ``factor`` w^``omega_power`` x(t) (10.22)."""

    factor: complex
    omega_power: int


def phasor_derivative(order: int) -> PhasorDerivative:
    """Differentiate e^(-i w t) ``order`` times: each derivative multiplies by -i w (10.22b)."""
    n = inputs.count(order, "order")
    factor, power = complex(1, 0), 0
    for _ in range(n):
        factor = factor * complex(0, -1)
        power += 1
    return PhasorDerivative(factor, power)


def phasor_rate(omega: Symbolic, x: Symbolic | complex, order: int) -> Symbolic | complex:
    """The ``order``-th time derivative of x(t) = x(0) e^(-i w t) as a multiple of x(t)
    ((10.22b), (10.23a)): the ``phasor_derivative`` factor times w^power times x."""
    d = phasor_derivative(order)
    f = d.factor  # a power of -i: real (+-1, kept an exact int) for an even order
    factor = int(f.real) if f.imag == 0 and f.real.is_integer() else f
    return factor * omega**d.omega_power * x


def unit_circle_radius(samples: int = 12) -> float:
    """Largest |e^(i theta)| over ``samples`` angles around the circle: 1 (Fig. 10.5a)."""
    n = inputs.count(samples, "samples", minimum=1)
    return max(abs(unit_phasor(2 * math.pi * j / n)) for j in range(n))


def rotate(x: Real, y: Real, angle: Real) -> tuple[float, float]:
    """The 2-D rotation of (x, y) by ``angle`` as the complex product e^(i phi)(x + i y)
    (10.27a): (x cos phi - y sin phi, x sin phi + y cos phi)."""
    z = unit_phasor(angle) * complex(float(x), float(y))
    return z.real, z.imag
