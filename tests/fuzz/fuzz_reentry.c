/* libFuzzer driver of the re-entry harness (logic in fuzz_reentry.h). */
#define GA2D_IMPLEMENTATION
#include "fuzz_reentry.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_reentry_one(data, size); }
