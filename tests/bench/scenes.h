/* scenes.h - the benchmark scenes, engine-neutral.

   Each scene is a plain list of boxes (static, kinematic or dynamic) that
   any engine can build: ga2d (tests/bench/bench_scenes.c, trade.c) and the
   peers (tests/bench/peers/) read the same list, so their figures compare.
   Layouts follow Box2D v3's benchmark scenes (its benchmark/ folder), with
   two changes for engines with one convex polygon per body: many_pyramids'
   ground segments are thin static boxes (half-height 0.05, top face where
   the segment was), and tumbler's hollow box is four kinematic walls that
   the driver turns about the pivot (bench_scene_kinematic_velocity gives
   each wall's velocity for its current position).

   Every scene has one accuracy figure, which every driver measures the
   same way (s.figure):
     BENCH_FIG_DRIFT        the probe body's distance from its start after
                            the run (the top box of a pyramid or stack), m;
     BENCH_FIG_MOMENTUM     |sum m v - P0| / |P0| at the end (smash: no
                            gravity, nothing static, so momentum is kept);
     BENCH_FIG_PENETRATION  the deepest contact penetration seen over the
                            run (tumbler), m.

   Header-only and C89-friendly, usable from C and C++:
     bench_scene s;
     if (bench_scene_make("large_pyramid", &s) == 0) { ... s.bodies[k] ... bench_scene_free(&s); } */
#ifndef GA2D_BENCH_SCENES_H
#define GA2D_BENCH_SCENES_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { BENCH_STATIC = 0, BENCH_KINEMATIC = 1, BENCH_DYNAMIC = 2 };
enum { BENCH_FIG_DRIFT = 0, BENCH_FIG_MOMENTUM = 1, BENCH_FIG_PENETRATION = 2 };

typedef struct bench_body {
    int type;         /* BENCH_STATIC / BENCH_KINEMATIC / BENCH_DYNAMIC */
    double x, y;      /* centre, m */
    double hx, hy;    /* half-extents, m */
    double vx, vy, w; /* initial velocity, m/s and rad/s */
    double density;   /* kg/m^2 (dynamic only) */
    double friction;  /* each body's own; pairs mix as sqrt(mu_a mu_b) */
    int asleep;       /* created asleep (smash's squares) */
} bench_body;

typedef struct bench_scene {
    const char *name;
    int steps;          /* steps the benchmark runs */
    double dt;          /* 1/60 */
    double gx, gy;      /* gravity */
    int sleep;          /* sleep on (smash) or off */
    int count;          /* bodies */
    bench_body *bodies; /* malloc'd */
    int figure;         /* BENCH_FIG_* */
    int probe;          /* BENCH_FIG_DRIFT: the body whose drift is measured */
    /* kinematic walls turn at pivot_w rad/s about (pivot_x, pivot_y) */
    double pivot_x, pivot_y, pivot_w;
} bench_scene;

/* ---------------------------------------------------------------- build */
static int bench__push(bench_scene *s, int cap, int type, double x, double y, double hx, double hy)
{
    bench_body *b;
    if (s->count >= cap) return -1;
    b = &s->bodies[s->count];
    memset(b, 0, sizeof *b);
    b->type = type;
    b->x = x;
    b->y = y;
    b->hx = hx;
    b->hy = hy;
    b->density = 1;
    b->friction = 0.6;
    return s->count++;
}

/* A pyramid of `base` boxes of half-extent a, its row i at
   y = (2i+1) a + base_y and box j (j = i..base-1) at
   x = (i+1) a + 2 (j-i) a + x0; returns the top box's index. */
static int bench__pyramid(bench_scene *s, int cap, int base, double a, double x0, double base_y)
{
    int i, j, top = -1;
    for (i = 0; i < base; ++i)
        for (j = i; j < base; ++j)
            top = bench__push(s, cap, BENCH_DYNAMIC, (i + 1) * a + 2 * (j - i) * a + x0, (2 * i + 1) * a + base_y, a, a);
    return top;
}

static void bench_scene_free(bench_scene *s)
{
    free(s->bodies);
    s->bodies = NULL;
    s->count = 0;
}

/* The velocity a kinematic wall at centre (x, y) needs to be where the
   rigid turn puts it one step later: the chord (R(w dt)(p - c) + c - p)/dt,
   not the tangent w (-dy, dx), which would let the walls spiral outwards
   (by 0.2 m over 750 steps).  Its angular velocity is pivot_w. */
static void bench_scene_kinematic_velocity(const bench_scene *s, double x, double y, double *vx, double *vy)
{
    double a = s->pivot_w * s->dt, c = cos(a), sn = sin(a), dx = x - s->pivot_x, dy = y - s->pivot_y;
    *vx = (c * dx - sn * dy - dx) / s->dt;
    *vy = (sn * dx + c * dy - dy) / s->dt;
}

