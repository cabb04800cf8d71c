/* texcc_abi.h: the structs shared by the host runtime (C++) and every OpenCL kernel, the
 * generated texture kernel included. Layouts are fixed: all members are 16-byte vectors or
 * 4-byte scalars in groups of four. See docs/abi.md. */
#ifndef TEXCC_ABI_H
#define TEXCC_ABI_H

#ifdef __OPENCL_C_VERSION__ /* defined by every OpenCL C compiler, plain clang -x cl included */
#define TEXCC_F4 float4
#define TEXCC_I4 int4
#else
#include <CL/cl_platform.h>
#define TEXCC_F4 cl_float4
#define TEXCC_I4 cl_int4
#endif

/* Attribute ids (ABI; also the order of attributeTable() in the graph library). */
#define TEXCC_ATTR_WORLDPOS 0
#define TEXCC_ATTR_OBJECTPOS 1
#define TEXCC_ATTR_NORMAL 2
#define TEXCC_ATTR_GEOMNORMAL 3
#define TEXCC_ATTR_TANGENT 4
#define TEXCC_ATTR_TEXCOORD0 5
#define TEXCC_ATTR_AO 6
#define TEXCC_ATTR_VIEWDIR 7
#define TEXCC_ATTR_TANGENTSIGN 8
#define TEXCC_ATTR_BACKFACING 9
#define TEXCC_ATTR_COUNT 10

/* Per-hit surface attributes. The hit-attributes kernel fills only those the textures read
 * (layout.json "attributes"); the rest are zero. */
typedef struct TexccHitAttrs {
  TEXCC_F4 worldPos;   /* xyz */
  TEXCC_F4 objectPos;  /* xyz */
  TEXCC_F4 normal;     /* xyz, shading normal, unit, facing the incoming ray */
  TEXCC_F4 geomNormal; /* xyz, unit, facing the incoming ray */
  /* xyz: the mesh's UV tangent. With the OBJ file's vtan: the corners' tangents interpolated
   * as Cycles interpolates its MikkTSpace tangent, over the length of the interpolated shading
   * normal (neither normalized: Cycles' Normal Map combines them so); without vtan: dP/du of
   * the triangle's UVs made orthogonal to the normal, unit (any orthogonal unit vector
   * without UVs). w: TangentSign, the bitangent sign (the vtan's interpolated, times the same
   * length; else the UVs' orientation, 1 or -1): sign * cross(normal, tangent) is the
   * bitangent (along dP/dv), the normal taken on the side of the triangle's winding. */
  TEXCC_F4 tangent;
  TEXCC_F4 viewDir;    /* xyz, unit, from the hit towards the viewer (-ray direction) */
  /* xy = TexCoord0, z = AO (1 = unoccluded), w = Backfacing (1: the ray hit the side the
   * triangle's winding faces away from, whose normals the kernels turn to face the ray) */
  TEXCC_F4 uvAO;
  /* xyz: bump's two offset directions, texcc_bump_frame's a and b of the geometric normal,
   * through the object's inverse transform (its linear part), set with GeomNormal and
   * ObjectPos: bump moves ObjectPos by them (texcc_device.h). */
  TEXCC_F4 objectTangent;
  TEXCC_F4 objectBitangent;
} TexccHitAttrs;

/* Global engine settings (readSetting). */
typedef struct TexccSettings {
  TEXCC_F4 cameraPos; /* xyz: CameraPos */
  float time;         /* Time, seconds */
  int frame;          /* Frame */
  /* The camera's angular size of one pixel, radians: 2 tan(fov / 2) / width (the film's
   * pixel pitch at unit distance, Cycles' ray differential at the image centre). Bump's step
   * (texcc_device.h texcc_bump_step) is 0.1 of the ray's footprint, this times the hit's
   * distance (less off the centre); 0: no footprint (the step is the float-resolution
   * floor). texrender sets it per render (Renderer.cpp textureSettings), so it follows the
   * image size. */
  float pixelAngle;
  int pad1;
  /* The camera's unit view direction and the film's unit right and up axes: where a hit lies
   * on the film, for bump's footprint off the image centre (texcc_bump_footprint). Zero: the
   * centre's footprint everywhere. Set with pixelAngle. */
  TEXCC_F4 cameraForward;
  TEXCC_F4 cameraRight;
  TEXCC_F4 cameraUp;
} TexccSettings;

/* One image bound to a sam2D: texels are linear float4 RGBA, row-major, row 0 at the top
 * (v = 0 at the top row's centre edge). flags: the image's colour space (graph.md "images"),
 * which tex2DFiltered follows as Blender does. */
#define TEXCC_IMAGE_SRGB 1   /* sRGB (decoded to linear on load) */
#define TEXCC_IMAGE_DATA 2   /* Non-Color: never premultiplied by alpha */
#define TEXCC_IMAGE_BYTES 4  /* an 8-bit file */
#define TEXCC_IMAGE_SHORTS 8 /* a 16-bit file */
typedef struct TexccImageInfo {
  int offset; /* first texel in the texel buffer */
  int width;
  int height;
  int flags; /* TEXCC_IMAGE_* */
} TexccImageInfo;

/* The fault record: the texture kernels' last argument (docs/abi.md "Faults"), TEXCC_FAULT_WORDS
 * ints, all zero until the first work-item whose user code trips a safety check that texcc
 * inserted (docs/reliability.md "User code") fills it; later faults of the launch are dropped. */
#define TEXCC_FAULT_NONE 0
#define TEXCC_FAULT_LOOP_BUDGET 1 /* a loop ran past the budget; detail: the budget */
#define TEXCC_FAULT_INDEX 2       /* a __global array read out of bounds; detail: the index,
                                     extra: the array's length */
#define TEXCC_FAULT_KIND 0        /* word indices */
#define TEXCC_FAULT_LINE 1        /* the user's line (__LINE__, #line-mapped) */
#define TEXCC_FAULT_AT 2          /* the node: TEXCC_AT_NODE | node index, or the material's
                                     instruction index */
#define TEXCC_FAULT_HIT 3         /* the work-item (hit) */
#define TEXCC_FAULT_DETAIL 4
#define TEXCC_FAULT_EXTRA 5
#define TEXCC_FAULT_MATERIAL 6
#define TEXCC_FAULT_WORDS 8
#define TEXCC_AT_NODE 0x40000000

#endif
