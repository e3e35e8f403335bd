"""Mass-property maths: principal moments, validity, primitive tensors, composition.

Plain Python on 3x3 matrices (tuples of rows), so that `check` needs no numpy.
Tensors are about the centre of mass unless said otherwise; URDF axes.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

Matrix = tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float]]
Vector = tuple[float, float, float]
KEYS = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
ZERO: Matrix = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
TOLERANCE = 0.1
"""Default largest relative element difference between declared and expected tensors.

Rounding a tensor to two significant digits moves it by under 5 %; swapping or
rotating the axes of any body whose moments differ by more than 10 % of the
largest moves it by more. 0.1 separates the two.
"""


def matrix(inertia: dict[str, float]) -> Matrix:
    xx, xy, xz, yy, yz, zz = inertia["ixx"], inertia["ixy"], inertia["ixz"], inertia["iyy"], inertia["iyz"], inertia["izz"]
    return ((xx, xy, xz), (xy, yy, yz), (xz, yz, zz))


def as_dict(m: Matrix) -> dict[str, float]:
    return {"ixx": m[0][0], "ixy": m[0][1], "ixz": m[0][2], "iyy": m[1][1], "iyz": m[1][2], "izz": m[2][2]}


def principal_moments(m: Matrix) -> tuple[float, float, float]:
    """Eigenvalues of a symmetric 3x3 matrix, ascending (closed form)."""
    size = scale_of(m)
    if size == 0:
        return (0.0, 0.0, 0.0)
    if not 1e-100 < size < 1e100:  # keep the squares below away from underflow and overflow
        return tuple(v * size for v in principal_moments(normalised(m)))  # type: ignore[return-value]
    a, b, c = m[0][0], m[1][1], m[2][2]
    d, e, f = m[0][1], m[1][2], m[0][2]
    off = d * d + e * e + f * f
    if off <= 1e-30 * (a * a + b * b + c * c + off):
        return tuple(sorted((a, b, c)))  # type: ignore[return-value]
    q = (a + b + c) / 3.0
    p2 = (a - q) ** 2 + (b - q) ** 2 + (c - q) ** 2 + 2.0 * off
    p = math.sqrt(p2 / 6.0)
    inv = 1.0 / p
    # B = (m - q I) / p, written out (a closed form called for every tensor of a model)
    (b00, b01, b02), (b10, b11, b12), (b20, b21, b22) = (
        ((m[0][0] - q) * inv, m[0][1] * inv, m[0][2] * inv),
        (m[1][0] * inv, (m[1][1] - q) * inv, m[1][2] * inv),
        (m[2][0] * inv, m[2][1] * inv, (m[2][2] - q) * inv),
    )
    det_b = b00 * (b11 * b22 - b12 * b21) - b01 * (b10 * b22 - b12 * b20) + b02 * (b10 * b21 - b11 * b20)
    r = max(-1.0, min(1.0, det_b / 2.0))
    phi = math.acos(r) / 3.0
    big = q + 2.0 * p * math.cos(phi)
    small = q + 2.0 * p * math.cos(phi + 2.0 * math.pi / 3.0)
    middle = 3.0 * q - big - small
    return tuple(sorted((small, middle, big)))  # type: ignore[return-value]


ZERO_FLOOR = 1e-12
"""kg·m²: an element smaller than this is rounding noise (iCub writes 2.4e-35), not a moment.

A gram spread over a millimetre already has moments near 1e-10: nothing physical is smaller."""

LIGHT = 0.02
"""kg: a link lighter than this (a sensor or tool frame, a dummy link) has mass properties too
small to matter to its body's dynamics; the physics rules leave its tensor alone."""


def floored(m: Matrix) -> Matrix:
    """The tensor with the elements below ZERO_FLOOR set to zero (written out: asked of every declared tensor)."""
    (a, b, c), (d, e, f), (g, h, i) = m
    return (
        (0.0 if abs(a) < ZERO_FLOOR else a, 0.0 if abs(b) < ZERO_FLOOR else b, 0.0 if abs(c) < ZERO_FLOOR else c),
        (0.0 if abs(d) < ZERO_FLOOR else d, 0.0 if abs(e) < ZERO_FLOOR else e, 0.0 if abs(f) < ZERO_FLOOR else f),
        (0.0 if abs(g) < ZERO_FLOOR else g, 0.0 if abs(h) < ZERO_FLOOR else h, 0.0 if abs(i) < ZERO_FLOOR else i),
    )


def is_negligible(m: Matrix) -> bool:
    """All elements are zero or rounding noise: the body is a point mass."""
    return scale_of(m) < ZERO_FLOOR


