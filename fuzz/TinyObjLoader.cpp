// tinyobjloader's parser compiled into fuzz-obj with the fuzz build's coverage and sanitizer
// flags. Debian ships it as a prebuilt shared library, which libFuzzer cannot see into; the
// executable's definitions take precedence over the shared library's (ELF interposition), so
// loadObj runs this copy.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
