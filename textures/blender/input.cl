/* blender/input.cl: Blender's input nodes over texrender's hit attributes: Texture Coordinate,
 * Geometry and Ambient Occlusion, one texture function per output.
 *
 *   float3 blTexCoordGenerated(float3 bboxMin, float3 bboxMax)
 *                                    Generated: ObjectPos in the object's auto texture space,
 *                                    0..1 over its bounding box (an axis of zero size spans
 *                                    -1..1, as Blender's auto texture space does)
 *   float3 blTexCoordObject()        Object: ObjectPos (the position in the mesh's own
 *                                    coordinates)
 *   float3 blTexCoordUV()            UV: TexCoord0 as (u, v, 0)
 *   float3 blTexCoordNormal(float3 axisX, float3 axisY, float3 axisZ)
 *                                    Normal: the shading normal in object space, normalised
 *                                    (Cycles' inverse normal transform: the dot products of
 *                                    the normal with the object's axes in world space)
 *   float3 blGeometryPosition()      Geometry's Position: WorldPos
 *   float3 blGeometryNormal()        Normal: the shading normal (world space)
 *   float3 blGeometryTrueNormal()    True Normal: GeomNormal
 *   float3 blGeometryTangent()       Tangent: texrender's Tangent made orthogonal to Normal
 *                                    and unit, as Cycles does (the mesh's MikkTSpace tangent
 *                                    when its OBJ gives vtan, else dP/du of its UVs;
 *                                    Cycles' Geometry Tangent is radial about Z without a UV
 *                                    map, so the two agree only with UVs)
 *   float3 blGeometryIncoming()      Incoming: ViewDir (towards the viewer, as Cycles' I)
 *   float  blAmbientOcclusionAO()    Ambient Occlusion's AO: the AO attribute (1 = open)
 *   float3 blAmbientOcclusionColor(float3 color)
 *                                    its Color: color * AO
 *   float  blFresnel(float ior, float3 normal)
 *                                    Fresnel's Fac: the dielectric reflectance for the angle
 *                                    between ViewDir and normal (Cycles' fresnel_dielectric_cos)
 *   float  blLayerWeightFresnel(float blend, float3 normal)
 *                                    Layer Weight's Fresnel: the same with IOR 1 / (1 - blend)
 *   float  blLayerWeightFacing(float blend, float3 normal)
 *                                    its Facing: 1 - |cos|, the cosine raised to a power that
 *                                    blend sets (2 blend below 0.5, 0.5 / (1 - blend) above)
 *   float3 blObjectInfoLocation(float3 location)   Object Info's outputs: the object's values,
 *   float3 blObjectInfoColor(float3 objectColor)    which the exporter passes (texrender has no
 *   float  blObjectInfoAlpha(float objectAlpha)     per-object attribute): its world location,
 *   float  blObjectInfoObjectIndex(float objectIndex) Object Color and alpha, Pass Index, the
 *   float  blObjectInfoMaterialIndex(float materialIndex) material's Pass Index, and Cycles'
 *   float  blObjectInfoRandom(float objectRandom)   random number of the object (a hash of its name)
 *   float3 blAttributeUV()                          Attribute (the UV map's name): Vector and
 *   float  blAttributeUVFac()                       Color (u, v, 0) as UV, Fac u, Alpha 1, as
 *   float  blAttributeUVAlpha()                     Cycles reads a 2D attribute
 *   blFresnelIncoming, blLayerWeightFresnelIncoming, blLayerWeightFacingIncoming: the same
 *                                    three with the incoming direction as their last argument
 *                                    (float3 incoming) instead of ViewDir (what the Cycles
 *                                    fixtures compare: a bake's incoming direction is fixed)
 *
 * The Ambient Occlusion node's Samples and Distance are the scene's render.aoSamples and
 * render.aoDistance (texrender's AO kernel traces them for every hit that reads AO); the Blender
 * exporter sets them from the node. Inside and Only Local have no counterpart.
 *
 * Fresnel and Layer Weight: Cycles inverts the IOR on a back face (a face seen from behind its
 * winding); texrender's Normal always faces the viewer and no attribute says whether the face was
 * turned, so a back face gets the front face's value. The exporter's Normal, unlinked, is the
 * Normal attribute (Cycles' shading normal).
 *
 * Parameters (the exporter passes the object's bounds and axes: no runtime attribute needed):
 *
 *   | name    | type   | default     | meaning                                         |
 *   |---------|--------|-------------|-------------------------------------------------|
 *   | bboxMin | float3 | -1, -1, -1  | the mesh's bounding box, object space           |
 *   | bboxMax | float3 | 1, 1, 1     |                                                 |
 *   | axisX   | float3 | 1, 0, 0     | object-to-world matrix's first column (X axis)  |
 *   | axisY   | float3 | 0, 1, 0     | its second column                               |
 *   | axisZ   | float3 | 0, 0, 1     | its third column                                |
 *   | color   | float3 | 1, 1, 1     | the AO node's Color input                       |
 *   | ior     | float  | 1.5         | Fresnel's index of refraction (at least 1e-5)   |
 *   | blend   | float  | 0.5         | Layer Weight's Blend                            |
 *   | normal  | float3 | Normal      | the normal the angle is measured from           |
 *   | incoming| float3 | ViewDir     | unit, from the point towards the viewer         |
 *   | location | float3 | 0, 0, 0    | Object Info: the object's world location        |
 *   | objectColor | float3 | 1, 1, 1 | Object Info: the object's colour (Object Color)  |
 *   | objectAlpha | float | 1.0      | Object Info: its alpha                          |
 *   | objectIndex | float | 0.0      | Object Info: the object's Pass Index            |
 *   | materialIndex | float | 0.0    | Object Info: the material's Pass Index          |
 *   | objectRandom | float | 0.0     | Object Info: the object's random number in [0, 1] |
 */

