/* determinism.c - prints the mixed scene's hash (tests/determinism_scene.h)
   for the build it was compiled in, and the hinge net's:
   "<float|double> <hash> <asleep> <hinge net hash>".
   `make test` builds it with gcc and clang, as C and C++, at -O0, -O2 and
   -O3 (always with -ffp-contract=off), and checks that every build of one
   precision prints the same line, with and without unrelated bodies made
   and destroyed elsewhere in the world.  It fails (status 1) when churn
   changes the scene, or when the hinge net's bare hinges, which the
   solver packs into its lanes (16-byte vectors, 32-byte ones with AVX2,
   plain structs with GA2D_NO_SIMD), give other bits than the same joints
   solved one by one. */
#define GA2D_IMPLEMENTATION
#include "determinism_scene.h"
#include <stdio.h>

/* 16 x 16: 465 joints, four colours of about 90 bare hinges each */
#define HINGE_NET 16

int main(void)
{
    int asleep = 0, asleep_churn = 0, in_lanes = 0, none = 0;
    uint64_t h = dscene_run(0, &asleep), hc = dscene_run(1, &asleep_churn);
    uint64_t lanes = dhinge_run(ga2d_default_world_def(), HINGE_NET, 1, &in_lanes);
    uint64_t one_by_one = dhinge_run(ga2d_default_world_def(), HINGE_NET, 0, &none);
    printf("%s %016llx %d %016llx\n", sizeof(ga2d_real) == sizeof(double) ? "double" : "float", (unsigned long long)h, asleep,
           (unsigned long long)lanes);
    if (h == 0 || h != hc || asleep != asleep_churn) {
        printf("churn changed the scene: %016llx vs %016llx\n", (unsigned long long)hc, (unsigned long long)h);
        return 1;
    }
    if (lanes == 0 || lanes != one_by_one || in_lanes == 0 || none != 0) {
        printf("the hinge net in lanes (%d hinges): %016llx, one by one: %016llx\n", in_lanes, (unsigned long long)lanes,
               (unsigned long long)one_by_one);
        return 1;
    }
    return 0;
}
