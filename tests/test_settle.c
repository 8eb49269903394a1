/* A resting pile settles to rounding (issue 23, finding 8b): one point
   where a clip's two ends coincide along the face, and the poured pile
   that never settled in float (warm starting by place, ga2d__warm_points,
   is what its seed 7 needs); and float far from the origin (8d). */
#include "test.h"

/* ------------------------------------------------- one point, not two */
/* A segment of length L stands on a wide box's top face (y = 0), tilted
   by a from the vertical, its lower end 1 mm deep: both ends are within
   the speculative margin (L < 4 slop), and the incident edge is the
   segment.  Its ends lie L sin(a) apart along the face: within 0.1 slop
   they are one point, the lower (its separation, -1 mm); beyond, two.
   Swept over L and a, both argument orders (the manifold seen from the
   segment is the same points). */
static void clip_ends_that_coincide_are_one_point(void)
{
    const double slop = GA2D_LINEAR_SLOP, depth = 1e-3;
    /* the ends' rounding in the box's frame: eps of the 2 cm they span */
    const double round = 64 * REAL_EPS * 0.02;
    ga2d_geometry box, seg;
    int il, ia, order;
    memset(&box, 0, sizeof box);
    memset(&seg, 0, sizeof seg);
    box.type = GA2D_SHAPE_POLYGON;
    box.as.polygon = ga2d_polygon_box(1, 0.5);
    seg.type = GA2D_SHAPE_SEGMENT;
    for (il = 1; il <= 3; ++il) {
        double L = il * 0.005; /* 5, 10, 15 mm: inside the 20 mm margin */
        for (ia = 0; ia <= 30; ++ia) {
            double a = 0.3 * ia / 30.0, along = L * sin(a);
            ga2d_transform xbox = ga2d_transform_make(ga2d_vec_make(0, -0.5), ga2d_rotor_identity());
            ga2d_transform xseg = ga2d_transform_identity();
            seg.as.segment.point1 = ga2d_vec_make(0, (ga2d_real)-depth);
            seg.as.segment.point2 = ga2d_vec_make((ga2d_real)along, (ga2d_real)(L * cos(a) - depth));
            for (order = 0; order < 2; ++order) {
                ga2d_manifold m;
                int n = order ? ga2d_collide_shapes(&seg, xseg, &box, xbox, &m) : ga2d_collide_shapes(&box, xbox, &seg, xseg, &m);
                if (along <= 0.1 * slop - round) {
                    CHECK(n == 1);
                    if (n == 1) CHECK_NEAR(m.points[0].separation, -depth, round);
                } else if (along >= 0.1 * slop + round) {
                    CHECK(n == 2);
                }
            }
        }
    }
}

/* ---------------------------------------------------------- the pile */
/* 100 shapes poured into a bin (as bench_scenes' mixed_pile, smaller):
   floor top y = 0, walls inside x = +-5, 8 m high; waves of 10 every 30
   steps from y = 7, 1 m apart (+-0.05), a random angle, falling at
   10 m/s; a circle (r 0.2-0.35), a capsule (half 0.12-0.25, r 0.1-0.18),
   a box (half-extents 0.15-0.3) or a regular 3- to 8-gon (circumradius
   0.2-0.35, rounded 0.04) as the generator says.  Density 1, friction
   0.6, defaults, sleep off. */
#define SETTLE_N 100
#define SETTLE_PER 10
#define SETTLE_EVERY 30
#define SETTLE_W 5.0

static double settle_uniform(unsigned long *r, double lo, double hi)
{
    *r = (*r * 1664525UL + 1013904223UL) & 0xFFFFFFFFUL;
    return lo + (hi - lo) * (double)(*r >> 8) / 16777216.0;
}

static void settle_static_box(ga2d_world *w, double x, double y, double hx, double hy)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    d.friction = (ga2d_real)0.6;
    CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &d)));
}

