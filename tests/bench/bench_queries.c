/* bench_queries.c - world queries and continuous collision (a benchmark,
   not a test; issue 25's performance figures).

   Queries: a world of 10 000 bodies of one shape each (a quarter each
   circles, capsules, boxes and rounded pentagons, 0.2-0.6 m; one per
   2 m x 2 m cell of a 200 m square, jittered; 10 % static, the rest
   dynamic and still, gravity 0), asked:
     - rays of 20 m and of 200 m (across the world) from random points in
       random directions: the closest hit (ga2d_world_cast_ray_closest) and
       every hit (ga2d_world_cast_ray, a callback that returns 1);
     - boxes of 4 m x 4 m and 20 m x 20 m (ga2d_world_overlap_aabb).
   Each kind: QUERIES of them per run, BENCH_RUNS runs (default 5), the
   median and the best of queries per second, and per query the tree
   nodes and shapes visited (counters.query_nodes, query_shapes) and the
   hits found.  One check first: every closest hit is the least fraction
   of the all-hits answer.

   Continuous collision's cost:
     - large_pyramid (scenes.h, 500 steps): a world with continuous on and
       one with it off, stepped in turn step by step (so a slow spell of
       the machine hits both), each step timed; per round the mean ms per
       step of each; the median over BENCH_RUNS rounds, the on / off ratio,
       the most continuous_bodies any step counted (nothing is fast: 0),
       and whether the two worlds ended the same bits;
     - 1 000 bullets at 300 m/s into a 0.1 m static wall: circles 0.1 m
       across (is_bullet) in 10 columns 0.5 m apart and 100 rows 1 m
       apart, starting 15-19.5 m from the wall, gravity 0, 40 steps, the
       same two worlds in turn: ms per step, bullets through the wall at
       the end, swept bodies and hits per step.

   Build and run: make bench (or make build/bench/bench_queries &&
   ./build/bench/bench_queries [out.csv]).                                  */
#define _POSIX_C_SOURCE 199309L
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "scenes.h"
#include "scene_run.h"

#define QB_BODIES 10000
#define QB_SIDE 200.0 /* m: 100 x 100 cells of 2 m */
#define QB_QUERIES 20000
#define QB_MAX_RUNS 64
#define QB_BULLETS 1000
#define QB_BULLET_SPEED 300.0
#define QB_BULLET_STEPS 40

static double qb_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* xorshift64*: the same world and queries every run */
static uint64_t g_rng = 0x9E3779B97F4A7C15ull;
static double qb_rand(void)
{
    g_rng ^= g_rng >> 12;
    g_rng ^= g_rng << 25;
    g_rng ^= g_rng >> 27;
    return (double)((g_rng * 0x2545F4914F6CDD1Dull) >> 11) * (1.0 / 9007199254740992.0);
}
static double qb_range(double lo, double hi) { return lo + (hi - lo) * qb_rand(); }
static ga2d_vec qb_vec(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }

