/* What a world accepted stays whole (issue 23, findings 3-7).

   3. A chain at the coordinate bound saves a snapshot that loads: open
      chains (whose ends have made-up ghosts) and loops, both windings,
      on static and kinematic bodies.
   4. Shapes each accepted whose sums (mass, centre, inertia) would pass
      the range of ga2d_real are refused with GA2D_ERR_MASS_OVERFLOW, the
      body and the world's snapshot exactly as they were; sums just
      inside the range are accepted and step; every path that sums the
      shapes again (shape destroy, chains, set_mass_data, the body def's
      polygon) keeps them finite.
   5. A force or torque from the force callback on a sleeping body wakes
      its island at the end of that step; it joins the next step and
      moves as the analytic answer from that step on.
   6. The pre-solve callback's only effect is its answer: writing garbage
      through the manifold it is handed changes nothing (the world's
      snapshot equals that of a run whose callback gives the same
      answers and writes nothing).
   7. ga2d_body_polygon's pointer lasts as documented: through steps,
      setters, bodies created without a shape, shapes and bodies
      destroyed elsewhere, and snapshot saves.

   eps is the build's machine epsilon (REAL_EPS).  With GA2D_TEST_VERBOSE
   set the figures are printed. */
#include "test.h"

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

#define MAXC ((ga2d_real)GA2D_MAX_COORDINATE)

static unsigned char *snap(const ga2d_world *w, size_t *size)
{
    unsigned char *buf;
    *size = ga2d_world_snapshot_size(w);
    buf = (unsigned char *)malloc(*size ? *size : 1);
    if (buf && ga2d_world_snapshot_save(w, buf, *size) != GA2D_OK) {
        free(buf);
        buf = NULL;
    }
    CHECK(buf != NULL);
    return buf;
}

/* The world's snapshot has these bytes. */
static int same_snap(const ga2d_world *w, const unsigned char *ref, size_t ref_size)
{
    size_t n;
    unsigned char *now = snap(w, &n);
    int same = now && ref && n == ref_size && memcmp(now, ref, n) == 0;
    free(now);
    return same;
}

static ga2d_world *world_no_gravity(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.gravity = ga2d_vec_make(0, 0);
    return ga2d_world_create(&wd);
}

static ga2d_body_id make_body(ga2d_world *w, ga2d_body_type type, ga2d_vec at)
{
    ga2d_body_def bd = ga2d_default_body_def();
    bd.type = type;
    bd.position = at;
    return ga2d_body_create(w, &bd);
}

/* ==================================================== 3. chains at the bound
   The chain is saved, loaded back into its own world and into a fresh
   one, and each load saves the same bytes again.  A made-up ghost (an
   open end's) lies behind its end at a right angle: (g - p) . e = 0 up
   to the rounding of g (|g| <= 5 M: 4 eps |g - p| |e| covers the two
   subtractions' half-ulps), and (g - p) . left(e) < 0. */
static void chain_saves_and_loads(ga2d_body_type type, const ga2d_vec *pts, int n, int loop, const char *what)
{
    ga2d_world *w = world_no_gravity(), *fresh = world_no_gravity();
    ga2d_body_id body = make_body(w, type, ga2d_vec_make(0, 0));
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_chain_id chain;
    ga2d_result r;
    size_t size = 0, size2 = 0;
    unsigned char *buf = NULL, *again = NULL;
    cd.points = pts;
    cd.count = n;
    cd.is_loop = loop;
    r = ga2d_chain_create_checked(w, body, &cd, &chain);
    if (r != GA2D_OK) test_fail(__FILE__, __LINE__, "%s: created \"%s\"", what, ga2d_result_string(r));
    if (!loop && r == GA2D_OK) {
        ga2d_shape_id seg[64];
        int count = ga2d_chain_get_segments(w, chain, seg, 64), end;
        CHECK(count == n - 1);
        for (end = 0; end < 2 && count > 0; ++end) {
            ga2d_chain_segment cs = ga2d_shape_geometry(w, seg[end ? count - 1 : 0]).as.chain_segment;
            ga2d_vec p = end ? cs.segment.point2 : cs.segment.point1, g = end ? cs.ghost2 : cs.ghost1;
            double ex = (double)cs.segment.point2.x - (double)cs.segment.point1.x;
            double ey = (double)cs.segment.point2.y - (double)cs.segment.point1.y;
            double gx = (double)g.x - (double)p.x, gy = (double)g.y - (double)p.y;
            double along = gx * ex + gy * ey, front = gx * -ey + gy * ex;
            double tol = 4 * REAL_EPS * sqrt(gx * gx + gy * gy) * sqrt(ex * ex + ey * ey);
            if (!(fabs(along) <= tol) || !(front < 0))
                test_fail(__FILE__, __LINE__, "%s: end %d's ghost is not behind it at a right angle (%.3g along, bound %.3g; %.3g in front)",
                          what, end, along, tol, front);
        }
    }
    buf = snap(w, &size);
    if (buf) {
        r = ga2d_world_snapshot_load(fresh, buf, size);
        if (r != GA2D_OK) test_fail(__FILE__, __LINE__, "%s: a fresh world loads \"%s\"", what, ga2d_result_string(r));
        else if (!same_snap(fresh, buf, size)) test_fail(__FILE__, __LINE__, "%s: the fresh world saves other bytes", what);
        r = ga2d_world_snapshot_load(w, buf, size);
        if (r != GA2D_OK) test_fail(__FILE__, __LINE__, "%s: its own world loads \"%s\"", what, ga2d_result_string(r));
        again = snap(w, &size2);
        CHECK(again && size2 == size && memcmp(again, buf, size) == 0);
    }
    free(buf);
    free(again);
    ga2d_world_destroy(w);
    ga2d_world_destroy(fresh);
}

