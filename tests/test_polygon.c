/* Polygons: validation with one named error per failure, the hull of any
   point cloud, boxes and regular polygons, transforms and bounding boxes.
   The polygon tolerances under test are the ones ga2d_polygon_make
   documents: with L the larger side of the bounding box, points within
   64 eps L are repeated or collinear, and an area below 1e-5 L^2 is
   degenerate. */
#include "test.h"

#define PI 3.14159265358979323846
#define MAXV GA2D_MAX_POLYGON_VERTICES

/* An output polygon between two guard bands: a failing call must write
   nothing, neither in the output nor around it. */
typedef struct guarded {
    unsigned char before[64];
    ga2d_polygon poly;
    unsigned char after[64];
} guarded;

static void guard_fill(guarded *g) { memset(g, 0xAB, sizeof *g); }
static int guard_untouched(const guarded *g)
{
    const unsigned char *b = (const unsigned char *)g;
    size_t i;
    for (i = 0; i < sizeof *g; ++i)
        if (b[i] != 0xAB) return 0;
    return 1;
}
static int guards_intact(const guarded *g)
{
    size_t i;
    for (i = 0; i < sizeof g->before; ++i)
        if (g->before[i] != 0xAB || g->after[i] != 0xAB) return 0;
    return 1;
}

/* make() must fail with `expected` and write nothing */
static void expect_make_fails(const ga2d_vec *pts, int n, ga2d_result expected)
{
    guarded g;
    guard_fill(&g);
    CHECK_RESULT(ga2d_polygon_make(pts, n, &g.poly), expected);
    CHECK(guard_untouched(&g));
}

static void expect_hull_fails(const ga2d_vec *pts, int n, ga2d_result expected)
{
    guarded g;
    guard_fill(&g);
    CHECK_RESULT(ga2d_polygon_hull(pts, n, &g.poly), expected);
    CHECK(guard_untouched(&g));
}

/* Normals are unit, perpendicular to their edge, and outward: every vertex
   lies on the inner side of every edge's line.  The normal is one
   normalization of an edge turned by 90 degrees: 4 eps per component. */
static void check_polygon_shape(const ga2d_polygon *p)
{
    int i, j, n = p->count;
    double L = 0;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            double d = (double)ga2d_vec_length(ga2d_vec_sub(p->vertices[i], p->vertices[j]));
            L = d > L ? d : L;
        }
    for (i = 0; i < n; ++i) {
        ga2d_vec e = ga2d_vec_sub(p->vertices[(i + 1) % n], p->vertices[i]);
        double le = (double)ga2d_vec_length(e);
        CHECK_NEAR(ga2d_vec_length(p->normals[i]), 1, 4 * REAL_EPS);
        CHECK_NEAR(ga2d_dot(p->normals[i], e), 0, 8 * REAL_EPS * le);
        for (j = 0; j < n; ++j)
            CHECK((double)ga2d_dot(p->normals[i], ga2d_vec_sub(p->vertices[j], p->vertices[i])) <= 8 * REAL_EPS * L);
    }
}

