"""blender_report.py: writes docs/blender-nodes.md, texcc's Blender nodes against Cycles.

Runs testsuite/Inputs/blender/compare.py over every fixture of testsuite/Inputs/blender/ on the
host target and (when an OpenCL device answers) on the OpenCL device, and writes one table row
per (variant, output) with both targets' figures, then the nodes of the issue that have no
fixture yet, with the reason.

    scripts/blender_report.py [--build build] [--no-device]

Needs a built texcc and texcc-eval (scripts/build.sh); not bpy.
"""

import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

from texcc_tools.paths import ROOT, add_build_argument

# Outputs of the nodes that textures/blender/ implements without a point fixture (or
# whose exported form the fixtures do not evaluate), how they are checked, and what is refused.
NOT_YET = [
    ("Texture Coordinate UV and Normal (`blTexCoordUV`, `blTexCoordNormal`)",
     "implemented (TexCoord0; the shading normal through the object's axes, passed as "
     "arguments), no fixture: compare.py evaluates at points with texcc-eval, which sets "
     "ObjectPos and WorldPos from a point but draws TexCoord0 and Normal at random; "
     "input-attributes-{host,device}.test check them against the same hit's attributes"),
    ("Geometry Normal, True Normal, Tangent, Incoming (`blGeometry*`)",
     "implemented as the attributes Normal, GeomNormal, Tangent and ViewDir; no fixture, for the "
     "same reason. Tangent is the mesh's MikkTSpace tangent where its OBJ gives one (the "
     "exporter writes it for meshes a Normal Map shades), else dP/du of its UVs; Cycles' "
     "Geometry Tangent is radial about Z when the mesh has no UV map, so they agree only with "
     "one. Backfacing (an attribute since the Normal Map needs it), Parametric, Pointiness and "
     "Random Per Island are not translated"),
    ("Normal Map, Tangent Space (`blNormalMap`)",
     "its fixtures above (normalmap-strength-*) compare `blNormalMapFrame`, which it calls with "
     "the hit's Normal, Tangent, TangentSign and Backfacing, with the bake plane's frame as "
     "arguments; the frame itself (the exporter's MikkTSpace tangents, interpolated as Cycles "
     "interpolates them) is checked by blender-export/export-normal-map.test against Cycles' "
     "picture (spheres at Strength 0 to 2, planes with turned, scaled and mirrored UVs, a back "
     "face, a lit sphere through a Bump; every 8x8 block within 1%; figures in "
     "bench/blender-nodes.md) and by runtime/tangent-*.test against the values expected per "
     "pixel. Object, World and Blender spaces and other UV maps are refused"),
    ("Fresnel and Layer Weight with ViewDir (`blFresnel`, `blLayerWeightFresnel`, "
     "`blLayerWeightFacing`)",
     "their fixtures above (fresnel-*, layerweight-*) compare the `*Incoming` functions these "
     "call, with the bake's incoming direction as an argument (a bake shades every point from "
     "one direction); blender-export/export-texture-nodes.test renders them, with Color Ramp "
     "HSV, Float, RGB and Vector Curves, on a sphere against Cycles (every 8x8 block off the "
     "silhouette within 0.2%; export-texture-nodes-bumped.test with a Bump node's Normal into "
     "both, the same). An unlinked Normal is the Normal attribute, a Bump's Normal the graph's "
     "bump node. Not reproduced: Cycles inverts the IOR on a back face (a face seen from behind its winding); "
     "texrender's Normal faces the viewer and no attribute says the face was turned, so a back "
     "face gets the front face's value (closed meshes seen from outside have none)"),
    ("Object Info (`blObjectInfo{Location,Color,Alpha,ObjectIndex,MaterialIndex,Random}`) and "
     "Attribute (`blAttributeUV`, `blAttributeUVFac`, `blAttributeUVAlpha`)",
     "the object's values are constants the exporter passes (Random: Cycles' hash of the "
     "object's name), so there is no point fixture; blender-export/object-info.test bakes every "
     "output with Cycles on four objects (names, locations, colours, pass indices; one name not "
     "ASCII) and compares the exporter's values: all equal. Attribute reads the render UV map "
     "only (texrender's meshes carry no other attribute): a colour attribute, another UV map or "
     "an object, instancer or view-layer attribute is refused, and so are Object Info Location "
     "and Random of an instanced object (Cycles gives each instance its own; the exporter "
     "translates a material once per object; error-texture-nodes.test)"),
    ("Ambient Occlusion (`blAmbientOcclusionAO`, `blAmbientOcclusionColor`)",
     "implemented through texrender's AO attribute; Samples and Distance are the scene's "
     "render.aoSamples and render.aoDistance (the Blender exporter sets them from the node). "
     "Not comparable point by point: both renderers estimate AO with their own random rays "
     "(input-attributes-*.test check AO in [0, 1] and Color = color * AO)"),
]


