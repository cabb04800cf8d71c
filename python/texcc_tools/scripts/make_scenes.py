"""make_scenes.py: generate the examples' geometry (Wavefront OBJ) deterministically.

Writes into examples/<name>/generated/ (git-ignored; the committed scene.json files reference
these paths):

  examples/atrium/generated/atrium.obj   a Sponza-like courtyard: two stories of arcades
                                          (columns, arches, balustrades), gallery floors and
                                          roofs, walls, end walls, hanging drapes, tiled floor
  examples/atrium/generated/pedestal.obj the plinth the inserted model stands on
  examples/<ex>/generated/model.obj      the inserted model: two meshing gears on an axle
                                          (crevices at the tooth roots, the rim/web and hub/web
                                          corners, the bolt heads and the axle)
  examples/<ex>/generated/ground.obj     a ground slab for the close-up scenes
  examples/<ex>/generated/shapes.obj     a UV sphere and a UV-mapped cube (image-multiply,
                                          marble, wood, custom-node)

Pure Python (no packages), no randomness: the same files on every run. Python 3.8+.

  python3 scripts/make_scenes.py            # every example
  python3 scripts/make_scenes.py --only atrium rust
  python3 scripts/make_scenes.py --stats    # also print triangle counts per file
  python3 scripts/make_scenes.py --out DIR  # write DIR/<example>/generated/ instead

Units are metres, y is up. The model's object space is about 3.4 x 0.8 x 2.2 (centred on the
origin, standing on y = 0): texture scales in the example graphs are chosen for it.
"""

import argparse
import math
import os
import sys

from texcc_tools.paths import ROOT
TWO_PI = 2.0 * math.pi


class Mesh:
    """Triangles with one position, normal and uv per vertex (OBJ 'f a/a/a')."""

    def __init__(self):
        self.pos = []
        self.nrm = []
        self.uv = []
        self.tris = []

    def vertex(self, p, n, uv):
        self.pos.append(p)
        self.nrm.append(n)
        self.uv.append(uv)
        return len(self.pos) - 1

    def tri(self, a, b, c):
        self.tris.append((a, b, c))

    def quad(self, a, b, c, d):
        """a b c d counter-clockwise seen from the front; a triangle that collapses (two corners
        at one point, as where a lathe profile meets the axis) is left out."""
        for t in ((a, b, c), (a, c, d)):
            p, q, r = (self.pos[i] for i in t)
            if p != q and q != r and r != p:
                self.tris.append(t)

    def flat_quad(self, p0, p1, p2, p3, uvs=((0, 0), (1, 0), (1, 1), (0, 1))):
        """A planar quad with its own vertices and face normal (counter-clockwise front)."""
        n = normalize(cross(sub(p1, p0), sub(p3, p0)))
        if n == (0.0, 0.0, 0.0):
            n = normalize(cross(sub(p2, p1), sub(p0, p1)))
        ids = [self.vertex(p, n, uv) for p, uv in zip((p0, p1, p2, p3), uvs)]
        self.quad(*ids)

    def flat_tri(self, p0, p1, p2):
        n = normalize(cross(sub(p1, p0), sub(p2, p0)))
        self.tri(self.vertex(p0, n, (0, 0)), self.vertex(p1, n, (1, 0)), self.vertex(p2, n, (0, 1)))

    def extend(self, other):
        base = len(self.pos)
        self.pos += other.pos
        self.nrm += other.nrm
        self.uv += other.uv
        self.tris += [(a + base, b + base, c + base) for a, b, c in other.tris]

    def transformed(self, fn_pos, fn_nrm):
        m = Mesh()
        m.pos = [fn_pos(p) for p in self.pos]
        m.nrm = [normalize(fn_nrm(n)) for n in self.nrm]
        m.uv = list(self.uv)
        m.tris = list(self.tris)
        return m


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(v):
    length = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    if length == 0.0:
        return (0.0, 0.0, 0.0)
    return (v[0] / length, v[1] / length, v[2] / length)


def translate(mesh, t):
    return mesh.transformed(lambda p: (p[0] + t[0], p[1] + t[1], p[2] + t[2]), lambda n: n)


def rotate_y(mesh, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))

    def rot(v):
        return (c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2])

    return mesh.transformed(rot, rot)


def scale_mesh(mesh, k):
    return mesh.transformed(lambda p: (p[0] * k, p[1] * k, p[2] * k), lambda n: n)


# --- primitives ------------------------------------------------------------------------------