/* The sweep: every chain below, forwards and backwards (the other
   winding: the front side flips), on a static and a kinematic body. */
static void chains_at_the_bound_load(void)
{
    const ga2d_real M = MAXC;
    /* a short end: apart by twice the tolerance of ga2d__ends_apart (64
       eps of the two points' size, 4 M), so the chain is accepted */
    const ga2d_real d = (ga2d_real)(2 * 64 * REAL_EPS * 4 * (double)M);
    struct { ga2d_vec p[5]; int n, loop; const char *name; } cases[] = {
        {{{-M, 0}, {M, 0}}, 2, 0, "open (-M,0)-(M,0)"},
        {{{-M, -M}, {M, -M}}, 2, 0, "open along the bottom edge"},
        {{{-M, M}, {M, M}}, 2, 0, "open along the top edge"},
        {{{-M, -M}, {M, M}}, 2, 0, "open diagonal"},
        {{{-M, -M}, {M, -M}, {M, M}, {-M, M}}, 4, 0, "open round three edges"},
        {{{-M, -M}, {M, -M}, {M, M}, {-M, M}}, 4, 1, "loop on the corners"},
        {{{-M, 0}, {0, -M}, {M, 0}, {0, M}}, 4, 1, "loop on the edges' middles"},
        {{{M, M}, {M - d, M}, {M - d, M - d}}, 3, 0, "open, short ends at a corner"},
        {{{M, M}, {M - d, M}, {M - d, M - d}, {M, M - d}}, 4, 1, "loop, short sides at a corner"},
    };
    int i, t, dir, runs = 0;
    for (i = 0; i < (int)(sizeof cases / sizeof cases[0]); ++i)
        for (dir = 0; dir < 2; ++dir)
            for (t = 0; t < 2; ++t) {
                ga2d_vec p[5];
                char what[160];
                int k, n = cases[i].n;
                for (k = 0; k < n; ++k) p[k] = cases[i].p[dir ? n - 1 - k : k];
                snprintf(what, sizeof what, "%s, %s, %s body", cases[i].name, dir ? "backwards" : "forwards",
                         t ? "kinematic" : "static");
                chain_saves_and_loads(t ? GA2D_BODY_KINEMATIC : GA2D_BODY_STATIC, p, n, cases[i].loop, what);
                ++runs;
            }
    CHECK(runs == 36);
    if (verbose()) printf("accepted: %d chains at the coordinate bound (M = %g) saved and loaded\n", runs, (double)M);
}

/* ==================================================== 4. mass sums
   A body's state as every getter gives it, to compare bit for bit. */
typedef struct body_state {
    ga2d_real v[16];
    int awake, type, shapes;
} body_state;

static body_state state_of(const ga2d_world *w, ga2d_body_id id)
{
    body_state s;
    ga2d_vec p = ga2d_body_position(w, id), c = ga2d_body_center(w, id), v = ga2d_body_velocity(w, id);
    ga2d_rotor q = ga2d_body_rotor(w, id);
    ga2d_mass m = ga2d_body_mass_data(w, id);
    ga2d_aabb box = ga2d_body_fat_aabb(w, id);
    memset(&s, 0, sizeof s);
    s.v[0] = p.x, s.v[1] = p.y, s.v[2] = q.c, s.v[3] = q.s, s.v[4] = c.x, s.v[5] = c.y, s.v[6] = v.x, s.v[7] = v.y;
    s.v[8] = ga2d_body_angular_velocity(w, id), s.v[9] = m.mass, s.v[10] = m.center.x, s.v[11] = m.center.y;
    s.v[12] = m.inertia, s.v[13] = ga2d_body_kinetic_energy(w, id), s.v[14] = box.lower.x, s.v[15] = box.upper.y;
    s.awake = ga2d_body_is_awake(w, id);
    s.type = (int)ga2d_body_get_type(w, id);
    s.shapes = ga2d_body_get_shapes(w, id, NULL, 0);
    return s;
}

static int same_state(const body_state *a, const body_state *b)
{
    return memcmp(a->v, b->v, sizeof a->v) == 0 && a->awake == b->awake && a->type == b->type && a->shapes == b->shapes;
}

static int state_finite(const body_state *s)
{
    int i;
    for (i = 0; i < 16; ++i)
        if (!isfinite((double)s->v[i])) return 0;
    return 1;
}

