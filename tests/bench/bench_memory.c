/* bench_memory.c - how much memory a world takes at scale, and whether it
   gives memory back.

   Speed is measured elsewhere (bench_scenes.c); this asks what a large
   world costs in bytes, which a timing table does not show: a user sizing
   an arena or a console budget needs the peak, not the average, and needs
   to know whether a world that shrinks frees anything.

   Scene, per N (default 10 000, 30 000 and 100 000): N dynamic boxes of
   0.2 m (half-extent 0.1, density 1, default friction) on a grid of
   0.2 m pitch, ~1.5 sqrt(N) columns wide (a wide, low heap rather than a
   tower), the lowest row 0.3 m above a static ground box between two
   static walls.  Default world def (4 substeps, soft step, sleep on),
   dt = 1/60, stepped until the pile settles (every body asleep, or none
   faster than 5 cm/s, the sleep threshold) or 300 steps (120 above 30 000
   bodies, for time), whichever comes first.  Then every body but each
   tenth is destroyed and the world stepped 10 more times, to see whether
   the memory follows the pair count down; a 0.8.1 header's
   ga2d_world_compact is called after that, if any.

   All the world's memory comes through ga2d_world_def.allocator, here a
   counting allocator: ga2d's free gets the size that was asked for, so
   current and peak bytes need no per-block header.  Only the library's
   bytes are counted (the bench's own id array is plain malloc).

   Per N: peak bytes and bytes per body at the peak; bytes at the end of
   settling; the counters of ga2d_world_get_counters at the end and the
   largest pair count seen after any step; bytes after destroying 90%, and
   after compacting.  The byte counts are deterministic (ga2d is); the
   seconds are this machine's.

     bench_memory [out.csv [N ...]]

   writes the CSV when given a path (the Makefile passes one), and runs
   only the given sizes when given any (bench_memory x.csv 2000 for a quick
   look).  Exit status 0 when every size ran and every byte was given back
   when its world was destroyed. */
#define _POSIX_C_SOURCE 199309L
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Settling stops at 300 steps (5 s), or at 120 above 30 000 bodies, to
   keep the default run near 2 minutes: the 100 000 pile does not settle
   in 300 steps (it is one island, never still) and costs 0.2-0.5 s a step
   on the 2-core development machine, 145 s for 300 steps alone.  Its peak
   is set by step ~26 and its pair count tops out near step 104; memory
   only grows, so later steps change no peak, only the end counters. */
#define MAX_SETTLE_STEPS 300
#define LARGE_SETTLE_STEPS 120
#define LARGE_N 30000
#define AFTER_DESTROY_STEPS 10
#define SETTLE_SPEED 0.05 /* m/s: ga2d's sleep threshold */
#define MAX_N 2000000     /* keeps the grid and the id array sane */

static const int DEFAULT_SIZES[] = {10000, 30000, 100000};
#define DEFAULT_SIZE_COUNT ((int)(sizeof DEFAULT_SIZES / sizeof DEFAULT_SIZES[0]))

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* ------------------------------------------------------ counting allocator */
typedef struct counter {
    size_t current, peak, largest; /* bytes live now, most ever, biggest block */
    long long allocs, frees;
    int bad_free; /* a free larger than what is live: the sizes disagree */
} counter;

static void *count_alloc(size_t size, void *ctx)
{
    counter *c = (counter *)ctx;
    void *p = malloc(size);
    if (!p) return NULL;
    c->current += size;
    if (c->current > c->peak) c->peak = c->current;
    if (size > c->largest) c->largest = size;
    c->allocs++;
    return p;
}

static void count_free(void *ptr, size_t size, void *ctx)
{
    counter *c = (counter *)ctx;
    if (size > c->current) c->bad_free = 1;
    c->current -= size > c->current ? c->current : size;
    c->frees++;
    free(ptr);
}

/* ------------------------------------------------------------------- a run */
typedef struct run_result {
    int n, steps, settled;
    int peak_step, max_pairs_step;   /* the settle step (1-based) that set each */
    size_t peak, end, after_destroy, after_compact, largest;
    int have_compact;
    long long allocs;
    ga2d_world_counters at_end, after_destroy_c;
    int max_pairs, max_touching;     /* the largest counts after any step */
    ga2d_world_counters at_peak;     /* after the step that set the peak */
    size_t leaked;                   /* bytes still live after world_destroy */
    int bad_free, failed;
    double seconds;
} run_result;

/* Whether the pile has settled: every body asleep, or none moving faster
   than the sleep threshold (a big island can take long to fall asleep as
   one, yet be still for any purpose of measuring memory). */
static int settled(const ga2d_world *w, const ga2d_body_id *ids, int n)
{
    int i;
    if (ga2d_world_get_counters(w).awake_body_count == 0) return 1;
    for (i = 0; i < n; ++i)
        if (ga2d_vec_length(ga2d_body_velocity(w, ids[i])) > (ga2d_real)SETTLE_SPEED) return 0;
    return 1;
}