static void make_accepts_and_copies(void)
{
    const ga2d_vec square[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    const ga2d_vec expected_normals[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    guarded g;
    int i;
    guard_fill(&g);
    CHECK_RESULT(ga2d_polygon_make(square, 4, &g.poly), GA2D_OK);
    CHECK(guards_intact(&g));
    CHECK(g.poly.count == 4);
    for (i = 0; i < 4; ++i) {
        /* vertices are copied as given, first vertex first */
        CHECK(g.poly.vertices[i].x == square[i].x && g.poly.vertices[i].y == square[i].y);
        /* axis-aligned edges normalize exactly */
        CHECK(g.poly.normals[i].x == expected_normals[i].x && g.poly.normals[i].y == expected_normals[i].y);
    }
    check_polygon_shape(&g.poly);
}

/* Every kind of bad input has its own named error, and writes nothing. */
static void make_rejects_bad_input(void)
{
    const ga2d_vec ok[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    ga2d_vec pts[MAXV + 1];
    ga2d_polygon out;
    int i;

    /* NaN and Inf */
    memcpy(pts, ok, sizeof ok);
    pts[2].x = (ga2d_real)NAN;
    expect_make_fails(pts, 4, GA2D_ERR_NOT_FINITE);
    pts[2].x = 1;
    pts[1].y = (ga2d_real)INFINITY;
    expect_make_fails(pts, 4, GA2D_ERR_NOT_FINITE);
    pts[1].y = -(ga2d_real)INFINITY;
    expect_make_fails(pts, 4, GA2D_ERR_NOT_FINITE);

    /* 0, 1, 2 points; bad pointers and counts */
    expect_make_fails(ok, 0, GA2D_ERR_TOO_FEW_POINTS);
    expect_make_fails(ok, 1, GA2D_ERR_TOO_FEW_POINTS);
    expect_make_fails(ok, 2, GA2D_ERR_TOO_FEW_POINTS);
    expect_make_fails(NULL, 0, GA2D_ERR_TOO_FEW_POINTS);
    expect_make_fails(NULL, 4, GA2D_ERR_INVALID_ARGUMENT);
    expect_make_fails(ok, -1, GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_make(ok, 4, NULL), GA2D_ERR_INVALID_ARGUMENT);

    /* more than the maximum: a valid regular (MAXV+1)-gon */
    for (i = 0; i <= MAXV; ++i)
        pts[i] = ga2d_vec_make((ga2d_real)cos(2 * PI * i / (MAXV + 1)), (ga2d_real)sin(2 * PI * i / (MAXV + 1)));
    expect_make_fails(pts, MAXV + 1, GA2D_ERR_TOO_MANY_POINTS);

    /* all collinear */
    for (i = 0; i < 4; ++i) pts[i] = ga2d_vec_make((ga2d_real)i, (ga2d_real)(2 * i));
    expect_make_fails(pts, 4, GA2D_ERR_COLLINEAR_POINTS);
    expect_make_fails(pts, 3, GA2D_ERR_COLLINEAR_POINTS);

    /* one redundant vertex on an edge of a good square */
    {
        const ga2d_vec mid[5] = {{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}};
        expect_make_fails(mid, 5, GA2D_ERR_COLLINEAR_POINTS);
    }

    /* repeated points: exactly, and closer than the tolerance 64 eps L
       (here L = 1, offset 8 eps) */
    {
        ga2d_vec rep[5] = {{0, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 1}};
        expect_make_fails(rep, 5, GA2D_ERR_REPEATED_POINTS);
        rep[3].x = (ga2d_real)(1 - 8 * REAL_EPS);
        expect_make_fails(rep, 5, GA2D_ERR_REPEATED_POINTS);
        rep[3] = rep[0]; /* not adjacent */
        expect_make_fails(rep, 5, GA2D_ERR_REPEATED_POINTS);
    }
    {
        const ga2d_vec same[3] = {{2, 2}, {2, 2}, {2, 2}};
        expect_make_fails(same, 3, GA2D_ERR_REPEATED_POINTS);
    }

    /* clockwise */
    for (i = 0; i < 4; ++i) pts[i] = ok[3 - i];
    expect_make_fails(pts, 4, GA2D_ERR_CLOCKWISE);

    /* a non-convex quad (a dart, CCW, reflex vertex at (0.5, 1)) */
    {
        const ga2d_vec dart[4] = {{0, 0}, {2, 1}, {0, 2}, {0.5, 1}};
        expect_make_fails(dart, 4, GA2D_ERR_NOT_CONVEX);
    }
    /* a pentagram: every turn is left and its area is positive, yet it
       crosses itself */
    for (i = 0; i < 5; ++i) {
        int k = (2 * i) % 5;
        pts[i] = ga2d_vec_make((ga2d_real)cos(2 * PI * k / 5), (ga2d_real)sin(2 * PI * k / 5));
    }
    if (MAXV >= 5) expect_make_fails(pts, 5, GA2D_ERR_NOT_CONVEX);

    /* A sliver of area 1e-12: a triangle of base L and height d = 2e-12/L.
       Its vertex lies d from the base line; to be a sliver and not a
       collinear set, d must exceed 64 eps L in float (7.6e-6 L), and its
       area d L / 2 must stay under 1e-5 L^2, so d/L in (7.6e-6, 2e-5):
       d/L = 1.4e-5 gives L = sqrt(2e-12 / 1.4e-5) = 3.78e-4. */
    {
        double L = sqrt(2e-12 / 1.4e-5), d = 2e-12 / L;
        ga2d_vec sliver[3];
        sliver[0] = ga2d_vec_make(0, 0);
        sliver[1] = ga2d_vec_make((ga2d_real)L, 0);
        sliver[2] = ga2d_vec_make((ga2d_real)(L / 2), (ga2d_real)d);
        expect_make_fails(sliver, 3, GA2D_ERR_DEGENERATE);
        /* The same area at unit length: 2e-12 is below float's 64 eps
           (7.6e-6) so float calls it collinear; double resolves it
           (64 eps = 1.4e-14) and calls it degenerate. */
        sliver[1] = ga2d_vec_make(1, 0);
        sliver[2] = ga2d_vec_make(0.5, (ga2d_real)2e-12);
#ifdef GA2D_DOUBLE
        expect_make_fails(sliver, 3, GA2D_ERR_DEGENERATE);
#else
        expect_make_fails(sliver, 3, GA2D_ERR_COLLINEAR_POINTS);
#endif
    }

    /* coordinates beyond GA2D_MAX_COORDINATE: 10x the documented limit in
       either precision, and 1e30 in both (in float inertia, size^4, would
       overflow: 1e120 is past FLT_MAX = 3.4e38; in double it is past the
       1e15 policy bound) */
    for (i = 0; i < 4; ++i) pts[i] = ga2d_vec_scale(ok[i], (ga2d_real)(10 * (double)GA2D_MAX_COORDINATE));
    expect_make_fails(pts, 4, GA2D_ERR_TOO_LARGE);
    for (i = 0; i < 4; ++i) pts[i] = ga2d_vec_scale(ok[i], (ga2d_real)1e30);
    expect_make_fails(pts, 4, GA2D_ERR_TOO_LARGE);
    /* a failing call leaves a previously good output exactly as it was */
    CHECK_RESULT(ga2d_polygon_make(ok, 4, &out), GA2D_OK);
    {
        ga2d_polygon before = out;
        CHECK_RESULT(ga2d_polygon_make(pts, 4, &out), GA2D_ERR_TOO_LARGE);
        CHECK(memcmp(&before, &out, sizeof out) == 0);
    }
}

/* Accepted polygons at the edges of the tolerances: tiny and huge ones
   (the tolerances are relative), a thin plank, and every regular n-gon. */
static void make_accepts_extremes(void)
{
    const double scales[] = {1e-6, 1e-3, 1, 1e3, 1e6};
    ga2d_vec pts[4];
    ga2d_polygon p;
    size_t s;
    for (s = 0; s < sizeof scales / sizeof scales[0]; ++s) {
        ga2d_real k = (ga2d_real)scales[s];
        pts[0] = ga2d_vec_make(0, 0);
        pts[1] = ga2d_vec_make(k, 0);
        pts[2] = ga2d_vec_make(k, k);
        pts[3] = ga2d_vec_make(0, k);
        CHECK_RESULT(ga2d_polygon_make(pts, 4, &p), GA2D_OK);
        /* a 1000:1 plank: area ratio 1e-3, far above 1e-5 */
        pts[2].y = pts[3].y = k / 1000;
        CHECK_RESULT(ga2d_polygon_make(pts, 4, &p), GA2D_OK);
    }
    /* a unit square far from the origin keeps its shape: its vertices are
       exact at 1e4 in float (spacing 2^-10) */
    pts[0] = ga2d_vec_make(10000, 10000);
    pts[1] = ga2d_vec_make(10001, 10000);
    pts[2] = ga2d_vec_make(10001, 10001);
    pts[3] = ga2d_vec_make(10000, 10001);
    CHECK_RESULT(ga2d_polygon_make(pts, 4, &p), GA2D_OK);
    check_polygon_shape(&p);
}

static void hull_of_clouds(void)
{
    test_rng rng = {21};
    ga2d_vec pts[64];
    guarded g;
    int trial, ok_count = 0, too_many = 0;
    for (trial = 0; trial < 2000; ++trial) {
        int n = rng_int(&rng, 3, 40), i, j, k;
        double L = 0, tol;
        ga2d_result r;
        for (i = 0; i < n; ++i)
            pts[i] = ga2d_vec_make((ga2d_real)rng_uniform(&rng, -5, 5), (ga2d_real)rng_uniform(&rng, -2, 2));
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) {
                double dx = fabs((double)pts[i].x - (double)pts[j].x), dy = fabs((double)pts[i].y - (double)pts[j].y);
                L = dx > L ? dx : L;
                L = dy > L ? dy : L;
            }
        tol = 4 * 64 * REAL_EPS * L; /* the hull's documented tolerance */
        guard_fill(&g);
        r = ga2d_polygon_hull(pts, n, &g.poly);
        if (r == GA2D_ERR_TOO_MANY_POINTS) {
            ++too_many;
            CHECK(guard_untouched(&g));
            continue;
        }
        CHECK_RESULT(r, GA2D_OK);
        if (r != GA2D_OK) continue;
        ++ok_count;
        CHECK(guards_intact(&g));
        check_polygon_shape(&g.poly);
        /* every input point is inside, or within tol of an edge */
        for (i = 0; i < n; ++i)
            for (k = 0; k < g.poly.count; ++k)
                CHECK((double)ga2d_dot(g.poly.normals[k], ga2d_vec_sub(pts[i], g.poly.vertices[k])) <= tol + 8 * REAL_EPS * L);
        /* every hull vertex is an input point */
        for (k = 0; k < g.poly.count; ++k) {
            int found = 0;
            for (i = 0; i < n; ++i) found |= pts[i].x == g.poly.vertices[k].x && pts[i].y == g.poly.vertices[k].y;
            CHECK(found);
        }
        /* starts at the lowest-x point */
        for (i = 0; i < n; ++i) CHECK(pts[i].x >= g.poly.vertices[0].x);
    }
    /* both outcomes must have happened, or the test saw too little (a
       cloud of <= 40 points cannot outgrow a maximum of 40 or more) */
    CHECK(ok_count > 200);
    if (MAXV < 40) CHECK(too_many > 200);
    else CHECK(too_many == 0);
}

/* A square's corners, its edge midpoints, interior points and
   near-duplicates of the corners (closer than the weld tolerance) hull to
   the square: 4 vertices, CCW from the lowest-x corner. */
static void hull_welds_and_drops(void)
{
    ga2d_vec pts[40];
    ga2d_polygon p;
    test_rng rng = {22};
    double weld = 4 * 64 * REAL_EPS * 2; /* L = 2 */
    int n = 0, i;
    const ga2d_vec corners[4] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (i = 0; i < 4; ++i) {
        pts[n++] = corners[i];
        pts[n++] = ga2d_vec_make(corners[i].x * (ga2d_real)(1 - weld / 4), corners[i].y);
        pts[n++] = ga2d_vec_scale(ga2d_vec_add(corners[i], corners[(i + 1) % 4]), 0.5);
    }
    for (i = 0; i < 20; ++i) pts[n++] = ga2d_vec_make((ga2d_real)rng_uniform(&rng, -0.99, 0.99), (ga2d_real)rng_uniform(&rng, -0.99, 0.99));
    CHECK_RESULT(ga2d_polygon_hull(pts, n, &p), GA2D_OK);
    CHECK(p.count == 4);
    if (p.count == 4) {
        /* (-1,-1) first, then CCW; welded corners may be either copy */
        const ga2d_vec expect[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (i = 0; i < 4; ++i) {
            CHECK_NEAR(p.vertices[i].x, expect[i].x, weld);
            CHECK_NEAR(p.vertices[i].y, expect[i].y, weld);
        }
    }
    /* the hull of a valid polygon's vertices, shuffled, is that polygon */
    {
        ga2d_polygon hex = ga2d_polygon_regular(MAXV < 6 ? MAXV : 6, 2), back;
        ga2d_vec shuffled[MAXV];
        int m = hex.count, j;
        for (i = 0; i < m; ++i) shuffled[i] = hex.vertices[(i * 5 + 3) % m];
        CHECK_RESULT(ga2d_polygon_hull(shuffled, m, &back), GA2D_OK);
        CHECK(back.count == m);
        for (i = 0; i < m; ++i) {
            int found = 0;
            for (j = 0; j < m; ++j) found |= back.vertices[i].x == hex.vertices[j].x && back.vertices[i].y == hex.vertices[j].y;
            CHECK(found);
        }
    }
}

static void hull_rejects(void)
{
    ga2d_vec pts[MAXV + 20];
    int i;
    for (i = 0; i < 6; ++i) pts[i] = ga2d_vec_make((ga2d_real)i, (ga2d_real)(3 * i));
    expect_hull_fails(pts, 6, GA2D_ERR_COLLINEAR_POINTS);
    /* two distinct points, each repeated */
    for (i = 0; i < 6; ++i) pts[i] = ga2d_vec_make((ga2d_real)(i % 2), 1);
    expect_hull_fails(pts, 6, GA2D_ERR_TOO_FEW_POINTS);
    for (i = 0; i < 6; ++i) pts[i] = ga2d_vec_make(3, 4);
    expect_hull_fails(pts, 6, GA2D_ERR_TOO_FEW_POINTS);
    expect_hull_fails(pts, 2, GA2D_ERR_TOO_FEW_POINTS);
    expect_hull_fails(NULL, 5, GA2D_ERR_INVALID_ARGUMENT);
    /* a circle of MAXV + 20 points has a hull of that many vertices */
    for (i = 0; i < MAXV + 20; ++i)
        pts[i] = ga2d_vec_make((ga2d_real)cos(2 * PI * i / (MAXV + 20)), (ga2d_real)sin(2 * PI * i / (MAXV + 20)));
    expect_hull_fails(pts, MAXV + 20, GA2D_ERR_TOO_MANY_POINTS);
    pts[3].y = (ga2d_real)NAN;
    expect_hull_fails(pts, MAXV + 20, GA2D_ERR_NOT_FINITE);
    pts[3].y = (ga2d_real)(10 * (double)GA2D_MAX_COORDINATE);
    expect_hull_fails(pts, MAXV + 20, GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(ga2d_polygon_hull(pts, 5, NULL), GA2D_ERR_INVALID_ARGUMENT);
}

static void box_and_regular(void)
{
    ga2d_polygon b = ga2d_polygon_box(2, 0.5), r;
    int n, i;
    CHECK(b.count == 4);
    check_polygon_shape(&b);
    CHECK(b.vertices[0].x == -2 && b.vertices[0].y == -(ga2d_real)0.5 && b.vertices[2].x == 2 && b.vertices[2].y == (ga2d_real)0.5);
    CHECK(ga2d_polygon_box(0, 1).count == 0);
    CHECK(ga2d_polygon_box(1, -1).count == 0);
    CHECK(ga2d_polygon_box((ga2d_real)NAN, 1).count == 0);
    CHECK(ga2d_polygon_box(1, (ga2d_real)INFINITY).count == 0);
    for (n = 3; n <= MAXV; ++n) {
        r = ga2d_polygon_regular(n, 3);
        CHECK(r.count == n);
        check_polygon_shape(&r);
        /* vertices on the circle: cos/sin rounded once to ga2d_real */
        for (i = 0; i < n; ++i) CHECK_NEAR(ga2d_vec_length(r.vertices[i]), 3, 4 * REAL_EPS * 3);
        CHECK(r.vertices[0].x == 3 && r.vertices[0].y == 0);
    }
    CHECK(ga2d_polygon_regular(2, 1).count == 0);
    CHECK(ga2d_polygon_regular(MAXV + 1, 1).count == 0);
    CHECK(ga2d_polygon_regular(5, 0).count == 0);
    CHECK(ga2d_polygon_regular(5, (ga2d_real)NAN).count == 0);
}

/* Transforms: apply and its inverse, composition, inv_mul.  Each is one or
   two rotations and additions of values of size <= 20: 64 eps * 20. */
static void transforms(void)
{
    test_rng rng = {23};
    int i;
    for (i = 0; i < 1000; ++i) {
        ga2d_transform a = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&rng, -5, 5), (ga2d_real)rng_uniform(&rng, -5, 5)),
                                               ga2d_rotor_from_angle((ga2d_real)rng_uniform(&rng, -4, 4)));
        ga2d_transform b = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&rng, -5, 5), (ga2d_real)rng_uniform(&rng, -5, 5)),
                                               ga2d_rotor_from_angle((ga2d_real)rng_uniform(&rng, -4, 4)));
        ga2d_vec v = ga2d_vec_make((ga2d_real)rng_uniform(&rng, -5, 5), (ga2d_real)rng_uniform(&rng, -5, 5));
        ga2d_vec w, u;
        double tol = 64 * REAL_EPS * 20;
        w = ga2d_transform_apply_inv(a, ga2d_transform_apply(a, v));
        CHECK_NEAR(w.x, v.x, tol);
        CHECK_NEAR(w.y, v.y, tol);
        w = ga2d_transform_apply(ga2d_transform_inverse(a), v);
        u = ga2d_transform_apply_inv(a, v);
        CHECK_NEAR(w.x, u.x, tol);
        CHECK_NEAR(w.y, u.y, tol);
        w = ga2d_transform_apply(ga2d_transform_mul(a, b), v);
        u = ga2d_transform_apply(a, ga2d_transform_apply(b, v));
        CHECK_NEAR(w.x, u.x, tol);
        CHECK_NEAR(w.y, u.y, tol);
        w = ga2d_transform_apply(ga2d_transform_inv_mul(a, b), v);
        u = ga2d_transform_apply(ga2d_transform_mul(ga2d_transform_inverse(a), b), v);
        CHECK_NEAR(w.x, u.x, tol);
        CHECK_NEAR(w.y, u.y, tol);
    }
    {
        ga2d_transform id = ga2d_transform_identity();
        ga2d_vec v = ga2d_vec_make(1.5, -2);
        CHECK(ga2d_transform_apply(id, v).x == v.x && ga2d_transform_apply(id, v).y == v.y);
    }
}

