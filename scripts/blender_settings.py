"""blender_settings.py: the scene settings that change the picture Blender renders, each either
reproduced by texrender or a problem the exporter names (docs/blender.md, "Render settings").

texrender's image is Cycles' with: the Standard view transform (its PNG is sRGB, its EXR linear
as Cycles' EXR), no look, exposure 0, gamma 1; no denoiser; the same samples in every pixel; a
box pixel filter 1 px wide; no clamping; each light picked with equal probability; no path
guiding; caustics; no glossy blur; one bounce limit for every kind of bounce; an opaque film; no
motion blur. SETTINGS is the one table; check_render_settings walks it.
"""

# (attribute path on the scene, the value texrender reproduces, the setting as Blender's
# interface names it, why it changes the picture, Cycles only). The fallback (--lenient) is
# always: the export goes on and texrender renders as with the reproduced value.
SETTINGS = [
    ("view_settings.view_transform", "Standard", "Color Management > View Transform",
     "texrender's PNG is Standard sRGB (its EXR is linear, as Cycles' EXR)", False),
    ("view_settings.look", "None", "Color Management > Look",
     "texrender applies no look", False),
    ("view_settings.exposure", 0.0, "Color Management > Exposure",
     "texrender's PNG has no exposure", False),
    ("view_settings.gamma", 1.0, "Color Management > Gamma",
     "texrender's PNG has no extra gamma", False),
    ("view_settings.use_curve_mapping", False, "Color Management > Curves",
     "texrender applies no curve", False),
    ("display_settings.display_device", "sRGB", "Color Management > Display Device",
     "texrender's PNG is for an sRGB display", False),
    ("cycles.use_denoising", False, "Render > Denoise",
     "texrender has no denoiser: its image is the noisy estimate", True),
    ("cycles.use_adaptive_sampling", False, "Sampling > Adaptive Sampling",
     "texrender takes the same number of samples in every pixel", True),
    ("cycles.pixel_filter_type", "BOX", "Film > Pixel Filter > Type",
     "texrender's pixel filter is a box 1 px wide", True),
    ("cycles.filter_width", 1.0, "Film > Pixel Filter > Width",
     "texrender's pixel filter is a box 1 px wide", True),
    ("cycles.film_exposure", 1.0, "Film > Exposure",
     "texrender does not scale the film", True),
    ("cycles.sample_clamp_direct", 0.0, "Light Paths > Clamping > Direct Light",
     "texrender clamps no sample (clamping darkens bright paths)", True),
    ("cycles.sample_clamp_indirect", 0.0, "Light Paths > Clamping > Indirect Light",
     "texrender clamps no sample (clamping darkens bright paths)", True),
    ("cycles.blur_glossy", 0.0, "Light Paths > Caustics > Filter Glossy",
     "texrender does not blur glossy bounces after a diffuse one", True),
    ("cycles.caustics_reflective", True, "Light Paths > Caustics > Reflective",
     "texrender keeps reflective caustic paths", True),
    ("cycles.caustics_refractive", True, "Light Paths > Caustics > Refractive",
     "texrender keeps refractive caustic paths", True),
    ("cycles.use_light_tree", False, "Sampling > Lights > Light Tree",
     "texrender picks each light with equal probability (docs/sampling.md): the same "
     "converged image, other noise", True),
    ("cycles.use_guiding", False, "Sampling > Path Guiding",
     "texrender has no path guiding (other noise)", True),
    ("cycles.use_fast_gi", False, "Light Paths > Fast GI Approximation",
     "texrender traces every bounce", True),
    ("render.film_transparent", False, "Film > Transparent",
     "texrender's film shows the world", False),
    ("render.use_motion_blur", False, "Motion Blur",
     "texrender renders one instant", False),
    ("render.use_simplify", False, "Simplify",
     "the exporter exports the render levels, not Simplify's limits", False),
]


def _get(obj, path):
    for part in path.split("."):
        obj = getattr(obj, part)
    return obj


def _differs(value, want):
    if isinstance(want, float):
        return abs(float(value) - want) > 1e-6
    return value != want


def _text(value):
    return "%g" % value if isinstance(value, float) else \
        ("on" if value else "off") if isinstance(value, bool) else "'%s'" % value


def check_render_settings(scene, refuse):
    """Calls refuse(message, fallback) for each setting of `scene` that texrender does not
    reproduce (Cycles' settings only when Cycles is the engine)."""
    cycles = scene.render.engine == "CYCLES"
    where = "scene '%s'" % scene.name
    for path, want, label, why, cycles_only in SETTINGS:
        if cycles_only and not cycles:
            continue
        value = _get(scene, path)
        if _differs(value, want):
            refuse("%s: %s is %s; supported: %s (%s)" % (where, label, _text(value),
                                                         _text(want), why),
                   "rendering as with %s" % _text(want))
    if cycles:
        c = scene.cycles
        for attr, label in (("diffuse_bounces", "Diffuse"), ("glossy_bounces", "Glossy")):
            if getattr(c, attr) < c.max_bounces:
                refuse("%s: Light Paths > Max Bounces > %s is %d, below Total %d; supported: "
                       "at least Total (texrender has one bounce limit for every kind of "
                       "bounce)" % (where, label, getattr(c, attr), c.max_bounces),
                       "every bounce up to Total")