static ga2d_body_id add_static_box(ga2d_world *w, double x, double y, double hx, double hy)
{
    ga2d_body_def bd = ga2d_default_body_def();
    bd.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    bd.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    return ga2d_body_create(w, &bd);
}

static int run(int n, run_result *r)
{
    const double pitch = 0.2, half = 0.1, lift = 0.3;
    const int cols = (int)ceil(sqrt((double)n) * 1.5), rows = (n + cols - 1) / cols;
    const double width = cols * pitch, height = rows * pitch + lift;
    counter c;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id *ids = (ga2d_body_id *)malloc((size_t)n * sizeof *ids);
    ga2d_body_def bd = ga2d_default_body_def();
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    const int max_steps = n > LARGE_N ? LARGE_SETTLE_STEPS : MAX_SETTLE_STEPS;
    double t0 = now_ms();
    int i, s;

    memset(r, 0, sizeof *r);
    memset(&c, 0, sizeof c);
    r->n = n;
    if (!ids) return 0;
    wd.allocator.alloc = count_alloc;
    wd.allocator.free = count_free;
    wd.allocator.ctx = &c;
    w = ga2d_world_create(&wd);
    if (!w) {
        free(ids);
        return 0;
    }

    /* Container: ground top at y = 0; walls a box-half clear of the grid
       so the boxes start free of them; both as tall as the grid. */
    if (ga2d_body_id_is_null(add_static_box(w, 0, -0.5, width / 2 + 1.5, 0.5)) ||
        ga2d_body_id_is_null(add_static_box(w, -(width / 2 + half + 0.5), height / 2, 0.5, height / 2 + 0.5)) ||
        ga2d_body_id_is_null(add_static_box(w, width / 2 + half + 0.5, height / 2, 0.5, height / 2 + 0.5)))
        r->failed = 1;

    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)half, (ga2d_real)half);
    for (i = 0; i < n && !r->failed; ++i) {
        const int col = i % cols, row = i / cols;
        bd.position = ga2d_vec_make((ga2d_real)(-width / 2 + half + col * pitch),
                                    (ga2d_real)(lift + half + row * pitch));
        ids[i] = ga2d_body_create(w, &bd);
        if (ga2d_body_id_is_null(ids[i])) r->failed = 1;
    }

    /* Settle.  The peak can only rise inside a step, so the counters read
       after the step that raised it are the nearest to the peak moment. */
    for (s = 0; s < max_steps && !r->failed; ++s) {
        const size_t before = c.peak;
        ga2d_world_counters k;
        if (ga2d_world_step(w, (ga2d_real)(1.0 / 60)) != GA2D_OK) r->failed = 1;
        k = ga2d_world_get_counters(w);
        if (c.peak > before || s == 0) {
            r->at_peak = k;
            r->peak_step = s + 1;
        }
        if (k.pair_count > r->max_pairs) {
            r->max_pairs = k.pair_count;
            r->max_pairs_step = s + 1;
        }
        if (k.touching_count > r->max_touching) r->max_touching = k.touching_count;
        r->steps = s + 1;
        if (settled(w, ids, n)) {
            r->settled = 1;
            break;
        }
    }
    r->end = c.current;
    r->at_end = ga2d_world_get_counters(w);

    /* Destroy all but each tenth body, then let the survivors fall. */
    for (i = 0; i < n && !r->failed; ++i)
        if (i % 10 != 0 && ga2d_body_destroy(w, ids[i]) != GA2D_OK) r->failed = 1;
    for (s = 0; s < AFTER_DESTROY_STEPS && !r->failed; ++s)
        if (ga2d_world_step(w, (ga2d_real)(1.0 / 60)) != GA2D_OK) r->failed = 1;
    r->after_destroy = c.current;
    r->after_destroy_c = ga2d_world_get_counters(w);
    /* compact builds its new pool before freeing the old: keep its own
       transient out of the peak, which is the scene's */
    r->peak = c.peak;

#if GA2D_VERSION_MINOR > 8 || (GA2D_VERSION_MINOR == 8 && GA2D_VERSION_PATCH >= 1)
    /* ga2d_world_compact came with 0.8.1: the guard lets this file build
       against an older header too, for before/after figures.  It gives
       back what the destroy left. */
    if (ga2d_world_compact(w) != GA2D_OK) r->failed = 1;
    r->have_compact = 1;
    r->after_compact = c.current;
#endif

    r->largest = c.largest;
    r->allocs = c.allocs;
    ga2d_world_destroy(w);
    r->leaked = c.current;
    r->bad_free = c.bad_free;
    free(ids);
    r->seconds = (now_ms() - t0) / 1e3;
    return !r->failed;
}

/* ------------------------------------------------------------------ report */
static double kb(size_t bytes) { return (double)bytes / 1024.0; }

static void print_row(const run_result *r)
{
    char compact[32];
    if (r->have_compact)
        snprintf(compact, sizeof compact, "%.0f", kb(r->after_compact));
    else
        snprintf(compact, sizeof compact, "n/a (0.%d)", GA2D_VERSION_MINOR);
    printf("| %7d | %9.0f | %9.1f | %6.2f | %6.2f | %9.0f | %s |\n", r->n, kb(r->peak), (double)r->peak / r->n,
           (double)r->at_end.pair_count / r->n, (double)r->at_end.touching_count / r->n, kb(r->after_destroy),
           compact);
}

