float one(void) { return 1.0f; }
float texA(float x) { return one() * x; }
