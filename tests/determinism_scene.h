/* determinism_scene.h - the mixed scene whose bits must not depend on the
   build (issue 8): a pyramid of base 8, 24 convex polygons of 3 to 6 sides
   falling onto it with spin and restitution, sleep on; 600 steps at 1/60.
   Joints too (0.10): a chain of 8 links on revolute joints swings from a
   post into the pyramid's side, two of the falling polygons are welded
   and two more tied by a distance joint, one rides a wheel joint under
   another, and one slides on a prismatic joint along a third.
   Its hash covers every scene body's position, rotor, velocity, angular
   velocity and awake flag, bit for bit (FNV-1a over the bytes).

   No libm in the scene either: the polygons are hulls of points from an
   integer generator, so nothing here can differ between platforms' sin and
   cos.  Optional churn: unrelated bodies, and joints between them, made
   and destroyed on their own ground 1 km away while the scene runs, which
   must not change its hash.

   Beside it, the hinge net (dhinge_run): the solver's lanes of bare
   hinges against the same joints solved one by one.

   Used by tests/test_determinism.c (inside each test build) and by
   tests/determinism.c (one small program built with many compilers and
   flags, whose hashes `make test` compares). */
#ifndef GA2D_DETERMINISM_SCENE_H
#define GA2D_DETERMINISM_SCENE_H

#include "ga2d_physics.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>

#define DSCENE_STEPS 600
#define DSCENE_MAX 96

typedef struct dscene {
    ga2d_world *w;
    ga2d_body_id ids[DSCENE_MAX];
    int count;
    ga2d_body_id churn[32];
    int churn_count;
    ga2d_body_id far_ground;
    unsigned lcg;
} dscene;

static inline unsigned dscene_next(dscene *s)
{
    s->lcg = s->lcg * 1664525u + 1013904223u;
    return s->lcg >> 8;
}

/* A number in [lo, hi] on a grid of 1/1024 of the range: exact in float. */
static inline ga2d_real dscene_pick(dscene *s, double lo, double hi)
{
    return (ga2d_real)(lo + (hi - lo) * (double)(dscene_next(s) % 1025u) / 1024.0);
}

/* A convex polygon of 3 to 6 sides: the hull of points on the integer
   grid around the origin (regenerated until the hull has `sides`). */
static inline ga2d_polygon dscene_polygon(dscene *s, int sides)
{
    ga2d_polygon p;
    for (;;) {
        ga2d_vec pts[6];
        int k;
        for (k = 0; k < sides; ++k) {
            /* points near a circle of radius 0.4, on a 1/64 grid: angles
               from a table of integer directions */
            static const int dir[12][2] = {{8, 0}, {7, 4}, {4, 7}, {0, 8}, {-4, 7}, {-7, 4},
                                           {-8, 0}, {-7, -4}, {-4, -7}, {0, -8}, {4, -7}, {7, -4}};
            int d = (int)((unsigned)(k * 12 / sides) + dscene_next(s) % 2u) % 12;
            pts[k] = ga2d_vec_make((ga2d_real)(dir[d][0] * 0.05), (ga2d_real)(dir[d][1] * 0.05));
        }
        if (ga2d_polygon_hull(pts, sides, &p) == GA2D_OK && p.count >= 3) return p;
    }
}

/* The joints: the chain (its links join ids), then joints between
   falling polygons (ids 37 on: each kind once). */
static inline int dscene_joints(dscene *s)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id post, prev;
    int i, first = s->count - 24;
    d.polygon = ga2d_polygon_box((ga2d_real)0.25, (ga2d_real)0.25);
    d.position = ga2d_vec_make(-9, 7);
    post = ga2d_body_create(s->w, &d);
    prev = post;
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box((ga2d_real)0.25, (ga2d_real)0.0625);
    for (i = 0; i < 8; ++i) {
        ga2d_revolute_joint_def r = ga2d_default_revolute_joint_def();
        d.position = ga2d_vec_make((ga2d_real)(-8.5 + 0.5 * i), 7);
        s->ids[s->count] = ga2d_body_create(s->w, &d);
        r.body_a = prev;
        r.body_b = s->ids[s->count];
        r.local_anchor_a = ga2d_vec_make(i == 0 ? 0 : (ga2d_real)0.25, 0);
        r.local_anchor_b = ga2d_vec_make((ga2d_real)-0.25, 0);
        if (ga2d_joint_id_is_null(ga2d_revolute_joint_create(s->w, &r))) return 0;
        prev = s->ids[s->count++];
    }
    {
        ga2d_weld_joint_def wj = ga2d_default_weld_joint_def();
        ga2d_distance_joint_def dj = ga2d_default_distance_joint_def();
        ga2d_wheel_joint_def hj = ga2d_default_wheel_joint_def();
        ga2d_prismatic_joint_def pj = ga2d_default_prismatic_joint_def();
        wj.body_a = s->ids[first];
        wj.body_b = s->ids[first + 1];
        wj.local_anchor_a = ga2d_body_local_point(s->w, wj.body_a, ga2d_body_position(s->w, wj.body_b));
        dj.body_a = s->ids[first + 2];
        dj.body_b = s->ids[first + 3];
        dj.length = 2;
        hj.body_a = s->ids[first + 4];
        hj.body_b = s->ids[first + 5];
        hj.enable_motor = 1;
        hj.motor_speed = 3;
        hj.max_motor_torque = 2;
        pj.body_a = s->ids[first + 6];
        pj.body_b = s->ids[first + 7];
        pj.enable_limit = 1;
        pj.lower_translation = -1;
        pj.upper_translation = 1;
        if (ga2d_joint_id_is_null(ga2d_weld_joint_create(s->w, &wj)) || ga2d_joint_id_is_null(ga2d_distance_joint_create(s->w, &dj)) ||
            ga2d_joint_id_is_null(ga2d_wheel_joint_create(s->w, &hj)) || ga2d_joint_id_is_null(ga2d_prismatic_joint_create(s->w, &pj)))
            return 0;
    }
    return 1;
}

