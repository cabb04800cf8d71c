#!/usr/bin/env python3
"""Writes kernels/common/rt_ggx_albedo.h: the tables rt_bsdf.h's GGX lobes (isotropic GGX,
alpha = roughness^2, height-correlated Smith masking-shadowing G2 = 1 / (1 + L(wi) + L(wo)), as
Cycles' microfacet closures) take their energy terms from, laid out as Cycles lays out the
tables of the same quantities (nodes at x / (n - 1), roughness on the fast axis, linear
interpolation: rt_ggx_lookup2/3):

The code is texcc_tools.scripts.make_ggx_albedo (python/texcc_tools/scripts/make_ggx_albedo.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.make_ggx_albedo import main

if __name__ == "__main__":
    main()