/* One creation that must be refused with `want`: the body's every getter
   and the world's snapshot are as they were. */
static void refused_shape(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *sd, const ga2d_geometry *g, ga2d_result want,
                          const char *what)
{
    size_t size;
    unsigned char *before = snap(w, &size);
    body_state s0 = state_of(w, body), s1;
    ga2d_shape_id id;
    ga2d_result r = ga2d_shape_create_checked(w, body, sd, g, &id);
    if (r != want) test_fail(__FILE__, __LINE__, "%s: \"%s\", expected \"%s\"", what, ga2d_result_string(r), ga2d_result_string(want));
    CHECK(ga2d_shape_id_is_null(id));
    s1 = state_of(w, body);
    if (!same_state(&s0, &s1)) test_fail(__FILE__, __LINE__, "%s: the body changed", what);
    if (!same_snap(w, before, size)) test_fail(__FILE__, __LINE__, "%s: the world's snapshot changed", what);
    free(before);
}

/* A circle, box or capsule of size r = max(1, |x| / 1024) at (x, 0): far
   out, a shape of size 1 would be below float's spacing there. */
static ga2d_geometry shape_at(int kind, ga2d_real x)
{
    ga2d_geometry g;
    ga2d_real r = (ga2d_real)(fabs((double)x) / 1024 > 1 ? fabs((double)x) / 1024 : 1);
    memset(&g, 0, sizeof g);
    if (kind == 0) {
        g.type = GA2D_SHAPE_CIRCLE;
        g.as.circle.center = ga2d_vec_make(x, 0);
        g.as.circle.radius = r;
    } else if (kind == 1) {
        ga2d_vec v[4];
        v[0] = ga2d_vec_make(x - r, -r), v[1] = ga2d_vec_make(x + r, -r), v[2] = ga2d_vec_make(x + r, r), v[3] = ga2d_vec_make(x - r, r);
        g.type = GA2D_SHAPE_POLYGON;
        CHECK_RESULT(ga2d_polygon_make(v, 4, &g.as.polygon), GA2D_OK);
    } else {
        g.type = GA2D_SHAPE_CAPSULE;
        g.as.capsule.center1 = ga2d_vec_make(x - r, 0);
        g.as.capsule.center2 = ga2d_vec_make(x + r, 0);
        g.as.capsule.radius = r;
    }
    return g;
}

static ga2d_geometry unit_circle(ga2d_real x)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_CIRCLE;
    g.as.circle.center = ga2d_vec_make(x, 0);
    g.as.circle.radius = 1;
    return g;
}

static ga2d_result shape_mass(const ga2d_geometry *g, ga2d_real density, ga2d_mass *m)
{
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE: return ga2d_circle_mass_checked(&g->as.circle, density, m);
    case GA2D_SHAPE_POLYGON: return ga2d_polygon_mass_checked(&g->as.polygon, density, m);
    default: return ga2d_capsule_mass_checked(&g->as.capsule, density, m);
    }
}

/* A shape alone accepted on a dynamic body: its mass and inertia and
   their inverses finite (as the library requires of one shape). */
static int alone_ok(const ga2d_geometry *g, ga2d_real density)
{
    ga2d_mass m;
    if (shape_mass(g, density, &m) != GA2D_OK) return 0;
    return isfinite((double)m.mass) && isfinite((double)m.inertia) && m.mass > 0 && m.inertia > 0 &&
           isfinite(1 / (double)m.mass) && isfinite(1 / (double)m.inertia) && (ga2d_real)(1 / m.mass) > 0;
}

/* The scene: two unit circles at x = +-1e8, density 8e36 in
   float (8e306 in double): each is accepted alone; their sum's inertia
   2 m (1e8)^2 is past the range, so the second is refused. */
static void heavy_pair_refused(void)
{
    ga2d_world *w = world_no_gravity();
    ga2d_body_id b = make_body(w, GA2D_BODY_DYNAMIC, ga2d_vec_make(0, 0));
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_geometry g1 = unit_circle((ga2d_real)1e8), g2 = unit_circle((ga2d_real)-1e8);
    ga2d_shape_id id;
    body_state s;
#ifdef GA2D_DOUBLE
    sd.density = 8e306;
#else
    sd.density = 8e36f;
#endif
    CHECK_RESULT(ga2d_shape_create_checked(w, b, &sd, &g1, &id), GA2D_OK);
    s = state_of(w, b);
    CHECK(state_finite(&s));
    refused_shape(w, b, &sd, &g2, GA2D_ERR_MASS_OVERFLOW, "the issue's second circle");
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
    CHECK(strcmp(ga2d_result_string(GA2D_ERR_MASS_OVERFLOW), "unknown result") != 0);
    ga2d_world_destroy(w);
}

