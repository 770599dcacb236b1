"""Panel meshes of parametric hulls for the BEM (plain numpy; Capytaine not needed).

Two hull forms, both port/starboard symmetric, meshed as their y <= 0 half (the BEM
rebuilds the other half by reflection in the centreplane), in the vessel frame
x forward, y to port, z up, z = 0 at the waterline, x = 0 at midship:

* :func:`slotted_twin_hull` - the representative heavy-lift hull of the default
  vessel: a flat-bottomed, wall-sided hull of length L and beam B whose forward part
  is split by a bow slot (length ``slot_length``, width ``slot_width``) into two
  demi-hulls, the layout of the twin-hull heavy-lift vessels that lift topsides in
  their bow slot; the slot moves the centre of buoyancy aft and makes the hull
  asymmetric fore and aft, so beam seas yaw it.
* :func:`ship_hull` - a monohull ship form (parallel middle body, a fine entrance
  forward and a fuller run aft, a rounded bilge), the ship-shaped hull of the
  interpolation test data (``scripts/make_rao_interpolation_data.py``).

Each returns a :class:`HalfMesh` of quadrilateral panels with outward normals (into
the water) and the panels of an interior lid at ``lid_z`` (irregular-frequency
removal, normals down as Capytaine's own lids), with the hull's analytical volume,
centre of buoyancy and waterplane properties where they have a closed form.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from jls.errors import InputError


@dataclass(frozen=True)
class HalfMesh:
    """The y <= 0 half of a hull: vertices (n, 3), quadrilateral faces (m, 4) and lid."""

    vertices: np.ndarray
    faces: np.ndarray
    lid_vertices: np.ndarray
    lid_faces: np.ndarray
    description: str
    facts: dict = field(default_factory=dict)


def _divisions(edges, size):
    """Grid coordinates through every breakpoint in ``edges`` (sorted), no cell larger
    than ``size``."""
    out = [edges[0]]
    for a, b in zip(edges[:-1], edges[1:]):
        n = max(1, int(np.ceil((b - a) / size - 1e-9)))
        out.extend(np.linspace(a, b, n + 1)[1:])
    return np.asarray(out, float)


class _Builder:
    """Collects quadrilaterals, merging shared vertices and orienting each face."""

    def __init__(self):
        self.index, self.vertices, self.faces = {}, [], []

    def vertex(self, p):
        key = tuple(np.round(np.asarray(p, float), 6))
        if key not in self.index:
            self.index[key] = len(self.vertices)
            self.vertices.append(key)
        return self.index[key]

    def quad(self, corners, outward):
        corners = [np.asarray(c, float) for c in corners]
        normal = np.cross(corners[2] - corners[0], corners[3] - corners[1])
        if np.dot(normal, outward) < 0:
            corners = corners[::-1]
        self.faces.append([self.vertex(c) for c in corners])

    def arrays(self):
        return np.asarray(self.vertices, float), np.asarray(self.faces, int)


def _check_positive(**values):
    for name, value in values.items():
        if not np.isfinite(value) or value <= 0:
            raise InputError("must be a positive length in m", field=name, value=value)


def slotted_twin_hull(length, beam, draught, slot_length, slot_width, panel_size,
                      lid_z=None, lid_panel_size=None) -> HalfMesh:
    """Wall-sided, flat-bottomed hull with a bow slot (see the module docstring); lid
    panels of ``lid_panel_size`` (default twice the hull's)."""
    _check_positive(length=length, beam=beam, draught=draught, panel_size=panel_size)
    if not (0 <= slot_length < length and 0 <= slot_width < beam):
        raise InputError("the slot must be shorter than the hull and narrower than its beam",
                         field="slot", value=[slot_length, slot_width])
    x0, x1, xs = -length / 2, length / 2, length / 2 - slot_length
    xs_grid = _divisions(sorted({x0, xs, x1}), panel_size)
    ys_grid = _divisions(sorted({-beam / 2, -slot_width / 2, 0.0}), panel_size)
    zs_grid = _divisions([-draught, 0.0], panel_size)
    xc, yc = (xs_grid[:-1] + xs_grid[1:]) / 2, (ys_grid[:-1] + ys_grid[1:]) / 2

    def inside(x, y):
        return (x0 < x < x1) and (-beam / 2 < y < 0.0 + 1e-9) and not (x > xs and y > -slot_width / 2)

    hull, lid = _Builder(), _Builder()
    zl = -0.02 * draught if lid_z is None else float(lid_z)
    for i, x in enumerate(xc):
        for j, y in enumerate(yc):
            if not inside(x, y):
                continue
            a, b = xs_grid[i], xs_grid[i + 1]
            c, d = ys_grid[j], ys_grid[j + 1]
            hull.quad([(a, c, -draught), (b, c, -draught), (b, d, -draught), (a, d, -draught)],
                      (0, 0, -1))
            # walls on the cell's edges that face water (not the centreplane y = 0)
            for (p, q), out, nb in (
                    (((a, c), (b, c)), (0, -1, 0), (x, y - (d - c))),
                    (((a, d), (b, d)), (0, 1, 0), (x, y + (d - c))),
                    (((a, c), (a, d)), (-1, 0, 0), (x - (b - a), y)),
                    (((b, c), (b, d)), (1, 0, 0), (x + (b - a), y))):
                if out == (0, 1, 0) and abs(d) < 1e-9:
                    continue
                if inside(*nb):
                    continue
                for k in range(zs_grid.size - 1):
                    z0, z1 = zs_grid[k], zs_grid[k + 1]
                    hull.quad([(*p, z0), (*q, z0), (*q, z1), (*p, z1)], out)
    lid_size = 2 * panel_size if lid_panel_size is None else float(lid_panel_size)
    xl = _divisions(sorted({x0, xs, x1}), lid_size)
    yl = _divisions(sorted({-beam / 2, -slot_width / 2, 0.0}), lid_size)
    for a, b in zip(xl[:-1], xl[1:]):
        for c, d in zip(yl[:-1], yl[1:]):
            if inside((a + b) / 2, (c + d) / 2):
                lid.quad([(a, c, zl), (b, c, zl), (b, d, zl), (a, d, zl)], (0, 0, -1))
    vertices, faces = hull.arrays()
    lid_vertices, lid_faces = lid.arrays()
    area = length * beam - slot_length * slot_width
    volume = area * draught
    x_b = -(slot_length * slot_width * (length / 2 - slot_length / 2)) / area
    # waterplane second moments about the centreplane (roll) and about x = x_b (pitch)
    i_t = length * beam ** 3 / 12 - slot_length * slot_width ** 3 / 12
    i_l0 = beam * length ** 3 / 12 - slot_width * (x1 ** 3 - xs ** 3) / 3
    i_l = i_l0 - area * x_b ** 2
    facts = {"volume_m3": volume, "waterplane_area_m2": area, "x_b_m": x_b,
             "z_b_m": -draught / 2, "waterplane_i_t_m4": i_t, "waterplane_i_l_m4": i_l,
             "bm_t_m": i_t / volume, "bm_l_m": i_l / volume}
    desc = (f"twin hull with a bow slot: {length:g} m x {beam:g} m, draught {draught:g} m, "
            f"slot {slot_length:g} m long x {slot_width:g} m wide (two demi-hulls of "
            f"{(beam - slot_width) / 2:g} m forward), wall-sided, flat bottom")
    return HalfMesh(vertices, faces, lid_vertices, lid_faces, desc, facts)


def ship_hull(length, beam, draught, panel_size, *, parallel=0.5, bow_power=2.0,
              stern_power=3.0, bilge_power=6.0, lid_z=None, lid_panel_size=None) -> HalfMesh:
    """Monohull ship form: half-breadth b(x, z) = B/2 f(x) g(z).

    f = 1 over the parallel middle body (``parallel`` of the length, centred 0.05 L aft
    of midship), falling to zero at the bow as 1 - s^bow_power and at the stern as
    1 - s^stern_power (s from 0 at the end of the parallel body to 1 at the end: a fine
    entrance forward and a fuller run aft); g = 1 - (-z/T)^bilge_power (a rounded bilge,
    the keel at z = -T). The lid's panels are ``lid_panel_size`` (default twice the
    hull's): a lid only has to suppress the irregular frequencies.
    """
    _check_positive(length=length, beam=beam, draught=draught, panel_size=panel_size)
    mid = -0.05 * length
    fwd, aft = mid + parallel * length / 2, mid - parallel * length / 2

    def f(x):
        x = np.asarray(x, float)
        s_b = np.clip((x - fwd) / (length / 2 - fwd), 0, 1)
        s_s = np.clip((aft - x) / (aft + length / 2), 0, 1)
        return np.where(x > fwd, 1 - s_b ** bow_power, np.where(x < aft, 1 - s_s ** stern_power, 1.0))

    def g(z):
        return 1 - np.clip(-np.asarray(z, float) / draught, 0, 1) ** bilge_power

    xs = _divisions(sorted({-length / 2, aft, fwd, length / 2}), panel_size)
    nz = max(3, int(np.ceil((draught + beam / 2) / panel_size)))
    # girth coordinate: cosine spacing toward the keel resolves the bilge
    zs = -draught * np.sin(np.linspace(0, np.pi / 2, nz + 1))
    hull = _Builder()
    for i in range(xs.size - 1):
        for k in range(nz):
            pts = [(xs[i], zs[k]), (xs[i + 1], zs[k]), (xs[i + 1], zs[k + 1]), (xs[i], zs[k + 1])]
            corners = [(x, -beam / 2 * float(f(x)) * float(g(z)), z) for x, z in pts]
            xm, zm = (xs[i] + xs[i + 1]) / 2, (zs[k] + zs[k + 1]) / 2
            # outward normal of the surface y + b(x, z) = 0 on the y < 0 side: -grad
            h = 1e-4 * length
            dbdx = (f(xm + h) - f(xm - h)) / (2 * h) * g(zm) * beam / 2
            dbdz = (g(zm + h * draught / length) - g(zm - h * draught / length)) \
                / (2 * h * draught / length) * f(xm) * beam / 2
            out = np.array([-dbdx, -1.0, -dbdz])
            if np.linalg.norm(np.cross(np.subtract(corners[2], corners[0]),
                                       np.subtract(corners[3], corners[1]))) < 1e-9:
                continue      # degenerate panel at a closed end
            hull.quad(corners, out)
    vertices, faces = hull.arrays()
    lid = _Builder()
    zl = -0.02 * draught if lid_z is None else float(lid_z)
    lid_size = 2 * panel_size if lid_panel_size is None else float(lid_panel_size)
    ny = max(2, int(np.ceil(beam / 2 / lid_size)))
    xl = _divisions(sorted({-length / 2, aft, fwd, length / 2}), lid_size)
    for i in range(xl.size - 1):
        b0 = beam / 2 * float(f(xl[i])) * float(g(zl))
        b1 = beam / 2 * float(f(xl[i + 1])) * float(g(zl))
        for j in range(ny):
            e0, e1 = j / ny, (j + 1) / ny
            corners = [(xl[i], -b0 * e0, zl), (xl[i + 1], -b1 * e0, zl),
                       (xl[i + 1], -b1 * e1, zl), (xl[i], -b0 * e1, zl)]
            if max(b0, b1) * (e1 - e0) < 1e-6:
                continue
            lid.quad(corners, (0, 0, -1))
    lid_vertices, lid_faces = lid.arrays()
    desc = (f"ship form {length:g} m x {beam:g} m, draught {draught:g} m: parallel middle "
            f"body {parallel:g} L, entrance power {bow_power:g}, run power {stern_power:g}, "
            f"bilge power {bilge_power:g}")
    return HalfMesh(vertices, faces, lid_vertices, lid_faces, desc, {})
