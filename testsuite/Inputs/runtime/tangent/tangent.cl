/* The tangent attributes as colours (tangent-*.test): each vector v as 0.5 v + 0.5. */
float3 tgEncode(float3 v) { return 0.5f * v + (float3)(0.5f); }
float3 tgTangent() { return tgEncode(readAttr("Tangent")); }
float3 tgSign() {
  return (float3)(0.5f * readAttr("TangentSign") + 0.5f, readAttr("Backfacing"), 0.0f);
}
float3 tgNormal() { return tgEncode(readAttr("Normal")); }
