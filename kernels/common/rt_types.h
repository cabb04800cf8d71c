/* rt_types.h: the structs shared by texrender's host code (C++) and its fixed OpenCL kernels.
 * Every struct is built from 16-byte vectors and 4-byte scalars in groups of four, so that the
 * host and device layouts agree without packing pragmas. See docs/runtime.md. */
#ifndef RT_TYPES_H
#define RT_TYPES_H

#include "texcc_abi.h"

#ifdef __OPENCL_C_VERSION__
#define RT_F4 float4
#define RT_I4 int4
#define RT_UINT uint
#else
#define RT_F4 cl_float4
#define RT_I4 cl_int4
#define RT_UINT cl_uint
#endif

/* BSDF node types (a material is a small tree of these). */
#define RT_BSDF_DIFFUSE 0
#define RT_BSDF_GLOSSY 1
#define RT_BSDF_MIRROR 2
#define RT_BSDF_EMISSION 3
#define RT_BSDF_BLEND 4
#define RT_BSDF_PRINCIPLED 5

/* RtBsdfNode inputs. Every type: 0 color (principled: baseColor; blend: mask), 1 roughness
 * (emission: strength), 6 normal (output -1: the interpolated shading normal). Principled
 * also: 2 metallic, 3 specular (IOR level), 4 emissionColor, 5 emissionStrength. */
#define RT_IN_COLOR 0
#define RT_IN_ROUGHNESS 1
#define RT_IN_METALLIC 2
#define RT_IN_SPECULAR 3
#define RT_IN_EMISSION_COLOR 4
#define RT_IN_EMISSION_STRENGTH 5
#define RT_IN_NORMAL 6
#define RT_BSDF_INPUTS 7

/* Light types. */
#define RT_LIGHT_TRIANGLE 0
#define RT_LIGHT_SUN 1
#define RT_LIGHT_SKY 2
#define RT_LIGHT_POINT 3 /* Blender's point lamp (Cycles' soft falloff: a disk facing the point) */
#define RT_LIGHT_SPOT 4  /* a point lamp inside a cone with a smoothstep edge */
#define RT_LIGHT_AREA 5  /* a one-sided rectangle or ellipse */
#define RT_LIGHT_ENV 6   /* an equirectangular environment map (the world; rt_env.h) */

/* Path flags. */
#define RT_PATH_ALIVE 1
#define RT_PATH_SPECULAR 2 /* the last bounce was a delta lobe (or the camera): MIS weight 1 */

/* The traversal stack depth. A BVH4 node pushes at most 3 children, so the host builder keeps
 * the tree at most RT_BVH_MAX_DEPTH levels deep (3 * 20 < 64). */
#define RT_BVH_STACK 64
#define RT_BVH_MAX_DEPTH 20

/* Counters in the device statistics buffer. */
#define RT_COUNT_SHADOW_RAYS 0
#define RT_COUNT_AO_RAYS 1
#define RT_COUNT_NONFINITE 2 /* samples dropped by accumulate because they were NaN or infinite */
#define RT_COUNT_SATURATED 3 /* samples whose addition saturated a pixel sum at FLT_MAX */
#define RT_COUNT_SLOTS 4

/* A node of the wide BVH (4 children; built by Embree's BVH builder, runtime/lib/Bvh.cpp), laid
 * out for 4-wide slab tests: lane k of each float4 is child k's box. child.sk >= 0: an inner
 * node's index; < 0: a leaf, ~child.sk = first << RT_BVH_LEAF_BITS | count, the triangles
 * [first, first + count) of the reordered triangle array. An unused slot has an empty box
 * (lo = FLT_MAX, hi = -FLT_MAX), which no ray enters. Node 0 is the root. 128 bytes. */
#define RT_BVH_LEAF_BITS 4
#define RT_BVH_MAX_LEAF 15
typedef struct RtBvh4Node {
  RT_F4 lox, loy, loz;
  RT_F4 hix, hiy, hiz;
  RT_I4 child;
  RT_I4 pad;
} RtBvh4Node;

/* A triangle for intersection (Moeller-Trumbore): v0 and the two edges, in BVH order (the
 * same order as RtTriAttr). */
typedef struct RtTri {
  RT_F4 v0;
  RT_F4 e1;
  RT_F4 e2;
} RtTri;

/* Per-triangle shading data, in the same (BVH) order as RtTri. */
typedef struct RtTriAttr {
  RT_F4 n0, n1, n2;    /* shading normals (world space); w of n0: 1 when the mesh had normals */
  RT_F4 uv01;          /* xy = uv of v0, zw = uv of v1 */
  RT_F4 uv2;           /* xy = uv of v2 */
  int mesh;            /* index into the mesh table */
  int light;           /* index into the light table, or -1 */
  int pad0;
  int pad1;
  /* The corners' UV tangents from the OBJ file's vtan (world space, as given: MikkTSpace's,
   * not normalized), w the bitangent sign (1 or -1); all zero when the file gave none. */
  RT_F4 t0, t1, t2;
} RtTriAttr;

