"""blender_tangents.py: the UV tangents a tangent-space Normal Map node needs, as Cycles has them.

Cycles (5.0, scene/mesh.cpp) computes MikkTSpace tangents of the render UV map over its
triangles (Blender's corner triangles), with each corner's normal: the corner normal of a
smooth face, the triangle's own normal of a flat one; the bitangent sign per corner. The
exporter (scripts/blender_export.py write_mesh) has exactly those triangles and normals; this
module hands them to Blender's own MikkTSpace (Mesh.calc_tangents) on a mesh made of the
triangles, so that the tangents are Cycles' (a quad's tangents computed on the quad split it
along MikkTSpace's diagonal, not Blender's, and differ), and writes them as OBJ vtan lines
(docs/scene.md "Tangents").
"""


def uses_normal_map(material):
    """Whether the material's node tree (node groups included) has a Normal Map node."""
    tree = getattr(material, "node_tree", None) if material is not None else None
    todo, seen = [tree] if tree is not None else [], set()
    while todo:
        tree = todo.pop()
        if tree.name in seen:
            continue
        seen.add(tree.name)
        for node in tree.nodes:
            if node.bl_idname == "ShaderNodeNormalMap" and not node.mute:
                return True
            inner = getattr(node, "node_tree", None)
            if node.bl_idname == "ShaderNodeGroup" and inner is not None:
                todo.append(inner)
    return False


def mikk_tangents(co, tv, corner_uv, corner_normals):
    """Per triangle corner, (tangent x, y, z, bitangent sign): MikkTSpace over the triangles
    `tv` (vertex indices, ntri x 3) of the positions `co`, with the corners' UVs and normals
    (ntri x 3 x 2, ntri x 3 x 3), as Cycles computes them. numpy float32 (ntri, 3, 4)."""
    import bpy
    import numpy as np
    ntri = len(tv)
    tmp = bpy.data.meshes.new("texcc-tangents")
    try:
        tmp.vertices.add(len(co))
        tmp.vertices.foreach_set("co", np.ascontiguousarray(co, np.float32).ravel())
        tmp.loops.add(3 * ntri)
        tmp.loops.foreach_set("vertex_index", np.ascontiguousarray(tv, np.int32).ravel())
        tmp.polygons.add(ntri)
        tmp.polygons.foreach_set("loop_start", np.arange(0, 3 * ntri, 3, dtype=np.int32))
        tmp.update(calc_edges=True)
        layer = tmp.uv_layers.new(name="UVMap")
        layer.data.foreach_set("uv", np.ascontiguousarray(corner_uv, np.float32).ravel())
        # Every corner's normal as given (a flat triangle's is its own normal already).
        tmp.shade_smooth()
        tmp.normals_split_custom_set(np.ascontiguousarray(corner_normals,
                                                          np.float32).reshape(-1, 3))
        tmp.calc_tangents(uvmap="UVMap")  # (the layer reference is stale by now)
        tangent = np.empty(3 * ntri * 3, np.float32)
        tmp.loops.foreach_get("tangent", tangent)
        sign = np.empty(3 * ntri, np.float32)
        tmp.loops.foreach_get("bitangent_sign", sign)
    finally:
        bpy.data.meshes.remove(tmp)
    out = np.empty((ntri, 3, 4), np.float32)
    out[:, :, :3] = tangent.reshape(ntri, 3, 3)
    out[:, :, 3] = np.where(sign.reshape(ntri, 3) < 0, -1.0, 1.0)
    return out