static ga2d_body_id settle_drop(ga2d_world *w, int i, unsigned long *r)
{
    const double pi = 3.14159265358979323846;
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    double x = -SETTLE_W + 0.5 + i % SETTLE_PER + settle_uniform(r, -0.05, 0.05), a = 0, b = 0, radius = 0;
    int kind = (int)settle_uniform(r, 0, 4), n = 0, v;
    ga2d_vec pts[8];
    ga2d_body_id id;
    /* the shape's numbers first, then the angle: the drivers' order */
    if (kind == 0) {
        radius = settle_uniform(r, 0.2, 0.35);
    } else if (kind == 1) {
        a = settle_uniform(r, 0.12, 0.25);
        radius = settle_uniform(r, 0.1, 0.18);
    } else if (kind == 2) {
        a = settle_uniform(r, 0.15, 0.3);
        b = settle_uniform(r, 0.15, 0.3);
    } else {
        double core;
        n = 3 + (int)settle_uniform(r, 0, 6);
        radius = 0.04;
        core = settle_uniform(r, 0.2, 0.35) - radius;
        for (v = 0; v < n; ++v)
            pts[v] = ga2d_vec_make((ga2d_real)(core * cos(2 * pi * v / n)), (ga2d_real)(core * sin(2 * pi * v / n)));
    }
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)x, 7);
    d.rotor = ga2d_rotor_from_angle((ga2d_real)settle_uniform(r, -pi, pi));
    d.velocity = ga2d_vec_make(0, -10);
    d.friction = (ga2d_real)0.6;
    sd.friction = (ga2d_real)0.6;
    if (kind == 2) d.polygon = ga2d_polygon_box((ga2d_real)a, (ga2d_real)b);
    id = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(id));
    if (kind == 0) {
        ga2d_circle c;
        c.center = ga2d_vec_make(0, 0);
        c.radius = (ga2d_real)radius;
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, id, &sd, &c)));
    } else if (kind == 1) {
        ga2d_capsule c;
        c.center1 = ga2d_vec_make((ga2d_real)-a, 0);
        c.center2 = ga2d_vec_make((ga2d_real)a, 0);
        c.radius = (ga2d_real)radius;
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_capsule(w, id, &sd, &c)));
    } else if (kind == 3) {
        ga2d_polygon p;
        CHECK_RESULT(ga2d_polygon_make(pts, n, &p), GA2D_OK);
        p.radius = (ga2d_real)radius;
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, id, &sd, &p)));
    }
    return id;
}

/* The pile of `seed` for `steps`: the fastest body over the last 10 s and
   the farthest one moved over them. */
static void settle_pile(unsigned long seed, int steps, double *vmax, double *drift)
{
    const int last = 600;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id ids[SETTLE_N];
    ga2d_vec p0[SETTLE_N];
    unsigned long r = seed;
    int s, i, made = 0;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    *vmax = *drift = 0;
    if (!w) {
        CHECK(w != NULL);
        return;
    }
    settle_static_box(w, 0, -0.25, SETTLE_W + 0.5, 0.25);
    settle_static_box(w, -SETTLE_W - 0.25, 4, 0.25, 4);
    settle_static_box(w, SETTLE_W + 0.25, 4, 0.25, 4);
    for (s = 0; s < steps; ++s) {
        while (made < SETTLE_N && (made / SETTLE_PER) * SETTLE_EVERY == s) {
            ids[made] = settle_drop(w, made, &r);
            ++made;
        }
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        if (s == steps - last - 1)
            for (i = 0; i < SETTLE_N; ++i) p0[i] = ga2d_body_position(w, ids[i]);
        if (s >= steps - last)
            for (i = 0; i < made; ++i) {
                ga2d_vec v = ga2d_body_velocity(w, ids[i]);
                double sp = sqrt((double)v.x * (double)v.x + (double)v.y * (double)v.y);
                if (sp > *vmax) *vmax = sp;
            }
    }
    for (i = 0; i < SETTLE_N; ++i) {
        ga2d_vec p = ga2d_body_position(w, ids[i]);
        double dx = (double)p.x - (double)p0[i].x, dy = (double)p.y - (double)p0[i].y, d = sqrt(dx * dx + dy * dy);
        if (d > *drift) *drift = d;
    }
    ga2d_world_destroy(w);
}

