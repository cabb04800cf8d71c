/* aotint.cl: a texture that reads AO (the runtime's AO tests).
 *   aoTint(color: float3) -> float3: color * AO (AO = 1 where the hemisphere is open). */
float3 aoTint(float3 color) { return color * readAttr("AO"); }
