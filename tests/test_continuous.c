/* Continuous collision (issue 25): fast bodies never pass through static
   walls, lone segments or chains; a world where nothing is fast steps
   with the same bits with continuous collision on or off.

   A body passes through when its centre crosses the wall's line within
   the wall's span (sliding off a wall's end is not passing through it):
   the crossing is checked at every step between the centre's positions
   before and after.  Each case runs from 40 start phases: the start
   offset along the path (a fraction of a step's travel), a height and a
   spin, so the body meets the wall at every point of its step and turned
   every way. */
#include "test.h"

#define PHASES 40
#define WALL_HALF 20.0 /* m: the walls span y in [-20, 20]; the bodies meet them within 0.4 m of y = 0 */

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

enum { WALL_BOX, WALL_SEGMENT, WALL_CHAIN, WALL_KINDS };
enum { BODY_BOX, BODY_CIRCLE, BODY_CAPSULE, BODY_KINDS };

/* A static wall on the line x = 0: a 0.1 m thick box, a lone segment, or
   an open chain whose segment on x = 0 faces -x (its front, where the
   bodies come from) with a concave join above it and a convex one below. */
static void make_wall(ga2d_world *w, int kind)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id g = ga2d_body_create(w, &bd);
    if (kind == WALL_BOX) {
        ga2d_polygon p = ga2d_polygon_box((ga2d_real)0.05, (ga2d_real)WALL_HALF);
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, g, &sd, &p)));
    } else if (kind == WALL_SEGMENT) {
        ga2d_segment s = {{0, (ga2d_real)-WALL_HALF}, {0, (ga2d_real)WALL_HALF}};
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_segment(w, g, &sd, &s)));
    } else {
        /* point1 -> point2 upward along x = 0: its left, the front, is -x */
        ga2d_vec pts[4];
        ga2d_chain_def cd = ga2d_default_chain_def();
        pts[0] = ga2d_vec_make(1, (ga2d_real)-WALL_HALF - 1); /* convex join below */
        pts[1] = ga2d_vec_make(0, (ga2d_real)-WALL_HALF);
        pts[2] = ga2d_vec_make(0, (ga2d_real)WALL_HALF);
        pts[3] = ga2d_vec_make(-1, (ga2d_real)WALL_HALF + 1); /* concave join above */
        cd.points = pts;
        cd.count = 4;
        ga2d_chain_create(w, g, &cd);
        CHECK(ga2d_body_get_shapes(w, g, NULL, 0) == 3);
    }
}

static ga2d_body_id make_body(ga2d_world *w, int kind, double size, double speed, int phase)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id b;
    ga2d_real s = (ga2d_real)size;
    bd.type = GA2D_BODY_DYNAMIC;
    /* start 3 m off plus a fraction of a step's travel, so the wall is met at every point of a step */
    bd.position = ga2d_vec_make((ga2d_real)(-3 - speed / 60 * phase / PHASES), (ga2d_real)(0.01 * phase - 0.2));
    bd.velocity = ga2d_vec_make((ga2d_real)speed, 0);
    bd.angular_velocity = (ga2d_real)(phase - PHASES / 2); /* -20 to 19 rad/s */
    b = ga2d_body_create(w, &bd);
    if (kind == BODY_BOX) {
        ga2d_polygon p = ga2d_polygon_box(s / 2, s / 2);
        ga2d_shape_create_polygon(w, b, &sd, &p);
    } else if (kind == BODY_CIRCLE) {
        ga2d_circle c;
        c.center = ga2d_vec_make(0, 0);
        c.radius = s / 2;
        ga2d_shape_create_circle(w, b, &sd, &c);
    } else {
        ga2d_capsule c;
        c.center1 = ga2d_vec_make(-s / 4, 0);
        c.center2 = ga2d_vec_make(s / 4, 0);
        c.radius = s / 4;
        ga2d_shape_create_capsule(w, b, &sd, &c);
    }
    return b;
}

