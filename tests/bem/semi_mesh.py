"""The paper's platform for a radiation-diffraction solution.

Geometry (Emmerhoff & Sclavounos 1996, SlowDrift's default platform): four columns of
radius 10 m on a 70 m square (centres at (+-35, +-35)), draft 30 m, standing on four pontoons
20 m wide and 14 m high along the sides, keel at z = -30 m. A pontoon is centred on the line
between two column centres, so its sides (y = 25 and 45 for the pontoon at y = 35) are
tangent to the columns. Below the pontoons' top (z = -16 m) a column is wetted only on its
outer quarter; the pontoons' top (z = -16 m) and the keel (z = -30 m) are flat rings with
rounded outer corners, the top without the columns' sections.

Frame: x, y horizontal, z up, origin at the centre of the waterplane (the body origin of
SlowDrift). Units: SI.

The mesh is structured, in quadrilaterals (some degenerate into triangles at the points where
a pontoon side is tangent to a column), of the quarter x >= 0, y >= 0, and reflected twice
(Capytaine's ReflectionSymmetricMesh), so the solver works on the symmetry.
"""

import numpy as np

RADIUS = 10.0
HALF_SPACING = 35.0
DRAFT = 30.0
PONTOON_WIDTH = 20.0
PONTOON_HEIGHT = 14.0
PONTOON_TOP = -DRAFT + PONTOON_HEIGHT  # z = -16 m

# Closed forms (the default configuration's comments): the displaced volume, the waterplane
# area and its second moment about the x axis.
COLUMNS_VOLUME = 4 * np.pi * RADIUS**2 * DRAFT
# Each pontoon between column centres less the two half columns inside it, less, at each of
# the four corners, the region the two pontoons there share outside the column (the inner
# corner's cusp, r^2 - pi r^2 / 4), which the sum of the pontoons counts twice.
PONTOONS_VOLUME = 4 * (PONTOON_WIDTH * 2 * HALF_SPACING - np.pi * RADIUS**2
                       - (RADIUS**2 - np.pi * RADIUS**2 / 4)) * PONTOON_HEIGHT
VOLUME = COLUMNS_VOLUME + PONTOONS_VOLUME
WATERPLANE_AREA = 4 * np.pi * RADIUS**2
WATERPLANE_INERTIA = 4 * (np.pi * RADIUS**4 / 4 + np.pi * RADIUS**2 * HALF_SPACING**2)


def _count(length, size):
    """Number of panels across `length` for a target panel size (at least 1)."""
    return max(1, int(np.ceil(length / size - 1e-9)))


class _Panels:
    """Quadrilaterals collected patch by patch, each oriented towards the fluid."""

    def __init__(self):
        self.quads = []

    def patch(self, points, outward):
        """points: (n + 1, m + 1, 3) grid; outward(centre) -> the normal's wanted direction."""
        n, m = points.shape[0] - 1, points.shape[1] - 1
        for i in range(n):
            for j in range(m):
                quad = np.array([points[i, j], points[i + 1, j], points[i + 1, j + 1],
                                 points[i, j + 1]])
                normal = np.cross(quad[2] - quad[0], quad[3] - quad[1])
                area = 0.5 * np.linalg.norm(normal)
                if area < 1e-9:
                    continue
                if np.dot(normal, outward(quad.mean(axis=0))) < 0:
                    quad = quad[::-1]
                self.quads.append(quad)

    def arrays(self):
        """Vertices (merged where they coincide) and faces for a Capytaine mesh."""
        quads = np.array(self.quads)
        flat = np.round(quads.reshape(-1, 3), 9)
        vertices, index = np.unique(flat, axis=0, return_inverse=True)
        faces = index.reshape(-1, 4)
        # A quad with two equal vertices is a triangle: Capytaine takes triangles as quads
        # whose last vertex repeats the first... rotate so that the repeat comes last.
        out = []
        for face in faces:
            unique = []
            for v in face:
                if v not in unique:
                    unique.append(v)
            if len(unique) == 3:
                unique.append(unique[0])
            out.append(unique)
        return vertices, np.array(out)


def _line(a, b, n):
    """n + 1 points from a to b."""
    t = np.linspace(0.0, 1.0, n + 1)[:, None]
    return (1 - t) * np.asarray(a, float) + t * np.asarray(b, float)


def _ruled(curve_a, curve_b, n):
    """Grid between two curves of equal length, n panels from a to b: (len, n + 1, 3)."""
    t = np.linspace(0.0, 1.0, n + 1)[None, :, None]
    return (1 - t) * curve_a[:, None, :] + t * curve_b[:, None, :]


def _arc(theta_a, theta_b, n, z):
    theta = np.linspace(theta_a, theta_b, n + 1)
    return np.stack([HALF_SPACING + RADIUS * np.cos(theta),
                     HALF_SPACING + RADIUS * np.sin(theta), np.full_like(theta, z)], axis=1)


