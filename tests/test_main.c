/* The test runner: the one translation unit that compiles the library. */
#define GA2D_IMPLEMENTATION
#include "test.h"

#include <stdarg.h>

static int g_passed, g_failed, g_case_failures;
static const char *g_case;
static char **g_filters; /* argv: run only tests whose name holds one */
static int g_filter_count;
/* TEST_FIRST_FAILURE set (make mutate sets it): the tests after the first
   that fails are skipped, since a planted bug is caught by one failure */
static int g_first_failure_ends;

static int selected(const char *name)
{
    int i;
    if (g_filter_count == 0) return 1;
    for (i = 0; i < g_filter_count; ++i)
        if (strstr(name, g_filters[i])) return 1;
    return 0;
}

void test_fail(const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    /* print only the first few failures of a case: a loop can fail often */
    if (g_case_failures++ < 5) {
        printf("  FAIL %s (%s:%d): ", g_case, file, line);
        va_start(ap, fmt);
        vprintf(fmt, ap);
        va_end(ap);
        printf("\n");
    }
}

void test_run(const char *name, void (*fn)(void))
{
    if (!selected(name)) return;
    if (g_first_failure_ends && g_failed) return;
    g_case = name;
    g_case_failures = 0;
    fn();
    if (g_case_failures) {
        ++g_failed;
        printf("not ok  %s (%d failed checks)\n", name, g_case_failures);
    } else {
        ++g_passed;
    }
    fflush(stdout);
}

uint64_t rng_next(test_rng *r)
{
    uint64_t z = (r->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double rng_uniform(test_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * ((double)(rng_next(r) >> 11) * (1.0 / 9007199254740992.0));
}

int rng_int(test_rng *r, int lo, int hi)
{
    return lo + (int)(rng_next(r) % (uint64_t)(hi - lo + 1));
}

/* ./build/tests/<config> [word ...]: every test, or those whose name
   contains one of the words (say "solver" or "hostile: blow-up"). */
int main(int argc, char **argv)
{
    g_filters = argv + 1;
    g_filter_count = argc - 1;
    g_first_failure_ends = getenv("TEST_FIRST_FAILURE") != NULL;
    printf("ga2d_physics %d.%d.%d tests, ga2d_real = %s, %s, max polygon vertices %d\n",
           GA2D_VERSION_MAJOR, GA2D_VERSION_MINOR, GA2D_VERSION_PATCH, REAL_NAME,
#ifdef __cplusplus
           "C++",
#else
           "C",
#endif
           GA2D_MAX_POLYGON_VERTICES);
    suite_config();
    suite_algebra();
    suite_polygon();
    suite_mass();
    suite_shape_mass();
    suite_world();
    suite_motion();
    suite_collide();
    suite_shape_collide();
    suite_contacts();
    suite_solver();
    suite_shape_world();
    suite_shape_terrain();
    suite_shape_dynamics();
    suite_features();
    suite_settle();
    suite_joints();
    suite_joints_kinds();
    suite_joints_scenes();
    suite_joints_extremes();
    suite_queries();
    suite_continuous();
    suite_mover();
    suite_restitution_fast();
    suite_threads();
    suite_accepted();
    suite_determinism();
    suite_snapshot();
    suite_containment();
    suite_fuzz_regress();
    suite_failinject();
    suite_extremes();
    suite_hostile();
    if (g_filter_count > 0 && g_passed + g_failed == 0) {
        printf("no test name contains %s%s\n", argv[1], argc > 2 ? " (or the other words)" : "");
        return 1;
    }
    printf("%d passed, %d failed\n", g_passed, g_failed);
    return g_failed ? 1 : 0;
}
