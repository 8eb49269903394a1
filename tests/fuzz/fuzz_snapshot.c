/* libFuzzer driver of the snapshot-loader harness (logic in fuzz_snapshot.h). */
#define GA2D_IMPLEMENTATION
#include "fuzz_snapshot.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_snapshot_one(data, size); }