/* Whether the body's centre ever crosses x = 0 within the wall's span in
   2 s of flight and rebound (gravity off). */
static int passes(int wall, int body, double size, double speed, int phase, int continuous, int *swept)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id b;
    ga2d_vec prev, now;
    int i, crossed = 0;
    wd.gravity = ga2d_vec_make(0, 0);
    wd.enable_continuous = continuous;
    w = ga2d_world_create(&wd);
    make_wall(w, wall);
    b = make_body(w, body, size, speed, phase);
    prev = ga2d_body_center(w, b);
    for (i = 0; i < 120; ++i) {
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1.0 / 60), GA2D_OK);
        *swept += ga2d_world_get_counters(w).continuous_bodies;
        now = ga2d_body_center(w, b);
        /* the centre went from x < 0 to x >= 0 (or the wall's middle, for the box): where it crossed, within the span */
        if (prev.x < 0 && now.x >= 0) {
            double t = -(double)prev.x / ((double)now.x - (double)prev.x), y = (double)prev.y + t * ((double)now.y - (double)prev.y);
            if (fabs(y) < WALL_HALF) crossed = 1;
        }
        prev = now;
    }
    ga2d_world_destroy(w);
    return crossed;
}

/* Every wall, body, size and speed up to the cap, from 40 phases: none
   passes with continuous collision; without it, the table shows what the
   speculative contacts alone let through. */
static void fast_bodies_never_pass_walls(void)
{
    static const double speeds[] = {10, 50, 100, 300, GA2D_MAX_LINEAR_SPEED};
    static const double sizes[] = {0.05, 0.1};
    static const char *walls[] = {"0.1 m box", "lone segment", "chain"}, *bodies[] = {"box", "circle", "capsule"};
    int wall, body, si, vi, ph;
    for (wall = 0; wall < WALL_KINDS; ++wall)
        for (body = 0; body < BODY_KINDS; ++body)
            for (si = 0; si < 2; ++si) {
                int on[5], off[5], swept = 0, dummy = 0;
                for (vi = 0; vi < 5; ++vi) {
                    on[vi] = off[vi] = 0;
                    for (ph = 0; ph < PHASES; ++ph) {
                        on[vi] += passes(wall, body, sizes[si], speeds[vi], ph, 1, &swept);
                        if (verbose()) off[vi] += passes(wall, body, sizes[si], speeds[vi], ph, 0, &dummy);
                    }
                    CHECK(on[vi] == 0);
                }
                CHECK(swept > 0); /* the fast ones were swept */
                if (verbose())
                    printf("continuous: %s, %.2f m %s at 10/50/100/300/%g m/s: passed %d/%d/%d/%d/%d of %d (off: %d/%d/%d/%d/%d)\n",
                           walls[wall], sizes[si], bodies[body], GA2D_MAX_LINEAR_SPEED, on[0], on[1], on[2], on[3], on[4],
                           PHASES, off[0], off[1], off[2], off[3], off[4]);
            }
}

/* Nothing fast, nothing changes: a pyramid settling steps with the same
   bits with continuous collision on and off, and sweeps nothing. */
