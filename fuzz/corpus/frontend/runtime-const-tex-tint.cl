/* tint.cl: the texture of the runtime's hand-written test kernel (const-tex/proctex.cl).
 *   tint(color: float3, gain: float) -> float3: color * gain. */
float3 tint(float3 color, float gain) { return color * gain; }