def box(lo, hi, uv_scale=1.0):
    """An axis-aligned box, outward normals, uvs in metres times uv_scale."""
    m = Mesh()
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    s = uv_scale
    faces = [  # four corners counter-clockwise seen from outside, and the uv axes
        (((x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)), 2, 1),  # +x
        (((x0, y0, z1), (x0, y1, z1), (x0, y1, z0), (x0, y0, z0)), 2, 1),  # -x
        (((x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)), 0, 2),  # +y
        (((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)), 0, 2),  # -y
        (((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)), 0, 1),  # +z
        (((x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0)), 0, 1),  # -z
    ]
    for corners, ua, va in faces:
        uvs = [(c[ua] * s, c[va] * s) for c in corners]
        m.flat_quad(*corners, uvs=uvs)
    return m


def lathe(profile, segments, y0=0.0):
    """Revolves a profile [(radius, y), ...] (bottom to top) around the y axis, smooth normals
    around, faceted along the profile. Radius 0 ends are closed by the profile itself."""
    m = Mesh()
    total = 0.0
    lengths = [0.0]
    for i in range(1, len(profile)):
        total += math.hypot(profile[i][0] - profile[i - 1][0], profile[i][1] - profile[i - 1][1])
        lengths.append(total)
    for i in range(len(profile) - 1):
        (r0, h0), (r1, h1) = profile[i], profile[i + 1]
        dr, dh = r1 - r0, h1 - h0
        length = math.hypot(dr, dh)
        if length == 0.0:
            continue
        nr, ny = dh / length, -dr / length  # outward normal in the (r, y) plane
        ring = []
        for k in range(segments + 1):
            a = TWO_PI * k / segments
            ca, sa = math.cos(a), math.sin(a)
            n = (nr * ca, ny, nr * sa)
            u = k / segments
            ring.append((
                m.vertex((r0 * ca, y0 + h0, r0 * sa), n, (u, lengths[i] / max(total, 1e-9))),
                m.vertex((r1 * ca, y0 + h1, r1 * sa), n, (u, lengths[i + 1] / max(total, 1e-9)))))
        for k in range(segments):
            a0, a1 = ring[k]
            b0, b1 = ring[k + 1]
            m.quad(a0, a1, b1, b0)
    return m


def uv_sphere(radius, center, segments, rings):
    m = Mesh()
    grid = []
    for j in range(rings + 1):
        v = j / rings
        theta = math.pi * v
        row = []
        for i in range(segments + 1):
            u = i / segments
            phi = TWO_PI * u
            n = (math.sin(theta) * math.cos(phi), -math.cos(theta), -math.sin(theta) * math.sin(phi))
            p = (center[0] + radius * n[0], center[1] + radius * n[1], center[2] + radius * n[2])
            row.append(m.vertex(p, n, (u, 1.0 - v)))
        grid.append(row)
    for j in range(rings):
        for i in range(segments):
            a, b = grid[j][i], grid[j][i + 1]
            c, d = grid[j + 1][i + 1], grid[j + 1][i]
            if j == 0:
                m.tri(a, c, d)
            elif j == rings - 1:
                m.tri(a, b, c)
            else:
                m.quad(a, b, c, d)
    return m


def uv_cube(center, half):
    """A cube whose six faces each carry uv [0, 1]^2."""
    m = box((center[0] - half, center[1] - half, center[2] - half),
            (center[0] + half, center[1] + half, center[2] + half))
    for i in range(0, len(m.uv), 4):
        m.uv[i:i + 4] = [(0, 0), (1, 0), (1, 1), (0, 1)]
    return m


def prism(points, y0, y1):
    """A vertical prism over a convex polygon (counter-clockwise seen from above)."""
    m = Mesh()
    n = len(points)
    for i in range(n):
        (xa, za), (xb, zb) = points[i], points[(i + 1) % n]
        m.flat_quad((xa, y0, za), (xa, y1, za), (xb, y1, zb), (xb, y0, zb))
    top = [(x, y1, z) for x, z in points]
    bottom = [(x, y0, z) for x, z in reversed(points)]
    for ring in (top, bottom):
        for i in range(1, n - 1):
            m.flat_tri(ring[0], ring[i + 1], ring[i])
    return m


# --- the inserted model: two meshing gears -----------------------------------------------------

def gear_radius(phase, root, tip):
    """Tooth outline: rise over [0, .2), tip over [.2, .5), fall over [.5, .7), root after."""
    if phase < 0.2:
        return root + (tip - root) * phase / 0.2
    if phase < 0.5:
        return tip
    if phase < 0.7:
        return tip + (root - tip) * (phase - 0.5) / 0.2
    return root


