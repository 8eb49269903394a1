/* Replays what the fuzzers found (issue 8): every input kept in
   tests/fuzz/regress/<harness>/ (one per finding, each fixed in the
   header) and the small seed corpus in tests/fuzz/seeds/<harness>/, run
   through the same per-input functions the libFuzzer drivers call
   (polygon, world, snapshot-loader, re-entry, world-free shapes and
   shapes-in-a-world harnesses)
   (tests/fuzz/fuzz_<harness>.h), in this build's configuration.  A
   violated invariant is a failed check here; a memory or UB error stops
   the sanitizer builds.  `make test` runs from the repository root, where
   the directories are found.

   Listing a directory needs POSIX <dirent.h>; elsewhere the suite says so
   and replays nothing. */
#if !defined(_WIN32) && !defined(_POSIX_C_SOURCE)
#define _POSIX_C_SOURCE 200809L
#endif
#include "test.h"

#define FUZZ_FAIL(file, line, what) test_fail((file), (line), "fuzz invariant: %s", (what))
#include "fuzz/fuzz_polygon.h"
#include "fuzz/fuzz_world.h"
#include "fuzz/fuzz_snapshot.h"
#include "fuzz/fuzz_reentry.h"
#include "fuzz/fuzz_shapes.h"
#include "fuzz/fuzz_shape_world.h"

#if !defined(_WIN32)
#include <dirent.h>
#define HAVE_DIRENT 1
#endif

#define FUZZ_ROOT "tests/fuzz"
#define FUZZ_MAX_INPUT (1 << 20)
#define MAX_FILES 512

typedef int fuzz_one_fn(const uint8_t *data, size_t size);