def _lift(curve, z):
    out = np.array(curve, float)
    out[:, 2] = z
    return out


def quarter_panels(size):
    """The quarter x >= 0, y >= 0 of the wetted surface, panels of about `size` metres."""
    r, c, zt, zk = RADIUS, HALF_SPACING, PONTOON_TOP, -DRAFT
    inner, outer = c - PONTOON_WIDTH / 2, c + PONTOON_WIDTH / 2  # 25, 45
    panels = _Panels()
    centre = np.array([c, c, 0.0])

    def radial(p):
        d = p - centre
        d[2] = 0.0
        return d

    # Even, so that the corner pieces' half arcs meet the shell's vertices.
    n_quarter = 2 * _count(np.pi * r / 4, size)
    n_upper = _count(-zt, size)
    n_lower = _count(zt - zk, size)
    # Column, z in [-16, 0]: the whole shell.
    ring = _arc(0.0, 2 * np.pi, 4 * n_quarter, 0.0)
    panels.patch(_ruled(_lift(ring, zt), ring, n_upper), radial)
    # Column, z in [-30, -16]: the outer quarter only.
    quarter = _arc(0.0, np.pi / 2, n_quarter, zk)
    panels.patch(_ruled(quarter, _lift(quarter, zt), n_lower), radial)
    # Pontoon walls, z in [-30, -16].
    n_outer = _count(c, size)
    n_inner = _count(inner, size)
    for a, b, n, direction in [
        ((0, outer), (c, outer), n_outer, (0, 1, 0)),      # x-pontoon, outer side y = 45
        ((0, inner), (inner, inner), n_inner, (0, -1, 0)),  # x-pontoon, inner side y = 25
        ((outer, 0), (outer, c), n_outer, (1, 0, 0)),      # y-pontoon, outer side x = 45
        ((inner, 0), (inner, inner), n_inner, (-1, 0, 0)),  # y-pontoon, inner side x = 25
    ]:
        bottom = _line((*a, zk), (*b, zk), n)
        panels.patch(_ruled(bottom, _lift(bottom, zt), n_lower), lambda p, d=direction: d)
    # Flat faces: the top (z = -16, fluid above) and the keel (z = -30, fluid below).
    n_width = _count(PONTOON_WIDTH, size)
    n_half = n_quarter // 2
    for z, up in [(zt, 1.0), (zk, -1.0)]:
        normal = (lambda p, s=up: (0, 0, s))
        # The straight parts between the symmetry planes and the corner square [25, 45]^2.
        for a, b, d in [((0, inner), (inner, inner), (0, PONTOON_WIDTH)),
                        ((inner, 0), (inner, inner), (PONTOON_WIDTH, 0))]:
            edge = _line((*a, z), (*b, z), n_inner)
            far = edge + np.array([*d, 0.0])
            panels.patch(_ruled(edge, far, n_width), normal)
        # The corner square minus the column's section, in four O-grid pieces between the
        # circle and the square's sides; the outer corner (beyond the rounded corner) is not
        # part of the body, so only the inner halves of the +x and +y pieces are wetted.
        for theta_a, theta_b, a, b, n in [
            (3 * np.pi / 4, 5 * np.pi / 4, (inner, outer), (inner, inner), 2 * n_half),  # -x
            (5 * np.pi / 4, 7 * np.pi / 4, (inner, inner), (outer, inner), 2 * n_half),  # -y
            (-np.pi / 4, 0.0, (outer, inner), (outer, c), n_half),  # +x, inner half
            (np.pi / 2, 3 * np.pi / 4, (c, outer), (inner, outer), n_half),  # +y, inner half
        ]:
            arc = _arc(theta_a, theta_b, n, z)
            side = _line((*a, z), (*b, z), n)
            n_across = _count(r * (np.sqrt(2) - 1), size)
            panels.patch(_ruled(arc, side, n_across), normal)
        if up < 0:
            # The keel under the column: its section, in rings.
            n_rings = _count(r, size)
            circle = _arc(0.0, 2 * np.pi, 4 * n_quarter, z)
            middle = np.tile(np.array([c, c, z]), (len(circle), 1))
            panels.patch(_ruled(middle, circle, n_rings), normal)
    return panels


def quarter_mesh(size, name="platform quarter"):
    import capytaine as cpt
    vertices, faces = quarter_panels(size).arrays()
    return cpt.Mesh(vertices=vertices, faces=faces, name=name)


def platform_mesh(size):
    """The whole wetted surface as a doubly symmetric Capytaine mesh."""
    import capytaine as cpt
    quarter = quarter_mesh(size)
    half = cpt.ReflectionSymmetricMesh(half=quarter, plane="xOz")
    return cpt.ReflectionSymmetricMesh(half=half, plane="yOz", name=f"platform {size} m")