def gear_outline(teeth, per_flat, root, tip):
    """(angle, radius) samples of the toothed outline, every tooth corner sampled exactly (sharp
    tooth roots), the flats subdivided; closed (the last sample repeats the first at +2 pi)."""
    marks = [0.0, 0.2, 0.5, 0.7, 1.0]
    phases = []
    for a, b in zip(marks, marks[1:]):
        steps = 1 if (a, b) in ((0.0, 0.2), (0.5, 0.7)) else per_flat
        phases += [a + (b - a) * k / steps for k in range(steps)]
    samples = [(TWO_PI * (t + ph) / teeth, gear_radius(ph, root, tip))
               for t in range(teeth) for ph in phases]
    return samples + [(samples[0][0] + TWO_PI, samples[0][1])]


def gear(teeth, module, thickness, phase_offset=0.0):
    """A spur gear lying flat (axis y, centred at y = 0): a toothed rim of full thickness, a
    thinner web, and a thick hub around a bore. Faceted (flat normals per quad)."""
    pitch = module * teeth / 2.0
    tip, root = pitch + module, pitch - 1.25 * module
    rim_in = root - 2.2 * module
    bore, hub = 0.16 * pitch, 0.36 * pitch
    ht, web, hub_t = thickness / 2.0, thickness * 0.22, thickness * 0.8
    # Closed (r, y) loop of the cross-section; None marks the toothed outer radius.
    loop = [(bore, hub_t), (hub, hub_t), (hub, web), (rim_in, web), (rim_in, ht), (None, ht),
            (None, -ht), (rim_in, -ht), (rim_in, -web), (hub, -web), (hub, -hub_t), (bore, -hub_t)]
    outline = gear_outline(teeth, 3, root, tip)
    m = Mesh()
    for (a0, r_out0), (a1, r_out1) in zip(outline, outline[1:]):
        b0, b1 = a0 + phase_offset, a1 + phase_offset
        c0, s0, c1, s1 = math.cos(b0), math.sin(b0), math.cos(b1), math.sin(b1)
        for i in range(len(loop)):
            (ra, ya), (rb, yb) = loop[i], loop[(i + 1) % len(loop)]
            ra0 = r_out0 if ra is None else ra
            ra1 = r_out1 if ra is None else ra
            rb0 = r_out0 if rb is None else rb
            rb1 = r_out1 if rb is None else rb
            m.flat_quad((ra0 * c0, ya, ra0 * s0), (ra1 * c1, ya, ra1 * s1),
                        (rb1 * c1, yb, rb1 * s1), (rb0 * c0, yb, rb0 * s0))
    # Six hex bolt heads on each face of the hub.
    for side in (1.0, -1.0):
        for b in range(6):
            a = TWO_PI * (b + 0.5) / 6
            cx, cz = 0.5 * (bore + hub) * math.cos(a), 0.5 * (bore + hub) * math.sin(a)
            size = 0.22 * (hub - bore)
            hexagon = [(cx + size * math.cos(TWO_PI * j / 6), cz + size * math.sin(TWO_PI * j / 6))
                       for j in range(6)]
            if side > 0:
                m.extend(prism(hexagon, hub_t, hub_t + 0.45 * size))
            else:
                m.extend(prism(hexagon, -hub_t - 0.45 * size, -hub_t))
    return m, pitch, bore, hub_t


def gear_model():
    """Two meshing gears and their axles, standing on y = 0, centred on the origin in x."""
    module, thickness = 0.11, 0.26
    big, pitch_big, bore_big, hub_big = gear(18, module, thickness)
    small, pitch_small, bore_small, hub_small = gear(11, module, thickness, phase_offset=math.pi / 11)
    distance = pitch_big + pitch_small
    m = Mesh()
    lift = hub_big + 0.1  # the lower bolt heads and hub rest just above the ground
    x_big, x_small = -distance * 0.42, distance * 0.58
    m.extend(translate(big, (x_big, lift, 0.0)))
    m.extend(translate(small, (x_small, lift, 0.0)))
    for x, bore in ((x_big, bore_big), (x_small, bore_small)):
        axle = lathe([(0.0, 0.0), (bore * 0.98, 0.0), (bore * 0.98, 2 * lift + 0.12),
                      (bore * 1.25, 2 * lift + 0.12), (bore * 1.25, 2 * lift + 0.2),
                      (0.0, 2 * lift + 0.2)], 32)
        m.extend(translate(axle, (x, 0.0, 0.0)))
    return m