static int cmp_names(const void *a, const void *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

/* Runs every file of FUZZ_ROOT/<kind>/<harness>/ through fn; returns how
   many it replayed, or -1 when the directory cannot be opened.  *listed
   gets how many files the directory holds: every one must be replayed. */
static int replay_dir(const char *kind, const char *harness, fuzz_one_fn *fn, int *listed)
{
#ifdef HAVE_DIRENT
    char path[512];
    char *names[MAX_FILES];
    int n = 0, i, replayed = 0;
    DIR *dir;
    struct dirent *e;
    uint8_t *buf = (uint8_t *)malloc(FUZZ_MAX_INPUT);
    *listed = 0;
    if (!buf) return -1;
    snprintf(path, sizeof path, "%s/%s/%s", FUZZ_ROOT, kind, harness);
    dir = opendir(path);
    if (!dir) {
        free(buf);
        return -1;
    }
    while ((e = readdir(dir)) != NULL) {
        size_t len = strlen(e->d_name);
        if (e->d_name[0] == '.') continue;
        ++*listed; /* counted even past MAX_FILES, which then fails the check */
        if (n == MAX_FILES) continue;
        names[n] = (char *)malloc(len + 1);
        if (!names[n]) continue;
        memcpy(names[n], e->d_name, len + 1);
        ++n;
    }
    closedir(dir);
    qsort(names, (size_t)n, sizeof names[0], cmp_names); /* the same order every run */
    for (i = 0; i < n; ++i) {
        char file[1024];
        FILE *f;
        size_t size;
        snprintf(file, sizeof file, "%s/%s", path, names[i]);
        f = fopen(file, "rb");
        CHECK(f != NULL);
        if (f) {
            size = fread(buf, 1, FUZZ_MAX_INPUT, f);
            CHECK(!ferror(f));
            fclose(f);
            fn(buf, size);
            ++replayed;
        }
        free(names[i]);
    }
    free(buf);
    return replayed;
#else
    (void)kind;
    (void)harness;
    (void)fn;
    *listed = 0;
    return -1;
#endif
}

/* Each harness: its findings and its seeds (tests/fuzz itself must be
   there: the suite runs from the repository root).  A replay that found
   fewer inputs than the repository keeps is no replay: each harness
   names the least number of findings and seeds it holds (inputs are only
   ever added; a harness with no finding has no regress directory, since
   git keeps no empty one), so a deleted or emptied directory, or a run
   from elsewhere, fails here, and every file a directory lists must have
   been read and replayed. */
static void replay(const char *harness, fuzz_one_fn *fn, int min_findings, int min_seeds)
{
    int listed_f = 0, listed_s = 0;
    int found = replay_dir("regress", harness, fn, &listed_f), seeds = replay_dir("seeds", harness, fn, &listed_s);
#ifdef HAVE_DIRENT
    DIR *root = opendir(FUZZ_ROOT);
    CHECK(root != NULL);
    if (root) closedir(root);
    if (found < 0) found = 0;
    if (seeds < 0) seeds = 0;
    if (found < min_findings || seeds < min_seeds)
        test_fail(__FILE__, __LINE__, "%s: replayed %d findings and %d seeds; the repository keeps at least %d and %d", harness,
                  found, seeds, min_findings, min_seeds);
    CHECK(found == listed_f);
    CHECK(seeds == listed_s);
#else
    (void)min_findings;
    (void)min_seeds;
#endif
    {
        const char *v = getenv("GA2D_TEST_VERBOSE");
        if (v && v[0]) printf("fuzz regress: %s: %d findings, %d seeds replayed\n", harness, found, seeds);
    }
}

static int polygon_one(const uint8_t *data, size_t size) { return fuzz_polygon_one(data, size); }
static int world_one(const uint8_t *data, size_t size) { return fuzz_world_one(data, size); }
static int snapshot_one(const uint8_t *data, size_t size) { return fuzz_snapshot_one(data, size); }
static int reentry_one(const uint8_t *data, size_t size) { return fuzz_reentry_one(data, size); }
static int shapes_one(const uint8_t *data, size_t size) { return fuzz_shapes_one(data, size); }
static int shape_world_one(const uint8_t *data, size_t size) { return fuzz_shape_world_one(data, size); }

/* The least numbers of findings and seeds kept in tests/fuzz/regress/ and
   tests/fuzz/seeds/ per harness: raise them when adding inputs. */
static void regress_polygon(void) { replay("polygon", polygon_one, 13, 8); }
static void regress_world(void) { replay("world", world_one, 9, 6); }
static void regress_snapshot(void) { replay("snapshot", snapshot_one, 0, 5); }
static void regress_reentry(void) { replay("reentry", reentry_one, 8, 7); }
static void regress_shapes(void) { replay("shapes", shapes_one, 17, 9); }
static void regress_shape_world(void) { replay("shape_world", shape_world_one, 25, 14); }

/* The empty input and a few fixed ones, which need no files. */
static void fixed_inputs(void)
{
    static const uint8_t zeros[64] = {0};
    uint8_t ramp[256];
    int i;
    for (i = 0; i < 256; ++i) ramp[i] = (uint8_t)i;
    fuzz_polygon_one(NULL, 0);
    fuzz_polygon_one(zeros, sizeof zeros);
    fuzz_polygon_one(ramp, sizeof ramp);
    fuzz_world_one(NULL, 0);
    fuzz_world_one(zeros, sizeof zeros);
    fuzz_world_one(ramp, sizeof ramp);
    fuzz_snapshot_one(NULL, 0);
    fuzz_snapshot_one(zeros, sizeof zeros);
    fuzz_snapshot_one(ramp, sizeof ramp);
    fuzz_reentry_one(NULL, 0);
    fuzz_reentry_one(zeros, sizeof zeros);
    fuzz_reentry_one(ramp, sizeof ramp);
    fuzz_shapes_one(NULL, 0);
    fuzz_shapes_one(zeros, sizeof zeros);
    fuzz_shapes_one(ramp, sizeof ramp);
    fuzz_shape_world_one(NULL, 0);
    fuzz_shape_world_one(zeros, sizeof zeros);
    fuzz_shape_world_one(ramp, sizeof ramp);
}

void suite_fuzz_regress(void)
{
    test_run("fuzz regress: fixed inputs", fixed_inputs);
    test_run("fuzz regress: polygon findings and seeds", regress_polygon);
    test_run("fuzz regress: world findings and seeds", regress_world);
    test_run("fuzz regress: snapshot findings and seeds", regress_snapshot);
    test_run("fuzz regress: re-entry findings and seeds", regress_reentry);
    test_run("fuzz regress: shapes findings and seeds", regress_shapes);
    test_run("fuzz regress: shape world findings and seeds", regress_shape_world);
}