/* The sweep: two like shapes (circle, box, capsule; shape_at's size) at
   x = +-x, x from 10 to 0.99 M, on a dynamic body.  Exactly, M = 2 rho m1 and I =
   2 rho (I1 + m1 x^2) (m1, I1 the shape's at density 1 about its own
   centre), so rho_lim = MAX / max(2 m1, 2 (I1 + m1 x^2)) is where a sum
   reaches the range.  At rho_lim / 4 the pair is accepted: the sums
   within 8 eps of the exact ones (a handful of roundings, each eps/2
   relative, as the sums are of like-signed terms), the body finite, a
   step OK, the snapshot loads.  At 4 rho_lim (when each shape alone is
   still accepted) the second is refused, nothing changed. */
static void heavy_sums_refused_sweep(void)
{
    const double xs[] = {10, 1e3, 1e5, 1e7, (double)MAXC / 2, (double)MAXC * 0.99};
    int kind, i, accepted = 0, refusals = 0;
    for (kind = 0; kind < 3; ++kind)
        for (i = 0; i < (int)(sizeof xs / sizeof xs[0]); ++i) {
            ga2d_real x = (ga2d_real)xs[i];
            ga2d_geometry ga = shape_at(kind, x), gb = shape_at(kind, -x);
            ga2d_mass m1;
            double lim, M, I;
            int big;
            CHECK_RESULT(shape_mass(&ga, 1, &m1), GA2D_OK);
            M = 2 * (double)m1.mass;
            I = 2 * ((double)m1.inertia + (double)m1.mass * (double)x * (double)x);
            lim = REAL_MAX / (M > I ? M : I);
            for (big = 0; big < 2; ++big) {
                ga2d_world *w = world_no_gravity();
                ga2d_body_id b = make_body(w, GA2D_BODY_DYNAMIC, ga2d_vec_make(0, 0));
                ga2d_shape_def sd = ga2d_default_shape_def();
                ga2d_shape_id id;
                char what[120];
                snprintf(what, sizeof what, "%s pair at +-%g, %s", kind == 0 ? "circle" : kind == 1 ? "box" : "capsule", xs[i],
                         big ? "4 x the limit" : "a quarter of the limit");
                sd.density = (ga2d_real)(big ? 4 * lim : lim / 4);
                if (!isfinite((double)sd.density) || !alone_ok(&ga, sd.density)) {
                    ga2d_world_destroy(w);
                    continue;
                }
                CHECK_RESULT(ga2d_shape_create_checked(w, b, &sd, &ga, &id), GA2D_OK);
                if (big) {
                    refused_shape(w, b, &sd, &gb, GA2D_ERR_MASS_OVERFLOW, what);
                    ++refusals;
                } else {
                    ga2d_result r = ga2d_shape_create_checked(w, b, &sd, &gb, &id);
                    ga2d_mass m = ga2d_body_mass_data(w, b);
                    body_state s = state_of(w, b);
                    double rho = (double)sd.density, want_m = rho * M, want_i = rho * I;
                    if (r != GA2D_OK) test_fail(__FILE__, __LINE__, "%s: refused \"%s\"", what, ga2d_result_string(r));
                    CHECK(state_finite(&s));
                    CHECK_NEAR(m.mass, want_m, 8 * REAL_EPS * want_m);
                    CHECK_NEAR(m.inertia, want_i, 8 * REAL_EPS * want_i);
                    /* the centre: 0 up to the rounding of the moment, m x eps per shape, over M */
                    CHECK_NEAR(m.center.x, 0, 4 * REAL_EPS * (double)x);
                    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
                    {
                        size_t size;
                        unsigned char *buf = snap(w, &size);
                        if (buf) CHECK_RESULT(ga2d_world_snapshot_load(w, buf, size), GA2D_OK);
                        free(buf);
                    }
                    ++accepted;
                }
                ga2d_world_destroy(w);
            }
        }
    /* every pair far enough out that the inertia, not the mass, binds
       refuses (x >= 1e3 for every kind: m1 x^2 >> m1 while rho I1 stays
       finite), and every quarter-limit pair is accepted */
    CHECK(accepted == 18);
    CHECK(refusals >= 15);
    if (verbose()) printf("accepted: heavy pairs: %d accepted at a quarter of the limit, %d refused at 4 x\n", accepted, refusals);
}

/* A light shape first, a heavy one far from it: the moment m (c - c0)
   about the first shape's centre passes the range while the centre and
   the inertia do not.  Accepted, centre within rounding of the exact
   one; then the paths that sum again: the first shape destroyed (the
   heavy one alone), then the last (no shape: mass 1, centre at the
   origin), each finite. */
