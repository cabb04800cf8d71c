/* shim.h: a stand-in for texcc's prelude, for a plain clang syntax check of a texture file
 * before (or without) texcc:
 *
 *   sed -E 's/read(Attr|Setting)\("([A-Za-z0-9_]+)"\)/tex_shim_\1_\2()/g' file.cl > t.cl
 *   clang-15 -x cl -cl-std=CL1.2 -Xclang -finclude-default-header -fsyntax-only \
 *            -include shim.h t.cl
 *
 * readAttr's result type depends on its string argument, which no C declaration can express,
 * so the sed step turns readAttr("Name") into a call of tex_shim_Attr_Name() (and
 * readSetting likewise), declared here with the types of DESIGN.md. An unknown name is then a
 * call of an undeclared function: an error, as in texcc. */
#ifndef TEX_SHIM_H
#define TEX_SHIM_H

typedef int sam2D;
float4 tex2D(sam2D image, float2 uv);

float3 tex_shim_Attr_WorldPos(void);
float3 tex_shim_Attr_ObjectPos(void);
float3 tex_shim_Attr_Normal(void);
float3 tex_shim_Attr_GeomNormal(void);
float3 tex_shim_Attr_Tangent(void);
float2 tex_shim_Attr_TexCoord0(void);
float tex_shim_Attr_AO(void);
float3 tex_shim_Attr_ViewDir(void);

float tex_shim_Setting_Time(void);
int tex_shim_Setting_Frame(void);
float3 tex_shim_Setting_CameraPos(void);

#endif