/* A mesh instance: its material (layout.json index), emission, and world-to-object matrix. */
typedef struct RtMesh {
  RT_F4 worldToObject[3]; /* rows of a 3x4 affine matrix */
  RT_F4 emission;         /* xyz: radiance of its front side (scene.json "emission") */
  int material;
  int pad0;
  int pad1;
  int pad2;
} RtMesh;

/* An input of a BSDF node: a constant, or texture output `output` of the material. */
typedef struct RtBsdfInput {
  RT_F4 value;
  int output;     /* -1: constant */
  int components; /* of the texture output: 1 (a float, broadcast to rgb) .. 4 */
  int pad1;
  int pad2;
} RtBsdfInput;

/* One node of a material's BSDF tree; in[] as RT_IN_* above. Blend children are node
 * indices a and b. */
typedef struct RtBsdfNode {
  int type;
  int a;
  int b;
  int pad;
  RtBsdfInput in[RT_BSDF_INPUTS];
} RtBsdfNode;

typedef struct RtMaterial {
  int root;       /* index of its root RtBsdfNode */
  int numOutputs; /* texture outputs; 0: the texture kernel does nothing for it */
  int readsAo;    /* its textures read AO: only its hits trace AO rays */
  int pad1;
} RtMaterial;

/* A light for next-event estimation; chosen with probability `select` (the CDF is a separate
 * float array). Triangle: tri = BVH-order triangle index. Sun: dir.xyz towards the sun,
 * dir.w = cos(angular radius). Lamps (point, spot, area; scene.json's units converted by the
 * host, docs/scene.md): radiance is the emitted radiance (a point or spot of radius 0: the
 * radiant intensity, W/sr), pos.xyz the centre, pos.w the radius (point, spot); spot: dir.xyz
 * the way it shines, dir.w cos(half the cone angle), u.w the smoothstep scale
 * 1 / ((1 - cos) * blend) (INFINITY for blend 0); area: dir.xyz the side it lights, u.xyz and
 * v.xyz the half extents, area its area; tri: RT_LAMP_* flags. */
#define RT_LAMP_ELLIPSE 1   /* area: an ellipse (else a rectangle) */
#define RT_LAMP_NO_SHADOW 2 /* casts no shadow: its shadow rays are not traced */
#define RT_LAMP_CAMERA 4    /* camera rays see it (Blender 5.0 light objects: off by default) */
#define RT_LAMP_SPHERE 8    /* point, spot of radius > 0: a sphere (Soft Falloff off) */
typedef struct RtLight {
  int type;
  int tri;
  float select;
  float area;
  RT_F4 radiance;
  RT_F4 dir;
  RT_F4 pos;
  RT_F4 u;
  RT_F4 v;
} RtLight;

/* The pinhole camera: rays through pixel (x, y) go along forward + (2u-1)*right - (2v-1)*up,
 * with right and up already scaled by tan(fov/2) and the aspect ratio. */
typedef struct RtCamera {
  RT_F4 position;
  RT_F4 forward;
  RT_F4 right;
  RT_F4 up;
} RtCamera;

/* One path of the wavefront. dir.w: the solid-angle pdf of the BSDF sample that produced the
 * ray (for MIS); origin.w: unused. */
typedef struct RtPath {
  RT_F4 origin;
  RT_F4 dir;
  RT_F4 throughput;
  RT_F4 radiance;
  RT_UINT pixel;
  RT_UINT rng;
  int depth; /* segments traced so far (the camera ray is segment 1) */
  int flags;
} RtPath;

typedef struct RtHit {
  float t;
  int tri; /* -1: miss */
  float u;
  float v;
} RtHit;

/* A shadow ray with the radiance it carries when unoccluded (contrib.w > 0: valid). */
typedef struct RtShadowRay {
  RT_F4 origin;
  RT_F4 dir; /* w = tmax */
  RT_F4 contrib;
} RtShadowRay;

/* Render parameters of the shading kernel. */
typedef struct RtShadeParams {
  int maxDepth; /* Mitsuba's max_depth; -1 = unlimited */
  int rrDepth;  /* Russian roulette from this depth on */
  int numLights;
  int skyLight; /* index of the sky in the light table, or -1 */
  int sunLight; /* index of the sun, or -1 */
  float epsilon; /* relative ray-origin offset */
  int lampFirst; /* the lamps (point, spot, area) are lights [lampFirst, lampFirst + numLamps) */
  int numLamps;
  int envLight;  /* index of the environment map in the light table, or -1 (rt_env.h) */
  int envWidth;  /* its texels (the shade kernel's envMap buffer) */
  int envHeight;
  int envFlags;  /* RT_ENV_* */
} RtShadeParams;

/* RtShadeParams.envFlags (runtime/lib/Environment.cpp sets them, rt_env.h reads them). */
#define RT_ENV_SRGB 1    /* texels hold sRGB-encoded values, decoded after interpolation */
#define RT_ENV_CLOSEST 2 /* the nearest texel (else bilinear) */

#endif
