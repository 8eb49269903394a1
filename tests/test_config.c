/* The header's configuration: GA2D_STATIC gives this file a private copy of
   the library, and a second inclusion with GA2D_IMPLEMENTATION adds nothing
   (were the implementation compiled twice, this file would not compile:
   every function would be defined twice). */
#define GA2D_STATIC
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "ga2d_physics.h"
#include "test.h"

/* Its functions are static here, so they cannot clash at link time with
   the extern copy that test_main.c compiles; both must agree. */
static void static_copy_works(void)
{
    ga2d_polygon box = ga2d_polygon_box(1, 2);
    ga2d_mass m = ga2d_polygon_mass(&box, 1);
    CHECK(box.count == 4);
    /* 2x4 box: m = 8 and I = m (w^2 + h^2) / 12 = 8 * 20 / 12, both exact
       in binary to within one rounding of the final division */
    CHECK_NEAR(m.mass, 8, 0);
    CHECK_NEAR(m.inertia, 8.0 * 20.0 / 12.0, 4 * REAL_EPS * 14);
}

/* Whether the file (read from the repository root, where make test runs)
   contains `text`. */
static int file_contains(const char *path, const char *text)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    int found;
    if (!f) return 0;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)n + 1);
    if (!buf || fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        fclose(f);
        return 0;
    }
    buf[n] = 0;
    fclose(f);
    found = strstr(buf, text) != NULL;
    free(buf);
    return found;
}

/* The version macros name a release the header's version history and the
   README's status line describe. */
static void version_macros(void)
{
    char entry[64], status[64];
    snprintf(entry, sizeof entry, "\n   %d.%d.%d  ", GA2D_VERSION_MAJOR, GA2D_VERSION_MINOR, GA2D_VERSION_PATCH);
    snprintf(status, sizeof status, "**Status (%d.%d.%d).**", GA2D_VERSION_MAJOR, GA2D_VERSION_MINOR, GA2D_VERSION_PATCH);
    CHECK(file_contains("ga2d_physics.h", entry));
    CHECK(file_contains("README.md", status));
}

static void real_matches_config(void)
{
#ifdef GA2D_DOUBLE
    CHECK(sizeof(ga2d_real) == sizeof(double));
#else
    CHECK(sizeof(ga2d_real) == sizeof(float));
#endif
    CHECK(sizeof(ga2d_vec) == 2 * sizeof(ga2d_real));
    CHECK(sizeof(ga2d_mv) == 4 * sizeof(ga2d_real));
}

static void every_result_has_a_name(void)
{
    int r, s;
    for (r = 0; r < GA2D_RESULT_COUNT; ++r) {
        const char *name = ga2d_result_string((ga2d_result)r);
        CHECK(name != NULL && strcmp(name, "unknown result") != 0);
        for (s = 0; s < r; ++s) CHECK(strcmp(name, ga2d_result_string((ga2d_result)s)) != 0);
    }
    CHECK(GA2D_OK == 0);
    CHECK(strcmp(ga2d_result_string(GA2D_RESULT_COUNT), "unknown result") == 0);
}

void suite_config(void)
{
    test_run("config: GA2D_STATIC copy, implementation included twice", static_copy_works);
    test_run("config: version macros", version_macros);
    test_run("config: ga2d_real follows GA2D_DOUBLE", real_matches_config);
    test_run("config: every result has its own name", every_result_has_a_name);
}
