/* Correct at the extremes (issue 8): scale, distance from the origin,
   long runs and absurd coordinates.

   - A pyramid of 10-box base stands 5 s alike with boxes of 1 m, 1/128 m,
     128 m, 0.01 m and 100 m, when the world's length unit
     (length_units_per_meter) and gravity are scaled to match.
   - A pyramid far from the origin ((1e4, 1e4) in float, (1e6, 1e6) in
     double) moves as the same pyramid at the origin, within what the
     spacing of representable positions out there allows.
   - A body spinning for 10^7 steps keeps a unit rotor.
   - Polygons with coordinates of 1e30, 1e-30, NaN or infinity get the
     results the header promises.

   eps is the build's machine epsilon (REAL_EPS); ulp(X) = eps 2^floor(log2
   X), the spacing of representable numbers near X.  With
   GA2D_TEST_VERBOSE set every measured figure is printed next to its
   bound. */
#include "test.h"

#define BASE 10
#define PYR_COUNT (BASE * (BASE + 1) / 2)
#define SECONDS 5
#define STEPS (SECONDS * 60)

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

/* ---------------------------------------------------------------- pyramid */
/* The pyramid in units of the box size s, placed at (ox, oy): a static
   ground of half-extents 20 s x s whose top is at y = oy, then rows of
   boxes of side s.  Sleep is off so that the solver works for the whole
   run.  Gravity is 10 s units/s^2 (10 m/s^2 in the world's metre) and the
   length unit is s per metre, so the scene is the 1 m scene with every
   length times s.  Reports each box's final displacement from its start
   divided by s, and the largest displacement of any box at any step. */
typedef struct pyramid_run {
    double dx[PYR_COUNT], dy[PYR_COUNT]; /* final displacement / s */
    double px[PYR_COUNT], py[PYR_COUNT]; /* path: sum of |moves| per step, / s */
    double any;                          /* max over boxes and steps, / s */
    int step_errors;
} pyramid_run;

static void run_pyramid(double s, double ox, double oy, pyramid_run *out)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d = ga2d_default_body_def();
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    ga2d_body_id ids[PYR_COUNT];
    ga2d_vec start[PYR_COUNT];
    ga2d_world *w;
    int i, j, k = 0, t;
    memset(out, 0, sizeof *out);
    wd.length_units_per_meter = (ga2d_real)s;
    wd.gravity = ga2d_vec_make(0, (ga2d_real)(-10 * s));
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    d.position = ga2d_vec_make((ga2d_real)ox, (ga2d_real)(oy - s));
    d.polygon = ga2d_polygon_box((ga2d_real)(20 * s), (ga2d_real)s);
    CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &d)));
    for (i = 0; i < BASE; ++i)
        for (j = i; j < BASE; ++j) {
            double x = ((i + 1) * 0.5 + (j - i) - BASE / 2.0) * s + ox, y = (i + 0.5) * s + oy;
            d = ga2d_default_body_def();
            d.type = GA2D_BODY_DYNAMIC;
            d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
            d.polygon = ga2d_polygon_box((ga2d_real)(0.5 * s), (ga2d_real)(0.5 * s));
            ids[k] = ga2d_body_create(w, &d);
            CHECK(!ga2d_body_id_is_null(ids[k]));
            start[k] = d.position;
            ++k;
        }
    for (t = 0; t < STEPS; ++t) {
        ga2d_vec before[PYR_COUNT];
        for (k = 0; k < PYR_COUNT; ++k) before[k] = ga2d_body_position(w, ids[k]);
        out->step_errors += ga2d_world_step(w, (ga2d_real)(1.0 / 60)) != GA2D_OK;
        for (k = 0; k < PYR_COUNT; ++k) {
            ga2d_vec p = ga2d_body_position(w, ids[k]);
            double m = hypot((double)p.x - (double)start[k].x, (double)p.y - (double)start[k].y) / s;
            out->any = m > out->any ? m : out->any;
            out->px[k] += fabs((double)p.x - (double)before[k].x) / s;
            out->py[k] += fabs((double)p.y - (double)before[k].y) / s;
        }
    }
    for (k = 0; k < PYR_COUNT; ++k) {
        ga2d_vec p = ga2d_body_position(w, ids[k]);
        out->dx[k] = ((double)p.x - (double)start[k].x) / s;
        out->dy[k] = ((double)p.y - (double)start[k].y) / s;
    }
    ga2d_world_destroy(w);
}

