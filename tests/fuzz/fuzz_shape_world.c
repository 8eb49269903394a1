/* libFuzzer driver of the shapes-in-a-world harness (logic in fuzz_shape_world.h). */
#define GA2D_IMPLEMENTATION
#include "fuzz_shape_world.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_shape_world_one(data, size); }
