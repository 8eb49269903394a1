/* Determinism (issue 8): the mixed scene of tests/determinism_scene.h gives
   the same bits run after run in one process, and with unrelated bodies
   made and destroyed 1 km away while it runs.  (Across compilers, languages
   and optimisation levels, tests/determinism.c's builds are compared by
   `make test`.) */
#include "test.h"
#include "determinism_scene.h"
#include <stdlib.h>

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static void same_bits_every_run(void)
{
    int asleep0 = 0, asleep1 = 0, asleep2 = 0;
    uint64_t h0 = dscene_run(0, &asleep0), h1 = dscene_run(0, &asleep1), h2 = dscene_run(1, &asleep2);
    CHECK(h0 != 0);
    CHECK(h0 == h1 && asleep0 == asleep1);
    CHECK(h0 == h2 && asleep0 == asleep2);
    /* the scene is not trivially still: by 10 s the pile has come to rest
       and part of it sleeps, which the hash covers too */
    CHECK(asleep0 > 0);
    if (verbose())
        printf("determinism: hash %016llx (again %016llx, with churn %016llx), %d bodies asleep\n", (unsigned long long)h0,
               (unsigned long long)h1, (unsigned long long)h2, asleep0);
}

void suite_determinism(void) { test_run("determinism: same bits every run, and with churn elsewhere", same_bits_every_run); }
