/* bench_solver.c - what each solver knob costs and buys.

   A 10-box stack and a pyramid of base 20 (210 boxes, laid out as Box2D's
   benchmark) stand for 10 s at dt = 1/60 with sleep off; for each setting
   it prints how far the top box moved and the median ms per step over 5
   runs (first 10 steps excluded).  Single-machine times: compare the rows
   with each other.  Writes a CSV to argv[1] when given. */
#define _POSIX_C_SOURCE 199309L
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define RUNS 5

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One run: the scene under `wd`; returns ms per step, *moved the top box's
   displacement over 10 s. */
static double run(ga2d_world_def wd, int pyramid, double *moved)
{
    ga2d_world *w;
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id top = ga2d_body_id_null();
    ga2d_vec start;
    double t0;
    int i, j;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    d.polygon = ga2d_polygon_box(100, 1);
    d.position = ga2d_vec_make(0, -1);
    ga2d_body_create(w, &d);
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box(0.5f, 0.5f);
    if (pyramid) {
        for (i = 0; i < 20; ++i)
            for (j = i; j < 20; ++j) {
                d.position = ga2d_vec_make((ga2d_real)((i + 1) * 0.5 + (j - i) * 1.0 - 10), (ga2d_real)((2 * i + 1) * 0.5));
                top = ga2d_body_create(w, &d);
            }
    } else {
        for (i = 0; i < 10; ++i) {
            d.position = ga2d_vec_make(0, (ga2d_real)(0.5 + i));
            top = ga2d_body_create(w, &d);
        }
    }
    start = ga2d_body_position(w, top);
    for (i = 0; i < 10; ++i) ga2d_world_step(w, 1.0f / 60);
    t0 = now_ms();
    for (i = 10; i < 600; ++i) ga2d_world_step(w, 1.0f / 60);
    t0 = (now_ms() - t0) / 590;
    *moved = (double)ga2d_vec_length(ga2d_vec_sub(ga2d_body_position(w, top), start));
    ga2d_world_destroy(w);
    return t0;
}

int main(int argc, char **argv)
{
    static const char *names[] = {
        "soft step, 4 substeps, 45 Hz (default)", "soft step, 8 substeps, 45 Hz", "accurate: 8 substeps, 90 Hz",
        "PGS + Baumgarte, 1 step x 8 iterations", "PGS + NGS, 1 step x (8 + 3) iterations",
        "PGS + Baumgarte, 4 substeps x 8 iterations", "PGS + NGS, 4 substeps x (8 + 3) iterations"};
    FILE *csv = argc > 1 ? fopen(argv[1], "w") : NULL;
    int k, scene, r;
    printf("bench_solver (ga2d_real %s): top box moved in 10 s, median ms/step of %d runs\n",
           sizeof(ga2d_real) == sizeof(double) ? "double" : "float", RUNS);
    printf("%-44s | %-20s | %-20s\n", "setting", "stack10", "pyramid20");
    if (csv) fprintf(csv, "setting,scene,moved_m,ms_per_step\n");
    for (k = 0; k < 7; ++k) {
        ga2d_world_def wd = k == 2 ? ga2d_accurate_world_def() : ga2d_default_world_def();
        if (k == 1) wd.substeps = 8;
        if (k >= 3) {
            wd.solver = (k == 3 || k == 5) ? GA2D_SOLVER_PGS_BAUMGARTE : GA2D_SOLVER_PGS_NGS;
            wd.substeps = k < 5 ? 1 : 4;
        }
        printf("%-44s", names[k]);
        for (scene = 0; scene < 2; ++scene) {
            double t[RUNS], moved = 0;
            for (r = 0; r < RUNS; ++r) t[r] = run(wd, scene, &moved);
            qsort(t, RUNS, sizeof t[0], cmp_double);
            printf(" | %6.2f cm %6.3f ms", moved * 100, t[RUNS / 2]);
            if (csv) fprintf(csv, "\"%s\",%s,%.6f,%.6f\n", names[k], scene ? "pyramid20" : "stack10", moved, t[RUNS / 2]);
        }
        printf("\n");
    }
    if (csv) fclose(csv);
    return 0;
}
