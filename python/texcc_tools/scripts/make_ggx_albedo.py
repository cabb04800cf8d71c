"""Writes kernels/common/rt_ggx_albedo.h: the tables rt_bsdf.h's GGX lobes (isotropic GGX,
alpha = roughness^2, height-correlated Smith masking-shadowing G2 = 1 / (1 + L(wi) + L(wo)), as
Cycles' microfacet closures) take their energy terms from, laid out as Cycles lays out the
tables of the same quantities (nodes at x / (n - 1), roughness on the fast axis, linear
interpolation: rt_ggx_lookup2/3):

  rt_ggx_e[32 x 32]       E(roughness, cos wo): the directional albedo of the lobe with
                          Fresnel 1 (single scattering)
  rt_ggx_eavg[32]         E_avg(roughness) = 2 * integral of E(mu) mu dmu
  rt_ggx_s_ior[16^3]      S(roughness, cos wo, z): the mean over the visible normals of the
                          Fresnel interpolation factor s = (F(cos wi.h, eta) - F0) / (1 - F0) of a
                          dielectric of IOR eta = ior(F0 = z^4) (0 where the reflection leaves the
                          surface): the albedo of a Principled specular layer of reflectance F0
                          is then estimated as F0 + (1 - F0) S, as Cycles estimates it

Each entry is the mean over a stratified grid of visible-normal samples (Heitz 2018), computed
here with numpy (nothing is copied from Cycles; only the definitions are the same).

usage: .venv/bin/python scripts/make_ggx_albedo.py [OUT.h]
"""
import argparse
import os

import numpy as np

from texcc_tools.atomic import atomic_open
from texcc_tools.paths import KERNELS

K = int(os.environ.get("GGX_TABLE_K", 256))  # K x K stratified samples per entry


def samples(k=K, seed=7):
    rng = np.random.default_rng(seed)
    g = (np.arange(k) + 0.5) / k
    u1, u2 = np.meshgrid(g, g)
    j = rng.random((2, k, k)) - 0.5
    return (u1 + j[0] / k).ravel(), (u2 + j[1] / k).ravel()


def concentric(u1, u2):
    a, b = 2 * u1 - 1, 2 * u2 - 1
    r = np.where(np.abs(a) > np.abs(b), a, b)
    phi = np.where(np.abs(a) > np.abs(b), np.pi / 4 * b / np.where(a == 0, 1, a),
                   np.pi / 2 - np.pi / 4 * a / np.where(b == 0, 1, b))
    phi = np.where((a == 0) & (b == 0), 0, phi)
    return r * np.cos(phi), r * np.sin(phi)


def lam(a2, c):
    return 0.5 * (np.sqrt(1 + a2 * np.maximum(1 / (c * c) - 1, 0)) - 1)


def fresnel_dielectric(c, eta):
    g2 = eta * eta - 1 + c * c
    g = np.sqrt(np.maximum(g2, 0))
    a = (g - c) / (g + c)
    b = (c * (g + c) - 1) / (c * (g - c) + 1)
    return np.where(g2 > 0, 0.5 * a * a * (1 + b * b), 1.0)


def vndf(rough, mu, u1, u2):
    """Visible normals for wo = (sqrt(1 - mu^2), 0, mu): (h, wi, valid, lambda(wo), lambda(wi))."""
    al = max(rough * rough, 1e-8)
    wo = np.array([np.sqrt(max(1 - mu * mu, 0)), 0.0, mu])
    v = np.array([al * wo[0], al * wo[1], wo[2]])
    v /= np.linalg.norm(v)
    lsq = v[0] ** 2 + v[1] ** 2
    t1 = np.array([-v[1], v[0], 0]) / np.sqrt(lsq) if lsq > 1e-7 else np.array([1.0, 0, 0])
    t2 = np.cross(v, t1)
    tx, ty = concentric(u1, u2)
    ty = (1 - 0.5 * (1 + v[2])) * np.sqrt(np.maximum(1 - tx * tx, 0)) + 0.5 * (1 + v[2]) * ty
    tz = np.sqrt(np.maximum(1 - tx * tx - ty * ty, 0))
    hh = tx[:, None] * t1 + ty[:, None] * t2 + tz[:, None] * v
    h = np.stack([al * hh[:, 0], al * hh[:, 1], np.maximum(hh[:, 2], 0)], 1)
    h /= np.linalg.norm(h, axis=1, keepdims=True)
    d = h @ wo
    wi_z = 2 * d * h[:, 2] - wo[2]
    a2 = al * al
    valid = wi_z > 0
    return d, valid, lam(a2, mu), lam(a2, np.maximum(wi_z, 1e-12))


