/* contrast.cl: a texture function that tier/graph.json declares on an unused node: the shape
 * kernel lacks it until an edit wires it in, the interp fallback (a case for every node's
 * function) has it from the start.
 *   tierContrast(x: float, amount: float) -> float: x pushed away from 0.5 by amount, in [0, 1]. */
float tierContrast(float x, float amount) {
  return clamp(0.5f + (x - 0.5f) * (1.0f + amount), 0.0f, 1.0f);
}