def scale_of(m: Matrix) -> float:
    """The largest element's size (written out: asked about seven times per link by the inertia rules)."""
    (a, b, c), (d, e, f), (g, h, i) = m
    return max(abs(a), abs(b), abs(c), abs(d), abs(e), abs(f), abs(g), abs(h), abs(i))


def is_zero(m: Matrix) -> bool:
    return scale_of(m) == 0.0


def is_positive_semidefinite(m: Matrix, rel_tol: float = 1e-9, moments: Vector | None = None) -> bool:
    """No principal moment below -rel_tol of the largest element (``moments``: the
    tensor's principal moments, where they were worked out already).

    The closed-form eigenvalues lose about eight digits on degenerate tensors (a
    rank-one tensor with all elements equal comes out at -5e-9): a smallest moment
    within that noise is decided by Sylvester's principal minors instead, which
    stay exact there."""
    scale = scale_of(m)
    if scale == 0:
        return True
    smallest = (moments if moments is not None else principal_moments(m))[0] / scale
    if smallest >= -rel_tol or smallest < -1e-6:
        return smallest >= -rel_tol
    m = normalised(m)  # elements in [-1, 1]: no overflow or underflow in the products
    minors = (
        m[0][0], m[1][1], m[2][2],
        m[0][0] * m[1][1] - m[0][1] ** 2, m[0][0] * m[2][2] - m[0][2] ** 2, m[1][1] * m[2][2] - m[1][2] ** 2,
        determinant(m),
    )  # fmt: skip
    return min(minors) >= -1e-12


def determinant(m: Matrix) -> float:
    return (
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    )


def without_noise(moments: Vector) -> Vector:
    """Principal moments with those that are rounding noise next to the largest (the eigen
    solve of an exactly singular tensor gives -7e-24, not 0) as 0."""
    largest = max(map(abs, moments))
    return tuple(0.0 if abs(m) <= 1e-9 * largest else m for m in moments)  # type: ignore[return-value]


def triangle_violation(m: Matrix, rel_tol: float = 1e-6, moments: Vector | None = None) -> tuple[float, float, float] | None:
    """The principal moments when the two smaller sum to less than the largest (``moments``:
    those of ``m``, where they were worked out already)."""
    a, b, c = moments if moments is not None else principal_moments(m)
    if a + b < c * (1.0 - rel_tol):
        return a, b, c
    return None


# -- primitives (about the centre, shape axes) -------------------------------------
def box(mass: float, size: Vector) -> Matrix:
    x, y, z = size
    return diagonal(mass * (y * y + z * z) / 12.0, mass * (x * x + z * z) / 12.0, mass * (x * x + y * y) / 12.0)


def cylinder(mass: float, radius: float, length: float) -> Matrix:
    side = mass * (3.0 * radius * radius + length * length) / 12.0
    return diagonal(side, side, mass * radius * radius / 2.0)


def sphere(mass: float, radius: float) -> Matrix:
    moment = 2.0 * mass * radius * radius / 5.0
    return diagonal(moment, moment, moment)


def diagonal(x: float, y: float, z: float) -> Matrix:
    return ((x, 0.0, 0.0), (0.0, y, 0.0), (0.0, 0.0, z))


