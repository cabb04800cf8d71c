"""blender_settings.py: the scene settings that change the picture Blender renders, each either
reproduced by texrender or a problem the exporter names (docs/blender.md, "Render settings").

texrender's image is Cycles' with: no denoiser; the same samples in every pixel; a
box pixel filter 1 px wide; no clamping; each light picked with equal probability; no path
guiding; caustics; no glossy blur; one bounce limit for every kind of bounce; an opaque film; no
motion blur. SETTINGS is the one table; check_render_settings walks it. The Color Management
that texrender's PNG reproduces (VIEWS: view transform, look, exposure, gamma on an sRGB display)
becomes scene.json's film.view (view_settings).
"""

# The view transforms texrender's PNG reproduces and their looks (Blender 5.0's names; texrender
# runtime/lib/ViewTransform.cpp builds each as Blender's config.ocio defines it).
VIEWS = {
    "Standard": [],
    "AgX": ["AgX - Punchy", "AgX - Greyscale", "AgX - Very High Contrast", "AgX - High Contrast",
            "AgX - Medium High Contrast", "AgX - Base Contrast", "AgX - Medium Low Contrast",
            "AgX - Low Contrast", "AgX - Very Low Contrast"],
    "Filmic": ["Very High Contrast", "High Contrast", "Medium High Contrast", "Medium Contrast",
               "Medium Low Contrast", "Low Contrast", "Very Low Contrast"],
}

# (attribute path on the scene, the value texrender reproduces, the setting as Blender's
# interface names it, why it changes the picture, Cycles only). The fallback (--lenient) is
# always: the export goes on and texrender renders as with the reproduced value.
SETTINGS = [
    ("view_settings.use_curve_mapping", False, "Color Management > Curves",
     "texrender's PNG applies no curve", False),
    ("view_settings.use_white_balance", False, "Color Management > White Balance",
     "texrender's PNG applies no white balance", False),
    ("display_settings.display_device", "sRGB", "Color Management > Display Device",
     "texrender's PNG is for an sRGB display", False),
    ("render.image_settings.color_management", "FOLLOW_SCENE", "Output > Color Management",
     "texrender's PNG follows the scene's view settings", False),
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


def view_settings(scene, refuse):
    """scene.json's film.view for the scene's view transform, look, exposure and gamma (None:
    Standard, no look, 0, 1: texrender's default); refuse(message, fallback) for a view
    transform or look that texrender does not reproduce."""
    where = "scene '%s'" % scene.name
    vs = scene.view_settings
    transform, look = vs.view_transform, vs.look
    if transform not in VIEWS:
        refuse("%s: Color Management > View Transform is '%s'; supported: %s (texrender's PNG "
               "reproduces these; its EXR is linear, as Cycles' EXR)"
               % (where, transform, ", ".join("'%s'" % v for v in VIEWS)),
               "rendering as with 'Standard'")
        transform, look = "Standard", "None"
    if look != "None" and look not in VIEWS[transform]:
        refuse("%s: Color Management > Look is '%s'; supported with '%s': %s (the looks of "
               "Blender 5.0's configuration that texrender's PNG reproduces)"
               % (where, look, transform, ", ".join("'%s'" % v for v in ["None"] + VIEWS[transform])),
               "no look")
        look = "None"
    view = {"transform": transform, "look": look, "exposure": float(vs.exposure),
            "gamma": float(vs.gamma)}
    if (transform, look, view["exposure"], view["gamma"]) == ("Standard", "None", 0.0, 1.0):
        return None
    return view


def check_render_settings(scene, refuse):
    """Calls refuse(message, fallback) for each setting of `scene` that texrender does not
    reproduce (Cycles' settings only when Cycles is the engine); returns scene.json's
    film.view (view_settings)."""
    view = view_settings(scene, refuse)
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
    return view
