/* blender/converter.cl: Blender's Separate XYZ and Combine XYZ nodes, one texture function per
 * output (the Geometry node is in input.cl).
 *
 *   float  blSeparateXYZX(float3 vector)     the X output of Separate XYZ
 *   float  blSeparateXYZY(float3 vector)     Y
 *   float  blSeparateXYZZ(float3 vector)     Z
 *   float3 blCombineXYZ(float x, float y, float z)
 *
 * Parameters:
 *
 *   | name    | type   | default | meaning              |
 *   |---------|--------|---------|----------------------|
 *   | vector  | float3 | 0       | the vector to split  |
 *   | x, y, z | float  | 0.0     | the components       |
 */

float blSeparateXYZX(float3 vector) { return vector.x; }

float blSeparateXYZY(float3 vector) { return vector.y; }

float blSeparateXYZZ(float3 vector) { return vector.z; }

float3 blCombineXYZ(float x, float y, float z) { return (float3)(x, y, z); }
