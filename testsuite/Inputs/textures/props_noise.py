"""Defining properties of textures/noise.cl, evaluated through texcc's host target."""
import math

from texprops import Oracle, check, finish, lcg_points, main_args

P = {"attr": "ObjectPos"}
UV = {"attr": "TexCoord0"}
o = Oracle(main_args(), "noise", ["noise.cl"], {
    "p3": ("perlin3", {"p": P, "scale": 1.0}),
    "p3s": ("perlin3", {"p": P, "scale": 2.5}),
    "p2": ("perlin2", {"p": UV, "scale": 1.0}),
    "fbm1": ("fbm3", {"p": P, "scale": 1.0, "octaves": 1, "lacunarity": 2.0, "gain": 0.5}),
    "fbm": ("fbm3", {"p": P, "scale": 1.0, "octaves": 6, "lacunarity": 2.0, "gain": 0.5}),
    "fbm16": ("fbm3", {"p": P, "scale": 1.0, "octaves": 16, "lacunarity": 1.9, "gain": 0.6}),
    "fbm40": ("fbm3", {"p": P, "scale": 1.0, "octaves": 40, "lacunarity": 1.9, "gain": 0.6}),
    "turb1": ("turbulence3", {"p": P, "scale": 1.0, "octaves": 1, "lacunarity": 2.0, "gain": 0.5}),
    "turb": ("turbulence3", {"p": P, "scale": 1.0, "octaves": 6, "lacunarity": 2.0, "gain": 0.5}),
    "ridged1": ("ridged3", {"p": P, "scale": 1.0, "octaves": 1, "lacunarity": 2.0, "gain": 0.5}),
    "ridged": ("ridged3", {"p": P, "scale": 1.0, "octaves": 6, "lacunarity": 2.0, "gain": 0.5}),
})
pts = lcg_points(1500, -40.0, 40.0)

# Known values: gradient noise is 0 on every lattice point (3D and 2D).
for x, y, z in lcg_points(60, -20.0, 20.0, seed=7):
    q = (float(math.floor(x)), float(math.floor(y)), float(math.floor(z)))
    check(abs(o.scalar("p3", pos=q)) < 1e-6, "perlin3%s = %g, expected 0" % (q, o.scalar("p3", pos=q)))
    check(abs(o.scalar("p2", uv=q[:2])) < 1e-6, "perlin2%s != 0" % (q[:2],))

# Range and spread: [-1, 1], mean near 0, not degenerate.
vals = [o.scalar("p3", pos=p) for p in pts]
check(all(abs(v) <= 1.0 + 1e-6 for v in vals), "perlin3 leaves [-1, 1]: %g" % max(map(abs, vals)))
mean = sum(vals) / len(vals)
std = math.sqrt(sum((v - mean) ** 2 for v in vals) / len(vals))
check(abs(mean) < 0.03, "perlin3 mean %g is not near 0" % mean)
check(0.15 < std < 0.4, "perlin3 standard deviation %g outside (0.15, 0.4)" % std)
vals2 = [o.scalar("p2", uv=p[:2]) for p in pts[:600]]
check(all(abs(v) <= 1.0 + 1e-6 for v in vals2), "perlin2 leaves [-1, 1]")
check(max(map(abs, vals2)) > 0.5, "perlin2 never leaves [-0.5, 0.5]: not rescaled to [-1, 1]?")

# Continuity across cell borders: value and slope agree on both sides of x = k (quintic fade:
# C2), for the 3D and the 2D noise.
eps = 1e-3
CURV = []
for x, y, z in pts[:150]:
    k = float(round(x))
    left = [o.scalar("p3", pos=(k - i * eps, y, z)) for i in (2, 1)]
    right = [o.scalar("p3", pos=(k + i * eps, y, z)) for i in (1, 2)]
    mid = o.scalar("p3", pos=(k, y, z))
    check(abs(left[1] - mid) < 1e-2 and abs(right[0] - mid) < 1e-2,
          "perlin3 jumps at x = %g" % k)
    slope_l, slope_r = (mid - left[1]) / eps, (right[0] - mid) / eps
    check(abs(slope_l - slope_r) < 0.05, "perlin3 slope jumps at x = %g: %g vs %g" % (k, slope_l, slope_r))
    # Curvature too (C2): one-sided second differences agree.
    e2 = 1e-2
    v = [o.scalar("p3", pos=(k + i * e2, y, z)) for i in (-2, -1, 0, 1, 2)]
    curv_l = (v[0] - 2 * v[1] + v[2]) / (e2 * e2)
    curv_r = (v[2] - 2 * v[3] + v[4]) / (e2 * e2)
    CURV.append(abs(curv_l - curv_r))
    j = float(round(y))
    a, b = o.scalar("p2", uv=(x, j - 1e-4)), o.scalar("p2", uv=(x, j + 1e-4))
    check(abs(a - b) < 1e-3, "perlin2 jumps at y = %g" % j)

print("largest curvature difference across x = k: %g" % max(CURV))
check(max(CURV) < 4.0, "perlin3 curvature jumps across cell borders (%g): not the quintic fade?" % max(CURV))

# Scale: perlin3(p, s) = perlin3(p * s, 1).
for p in pts[:200]:
    a = o.scalar("p3s", pos=p)
    b = o.scalar("p3", pos=tuple(c * 2.5 for c in p))
    check(abs(a - b) < 2e-4, "perlin3(p, 2.5) != perlin3(2.5 p, 1) at %s: %g vs %g" % (p, a, b))

# Fractals: one octave is the noise itself (fbm), its magnitude (turbulence), its ridge
# (1 - |n|)^2 (ridged); ranges; octaves beyond 16 are clamped to 16.
for p in pts[:300]:
    n = o.scalar("p3", pos=p)
    check(abs(o.scalar("fbm1", pos=p) - n) < 1e-6, "fbm3(octaves 1) != perlin3 at %s" % (p,))
    check(abs(o.scalar("turb1", pos=p) - abs(n)) < 1e-6, "turbulence3(octaves 1) != |perlin3|")
    check(abs(o.scalar("ridged1", pos=p) - (1 - abs(n)) ** 2) < 1e-5, "ridged3(octaves 1) != (1-|n|)^2")
    f, t, r = o.scalar("fbm", pos=p), o.scalar("turb", pos=p), o.scalar("ridged", pos=p)
    check(-1.0 <= f <= 1.0, "fbm3 = %g outside [-1, 1]" % f)
    check(0.0 <= t <= 1.0, "turbulence3 = %g outside [0, 1]" % t)
    check(0.0 <= r <= 1.0, "ridged3 = %g outside [0, 1]" % r)
    check(o.scalar("fbm16", pos=p) == o.scalar("fbm40", pos=p), "fbm3 octaves not clamped to 16")
# More octaves add detail: fbm differs from its first octave somewhere.
check(any(abs(o.scalar("fbm", pos=p) - o.scalar("fbm1", pos=p)) > 0.01 for p in pts[:50]),
      "fbm3 with 6 octaves equals its first octave everywhere")
finish()