# --- the atrium --------------------------------------------------------------------------------

def arch_wall(x0, x1, y_spring, y_top, z0, z1, samples):
    """A wall panel between two columns with a semicircular opening springing at y_spring:
    front (z1) and back (z0) faces and the arch's soffit."""
    m = Mesh()
    xc, r = 0.5 * (x0 + x1), 0.5 * (x1 - x0)
    h = y_top - y_spring
    corner = math.atan2(h, r)
    angles = sorted({math.pi * k / samples for k in range(samples + 1)} |
                    {corner, math.pi - corner})
    inner, outer = [], []
    for a in angles:
        ca, sa = math.cos(a), math.sin(a)
        inner.append((xc + r * ca, y_spring + r * sa))
        # Ray from the centre to the panel's boundary (sides x = x0/x1, top y = y_top).
        t_side = r / abs(ca) if abs(ca) > 1e-9 else float("inf")
        t_top = h / sa if sa > 1e-9 else float("inf")
        t = min(t_side, t_top)
        outer.append((xc + t * ca, y_spring + t * sa))
    for i in range(len(angles) - 1):
        (ix0, iy0), (ix1, iy1) = inner[i], inner[i + 1]
        (ox0, oy0), (ox1, oy1) = outer[i], outer[i + 1]
        # front face (normal +z)
        m.flat_quad((ix0, iy0, z1), (ox0, oy0, z1), (ox1, oy1, z1), (ix1, iy1, z1))
        # back face (normal -z)
        m.flat_quad((ix1, iy1, z0), (ox1, oy1, z0), (ox0, oy0, z0), (ix0, iy0, z0))
        # soffit (normal towards the arch centre)
        m.flat_quad((ix0, iy0, z0), (ix0, iy0, z1), (ix1, iy1, z1), (ix1, iy1, z0))
    return m


def column(height, radius, segments):
    """A column on y = 0: square plinth, moulded base, shaft with entasis, capital, abacus."""
    r = radius
    profile = [(0.0, 0.10), (r * 1.30, 0.10), (r * 1.30, 0.16)]
    for k in range(1, 7):  # torus moulding
        a = math.pi * k / 6
        profile.append((r * 1.18 + 0.12 * r * math.sin(a), 0.16 + 0.12 * r * (1 - math.cos(a))))
    shaft0, shaft1 = 0.16 + 0.24 * r, height - 0.55 * r - 0.08
    rings = 14
    for k in range(rings + 1):
        t = k / rings
        profile.append((r * (1.0 - 0.12 * t * t), shaft0 + (shaft1 - shaft0) * t))
    for k in range(1, 9):  # echinus (capital)
        t = k / 8
        profile.append((r * 0.88 + r * 0.42 * math.sin(0.5 * math.pi * t), shaft1 + 0.55 * r * t))
    profile.append((0.0, shaft1 + 0.55 * r))
    m = lathe(profile, segments)
    m.extend(box((-r * 1.45, 0.0, -r * 1.45), (r * 1.45, 0.10, r * 1.45)))
    a = r * 1.45
    m.extend(box((-a, height - 0.08, -a), (a, height, a)))
    return m


def drape(x0, x1, y_top, y_bottom, z, cols, rows, folds, depth, shift):
    """A hanging cloth banner with sinusoidal folds, both sides (two sheets)."""
    m = Mesh()
    for side in (1.0, -1.0):
        grid = []
        for j in range(rows + 1):
            v = j / rows
            y = y_top + (y_bottom - y_top) * v
            row = []
            for i in range(cols + 1):
                u = i / cols
                x = x0 + (x1 - x0) * u
                ph = TWO_PI * folds * u + shift
                amp = depth * (0.35 + 0.65 * v)
                dz = amp * math.sin(ph + 1.3 * v)
                nz = 1.0
                nx = -amp * math.cos(ph + 1.3 * v) * TWO_PI * folds / (x1 - x0)
                n = normalize((nx * side, 0.0, nz * side))
                row.append(m.vertex((x, y, z + dz + side * 0.004), n, (u, 1.0 - v)))
            grid.append(row)
        for j in range(rows):
            for i in range(cols):
                a, b, c, d = grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]
                if side > 0:
                    m.quad(a, d, c, b)
                else:
                    m.quad(a, b, c, d)
    return m


