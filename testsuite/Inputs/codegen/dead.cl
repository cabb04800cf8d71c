/* dead.cl: for dead-functions.test. base is what the live node calls; occluded and facing
 * only dead nodes name (facing's n is fed by an attribute no live node reads). */
float base(float a) { return a * 0.5f; }
float occluded(float x) { return x * readAttr("AO"); }
float facing(float3 n, float k) { return dot(n, (float3)(0.0f, 1.0f, 0.0f)) * k; }
