/* marble.cl: veined marble (the marble example's own node; the turbulence and the colour
 * ramp come from the texture library, ../../textures/).
 *
 * Classic Perlin marble: parallel sine bands across a solid block of stone, bent by
 * turbulence so that the bands wander and fold into veins. The result is a band position in
 * [0, 1] for a colour ramp: 0 the vein's centre, 1 the clear stone between veins.
 *
 * Texture function (graph "fn" name):
 *
 *   float marbleBands(float3 p, float3 direction, float turbulence, float frequency, float distortion, float sharpness)
 *       s = sin(frequency * dot(p, direction) + distortion * turbulence); returns
 *       |s|^(1 / sharpness), range [0, 1]: sharpness > 1 makes the veins (s near 0) thinner.
 *
 * Parameters:
 *
 *   | name       | type   | default        | range | meaning                                  |
 *   |------------|--------|----------------|-------|------------------------------------------|
 *   | p          | float3 | -              | any   | {"attr": "ObjectPos"}                    |
 *   | direction  | float3 | (1, 0.35, 0.2) | != 0  | across the bands (need not be unit)      |
 *   | turbulence | float  | -              | 0..1  | a turbulence3 node                       |
 *   | frequency  | float  | 6.0            | > 0   | radians of band phase per unit along direction |
 *   | distortion | float  | 9.0            | >= 0  | how far the turbulence bends the bands (radians) |
 *   | sharpness  | float  | 2.5            | > 0   | vein thinness                            |
 */

float marbleBands(float3 p, float3 direction, float turbulence, float frequency, float distortion,
                  float sharpness) {
  float along = p.x * direction.x + p.y * direction.y + p.z * direction.z;
  float s = sin(frequency * along + distortion * turbulence);
  return pow(fabs(s), 1.0f / fmax(sharpness, 1e-3f));
}
