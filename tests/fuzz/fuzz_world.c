/* libFuzzer driver of the world harness (logic in fuzz_world.h). */
#define GA2D_IMPLEMENTATION
#include "fuzz_world.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_world_one(data, size); }