static void moment_past_range_is_not_an_overflow(void)
{
    ga2d_world *w = world_no_gravity();
    ga2d_body_id b = make_body(w, GA2D_BODY_DYNAMIC, ga2d_vec_make(0, 0));
    ga2d_shape_def light = ga2d_default_shape_def(), heavy = ga2d_default_shape_def();
    const ga2d_real x = (ga2d_real)1e4;
    ga2d_geometry ga = shape_at(0, -x), gb = shape_at(0, x);
    ga2d_shape_id a_id, b_id;
    ga2d_mass m1, m;
    body_state s;
    double mh, cx;
    CHECK_RESULT(shape_mass(&gb, 1, &m1), GA2D_OK);
    /* m_heavy 2x > MAX: the moment overflows; m_heavy < MAX / 4 and its
       parallel-axis term stays finite since the centre is near it */
    heavy.density = (ga2d_real)(REAL_MAX / (double)x / (double)m1.mass);
    CHECK(alone_ok(&gb, heavy.density));
    CHECK_RESULT(ga2d_shape_create_checked(w, b, &light, &ga, &a_id), GA2D_OK);
    CHECK_RESULT(ga2d_shape_create_checked(w, b, &heavy, &gb, &b_id), GA2D_OK);
    s = state_of(w, b);
    CHECK(state_finite(&s));
    m = ga2d_body_mass_data(w, b);
    mh = (double)heavy.density * (double)m1.mass;
    /* exact centre: x - 2x m_light / (m_light + m_heavy); rounding: each
       term of the scaled moment within eps of 2x */
    cx = (double)x - 2 * (double)x * (double)m1.mass / ((double)m1.mass + mh);
    CHECK_NEAR(m.center.x, cx, 4 * REAL_EPS * 2 * (double)x);
    CHECK_RESULT(ga2d_shape_destroy(w, a_id, 1), GA2D_OK);
    m = ga2d_body_mass_data(w, b);
    s = state_of(w, b);
    CHECK(state_finite(&s));
    CHECK(m.center.x == x); /* one shape: its own centre */
    CHECK_NEAR(m.mass, mh, 2 * REAL_EPS * mh);
    CHECK_RESULT(ga2d_shape_destroy(w, b_id, 1), GA2D_OK);
    m = ga2d_body_mass_data(w, b);
    CHECK(m.mass == 1 && m.inertia == 0 && m.center.x == 0 && m.center.y == 0);
    ga2d_world_destroy(w);
}

/* The other paths. */
static void mass_paths_stay_finite(void)
{
    ga2d_world *w = world_no_gravity();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_geometry g = shape_at(1, 0);
    ga2d_shape_id id;
    ga2d_mass m1, md;
    body_state s;
    CHECK_RESULT(shape_mass(&g, 1, &m1), GA2D_OK);
    {
        /* the body def's polygon, at the densest a box alone takes (a
           quarter of MAX / I1: the mass m1 / I1 = 6 times that is still
           finite), placed at the bound: one shape sums to itself, and the
           centre (position + the box's centre, 2 M at most) is finite */
        ga2d_body_def bd = ga2d_default_body_def();
        ga2d_body_id b;
        bd.type = GA2D_BODY_DYNAMIC;
        bd.position = ga2d_vec_make(MAXC, -MAXC);
        bd.polygon = g.as.polygon;
        bd.density = (ga2d_real)(REAL_MAX / 4 / (double)m1.inertia * (double)m1.mass / 6);
        b = ga2d_body_create(w, &bd);
        CHECK(!ga2d_body_id_is_null(b));
        s = state_of(w, b);
        CHECK(state_finite(&s));
    }
    {
        /* set_mass_data's mass is kept when a shape that would pass the
           range is refused; a chain on a dynamic body is refused */
        ga2d_body_id b = make_body(w, GA2D_BODY_DYNAMIC, ga2d_vec_make(0, 0));
        ga2d_geometry far1 = unit_circle((ga2d_real)1e7), far2 = unit_circle((ga2d_real)-1e7);
        ga2d_mass mass;
        ga2d_chain_def cd = ga2d_default_chain_def();
        ga2d_vec pts[2];
        ga2d_chain_id chain;
        sd.density = (ga2d_real)(REAL_MAX / 1e13);
        CHECK_RESULT(ga2d_shape_create_checked(w, b, &sd, &far1, &id), GA2D_OK);
        mass.mass = 2, mass.inertia = 3, mass.center = ga2d_vec_make(1, 1);
        CHECK_RESULT(ga2d_body_set_mass_data(w, b, mass), GA2D_OK);
        refused_shape(w, b, &sd, &far2, GA2D_ERR_MASS_OVERFLOW, "a shape after set_mass_data");
        md = ga2d_body_mass_data(w, b);
        CHECK(md.mass == 2 && md.inertia == 3 && md.center.x == 1 && md.center.y == 1);
        pts[0] = ga2d_vec_make(-1, 0), pts[1] = ga2d_vec_make(1, 0);
        cd.points = pts;
        cd.count = 2;
        CHECK_RESULT(ga2d_chain_create_checked(w, b, &cd, &chain), GA2D_ERR_INVALID_ARGUMENT);
    }
    {
        /* a kinematic body spinning at MAX / 1e4 rad/s with no shape: a
           shape or a chain off its origin moves its centre by 0.75 M, and
           the centre's velocity v + (C' - C) Omega would pass the range */
        ga2d_body_id b = make_body(w, GA2D_BODY_KINEMATIC, ga2d_vec_make(0, 0));
        ga2d_chain_def cd = ga2d_default_chain_def();
        ga2d_vec pts[2];
        ga2d_chain_id chain;
        ga2d_geometry off = unit_circle((ga2d_real)(0.75 * (double)MAXC));
        size_t size;
        unsigned char *before;
        body_state s0, s1;
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, b, (ga2d_real)(REAL_MAX / 1e4)), GA2D_OK);
        refused_shape(w, b, &sd, &off, GA2D_ERR_MASS_OVERFLOW, "a shape on a fast-spinning kinematic body");
        pts[0] = ga2d_vec_make(MAXC / 2, 0), pts[1] = ga2d_vec_make(MAXC, 0);
        cd.points = pts;
        cd.count = 2;
        before = snap(w, &size);
        s0 = state_of(w, b);
        CHECK_RESULT(ga2d_chain_create_checked(w, b, &cd, &chain), GA2D_ERR_MASS_OVERFLOW);
        s1 = state_of(w, b);
        CHECK(same_state(&s0, &s1));
        CHECK(same_snap(w, before, size));
        free(before);
        /* at rest, the chain is fine, and its destruction too */
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, b, 0), GA2D_OK);
        CHECK_RESULT(ga2d_chain_create_checked(w, b, &cd, &chain), GA2D_OK);
        CHECK_RESULT(ga2d_chain_destroy(w, chain), GA2D_OK);
        s1 = state_of(w, b);
        CHECK(state_finite(&s1));
    }
    ga2d_world_destroy(w);
}

