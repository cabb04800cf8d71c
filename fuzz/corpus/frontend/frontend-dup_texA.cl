// A second definition of texA (see err-duplicate-texture.test).
float texA(float x) { return x; }