static double top_drift(const pyramid_run *r) { return hypot(r->dx[PYR_COUNT - 1], r->dy[PYR_COUNT - 1]); }

/* Bounds, all relative to the box size (so they hold at every scale):
   - the top box moves less than 0.05: the soft contacts and the linear
     slop (0.005 m per metre of length unit) let each of the 10 rows below
     it settle by about the slop, 10 x 0.005 = 0.05, and nothing pushes it
     sideways;
   - no box moves by 0.5 at any step: each rests on two boxes, overlapping
     each by half its width, and a box moved by half its width would have
     lost one (as in the solver suite's pyramid).
   Scale: every length in the step scales with length_units_per_meter
   (slop, speculative distance, AABB margin, velocity cap, push velocity,
   restitution threshold, sleep threshold), gravity was scaled, masses
   scale as s^2 and inertias as s^4, times do not scale; so the scaled
   scene is the 1 m scene in other units.  For s a power of two every
   product and sum is the 1 m one times a power of two, exactly (no
   result comes near the subnormal or overflow range): the runs are
   bit-identical after dividing by s.  For s = 0.01 and 100 each input is
   the scaled 1 m input with one rounding (eps/2), which can flip isolated
   discrete choices of the solver (a friction clamp, a point at the edge
   of the speculative margin), not the creep itself, which is set by the
   contacts' compliance and the slop and scales exactly: the drift stays
   within a factor of 2 of the 1 m drift (a flip changes at most the share
   of one contact among the ten rows'). */
static void pyramid_scales(void)
{
    static const double scales[5] = {1, 1.0 / 128, 128, 0.01, 100};
    static pyramid_run runs[5];
    double d1;
    int i, k;
    for (i = 0; i < 5; ++i) run_pyramid(scales[i], 0, 0, &runs[i]);
    d1 = top_drift(&runs[0]);
    for (i = 0; i < 5; ++i) {
        double di = top_drift(&runs[i]);
        CHECK(runs[i].step_errors == 0);
        CHECK(di < 0.05);
        CHECK(runs[i].any < 0.5);
        if (i == 1 || i == 2) {
            int same = 1;
            for (k = 0; k < PYR_COUNT; ++k) same &= runs[i].dx[k] == runs[0].dx[k] && runs[i].dy[k] == runs[0].dy[k];
            CHECK(same);
        } else if (i > 2) {
            CHECK(di <= 2 * d1 && di >= d1 / 2);
        }
        if (verbose())
            printf("extremes: pyramid%d of %g m boxes (units %g per m), %d s: top drift %.3g of a box (bound 0.05, "
                   "1 m run %.3g%s), any box at most %.3g (bound 0.5)\n",
                   BASE, scales[i], scales[i], SECONDS, di, d1,
                   (i == 1 || i == 2) ? ", bit-identical expected" : (i > 2 ? ", within x2 expected" : ""), runs[i].any);
    }
}

/* ulp(x) for |x| >= the smallest normal number */
static double ulp_of(double x)
{
    int e;
    frexp(fabs(x), &e); /* |x| = m 2^e, m in [0.5, 1) */
    return REAL_EPS * ldexp(1.0, e - 1);
}

/* The pyramid at (X, X) against the one at the origin, box by box.  The
   narrowphase and the solver work on differences of nearby positions
   (exact for numbers within a factor of 2 of each other) and on anchors
   relative to the bodies, so far from the origin they see what they see
   at it, except that each stored position is a multiple of ulp(X):
   - every position update x += v h rounds by up to ulp(X)/2, and one
     smaller than that is lost: over the run's N = 4 x 300 substeps a box
     ends off by at most min(its path, N ulp(X)/2), its path being what
     the origin box travels (summed once per step; a factor 2 covers
     reversals within a step);
   - a box sits on at most BASE rows of contacts, each row's separation
     set between two quantized positions: BASE ulp(X) more.
   Per component, against the origin pyramid (whose own rounding at
   |x| <= 11 is 2^-20 of ulp(X) or less).  X = 1e4 in float: ulp = 2^-10
   = 0.98 mm (creep below ulp/2 per substep is lost); X = 1e6 in double:
   ulp = 2^-33 = 1.2e-10 m, N ulp/2 = 7e-8 m. */