def tables():
    u1, u2 = samples()
    n, m = 32, 16
    e = np.zeros((n, n))  # [mu][rough]
    for y in range(n):
        for x in range(n):
            rough, mu = min(max(x / (n - 1), 1e-4), 1), min(max(y / (n - 1), 1e-4), 1)
            d, valid, lo, li = vndf(rough, mu, u1, u2)
            e[y, x] = min(np.where(valid, (1 + lo) / (1 + lo + li), 0).mean(), 1)
    # E_avg: 2 int E mu dmu, by Gauss-Legendre in mu with E computed at each node
    gx, gw = np.polynomial.legendre.leggauss(48)
    mus, ws = 0.5 * (gx + 1), 0.5 * gw
    eavg = np.zeros(n)
    for x in range(n):
        rough = min(max(x / (n - 1), 1e-4), 1)
        tot = 0.0
        for mu, w in zip(mus, ws):
            d, valid, lo, li = vndf(rough, mu, u1[::4], u2[::4])
            tot += w * 2 * mu * np.where(valid, (1 + lo) / (1 + lo + li), 0).mean()
        eavg[x] = min(tot, 1)
    s = np.zeros((m, m, m))  # [z][mu][rough]
    for z in range(m):
        zz = min(max(z / (m - 1), 1e-4), 0.99)
        f0 = zz ** 4
        eta = (1 + np.sqrt(f0)) / (1 - np.sqrt(f0))
        for y in range(m):
            for x in range(m):
                rough, mu = min(max(x / (m - 1), 1e-4), 1), min(max(y / (m - 1), 1e-4), 1)
                d, valid, _, _ = vndf(rough, mu, u1, u2)
                f = fresnel_dielectric(np.clip(d, 0, 1), eta)
                sv = np.clip((f - f0) / (1 - f0), 0, 1)
                s[z, y, x] = np.clip(np.where(valid, sv, 0).mean(), 0, 1)
    return e, eavg, s


def main():
    ap = argparse.ArgumentParser(description="Writes the GGX energy tables of rt_bsdf.h.")
    ap.add_argument("out", nargs="?", default=os.path.join(KERNELS, "common", "rt_ggx_albedo.h"),
                    help="the header to write (default: kernels/common/rt_ggx_albedo.h)")
    out = ap.parse_args().out
    e, eavg, s = tables()

    def rows(t):
        t = t.reshape(-1, t.shape[-1])
        return ",\n".join("  " + ", ".join("%.5ff" % v for v in row) for row in t)

    with atomic_open(out, "w") as f:
        f.write("/* rt_ggx_albedo.h: generated by scripts/make_ggx_albedo.py; do not edit.\n"
                " * The energy terms of rt_bsdf.h's GGX lobes (height-correlated Smith G), Cycles'\n"
                " * layout: node i of an axis of n nodes at i / (n - 1), roughness fastest.\n"
                " * rt_ggx_e[mu][roughness]: directional albedo, Fresnel 1 (32 x 32);\n"
                " * rt_ggx_eavg[roughness]: its cosine-weighted average over cos wo (32);\n"
                " * rt_ggx_s_ior[z][mu][roughness]: the mean dielectric Fresnel interpolation\n"
                " * factor over the visible normals, IOR from F0 = z^4 (16 x 16 x 16). */\n"
                "#ifndef RT_GGX_ALBEDO_H\n#define RT_GGX_ALBEDO_H\n\n"
                "__constant float rt_ggx_e[32 * 32] = {\n%s};\n\n"
                "__constant float rt_ggx_eavg[32] = {\n%s};\n\n"
                "__constant float rt_ggx_s_ior[16 * 16 * 16] = {\n%s};\n\n#endif\n"
                % (rows(e), rows(eavg.reshape(4, 8)), rows(s)))


if __name__ == "__main__":
    main()