/* ------------------------------------------------------------ the world */
static ga2d_world *qb_query_world(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_world *w;
    int i;
    wd.gravity = qb_vec(0, 0);
    w = ga2d_world_create(&wd);
    if (!w) return NULL;
    for (i = 0; i < QB_BODIES; ++i) {
        ga2d_body_def bd = ga2d_default_body_def();
        ga2d_body_id id;
        double s = qb_range(0.2, 0.6);
        int cx = i % 100, cy = i / 100;
        bd.type = i % 10 == 0 ? GA2D_BODY_STATIC : GA2D_BODY_DYNAMIC;
        bd.position = qb_vec(-QB_SIDE / 2 + 2 * cx + 1 + qb_range(-0.3, 0.3), -QB_SIDE / 2 + 2 * cy + 1 + qb_range(-0.3, 0.3));
        bd.rotor = ga2d_rotor_from_angle((ga2d_real)qb_range(0, 2 * SR_PI));
        id = ga2d_body_create(w, &bd);
        switch (i % 4) {
        case 0: {
            ga2d_circle c;
            c.center = qb_vec(0, 0);
            c.radius = (ga2d_real)s;
            ga2d_shape_create_circle(w, id, &sd, &c);
            break;
        }
        case 1: {
            ga2d_capsule c;
            c.center1 = qb_vec(-s / 2, 0);
            c.center2 = qb_vec(s / 2, 0);
            c.radius = (ga2d_real)(s / 3);
            ga2d_shape_create_capsule(w, id, &sd, &c);
            break;
        }
        case 2: {
            ga2d_polygon p = ga2d_polygon_box((ga2d_real)s, (ga2d_real)(s * 0.7));
            ga2d_shape_create_polygon(w, id, &sd, &p);
            break;
        }
        default: {
            ga2d_polygon p = ga2d_polygon_regular(5, (ga2d_real)(s * 0.9));
            p.radius = (ga2d_real)(s * 0.1);
            ga2d_shape_create_polygon(w, id, &sd, &p);
            break;
        }
        }
    }
    /* two steps: the trees as a running game has them */
    ga2d_world_step(w, (ga2d_real)(1.0 / 60));
    ga2d_world_step(w, (ga2d_real)(1.0 / 60));
    return w;
}

/* ---------------------------------------------------------- the queries */
typedef struct qb_count { long hits; long nodes, shapes; } qb_count;

static ga2d_real qb_all_hits(ga2d_shape_id s, ga2d_vec p, ga2d_vec n, ga2d_real f, void *ctx)
{
    (void)s;
    (void)p;
    (void)n;
    (void)f;
    ++((qb_count *)ctx)->hits;
    return 1;
}

static ga2d_real qb_least(ga2d_shape_id s, ga2d_vec p, ga2d_vec n, ga2d_real f, void *ctx)
{
    ga2d_real *least = (ga2d_real *)ctx;
    (void)s;
    (void)p;
    (void)n;
    if (f < *least) *least = f;
    return 1;
}

static int qb_box_found(ga2d_shape_id s, void *ctx)
{
    (void)s;
    ++((qb_count *)ctx)->hits;
    return 1;
}

enum { QB_RAY_CLOSEST, QB_RAY_ALL, QB_BOX };

/* One run of n queries of one kind over the prepared inputs; seconds. */
static double qb_run(ga2d_world *w, int kind, const ga2d_vec *a, const ga2d_vec *b, int n, qb_count *c)
{
    ga2d_filter f = ga2d_default_filter();
    double t0 = qb_now();
    int i;
    memset(c, 0, sizeof *c);
    for (i = 0; i < n; ++i) {
        ga2d_world_counters k;
        if (kind == QB_RAY_CLOSEST) {
            c->hits += ga2d_world_cast_ray_closest(w, a[i], b[i], f).hit;
        } else if (kind == QB_RAY_ALL) {
            ga2d_world_cast_ray(w, a[i], b[i], f, qb_all_hits, c);
        } else {
            ga2d_aabb box;
            box.lower = a[i];
            box.upper = b[i];
            ga2d_world_overlap_aabb(w, box, f, qb_box_found, c);
        }
        k = ga2d_world_get_counters(w);
        c->nodes += k.query_nodes;
        c->shapes += k.query_shapes;
    }
    return qb_now() - t0;
}

