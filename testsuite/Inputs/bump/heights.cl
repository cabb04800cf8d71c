/* heights.cl: height fields and probes for the bump tests (testsuite/texcc/graph/bump-*.test,
 * testsuite/runtime/bump-*.test).
 *   linearX(a)       float   a * WorldPos.x: a height whose gradient is (a, 0, 0)
 *   objectWaves(f)   float   sin(f * ObjectPos.x) * cos(f * ObjectPos.y): reads the position
 *                            inside the body (as textures/blender's coordinate nodes do)
 *   along(p, k)      float   k * p.z, p an argument (e.g. {"attr": "WorldPos"})
 *   add3(a, b, c)    float   a + b + c
 *   scaled(h, k)     float   h * k
 *   hitNormal()      float3  the hit's shading normal (to compare the bumped normal with)
 *   hitGeomNormal()  float3  the hit's geometric normal (bump's offsets lie across it) */
float linearX(float a) { return a * readAttr("WorldPos").x; }

float objectWaves(float f) {
  float3 p = readAttr("ObjectPos");
  return sin(f * p.x) * cos(f * p.y);
}

float scaled(float h, float k) { return h * k; }

float along(float3 p, float k) { return k * p.z; }

float add3(float a, float b, float c) { return a + b + c; }

float3 hitNormal() { return readAttr("Normal"); }

float3 hitGeomNormal() { return readAttr("GeomNormal"); }
