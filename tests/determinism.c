/* determinism.c - prints the mixed scene's hash (tests/determinism_scene.h)
   for the build it was compiled in:  "<float|double> <hash> <asleep>".
   `make test` builds it with gcc and clang, as C and C++, at -O0, -O2 and
   -O3 (always with -ffp-contract=off), and checks that every build of one
   precision prints the same line, with and without unrelated bodies made
   and destroyed elsewhere in the world. */
#define GA2D_IMPLEMENTATION
#include "determinism_scene.h"
#include <stdio.h>

int main(void)
{
    int asleep = 0, asleep_churn = 0;
    uint64_t h = dscene_run(0, &asleep), hc = dscene_run(1, &asleep_churn);
    printf("%s %016llx %d\n", sizeof(ga2d_real) == sizeof(double) ? "double" : "float", (unsigned long long)h, asleep);
    if (h == 0 || h != hc || asleep != asleep_churn) {
        printf("churn changed the scene: %016llx vs %016llx\n", (unsigned long long)hc, (unsigned long long)h);
        return 1;
    }
    return 0;
}
