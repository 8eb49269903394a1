/* threads.c - a world stepped on a task system (examples/task_pool.h):
   a pyramid of base 40 (820 boxes) under 60 falling discs, stepped 300
   times with 1, 2 and 4 workers.  It prints each run's ms/step and the
   hash of every body's state at the end: the hashes are the same for
   every worker count (ga2d's results do not depend on its threads).

   Today the step hands its workers the narrowphase and the bodies' marks
   only; the solver's passes are still one chain on the calling thread,
   so more workers step no faster yet (the README's Limitations).  Run it
   from the repository root: ./build/examples/threads.  Exit status 0
   when every run was built and the hashes agree. */
#define _POSIX_C_SOURCE 200112L /* clock_gettime, pthreads */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#define TASK_POOL_IMPLEMENTATION
#include "task_pool.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define BASE 40
#define DISCS 60
#define STEPS 300

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e3 * (double)t.tv_sec + 1e-6 * (double)t.tv_nsec;
}

/* FNV-1a over every body's position, rotor and velocities. */
static unsigned long long hash_world(const ga2d_world *w, const ga2d_body_id *ids, int n)
{
    unsigned long long h = 14695981039346656037ull;
    int i;
    for (i = 0; i < n; ++i) {
        ga2d_real v[7];
        const unsigned char *p = (const unsigned char *)v;
        size_t k;
        ga2d_vec x = ga2d_body_position(w, ids[i]), u = ga2d_body_velocity(w, ids[i]);
        ga2d_rotor q = ga2d_body_rotor(w, ids[i]);
        v[0] = x.x, v[1] = x.y, v[2] = q.c, v[3] = q.s, v[4] = u.x, v[5] = u.y, v[6] = ga2d_body_angular_velocity(w, ids[i]);
        for (k = 0; k < sizeof v; ++k) h = (h ^ p[k]) * 1099511628211ull;
    }
    return h;
}

/* Builds and steps the scene with `workers` workers; 0 when it could not. */
static int run(int workers, double *ms, unsigned long long *hash)
{
    task_pool *pool = task_pool_create(workers);
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id *ids = (ga2d_body_id *)malloc(sizeof *ids * (1 + BASE * (BASE + 1) / 2 + DISCS));
    ga2d_world *w;
    int n = 0, row, i;
    double t = 0;
    if (!pool || !ids) return 0;
    wd.worker_count = task_pool_workers(pool);
    wd.enqueue_task = task_pool_enqueue;
    wd.finish_task = task_pool_finish;
    wd.user_task_context = pool;
    w = ga2d_world_create(&wd);
    if (!w) return 0;
    d.polygon = ga2d_polygon_box(50, 0.5f);
    d.position = ga2d_vec_make(0, -0.5f);
    ids[n++] = ga2d_body_create(w, &d);
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box(0.5f, 0.5f);
    for (row = 0; row < BASE; ++row)
        for (i = 0; i < BASE - row; ++i) {
            d.position = ga2d_vec_make((ga2d_real)(1.05 * (i - 0.5 * (BASE - row - 1))), (ga2d_real)(0.5 + row));
            ids[n++] = ga2d_body_create(w, &d);
        }
    d.polygon.count = 0;
    for (i = 0; i < DISCS; ++i) {
        ga2d_circle c;
        c.center = ga2d_vec_make(0, 0);
        c.radius = 0.3f;
        d.position = ga2d_vec_make((ga2d_real)(-9 + 0.3 * i), (ga2d_real)(BASE + 3 + i % 3));
        ids[n] = ga2d_body_create(w, &d);
        ga2d_shape_create_circle(w, ids[n++], &sd, &c);
    }
    for (i = 0; i < STEPS; ++i) {
        double t0 = now_ms();
        ga2d_world_step(w, 1.0f / 60);
        t += now_ms() - t0;
    }
    *ms = t / STEPS;
    *hash = hash_world(w, ids, n);
    ga2d_world_destroy(w);
    task_pool_destroy(pool);
    free(ids);
    return 1;
}

int main(void)
{
    static const int workers[3] = {1, 2, 4};
    unsigned long long first = 0;
    int k, same = 1;
    printf("pyramid of %d boxes under %d discs, %d steps\n", BASE * (BASE + 1) / 2, DISCS, STEPS);
    for (k = 0; k < 3; ++k) {
        double ms;
        unsigned long long h;
        if (!run(workers[k], &ms, &h)) {
            printf("could not build the world\n");
            return 1;
        }
        if (k == 0) first = h;
        same = same && h == first;
        printf("  %d worker%s  %7.3f ms/step  hash %016llx\n", workers[k], workers[k] == 1 ? " " : "s", ms, h);
    }
    printf("%s\n", same ? "the same bits with every worker count" : "the hashes DIFFER");
    return same ? 0 : 1;
}