static void qb_queries(ga2d_world *w, int runs, FILE *csv)
{
    static const char *const names[6] = {"ray 20 m, closest", "ray 20 m, all hits", "ray 200 m, closest",
                                         "ray 200 m, all hits", "box 4 m x 4 m", "box 20 m x 20 m"};
    ga2d_vec *a = (ga2d_vec *)malloc(QB_QUERIES * sizeof *a), *b = (ga2d_vec *)malloc(QB_QUERIES * sizeof *b);
    int q, i, r, bad = 0;
    if (!a || !b) return;
    printf("queries: %d bodies of one shape each, %d queries per run, %d runs\n", ga2d_world_get_counters(w).body_count,
           QB_QUERIES, runs);
    printf("  %-22s %14s %14s %10s %10s %10s\n", "query", "per s, median", "(best)", "nodes", "shapes", "found");
    for (q = 0; q < 6; ++q) {
        double rate[QB_MAX_RUNS];
        qb_count c;
        int kind = q < 4 ? (q % 2 ? QB_RAY_ALL : QB_RAY_CLOSEST) : QB_BOX;
        double len = q < 2 ? 20 : q < 4 ? QB_SIDE : q == 4 ? 4 : 20;
        g_rng = 0x9E3779B97F4A7C15ull + (uint64_t)q;
        for (i = 0; i < QB_QUERIES; ++i) {
            a[i] = qb_vec(qb_range(-QB_SIDE / 2, QB_SIDE / 2), qb_range(-QB_SIDE / 2, QB_SIDE / 2));
            if (kind == QB_BOX) {
                b[i] = ga2d_vec_add(a[i], qb_vec(len, len));
            } else {
                double t = qb_range(0, 2 * SR_PI);
                b[i] = qb_vec(len * cos(t), len * sin(t));
            }
        }
        if (kind == QB_RAY_CLOSEST) {
            /* the closest hit is the least of every hit (checked, not timed) */
            for (i = 0; i < 200; ++i) {
                ga2d_real least = 2;
                ga2d_ray_result h = ga2d_world_cast_ray_closest(w, a[i], b[i], ga2d_default_filter());
                ga2d_world_cast_ray(w, a[i], b[i], ga2d_default_filter(), qb_least, &least);
                bad += h.hit ? h.fraction != least : least != 2;
            }
        }
        for (r = 0; r < runs; ++r) rate[r] = QB_QUERIES / qb_run(w, kind, a, b, QB_QUERIES, &c);
        {
            double best = rate[0];
            for (r = 1; r < runs; ++r) best = rate[r] > best ? rate[r] : best;
            printf("  %-22s %14.0f %14.0f %10.1f %10.1f %10.2f\n", names[q], sr_median(rate, runs), best,
                   (double)c.nodes / QB_QUERIES, (double)c.shapes / QB_QUERIES, (double)c.hits / QB_QUERIES);
            if (csv)
                fprintf(csv, "query,%s,%.0f,%.0f,%.2f,%.2f,%.3f\n", names[q], sr_median(rate, runs), best,
                        (double)c.nodes / QB_QUERIES, (double)c.shapes / QB_QUERIES, (double)c.hits / QB_QUERIES);
        }
    }
    printf("  closest hit = least of all hits: %s (200 rays of each length)\n", bad ? "NO" : "yes");
    free(a);
    free(b);
}

/* ------------------------------------------------------------ continuous */
/* Two worlds built alike, one with continuous on and one off, stepped in
   turn; per world the mean ms per step of the round. */
typedef struct qb_pair { ga2d_world *w[2]; double ms[2]; int max_swept, swept_sum, hits_sum; } qb_pair;

static void qb_step_pair(qb_pair *p, int steps, double dt)
{
    int k, j;
    double total[2] = {0, 0};
    p->max_swept = p->swept_sum = p->hits_sum = 0;
    for (k = 0; k < steps; ++k)
        for (j = 0; j < 2; ++j) {
            int which = (k + j) % 2; /* the order swapped every step */
            double t0 = qb_now();
            ga2d_world_step(p->w[which], (ga2d_real)dt);
            total[which] += qb_now() - t0;
            if (which == 0) {
                ga2d_world_counters c = ga2d_world_get_counters(p->w[0]);
                if (c.continuous_bodies > p->max_swept) p->max_swept = c.continuous_bodies;
                p->swept_sum += c.continuous_bodies;
                p->hits_sum += c.continuous_hits;
            }
        }
    for (j = 0; j < 2; ++j) p->ms[j] = 1e3 * total[j] / steps;
}

/* Whether the two worlds hold the same bits (their snapshots, less the
   continuous switch itself: compared body by body). */