static void pyramid_far_away(void)
{
#ifdef GA2D_DOUBLE
    const double X = 1e6;
#else
    const double X = 1e4;
#endif
    static pyramid_run far, near;
    double worst = 0, worst_bound = 0, u = ulp_of(X + 11); /* coordinates stay in [X - 10, X + 11]: one binade */
    int k, within = 1;
    run_pyramid(1, X, X, &far);
    run_pyramid(1, 0, 0, &near);
    CHECK(far.step_errors == 0 && near.step_errors == 0);
    for (k = 0; k < PYR_COUNT; ++k) {
        double bx = fmin(2 * near.px[k], STEPS * 4 * u / 2) + BASE * u;
        double by = fmin(2 * near.py[k], STEPS * 4 * u / 2) + BASE * u;
        double ex = fabs(far.dx[k] - near.dx[k]), ey = fabs(far.dy[k] - near.dy[k]);
        within &= ex <= bx && ey <= by;
        if (ex / bx > worst / (worst_bound > 0 ? worst_bound : 1)) {
            worst = ex;
            worst_bound = bx;
        }
        if (ey / by > worst / (worst_bound > 0 ? worst_bound : 1)) {
            worst = ey;
            worst_bound = by;
        }
    }
    CHECK(within);
    CHECK(top_drift(&far) < 0.05 && far.any < 0.5);
    if (verbose())
        printf("extremes: pyramid%d at (%g, %g) vs at the origin, %d s: closest to its bound, a box differs by %.3g m "
               "(bound %.3g m; ulp %.3g m); top drift %.3g m here, %.3g m at the origin\n",
               BASE, X, X, SECONDS, worst, worst_bound, u, top_drift(&far), top_drift(&near));
}

/* ------------------------------------------------------------------- spin */
/* One body spinning freely (no gravity, no contact) for 10^7 steps of
   4 substeps: 4e7 rotor updates.  The exact update multiplies by the
   series exp(w h e12) (|e| = 1 within about 2 eps: truncated below eps/2,
   Horner's rounding) and the product rounds by under 1.5 eps, so
   |r| = |q| (1 + x) with |x| <= 4 eps; then the Newton step r (3 -
   |r|^2)/2 maps a norm of 1 + y to 1 - 3 y^2/2 + O(y^3) and rounds by
   under 3 eps (|r|^2: 1.5 eps, 3 - |r|^2: eps, the product: eps/2).  So if
   ||q| - 1| <= 3 eps before, ||r| - 1| <= 7 eps and after the Newton step
   ||q| - 1| <= 3 eps + 1.5 (7 eps)^2: it never accumulates.  We allow
   8 eps, under the 1e-6 in float (9.5e-7) as in double.
   The linear update divides by the norm each time: within 2 eps.
   Runtime: about 0.2 us a step optimized, 4x that under the sanitizers,
   so the sanitizer builds run 10^6 steps (the bound does not depend on
   the count: the error does not accumulate). */
#if defined(__SANITIZE_ADDRESS__)
#define SPIN_STEPS 1000000L
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SPIN_STEPS 1000000L
#endif
#endif
#ifndef SPIN_STEPS
#define SPIN_STEPS 10000000L
#endif