# -- frames ----------------------------------------------------------------------
def rotation(rpy: Vector) -> Matrix:
    """URDF fixed-axis roll-pitch-yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    r, p, y = rpy
    if not (r or p or y):
        return IDENTITY  # most frames are not turned
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return (
        (cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr),
        (sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr),
        (-sp, cp * sr, cp * cr),
    )


# Written out, not looped: these are the inner loops of frame composition and of the inertia rules.
def multiply(a: Matrix, b: Matrix) -> Matrix:
    """a b."""
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = a
    (b00, b01, b02), (b10, b11, b12), (b20, b21, b22) = b
    return (
        (a00 * b00 + a01 * b10 + a02 * b20, a00 * b01 + a01 * b11 + a02 * b21, a00 * b02 + a01 * b12 + a02 * b22),
        (a10 * b00 + a11 * b10 + a12 * b20, a10 * b01 + a11 * b11 + a12 * b21, a10 * b02 + a11 * b12 + a12 * b22),
        (a20 * b00 + a21 * b10 + a22 * b20, a20 * b01 + a21 * b11 + a22 * b21, a20 * b02 + a21 * b12 + a22 * b22),
    )


def transpose(a: Matrix) -> Matrix:
    if a is IDENTITY:  # most frames' rotation: kept the very object, which rotate() passes by
        return a
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = a
    return ((a00, a10, a20), (a01, a11, a21), (a02, a12, a22))


def apply(a: Matrix, v: Vector) -> Vector:
    x, y, z = v
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = a
    # from 0.0, as sum() counts: a sum of negative zeros is +0.0 either way
    return (0.0 + a00 * x + a01 * y + a02 * z, 0.0 + a10 * x + a11 * y + a12 * z, 0.0 + a20 * x + a21 * y + a22 * z)


def rotate(tensor: Matrix, r: Matrix) -> Matrix:
    """The tensor expressed in the frame where the body's axes are rotated by r: R I Rᵀ
    (the tensor itself when r is the identity, as most frames' rotation is)."""
    if r == IDENTITY:
        return tensor
    return multiply(multiply(r, tensor), transpose(r))


def parallel_axis(tensor: Matrix, mass: float, offset: Vector) -> Matrix:
    """Move a tensor about the centre of mass to a point ``offset`` away: I + m(|r|²E − r rᵀ)."""
    x, y, z = offset
    r2 = x * x + y * y + z * z
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = tensor
    return (
        (a00 + mass * (r2 - x * x), a01 + mass * (0.0 - x * y), a02 + mass * (0.0 - x * z)),
        (a10 + mass * (0.0 - y * x), a11 + mass * (r2 - y * y), a12 + mass * (0.0 - y * z)),
        (a20 + mass * (0.0 - z * x), a21 + mass * (0.0 - z * y), a22 + mass * (r2 - z * z)),
    )


def add(a: Matrix, b: Matrix) -> Matrix:
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = a
    (b00, b01, b02), (b10, b11, b12), (b20, b21, b22) = b
    return ((a00 + b00, a01 + b01, a02 + b02), (a10 + b10, a11 + b11, a12 + b12), (a20 + b20, a21 + b21, a22 + b22))


def combine(parts: Iterable[tuple[float, Vector, Matrix]]) -> tuple[float, Vector, Matrix]:
    """Total mass, centre of mass and tensor about it, of bodies given as
    (mass, centre, tensor about that centre, already in the common frame)."""
    parts = list(parts)
    mass = sum([m for m, _, _ in parts])
    if mass <= 0:
        return 0.0, (0.0, 0.0, 0.0), ZERO
    x = y = z = 0  # summed as sum() would
    for m, (cx, cy, cz), _ in parts:
        x, y, z = x + m * cx, y + m * cy, z + m * cz
    cx, cy, cz = x / mass, y / mass, z / mass
    com = (cx, cy, cz)
    total = ZERO
    for m, c, tensor in parts:
        total = add(total, parallel_axis(tensor, m, (c[0] - cx, c[1] - cy, c[2] - cz)))
    return mass, com, total


def relative_difference(a: Matrix, b: Matrix) -> float:
    """Largest element difference, relative to the larger tensor's scale."""
    scale = max(scale_of(a), scale_of(b))
    if scale == 0:
        return 0.0
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = a
    (b00, b01, b02), (b10, b11, b12), (b20, b21, b22) = b
    return max(
        abs(a00 - b00), abs(a01 - b01), abs(a02 - b02), abs(a10 - b10), abs(a11 - b11), abs(a12 - b12), abs(a20 - b20), abs(a21 - b21), abs(a22 - b22)
    ) / scale


def is_identity(m: Matrix) -> bool:
    """Exactly the identity: the classic copy-pasted placeholder."""
    return m == ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def tidy(m: Matrix, rel_tol: float = 1e-5) -> Matrix:
    """Zero the elements that are rounding noise next to the largest (e.g. cos(1.5708))."""
    floor = rel_tol * scale_of(m)
    (a, b, c), (d, e, f), (g, h, i) = m
    return (
        (0.0 if abs(a) <= floor else a, 0.0 if abs(b) <= floor else b, 0.0 if abs(c) <= floor else c),
        (0.0 if abs(d) <= floor else d, 0.0 if abs(e) <= floor else e, 0.0 if abs(f) <= floor else f),
        (0.0 if abs(g) <= floor else g, 0.0 if abs(h) <= floor else h, 0.0 if abs(i) <= floor else i),
    )


def normalised(m: Matrix) -> Matrix:
    """The matrix divided by its largest element's magnitude (which must not be zero)."""
    size = scale_of(m)
    return tuple(tuple(v / size for v in row) for row in m)  # type: ignore[return-value]


def principal_axis(m: Matrix, moment: float) -> Vector | None:
    """The unit axis of a principal moment that stands apart from the other two (its
    sign is arbitrary): the cross product of two rows of ``m - moment * I``, the
    pair that gives the longest. None when the moment is not a simple one of ``m``."""
    size = scale_of(m)
    if size == 0:
        return None
    m, moment = normalised(m), moment / size
    rows = [tuple(m[i][j] - (moment if i == j else 0.0) for j in range(3)) for i in range(3)]
    candidates = [_cross(rows[0], rows[1]), _cross(rows[0], rows[2]), _cross(rows[1], rows[2])]
    best = max(candidates, key=lambda v: v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    length = math.sqrt(best[0] * best[0] + best[1] * best[1] + best[2] * best[2])
    return (best[0] / length, best[1] / length, best[2] / length) if length > 1e-12 else None


def _cross(a: Vector, b: Vector) -> Vector:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def scaled(m: Matrix, factor: float) -> Matrix:
    (a, b, c), (d, e, f), (g, h, i) = m
    return ((a * factor, b * factor, c * factor), (d * factor, e * factor, f * factor), (g * factor, h * factor, i * factor))


def moments_difference(a: Matrix, b: Matrix) -> float:
    """Like relative_difference, on the principal moments only (frame-independent)."""
    pa, pb = principal_moments(a), principal_moments(b)
    scale = max(max(abs(v) for v in pa), max(abs(v) for v in pb))
    return 0.0 if scale == 0 else max(abs(x - y) for x, y in zip(pa, pb)) / scale


# -- primitive volumes ----------------------------------------------------------------
def box_volume(size: Vector) -> float:
    return size[0] * size[1] * size[2]


def cylinder_volume(radius: float, length: float) -> float:
    return math.pi * radius * radius * length


def sphere_volume(radius: float) -> float:
    return 4.0 / 3.0 * math.pi * radius**3


# -- rigid transforms (rotation, translation) -------------------------------------------
Transform = tuple[Matrix, Vector]
IDENTITY: Matrix = diagonal(1.0, 1.0, 1.0)
ORIGIN: Transform = (IDENTITY, (0.0, 0.0, 0.0))


def transform(xyz: Vector, rpy: Vector) -> Transform:
    """The pose a URDF ``<origin xyz rpy>`` describes."""
    return rotation(rpy), tuple(xyz)  # type: ignore[return-value]


def compose(a: Transform, b: Transform) -> Transform:
    """Pose b given in frame a, expressed in a's parent frame."""
    (ra, ta), (rb, tb) = a, b
    moved = apply(ra, tb)
    return multiply(ra, rb), (ta[0] + moved[0], ta[1] + moved[1], ta[2] + moved[2])


def place(pose: Transform, point: Vector) -> Vector:
    """A point of the child frame, in the parent frame."""
    moved = apply(pose[0], point)
    return (moved[0] + pose[1][0], moved[1] + pose[1][1], moved[2] + pose[1][2])


def unplace(pose: Transform, point: Vector) -> Vector:
    """A point of the parent frame, in the child frame (the inverse of :func:`place`)."""
    rotation, (x, y, z) = pose
    return apply(transpose(rotation), (point[0] - x, point[1] - y, point[2] - z))


def number(value: float) -> str:
    """Six significant digits, never '-0'."""
    text = f"{value:.6g}"
    return "0" if text in ("-0", "0") else text


def tensor_text(tensor: Matrix, other: Matrix | None = None) -> str:
    """``ixx=.. iyy=.. izz=..``, with the products of inertia where either tensor has one."""
    values = as_dict(tensor)
    extra = as_dict(other) if other is not None else values
    shown = [k for k in KEYS if k in ("ixx", "iyy", "izz") or values[k] or extra[k]]
    # to 12 digits first: one value computed two ways (3.3749999999999994e-05, 3.375e-05) reads the same
    return " ".join(f"{k}={float(f'{values[k]:.12g}'):.3g}" for k in shown)


def negated_products(m: Matrix) -> Matrix:
    """The tensor with its products of inertia (ixy, ixz, iyz) negated: the other sign
    convention for them, which some CAD tools export."""
    return ((m[0][0], -m[0][1], -m[0][2]), (-m[1][0], m[1][1], -m[1][2]), (-m[2][0], -m[2][1], m[2][2]))


def inertia_element(m: Matrix) -> str:
    """``<inertia ixx=".." .../>`` for a tensor, values to six significant digits."""
    values = as_dict(m)
    return "<inertia " + " ".join(f'{k}="{number(values[k])}"' for k in KEYS) + "/>"