static int qb_same_bodies(ga2d_world *a, ga2d_world *b)
{
    int n = ga2d_world_get_bodies(a, NULL, 0), i, same = n == ga2d_world_get_bodies(b, NULL, 0);
    ga2d_body_id *ia = (ga2d_body_id *)malloc((size_t)(n + 1) * sizeof *ia), *ib = (ga2d_body_id *)malloc((size_t)(n + 1) * sizeof *ib);
    if (!ia || !ib) same = 0;
    if (same) {
        ga2d_world_get_bodies(a, ia, n);
        ga2d_world_get_bodies(b, ib, n);
        for (i = 0; i < n && same; ++i) {
            ga2d_vec pa = ga2d_body_position(a, ia[i]), pb = ga2d_body_position(b, ib[i]);
            ga2d_vec va = ga2d_body_velocity(a, ia[i]), vb = ga2d_body_velocity(b, ib[i]);
            ga2d_rotor qa = ga2d_body_rotor(a, ia[i]), qb = ga2d_body_rotor(b, ib[i]);
            same = memcmp(&pa, &pb, sizeof pa) == 0 && memcmp(&va, &vb, sizeof va) == 0 && memcmp(&qa, &qb, sizeof qa) == 0;
        }
    }
    free(ia);
    free(ib);
    return same;
}

static void qb_pyramid(int runs, FILE *csv)
{
    bench_scene s;
    double on[QB_MAX_RUNS], off[QB_MAX_RUNS], ratio[QB_MAX_RUNS];
    int r, i, j, max_swept = 0, same = 1;
    if (bench_scene_make("large_pyramid", &s) != 0) return;
    for (r = 0; r < runs; ++r) {
        qb_pair p;
        for (j = 0; j < 2; ++j) {
            ga2d_world_def wd = sr_scene_def(&s, ga2d_default_world_def());
            wd.enable_continuous = j == 0;
            p.w[j] = ga2d_world_create(&wd);
            for (i = 0; i < s.count; ++i) sr__make_body(p.w[j], &s, i, 0);
        }
        qb_step_pair(&p, s.steps, s.dt);
        on[r] = p.ms[0];
        off[r] = p.ms[1];
        ratio[r] = on[r] / off[r];
        if (p.max_swept > max_swept) max_swept = p.max_swept;
        same &= qb_same_bodies(p.w[0], p.w[1]);
        for (j = 0; j < 2; ++j) ga2d_world_destroy(p.w[j]);
    }
    printf("continuous on large_pyramid (%d bodies, %d steps, %d rounds, the two worlds stepped in turn):\n", s.count, s.steps,
           runs);
    {
        double lo = ratio[0], hi = ratio[0];
        for (r = 1; r < runs; ++r) {
            lo = ratio[r] < lo ? ratio[r] : lo;
            hi = ratio[r] > hi ? ratio[r] : hi;
        }
        printf("  ms/step on %.3f, off %.3f (medians); on / off %.3f (median of the rounds' ratios; range %.3f-%.3f)\n",
               sr_median(on, runs), sr_median(off, runs), sr_median(ratio, runs), lo, hi);
    }
    printf("  continuous_bodies: at most %d in any step; on and off end the same bits: %s\n", max_swept, same ? "yes" : "NO");
    if (csv) fprintf(csv, "continuous,large_pyramid,%.4f,%.4f,%.4f,%d,%d\n", sr_median(on, runs), sr_median(off, runs),
                     sr_median(ratio, runs), max_swept, same);
    bench_scene_free(&s);
}