/* Fills *s with the named scene; returns 0, or -1 for an unknown name or
   no memory.  Names: large_pyramid, many_pyramids, smash, tumbler,
   pyramid20, stack10. */
static int bench_scene_make(const char *name, bench_scene *s)
{
    int cap = 23000, i, j;
    memset(s, 0, sizeof *s);
    s->dt = 1.0 / 60;
    s->gy = -10;
    s->bodies = (bench_body *)malloc((size_t)cap * sizeof *s->bodies);
    if (!s->bodies) return -1;
    if (strcmp(name, "large_pyramid") == 0) {
        s->name = "large_pyramid";
        s->steps = 500;
        bench__push(s, cap, BENCH_STATIC, 0, -1, 100, 1);
        s->probe = bench__pyramid(s, cap, 100, 0.5, -50, 0);
    } else if (strcmp(name, "pyramid20") == 0) {
        s->name = "pyramid20";
        s->steps = 600;
        bench__push(s, cap, BENCH_STATIC, 0, -1, 100, 1);
        s->probe = bench__pyramid(s, cap, 20, 0.5, -10, 0);
    } else if (strcmp(name, "many_pyramids") == 0) {
        /* 20 rows of 20 base-10 pyramids; row r's ground top at y = 11 r,
           220 m wide; pyramid c's centre x = -110 + 11 c + 1 */
        s->name = "many_pyramids";
        s->steps = 200;
        for (i = 0; i < 20; ++i) bench__push(s, cap, BENCH_STATIC, 0, 11.0 * i - 0.05, 110, 0.05);
        for (i = 0; i < 20; ++i)
            for (j = 0; j < 20; ++j) {
                int top = bench__pyramid(s, cap, 10, 0.5, -110 + 11.0 * j + 1 - 0.5, 11.0 * i);
                if (i == 19 && j == 10) s->probe = top;
            }
    } else if (strcmp(name, "smash") == 0) {
        /* no gravity; an 8 m box of density 8 at (-20, 0) at 40 m/s into
           120 x 80 sleeping 0.4 m squares from x = 30 */
        int k;
        s->name = "smash";
        s->steps = 300;
        s->gy = 0;
        s->sleep = 1;
        s->figure = BENCH_FIG_MOMENTUM;
        k = bench__push(s, cap, BENCH_DYNAMIC, -20, 0, 4, 4);
        s->bodies[k].density = 8;
        s->bodies[k].vx = 40;
        s->probe = k;
        for (i = 0; i < 120; ++i)
            for (j = 0; j < 80; ++j) {
                k = bench__push(s, cap, BENCH_DYNAMIC, 30 + 0.4 * i, 0.4 * (j - 40), 0.2, 0.2);
                s->bodies[k].asleep = 1;
            }
    } else if (strcmp(name, "tumbler") == 0) {
        /* a 20 m hollow square of 0.5 m thick walls (half-thickness 0.5,
           as Box2D's) turning at 25 deg/s about (0, 10); 45 x 45 boxes of
           half-extent 0.125 on a 0.4 m grid inside */
        s->name = "tumbler";
        s->steps = 750;
        s->figure = BENCH_FIG_PENETRATION;
        s->pivot_x = 0;
        s->pivot_y = 10;
        s->pivot_w = 25 * 3.14159265358979323846 / 180;
        bench__push(s, cap, BENCH_KINEMATIC, 10, 10, 0.5, 10);
        bench__push(s, cap, BENCH_KINEMATIC, -10, 10, 0.5, 10);
        bench__push(s, cap, BENCH_KINEMATIC, 0, 20, 10, 0.5);
        bench__push(s, cap, BENCH_KINEMATIC, 0, 0, 10, 0.5);
        for (i = 0; i < 4; ++i) {
            s->bodies[i].w = s->pivot_w;
            bench_scene_kinematic_velocity(s, s->bodies[i].x, s->bodies[i].y, &s->bodies[i].vx, &s->bodies[i].vy);
        }
        for (i = 0; i < 45; ++i)
            for (j = 0; j < 45; ++j) bench__push(s, cap, BENCH_DYNAMIC, -0.2 * 45 + 0.4 * j, -0.2 * 45 + 10 + 0.4 * i, 0.125, 0.125);
        s->probe = s->count - 1;
    } else if (strcmp(name, "stack10") == 0) {
        s->name = "stack10";
        s->steps = 600;
        bench__push(s, cap, BENCH_STATIC, 0, -1, 100, 1);
        for (i = 0; i < 10; ++i) s->probe = bench__push(s, cap, BENCH_DYNAMIC, 0, 0.5 + i, 0.5, 0.5);
    } else {
        bench_scene_free(s);
        return -1;
    }
    return 0;
}

/* The accuracy figure's name, for tables. */
static const char *bench_scene_figure_name(const bench_scene *s)
{
    static const char *names[3] = {"top box drift (m)", "momentum error (rel.)", "deepest penetration (m)"};
    return names[s->figure];
}

#endif