/* The scene in a world made from `wd` (the defaults, or the same with a
   task system: tests/test_threads.c). */
static inline int dscene_build_in(dscene *s, const ga2d_world_def *wd)
{
    ga2d_body_def d = ga2d_default_body_def();
    int i, j;
    memset(s, 0, sizeof *s);
    s->lcg = 12345u;
    s->w = ga2d_world_create(wd);
    if (!s->w) return 0;
    d.polygon = ga2d_polygon_box(20, (ga2d_real)0.5);
    d.position = ga2d_vec_make(0, (ga2d_real)-0.5);
    s->ids[s->count++] = ga2d_body_create(s->w, &d);
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    for (i = 0; i < 8; ++i)
        for (j = i; j < 8; ++j) {
            d.position = ga2d_vec_make((ga2d_real)((i + 1) * 0.5 + (j - i) * 1.0 - 4.5), (ga2d_real)((2 * i + 1) * 0.5));
            s->ids[s->count++] = ga2d_body_create(s->w, &d);
        }
    for (i = 0; i < 24; ++i) {
        /* one pick per statement: the order in which a call's arguments
           are evaluated is unspecified (gcc and clang differ) */
        ga2d_real x, y, vx, vy;
        d.polygon = dscene_polygon(s, 3 + i % 4);
        x = dscene_pick(s, -6, 6);
        y = dscene_pick(s, 10, 22);
        vx = dscene_pick(s, -2, 2);
        vy = dscene_pick(s, -3, 0);
        d.position = ga2d_vec_make(x, y);
        d.velocity = ga2d_vec_make(vx, vy);
        d.angular_velocity = dscene_pick(s, -6, 6);
        d.restitution = dscene_pick(s, 0, 0.7);
        d.friction = dscene_pick(s, 0.2, 0.8);
        s->ids[s->count++] = ga2d_body_create(s->w, &d);
    }
    for (i = 0; i < s->count; ++i)
        if (ga2d_body_id_is_null(s->ids[i])) return 0;
    return dscene_joints(s);
}

static inline int dscene_build(dscene *s)
{
    ga2d_world_def wd = ga2d_default_world_def();
    return dscene_build_in(s, &wd);
}

/* Step `step` of the churn: from step 40 to 400, every 20 steps three
   boxes drop onto their own ground at x = 1000 and the oldest three go. */
static inline void dscene_churn(dscene *s, int step)
{
    ga2d_body_def d = ga2d_default_body_def();
    int k;
    if (step == 30) {
        d.polygon = ga2d_polygon_box(10, (ga2d_real)0.5);
        d.position = ga2d_vec_make(1000, (ga2d_real)-0.5);
        s->far_ground = ga2d_body_create(s->w, &d);
    }
    if (step < 40 || step > 400 || step % 20 != 0) return;
    if (s->churn_count >= 9) {
        for (k = 0; k < 3; ++k) ga2d_body_destroy(s->w, s->churn[k]);
        memmove(s->churn, s->churn + 3, (size_t)(s->churn_count - 3) * sizeof s->churn[0]);
        s->churn_count -= 3;
    }
    d.type = GA2D_BODY_DYNAMIC;
    for (k = 0; k < 3; ++k) {
        d.polygon = ga2d_polygon_box((ga2d_real)0.4, (ga2d_real)0.3);
        d.position = ga2d_vec_make((ga2d_real)(998 + 2 * k), (ga2d_real)(1 + step % 3));
        d.angular_velocity = (ga2d_real)(k - 1);
        s->churn[s->churn_count++] = ga2d_body_create(s->w, &d);
    }
    for (k = 0; k < 2; ++k) { /* joints among them, gone with their bodies */
        ga2d_revolute_joint_def r = ga2d_default_revolute_joint_def();
        r.body_a = s->churn[s->churn_count - 3 + k];
        r.body_b = s->churn[s->churn_count - 2 + k];
        r.local_anchor_a = ga2d_vec_make(1, 0);
        r.local_anchor_b = ga2d_vec_make(-1, 0);
        (void)ga2d_revolute_joint_create(s->w, &r);
    }
}

