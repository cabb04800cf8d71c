// helpers.cl: no texture function here.
float twice(float x) { return 2.0f * x; }
