/* scenes.h - the benchmark scenes, engine-neutral.

   Each scene is a plain list of bodies (static, kinematic or dynamic) that
   any engine can build: ga2d (tests/bench/bench_scenes.c, trade.c) and the
   peers (tests/bench/peers/) read the same list, so their figures compare.
   Layouts follow Box2D v3's benchmark scenes (its benchmark/ folder and
   shared/benchmarks.c), with two changes for engines with one convex
   polygon per body: many_pyramids' ground segments are thin static boxes
   (half-height 0.05, top face where the segment was), and tumbler's hollow
   box is four kinematic walls that the driver turns about the pivot
   (bench_scene_kinematic_velocity gives each wall's velocity for its
   current position).

   A body is a box (hx, hy) unless it lists shapes of its own (shape_count
   > 0: circles, capsules, convex polygons with an optional rounding, in
   the body's frame; s.shapes), or has neither (hx = hy = 0: a chain's
   body).  The first six scenes are boxes only; the peer runner builds
   those, mixed_bin, joint_grid (bodies of one circle) and spinner.
     mixed_bin   100 circles, capsules, boxes and rounded polygons
                 dropped together into a 10 m wide bin (test_settle's
                 pile, all there from the start): a small mixed scene.
   Two scenes use the shapes, and bodies that come and go: a body is made just before step `birth` and, when
   `death` > 0, destroyed just before step `death`.  Bodies are listed in
   order of birth, so a driver walks them with one cursor:
     rain        Box2D v3's rain: five floors of 0.5 m ground boxes, and
                 groups of five humans (11 capsule bones each, the feet
                 rounded polygons) raining on them every 8 steps, the
                 oldest groups recycled once 40 columns stand;
     mixed_pile  5 000 circles, capsules, boxes and rounded polygons
                 poured in waves into a 50 m wide open box.

   A scene may also list joints (s.joints): revolute joints (pins), each
   between two of its bodies at a local anchor on each, made with the
   world after the bodies, in list order; no limit or spring, a motor
   where it says so, and the joined bodies do not collide.  Two scenes
   have them:
     joint_grid  Box2D v3's joint grid: 100 x 100 circles, each pinned to
                 its neighbour above and to its left, hanging from seven
                 static bodies in the middle of the top row;
     spinner     Box2D v3's spinner: a bar turned by a motor inside a
                 static loop of segments (s.chain_*), stirring 6 076
                 capsules, circles and boxes.

   Every scene has one accuracy figure, which every driver measures the
   same way (s.figure):
     BENCH_FIG_DRIFT        the probe body's distance from its start after
                            the run (the top box of a pyramid or stack), m;
     BENCH_FIG_MOMENTUM     |sum m v - P0| / |P0| at the end (smash: no
                            gravity, nothing static, so momentum is kept);
     BENCH_FIG_PENETRATION  the deepest contact penetration seen over the
                            run (tumbler, mixed_pile), m;
     BENCH_FIG_THROUGH      the bodies found through their floor (bounded:
                            centre below lo_y while between lo_x and hi_x)
                            when they are destroyed or at the end of the
                            run (rain; a bone that rolled off a floor's end
                            falls past them all, and is not counted);
     BENCH_FIG_SAG          how far the probe body ends below where it
                            started (start y - end y; joint_grid's bottom
                            corner), m;
     BENCH_FIG_LAG          how far the probe body's turn over the run
                            falls short of its motor's: the first
                            joint's motor_speed times the run's time
                            (steps dt) less the turn, the sum of each
                            step's change of angle wrapped into
                            (-pi, pi] (a step turns it far less), rad;
                            positive: behind (spinner's bar).
   A scene with joints also has their worst separation: the largest
   distance between a joint's two anchors in the world at the end of the
   run (bench_scene_joint_gap, from each engine's poses).

   Header-only and C89-friendly, usable from C and C++:
     bench_scene s;
     if (bench_scene_make("large_pyramid", &s) == 0) { ... s.bodies[k] ... bench_scene_free(&s); } */
#ifndef GA2D_BENCH_SCENES_H
#define GA2D_BENCH_SCENES_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { BENCH_STATIC = 0, BENCH_KINEMATIC = 1, BENCH_DYNAMIC = 2 };
enum { BENCH_FIG_DRIFT = 0, BENCH_FIG_MOMENTUM = 1, BENCH_FIG_PENETRATION = 2, BENCH_FIG_THROUGH = 3, BENCH_FIG_SAG = 4,
       BENCH_FIG_LAG = 5 };
enum { BENCH_SHAPE_CIRCLE = 1, BENCH_SHAPE_CAPSULE = 2, BENCH_SHAPE_POLYGON = 3 };
#define BENCH_MAX_VERTICES 8

/* One shape of a body, in the body's frame. */
typedef struct bench_shape {
    int kind;                      /* BENCH_SHAPE_* */
    double x1, y1, x2, y2;         /* circle: centre (x1, y1); capsule: its two centres */
    double radius;                 /* circle, capsule; polygon: its rounding (0: sharp) */
    int count;                     /* polygon: vertices, counter-clockwise */
    double px[BENCH_MAX_VERTICES], py[BENCH_MAX_VERTICES];
    double density, friction;
    double restitution;            /* 0 but in spinner; pairs mix as the larger */
    int group;                     /* filter, as Box2D's: a negative group never */
    unsigned category, mask;       /* collides with itself; else category & mask */
} bench_shape;

