/* bench_overhead.c - what a step costs when there is almost nothing to do
   (issue 26: "a one-body world steps in under 1 us"; "a world with no
   joints, no continuous-fast bodies, no sensors pays nothing for them,
   and the counters prove it").

   Worlds, each stepped at dt = 1/60 with the defaults (4 substeps):
     empty        no body at all;
     one body     one dynamic box drifting at 1 m/s with gravity off (it
                  never sleeps, nothing stops it, and it is never fast
                  enough to be swept: every step integrates it);
     one resting  one box resting on a static ground box, sleep off (one
                  touching contact solved every step);
     one asleep   the same with sleep on, after it fell asleep.
   Per world: ns per step, median and minimum of BENCH_RUNS runs (default
   5) of 100 000 steps each (the first 1 000 untimed), and the counters
   after the last step that show which parts ran: contacts solved
   (constraint_count), joints solved, bodies swept by continuous
   collision, sensor tests and bodies integrated.  Joints, continuous
   collision and sensors must be 0 in all of them (the exit status says
   whether they were).

     bench_overhead [out.csv]

   writes the CSV when given a path (make bench passes one). */
#define _POSIX_C_SOURCE 199309L
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define STEPS 100000
#define WARM 1000
#define MAX_RUNS 64
#define DEFAULT_RUNS 5

enum { EMPTY, ONE_BODY, ONE_RESTING, ONE_ASLEEP, WORLD_COUNT };
static const char *const NAMES[WORLD_COUNT] = {"empty", "one body", "one resting", "one asleep"};

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e9 * (double)t.tv_sec + (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static ga2d_world *make_world(int kind)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_world *w;
    wd.enable_sleep = kind == ONE_ASLEEP;
    if (kind == ONE_BODY) wd.gravity = ga2d_vec_make(0, 0);
    w = ga2d_world_create(&wd);
    if (!w || kind == EMPTY) return w;
    if (kind != ONE_BODY) {
        d.polygon = ga2d_polygon_box(5, 0.5f);
        d.position = ga2d_vec_make(0, -0.5f);
        ga2d_body_create(w, &d);
    }
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box(0.5f, 0.5f);
    d.position = ga2d_vec_make(0, 0.5f);
    if (kind == ONE_BODY) d.velocity = ga2d_vec_make(1, 0);
    ga2d_body_create(w, &d);
    return w;
}

/* ns per step over one run; the world's counters after it in *out. */
static double run(int kind, ga2d_world_counters *out)
{
    ga2d_world *w = make_world(kind);
    double t0;
    int i;
    if (!w) return -1;
    for (i = 0; i < WARM; ++i) ga2d_world_step(w, 1.0f / 60);
    t0 = now_ns();
    for (i = 0; i < STEPS; ++i) ga2d_world_step(w, 1.0f / 60);
    t0 = (now_ns() - t0) / STEPS;
    *out = ga2d_world_get_counters(w);
    ga2d_world_destroy(w);
    return t0;
}

int main(int argc, char **argv)
{
    const char *env = getenv("BENCH_RUNS");
    int runs = env ? atoi(env) : DEFAULT_RUNS, kind, r, clean = 1;
    FILE *csv = argc > 1 ? fopen(argv[1], "w") : NULL;
    if (runs < 1) runs = 1;
    if (runs > MAX_RUNS) runs = MAX_RUNS;
    if (argc > 1 && !csv) {
        fprintf(stderr, "bench_overhead: cannot write %s\n", argv[1]);
        return 1;
    }
    printf("bench_overhead: ns per ga2d_world_step, %d runs of %d steps (defaults, dt = 1/60)\n", runs, STEPS);
    printf("%-12s %10s %10s %9s %7s %10s %7s %10s\n", "world", "median", "min", "contacts", "joints", "continuous", "sensor", "integrated");
    if (csv) fprintf(csv, "world,ns_median,ns_min,contacts_solved,joints_solved,continuous_bodies,sensor_tests,integrated_bodies\n");
    for (kind = 0; kind < WORLD_COUNT; ++kind) {
        double t[MAX_RUNS];
        ga2d_world_counters c;
        for (r = 0; r < runs; ++r) t[r] = run(kind, &c);
        qsort(t, (size_t)runs, sizeof t[0], cmp_double);
        printf("%-12s %10.1f %10.1f %9d %7d %10d %7d %10d\n", NAMES[kind], t[runs / 2], t[0], c.constraint_count, c.joints_solved,
               c.continuous_bodies, c.sensor_tests, c.integrated_bodies);
        if (csv)
            fprintf(csv, "%s,%.1f,%.1f,%d,%d,%d,%d,%d\n", NAMES[kind], t[runs / 2], t[0], c.constraint_count, c.joints_solved,
                    c.continuous_bodies, c.sensor_tests, c.integrated_bodies);
        clean = clean && t[0] >= 0 && c.joints_solved == 0 && c.continuous_bodies == 0 && c.sensor_tests == 0;
    }
    if (csv) fclose(csv);
    printf("%s\n", clean ? "no joint, sweep or sensor test in any of them" : "a part the worlds do not use RAN");
    return clean ? 0 : 1;
}
