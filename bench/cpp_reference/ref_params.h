/* ref_params.h: the run-time parameters of ref.c's variants (ref_textures.cl, ref_voronoi.cl and
 * ref.c share it; each variant reads the fields its texture function takes). */
#ifndef REF_PARAMS_H
#define REF_PARAMS_H
typedef struct RefParams {
  float scale, detail, roughness, lacunarity, offset, gain, distortion;
  int type, normalize, octaves;
  /* Wave (detailScale; direction, profile) and Voronoi (smoothness, exponent, randomness;
   * type is the feature, direction the metric). */
  float detailScale, smoothness, exponent, randomness;
  int direction, profile;
} RefParams;
#endif