static inline uint64_t dscene_fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; ++i) {
        h ^= c[i];
        h *= 1099511628211ull;
    }
    return h;
}

static inline uint64_t dscene_hash(const dscene *s)
{
    uint64_t h = 14695981039346656037ull;
    int i;
    for (i = 0; i < s->count; ++i) {
        ga2d_vec x = ga2d_body_position(s->w, s->ids[i]), v = ga2d_body_velocity(s->w, s->ids[i]);
        ga2d_rotor q = ga2d_body_rotor(s->w, s->ids[i]);
        ga2d_real om = ga2d_body_angular_velocity(s->w, s->ids[i]);
        int awake = ga2d_body_is_awake(s->w, s->ids[i]);
        h = dscene_fnv(h, &x, sizeof x);
        h = dscene_fnv(h, &q, sizeof q);
        h = dscene_fnv(h, &v, sizeof v);
        h = dscene_fnv(h, &om, sizeof om);
        h = dscene_fnv(h, &awake, sizeof awake);
    }
    return h;
}

/* Runs the scene (with churn or not) and returns its hash, 0 if the world
   could not be built; *asleep counts scene bodies asleep at the end. */
static inline uint64_t dscene_run(int churn, int *asleep)
{
    dscene s;
    uint64_t h = 0;
    int step, i;
    if (dscene_build(&s)) {
        for (step = 0; step < DSCENE_STEPS; ++step) {
            if (churn) dscene_churn(&s, step);
            ga2d_world_step(s.w, (ga2d_real)1 / 60);
        }
        h = dscene_hash(&s);
        *asleep = 0;
        for (i = 0; i < s.count; ++i) *asleep += !ga2d_body_is_awake(s.w, s.ids[i]) && i > 0;
    }
    ga2d_world_destroy(s.w);
    return h;
}


/* ------------------------------------------------------ the hinge net */
/* The solver packs bare revolute joints (no spring, motor or limit) of
   one colour several at a time into its lanes and solves them at once;
   each lane must compute exactly what the joint alone would.  A joint
   whose spring is enabled at 0 Hz is the same joint (a spring of no
   stiffness acts nowhere) solved one by one, so a net built both ways
   must give the same bits: every body's state, and every joint's reaction
   read after each step and from inside the force callback (mid-step,
   while the lanes hold the impulses).  The net: n x n discs, each on a
   revolute joint to its left and its upper neighbour, the top row static,
   every fifth joint with a limit of +-0.5 rad (not bare: each colour
   mixes both kinds), the discs passing through each other (as in Box2D
   v3's joint grid), swinging sideways under a slanted gravity; at step
   DHINGE_BLOW a disc in the middle is driven non-finite by a huge force,
   so that step contains it and its joints forget their impulses (in the
   lanes too). */
#define DHINGE_STEPS 150
#define DHINGE_BLOW 60
#define DHINGE_JOINTS(n) (2 * ((n) - 1) * ((n) - 1) + (n) - 1)

typedef struct dhinge {
    ga2d_world *w;
    ga2d_body_id *bodies;
    ga2d_joint_id *joints;
    int n, joint_count;
    uint64_t field_hash; /* the reactions read in the force callback */
} dhinge;

static inline uint64_t dhinge_reactions(const dhinge *s, uint64_t h)
{
    int i;
    for (i = 0; i < s->joint_count; ++i) {
        ga2d_vec f = ga2d_joint_reaction_force(s->w, s->joints[i]);
        ga2d_real t = ga2d_joint_reaction_torque(s->w, s->joints[i]);
        h = dscene_fnv(h, &f, sizeof f);
        h = dscene_fnv(h, &t, sizeof t);
    }
    return h;
}

static inline void dhinge_field(ga2d_world *w, void *context)
{
    dhinge *s = (dhinge *)context;
    (void)w;
    s->field_hash = dhinge_reactions(s, s->field_hash);
}

/* One disc of row `row`, column k, and its joints to the left and up; 0
   if anything was refused. */