static uint64_t pyramid_hash(int continuous, int *swept)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id ids[64];
    uint64_t hash = 1469598103934665603u;
    int n = 0, row, i, step;
    wd.enable_continuous = continuous;
    w = ga2d_world_create(&wd);
    bd.polygon = ga2d_polygon_box(10, (ga2d_real)0.5);
    bd.position = ga2d_vec_make(0, -(ga2d_real)0.5);
    ga2d_body_create(w, &bd);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    for (row = 0; row < 8; ++row)
        for (i = 0; i < 8 - row; ++i) {
            bd.position = ga2d_vec_make((ga2d_real)(i - (8 - row) / 2.0 + 0.5), (ga2d_real)(0.5 + row * 1.05));
            ids[n++] = ga2d_body_create(w, &bd);
        }
    for (step = 0; step < 300; ++step) {
        ga2d_world_step(w, (ga2d_real)1.0 / 60);
        *swept += ga2d_world_get_counters(w).continuous_bodies;
    }
    for (i = 0; i < n; ++i) {
        ga2d_vec p = ga2d_body_position(w, ids[i]);
        ga2d_real a = ga2d_body_angle(w, ids[i]);
        unsigned char bytes[3 * sizeof(ga2d_real)];
        size_t k;
        memcpy(bytes, &p.x, sizeof p.x);
        memcpy(bytes + sizeof p.x, &p.y, sizeof p.y);
        memcpy(bytes + 2 * sizeof p.x, &a, sizeof a);
        for (k = 0; k < sizeof bytes; ++k) hash = (hash ^ bytes[k]) * 1099511628211u;
    }
    ga2d_world_destroy(w);
    return hash;
}

static void nothing_fast_same_bits(void)
{
    int swept_on = 0, swept_off = 0;
    uint64_t on = pyramid_hash(1, &swept_on), off = pyramid_hash(0, &swept_off);
    CHECK(on == off);
    CHECK(swept_on == 0 && swept_off == 0);
}

/* Bullets against moving bodies.  A bullet is swept against dynamic
   shapes too: a 5 cm disc at 100 to 400 m/s (1.7 to 6.7 m a step) at a
   free plank 5 cm thick and 2 m tall, 40 phases each, never gets its
   centre past the plank's midline within its span (in the plank's own
   frame: the plank is knocked away and turns); and two bullets head on
   at up to 400 m/s each (a closing speed of 13 m a step) never pass
   through each other: their order along the line never flips while they
   overlap across it.  Without the bullet flag (verbose) the counts show
   what the speculative contacts alone catch. */
static int bullet_passes_plank(double speed, int phase, int bullet)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_world *w;
    ga2d_body_id plank, shot;
    ga2d_circle c = {{0, 0}, (ga2d_real)0.025};
    double prev_x = -1;
    int i, crossed = 0;
    wd.gravity = ga2d_vec_make(0, 0);
    w = ga2d_world_create(&wd);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.025, 1);
    plank = ga2d_body_create(w, &bd);
    bd = ga2d_default_body_def();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.is_bullet = bullet;
    bd.position = ga2d_vec_make((ga2d_real)(-3 - speed / 60 * phase / PHASES), (ga2d_real)(0.02 * phase - 0.4));
    bd.velocity = ga2d_vec_make((ga2d_real)speed, 0);
    shot = ga2d_body_create(w, &bd);
    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, shot, &sd, &c)));
    for (i = 0; i < 60; ++i) {
        ga2d_vec local;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1.0 / 60), GA2D_OK);
        local = ga2d_body_local_point(w, plank, ga2d_body_center(w, shot));
        if (prev_x < 0 && local.x >= 0 && fabs((double)local.y) < 1) crossed = 1;
        prev_x = (double)local.x;
    }
    ga2d_world_destroy(w);
    return crossed;
}

static int bullets_pass_head_on(double speed, int phase, int bullet)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id b[2];
    ga2d_circle c = {{0, 0}, (ga2d_real)0.025};
    int i, k, flipped = 0;
    wd.gravity = ga2d_vec_make(0, 0);
    w = ga2d_world_create(&wd);
    for (k = 0; k < 2; ++k) {
        ga2d_body_def bd = ga2d_default_body_def();
        ga2d_shape_def sd = ga2d_default_shape_def();
        bd.type = GA2D_BODY_DYNAMIC;
        bd.is_bullet = bullet;
        /* 40 phases of where in a step they meet, and offsets across the line within 3 cm */
        bd.position = ga2d_vec_make((ga2d_real)(k ? 3 : -3 - speed / 60 * phase / PHASES), (ga2d_real)(k ? 0.0015 * (phase - PHASES / 2) : 0));
        bd.velocity = ga2d_vec_make((ga2d_real)(k ? -speed : speed), 0);
        b[k] = ga2d_body_create(w, &bd);
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b[k], &sd, &c)));
    }
    for (i = 0; i < 60; ++i) {
        ga2d_vec p0, p1;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1.0 / 60), GA2D_OK);
        p0 = ga2d_body_center(w, b[0]);
        p1 = ga2d_body_center(w, b[1]);
        /* still on crossing lines (within their 5 cm of each other across) and swapped */
        if (p0.x > p1.x && fabs((double)p0.y - (double)p1.y) < 0.05) flipped = 1;
    }
    ga2d_world_destroy(w);
    return flipped;
}