static ga2d_world *qb_bullet_world(int continuous, int segment)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_world *w;
    ga2d_circle c;
    int i;
    wd.gravity = qb_vec(0, 0);
    wd.enable_continuous = continuous;
    w = ga2d_world_create(&wd);
    if (segment) {
        /* the wall: a segment 120 m tall at x = 0, its front (left of
           point1 -> point2) facing the bullets */
        ga2d_segment g;
        ga2d_body_id wall = ga2d_body_create(w, &bd);
        g.point1 = qb_vec(0, 60);
        g.point2 = qb_vec(0, -60);
        ga2d_shape_create_segment(w, wall, &sd, &g);
    } else {
        bd.polygon = ga2d_polygon_box((ga2d_real)0.05, 60); /* the wall: 0.1 m thick, 120 m tall, at x = 0 */
        ga2d_body_create(w, &bd);
    }
    bd = ga2d_default_body_def();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.is_bullet = 1;
    bd.velocity = qb_vec(QB_BULLET_SPEED, 0);
    c.center = qb_vec(0, 0);
    c.radius = (ga2d_real)0.05;
    for (i = 0; i < QB_BULLETS; ++i) {
        ga2d_body_id id;
        bd.position = qb_vec(-15 - 0.5 * (i % 10), -49.5 + (i / 10));
        id = ga2d_body_create(w, &bd);
        ga2d_shape_create_circle(w, id, &sd, &c);
    }
    return w;
}

static int qb_through(ga2d_world *w)
{
    ga2d_body_id ids[QB_BULLETS + 1];
    int n = ga2d_world_get_bodies(w, ids, QB_BULLETS + 1), i, through = 0;
    for (i = 0; i < n && i <= QB_BULLETS; ++i)
        if (ga2d_body_get_type(w, ids[i]) == GA2D_BODY_DYNAMIC && ga2d_body_position(w, ids[i]).x > 0) ++through;
    return through;
}

static void qb_bullets(int runs, int segment, FILE *csv)
{
    double on[QB_MAX_RUNS], off[QB_MAX_RUNS], ratio[QB_MAX_RUNS];
    int r, j, through[2] = {0, 0}, swept = 0, hits = 0;
    for (r = 0; r < runs; ++r) {
        qb_pair p;
        for (j = 0; j < 2; ++j) p.w[j] = qb_bullet_world(j == 0, segment);
        qb_step_pair(&p, QB_BULLET_STEPS, 1.0 / 60);
        on[r] = p.ms[0];
        off[r] = p.ms[1];
        ratio[r] = on[r] / off[r];
        for (j = 0; j < 2; ++j) {
            through[j] = qb_through(p.w[j]);
            ga2d_world_destroy(p.w[j]);
        }
        swept = p.swept_sum;
        hits = p.hits_sum;
    }
    printf("continuous with %d bullets at %.0f m/s into %s (%d steps, %d rounds, stepped in turn):\n", QB_BULLETS,
           QB_BULLET_SPEED, segment ? "a segment wall" : "a 0.1 m box wall", QB_BULLET_STEPS, runs);
    printf("  ms/step on %.3f, off %.3f (medians); on / off %.2f (median of the rounds' ratios)\n", sr_median(on, runs),
           sr_median(off, runs), sr_median(ratio, runs));
    printf("  through the wall at the end: on %d, off %d of %d; swept %.1f and stopped %.1f bodies per step (on)\n", through[0],
           through[1], QB_BULLETS, (double)swept / QB_BULLET_STEPS, (double)hits / QB_BULLET_STEPS);
    if (csv) fprintf(csv, "continuous,%s,%.4f,%.4f,%.4f,%d,%d\n",
                     segment ? "bullets_segment_wall" : "bullets_box_wall", sr_median(on, runs), sr_median(off, runs),
                     sr_median(ratio, runs), through[0], through[1]);
}

int main(int argc, char **argv)
{
    int runs = sr_runs_from_env("BENCH_RUNS", 5);
    FILE *csv = argc > 1 ? fopen(argv[1], "w") : NULL;
    ga2d_world *w;
    (void)bench_scene_figure_name; /* scenes.h's, for the scene tables */
    if (runs > QB_MAX_RUNS) runs = QB_MAX_RUNS;
    if (csv) fprintf(csv, "part,name,a,b,c,d,e\n");
    w = qb_query_world();
    if (!w) return 1;
    qb_queries(w, runs, csv);
    ga2d_world_destroy(w);
    qb_pyramid(runs, csv);
    qb_bullets(runs, 0, csv);
    qb_bullets(runs, 1, csv);
    if (csv) fclose(csv);
    return 0;
}