typedef struct bench_body {
    int type;         /* BENCH_STATIC / BENCH_KINEMATIC / BENCH_DYNAMIC */
    double x, y;      /* centre (a box) or origin (a body with shapes), m */
    double angle;     /* rad */
    double hx, hy;    /* a box's half-extents, m (shape_count 0) */
    double vx, vy, w; /* initial velocity, m/s and rad/s */
    double density;   /* kg/m^2 (a dynamic box only) */
    double friction;  /* a box's own; pairs mix as sqrt(mu_a mu_b) */
    double linear_damping; /* 1/s */
    int asleep;       /* created asleep (smash's squares) */
    int never_sleeps; /* this body may not sleep (spinner's bar; where the engine has the switch) */
    int shape_first, shape_count; /* its shapes in s.shapes; count 0: the box hx, hy */
    int birth;        /* made just before this step (0: with the world) */
    int death;        /* destroyed just before this step; 0: never */
    int bounded;      /* BENCH_FIG_THROUGH: counts if its centre ends */
    double lo_x, hi_x, lo_y; /* below lo_y, between lo_x and hi_x */
} bench_body;

/* A revolute joint: bodies a and b (indices into s.bodies, both made with
   the world), pinned where anchor (ax, ay) of a's frame meets anchor
   (bx, by) of b's. */
typedef struct bench_joint {
    int a, b;
    double ax, ay, bx, by;
    int motor;                      /* a motor drives b's turn relative to a's */
    double motor_speed;             /* toward this, rad/s (counter-clockwise) */
    double max_motor_torque;        /* with at most this, N m */
} bench_joint;

typedef struct bench_scene {
    const char *name;
    int steps;          /* steps the benchmark runs */
    double dt;          /* 1/60 */
    double gx, gy;      /* gravity */
    int sleep;          /* sleep on (smash, rain) or off */
    int count;          /* bodies, over the whole run */
    bench_body *bodies; /* malloc'd, in order of birth */
    int shape_count;    /* shapes of the bodies that list their own */
    bench_shape *shapes;
    int joint_count;    /* joints, made after the bodies (0: none) */
    bench_joint *joints;
    int peak;           /* the most bodies alive at once (count, if none come or go) */
    int figure;         /* BENCH_FIG_* */
    int probe;          /* BENCH_FIG_DRIFT, _SAG, _LAG: the body measured */
    /* a closed loop of one-sided segments on body chain_body (a static
       body with no shape of its own: hx = hy = 0, shape_count 0), its
       points (chain_x[i], chain_y[i]) in the body's frame wound as Box2D
       winds them: clockwise, solid to the right of each segment, so it
       holds bodies inside (an engine whose segments push to their left
       walks the points backwards); chain_count 0: none */
    int chain_body, chain_count;
    double *chain_x, *chain_y;
    double chain_friction;
    /* kinematic walls turn at pivot_w rad/s about (pivot_x, pivot_y) */
    double pivot_x, pivot_y, pivot_w;
    int body_cap, shape_cap, joint_cap, failed; /* building: room, and no memory */
} bench_scene;

/* ---------------------------------------------------------------- build */
/* Room for one more element of an array that doubles as it grows. */
static void *bench__grow(void *array, int *cap, int used, size_t size)
{
    void *grown;
    int want = *cap ? 2 * *cap : 1024;
    if (used < *cap) return array;
    grown = realloc(array, (size_t)want * size);
    if (grown) *cap = want;
    return grown;
}

/* A new body (a box of half-extents hx, hy, density 1, friction 0.6);
   its index, or -1 when out of memory (s->failed is set). */