static void bullets_stop_at_moving_bodies(void)
{
    static const double speeds[] = {100, 200, GA2D_MAX_LINEAR_SPEED};
    int vi, ph;
    for (vi = 0; vi < 3; ++vi) {
        int plank = 0, head_on = 0, plank_off = 0, head_on_off = 0;
        for (ph = 0; ph < PHASES; ++ph) {
            plank += bullet_passes_plank(speeds[vi], ph, 1);
            head_on += bullets_pass_head_on(speeds[vi], ph, 1);
            if (verbose()) {
                plank_off += bullet_passes_plank(speeds[vi], ph, 0);
                head_on_off += bullets_pass_head_on(speeds[vi], ph, 0);
            }
        }
        CHECK(plank == 0);
        CHECK(head_on == 0);
        if (verbose())
            printf("continuous: bullets at %g m/s: through a free 5 cm plank %d of %d (not bullets: %d), "
                   "through each other head on %d of %d (not bullets: %d)\n",
                   speeds[vi], plank, PHASES, plank_off, head_on, PHASES, head_on_off);
    }
}

/* A fast body stopped at a wall reports its impact as any contact does,
   whether a speculative contact or continuous collision stopped it: a
   disc, a box or a capsule 10 cm across at 5 to 400 m/s, from 20 start
   phases (where in a step it arrives), straight at a static segment or a
   0.1 m box wall with hit events on: in 60 steps exactly one begin event
   and exactly one hit, at its approach speed.  Nothing but the wall acts
   on it (gravity 0, no spin, restitution 0), continuous collision keeps
   the velocity, and the wall's normal is exactly -x (a vertical segment;
   the box's face), so the approach is the speed to the rounding of a dot
   product and a difference (4 eps relative).  (A body stopped early in
   the step, its impulse relaxed to 0 by the last substep, was reported
   by none: 300 m/s into a segment, no hit.) */
