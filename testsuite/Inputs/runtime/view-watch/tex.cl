/* gradient(p) -> float3: a ramp across the quad, above 1 at its right. */
float3 gradient() { float x = readAttr("WorldPos").x; return (float3)(0.5f + x, 0.3f + 0.5f * x, 0.2f); }
