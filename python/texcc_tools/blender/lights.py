"""The lights of a Blender scene as texrender's (docs/blender.md "Lamps", docs/scene.md): the
sun, and point, spot and area lamps in Cycles' units. A mixin of blender_export.Export: its
methods use the export's problems, check_finite and scene."""
import math
import sys


class LightsExport:
    def sun(self, obj):
        light = obj.data
        where = "light '%s'" % obj.name
        # Settings texrender's sun has no counterpart for, each at Blender's default or refused.
        for attr, default, fallback in (("use_temperature", False, "using its Color"),
                                        ("use_nodes", False, "using its Color and Strength"),
                                        ("use_shadow", True, "casting shadows"),
                                        ("diffuse_factor", 1.0, "using 1"),
                                        ("specular_factor", 1.0, "using 1")):
            if getattr(light, attr, default) != default:
                self.problems.refuse("%s: '%s' is %s; supported: %s" % (
                    where, attr, getattr(light, attr), default), fallback)
        # Strength x 2^Exposure is what Cycles uses (Exposure is 0 by default).
        strength = float(light.energy) * 2.0 ** float(getattr(light, "exposure", 0.0))
        radius = max(float(light.angle) / 2.0, math.radians(0.01))
        if light.angle / 2.0 < radius:
            sys.stderr.write("blender_export: note: sun '%s': angle %g deg is below texrender's "
                             "smallest disc; using a radius of 0.01 deg\n"
                             % (obj.name, math.degrees(light.angle)))
        # Blender's strength is the irradiance (W/m^2) facing the sun; texrender's sun is a disc
        # of uniform radiance R over a cone of half-angle r: irradiance R * 2 pi (1 - cos r).
        scale = strength / (2.0 * math.pi * (1.0 - math.cos(radius)))
        m = obj.matrix_world
        direction = [float(m[k][2]) for k in range(3)]  # the sun shines along its -Z
        if not self.check_finite(where, "its strength, colour, angle or rotation",
                                 [scale, radius, direction, [float(c) for c in light.color]],
                                 "leaving it out"):
            return None
        return {"type": "sun", "direction": direction,
                "radiance": [float(c) * scale for c in light.color],
                "angularRadius": math.degrees(radius)}

    def lamp_settings(self, obj, where):
        """Settings of a point, spot or area lamp that texrender has no counterpart for, each at
        Blender's default or refused; returns Cycles' colour x strength (W)."""
        light = obj.data
        for attr, default, fallback in (("use_nodes", False, "using its Color and Power"),
                                        ("normalize", True, "normalizing it"),
                                        ("diffuse_factor", 1.0, "using 1"),
                                        ("specular_factor", 1.0, "using 1"),
                                        ("transmission_factor", 1.0, "using 1"),
                                        ("volume_factor", 1.0, "using 1")):
            if getattr(light, attr, default) != default:
                self.problems.refuse("%s: '%s' is %s; supported: %s" % (
                    where, attr, getattr(light, attr), default), fallback)
        cycles = getattr(light, "cycles", None)
        scene = getattr(self, "scene", None)
        scene_bounces = int(scene.cycles.max_bounces) if scene is not None else 0
        if cycles is not None and int(cycles.max_bounces) < scene_bounces:
            self.problems.refuse("%s: Max Bounces is %d, below the scene's %d; supported: at "
                                 "least the scene's (texrender has one bounce limit)"
                                 % (where, cycles.max_bounces, scene_bounces),
                                 "the scene's bounce limit")
        linking = getattr(obj, "light_linking", None)
        if linking is not None and (linking.receiver_collection is not None or
                                    linking.blocker_collection is not None):
            self.problems.refuse("%s: Light Linking is set; supported: none (texrender's lamps "
                                 "light and are shadowed by every object)" % where,
                                 "lighting every object")
        # A light object's ray visibility: Camera is texrender's visibleToCamera (off by
        # default in Blender 5.0, as is Shadow Catcher, which matters only with a shadow
        # catcher object); Diffuse and Glossy off would hide it from those bounces.
        for attr, label in (("visible_diffuse", "Diffuse"), ("visible_glossy", "Glossy")):
            if not getattr(obj, attr, True):
                self.problems.refuse("%s: Visibility > Ray Visibility > %s is off; supported: on "
                                     "(texrender's lamps light every bounce)" % (where, label),
                                     "visible to every bounce")
        color = [float(c) for c in light.color]
        if getattr(light, "use_temperature", False):
            # Cycles multiplies the colour by the blackbody colour of the temperature.
            color = [c * float(t) for c, t in zip(color, light.temperature_color)]
        strength = float(light.energy) * 2.0 ** float(getattr(light, "exposure", 0.0))
        return [c * strength for c in color]

    def lamp(self, obj, matrix):
        """A point, spot or area lamp (docs/blender.md): Cycles' Color x Power x 2^Exposure in
        watts, its radius, cone and blend, its shape and size times the object's scale; None
        when it adds no light (leaving it out changes nothing)."""
        light = obj.data
        kind = light.type
        where = "light '%s'" % obj.name
        if kind == "AREA" and getattr(getattr(light, "cycles", None), "is_portal", False):
            sys.stderr.write("blender_export: note: %s is a portal: left out (a portal only "
                             "guides Cycles' sampling of the world; the image is the same)\n"
                             % where)
            return None
        power = self.lamp_settings(obj, where)
        m = [[float(matrix[r][c]) for c in range(4)] for r in range(3)]
        position = [m[r][3] for r in range(3)]
        cols = [[m[r][c] for r in range(3)] for c in range(3)]
        if not self.check_finite(where, "its power, colour, size or transform",
                                 [power, m, float(getattr(light, "shadow_soft_size", 0.0)),
                                  float(getattr(light, "size", 0.0)),
                                  float(getattr(light, "size_y", 0.0))], "leaving it out"):
            return None
        if max(power) <= 0.0:
            return None
        lamp = {"type": kind.lower(), "position": position, "power": power}
        if not light.use_shadow:
            lamp["castShadow"] = False
        if getattr(obj, "visible_camera", False):
            lamp["visibleToCamera"] = True

        def norm(v):
            return math.sqrt(sum(x * x for x in v))

        if kind in ("POINT", "SPOT"):
            lamp["radius"] = float(light.shadow_soft_size)
            if not getattr(light, "use_soft_falloff", True):
                lamp["softFalloff"] = False  # Cycles' sphere lamp
        if kind == "SPOT":
            if getattr(light, "use_square", False):
                self.problems.refuse("%s: Square is on; supported: off (a round cone)" % where,
                                     "a round cone")
            scales = [norm(c) for c in cols]
            if max(scales) - min(scales) > 1e-4 * max(scales):
                self.problems.refuse("%s: its object scale (%s) is not uniform; supported: a "
                                     "uniform scale (Cycles stretches the cone with it)" % (
                                         where, ", ".join("%g" % x for x in scales)),
                                     "a round cone")
            if min(scales) <= 0.0:
                return None
            lamp["direction"] = [-c / scales[2] for c in cols[2]]
            lamp["spotSize"] = math.degrees(float(light.spot_size))
            lamp["spotBlend"] = float(light.spot_blend)
        if kind == "AREA":
            spread = float(getattr(light, "spread", math.pi))
            if abs(spread - math.pi) > 1e-6:
                self.problems.refuse("%s: Spread is %g deg; supported: 180 (texrender's area "
                                     "lamp emits as a Lambertian surface)" % (
                                         where, math.degrees(spread)), "a spread of 180 deg")
            shape = light.shape
            size_x = float(light.size)
            size_y = size_x if shape in ("SQUARE", "DISK") else float(light.size_y)
            u = [c * size_x for c in cols[0]]
            v = [c * size_y for c in cols[1]]
            width, height = norm(u), norm(v)
            z = cols[2]
            if width <= 0.0 or height <= 0.0 or norm(z) <= 0.0:
                return None  # Cycles: an area lamp of no size adds nothing
            cos_uv = abs(sum(a * b for a, b in zip(u, v))) / (width * height)
            if cos_uv > 1e-4:
                self.problems.refuse("%s: its object transform shears it (its X and Y axes are "
                                     "%g deg apart); supported: a rectangle or ellipse" % (
                                         where, math.degrees(math.acos(min(cos_uv, 1.0)))),
                                     "a rectangle")
            lamp["direction"] = [-c / norm(z) for c in z]  # Cycles' area lamp lights its -Z
            lamp["shape"] = "ellipse" if shape in ("DISK", "ELLIPSE") else "rectangle"
            lamp["size"] = [width, height]
            lamp["axisU"] = [c / width for c in u]
        return lamp

    # --- The world ---
    def world(self, scene, staging):
        """The world (docs/blender.md "World"): a Background node of an unlinked Color and
        Strength is texrender's `sky` of radiance Color x Strength (a world without nodes: its
        colour); an Environment Texture (Equirectangular) into the Background's Color is an
        `environment` light of that Strength, its image written as Image Textures' are. None
        when the world adds no light."""
        world = scene.world
        if world is None:
            return None
        where = "world '%s'" % world.name
        color = [float(c) for c in world.color]
        tree = world.node_tree
        visibility = getattr(world, "cycles_visibility", None)
        for attr, label in (("camera", "Camera"), ("diffuse", "Diffuse"), ("glossy", "Glossy"),
                            ("transmission", "Transmission"), ("scatter", "Volume Scatter")):
            if visibility is not None and not getattr(visibility, attr, True):
                self.problems.refuse("%s: Ray Visibility > %s is off; supported: on (texrender's "
                                     "world is seen by every ray)" % (where, label),
                                     "visible to every ray")
        if tree is not None:
            outputs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputWorld"
                       and n.target in ("ALL", "CYCLES")]
            active = [n for n in outputs if n.is_active_output] or outputs
            if not active:
                return None
            volume = active[0].inputs.get("Volume")
            if volume is not None and any(not l.is_muted for l in volume.links):
                self.problems.refuse("%s: the World Output's Volume is linked; supported: "
                                     "unlinked (texrender has no volumes)" % where, "ignoring it")
            node = self._world_source(active[0].inputs["Surface"])
            if node is None:
                return None
            supported = ("supported: a Background node with an unlinked Strength and a Color "
                         "unlinked or from an Environment Texture")
            if node.bl_idname != "ShaderNodeBackground":
                self.problems.refuse("%s: node '%s' (%s) is not supported; %s" % (
                    where, node.name, node.bl_idname, supported), "using the world's colour")
            else:
                strength_in = node.inputs["Strength"]
                if self._world_source(strength_in) is not None:
                    self.problems.refuse("%s: node '%s' (%s): input 'Strength' is linked (%s); %s"
                                         % (where, node.name, node.bl_idname,
                                            self._world_source(strength_in).bl_idname, supported),
                                         "using its unlinked value")
                strength = float(strength_in.default_value)
                color_in = node.inputs["Color"]
                source = self._world_source(color_in)
                if source is not None and source.bl_idname == "ShaderNodeTexEnvironment":
                    env = self.environment(where, source, strength, staging)
                    if env is not None:
                        return env
                elif source is not None:
                    self.problems.refuse("%s: node '%s' (%s): input 'Color' is linked (%s); %s"
                                         % (where, node.name, node.bl_idname, source.bl_idname,
                                            supported), "using its unlinked value")
                color = [float(c) * strength for c in color_in.default_value[:3]]
        if not self.check_finite(where, "its colour or strength", color, "no sky light"):
            return None
        if max(color) <= 0.0:
            return None
        return {"type": "sky", "radiance": color}

    @staticmethod
    def _world_link(socket):
        """The node feeding an input (through reroutes and past muted links) and the identifier
        of its output; (None, None) when unlinked."""
        while True:
            links = [l for l in socket.links if not l.is_muted]
            if not links:
                return None, None
            node = links[0].from_node
            if node.bl_idname != "NodeReroute":
                return node, links[0].from_socket.identifier
            socket = node.inputs[0]

    def _world_source(self, socket):
        return self._world_link(socket)[0]

    def environment(self, where, node, strength, staging):
        """An Environment Texture node into the Background's Color: an `environment` light of
        its image, Strength and rotation (the Vector unlinked, or a Texture Coordinate's
        Generated or Object through at most one Mapping node that only rotates); None (and
        problems, whose fallback is the Background's unlinked Color) when it is not one."""
        what = "%s: node '%s' (ShaderNodeTexEnvironment)" % (where, node.name)
        fallback = "using the Background's unlinked Color x Strength"
        problems = []
        if node.mute:
            problems.append("it is muted")
        if node.projection != "EQUIRECTANGULAR":
            problems.append("projection '%s' is not supported; supported: EQUIRECTANGULAR"
                            % node.projection)
        if node.interpolation not in ("Linear", "Closest"):
            problems.append("interpolation '%s' is not supported; supported: Linear, Closest"
                            % node.interpolation)
        tm = node.texture_mapping
        if tuple(tm.translation) != (0, 0, 0) or tuple(tm.rotation) != (0, 0, 0) or \
                tuple(tm.scale) != (1, 1, 1) or tm.use_min or tm.use_max or \
                (tm.mapping_x, tm.mapping_y, tm.mapping_z) != ("X", "Y", "Z"):
            problems.append("its own texture mapping is set; supported: none (a Mapping node "
                            "rotates it)")
        matrix = self._environment_matrix(node, problems)
        image, path, colorspace = node.image, None, None
        if image is None:
            problems.append("it has no image")
        else:
            image_problems, path, colorspace = self.image_problems(image)
            problems += ["image '%s': %s" % (image.name, p) for p in image_problems]
        if not self.check_finite(where, "its Strength", [strength], fallback):
            return None
        for problem in problems:
            self.problems.refuse("%s: %s" % (what, problem), fallback)
        if problems:
            return None
        if not (strength > 0.0):
            return None
        entry = {"image": image, "name": "world-" + image.name, "path": path}
        light = {"type": "environment",
                 "image": self.image_file(entry, staging, self.final_dir),
                 "colorSpace": colorspace, "strength": strength}
        if node.interpolation == "Closest":
            light["interpolation"] = "closest"
        if matrix is not None:
            light["matrix"] = matrix
        return light

    def _environment_matrix(self, node, problems):
        """The rotation of the Environment Texture's Vector (scene.json's matrix: world
        directions to the map's), None for none; appends to problems what is not a rotation."""
        from mathutils import Euler, Matrix
        mapping, output = self._world_link(node.inputs["Vector"])
        if mapping is None:
            return None
        matrix = Matrix.Identity(3)
        coords = mapping
        if mapping.bl_idname == "ShaderNodeMapping":
            for name in ("Location", "Rotation", "Scale"):
                socket = mapping.inputs.get(name)
                if socket is not None and socket.enabled and self._world_source(socket):
                    problems.append("Mapping '%s': input '%s' is linked; supported: unlinked"
                                    % (mapping.name, name))
                    return None
            kind = mapping.vector_type
            loc = mapping.inputs["Location"].default_value
            rot = Euler(tuple(mapping.inputs["Rotation"].default_value), "XYZ").to_matrix()
            scale = [float(v) for v in mapping.inputs["Scale"].default_value]
            if kind in ("POINT", "TEXTURE") and any(float(v) != 0.0 for v in loc):
                problems.append("Mapping '%s': Location is %s; supported: 0 (a moved direction "
                                "is not a rotation)" % (mapping.name, tuple(round(v, 6) for v in loc)))
                return None
            if any(v == 0.0 for v in scale):
                problems.append("Mapping '%s': a Scale of 0 is not supported" % mapping.name)
                return None
            s = Matrix.Diagonal(scale)
            if kind in ("POINT", "VECTOR"):
                matrix = rot @ s
            elif kind == "TEXTURE":
                matrix = (rot @ s).inverted()
            else:  # NORMAL: R (v / scale)
                matrix = rot @ Matrix.Diagonal([1.0 / v for v in scale])
            if len({abs(v) for v in scale}) != 1:
                problems.append("Mapping '%s': Scale %s is not uniform; supported: a uniform "
                                "scale (a rotation)" % (mapping.name, tuple(scale)))
                return None
            coords, output = self._world_link(mapping.inputs["Vector"])
        if coords is None or coords.bl_idname != "ShaderNodeTexCoord" or \
                output not in ("Generated", "Object") or \
                getattr(coords, "object", None) is not None:
            problems.append("its Vector comes from %s; supported: unlinked, or a Texture "
                            "Coordinate's Generated or Object (no object), through one "
                            "Mapping node" % ("'%s' (%s)" % (coords.name, coords.bl_idname)
                                              if coords is not None else "an unlinked Mapping"))
            return None
        rows = [[float(matrix[r][c]) for c in range(3)] for r in range(3)]
        if rows == [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]:
            return None
        return rows