static void stopped_body_reports_its_hit(void)
{
    static const double speeds[] = {5, 30, 100, 300, GA2D_MAX_LINEAR_SPEED};
    int vi, wall, body, ph, by_ccd = 0, runs = 0;
    double worst = 0;
    for (vi = 0; vi < 5; ++vi)
        for (wall = 0; wall < 2; ++wall)
            for (body = 0; body < BODY_KINDS; ++body)
                for (ph = 0; ph < 20; ++ph) {
                    ga2d_world_def wd = ga2d_default_world_def();
                    ga2d_body_def bd = ga2d_default_body_def();
                    ga2d_shape_def sd = ga2d_default_shape_def();
                    ga2d_world *w;
                    ga2d_body_id g, b;
                    ga2d_shape_id sh;
                    int i, begins = 0, hits = 0, ccd = 0;
                    double approach = 0;
                    wd.gravity = ga2d_vec_make(0, 0);
                    w = ga2d_world_create(&wd);
                    g = ga2d_body_create(w, &bd);
                    sd.enable_hit_events = 1;
                    if (wall == 0) {
                        ga2d_segment seg = {{0, -5}, {0, 5}};
                        sh = ga2d_shape_create_segment(w, g, &sd, &seg);
                    } else {
                        ga2d_polygon p = ga2d_polygon_box((ga2d_real)0.05, 5);
                        sh = ga2d_shape_create_polygon(w, g, &sd, &p);
                    }
                    CHECK(!ga2d_shape_id_is_null(sh));
                    bd.type = GA2D_BODY_DYNAMIC;
                    bd.position = ga2d_vec_make((ga2d_real)(-3.3 - speeds[vi] / 60 * ph / 20), (ga2d_real)(0.1 * ph - 1));
                    bd.velocity = ga2d_vec_make((ga2d_real)speeds[vi], 0);
                    b = ga2d_body_create(w, &bd);
                    if (body == BODY_BOX) {
                        ga2d_polygon p = ga2d_polygon_box((ga2d_real)0.05, (ga2d_real)0.05);
                        sh = ga2d_shape_create_polygon(w, b, &sd, &p);
                    } else if (body == BODY_CIRCLE) {
                        ga2d_circle c = {{0, 0}, (ga2d_real)0.05};
                        sh = ga2d_shape_create_circle(w, b, &sd, &c);
                    } else {
                        ga2d_capsule c = {{(ga2d_real)-0.025, 0}, {(ga2d_real)0.025, 0}, (ga2d_real)0.025};
                        sh = ga2d_shape_create_capsule(w, b, &sd, &c);
                    }
                    CHECK(!ga2d_shape_id_is_null(sh));
                    for (i = 0; i < 60; ++i) {
                        ga2d_contact_events ev;
                        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1.0 / 60), GA2D_OK);
                        ccd += ga2d_world_get_counters(w).continuous_hits;
                        ev = ga2d_world_contact_events(w);
                        begins += ev.begin_count;
                        hits += ev.hit_count;
                        if (ev.hit_count > 0) approach = (double)ev.hit[0].approach_speed;
                    }
                    CHECK(begins == 1);
                    CHECK(hits == 1);
                    CHECK_NEAR(approach, speeds[vi], 4 * speeds[vi] * REAL_EPS);
                    if (fabs(approach / speeds[vi] - 1) > worst) worst = fabs(approach / speeds[vi] - 1);
                    by_ccd += ccd > 0;
                    ++runs;
                    ga2d_world_destroy(w);
                }
    if (verbose())
        printf("continuous: %d walls hit at 5-400 m/s: one begin and one hit each, approach within %.3g of the speed; "
               "%d stopped by continuous collision, the rest by speculative contacts\n",
               runs, worst, by_ccd);
}

/* The switches: the world's and a body's bullet flag, with their errors. */
static void continuous_switches(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id b;
    bd.type = GA2D_BODY_DYNAMIC;
    CHECK(ga2d_default_world_def().enable_continuous == 1 && ga2d_default_body_def().is_bullet == 0);
    b = ga2d_body_create(w, &bd);
    CHECK(!ga2d_body_is_bullet(w, b));
    CHECK_RESULT(ga2d_body_set_bullet(w, b, 1), GA2D_OK);
    CHECK(ga2d_body_is_bullet(w, b));
    CHECK_RESULT(ga2d_body_set_bullet(w, ga2d_body_id_null(), 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_world_enable_continuous(w, 0), GA2D_OK);
    CHECK_RESULT(ga2d_world_enable_continuous(NULL, 0), GA2D_ERR_INVALID_ARGUMENT);
    ga2d_world_destroy(w);
}

void suite_continuous(void)
{
    test_run("continuous: fast bodies never pass walls", fast_bodies_never_pass_walls);
    test_run("continuous: nothing fast, the same bits", nothing_fast_same_bits);
    test_run("continuous: switches", continuous_switches);
    test_run("continuous: bullets stop at moving bodies", bullets_stop_at_moving_bodies);
    test_run("continuous: a stopped body reports its hit", stopped_body_reports_its_hit);
}