def baluster(height, radius, segments):
    r = radius
    profile = [(0.0, 0.0), (r, 0.0), (r, 0.05 * height)]
    for k in range(1, 13):
        t = k / 12
        bulge = 0.55 + 0.45 * math.sin(math.pi * min(1.0, t * 1.4))
        profile.append((r * bulge, 0.05 * height + 0.85 * height * t))
    profile += [(r, 0.9 * height), (r, height), (0.0, height)]
    return lathe(profile, segments)


def atrium(detail):
    """The courtyard. detail scales every tessellation (1.0: about 250k triangles)."""
    seg = max(8, int(round(48 * detail)))
    m = Mesh()
    half_x, half_z, gallery = 15.0, 5.0, 3.2      # courtyard x in [-15, 15], z in [-5, 5]
    back = half_z + gallery                         # back walls at z = +-8.2
    bays = 9
    bay = 2.0 * (half_x - 1.5) / bays               # column spacing
    stories = [  # (floor y, column height, column radius, arch top y)
        (0.0, 4.2, 0.34, 6.2),
        (6.2, 2.5, 0.22, 10.2),
    ]
    # Floor: tiles with thin joints (a grid of slightly raised slabs).
    tiles_x, tiles_z = int(round(30 * detail)), int(round(16 * detail))
    tx, tz = 2 * half_x / tiles_x, 2 * back / tiles_z
    for i in range(tiles_x):
        for j in range(tiles_z):
            x0, z0 = -half_x + i * tx, -back + j * tz
            m.extend(box((x0 + 0.015, -0.05, z0 + 0.015), (x0 + tx - 0.015, 0.0, z0 + tz - 0.015),
                         uv_scale=0.5))
    m.extend(box((-half_x, -0.3, -back), (half_x, -0.05, back)))
    for side in (1.0, -1.0):
        for si, (y0, height, radius, y_top) in enumerate(stories):
            z_front = side * half_z
            xs = [-half_x + 1.5 + bay * k for k in range(bays + 1)]
            for x in xs:
                m.extend(translate(column(height, radius, seg), (x, y0, z_front)))
            depth = radius * 1.45
            z0, z1 = (z_front - depth, z_front + depth) if side > 0 else (z_front - depth, z_front + depth)
            for k in range(bays):
                m.extend(arch_wall(xs[k], xs[k + 1], y0 + height, y_top, z0, z1, seg))
            # Entablature over the arches, and the walls at the ends of the arcade.
            m.extend(box((-half_x, y_top, z0), (half_x, y_top + 0.35, z1)))
            m.extend(box((-half_x, y0, z0), (xs[0] - radius * 1.45, y_top, z1)))
            m.extend(box((xs[-1] + radius * 1.45, y0, z0), (half_x, y_top, z1)))
            # Gallery ceiling/floor slab and the back wall of the gallery.
            zb0, zb1 = sorted((z_front, side * back))
            m.extend(box((-half_x, y_top, zb0), (half_x, y_top + 0.35, zb1)))
            wall0, wall1 = sorted((side * back, side * (back + 0.4)))
            m.extend(box((-half_x, y0, wall0), (half_x, y_top + 0.35, wall1)))
            if si == 1:
                # Balustrade along the upper gallery: rails and balusters between the columns.
                rail_z0, rail_z1 = z_front - 0.14, z_front + 0.14
                for k in range(bays):
                    xa, xb = xs[k] + radius * 1.5, xs[k + 1] - radius * 1.5
                    m.extend(box((xa, y0, rail_z0), (xb, y0 + 0.08, rail_z1)))
                    m.extend(box((xa, y0 + 0.86, rail_z0), (xb, y0 + 0.96, rail_z1)))
                    count = max(2, int(round(10 * detail)))
                    for b in range(count):
                        bx = xa + (xb - xa) * (b + 0.5) / count
                        m.extend(translate(baluster(0.78, 0.07, max(8, seg // 4)),
                                           (bx, y0 + 0.08, z_front)))
            if si == 0:
                # Drapes hanging from the upper gallery, every other bay.
                for k in range(0, bays, 2):
                    xa, xb = xs[k] + 0.55, xs[k + 1] - 0.55
                    m.extend(drape(xa, xb, 9.9, 7.4, z_front - side * 0.5,
                                   int(32 * detail), int(40 * detail), 3, 0.09, 0.7 * k))
    # End walls with a doorway, up to the roof line, and a cornice all around the top.
    top = stories[-1][3] + 0.35
    for side in (1.0, -1.0):
        x0, x1 = sorted((side * half_x, side * (half_x + 0.5)))
        m.extend(box((x0, 0.0, -back), (x1, top, -1.4)))
        m.extend(box((x0, 0.0, 1.4), (x1, top, back)))
        m.extend(box((x0, 3.6, -1.4), (x1, top, 1.4)))
        c0, c1 = sorted((side * (half_x + 0.5), side * (half_x - 0.3)))
        m.extend(box((c0, top, -back - 0.4), (c1, top + 0.3, back + 0.4)))
    for side in (1.0, -1.0):
        z0, z1 = sorted((side * (back + 0.4), side * (half_z - 0.3)))
        m.extend(box((-half_x - 0.5, top, z0), (half_x + 0.5, top + 0.3, z1)))
    return m


def pedestal():
    """The plinth in the middle of the courtyard (the model stands on it)."""
    m = box((-2.9, 0.0, -2.9), (2.9, 0.45, 2.9))
    m.extend(box((-2.75, 0.45, -2.75), (2.75, 0.6, 2.75)))
    return m


def ground(size):
    return box((-size, -0.1, -size), (size, 0.0, size), uv_scale=0.5)


def shapes():
    """A UV sphere and a UV-mapped cube side by side, standing on y = 0."""
    m = uv_sphere(0.75, (-0.9, 0.75, 0.0), 96, 48)
    m.extend(rotate_y(uv_cube((0.0, 0.6, 0.0), 0.6), 30.0).transformed(
        lambda p: (p[0] + 1.0, p[1], p[2]), lambda n: n))
    return m


# --- output ------------------------------------------------------------------------------------

def write_obj(path, mesh, what):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    out = ["# %s\n# generated by scripts/make_scenes.py (do not edit; git-ignored)\n" % what,
           "# %d vertices, %d triangles\n" % (len(mesh.pos), len(mesh.tris))]
    out += ["v %.5f %.5f %.5f\n" % p for p in mesh.pos]
    out += ["vt %.5f %.5f\n" % uv for uv in mesh.uv]
    out += ["vn %.4f %.4f %.4f\n" % n for n in mesh.nrm]
    out += ["f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a + 1, a + 1, a + 1, b + 1, b + 1, b + 1,
                                                  c + 1, c + 1, c + 1) for a, b, c in mesh.tris]
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("".join(out))
    os.replace(tmp, path)
    return len(mesh.tris)


def closeup_files(model):
    return [("model.obj", model, "two meshing gears (the inserted model)"),
            ("ground.obj", ground(20.0), "ground slab")]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", nargs="*", help="examples to generate (default: all)")
    ap.add_argument("--detail", type=float, default=1.0, help="atrium tessellation factor")
    ap.add_argument("--stats", action="store_true", help="print triangle counts")
    ap.add_argument("--out", default=os.path.join(ROOT, "examples"),
                    help="folder holding the example folders (default: the repository's examples/)")
    args = ap.parse_args(argv)
    model = gear_model()
    plan = {
        "atrium": [("atrium.obj", None, "Sponza-like atrium"),
                   ("pedestal.obj", pedestal(), "pedestal"),
                   ("model.obj", model, "two meshing gears (the inserted model)")],
        "rust": closeup_files(model),
        "scratches": closeup_files(model),
        "image-multiply": [("shapes.obj", None, "UV sphere and UV cube"),
                           ("ground.obj", ground(20.0), "ground slab")],
        "marble": [("shapes.obj", None, "UV sphere and UV cube"),
                   ("ground.obj", ground(20.0), "ground slab")],
        "custom-node": [("shapes.obj", None, "UV sphere and UV cube"),
                        ("ground.obj", ground(20.0), "ground slab")],
        "wood": [("shapes.obj", None, "UV sphere and UV cube"),
                 ("ground.obj", ground(20.0), "ground slab")],
    }
    wanted = args.only or list(plan)
    for name in wanted:
        if name not in plan:
            sys.exit("make_scenes: unknown example '%s' (known: %s)" % (name, ", ".join(plan)))
    shapes_mesh = None
    for name in wanted:
        for filename, mesh, what in plan[name]:
            if mesh is None and filename == "atrium.obj":
                mesh = atrium(args.detail)
            elif mesh is None:
                shapes_mesh = shapes_mesh or shapes()
                mesh = shapes_mesh
            path = os.path.join(args.out, name, "generated", filename)
            count = write_obj(path, mesh, what)
            if args.stats:
                print("%-45s %8d triangles" % ("%s/generated/%s" % (name, filename), count))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
