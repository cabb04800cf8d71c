/* tint.cl: a user function that the rust kernel does not contain until the benchmark's
 * "new user function" edit rewires the rust tone through it (rewire tone.a=contrast). */
float benchContrast(float x, float amount) {
  return clamp(0.5f + (x - 0.5f) * (1.0f + amount), 0.0f, 1.0f);
}