static inline int dhinge_disc(dhinge *s, int row, int k, int bare)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle disc;
    ga2d_body_id id;
    int side, n = s->n;
    disc.center = ga2d_vec_make(0, 0);
    disc.radius = (ga2d_real)0.2;
    sd.filter.group_index = -1;
    d.type = row == 0 ? GA2D_BODY_STATIC : GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)(0.5 * k), (ga2d_real)(-0.5 * row));
    id = s->bodies[row * n + k] = ga2d_body_create(s->w, &d);
    if (ga2d_shape_id_is_null(ga2d_shape_create_circle(s->w, id, &sd, &disc))) return 0;
    for (side = 0; row > 0 && side < 2; ++side) {
        ga2d_revolute_joint_def j = ga2d_default_revolute_joint_def();
        if (side == 0 && k == 0) continue;
        j.body_a = side == 0 ? s->bodies[row * n + k - 1] : s->bodies[(row - 1) * n + k];
        j.body_b = id;
        j.local_anchor_a = side == 0 ? ga2d_vec_make((ga2d_real)0.25, 0) : ga2d_vec_make(0, (ga2d_real)-0.25);
        j.local_anchor_b = side == 0 ? ga2d_vec_make((ga2d_real)-0.25, 0) : ga2d_vec_make(0, (ga2d_real)0.25);
        if (s->joint_count % 5 == 4) {
            j.enable_limit = 1;
            j.lower_angle = (ga2d_real)-0.5;
            j.upper_angle = (ga2d_real)0.5;
        }
        j.enable_spring = !bare; /* at 0 Hz */
        j.hertz = 0;
        s->joints[s->joint_count] = ga2d_revolute_joint_create(s->w, &j);
        if (ga2d_joint_id_is_null(s->joints[s->joint_count++])) return 0;
    }
    return 1;
}

/* Steps the net of n x n (bare hinges, or each with its spring on at 0
   Hz) in a world made from wd; returns its hash (bodies, then the
   reactions), 0 if it could not run or the blow-up was not contained
   once.  *in_lanes: the most hinges a step solved in lanes. */
static inline uint64_t dhinge_run(ga2d_world_def wd, int n, int bare, int *in_lanes)
{
    dhinge s;
    uint64_t h = 14695981039346656037ull;
#ifdef GA2D_DOUBLE
    ga2d_real huge = DBL_MAX / 2; /* F / m past the largest real: not finite */
#else
    ga2d_real huge = FLT_MAX / 2;
#endif
    int step, row, k, ok, blown = 0;
    memset(&s, 0, sizeof s);
    *in_lanes = 0;
    s.n = n;
    wd.gravity = ga2d_vec_make(4, -10);
    wd.force_callback = dhinge_field;
    wd.force_context = &s;
    s.w = ga2d_world_create(&wd);
    s.bodies = (ga2d_body_id *)malloc(sizeof *s.bodies * (size_t)(n * n));
    s.joints = (ga2d_joint_id *)malloc(sizeof *s.joints * (size_t)DHINGE_JOINTS(n));
    ok = s.w && s.bodies && s.joints;
    for (row = 0; ok && row < n; ++row)
        for (k = 0; ok && k < n; ++k) ok = dhinge_disc(&s, row, k, bare);
    for (step = 0; ok && step < DHINGE_STEPS; ++step) {
        ga2d_result r;
        ga2d_world_counters wc;
        if (step == DHINGE_BLOW)
            ok = ga2d_body_apply_force_to_center(s.w, s.bodies[n * (n / 2) + n / 2], ga2d_vec_make(0, huge)) == GA2D_OK;
        r = ga2d_world_step(s.w, (ga2d_real)1 / 60);
        blown += r == GA2D_ERR_NOT_FINITE;
        ok = ok && (r == GA2D_OK || (r == GA2D_ERR_NOT_FINITE && step == DHINGE_BLOW));
        wc = ga2d_world_get_counters(s.w);
        if (wc.hinges_in_lanes > *in_lanes) *in_lanes = wc.hinges_in_lanes;
        s.field_hash = dhinge_reactions(&s, s.field_hash);
    }
    for (k = 0; ok && k < n * n; ++k) {
        ga2d_vec x = ga2d_body_position(s.w, s.bodies[k]), v = ga2d_body_velocity(s.w, s.bodies[k]);
        ga2d_rotor q = ga2d_body_rotor(s.w, s.bodies[k]);
        ga2d_real om = ga2d_body_angular_velocity(s.w, s.bodies[k]);
        h = dscene_fnv(h, &x, sizeof x);
        h = dscene_fnv(h, &q, sizeof q);
        h = dscene_fnv(h, &v, sizeof v);
        h = dscene_fnv(h, &om, sizeof om);
    }
    h = dscene_fnv(h, &s.field_hash, sizeof s.field_hash);
    ga2d_world_destroy(s.w);
    free(s.bodies);
    free(s.joints);
    return ok && blown == 1 && s.joint_count == DHINGE_JOINTS(n) ? h : 0;
}

#endif
