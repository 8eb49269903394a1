/* libFuzzer driver of the world-free shapes harness (logic in fuzz_shapes.h). */
#define GA2D_IMPLEMENTATION
#include "fuzz_shapes.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_shapes_one(data, size); }