/* The pile comes to rest to rounding.  Every coordinate in the bin is
   below 8 m, so a position rounds by at most u/2 with u = 4 eps (the ulp
   of [4, 8)), once a step (the substeps' motion is summed apart,
   ga2d__drift): a contact's two bodies stand off by up to u from where
   the solver left them.  A contact is a spring of at most 2 x
   contact_hertz (a static partner's stiffer one, 90 Hz) that the solver
   holds overdamped: a displacement x kicks it to at most omega x.  So a
   body at rest moves at below vmax = 2 pi 90 Hz x u (2.7e-4 m/s in
   float, 5e-13 in double), and by at most u a step over the last 10 s
   (both coordinates by u/2): 600 u (0.29 mm in float).  Before the
   fixes, seed 7 (the pile) kept a capsule in a 16-step cycle at
   1.6e-2 m/s, and seed 23 a box kicked every hundred steps at 1e-2 (3e-3
   with warm starting by place alone); 10 000 steps is past where both
   began.  In double, seed 7 leaves a capsule on one point of another
   tilted at 30.96 degrees: tan = 0.6001 against friction 0.6, on the edge
   of the cone.  It holds to rounding until step 9000, then slides off,
   rightly (once it slips the slope only steepens: its turn grows by e
   every 13 steps, with no sign change, as a tipping body's does), and the
   pile rests to rounding again from step 9650: double runs 12 000 steps,
   judged over the last 10 s as float. */
static void poured_pile_settles(void)
{
#ifdef GA2D_DOUBLE
    /* seed 23 leaves a ball rolling along a level stretch at a constant
       4e-5 m/s in double, rightly (nothing slows a rolling ball) */
    static const unsigned long seeds[] = {7};
#else
    static const unsigned long seeds[] = {7, 23};
#endif
    const double u = 4 * REAL_EPS, omega = 2 * 3.14159265358979323846 * 2 * GA2D_DEFAULT_CONTACT_HERTZ;
    const double vbound = omega * u, dbound = 600 * u;
    size_t k;
    for (k = 0; k < sizeof seeds / sizeof seeds[0]; ++k) {
        double vmax, drift;
#ifdef GA2D_DOUBLE
        settle_pile(seeds[k], 12000, &vmax, &drift);
#else
        settle_pile(seeds[k], 10000, &vmax, &drift);
#endif
        if (!(vmax <= vbound)) test_fail(__FILE__, __LINE__, "seed %lu: last 10 s max speed %.3g > %.3g m/s", seeds[k], vmax, vbound);
        if (!(drift <= dbound)) test_fail(__FILE__, __LINE__, "seed %lu: drift over the last 10 s %.3g > %.3g m", seeds[k], drift, dbound);
    }
}

/* ------------------------------------------------ far from the origin */
/* The ulp of x in ga2d_real: the spacing of the reals at |x|. */
static double settle_ulp(double x)
{
    int e;
    (void)frexp(x, &e);
    return ldexp(REAL_EPS, e - 1);
}

/* A disc (r 0.5) rolling at 2 m/s without slipping on a static box whose
   top is y = 0 and whose centre is at x = X (the README's table, from
   x = X - 10, for 10 s), and a 1 m box resting at X + 30: the rolling
   error (distance / (v T) - 1), the disc's deepest sinking after the
   first second, the box's farthest move over the last 5 s. */