static double spin(ga2d_rotation_update mode, long steps, double omega)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d = ga2d_default_body_def();
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    ga2d_world *w;
    ga2d_body_id id;
    double worst = 0;
    long i;
    int errors = 0;
    wd.gravity = ga2d_vec_make(0, 0);
    wd.enable_sleep = 0;
    wd.rotation_update = mode;
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return 1;
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box(1, (ga2d_real)0.5);
    d.angular_velocity = (ga2d_real)omega;
    id = ga2d_body_create(w, &d);
    for (i = 0; i < steps; ++i) {
        ga2d_rotor q;
        double e;
        errors += ga2d_world_step(w, (ga2d_real)(1.0 / 60)) != GA2D_OK;
        q = ga2d_body_rotor(w, id);
        e = fabs(sqrt((double)q.c * (double)q.c + (double)q.s * (double)q.s) - 1);
        worst = e > worst ? e : worst;
    }
    CHECK(errors == 0);
    /* it kept spinning at the speed it was given (nothing damps it) */
    CHECK(ga2d_body_angular_velocity(w, id) == (ga2d_real)omega);
    ga2d_world_destroy(w);
    return worst;
}

static void long_spin(void)
{
    /* 7 rad/s: 0.029 rad per substep, the series' range; the rotor
       passes every angle many times (7 x 1.7e5 s / 2 pi turns) */
    double exact = spin(GA2D_ROTATION_EXACT, SPIN_STEPS, 7.0);
    double linear = spin(GA2D_ROTATION_LINEAR, SPIN_STEPS / 100, 7.0);
    CHECK(exact <= 8 * REAL_EPS);
    CHECK(exact <= 1e-6);
    CHECK(linear <= 8 * REAL_EPS);
    if (verbose())
        printf("extremes: %ld steps of a spinning body: max ||q| - 1| = %.3g = %.2f eps (bound 8 eps = %.3g, issue 1e-6); "
               "linear update over %ld steps: %.2f eps\n",
               SPIN_STEPS, exact, exact / REAL_EPS, 8 * REAL_EPS, SPIN_STEPS / 100, linear / REAL_EPS);
}

/* -------------------------------------------------------------- polygons */
static ga2d_result make_box(double h, ga2d_polygon *out)
{
    ga2d_vec p[4];
    p[0] = ga2d_vec_make((ga2d_real)-h, (ga2d_real)-h);
    p[1] = ga2d_vec_make((ga2d_real)h, (ga2d_real)-h);
    p[2] = ga2d_vec_make((ga2d_real)h, (ga2d_real)h);
    p[3] = ga2d_vec_make((ga2d_real)-h, (ga2d_real)h);
    return ga2d_polygon_make(p, 4, out);
}

/* The same points through ga2d_body_def_validate (a hand-filled polygon
   is validated again from its vertices): the same result. */
static ga2d_result via_body(double h)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.polygon.count = 4;
    d.polygon.vertices[0] = ga2d_vec_make((ga2d_real)-h, (ga2d_real)-h);
    d.polygon.vertices[1] = ga2d_vec_make((ga2d_real)h, (ga2d_real)-h);
    d.polygon.vertices[2] = ga2d_vec_make((ga2d_real)h, (ga2d_real)h);
    d.polygon.vertices[3] = ga2d_vec_make((ga2d_real)-h, (ga2d_real)h);
    return ga2d_body_def_validate(&d);
}

/* The header's promises, in its order of checks:
   - NaN or an infinity anywhere: NOT_FINITE (checked before size);
   - |coordinate| > GA2D_MAX_COORDINATE: TOO_LARGE.  In float that bound
     is where the mass's 4th-power sums keep room for densities up to 1e6;
     in double it is the 1e15 policy bound (well inside that room), so in
     both a box at exactly the bound is accepted and its mass at density
     1e6 is finite, and 1e30 is beyond it;
   - an extent L below GA2D_MIN_EXTENT (double: 1e-15) or so small that
     1e-5 L^2 is below the smallest normal number (float L < 2.4e-17):
     DEGENERATE.  A box of half-side 1e-30 is that in both precisions;
   - a 1e-30 or 1e30 coordinate in an otherwise unit polygon is a repeated
     point (its vertex coincides with another within 64 eps L). */
