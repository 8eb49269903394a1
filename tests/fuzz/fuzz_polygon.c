/* libFuzzer driver of the polygon harness (logic in fuzz_polygon.h). */
#define GA2D_IMPLEMENTATION
#include "fuzz_polygon.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_polygon_one(data, size); }