static int bench__push(bench_scene *s, int type, double x, double y, double hx, double hy)
{
    bench_body *b, *grown;
    if (s->failed) return -1;
    grown = (bench_body *)bench__grow(s->bodies, &s->body_cap, s->count, sizeof *s->bodies);
    if (!grown) {
        s->failed = 1;
        return -1;
    }
    s->bodies = grown;
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

/* A new shape for body k, the last pushed (its shapes are consecutive):
   density 1, friction 0.6, category 1, collides with all; NULL when out
   of memory. */
static bench_shape *bench__shape(bench_scene *s, int k, int kind)
{
    bench_shape *sh, *grown;
    if (s->failed || k < 0) return NULL;
    grown = (bench_shape *)bench__grow(s->shapes, &s->shape_cap, s->shape_count, sizeof *s->shapes);
    if (!grown) {
        s->failed = 1;
        return NULL;
    }
    s->shapes = grown;
    if (s->bodies[k].shape_count == 0) s->bodies[k].shape_first = s->shape_count;
    ++s->bodies[k].shape_count;
    sh = &s->shapes[s->shape_count++];
    memset(sh, 0, sizeof *sh);
    sh->kind = kind;
    sh->density = 1;
    sh->friction = 0.6;
    sh->category = 1;
    sh->mask = 0xFFFFFFFFu;
    return sh;
}

/* A shape for body k: a box of half-extents hx, hy centred at (x, y) of
   its frame, or a polygon's vertices. */
static bench_shape *bench__shape_box(bench_scene *s, int k, double x, double y, double hx, double hy)
{
    bench_shape *sh = bench__shape(s, k, BENCH_SHAPE_POLYGON);
    if (!sh) return NULL;
    sh->count = 4;
    sh->px[0] = sh->px[3] = x - hx;
    sh->px[1] = sh->px[2] = x + hx;
    sh->py[0] = sh->py[1] = y - hy;
    sh->py[2] = sh->py[3] = y + hy;
    return sh;
}

static bench_shape *bench__shape_capsule(bench_scene *s, int k, double x1, double y1, double x2, double y2, double r)
{
    bench_shape *sh = bench__shape(s, k, BENCH_SHAPE_CAPSULE);
    if (!sh) return NULL;
    sh->x1 = x1;
    sh->y1 = y1;
    sh->x2 = x2;
    sh->y2 = y2;
    sh->radius = r;
    return sh;
}

/* A revolute joint between bodies a and b at their local anchors. */
static void bench__joint(bench_scene *s, int a, int b, double ax, double ay, double bx, double by)
{
    bench_joint *j, *grown;
    if (s->failed || a < 0 || b < 0) return;
    grown = (bench_joint *)bench__grow(s->joints, &s->joint_cap, s->joint_count, sizeof *s->joints);
    if (!grown) {
        s->failed = 1;
        return;
    }
    s->joints = grown;
    j = &s->joints[s->joint_count++];
    memset(j, 0, sizeof *j); /* no motor */
    j->a = a;
    j->b = b;
    j->ax = ax;
    j->ay = ay;
    j->bx = bx;
    j->by = by;
}

/* A pyramid of `base` boxes of half-extent a, its row i at
   y = (2i+1) a + base_y and box j (j = i..base-1) at
   x = (i+1) a + 2 (j-i) a + x0; returns the top box's index. */
static int bench__pyramid(bench_scene *s, int base, double a, double x0, double base_y)
{
    int i, j, top = -1;
    for (i = 0; i < base; ++i)
        for (j = i; j < base; ++j)
            top = bench__push(s, BENCH_DYNAMIC, (i + 1) * a + 2 * (j - i) * a + x0, (2 * i + 1) * a + base_y, a, a);
    return top;
}

static void bench_scene_free(bench_scene *s)
{
    free(s->bodies);
    free(s->shapes);
    free(s->joints);
    free(s->chain_x);
    free(s->chain_y);
    s->bodies = NULL;
    s->shapes = NULL;
    s->joints = NULL;
    s->chain_x = s->chain_y = NULL;
    s->chain_count = 0;
    s->count = s->shape_count = s->body_cap = s->shape_cap = s->joint_count = s->joint_cap = 0;
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

/* --------------------------------------------------------------- rain */
/* After Box2D v3's "rain" benchmark (erincatto/box2d, shared/benchmarks.c,
   CreateRain / CreateGroup / StepRain, with the human of shared/human.c;
   its benchmark/main.c runs it 1000 steps at 1/60 s, 4 substeps, sleep on,
   continuous collision on).  Taken from it: five floors 45 m apart, each a
   row of 501 static 0.5 m squares centred 0.5 m apart from x = -125 (all
   shapes of one static body); 40 columns 6.25 m apart; every 8th step
   (0, 8, ...) one group per floor appears in the next column, 40 m above
   its floor, five humans 0.5 m apart, and once all 40 columns stand, the
   oldest column's groups are destroyed and made anew each time.  The
   human's bones: the body heights, capsule ends and radii of its hip,
   torso, head, legs and arms; a rounded-polygon foot on each lower leg
   that collides with the ground only; friction 0.2 (feet 0.05); linear
   damping 0.1 on the head and forearms; human i of every group in
   filter group -(i + 1), so humans of one index never meet, as there.
   Not taken: the joints (ga2d had none when this scene was written; it
   has revolute joints now, but the human's ten hinges carry angle
   limits, a 5 Hz spring toward the standing pose and joint friction, so
   they are still left out), so each bone is a free body, a human's 11
   bones falling together and scattering where they land; the per-body
   sleep threshold of 0.1 m/s (ga2d has one for the world).  The
   peak is 11 000 bones (+ the ground) as in Box2D, 34 375 over the run. */
#define BENCH_RAIN_FLOORS 5
#define BENCH_RAIN_COLUMNS 40
#define BENCH_RAIN_HUMANS 5    /* per group */
#define BENCH_RAIN_EVERY 8     /* steps between spawns */
#define BENCH_RAIN_CELL 0.5    /* ground square */
#define BENCH_RAIN_CELLS 500   /* the floor spans this many cells (501 squares) */
#define BENCH_RAIN_FLOOR_GAP 45.0
#define BENCH_RAIN_DROP 40.0   /* a group starts this high above its floor (its soles 0.275 m higher) */

/* The bones of a standing human: body origin height, capsule ends (on
   the body's vertical axis) and radius, linear damping; feet apart. */
typedef struct bench__bone { double y, c1, c2, r, damping; int foot; } bench__bone;
static const bench__bone bench__bones[11] = {
    {0.95, -0.02, 0.02, 0.095, 0, 0},     /* hip */
    {1.2, -0.135, 0.135, 0.09, 0, 0},     /* torso */
    {1.475, -0.038, 0.039, 0.075, 0.1, 0}, /* head */
    {0.775, -0.125, 0.125, 0.06, 0, 0},   /* upper leg (left) */
    {0.475, -0.155, 0.125, 0.045, 0, 1},  /* lower leg (left), with a foot */
    {0.775, -0.125, 0.125, 0.06, 0, 0},   /* upper leg (right) */
    {0.475, -0.155, 0.125, 0.045, 0, 1},  /* lower leg (right), with a foot */
    {1.225, -0.125, 0.125, 0.035, 0, 0},  /* upper arm (left) */
    {0.975, -0.125, 0.125, 0.03, 0.1, 0}, /* forearm (left) */
    {1.225, -0.125, 0.125, 0.035, 0, 0},  /* upper arm (right) */
    {0.975, -0.125, 0.125, 0.03, 0.1, 0}, /* forearm (right) */
};

/* One human placed from (x, y) (its soles 0.275 m above it) over floor
   `floor`, human i of its group, made before step `birth` and destroyed
   before `death`. */
static void bench__human(bench_scene *s, double x, double y, int floor, int i, int birth, int death)
{
    /* the foot's core (rounded by 0.015 m), in the lower leg's frame */
    static const double foot_x[4] = {-0.03, 0.11, 0.11, -0.03}, foot_y[4] = {-0.185, -0.185, -0.16, -0.14};
    int b, v;
    for (b = 0; b < 11; ++b) {
        const bench__bone *bone = &bench__bones[b];
        int k = bench__push(s, BENCH_DYNAMIC, x, y + bone->y, 0, 0);
        bench_shape *sh;
        if (k < 0) return;
        s->bodies[k].linear_damping = bone->damping;
        s->bodies[k].birth = birth;
        s->bodies[k].death = death;
        s->bodies[k].bounded = 1;
        /* under the floor's underside, and not past its ends */
        s->bodies[k].lo_x = -0.5 * (BENCH_RAIN_CELLS + 1) * BENCH_RAIN_CELL;
        s->bodies[k].hi_x = 0.5 * (BENCH_RAIN_CELLS + 1) * BENCH_RAIN_CELL;
        s->bodies[k].lo_y = floor * BENCH_RAIN_FLOOR_GAP - 0.5 * BENCH_RAIN_CELL;
        sh = bench__shape_capsule(s, k, 0, bone->c1, 0, bone->c2, bone->r);
        if (!sh) return;
        sh->friction = 0.2;
        sh->group = -(i + 1);
        sh->category = 2;
        sh->mask = 1 | 2;
        if (bone->foot) {
            sh = bench__shape(s, k, BENCH_SHAPE_POLYGON);
            if (!sh) return;
            sh->count = 4;
            for (v = 0; v < 4; ++v) {
                sh->px[v] = foot_x[v];
                sh->py[v] = foot_y[v];
            }
            sh->radius = 0.015;
            sh->friction = 0.05;
            sh->group = -(i + 1);
            sh->category = 2;
            sh->mask = 1; /* the ground only */
        }
    }
}

static void bench__rain(bench_scene *s)
{
    const double span = BENCH_RAIN_CELLS * BENCH_RAIN_CELL, column_gap = span / BENCH_RAIN_COLUMNS;
    const int spawns = (s->steps + BENCH_RAIN_EVERY - 1) / BENCH_RAIN_EVERY;
    int ground = bench__push(s, BENCH_STATIC, 0, 0, 0, 0), floor, j, e, i;
    for (floor = 0; floor < BENCH_RAIN_FLOORS; ++floor)
        for (j = 0; j <= BENCH_RAIN_CELLS; ++j)
            bench__shape_box(s, ground, -0.5 * span + j * BENCH_RAIN_CELL, floor * BENCH_RAIN_FLOOR_GAP,
                             0.5 * BENCH_RAIN_CELL, 0.5 * BENCH_RAIN_CELL);
    /* spawn e (before step 8e) fills column e mod 40; the column's next
       spawn, 40 later, destroys it first */
    for (e = 0; e < spawns; ++e) {
        int column = e % BENCH_RAIN_COLUMNS, birth = e * BENCH_RAIN_EVERY;
        int death = e + BENCH_RAIN_COLUMNS < spawns ? (e + BENCH_RAIN_COLUMNS) * BENCH_RAIN_EVERY : 0;
        for (floor = 0; floor < BENCH_RAIN_FLOORS; ++floor)
            for (i = 0; i < BENCH_RAIN_HUMANS; ++i)
                bench__human(s, -0.5 * span + column_gap * (column + 0.5) + 0.5 * i,
                              BENCH_RAIN_DROP + floor * BENCH_RAIN_FLOOR_GAP, floor, i, birth, death);
    }
}

/* --------------------------------------------------------- mixed_pile */
/* 5 000 bodies poured into an open box: a floor (top face y = 0) and two
   walls 30 m high, 50 m apart inside, all 0.5 m thick static boxes.  100
   waves of 50, one every 6 steps from step 0, start 31.5 m up, 1 m apart
   (+-0.05 m), at a random angle, falling at 10 m/s (no two overlap: each
   reaches at most 0.43 m from its centre); each body is, as a random
   number says, a circle (radius 0.2-0.35 m), a capsule (half-length
   0.12-0.25, radius 0.1-0.18), a box (half-extents 0.15-0.3 each) or a
   regular 3- to 8-gon of circumradius 0.2-0.35 rounded by 0.04 m (its
   outline that size).  Density 1, friction 0.6.  The pile ends about
   24 m deep.
   1 000 steps: the last wave starts at step 594 and lands by about 700;
   sleep off, so the pile is solved every step.  The numbers come from a
   fixed linear congruential generator, the same on every platform (the
   polygons' corners go through the C library's cos and sin). */
#define BENCH_PILE_WAVES 100
#define BENCH_PILE_PER_WAVE 50
#define BENCH_PILE_EVERY 6
#define BENCH_PILE_HALF_WIDTH 25.0
#define BENCH_PILE_WALL 30.0
#define BENCH_PILE_START 31.5

/* A uniform number in [lo, hi) from the 32-bit state *r (Numerical
   Recipes' constants; the top 24 bits used). */
static double bench__uniform(unsigned long *r, double lo, double hi)
{
    *r = (*r * 1664525UL + 1013904223UL) & 0xFFFFFFFFUL;
    return lo + (hi - lo) * (double)(*r >> 8) / 16777216.0;
}

/* The floor (top face y = 0) and two walls h high, w apart inside, of a
   pile's open box: static boxes 0.5 m thick. */
static void bench__bin(bench_scene *s, double w, double h)
{
    bench__push(s, BENCH_STATIC, 0, -0.25, 0.5 * w + 0.5, 0.25);
    bench__push(s, BENCH_STATIC, -0.5 * w - 0.25, 0.5 * h, 0.25, 0.5 * h);
    bench__push(s, BENCH_STATIC, 0.5 * w + 0.25, 0.5 * h, 0.25, 0.5 * h);
}

/* One body of a pile at (x, y), its kind, size and angle drawn from *r in
   mixed_pile's order (x's own draw comes before, from the caller): its
   index, or -1 when memory ran out. */
static int bench__pile_body(bench_scene *s, unsigned long *r, double x, double y)
{
    const double pi = 3.14159265358979323846;
    int kind = (int)bench__uniform(r, 0, 4), k, v;
    bench_shape *sh;
    if (kind == 2) { /* a plain box: the same body as the box scenes' */
        double hx = bench__uniform(r, 0.15, 0.3), hy = bench__uniform(r, 0.15, 0.3); /* in this order */
        k = bench__push(s, BENCH_DYNAMIC, x, y, hx, hy);
    } else {
        k = bench__push(s, BENCH_DYNAMIC, x, y, 0, 0);
        if (kind == 0) {
            sh = bench__shape(s, k, BENCH_SHAPE_CIRCLE);
            if (sh) sh->radius = bench__uniform(r, 0.2, 0.35);
        } else if (kind == 1) {
            double half = bench__uniform(r, 0.12, 0.25);
            bench__shape_capsule(s, k, -half, 0, half, 0, bench__uniform(r, 0.1, 0.18));
        } else {
            int n = 3 + (int)bench__uniform(r, 0, 6);
            double rounding = 0.04, core = bench__uniform(r, 0.2, 0.35) - rounding;
            sh = bench__shape(s, k, BENCH_SHAPE_POLYGON);
            if (sh) {
                sh->count = n;
                sh->radius = rounding;
                for (v = 0; v < n; ++v) {
                    sh->px[v] = core * cos(2 * pi * v / n);
                    sh->py[v] = core * sin(2 * pi * v / n);
                }
            }
        }
    }
    if (k >= 0) s->bodies[k].angle = bench__uniform(r, -pi, pi);
    return k;
}

static void bench__mixed_pile(bench_scene *s)
{
    const double W = BENCH_PILE_HALF_WIDTH;
    unsigned long r = 12345;
    int wave, j;
    bench__bin(s, 2 * W, BENCH_PILE_WALL);
    for (wave = 0; wave < BENCH_PILE_WAVES; ++wave)
        for (j = 0; j < BENCH_PILE_PER_WAVE; ++j) {
            double x = -W + 0.5 + j + bench__uniform(&r, -0.05, 0.05);
            int k = bench__pile_body(s, &r, x, BENCH_PILE_START);
            if (k < 0) return;
            s->bodies[k].vy = -10;
            s->bodies[k].birth = wave * BENCH_PILE_EVERY;
        }
}

/* ---------------------------------------------------------- mixed_bin */
/* A small mixed scene: test_settle's bin (floor top y = 0, walls 8 m
   high, 10 m apart inside) with its 100 bodies (mixed_pile's kinds and
   sizes, drawn the same way from seed 12345) all there at step 0, at rest
   on a 1 m grid, rows at y = 0.5 + i (no two overlap: each reaches at most
   0.43 m), and let fall together.  1 000 steps, sleep off, so the settled
   pile is solved every step.  Its figure is the deepest penetration. */
#define BENCH_BIN_ROWS 10
#define BENCH_BIN_HALF_WIDTH 5.0
#define BENCH_BIN_WALL 8.0

static void bench__mixed_bin(bench_scene *s)
{
    const double W = BENCH_BIN_HALF_WIDTH;
    unsigned long r = 12345;
    int i, j;
    bench__bin(s, 2 * W, BENCH_BIN_WALL);
    for (i = 0; i < BENCH_BIN_ROWS; ++i)
        for (j = 0; j < 2 * (int)W; ++j) {
            double x = -W + 0.5 + j + bench__uniform(&r, -0.05, 0.05);
            if (bench__pile_body(s, &r, x, 0.5 + i) < 0) return;
        }
}

/* --------------------------------------------------------- joint_grid */
/* After Box2D v3's "joint_grid" benchmark (erincatto/box2d,
   shared/benchmarks.c, CreateJointGrid; its benchmark/main.c runs it 500
   steps at 1/60 s, 4 substeps): N x N circles of radius 0.4 m, density 1,
   body (k, i) at (k, -i) m for k, i = 0..N-1, made k by k and i by i
   within; static where i = 0 and N/2 - 3 <= k <= N/2 + 3 (seven bodies in
   the middle of the top row), else dynamic.  Each body (k, i) is pinned,
   in this order, to the body above, (k, i - 1), at (0, -0.5) of that one
   and (0, 0.5) of its own, and to the body on its left, (k - 1, i), at
   (0.5, 0) of that one and (-0.5, 0) of its own: each pin sits halfway
   between the two centres, so the grid starts with every joint closed.
   The circles are in filter category 2 and collide only with other
   categories, so no two meet: the step has no contacts, only joints.
   Sleep off.  Box2D also pins the six neighbouring pairs of static bodies
   in the top row, which no engine solves (ga2d refuses a joint with no
   dynamic body); they are left out: 2 N (N - 1) - 6 joints. */
#define BENCH_GRID_N 100
#define BENCH_GRID_RADIUS 0.4
#define BENCH_GRID_FIXED 3 /* static: the top row's bodies within this many of the middle */

static void bench__joint_grid(bench_scene *s, int n)
{
    int k, i;
    for (k = 0; k < n; ++k)
        for (i = 0; i < n; ++i) {
            int fixed = i == 0 && k >= n / 2 - BENCH_GRID_FIXED && k <= n / 2 + BENCH_GRID_FIXED;
            int body = bench__push(s, fixed ? BENCH_STATIC : BENCH_DYNAMIC, k, -i, 0, 0);
            bench_shape *sh = bench__shape(s, body, BENCH_SHAPE_CIRCLE);
            if (!sh) return;
            sh->radius = BENCH_GRID_RADIUS;
            sh->category = 2;
            sh->mask = ~2u;
            /* above: (k, i - 1) is the body made just before (dynamic: i > 0) */
            if (i > 0) bench__joint(s, body - 1, body, 0, -0.5, 0, 0.5);
            /* left: (k - 1, i) was made n bodies before */
            if (k > 0 && !(fixed && s->bodies[body - n].type == BENCH_STATIC))
                bench__joint(s, body - n, body, 0.5, 0, -0.5, 0);
        }
    s->probe = n - 1; /* (0, N - 1): the bottom-left corner */
}

/* The largest distance between a joint's two anchors in the world, m,
   given every body's pose (x[i], y[i], angle[i]: its origin and turn). */
static double bench_scene_joint_gap(const bench_scene *s, const double *x, const double *y, const double *angle)
{
    double worst = 0;
    int i;
    for (i = 0; i < s->joint_count; ++i) {
        const bench_joint *j = &s->joints[i];
        double ca = cos(angle[j->a]), sa = sin(angle[j->a]), cb = cos(angle[j->b]), sb = sin(angle[j->b]);
        double dx = x[j->b] + cb * j->bx - sb * j->by - (x[j->a] + ca * j->ax - sa * j->ay);
        double dy = y[j->b] + sb * j->bx + cb * j->by - (y[j->a] + sa * j->ax + ca * j->ay);
        double d = sqrt(dx * dx + dy * dy);
        if (!(d <= worst)) worst = d; /* a NaN sticks */
    }
    return worst;
}

/* ------------------------------------------------------------ spinner */
/* After Box2D v3's "spinner" benchmark (erincatto/box2d,
   shared/benchmarks.c, CreateSpinner / StepSpinner; its benchmark/main.c
   runs it 500 steps at 1/60 s, 4 substeps, sleep on): a static loop of
   360 one-sided segments through points 40 m from (0, 32), the first at
   (40, 32), each next one 1 degree further clockwise (from cos and sin;
   Box2D turns one point 1 degree at a time in float: the two differ by
   its rounding), friction 0.1; a
   bar, a box of half-extents 0.4 x 20 rounded by 0.2 (density 1,
   friction 0), centred at (0, 12), that may never sleep, pinned to the
   loop's body at its centre and turned by a motor at 5 rad/s with no
   torque limit (Box2D's FLT_MAX); and 2 x 3038 bodies of density 0.25,
   friction 0.1, restitution 0.1, laid in rows from (-23, 2): 0.5 m apart
   along x, a new row 0.5 m higher once x reaches 23 (92 a row), body i a
   capsule (centres (+-0.25, 0), radius 0.25) when i mod 3 is 0, a circle
   of radius 0.35 when 1, a box of half-extent 0.35 when 2.  They start
   overlapping (0.7 m wide, 0.5 m apart), as in Box2D, and are pushed
   apart in the first steps.  The figure: the bar's lag on its motor
   (BENCH_FIG_LAG). */
#define BENCH_SPIN_POINTS 360
#define BENCH_SPIN_RADIUS 40.0
#define BENCH_SPIN_CENTRE_Y 32.0
#define BENCH_SPIN_BODIES (2 * 3038)
#define BENCH_SPIN_SPEED 5.0             /* the motor's, rad/s */
#define BENCH_SPIN_TORQUE 3.40282347e38  /* no limit: the largest float, Box2D's FLT_MAX */
#define BENCH_SPIN_GAP 0.5               /* between bodies, along a row and between rows */

static void bench__spinner(bench_scene *s)
{
    const double pi = 3.14159265358979323846;
    double x = -23, y = 2;
    int ground = bench__push(s, BENCH_STATIC, 0, 0, 0, 0), bar, i;
    bench_shape *sh;
    s->chain_x = (double *)malloc(BENCH_SPIN_POINTS * sizeof *s->chain_x);
    s->chain_y = (double *)malloc(BENCH_SPIN_POINTS * sizeof *s->chain_y);
    if (!s->chain_x || !s->chain_y || ground < 0) {
        s->failed = 1;
        return;
    }
    s->chain_body = ground;
    s->chain_count = BENCH_SPIN_POINTS;
    s->chain_friction = 0.1;
    for (i = 0; i < BENCH_SPIN_POINTS; ++i) {
        double a = -2 * pi * i / BENCH_SPIN_POINTS; /* clockwise */
        s->chain_x[i] = BENCH_SPIN_RADIUS * cos(a);
        s->chain_y[i] = BENCH_SPIN_RADIUS * sin(a) + BENCH_SPIN_CENTRE_Y;
    }
    bar = bench__push(s, BENCH_DYNAMIC, 0, 12, 0, 0);
    sh = bench__shape_box(s, bar, 0, 0, 0.4, 20);
    if (!sh) return;
    sh->radius = 0.2;
    sh->friction = 0;
    s->bodies[bar].never_sleeps = 1;
    bench__joint(s, ground, bar, 0, 12, 0, 0);
    if (s->failed) return;
    s->joints[0].motor = 1;
    s->joints[0].motor_speed = BENCH_SPIN_SPEED;
    s->joints[0].max_motor_torque = BENCH_SPIN_TORQUE;
    s->probe = bar;
    for (i = 0; i < BENCH_SPIN_BODIES; ++i) {
        int k = bench__push(s, BENCH_DYNAMIC, x, y, 0, 0);
        if (i % 3 == 0)
            sh = bench__shape_capsule(s, k, -0.25, 0, 0.25, 0, 0.25);
        else if (i % 3 == 1)
            sh = bench__shape(s, k, BENCH_SHAPE_CIRCLE);
        else
            sh = bench__shape_box(s, k, 0, 0, 0.35, 0.35);
        if (!sh) return;
        if (i % 3 == 1) sh->radius = 0.35;
        sh->density = 0.25;
        sh->friction = 0.1;
        sh->restitution = 0.1;
        x += BENCH_SPIN_GAP;
        if (x >= 23) {
            x = -23;
            y += BENCH_SPIN_GAP;
        }
    }
}

/* One step's change of a body's angle, from `before` to `after`, wrapped
   into (-pi, pi]: summed over the steps, the turn (BENCH_FIG_LAG). */
static double bench_scene_turn(double before, double after)
{
    const double pi = 3.14159265358979323846;
    double d = fmod(after - before, 2 * pi);
    if (d > pi) d -= 2 * pi;
    if (d <= -pi) d += 2 * pi;
    return d;
}

/* BENCH_FIG_LAG's figure from the turn summed over the run. */
static double bench_scene_lag(const bench_scene *s, double turn)
{
    return s->joints[0].motor_speed * s->steps * s->dt - turn;
}

/* The most bodies alive at once. */
static int bench__peak(const bench_scene *s)
{
    int i, alive = 0, peak = 0, step = -1;
    /* births come in order; a step's deaths (of earlier births) come first */
    for (i = 0; i < s->count; ++i) {
        if (s->bodies[i].birth != step) {
            int k, died = 0;
            step = s->bodies[i].birth;
            for (k = 0; k < i; ++k) died += s->bodies[k].death > 0 && s->bodies[k].death <= step;
            alive = i - died;
        }
        ++alive;
        if (alive > peak) peak = alive;
    }
    return peak;
}

/* Fills *s with the named scene; returns 0, or -1 for an unknown name or
   no memory.  Names: large_pyramid, many_pyramids, smash, tumbler,
   pyramid20, stack10, rain, mixed_pile, mixed_bin, joint_grid, spinner. */
static int bench_scene_make(const char *name, bench_scene *s)
{
    int i, j;
    memset(s, 0, sizeof *s);
    s->dt = 1.0 / 60;
    s->gy = -10;
    if (strcmp(name, "large_pyramid") == 0) {
        s->name = "large_pyramid";
        s->steps = 500;
        bench__push(s, BENCH_STATIC, 0, -1, 100, 1);
        s->probe = bench__pyramid(s, 100, 0.5, -50, 0);
    } else if (strcmp(name, "pyramid20") == 0) {
        s->name = "pyramid20";
        s->steps = 600;
        bench__push(s, BENCH_STATIC, 0, -1, 100, 1);
        s->probe = bench__pyramid(s, 20, 0.5, -10, 0);
    } else if (strcmp(name, "many_pyramids") == 0) {
        /* 20 rows of 20 base-10 pyramids; row r's ground top at y = 11 r,
           220 m wide; pyramid c's centre x = -110 + 11 c + 1 */
        s->name = "many_pyramids";
        s->steps = 200;
        for (i = 0; i < 20; ++i) bench__push(s, BENCH_STATIC, 0, 11.0 * i - 0.05, 110, 0.05);
        for (i = 0; i < 20; ++i)
            for (j = 0; j < 20; ++j) {
                int top = bench__pyramid(s, 10, 0.5, -110 + 11.0 * j + 1 - 0.5, 11.0 * i);
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
        k = bench__push(s, BENCH_DYNAMIC, -20, 0, 4, 4);
        if (k >= 0) {
            s->bodies[k].density = 8;
            s->bodies[k].vx = 40;
        }
        s->probe = k;
        for (i = 0; i < 120; ++i)
            for (j = 0; j < 80; ++j) {
                k = bench__push(s, BENCH_DYNAMIC, 30 + 0.4 * i, 0.4 * (j - 40), 0.2, 0.2);
                if (k >= 0) s->bodies[k].asleep = 1;
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
        bench__push(s, BENCH_KINEMATIC, 10, 10, 0.5, 10);
        bench__push(s, BENCH_KINEMATIC, -10, 10, 0.5, 10);
        bench__push(s, BENCH_KINEMATIC, 0, 20, 10, 0.5);
        bench__push(s, BENCH_KINEMATIC, 0, 0, 10, 0.5);
        for (i = 0; i < 4 && !s->failed; ++i) {
            s->bodies[i].w = s->pivot_w;
            bench_scene_kinematic_velocity(s, s->bodies[i].x, s->bodies[i].y, &s->bodies[i].vx, &s->bodies[i].vy);
        }
        for (i = 0; i < 45; ++i)
            for (j = 0; j < 45; ++j) bench__push(s, BENCH_DYNAMIC, -0.2 * 45 + 0.4 * j, -0.2 * 45 + 10 + 0.4 * i, 0.125, 0.125);
        s->probe = s->count - 1;
    } else if (strcmp(name, "stack10") == 0) {
        s->name = "stack10";
        s->steps = 600;
        bench__push(s, BENCH_STATIC, 0, -1, 100, 1);
        for (i = 0; i < 10; ++i) s->probe = bench__push(s, BENCH_DYNAMIC, 0, 0.5 + i, 0.5, 0.5);
    } else if (strcmp(name, "rain") == 0) {
        s->name = "rain";
        s->steps = 1000;
        s->sleep = 1;
        s->figure = BENCH_FIG_THROUGH;
        bench__rain(s);
    } else if (strcmp(name, "mixed_pile") == 0) {
        s->name = "mixed_pile";
        s->steps = 1000;
        s->figure = BENCH_FIG_PENETRATION;
        bench__mixed_pile(s);
    } else if (strcmp(name, "mixed_bin") == 0) {
        s->name = "mixed_bin";
        s->steps = 1000;
        s->figure = BENCH_FIG_PENETRATION;
        bench__mixed_bin(s);
    } else if (strcmp(name, "spinner") == 0) {
        s->name = "spinner";
        s->steps = 500;
        s->sleep = 1;
        s->figure = BENCH_FIG_LAG;
        bench__spinner(s);
    } else if (strcmp(name, "joint_grid") == 0) {
        s->name = "joint_grid";
        s->steps = 500;
        s->figure = BENCH_FIG_SAG;
        bench__joint_grid(s, BENCH_GRID_N);
    } else {
        return -1;
    }
    if (s->failed) {
        bench_scene_free(s);
        return -1;
    }
    s->peak = bench__peak(s);
    return 0;
}

/* The accuracy figure's name, for tables. */
static const char *bench_scene_figure_name(const bench_scene *s)
{
    static const char *names[6] = {"top box drift (m)",       "momentum error (rel.)",   "deepest penetration (m)",
                                   "bodies through a floor",  "bottom corner's sag (m)", "bar's lag on its motor (rad)"};
    return names[s->figure];
}

#endif