/* ==================================================== 5. the field wakes
   A 1 kg box (1 x 1 m, density 1) put to sleep in mid air, g = (0, -10);
   the force callback pushes it with F = 100 N up (or turns it with a
   torque) from its first call.  The push comes while it sleeps: the step
   wakes it at its end and the box has not moved; from the next step on
   the field acts at every evaluation, a = F/m + g = 90 m/s^2.  After n
   substeps of h from rest: symplectic Euler y = a h^2 n (n + 1) / 2
   (v_k = k h a, y = sum h v_k); Verlet and RK4 are exact under a
   constant force, y = a (n h)^2 / 2.  The same for the angle under a
   torque tau = 0.1 N m, alpha = tau / I, I = 1/6 kg m^2.  Rounding: each
   substep rounds v and y by eps/2 of their size, and an error in v
   carries into every later y: within 2 n eps |y| (+ eps for the start). */
typedef struct field_push {
    ga2d_body_id box;
    int torque, zero, calls, calls_asleep;
    ga2d_result worst;
} field_push;

static void push_cb(ga2d_world *w, void *ctx)
{
    field_push *f = (field_push *)ctx;
    ga2d_result r;
    ++f->calls;
    f->calls_asleep += !ga2d_body_is_awake(w, f->box);
    if (f->torque) r = ga2d_body_apply_torque(w, f->box, f->zero ? 0 : (ga2d_real)0.1);
    else r = ga2d_body_apply_force_to_center(w, f->box, ga2d_vec_make(0, f->zero ? 0 : 100));
    if (r != GA2D_OK) f->worst = r;
}

static void field_wakes_a_sleeping_body(void)
{
    int integ, torque;
    for (integ = 0; integ < 3; ++integ)
        for (torque = 0; torque < 2; ++torque) {
            ga2d_world_def wd = ga2d_default_world_def();
            ga2d_body_def bd = ga2d_default_body_def();
            ga2d_world *w;
            field_push f;
            const int steps = 60, subs = 4;
            const double h = 1.0 / 60 / subs, a = torque ? 0.1 * 6 : 90;
            double y0, got, want, n = (steps - 1) * subs;
            int i;
            memset(&f, 0, sizeof f);
            f.torque = torque;
            f.worst = GA2D_OK;
            wd.substeps = subs;
            wd.integrator = integ == 0 ? GA2D_INTEGRATOR_SYMPLECTIC_EULER : integ == 1 ? GA2D_INTEGRATOR_VERLET : GA2D_INTEGRATOR_RK4;
            wd.force_callback = push_cb;
            wd.force_context = &f;
            if (torque) wd.gravity = ga2d_vec_make(0, 0);
            w = ga2d_world_create(&wd);
            bd.type = GA2D_BODY_DYNAMIC;
            bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
            bd.position = ga2d_vec_make(0, 10);
            bd.is_awake = 0;
            f.box = ga2d_body_create(w, &bd);
            CHECK(!ga2d_body_is_awake(w, f.box));
            y0 = (double)ga2d_body_center(w, f.box).y;
            CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
            /* the integrator evaluates only awake bodies' states: the
               sleeping box is pushed from the callback all the same */
            CHECK(ga2d_body_is_awake(w, f.box));
            CHECK((double)ga2d_body_center(w, f.box).y == y0 && ga2d_body_angular_velocity(w, f.box) == 0);
            for (i = 1; i < steps; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
            CHECK(f.worst == GA2D_OK);
            got = torque ? (double)ga2d_body_angle(w, f.box) : (double)ga2d_body_center(w, f.box).y - y0;
            want = integ == 0 ? a * h * h * n * (n + 1) / 2 : a * (n * h) * (n * h) / 2;
            CHECK_NEAR(got, want, 2 * n * REAL_EPS * (fabs(want) + (torque ? 0 : y0)) + REAL_EPS * y0);
            if (verbose())
                printf("accepted: field %s on a sleeping box, %s: %.6g (analytic %.6g)\n", torque ? "torque" : "force",
                       integ == 0 ? "Euler" : integ == 1 ? "Verlet" : "RK4", got, want);
            ga2d_world_destroy(w);
        }
}

/* The island wakes: two boxes side by side, touching, put to sleep
   together; the field pushes one.  Both wake at the step's end.  A zero
   push is no push: the island sleeps on. */
static void field_wakes_the_island(void)
{
    int zero;
    for (zero = 0; zero < 2; ++zero) {
        ga2d_world_def wd = ga2d_default_world_def();
        ga2d_body_def bd = ga2d_default_body_def();
        ga2d_world *w;
        ga2d_body_id other;
        field_push f;
        memset(&f, 0, sizeof f);
        f.zero = zero;
        f.worst = GA2D_OK;
        wd.gravity = ga2d_vec_make(0, 0);
        w = ga2d_world_create(&wd);
        bd.type = GA2D_BODY_DYNAMIC;
        bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        f.box = ga2d_body_create(w, &bd);
        bd.position = ga2d_vec_make(1, 0);
        other = ga2d_body_create(w, &bd);
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK); /* their contact begins */
        CHECK_RESULT(ga2d_body_set_awake(w, f.box, 0), GA2D_OK);
        CHECK(!ga2d_body_is_awake(w, f.box) && !ga2d_body_is_awake(w, other));
        CHECK_RESULT(ga2d_world_set_force_callback(w, push_cb, &f), GA2D_OK);
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
        CHECK(f.calls_asleep > 0);
        CHECK(ga2d_body_is_awake(w, f.box) == !zero);
        CHECK(ga2d_body_is_awake(w, other) == !zero);
        ga2d_world_destroy(w);
    }
}

