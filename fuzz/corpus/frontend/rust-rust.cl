/* rust.cl: where rust grows (the rust example's own node; the noise and the ramps come from
 * the texture library, ../../textures/).
 *
 * Rust gathers where water and dirt stay: in crevices and corners, which ambient occlusion
 * finds (AO is 1 in the open, lower where nearby geometry hides the sky), and in patches that
 * a noise spreads over open surfaces. The mask blends the two into a coverage value and
 * thresholds it with a soft edge.
 *
 * Texture function (graph "fn" name):
 *
 *   float rustMask(float ao, float noise, float threshold, float softness, float aoWeight)
 *       coverage c = aoWeight * (1 - ao) + (1 - aoWeight) * noise, then
 *       smoothstep(threshold - softness, threshold + softness, c): 0 clean metal, 1 rust.
 *
 * Parameters:
 *
 *   | name      | type  | default | range | meaning                                           |
 *   |-----------|-------|---------|-------|---------------------------------------------------|
 *   | ao        | float | -       | 0..1  | {"attr": "AO"}: 1 unoccluded, 0 fully occluded    |
 *   | noise     | float | -       | 0..1  | patchiness, e.g. fbm3 remapped to [0, 1]          |
 *   | threshold | float | 0.36    | 0..1  | coverage at which rust starts (lower: more rust)  |
 *   | softness  | float | 0.08    | > 0   | half width of the clean-to-rust transition        |
 *   | aoWeight  | float | 0.5     | 0..1  | share of the occlusion in the coverage (0: noise only) |
 */

float rustMask(float ao, float noise, float threshold, float softness, float aoWeight) {
  float w = clamp(aoWeight, 0.0f, 1.0f);
  float c = w * (1.0f - clamp(ao, 0.0f, 1.0f)) + (1.0f - w) * clamp(noise, 0.0f, 1.0f);
  float s = fmax(softness, 1e-4f);
  return smoothstep(threshold - s, threshold + s, c);
}
