"""The one reader (and writer) of a texcc output folder's layout.json, the manifest texrender
loads: the kernel's entry points and uniforms, the nodes' signatures, the images, the programs.

load(folder) takes the output folder (or the layout.json path itself) and returns the parsed
object; a missing or malformed file is one ManifestError naming it. The accessors below are
what more than one tool reads; the format is docs/abi.md's."""
import json
import os

NAME = "layout.json"


class ManifestError(Exception):
    pass


def path(folder):
    """The layout.json of a texcc output folder (a path ending in .json is taken as is)."""
    return folder if folder.endswith(".json") else os.path.join(folder, NAME)


def exists(folder):
    return os.path.isfile(path(folder))


def loads(data, name=NAME):
    try:
        layout = json.loads(data)
    except ValueError as e:
        raise ManifestError("%s: not JSON: %s" % (name, e)) from None
    if not isinstance(layout, dict):
        raise ManifestError("%s: not a JSON object" % name)
    return layout


def load(folder):
    p = path(folder)
    try:
        with open(p, "rb") as f:
            return loads(f.read(), p)
    except OSError as e:
        raise ManifestError("%s: %s" % (p, e.strerror or e)) from None


def dumps(layout):
    """The bytes save() writes (indent 1, as farm's bundles carry it)."""
    return json.dumps(layout, indent=1).encode()


def save(folder, layout):
    """Writes layout into folder's layout.json atomically."""
    from texcc_tools.atomic import write_bytes
    write_bytes(path(folder), dumps(layout))


def images(layout):
    """The images texrender loads, in the graph's order: [{"path": ..., ...}]."""
    return layout.get("images", [])


def with_image_paths(layout, rename):
    """A copy of layout whose images' paths are rename(index, path) (farm's bundles ship the
    images next to the folder); the rest is unchanged."""
    out = dict(layout)
    out["images"] = [dict(image, path=rename(k, image["path"]))
                     for k, image in enumerate(images(layout))]
    if "images" not in layout:
        del out["images"]
    return out

