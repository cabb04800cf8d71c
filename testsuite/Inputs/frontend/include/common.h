// A user header shared by several texture files (see include-splice.cl).
#ifndef COMMON_H
#define COMMON_H
#define COMMON_GAIN 0.5f
float gainOf(float x) { return x * COMMON_GAIN; }
#endif