def run_compare(build, host, rows_path, work):
    fixtures = sorted(f for f in glob.glob(os.path.join(ROOT, "testsuite/Inputs/blender/*.json")))
    cmd = [sys.executable, os.path.join(ROOT, "testsuite/Inputs/blender/compare.py"),
           "--texcc", os.path.join(build, "bin/texcc"),
           "--eval", os.path.join(build, "bin/texcc-eval"), "--src", ROOT, "--work", work,
           "--rows", rows_path] + (["--host"] if host else []) + fixtures
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if not os.path.exists(rows_path):
        sys.exit("compare.py failed:\n" + r.stdout)
    with open(rows_path) as f:
        return json.load(f)


def vec(v):
    return "(" + ", ".join("%.6g" % x for x in v) + ")"


def main():
    ap = argparse.ArgumentParser()
    add_build_argument(ap)
    ap.add_argument("--no-device", action="store_true")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as work:
        host = run_compare(args.build, True, os.path.join(work, "host.json"),
                           os.path.join(work, "host"))
        device = []
        if not args.no_device:
            device = run_compare(args.build, False, os.path.join(work, "device.json"),
                                 os.path.join(work, "device"))
    by_key = {(r["variant"], r["output"]): r for r in device}
    blender = host[0]["blender"] if host else "?"
    lines = [
        "# Blender nodes: texcc against Cycles",
        "",
        "Generated by `scripts/blender_report.py` from the fixtures that",
        "`scripts/blender_conformance.py` baked with Cycles (bpy %s); do not edit by hand." % blender,
        "The tests `testsuite/texcc/blender/*-{host,device}.test` check the same figures.",
        "",
        "Each row is one output of one node variant (its settings are in",
        "`testsuite/Inputs/blender/<variant>.json`), evaluated by texcc at the %d points where Cycles"
        % (host[0]["points"] if host else 0),
        "shaded (a tilted plane, the baked Position). *near disc.* counts the points near a",
        "discontinuity: texcc's value jumps by more than 0.01 within 1e-5 of the point (cell",
        "borders, Constant steps, poles); they are counted apart, never dropped, and their error is",
        "its own column. *max* is the largest absolute error per channel over the other points",
        "(target <= 1e-4), *mean* and *<= 1e-6* are over all points. A point near a discontinuity",
        "meets the target when Cycles equals texcc at it or at one of its six neighbours (Cycles",
        "took the other side); *near disc.* shows how many do not, after the slash. *worst* is the",
        "point of *max* on the host target: position, texcc, Cycles.",
        "",
        "| variant | output | points | near disc. | host max | host max near disc. | host mean "
        "| host <= 1e-6 | OpenCL max | OpenCL max near disc. | target | worst (host) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    missed = []
    for r in host:
        d = by_key.get((r["variant"], r["output"]))
        met = r["met"] and (d is None or d["met"])
        if not met:
            missed.append((r, d))
        w = r["worst"]
        lines.append("| %s | %s | %d | %d / %d | %.3g | %.3g | %.3g | %.1f%% | %s | %s | %s | %s |" % (
            r["variant"], r["output"], r["points"], r["near_discontinuity"],
            r["near_discontinuity_matching_neither_side"], r["max_abs_error"],
            r["max_abs_error_near_discontinuity"], r["mean_abs_error"], 100 * r["within_1e-6"],
            "%.3g" % d["max_abs_error"] if d else "not run",
            "%.3g" % d["max_abs_error_near_discontinuity"] if d else "not run",
            "met" if met else "**missed**",
            "%s, %s, %s" % (vec(w["position"]), vec(w["texcc"]), vec(w["cycles"])) if w else "-"))
    lines += ["", "## Variants that miss the target", ""]
    if missed:
        for r, d in missed:
            lines.append("- %s %s: host max %.3g, OpenCL max %s" % (
                r["variant"], r["output"], r["max_abs_error"],
                "%.3g" % d["max_abs_error"] if d else "not run"))
    else:
        lines.append("None: every output above is within 1e-4 of Cycles on %s." %
                     ("both targets" if device else "the host target (OpenCL not run)"))
    lines += ["", "## Nodes checked apart from the point fixtures", ""]
    lines += ["- %s: %s." % (name, why) for name, why in NOT_YET]
    out = os.path.join(ROOT, "docs", "blender-nodes.md")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("blender_report: %d outputs, %d miss the target; wrote %s" % (len(host), len(missed),
                                                                        out))


if __name__ == "__main__":
    main()
