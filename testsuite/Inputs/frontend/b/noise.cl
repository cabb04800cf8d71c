float one(void) { return 2.0f; }
float texB(float x) { return one() + x; }