/* The AABB of a unit box turned 45 degrees at (10, 5): half-diagonal
   sqrt(2)/2, and each side touched by a vertex. */
static void aabb_of_transformed_polygon(void)
{
    ga2d_polygon b = ga2d_polygon_box(0.5, 0.5);
    ga2d_transform x = ga2d_transform_make(ga2d_vec_make(10, 5), ga2d_rotor_from_angle((ga2d_real)(PI / 4)));
    ga2d_aabb box = ga2d_polygon_aabb(&b, x);
    double h = sqrt(0.5), tol = 16 * REAL_EPS * 10;
    test_rng rng = {24};
    int i, k;
    CHECK_NEAR(box.lower.x, 10 - h, tol);
    CHECK_NEAR(box.upper.x, 10 + h, tol);
    CHECK_NEAR(box.lower.y, 5 - h, tol);
    CHECK_NEAR(box.upper.y, 5 + h, tol);
    for (i = 0; i < 200; ++i) {
        ga2d_polygon p = ga2d_polygon_regular(rng_int(&rng, 3, MAXV), (ga2d_real)rng_uniform(&rng, 0.1, 3));
        int hit[4] = {0, 0, 0, 0};
        x = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&rng, -50, 50), (ga2d_real)rng_uniform(&rng, -50, 50)),
                                ga2d_rotor_from_angle((ga2d_real)rng_uniform(&rng, -4, 4)));
        box = ga2d_polygon_aabb(&p, x);
        for (k = 0; k < p.count; ++k) {
            ga2d_vec v = ga2d_transform_apply(x, p.vertices[k]);
            CHECK(v.x >= box.lower.x && v.x <= box.upper.x && v.y >= box.lower.y && v.y <= box.upper.y);
            hit[0] |= v.x == box.lower.x;
            hit[1] |= v.x == box.upper.x;
            hit[2] |= v.y == box.lower.y;
            hit[3] |= v.y == box.upper.y;
        }
        CHECK(hit[0] && hit[1] && hit[2] && hit[3]);
    }
}

void suite_polygon(void)
{
    test_run("polygon: make accepts a CCW convex polygon, copies it, outward normals", make_accepts_and_copies);
    test_run("polygon: make names each bad input and writes nothing", make_rejects_bad_input);
    test_run("polygon: make accepts tiny, huge, thin and far polygons", make_accepts_extremes);
    test_run("polygon: hull of 2000 random clouds contains them, convex", hull_of_clouds);
    test_run("polygon: hull welds near-duplicates and drops edge points", hull_welds_and_drops);
    test_run("polygon: hull names collinear, too few, too many", hull_rejects);
    test_run("polygon: box and regular n-gons", box_and_regular);
    test_run("polygon: transform apply, inverse, composition", transforms);
    test_run("polygon: AABB of a transformed polygon", aabb_of_transformed_polygon);
}
