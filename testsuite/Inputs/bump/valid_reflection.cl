/* valid_reflection.cl: a given shading normal for testsuite/bump/bump-valid-reflection.test.
 *   givenNormal(x, y, z)   float3  normalize((x, y, z)) */
float3 givenNormal(float x, float y, float z) { return normalize((float3)(x, y, z)); }