/* ==================================================== 6. pre-solve garbage
   Boxes and balls dropped on a floor; every contact asks pre-solve.  The
   answer is a function of the call's index (every third declined), the
   same in both runs; one run's callback also writes garbage through the
   manifold it is handed.  After 90 steps the two runs' snapshots are
   the same bytes (and the garbage run found a sane manifold each time
   before it wrote). */
typedef struct presolve_run {
    int garbage, calls, sane;
} presolve_run;

static int answer_cb(ga2d_shape_id a, ga2d_shape_id b, const ga2d_manifold *m, void *ctx)
{
    presolve_run *p = (presolve_run *)ctx;
    int answer = p->calls++ % 3 != 0;
    (void)a;
    (void)b;
    p->sane &= m->count >= 1 && m->count <= 2 && isfinite((double)m->normal.x) && isfinite((double)m->points[0].point.x);
    if (p->garbage) {
        ga2d_manifold *g = (ga2d_manifold *)m; /* what a careless callback may do */
        int k;
        g->count = p->garbage == 1 ? 1000 : p->garbage == 2 ? -5 : p->garbage == 3 ? 0 : 2;
        if (p->garbage >= 4) {
            g->normal = ga2d_vec_make((ga2d_real)NAN, (ga2d_real)INFINITY);
            for (k = 0; k < 2; ++k) {
                g->points[k].point = ga2d_vec_make((ga2d_real)NAN, (ga2d_real)NAN);
                g->points[k].anchor_a = g->points[k].anchor_b = ga2d_vec_make((ga2d_real)1e30, (ga2d_real)-1e30);
                g->points[k].separation = (ga2d_real)-INFINITY;
                g->points[k].normal_impulse = g->points[k].tangent_impulse = (ga2d_real)NAN;
                g->points[k].id = 0xdeadbeefu;
                g->points[k].persisted = -1;
            }
        }
    }
    return answer;
}

/* The scene, built once (the snapshot of a world carries its world's
   mark, so the runs are made in one world, each from the start's
   snapshot). */
static ga2d_world *presolve_world(presolve_run *p)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_world *w;
    ga2d_body_id ground;
    ga2d_polygon floor_box = ga2d_polygon_box(10, (ga2d_real)0.5), box = ga2d_polygon_box((ga2d_real)0.4, (ga2d_real)0.4);
    ga2d_circle ball;
    int i;
    wd.pre_solve = answer_cb;
    wd.pre_solve_context = p;
    w = ga2d_world_create(&wd);
    sd.enable_pre_solve_events = 1;
    ground = ga2d_body_create(w, &bd);
    ga2d_shape_create_polygon(w, ground, &sd, &floor_box);
    bd.type = GA2D_BODY_DYNAMIC;
    ball.center = ga2d_vec_make(0, 0);
    ball.radius = (ga2d_real)0.3;
    for (i = 0; i < 6; ++i) {
        ga2d_body_id b;
        bd.position = ga2d_vec_make((ga2d_real)(i - 3) * (ga2d_real)0.9, (ga2d_real)(1 + 0.5 * i));
        bd.angular_velocity = (ga2d_real)(i - 2);
        b = ga2d_body_create(w, &bd);
        if (i % 2) ga2d_shape_create_polygon(w, b, &sd, &box);
        else ga2d_shape_create_circle(w, b, &sd, &ball);
    }
    return w;
}

