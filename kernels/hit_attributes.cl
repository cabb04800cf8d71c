/* hit_attributes.cl: fills TexccHitAttrs for each active hit, computing only the attributes in
 * attrMask (bit k = TEXCC_ATTR_k, from layout.json "attributes"); the others stay zero. Also
 * sets hitMaterial (the texture kernel's material index, -1 for a miss or a material without
 * texture outputs). AO (bit TEXCC_ATTR_AO) is filled later by ao_reduce. TangentSign shares
 * TexccHitAttrs.tangent (its w), Backfacing uvAO (its w). WorldPos.w is 1 on a
 * hit; ViewDir is also set for a miss (the tests recover the ray from it). */
#include "rt_surface.h"

__kernel void hit_attributes(__global const RtTri *tris, __global const RtTriAttr *triAttrs,
                             __global const RtMesh *meshes, __global const RtMaterial *materials,
                             __global const RtPath *paths, __global const int *active,
                             int numActive, __global const RtHit *hits, uint attrMask,
                             __global TexccHitAttrs *out, __global int *hitMaterial) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  RtHit h = hits[i];
  TexccHitAttrs a;
  a.worldPos = a.objectPos = a.normal = a.geomNormal = (float4)(0.0f);
  a.tangent = a.viewDir = a.uvAO = a.objectTangent = a.objectBitangent = (float4)(0.0f);
  a.uvAO.z = 1.0f;
  __global const RtPath *p = &paths[active[i]];
  float3 d = p->dir.xyz;
  if (attrMask & (1u << TEXCC_ATTR_VIEWDIR))
    a.viewDir = (float4)(-d, 0.0f);
  if (h.tri < 0) {
    out[i] = a;
    hitMaterial[i] = -1;
    return;
  }
  RtSurface s = rt_surface(tris, triAttrs, p->origin.xyz, d, h);
  RtMesh mesh = meshes[triAttrs[h.tri].mesh];
  RtMaterial m = materials[mesh.material];
  hitMaterial[i] = m.numOutputs > 0 ? mesh.material : -1;
  if (attrMask & (1u << TEXCC_ATTR_WORLDPOS))
    a.worldPos = (float4)(s.p, 1.0f);
  if (attrMask & (1u << TEXCC_ATTR_OBJECTPOS)) {
    float4 wp = (float4)(s.p, 1.0f);
    a.objectPos = (float4)(dot(mesh.worldToObject[0], wp), dot(mesh.worldToObject[1], wp),
                           dot(mesh.worldToObject[2], wp), 1.0f);
  }
  if (attrMask & (1u << TEXCC_ATTR_NORMAL))
    a.normal = (float4)(s.ns, 0.0f);
  if (attrMask & (1u << TEXCC_ATTR_GEOMNORMAL))
    a.geomNormal = (float4)(s.ng, 0.0f);
  if (attrMask & ((1u << TEXCC_ATTR_TANGENT) | (1u << TEXCC_ATTR_TANGENTSIGN))) {
    /* The UV tangent: the corners' vtan interpolated as Cycles interpolates its MikkTSpace
     * tangent attribute (barycentric, not normalized), with the interpolated bitangent sign;
     * without vtan (or where it vanishes), dP/du of the triangle's UVs made orthogonal to the
     * shading normal and normalized, and the sign of the UVs' orientation; any orthogonal
     * vector when all else is degenerate. */
    __global const RtTriAttr *ta = &triAttrs[h.tri];
    const float b0 = 1.0f - h.u - h.v;
    float3 t = b0 * ta->t0.xyz + h.u * ta->t1.xyz + h.v * ta->t2.xyz;
    float sgn = b0 * ta->t0.w + h.u * ta->t1.w + h.v * ta->t2.w;
    /* The shading normal on the side of the winding (s.ns faces the ray). */
    const float3 nWound = s.front ? s.ns : -s.ns;
    if (ta->t0.w != 0.0f && dot(t, t) >= 1e-24f) {
      /* Cycles' Normal Map combines the tangent and the normal as interpolated, neither
       * normalized: both divided by the normal's length (Tangent and TangentSign in the units
       * of the unit Normal), its frame stays Cycles' exactly. */
      const float len = ta->n0.w > 0.0f ? length(b0 * ta->n0.xyz + h.u * ta->n1.xyz +
                                                 h.v * ta->n2.xyz) : 1.0f;
      if (len > 0.0f)
        a.tangent = (float4)(t / len, sgn * len);
    }
    if (ta->t0.w == 0.0f || dot(t, t) < 1e-24f) {
      float2 duv1 = ta->uv01.zw - ta->uv01.xy, duv2 = ta->uv2.xy - ta->uv01.xy;
      float det = duv1.x * duv2.y - duv1.y * duv2.x;
      t = (float3)(0.0f);
      sgn = 1.0f;
      if (fabs(det) > 1e-12f) {
        const float3 e1 = tris[h.tri].e1.xyz, e2 = tris[h.tri].e2.xyz;
        t = (duv2.y * e1 - duv1.y * e2) / det;
        const float3 dpdv = (duv1.x * e2 - duv2.x * e1) / det;
        sgn = dot(cross(nWound, t), dpdv) < 0.0f ? -1.0f : 1.0f;
      }
    }
    if (a.tangent.w == 0.0f) {
      t -= dot(t, s.ns) * s.ns;
      if (length(t) < 1e-12f) {
        float3 b;
        rt_frame(s.ns, &t, &b);
      }
      a.tangent = (float4)(normalize(t), sgn);
    }
  }
  if (attrMask & (1u << TEXCC_ATTR_BACKFACING))
    a.uvAO.w = s.front ? 0.0f : 1.0f;
  if ((attrMask & (1u << TEXCC_ATTR_OBJECTPOS)) && (attrMask & (1u << TEXCC_ATTR_GEOMNORMAL))) {
    /* For bump's moved ObjectPos: its offset directions (texcc_device.h texcc_bump_frame, the
     * same arithmetic on the geometric normal) through the inverse transform. */
    float3 n = s.ng;
    float3 t = normalize((n.x != n.y || n.x != n.z) ? (float3)(n.z - n.y, n.x - n.z, n.y - n.x)
                                                    : (float3)(n.z - n.y, n.x + n.z, -n.y - n.x));
    float3 b = cross(n, t);
    a.objectTangent = (float4)(dot(mesh.worldToObject[0].xyz, t),
                               dot(mesh.worldToObject[1].xyz, t),
                               dot(mesh.worldToObject[2].xyz, t), 0.0f);
    a.objectBitangent = (float4)(dot(mesh.worldToObject[0].xyz, b),
                                 dot(mesh.worldToObject[1].xyz, b),
                                 dot(mesh.worldToObject[2].xyz, b), 0.0f);
  }
  if (attrMask & (1u << TEXCC_ATTR_TEXCOORD0))
    a.uvAO.xy = s.uv;
  out[i] = a;
}