/* One axis of Blender's auto texture space: half the extent, 1 when flat, at least 1e-5. */
float blTexSpaceHalfSize(float lo, float hi) {
  float size = (hi - lo) / 2.0f;
  if (size == 0.0f)
    return 1.0f;
  if (size > 0.0f && size < 0.00001f)
    return 0.00001f;
  if (size < 0.0f && size > -0.00001f)
    return -0.00001f;
  return size;
}

float3 blTexCoordGenerated(float3 bboxMin, float3 bboxMax) {
  float3 halfSize = (float3)(blTexSpaceHalfSize(bboxMin.x, bboxMax.x),
                         blTexSpaceHalfSize(bboxMin.y, bboxMax.y),
                         blTexSpaceHalfSize(bboxMin.z, bboxMax.z));
  float3 centre = (bboxMin + bboxMax) / 2.0f;
  return (readAttr("ObjectPos") - (centre - halfSize)) / (2.0f * halfSize);
}

float3 blTexCoordObject() { return readAttr("ObjectPos"); }

float3 blTexCoordUV() { return (float3)(readAttr("TexCoord0"), 0.0f); }

float3 blTexCoordNormal(float3 axisX, float3 axisY, float3 axisZ) {
  float3 n = readAttr("Normal");
  return normalize((float3)(dot(axisX, n), dot(axisY, n), dot(axisZ, n)));
}

float3 blGeometryPosition() { return readAttr("WorldPos"); }

float3 blGeometryNormal() { return readAttr("Normal"); }

float3 blGeometryTrueNormal() { return readAttr("GeomNormal"); }

float3 blGeometryTangent() {
  /* Cycles' svm_node_tangent: the tangent made orthogonal to the normal, unit. */
  const float3 n = readAttr("Normal");
  return cross(n, normalize(cross(readAttr("Tangent"), n)));
}

float3 blGeometryIncoming() { return readAttr("ViewDir"); }

float blAmbientOcclusionAO() { return readAttr("AO"); }

float3 blAmbientOcclusionColor(float3 color) { return color * readAttr("AO"); }

/* Reflectance of a dielectric of relative IOR eta at the cosine cosi of the angle of incidence
 * (either side: |cosi|); 1 under total internal reflection. */
float blFresnelDielectric(float cosi, float eta) {
  float c = fabs(cosi);
  float g = eta * eta - 1.0f + c * c;
  if (!(g > 0.0f))
    return 1.0f;
  g = sqrt(g);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - 1.0f) / (c * (g - c) + 1.0f);
  return 0.5f * a * a * (1.0f + b * b);
}

float blFresnelIncoming(float ior, float3 normal, float3 incoming) {
  return blFresnelDielectric(dot(incoming, normal), fmax(ior, 1e-5f));
}

float blLayerWeightFresnelIncoming(float blend, float3 normal, float3 incoming) {
  return blFresnelDielectric(dot(incoming, normal), 1.0f / fmax(1.0f - blend, 1e-5f));
}

float blLayerWeightFacingIncoming(float blend, float3 normal, float3 incoming) {
  float facing = fabs(dot(incoming, normal));
  if (blend != 0.5f) {
    blend = clamp(blend, 0.0f, 1.0f - 1e-5f);
    facing = pow(facing, blend < 0.5f ? 2.0f * blend : 0.5f / (1.0f - blend));
  }
  return 1.0f - facing;
}

float blFresnel(float ior, float3 normal) {
  return blFresnelIncoming(ior, normal, readAttr("ViewDir"));
}

float blLayerWeightFresnel(float blend, float3 normal) {
  return blLayerWeightFresnelIncoming(blend, normal, readAttr("ViewDir"));
}

float blLayerWeightFacing(float blend, float3 normal) {
  return blLayerWeightFacingIncoming(blend, normal, readAttr("ViewDir"));
}

float3 blObjectInfoLocation(float3 location) { return location; }

float3 blObjectInfoColor(float3 objectColor) { return objectColor; }

float blObjectInfoAlpha(float objectAlpha) { return objectAlpha; }

float blObjectInfoObjectIndex(float objectIndex) { return objectIndex; }

float blObjectInfoMaterialIndex(float materialIndex) { return materialIndex; }

float blObjectInfoRandom(float objectRandom) { return objectRandom; }

float3 blAttributeUV() { return (float3)(readAttr("TexCoord0"), 0.0f); }

float blAttributeUVFac() { return readAttr("TexCoord0").x; }

float blAttributeUVAlpha() { return 1.0f; }