/* One run of 90 steps from the start's snapshot, the callback writing
   garbage of the given kind (0: none); the end's snapshot. */
static unsigned char *presolve_run_from(ga2d_world *w, const unsigned char *start, size_t start_size, presolve_run *p, int garbage,
                                        size_t *size)
{
    int i;
    CHECK_RESULT(ga2d_world_snapshot_load(w, start, start_size), GA2D_OK);
    p->garbage = garbage;
    p->calls = 0;
    p->sane = 1;
    for (i = 0; i < 90; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
    return snap(w, size);
}

static void presolve_garbage_changes_nothing(void)
{
    presolve_run p;
    ga2d_world *w;
    size_t n_start, n0, n1;
    unsigned char *start, *a;
    int garbage, ref_calls;
    memset(&p, 0, sizeof p);
    w = presolve_world(&p);
    start = snap(w, &n_start);
    a = presolve_run_from(w, start, n_start, &p, 0, &n0);
    ref_calls = p.calls;
    CHECK(ref_calls > 100 && p.sane); /* the scene touches: the callback has answers to give */
    for (garbage = 0; garbage <= 5; ++garbage) { /* 0: a well-behaved run again, the same bytes */
        unsigned char *b = presolve_run_from(w, start, n_start, &p, garbage, &n1);
        if (!(a && b && n0 == n1 && memcmp(a, b, n0) == 0))
            test_fail(__FILE__, __LINE__, "garbage kind %d through the pre-solve manifold changed the world", garbage);
        CHECK(p.calls == ref_calls && p.sane);
        free(b);
    }
    free(a);
    free(start);
    ga2d_world_destroy(w);
}

/* ==================================================== 7. body_polygon's life
   The pointer stays the same and its polygon the same bytes through what
   the header says keeps it: steps, setters, impulses, bodies created
   without a shape, other shapes and bodies destroyed, snapshot saves.
   (Under the sanitizer builds a freed pointer read here would abort.) */
static void body_polygon_pointer_lasts(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id box, other, bare;
    ga2d_circle c;
    ga2d_shape_id extra;
    const ga2d_polygon *p;
    ga2d_polygon copy;
    size_t size;
    unsigned char *buf;
    int i, same = 1;
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.25);
    box = ga2d_body_create(w, &bd);
    bd.position = ga2d_vec_make(3, 0);
    other = ga2d_body_create(w, &bd);
    c.center = ga2d_vec_make(0, 1), c.radius = (ga2d_real)0.2;
    extra = ga2d_shape_create_circle(w, other, &sd, &c);
    p = ga2d_body_polygon(w, box);
    CHECK(p != NULL);
    if (!p) return;
    copy = *p;
#define STILL() same &= ga2d_body_polygon(w, box) == p && memcmp(p, &copy, sizeof copy) == 0
    for (i = 0; i < 30; ++i) {
        ga2d_world_step(w, (ga2d_real)1 / 60);
        STILL();
    }
    ga2d_body_set_velocity(w, box, ga2d_vec_make(1, 2));
    ga2d_body_set_transform(w, box, ga2d_vec_make(1, 1), ga2d_rotor_from_angle(1));
    ga2d_body_apply_impulse(w, box, ga2d_vec_make(1, 0), ga2d_vec_make(0, 0));
    STILL();
    bd.polygon.count = 0;
    for (i = 0; i < 100; ++i) bare = ga2d_body_create(w, &bd); /* no shape: the body array grows, not the shapes' */
    STILL();
    ga2d_body_destroy(w, bare);
    ga2d_shape_destroy(w, extra, 1);
    ga2d_body_destroy(w, other);
    STILL();
    buf = snap(w, &size);
    free(buf);
    STILL();
#undef STILL
    CHECK(same);
    ga2d_world_destroy(w);
}

void suite_accepted(void)
{
    test_run("accepted: chains at the coordinate bound save snapshots that load", chains_at_the_bound_load);
    test_run("accepted: the issue's heavy pair is refused, the body as it was", heavy_pair_refused);
    test_run("accepted: sums of heavy shapes, accepted within the range and refused past it", heavy_sums_refused_sweep);
    test_run("accepted: a moment past the range is no overflow; destroy sums again", moment_past_range_is_not_an_overflow);
    test_run("accepted: body def, set_mass_data, chains, spinning kinematic: sums stay finite", mass_paths_stay_finite);
    test_run("accepted: a field force on a sleeping body wakes it for the next step", field_wakes_a_sleeping_body);
    test_run("accepted: a field push wakes the whole island, a zero push none", field_wakes_the_island);
    test_run("accepted: garbage written through the pre-solve manifold changes nothing", presolve_garbage_changes_nothing);
    test_run("accepted: ga2d_body_polygon's pointer lasts as documented", body_polygon_pointer_lasts);
}
