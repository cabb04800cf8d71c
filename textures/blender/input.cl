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
 *   float3 blGeometryTangent()       Tangent: texrender's Tangent (dP/du of the mesh's UVs;
 *                                    Cycles' Geometry Tangent is radial about Z without a UV
 *                                    map, so the two agree only with UVs)
 *   float3 blGeometryIncoming()      Incoming: ViewDir (towards the viewer, as Cycles' I)
 *   float  blAmbientOcclusionAO()    Ambient Occlusion's AO: the AO attribute (1 = open)
 *   float3 blAmbientOcclusionColor(float3 color)
 *                                    its Color: color * AO
 *
 * The Ambient Occlusion node's Samples and Distance are the scene's render.aoSamples and
 * render.aoDistance (texrender's AO kernel traces them for every hit that reads AO); the Blender
 * exporter sets them from the node. Inside and Only Local have no counterpart.
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

float3 blGeometryTangent() { return readAttr("Tangent"); }

float3 blGeometryIncoming() { return readAttr("ViewDir"); }

float blAmbientOcclusionAO() { return readAttr("AO"); }

float3 blAmbientOcclusionColor(float3 color) { return color * readAttr("AO"); }
