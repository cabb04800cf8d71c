/* facing.cl: a texture function that reads an attribute no other node of tier/graph-dead.json
 * reads (Normal, in its own code), on a dead node whose argument p reads another one
 * (WorldPos): wiring it in must bring both to the renderer.
 *   tierFacing(p: float3, amount: float) -> float in [0, 1]: brighter where the shading normal
 *   faces +y, mixed by amount with stripes along world x. */
float tierFacing(float3 p, float amount) {
  float3 n = readAttr("Normal");
  float stripes = 0.5f + 0.5f * sin(12.0f * p.x);
  return clamp(mix(0.5f + 0.5f * n.y, stripes, amount), 0.0f, 1.0f);
}
