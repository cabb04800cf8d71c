/* reach.cl: a texture with a helper, and a texture no live node uses (with its own helper),
 * for the "only what the scene needs" test. */
float helperUsed(float x) { return x * 0.5f; }
float helperUnused(float x) { return x * 2.0f; }

float liveTex(float a) { return helperUsed(a) + readAttr("AO"); }
float deadTex(float a) { return helperUnused(a) + readAttr("WorldPos").x; }