static void extreme_coordinates(void)
{
    ga2d_polygon p, untouched;
    ga2d_mass m;
    ga2d_vec tri[3];
    double max = (double)GA2D_MAX_COORDINATE;
    memset(&untouched, 0x5A, sizeof untouched);

    p = untouched;
    CHECK_RESULT(make_box((double)NAN, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(make_box((double)INFINITY, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(via_body((double)NAN), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(via_body((double)INFINITY), GA2D_ERR_NOT_FINITE);
    CHECK(memcmp(&p, &untouched, sizeof p) == 0);
    tri[0] = ga2d_vec_make(0, 0);
    tri[1] = ga2d_vec_make(1, 0);
    tri[2] = ga2d_vec_make((ga2d_real)NAN, 1);
    CHECK_RESULT(ga2d_polygon_make(tri, 3, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_hull(tri, 3, &p), GA2D_ERR_NOT_FINITE);
    tri[2] = ga2d_vec_make(0, (ga2d_real)-INFINITY);
    CHECK_RESULT(ga2d_polygon_make(tri, 3, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_hull(tri, 3, &p), GA2D_ERR_NOT_FINITE);
    CHECK(memcmp(&p, &untouched, sizeof p) == 0);

    /* the largest coordinate: accepted, with room for density 1e6 */
    CHECK_RESULT(make_box(max, &p), GA2D_OK);
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, (ga2d_real)1e6, &m), GA2D_OK);
    CHECK(isfinite((double)m.mass) && isfinite((double)m.inertia) && m.mass > 0 && m.inertia > 0);
    p = untouched;
#ifdef GA2D_DOUBLE
    CHECK_RESULT(make_box(nextafter(max, 2 * max), &p), GA2D_ERR_TOO_LARGE);
#else
    CHECK_RESULT(make_box((double)nextafterf((float)max, (float)(2 * max)), &p), GA2D_ERR_TOO_LARGE);
#endif
    CHECK(memcmp(&p, &untouched, sizeof p) == 0);
    p = untouched;
    CHECK_RESULT(make_box(1e30, &p), GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(via_body(1e30), GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(make_box(1e-30, &p), GA2D_ERR_DEGENERATE);
    CHECK_RESULT(via_body(1e-30), GA2D_ERR_DEGENERATE);
    CHECK(memcmp(&p, &untouched, sizeof p) == 0);
#ifdef GA2D_DOUBLE
    /* just above the smallest extent: an ordinary (scale-free) box */
    CHECK_RESULT(make_box(1e-14, &p), GA2D_OK);
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, 1, &m), GA2D_OK);
    CHECK(m.mass > 0 && m.inertia > 0 && isfinite(1 / (double)m.inertia));
#endif
    {
        ga2d_vec cloud[4];
        cloud[0] = ga2d_vec_make(0, 0);
        cloud[1] = ga2d_vec_make((ga2d_real)1e-30, 0);
        cloud[2] = ga2d_vec_make(0, (ga2d_real)1e-30);
        cloud[3] = ga2d_vec_make((ga2d_real)1e-30, (ga2d_real)1e-30);
        CHECK_RESULT(ga2d_polygon_hull(cloud, 4, &p), GA2D_ERR_DEGENERATE);
    }
    /* a 1e-30 vertex by another at the origin of a unit triangle: repeated */
    tri[0] = ga2d_vec_make(0, 0);
    tri[1] = ga2d_vec_make(1, 0);
    tri[2] = ga2d_vec_make((ga2d_real)1e-30, (ga2d_real)1e-30);
    CHECK_RESULT(ga2d_polygon_make(tri, 3, &p), GA2D_ERR_REPEATED_POINTS);
    /* 1e30 in a unit triangle: too large (the size check comes first) */
    tri[2] = ga2d_vec_make(0, (ga2d_real)1e30);
    CHECK_RESULT(ga2d_polygon_make(tri, 3, &p), GA2D_ERR_TOO_LARGE);
}

void suite_extremes(void)
{
    test_run("extremes: pyramids of 0.01 m and 100 m boxes stand like 1 m boxes", pyramid_scales);
    test_run("extremes: a pyramid far from the origin moves as one at it", pyramid_far_away);
    test_run("extremes: a long spin keeps a unit rotor", long_spin);
    test_run("extremes: 1e30, 1e-30, NaN and infinite coordinates", extreme_coordinates);
}
