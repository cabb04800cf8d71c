// Two files that define the same helpers and macro (see two-files-clash.cl).
#define SCALE 0.5f
float hash(float3 p) { return sin(p.x * 17.0f + p.y * 31.0f) * SCALE; }
float noise(float3 p) { return hash(p) + hash(p + 1.0f); }
float marbleB(float3 p) { return noise(p) + readAttr("AO"); }