static void print_detail(const run_result *r)
{
    printf("  N=%d: %d steps, %s (%d awake); %.1f s; peak at step %d, end %.0f KB; largest block %.0f KB; "
           "%lld allocations\n",
           r->n, r->steps, r->settled ? "settled" : "NOT settled", r->at_end.awake_body_count, r->seconds,
           r->peak_step, kb(r->end), kb(r->largest), r->allocs);
    printf("    pairs/touching: end %d/%d, most pairs %d (step %d), most touching %d, after the peak step %d/%d; "
           "after destroying 90%%: %d/%d of %d bodies\n",
           r->at_end.pair_count, r->at_end.touching_count, r->max_pairs, r->max_pairs_step, r->max_touching,
           r->at_peak.pair_count, r->at_peak.touching_count, r->after_destroy_c.pair_count,
           r->after_destroy_c.touching_count, r->after_destroy_c.body_count);
    if (r->failed) printf("    FAILED (a body, step or destroy was refused)\n");
    if (r->leaked || r->bad_free)
        printf("    %zu bytes not given back%s\n", r->leaked, r->bad_free ? ", sizes disagree" : "");
}

/* after_compact_bytes is left empty when the header has no compact. */
static void write_csv(FILE *csv, const run_result *r)
{
    char compact[32] = "";
    if (r->have_compact) snprintf(compact, sizeof compact, "%zu", r->after_compact);
    fprintf(csv, "%d,%d,%d,%d,%d,%d,%.2f,%zu,%.1f,%zu,%d,%d,%d,%d,%d,%d,%zu,%d,%d,%s,%zu,%lld,%zu,%d\n", r->n,
            r->steps, r->settled, r->at_end.awake_body_count, r->peak_step, r->max_pairs_step, r->seconds, r->peak,
            (double)r->peak / r->n, r->end, r->at_end.pair_count, r->at_end.touching_count, r->max_pairs,
            r->max_touching, r->at_peak.pair_count, r->at_peak.touching_count, r->after_destroy,
            r->after_destroy_c.pair_count, r->after_destroy_c.touching_count, compact, r->largest, r->allocs,
            r->leaked, r->failed);
}

int main(int argc, char **argv)
{
    FILE *csv = argc > 1 ? fopen(argv[1], "w") : NULL;
    int sizes[64], count = 0, i, bad = 0;
    double start = now_ms();
    run_result *res;

    if (argc > 1 && !csv) {
        fprintf(stderr, "bench_memory: cannot write %s\n", argv[1]);
        return 1;
    }
    for (i = 2; i < argc && count < 64; ++i) {
        char *end;
        long v = strtol(argv[i], &end, 10);
        if (*end || v < 1 || v > MAX_N) {
            fprintf(stderr, "bench_memory: bad size %s (1..%d)\n", argv[i], MAX_N);
            return 1;
        }
        sizes[count++] = (int)v;
    }
    if (count == 0)
        for (i = 0; i < DEFAULT_SIZE_COUNT; ++i) sizes[count++] = DEFAULT_SIZES[i];
    res = (run_result *)calloc((size_t)count, sizeof *res);
    if (!res) return 1;

    printf("bench_memory (ga2d %d.%d.%d, ga2d_real %s): boxes of 0.2 m piled in a container, defaults, dt = 1/60\n",
           GA2D_VERSION_MAJOR, GA2D_VERSION_MINOR, GA2D_VERSION_PATCH,
           sizeof(ga2d_real) == sizeof(double) ? "double" : "float");
    for (i = 0; i < count; ++i) {
        bad |= !run(sizes[i], &res[i]) || res[i].leaked || res[i].bad_free;
        print_detail(&res[i]);
        fflush(stdout);
    }

    printf("\n| bodies | peak KB | bytes/body at peak | pairs/body | touching/body | KB after destroying 90%% | "
           "KB after compact |\n");
    printf("|---:|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < count; ++i) print_row(&res[i]);
    printf("\npairs/body and touching/body at the end of settling; KB after destroying 90%% is %d steps later.\n",
           AFTER_DESTROY_STEPS);

    if (csv) {
        fprintf(csv, "bodies,steps,settled,awake_end,peak_step,pairs_max_step,seconds,peak_bytes,"
                     "peak_bytes_per_body,end_bytes,pairs_end,touching_end,pairs_max,touching_max,pairs_at_peak,"
                     "touching_at_peak,after_destroy_bytes,pairs_after_destroy,touching_after_destroy,"
                     "after_compact_bytes,largest_block_bytes,allocations,leaked_bytes,failed\n");
        for (i = 0; i < count; ++i) write_csv(csv, &res[i]);
        fclose(csv);
    }
    printf("bench_memory: %.1f s in all\n", (now_ms() - start) / 1e3);
    free(res);
    return bad;
}