static void settle_far(double X, double *roll, double *sink, double *box_moved)
{
    const double v0 = 2, r = 0.5, T = 10;
    const int steps = 600;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_def d;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_body_id disc, box;
    ga2d_vec x0, b0 = ga2d_vec_make(0, 0);
    int s;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    *roll = *sink = *box_moved = 0;
    if (!w) {
        CHECK(w != NULL);
        return;
    }
    d = ga2d_default_body_def();
    d.position = ga2d_vec_make((ga2d_real)X, (ga2d_real)-0.5);
    d.polygon = ga2d_polygon_box(50, (ga2d_real)0.5);
    d.friction = (ga2d_real)0.6;
    CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &d)));
    d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)(X - 10), (ga2d_real)r);
    d.velocity = ga2d_vec_make((ga2d_real)v0, 0);
    d.angular_velocity = (ga2d_real)(-v0 / r);
    disc = ga2d_body_create(w, &d);
    sd.friction = (ga2d_real)0.6;
    c.center = ga2d_vec_make(0, 0);
    c.radius = (ga2d_real)r;
    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, disc, &sd, &c)));
    d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)(X + 30), (ga2d_real)0.5);
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.friction = (ga2d_real)0.6;
    box = ga2d_body_create(w, &d);
    x0 = ga2d_body_position(w, disc);
    for (s = 0; s < steps; ++s) {
        ga2d_vec p;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        p = ga2d_body_position(w, disc);
        if (s >= 60 && r - (double)p.y > *sink) *sink = r - (double)p.y;
        if (s == steps / 2 - 1) b0 = ga2d_body_position(w, box);
        if (s >= steps / 2) {
            ga2d_vec q = ga2d_body_position(w, box);
            double m = fabs((double)q.x - (double)b0.x) + fabs((double)q.y - (double)b0.y);
            if (m > *box_moved) *box_moved = m;
        }
    }
    *roll = ((double)ga2d_body_position(w, disc).x - (double)x0.x) / (v0 * T) - 1;
    ga2d_world_destroy(w);
}

/* Far from the origin the positions round to the ulp u of x, once per
   step (ga2d__drift sums the substeps apart): a disc moving v dt = 33 mm
   a step is off by at most u/2 a step, so its rolling error departs from
   the one it has at the origin by at most u / (2 v dt) (float: 0.09 % at
   1e3 m, 1.5 % at 1e4, 12 % at 1e5; past v dt = u/2, from 2^20 m in
   float, it cannot move at all: the README's range).  Everything else is relative
   (the narrowphase and the solver subtract the two bodies' positions
   first), so the disc sinks no deeper than a slop at any x; and the
   resting box does not move at all: its speed is the rounding left of
   g h = 0.04 m/s against its contact, a few eps of that, and that times
   h is far below half an ulp of its y = 0.5 (and of its x). */
static void far_from_origin_rolls_within_rounding(void)
{
    static const double xs[] = {1e3, 1e4, 3e4, 1e5, 1e6};
    const double vdt = 2.0 / 60;
    double roll0, sink0, moved0;
    size_t k;
    settle_far(0, &roll0, &sink0, &moved0);
    CHECK(sink0 <= GA2D_LINEAR_SLOP);
    CHECK(moved0 == 0);
    for (k = 0; k < sizeof xs / sizeof xs[0]; ++k) {
        double roll, sink, moved, bound = settle_ulp(xs[k] + 10) / (2 * vdt);
        settle_far(xs[k], &roll, &sink, &moved);
        if (bound < 1 && !(fabs(roll - roll0) <= bound))
            test_fail(__FILE__, __LINE__, "x = %g: rolling error %.3g departs from the origin's %.3g by more than u/(2 v dt) = %.3g",
                      xs[k], roll, roll0, bound);
        if (!(sink <= GA2D_LINEAR_SLOP)) test_fail(__FILE__, __LINE__, "x = %g: the disc sank %.3g m", xs[k], sink);
        if (!(moved == 0)) test_fail(__FILE__, __LINE__, "x = %g: the resting box moved %.3g m", xs[k], moved);
    }
}

void suite_settle(void)
{
    test_run("settle: a clip's two ends within 0.1 slop along the face are one point, the deeper",
             clip_ends_that_coincide_are_one_point);
    test_run("settle: 100 mixed shapes poured into a bin rest to rounding (speed and drift over the last 10 s)",
             poured_pile_settles);
    test_run("settle: far from the origin a disc rolls within the positions' rounding, does not sink, a box rests",
             far_from_origin_rolls_within_rounding);
}
