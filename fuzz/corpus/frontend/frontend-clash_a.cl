// Two files that define the same helpers and macro (see two-files-clash.cl).
#define SCALE 2.0f
float hash(float3 p) {
  float whole;
  return fract(sin(dot(p, (float3)(12.9898f, 78.233f, 37.719f))) * 43758.5453f, &whole);
}
float noise(float3 p) { return hash(floor(p)) * SCALE; }
float woodA(float3 p) { return noise(p * SCALE); }
