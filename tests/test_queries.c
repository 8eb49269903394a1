/* Queries (issue 25): ray casts against each shape and through the world,
   overlaps, and the body listing.

   Every ray is checked against an independent answer computed in double
   from the same (rounded) inputs: a shape's signed distance f(x) (a
   circle's |x - c| - r, a capsule's distance from its segment less r, a
   polygon's from its core, recomputed from the vertices, less its
   radius), which along a ray is a convex function of t for a convex
   shape.  So the ray misses when the least f along it is > 0 (found by
   golden-section search), starts inside when f(origin) < 0, and enters at
   the root of f before that least point (found by bisection).  Segments
   are checked by the signs of two orientations instead (o1 = (b - a) ^
   (p - a) at the ray's ends, entry at o1 / (o1 - o2)).

   The bound.  The library's hit is a few operations (an offset, a dot
   product, a square root, a quotient, the point) on numbers no larger than
   S = |origin - the shape's centre| + |translation| + the shape's size;
   each rounding moves the boundary point it finds by at most eps/2 of S
   along the surface's normal (the square root's error, large for a grazing
   ray, is divided back out: |n . u| is the square root's value over r).
   Eight roundings, the point's own included, give 4 eps S; the bound is
   TOL_K = 8 eps S, twice that.  Measured along the normal: a hit's
   point is within it of the surface, and its fraction within it of the
   true one times |translation| |n . u|.  A ray whose least f, or whose
   start's f, is within the bound of 0 may go either way and is not
   counted (their number is printed).

   With GA2D_TEST_VERBOSE set each check prints its worst figure next to
   its bound. */
#include "test.h"

#include <float.h>

#define TOL_K 8.0
#define RAYS_PER_TYPE 2000
#define WORLD_SHAPES 1000
#define WORLD_QUERIES 200

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

/* ------------------------------------------------------------ brute force */
typedef struct dvec { double x, y; } dvec;
static dvec dv(double x, double y) { dvec r; r.x = x; r.y = y; return r; }
static dvec dvg(ga2d_vec v) { return dv((double)v.x, (double)v.y); }
static dvec dsub(dvec a, dvec b) { return dv(a.x - b.x, a.y - b.y); }
static dvec dadd(dvec a, dvec b) { return dv(a.x + b.x, a.y + b.y); }
static dvec dscale(dvec a, double s) { return dv(a.x * s, a.y * s); }
static double ddot(dvec a, dvec b) { return a.x * b.x + a.y * b.y; }
static double dcross(dvec a, dvec b) { return a.x * b.y - a.y * b.x; }
static double dlen(dvec a) { return sqrt(ddot(a, a)); }

/* The closest point of segment a-b to x. */
static dvec closest_on_segment(dvec a, dvec b, dvec x)
{
    dvec e = dsub(b, a);
    double ee = ddot(e, e), s = ee > 0 ? ddot(dsub(x, a), e) / ee : 0;
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    return dadd(a, dscale(e, s));
}

/* A shape's signed distance at x (its own frame), and the outward unit
   normal of the nearest boundary there (*n, may be NULL).  *corner is set
   when x is within tol of two faces of a sharp polygon (its normal is
   then either face's). */
static double sdf(const ga2d_geometry *g, dvec x, dvec *n, int *corner, double tol)
{
    dvec c, q = dv(0, 0);
    double r = 0, d;
    int i, k;
    if (corner) *corner = 0;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE:
        c = dvg(g->as.circle.center);
        r = (double)g->as.circle.radius;
        q = c;
        break;
    case GA2D_SHAPE_CAPSULE:
        q = closest_on_segment(dvg(g->as.capsule.center1), dvg(g->as.capsule.center2), x);
        r = (double)g->as.capsule.radius;
        break;
    case GA2D_SHAPE_POLYGON: {
        const ga2d_polygon *p = &g->as.polygon;
        double best = -1e300, second = -1e300;
        int face = 0;
        r = (double)p->radius;
        for (i = 0; i < p->count; ++i) {
            dvec a = dvg(p->vertices[i]), b = dvg(p->vertices[(i + 1) % p->count]), e = dsub(b, a), nn;
            double s;
            nn = dscale(dv(e.y, -e.x), 1 / dlen(e));
            s = ddot(nn, dsub(x, a));
            if (s > best) {
                second = best;
                best = s;
                face = i;
            } else if (s > second) {
                second = s;
            }
        }
        if (best <= 0) { /* inside the core: the nearest face */
            dvec a = dvg(p->vertices[face]), b = dvg(p->vertices[(face + 1) % p->count]), e = dsub(b, a);
            if (n) *n = dscale(dv(e.y, -e.x), 1 / dlen(e));
            if (corner) *corner = best - second <= tol;
            return best - r;
        }
        d = 1e300;
        for (k = 0; k < p->count; ++k) {
            dvec cq = closest_on_segment(dvg(p->vertices[k]), dvg(p->vertices[(k + 1) % p->count]), x);
            double dd = dlen(dsub(x, cq));
            if (dd < d) {
                d = dd;
                q = cq;
            }
        }
        if (r == 0 && d <= tol) { /* on a sharp boundary: the face's normal, a corner's either */
            dvec a = dvg(p->vertices[face]), b = dvg(p->vertices[(face + 1) % p->count]), e = dsub(b, a);
            if (n) *n = dscale(dv(e.y, -e.x), 1 / dlen(e));
            if (corner) *corner = best - second <= 2 * tol;
            return d;
        }
        break;
    }
    default: return 1e300; /* segments: not by distance */
    }
    d = dlen(dsub(x, q));
    if (n) *n = d > 0 ? dscale(dsub(x, q), 1 / d) : dv(0, 0);
    return d - r;
}

/* A shape's size: its vertices' and centres' distance from its frame's
   origin plus its radius (the S of the bound, with the ray's). */
static double geometry_size(const ga2d_geometry *g)
{
    double s = 0;
    int i;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE: return dlen(dvg(g->as.circle.center)) + (double)g->as.circle.radius;
    case GA2D_SHAPE_CAPSULE:
        s = dlen(dvg(g->as.capsule.center1));
        if (dlen(dvg(g->as.capsule.center2)) > s) s = dlen(dvg(g->as.capsule.center2));
        return s + (double)g->as.capsule.radius;
    case GA2D_SHAPE_POLYGON:
        for (i = 0; i < g->as.polygon.count; ++i)
            if (dlen(dvg(g->as.polygon.vertices[i])) > s) s = dlen(dvg(g->as.polygon.vertices[i]));
        return s + (double)g->as.polygon.radius;
    default: {
        const ga2d_segment *sg = g->type == GA2D_SHAPE_SEGMENT ? &g->as.segment : &g->as.chain_segment.segment;
        s = dlen(dvg(sg->point1));
        if (dlen(dvg(sg->point2)) > s) s = dlen(dvg(sg->point2));
        return s;
    }
    }
}

/* The brute-force answer for a round or polygon shape: 1 hit (*t the
   fraction, *n the normal), 0 miss, -1 too close to call. */
typedef struct brute { int kind; double t; dvec n; int corner; } brute;
static brute brute_ray(const ga2d_geometry *g, dvec p, dvec d, double tol)
{
    brute out;
    double lo = 0, hi = 1, f0, fmin, tmin;
    int i;
    dvec n;
    const double phi = 0.6180339887498949;
    memset(&out, 0, sizeof out);
    f0 = sdf(g, p, NULL, NULL, tol);
    if (fabs(f0) <= tol) {
        out.kind = -1;
        return out;
    }
    if (f0 < 0) return out; /* starts inside: no hit, by the documented rule */
    /* golden-section search for f's least value on [0, 1] */
    {
        double a = 0, b = 1, x1 = b - phi * (b - a), x2 = a + phi * (b - a);
        double f1 = sdf(g, dadd(p, dscale(d, x1)), NULL, NULL, tol), f2 = sdf(g, dadd(p, dscale(d, x2)), NULL, NULL, tol);
        for (i = 0; i < 200 && b - a > 1e-17; ++i) {
            if (f1 < f2) {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - phi * (b - a);
                f1 = sdf(g, dadd(p, dscale(d, x1)), NULL, NULL, tol);
            } else {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + phi * (b - a);
                f2 = sdf(g, dadd(p, dscale(d, x2)), NULL, NULL, tol);
            }
        }
        tmin = (a + b) / 2;
        fmin = sdf(g, dadd(p, dscale(d, tmin)), NULL, NULL, tol);
        if (sdf(g, dadd(p, d), NULL, NULL, tol) < fmin) {
            tmin = 1;
            fmin = sdf(g, dadd(p, d), NULL, NULL, tol);
        }
    }
    if (fabs(fmin) <= tol) {
        out.kind = -1;
        return out;
    }
    if (fmin > 0) return out; /* misses */
    hi = tmin;
    for (i = 0; i < 200; ++i) {
        double mid = (lo + hi) / 2;
        if (mid <= lo || mid >= hi) break;
        if (sdf(g, dadd(p, dscale(d, mid)), NULL, NULL, tol) > 0)
            lo = mid;
        else
            hi = mid;
    }
    out.kind = 1;
    out.t = (lo + hi) / 2;
    sdf(g, dadd(p, dscale(d, out.t)), &n, &out.corner, tol);
    out.n = n;
    return out;
}

/* The same for a segment (one_sided: from its left only). */
static brute brute_segment(const ga2d_segment *s, int one_sided, dvec p, dvec d, double tol)
{
    brute out;
    dvec a = dvg(s->point1), b = dvg(s->point2), e = dsub(b, a), n;
    double le = dlen(e), o1, o2, t, along;
    memset(&out, 0, sizeof out);
    if (le == 0) return out;
    n = dscale(dv(-e.y, e.x), 1 / le); /* left */
    o1 = ddot(n, dsub(p, a));
    o2 = ddot(n, dsub(dadd(p, d), a));
    if (fabs(o1) <= tol || fabs(o2) <= tol || fabs(ddot(n, d)) <= tol) {
        out.kind = -1; /* an end on its line, or along it */
        return out;
    }
    if ((o1 > 0) == (o2 > 0)) return out;
    if (one_sided && o1 < 0) return out; /* from behind */
    t = o1 / (o1 - o2);
    along = ddot(dsub(dadd(p, dscale(d, t)), a), e) / le;
    if (fabs(along) <= tol || fabs(along - le) <= tol) {
        out.kind = -1;
        return out;
    }
    if (along < 0 || along > le) return out;
    out.kind = 1;
    out.t = t;
    out.n = o1 > 0 ? n : dscale(n, -1);
    return out;
}

/* --------------------------------------------------------------- shapes */
static void random_geometry(test_rng *r, int type, ga2d_geometry *g)
{
    memset(g, 0, sizeof *g);
    g->type = (ga2d_shape_type)type;
    switch (type) {
    case GA2D_SHAPE_CIRCLE:
        g->as.circle.center = ga2d_vec_make((ga2d_real)rng_uniform(r, -1, 1), (ga2d_real)rng_uniform(r, -1, 1));
        g->as.circle.radius = (ga2d_real)rng_uniform(r, 0.05, 2);
        break;
    case GA2D_SHAPE_CAPSULE:
        g->as.capsule.center1 = ga2d_vec_make((ga2d_real)rng_uniform(r, -1.5, 1.5), (ga2d_real)rng_uniform(r, -1.5, 1.5));
        g->as.capsule.center2 = ga2d_vec_make((ga2d_real)rng_uniform(r, -1.5, 1.5), (ga2d_real)rng_uniform(r, -1.5, 1.5));
        g->as.capsule.radius = (ga2d_real)rng_uniform(r, 0.05, 1);
        break;
    case GA2D_SHAPE_POLYGON: {
        ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
        int n, i;
        do {
            n = rng_int(r, 3, GA2D_MAX_POLYGON_VERTICES);
            for (i = 0; i < n; ++i) pts[i] = ga2d_vec_make((ga2d_real)rng_uniform(r, -2, 2), (ga2d_real)rng_uniform(r, -2, 2));
        } while (ga2d_polygon_hull(pts, n, &g->as.polygon) != GA2D_OK);
        g->as.polygon.radius = rng_int(r, 0, 1) ? (ga2d_real)rng_uniform(r, 0.01, 0.5) : 0;
        break;
    }
    default:
        g->as.segment.point1 = ga2d_vec_make((ga2d_real)rng_uniform(r, -2, 2), (ga2d_real)rng_uniform(r, -2, 2));
        g->as.segment.point2 = ga2d_vec_make((ga2d_real)rng_uniform(r, -2, 2), (ga2d_real)rng_uniform(r, -2, 2));
        break;
    }
}

/* The library's world-free cast of g (type by type, or through
   ga2d_ray_cast_shape with the identity). */
static ga2d_ray_result cast_local(const ga2d_geometry *g, ga2d_vec o, ga2d_vec d, int one_sided)
{
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE: return ga2d_ray_cast_circle(&g->as.circle, o, d);
    case GA2D_SHAPE_CAPSULE: return ga2d_ray_cast_capsule(&g->as.capsule, o, d);
    case GA2D_SHAPE_POLYGON: return ga2d_ray_cast_polygon(&g->as.polygon, o, d);
    default: return ga2d_ray_cast_segment(&g->as.segment, o, d, one_sided);
    }
}

/* --------------------------------------------------------- ray vs brute */
/* Random rays against random shapes of each type: half aimed at a point
   near the shape (most hit), half anywhere.  Each hit agrees with the
   brute-force answer within the bound; misses and starts inside agree. */
static void rays_against_brute_force(void)
{
    static const char *names[] = {"circle", "capsule", "polygon", "segment", "one-sided segment"};
    test_rng r = {25};
    int type;
    for (type = 0; type < 5; ++type) {
        int i, hits = 0, misses = 0, unsure = 0;
        double worst_surface = 0, worst_t = 0, worst_n = 0;
        for (i = 0; i < RAYS_PER_TYPE; ++i) {
            ga2d_geometry g;
            ga2d_ray_result got;
            ga2d_vec o, d, aim;
            dvec p, dd;
            brute want;
            double S, tol;
            int one_sided = type == 4;
            random_geometry(&r, type < 4 ? type : GA2D_SHAPE_SEGMENT, &g);
            o = ga2d_vec_make((ga2d_real)rng_uniform(&r, -6, 6), (ga2d_real)rng_uniform(&r, -6, 6));
            aim = rng_int(&r, 0, 1) ? ga2d_vec_make((ga2d_real)rng_uniform(&r, -2, 2), (ga2d_real)rng_uniform(&r, -2, 2))
                                    : ga2d_vec_make((ga2d_real)rng_uniform(&r, -8, 8), (ga2d_real)rng_uniform(&r, -8, 8));
            d = ga2d_vec_scale(ga2d_vec_sub(aim, o), (ga2d_real)rng_uniform(&r, 0.3, 2));
            if (d.x == 0 && d.y == 0) continue;
            p = dvg(o);
            dd = dvg(d);
            S = dlen(p) + dlen(dd) + geometry_size(&g);
            tol = TOL_K * REAL_EPS * S;
            want = type < 3 ? brute_ray(&g, p, dd, tol) : brute_segment(&g.as.segment, one_sided, p, dd, tol);
            got = cast_local(&g, o, d, one_sided);
            CHECK(ga2d_shape_id_is_null(got.shape) && ga2d_body_id_is_null(got.body));
            if (want.kind < 0) {
                ++unsure;
                continue;
            }
            if (want.kind == 0) {
                ++misses;
                CHECK(!got.hit);
                continue;
            }
            ++hits;
            CHECK(got.hit);
            if (!got.hit) continue;
            {
                dvec at = dvg(got.point), n = dvg(got.normal);
                double along = fabs(ddot(want.n, dscale(dd, 1 / dlen(dd)))), es, et, en;
                /* on the surface: its distance from the shape's boundary */
                es = type < 3 ? fabs(sdf(&g, at, NULL, NULL, tol)) : fabs(dcross(dsub(dvg(g.as.segment.point2), dvg(g.as.segment.point1)), dsub(at, dvg(g.as.segment.point1)))) / dlen(dsub(dvg(g.as.segment.point2), dvg(g.as.segment.point1)));
                /* the fraction, measured along the normal */
                et = fabs((double)got.fraction - want.t) * dlen(dd) * along;
                /* the normal: unit, and the true one (a corner's either face passes by facing the ray) */
                en = want.corner ? (ddot(n, dd) <= tol * dlen(dd) ? 0 : 1) : dlen(dsub(n, want.n));
                CHECK(es <= tol);
                CHECK(et <= tol);
                CHECK(fabs(dlen(n) - 1) <= 4 * REAL_EPS);
                /* the normal's angle: the surface point's error over the
                   curvature radius (at least 0.01 m here: a rounded
                   polygon's smallest radius), or eps for a flat face */
                CHECK(en <= tol / 0.01 + 4 * REAL_EPS);
                if (got.fraction < 0 || got.fraction > 1) CHECK(0);
                if (es / tol > worst_surface) worst_surface = es / tol;
                if (et / tol > worst_t) worst_t = et / tol;
                if (en > worst_n) worst_n = en;
            }
        }
        CHECK(hits > RAYS_PER_TYPE / 20 && misses > RAYS_PER_TYPE / 10); /* both kinds of case were made */
        if (verbose())
            printf("queries: %s: %d hits, %d misses, %d too close to call; worst |f(point)| %.3g, fraction along the "
                   "normal %.3g of the bound %g eps S; normal off by %.3g\n",
                   names[type], hits, misses, unsure, worst_surface, worst_t, TOL_K, worst_n);
    }
}

/* The documented edge cases, exactly. */
static void ray_edge_cases(void)
{
    ga2d_polygon box = ga2d_polygon_box(1, 1);
    ga2d_circle c = {{0, 0}, 1};
    ga2d_capsule cap = {{-1, 0}, {1, 0}, (ga2d_real)0.5};
    ga2d_segment s = {{-1, 0}, {1, 0}};
    ga2d_ray_result r;
    /* from inside: no hit, for every shape */
    CHECK(!ga2d_ray_cast_polygon(&box, ga2d_vec_make(0, 0), ga2d_vec_make(5, 0)).hit);
    CHECK(!ga2d_ray_cast_circle(&c, ga2d_vec_make((ga2d_real)0.5, 0), ga2d_vec_make(5, 0)).hit);
    CHECK(!ga2d_ray_cast_capsule(&cap, ga2d_vec_make((ga2d_real)1.2, 0), ga2d_vec_make(5, 0)).hit);
    box.radius = (ga2d_real)0.25;
    CHECK(!ga2d_ray_cast_polygon(&box, ga2d_vec_make((ga2d_real)1.2, (ga2d_real)1.1), ga2d_vec_make(5, 0)).hit); /* in a rounded corner */
    box.radius = 0;
    /* head on: the face, its normal, the fraction exactly (all values exact in binary) */
    r = ga2d_ray_cast_polygon(&box, ga2d_vec_make(-3, 0), ga2d_vec_make(4, 0));
    CHECK(r.hit && r.fraction == (ga2d_real)0.5 && r.point.x == -1 && r.normal.x == -1 && r.normal.y == 0);
    r = ga2d_ray_cast_circle(&c, ga2d_vec_make(0, 3), ga2d_vec_make(0, -4));
    CHECK(r.hit && r.fraction == (ga2d_real)0.5 && r.point.y == 1 && r.normal.y == 1);
    r = ga2d_ray_cast_capsule(&cap, ga2d_vec_make(0, (ga2d_real)2.5), ga2d_vec_make(0, -4));
    CHECK(r.hit && r.fraction == (ga2d_real)0.5 && r.point.y == (ga2d_real)0.5 && r.normal.y == 1);
    /* through a corner exactly (a diagonal through (1, 1)): a hit there */
    r = ga2d_ray_cast_polygon(&box, ga2d_vec_make(2, 2), ga2d_vec_make(-2, -2));
    CHECK(r.hit && r.fraction == (ga2d_real)0.5);
    /* grazing a corner from the side (along y = 1, the top face's line): running along a face is outside no edge, so
       the ray that skims the top face is a hit at the corner it enters by */
    r = ga2d_ray_cast_polygon(&box, ga2d_vec_make(-3, 1), ga2d_vec_make(4, 0));
    CHECK(r.hit && r.fraction == (ga2d_real)0.5 && r.normal.x == -1);
    /* along a segment's line: no hit; tangent to a circle: a hit at the touching point */
    CHECK(!ga2d_ray_cast_segment(&s, ga2d_vec_make(-3, 0), ga2d_vec_make(6, 0), 0).hit);
    r = ga2d_ray_cast_circle(&c, ga2d_vec_make(-3, 1), ga2d_vec_make(6, 0));
    CHECK(r.hit && r.fraction == (ga2d_real)0.5 && r.normal.y == 1);
    /* a segment from either side, and one-sided only from the left (above, for point1 -> point2 along +x) */
    r = ga2d_ray_cast_segment(&s, ga2d_vec_make(0, -1), ga2d_vec_make(0, 2), 0);
    CHECK(r.hit && r.fraction == (ga2d_real)0.5 && r.normal.y == -1);
    CHECK(!ga2d_ray_cast_segment(&s, ga2d_vec_make(0, -1), ga2d_vec_make(0, 2), 1).hit);
    r = ga2d_ray_cast_segment(&s, ga2d_vec_make(0, 1), ga2d_vec_make(0, -2), 1);
    CHECK(r.hit && r.fraction == (ga2d_real)0.5 && r.normal.y == 1);
    /* short of the shape, and exactly reaching it */
    CHECK(!ga2d_ray_cast_circle(&c, ga2d_vec_make(-3, 0), ga2d_vec_make((ga2d_real)1.5, 0)).hit);
    r = ga2d_ray_cast_circle(&c, ga2d_vec_make(-3, 0), ga2d_vec_make(2, 0));
    CHECK(r.hit && r.fraction == 1);
    /* bad input: no hit */
    CHECK(!ga2d_ray_cast_circle(NULL, ga2d_vec_make(-3, 0), ga2d_vec_make(4, 0)).hit);
    CHECK(!ga2d_ray_cast_circle(&c, ga2d_vec_make(-3, 0), ga2d_vec_make(0, 0)).hit);
    CHECK(!ga2d_ray_cast_circle(&c, ga2d_vec_make(-3, 0), ga2d_vec_make((ga2d_real)NAN, 0)).hit);
    c.radius = -1;
    CHECK(!ga2d_ray_cast_circle(&c, ga2d_vec_make(-3, 0), ga2d_vec_make(4, 0)).hit);
}

/* ga2d_ray_cast_shape: the local cast carried by a transform, and its
   named errors.  The placed hit is the local one moved by x: within
   rounding of the transform (a few eps of the coordinates' size). */
static void ray_cast_shape_placed(void)
{
    test_rng r = {2501};
    int i, type, flipped = 0;
    double worst = 0;
    for (i = 0; i < 400; ++i) {
        ga2d_geometry g;
        ga2d_transform x;
        ga2d_vec o, d;
        ga2d_ray_result local, placed;
        type = i % 4;
        random_geometry(&r, type, &g);
        x = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&r, -50, 50), (ga2d_real)rng_uniform(&r, -50, 50)),
                                ga2d_rotor_from_angle((ga2d_real)rng_uniform(&r, -3.1, 3.1)));
        o = ga2d_vec_make((ga2d_real)rng_uniform(&r, -6, 6), (ga2d_real)rng_uniform(&r, -6, 6));
        d = ga2d_vec_make((ga2d_real)rng_uniform(&r, -8, 8), (ga2d_real)rng_uniform(&r, -8, 8));
        local = cast_local(&g, o, d, 0);
        CHECK_RESULT(ga2d_ray_cast_shape(&g, x, ga2d_transform_apply(x, o), ga2d_rotate(x.q, d), &placed), GA2D_OK);
        if (local.hit != placed.hit) {
            ++flipped; /* a ray within rounding of grazing may go either way once moved: rare */
            continue;
        }
        if (local.hit) {
            /* S = 50 sqrt 2 + the ray and shape: the transform's rounding is 4 eps S, the cast's TOL_K eps S */
            double S = 71 + 20, tol = (TOL_K + 4) * REAL_EPS * S, e;
            e = dlen(dsub(dvg(placed.point), dvg(ga2d_transform_apply(x, local.point))));
            CHECK(e <= tol / fabs(ddot(dvg(local.normal), dscale(dvg(d), 1 / dlen(dvg(d))))) + tol);
            if (e / tol > worst) worst = e / tol;
        }
    }
    {
        ga2d_geometry g;
        ga2d_ray_result out;
        ga2d_transform bad = ga2d_transform_identity();
        random_geometry(&r, GA2D_SHAPE_CIRCLE, &g);
        CHECK_RESULT(ga2d_ray_cast_shape(NULL, bad, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), &out), GA2D_ERR_INVALID_ARGUMENT);
        CHECK_RESULT(ga2d_ray_cast_shape(&g, bad, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), NULL), GA2D_ERR_INVALID_ARGUMENT);
        CHECK_RESULT(ga2d_ray_cast_shape(&g, bad, ga2d_vec_make(0, 0), ga2d_vec_make(0, 0), &out), GA2D_ERR_INVALID_ARGUMENT);
        CHECK_RESULT(ga2d_ray_cast_shape(&g, bad, ga2d_vec_make((ga2d_real)INFINITY, 0), ga2d_vec_make(1, 0), &out),
                     GA2D_ERR_NOT_FINITE);
        bad.q.c = 2; /* not unit */
        CHECK_RESULT(ga2d_ray_cast_shape(&g, bad, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), &out), GA2D_ERR_INVALID_ARGUMENT);
        bad.q.c = (ga2d_real)NAN;
        CHECK_RESULT(ga2d_ray_cast_shape(&g, bad, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), &out), GA2D_ERR_NOT_FINITE);
        g.as.circle.radius = -1;
        CHECK_RESULT(ga2d_ray_cast_shape(&g, ga2d_transform_identity(), ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), &out),
                     GA2D_ERR_INVALID_ARGUMENT);
    }
    CHECK(flipped <= 4); /* 1 % of the rays: grazing within rounding is far rarer in random rays */
    if (verbose()) printf("queries: placed casts: worst point difference %.3g of the bound, %d of 400 flipped\n", worst, flipped);
}

/* A ray ending at the real range's end (M, the largest real): a hit's
   point is the ray's at its fraction, which lies between the origin and
   the end, both finite, however the turn back from the shape's frame
   rounds.  The box [-M/4, M/4] x [M/2, M] (a sharp polygon, whose cast
   takes differences and unit dot products only, so nothing overflows),
   given in the frame of a placement turned by each angle of a sweep, and
   a ray down from (M/8, M), a point of its top edge: where rounding puts
   the origin outside the box the ray enters it at once, at (M/8, M),
   whose turn back may round past M.  Each hit's point within
   (TOL_K + 4) eps M per coordinate of origin + fraction translation (the
   cast's rounding at size M, and the turn's).  A ray whose end is not
   finite is refused. */
static void ray_cast_at_range_end(void)
{
    const double M = REAL_MAX, tol = (TOL_K + 4) * REAL_EPS * M;
    const ga2d_vec corner[4] = {{(ga2d_real)(-M / 4), (ga2d_real)(M / 2)}, {(ga2d_real)(M / 4), (ga2d_real)(M / 2)},
                                {(ga2d_real)(M / 4), (ga2d_real)M}, {(ga2d_real)(-M / 4), (ga2d_real)M}};
    const ga2d_vec side[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    ga2d_vec o = ga2d_vec_make((ga2d_real)(M / 8), (ga2d_real)M), d = ga2d_vec_make(0, (ga2d_real)(-M / 2));
    int i, k, hits = 0, rounded_past = 0;
    for (i = 0; i < 1024; ++i) {
        ga2d_geometry g;
        ga2d_transform x = ga2d_transform_make(ga2d_vec_make(0, 0), ga2d_rotor_from_angle((ga2d_real)(-3.14 + i * (6.28 / 1024))));
        ga2d_ray_result h, local;
        ga2d_vec turned;
        memset(&g, 0, sizeof g);
        g.type = GA2D_SHAPE_POLYGON;
        g.as.polygon.count = 4;
        for (k = 0; k < 4; ++k) {
            g.as.polygon.vertices[k] = ga2d_rotate_inv(x.q, corner[k]);
            g.as.polygon.normals[k] = ga2d_rotate_inv(x.q, side[k]);
            if (!isfinite((double)g.as.polygon.vertices[k].x) || !isfinite((double)g.as.polygon.vertices[k].y)) break;
        }
        if (k < 4) continue; /* a corner (M/4, M) turns past the range */
        CHECK_RESULT(ga2d_ray_cast_shape(&g, x, o, d, &h), GA2D_OK);
        if (!h.hit) continue;
        ++hits;
        local = ga2d_ray_cast_polygon(&g.as.polygon, ga2d_rotate_inv(x.q, o), ga2d_rotate_inv(x.q, d));
        turned = ga2d_transform_apply(x, local.point);
        rounded_past += !isfinite((double)turned.x) || !isfinite((double)turned.y);
        CHECK(h.fraction >= 0 && h.fraction <= 1);
        CHECK(isfinite((double)h.point.x) && isfinite((double)h.point.y));
        CHECK(fabs((double)o.x + (double)h.fraction * (double)d.x - (double)h.point.x) <= tol);
        CHECK(fabs((double)o.y + (double)h.fraction * (double)d.y - (double)h.point.y) <= tol);
    }
    CHECK(rounded_past > 0); /* the case is exercised: some turns back round past the range */
    {
        ga2d_geometry g;
        ga2d_ray_result h;
        memset(&g, 0, sizeof g);
        g.type = GA2D_SHAPE_CIRCLE;
        g.as.circle.radius = 1;
        CHECK_RESULT(ga2d_ray_cast_shape(&g, ga2d_transform_identity(), ga2d_vec_make(0, (ga2d_real)M), ga2d_vec_make(0, (ga2d_real)M), &h),
                     GA2D_ERR_NOT_FINITE);
        CHECK(!ga2d_ray_cast_circle(&g.as.circle, ga2d_vec_make(0, (ga2d_real)M), ga2d_vec_make(0, (ga2d_real)M)).hit);
    }
    if (verbose()) printf("queries: range end: %d hits, %d rounded past the range when turned back\n", hits, rounded_past);
}

/* ------------------------------------------------- distance, casts, TOI */
/* A random proxy: a hull of 3 to 8 points, a capsule's two, a circle's
   one (a radius 0 to 0.5; a point cloud of 2 with radius 0 is a segment). */
static ga2d_shape_proxy random_proxy(test_rng *r)
{
    ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
    ga2d_polygon p;
    int kind = rng_int(r, 0, 3), n, i;
    ga2d_real radius = rng_int(r, 0, 2) ? (ga2d_real)rng_uniform(r, 0, 0.5) : 0;
    if (kind == 0) {
        pts[0] = ga2d_vec_make((ga2d_real)rng_uniform(r, -0.5, 0.5), (ga2d_real)rng_uniform(r, -0.5, 0.5));
        return ga2d_make_proxy(pts, 1, (ga2d_real)rng_uniform(r, 0.05, 1));
    }
    if (kind == 1) {
        for (i = 0; i < 2; ++i) pts[i] = ga2d_vec_make((ga2d_real)rng_uniform(r, -1, 1), (ga2d_real)rng_uniform(r, -1, 1));
        return ga2d_make_proxy(pts, 2, radius);
    }
    do {
        n = rng_int(r, 3, GA2D_MAX_POLYGON_VERTICES);
        for (i = 0; i < n; ++i) pts[i] = ga2d_vec_make((ga2d_real)rng_uniform(r, -1, 1), (ga2d_real)rng_uniform(r, -1, 1));
    } while (ga2d_polygon_hull(pts, n, &p) != GA2D_OK);
    return ga2d_make_proxy(p.vertices, p.count, radius);
}

/* A proxy's core points placed by x, in double. */
static int placed_points(const ga2d_shape_proxy *p, ga2d_transform x, dvec *out)
{
    int i;
    for (i = 0; i < p->count; ++i) {
        /* the transform in double: rounding it in ga2d_real would be the library's error, not the truth's */
        double c = (double)x.q.c, s = (double)x.q.s, px = (double)p->points[i].x, py = (double)p->points[i].y;
        out[i] = dv((double)x.p.x + c * px - s * py, (double)x.p.y + s * px + c * py);
    }
    return p->count;
}

/* Whether point q lies in the convex hull of pts (CCW; a point or a
   segment has no inside). */
static int inside_hull(const dvec *pts, int n, dvec q)
{
    int i;
    if (n < 3) return 0;
    for (i = 0; i < n; ++i)
        if (dcross(dsub(pts[(i + 1) % n], pts[i]), dsub(q, pts[i])) < 0) return 0;
    return 1;
}

/* Whether segments ab and cd cross (strictly). */
static int segments_cross(dvec a, dvec b, dvec c, dvec d)
{
    double o1 = dcross(dsub(b, a), dsub(c, a)), o2 = dcross(dsub(b, a), dsub(d, a));
    double o3 = dcross(dsub(d, c), dsub(a, c)), o4 = dcross(dsub(d, c), dsub(b, c));
    return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0));
}

/* The distance between two cores (point, segment or convex polygon): 0
   when they overlap, else the least point-to-edge distance either way. */
static double core_distance(const dvec *a, int na, const dvec *b, int nb)
{
    double best = 1e300;
    int i, j;
    if (inside_hull(a, na, b[0]) || inside_hull(b, nb, a[0])) return 0;
    for (i = 0; i < na; ++i)
        for (j = 0; j < nb; ++j) {
            dvec a1 = a[i], a2 = a[(i + 1) % na], b1 = b[j], b2 = b[(j + 1) % nb];
            double d;
            if (na > 1 && nb > 1 && segments_cross(a1, a2, b1, b2)) return 0;
            d = dlen(dsub(b1, closest_on_segment(a1, a2, b1)));
            if (d < best) best = d;
            d = dlen(dsub(a1, closest_on_segment(b1, b2, a1)));
            if (d < best) best = d;
        }
    return best;
}

static double brute_gap(const ga2d_shape_proxy *a, ga2d_transform xa, const ga2d_shape_proxy *b, ga2d_transform xb, dvec shift)
{
    dvec pa[GA2D_MAX_POLYGON_VERTICES], pb[GA2D_MAX_POLYGON_VERTICES];
    int na = placed_points(a, xa, pa), nb = placed_points(b, xb, pb), i;
    for (i = 0; i < nb; ++i) pb[i] = dadd(pb[i], shift);
    return core_distance(pa, na, pb, nb) - (double)a->radius - (double)b->radius;
}

static double proxy_size(const ga2d_shape_proxy *p, ga2d_transform x)
{
    double s = 0;
    int i;
    for (i = 0; i < p->count; ++i) {
        double d = dlen(dvg(ga2d_transform_apply(x, p->points[i])));
        if (d > s) s = d;
    }
    return s + (double)p->radius;
}

/* GJK against brute force on random pairs at random placements: the
   distance within rounding of the truth (the closest points are a few
   operations on coordinates of size S: TOL_K eps S), the witness points
   that far apart and on their surfaces' side, and a warm-started second
   call after a small move as exact, in fewer iterations. */
static void distance_against_brute_force(void)
{
    test_rng r = {2530};
    int i, overlaps = 0, apart = 0;
    long cold = 0, warm = 0;
    double worst = 0;
    for (i = 0; i < 3000; ++i) {
        ga2d_shape_proxy a = random_proxy(&r), b = random_proxy(&r);
        ga2d_transform xa = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&r, -3, 3), (ga2d_real)rng_uniform(&r, -3, 3)),
                                                ga2d_rotor_from_angle((ga2d_real)rng_uniform(&r, -3, 3)));
        ga2d_transform xb = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&r, -3, 3), (ga2d_real)rng_uniform(&r, -3, 3)),
                                                ga2d_rotor_from_angle((ga2d_real)rng_uniform(&r, -3, 3)));
        ga2d_simplex_cache cache;
        ga2d_distance_result d, d2;
        double truth = brute_gap(&a, xa, &b, xb, dv(0, 0)), S = proxy_size(&a, xa) + proxy_size(&b, xb), tol = TOL_K * REAL_EPS * S;
        memset(&cache, 0, sizeof cache);
        CHECK_RESULT(ga2d_shape_distance(&a, xa, &b, xb, &cache, &d), GA2D_OK);
        cold += d.iterations;
        if (truth <= 0) {
            ++overlaps;
            CHECK((double)d.distance <= tol);
        } else {
            ++apart;
            CHECK_NEAR(d.distance, truth, tol);
            if (fabs((double)d.distance - truth) / tol > worst) worst = fabs((double)d.distance - truth) / tol;
            if (truth > tol) {
                CHECK_NEAR(dlen(dsub(dvg(d.point_b), dvg(d.point_a))), d.distance, tol);
                CHECK_NEAR(dlen(dvg(d.normal)), 1, 4 * REAL_EPS);
                /* the normal runs from A's point to B's */
                CHECK(ddot(dvg(d.normal), dsub(dvg(d.point_b), dvg(d.point_a))) >= (double)d.distance - tol);
            }
        }
        /* warm: move B a little and ask again with the cache */
        xb.p = ga2d_vec_add(xb.p, ga2d_vec_make((ga2d_real)0.01, -(ga2d_real)0.01));
        truth = brute_gap(&a, xa, &b, xb, dv(0, 0));
        CHECK_RESULT(ga2d_shape_distance(&a, xa, &b, xb, &cache, &d2), GA2D_OK);
        warm += d2.iterations;
        if (truth > 0) CHECK_NEAR(d2.distance, truth, tol);
        else CHECK((double)d2.distance <= tol);
    }
    CHECK(overlaps > 300 && apart > 300);
    CHECK(warm < cold); /* the cache saves work */
    {
        ga2d_shape_proxy a = random_proxy(&r), bad = a;
        ga2d_distance_result d;
        ga2d_transform x = ga2d_transform_identity(), notunit = x;
        notunit.q.c = 2;
        bad.radius = -1;
        CHECK_RESULT(ga2d_shape_distance(&a, x, &bad, x, NULL, &d), GA2D_ERR_INVALID_ARGUMENT);
        bad = a;
        bad.count = 0;
        CHECK_RESULT(ga2d_shape_distance(&a, x, &bad, x, NULL, &d), GA2D_ERR_INVALID_ARGUMENT);
        bad = a;
        bad.points[0].x = (ga2d_real)NAN;
        CHECK_RESULT(ga2d_shape_distance(&a, x, &bad, x, NULL, &d), GA2D_ERR_NOT_FINITE);
        CHECK_RESULT(ga2d_shape_distance(&a, notunit, &a, x, NULL, &d), GA2D_ERR_INVALID_ARGUMENT);
        CHECK_RESULT(ga2d_shape_distance(&a, x, &a, x, NULL, NULL), GA2D_ERR_INVALID_ARGUMENT);
    }
    if (verbose())
        printf("queries: GJK on 3000 random pairs (%d overlapping, %d apart): worst distance error %.3g of %g eps S; "
               "iterations %.2f cold, %.2f warm on average\n",
               overlaps, apart, worst, TOL_K, (double)cold / 3000, (double)warm / 3000);
}

/* The gap along a linear sweep, shift(l) = l r, is convex in l (the
   distance from a moving point to a convex set), so the truth is found as
   for rays: the least gap by golden section, then the first root by
   bisection.  A cast hit must lie at or before the true touch, with its
   gap within the cast's tolerance (a quarter slop) plus rounding; a miss
   must never come within that of touching. */
static double sweep_gap(const ga2d_shape_proxy *a, ga2d_transform xa, const ga2d_shape_proxy *b, ga2d_transform xb, dvec r,
                        double l)
{
    return brute_gap(a, xa, b, xb, dscale(r, l));
}

static void shape_cast_against_brute_force(void)
{
    test_rng r = {2531};
    int i, hits = 0, misses = 0, at_start = 0, unsure = 0;
    double worst_gap = 0, slop = GA2D_LINEAR_SLOP, cast_tol = slop / 4;
    for (i = 0; i < 2000; ++i) {
        ga2d_shape_proxy a = random_proxy(&r), b = random_proxy(&r);
        ga2d_transform xa = ga2d_transform_make(ga2d_vec_make(0, 0), ga2d_rotor_from_angle((ga2d_real)rng_uniform(&r, -3, 3)));
        ga2d_transform xb = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&r, -6, 6), (ga2d_real)rng_uniform(&r, -6, 6)),
                                                ga2d_rotor_from_angle((ga2d_real)rng_uniform(&r, -3, 3)));
        ga2d_vec aim = ga2d_vec_make((ga2d_real)rng_uniform(&r, -1.5, 1.5), (ga2d_real)rng_uniform(&r, -1.5, 1.5));
        ga2d_vec tr = ga2d_vec_scale(ga2d_vec_sub(aim, xb.p), (ga2d_real)rng_uniform(&r, 0.5, 2));
        ga2d_ray_result c;
        double S = proxy_size(&a, xa) + proxy_size(&b, xb) + dlen(dvg(tr)), tol = TOL_K * REAL_EPS * S, lo = 0, hi = 1, least,
               lmin, g0;
        int k;
        CHECK_RESULT(ga2d_shape_cast(&a, xa, &b, xb, tr, &c), GA2D_OK);
        g0 = sweep_gap(&a, xa, &b, xb, dvg(tr), 0);
        if (g0 <= cast_tol + tol) {
            if (g0 < cast_tol - tol) {
                ++at_start;
                CHECK(c.hit && c.fraction == 0);
            } else {
                ++unsure;
            }
            continue;
        }
        {
            const double phi = 0.6180339887498949;
            double x1 = hi - phi, x2 = phi, f1 = sweep_gap(&a, xa, &b, xb, dvg(tr), x1), f2 = sweep_gap(&a, xa, &b, xb, dvg(tr), x2);
            for (k = 0; k < 120; ++k) {
                if (f1 < f2) {
                    hi = x2, x2 = x1, f2 = f1, x1 = hi - phi * (hi - lo), f1 = sweep_gap(&a, xa, &b, xb, dvg(tr), x1);
                } else {
                    lo = x1, x1 = x2, f1 = f2, x2 = lo + phi * (hi - lo), f2 = sweep_gap(&a, xa, &b, xb, dvg(tr), x2);
                }
            }
            lmin = (lo + hi) / 2;
            least = sweep_gap(&a, xa, &b, xb, dvg(tr), lmin);
            if (sweep_gap(&a, xa, &b, xb, dvg(tr), 1) < least) least = sweep_gap(&a, xa, &b, xb, dvg(tr), lmin = 1);
        }
        if (fabs(least - cast_tol) <= cast_tol + tol) {
            ++unsure; /* comes within the tolerance band of touching: either answer is right */
            continue;
        }
        if (least > 0) {
            ++misses;
            CHECK(!c.hit);
            continue;
        }
        ++hits;
        CHECK(c.hit);
        if (!c.hit) continue;
        {
            double gap = sweep_gap(&a, xa, &b, xb, dvg(tr), (double)c.fraction);
            /* at or before touching, within the tolerance of it */
            CHECK(gap >= -tol && gap <= cast_tol + tol);
            if (gap / cast_tol > worst_gap) worst_gap = gap / cast_tol;
            /* the point on A's surface, the normal out of A toward B */
            CHECK_NEAR(dlen(dvg(c.normal)), 1, 4 * REAL_EPS);
        }
    }
    CHECK(hits > 200 && misses > 100);
    if (verbose())
        printf("queries: shape casts, 2000 random sweeps: %d hits (gap at the hit at most %.3g of the quarter-slop "
               "tolerance), %d misses, %d touching at the start, %d too close to call\n",
               hits, worst_gap, misses, at_start, unsure);
}

/* Time of impact with turning: against a fine sweep (1000 steps of t,
   the brute gap at each), the first step within the target.  TOI's t is
   never after the true impact (conservative advancement never steps past
   one) and its gap is within the target's tolerance; SEPARATED only when
   no step comes within the target.  A sample grid misses a touch that
   lasts less than a step, so t_true is known to a step (0.001); the
   shapes here move at most ~10 m in t, 0.01 m a step. */
static void toi_against_sweep(void)
{
    test_rng r = {2532};
    int i, hits = 0, apart = 0, gave_up = 0, overlapped = 0;
    long iters = 0;
    double target = GA2D_LINEAR_SLOP, tol = GA2D_LINEAR_SLOP / 4;
    for (i = 0; i < 600; ++i) {
        ga2d_shape_proxy a = random_proxy(&r), b = random_proxy(&r);
        ga2d_sweep sa, sb;
        ga2d_toi_result out;
        double t_true = 2, least = 1e300;
        int k;
        memset(&sa, 0, sizeof sa);
        memset(&sb, 0, sizeof sb);
        sa.c1 = sa.c2 = ga2d_vec_make(0, 0);
        sa.a1 = (ga2d_real)rng_uniform(&r, -3, 3);
        sa.a2 = sa.a1 + (ga2d_real)rng_uniform(&r, -1, 1);
        sb.c1 = ga2d_vec_make((ga2d_real)rng_uniform(&r, -6, 6), (ga2d_real)rng_uniform(&r, -6, 6));
        sb.c2 = ga2d_vec_make((ga2d_real)rng_uniform(&r, -3, 3), (ga2d_real)rng_uniform(&r, -3, 3));
        sb.a1 = (ga2d_real)rng_uniform(&r, -3, 3);
        sb.a2 = sb.a1 + (ga2d_real)rng_uniform(&r, -3, 3);
        CHECK_RESULT(ga2d_time_of_impact(&a, &sa, &b, &sb, (ga2d_real)target, 1, &out), GA2D_OK);
        iters += out.iterations;
        for (k = 0; k <= 1000; ++k) {
            double t = k / 1000.0, g = brute_gap(&a, ga2d_sweep_transform(&sa, (ga2d_real)t), &b, ga2d_sweep_transform(&sb, (ga2d_real)t), dv(0, 0));
            if (g < least) least = g;
            if (g <= target && t_true > 1) t_true = t;
        }
        if (out.state == GA2D_TOI_OVERLAPPED) {
            ++overlapped;
            CHECK(brute_gap(&a, ga2d_sweep_transform(&sa, 0), &b, ga2d_sweep_transform(&sb, 0), dv(0, 0)) <= target + tol + 1e-4);
            continue;
        }
        if (out.state == GA2D_TOI_GAVE_UP) {
            ++gave_up;
            CHECK((double)out.t <= t_true + 1e-3); /* a safe time */
            continue;
        }
        if (out.state == GA2D_TOI_SEPARATED) {
            ++apart;
            /* no sample came within the target, bar rounding of the
               transforms (1e-4 m: float's eps times the 6 m reach, with margin) */
            CHECK(least > target - 1e-4);
            continue;
        }
        ++hits;
        {
            double g = brute_gap(&a, ga2d_sweep_transform(&sa, out.t), &b, ga2d_sweep_transform(&sb, out.t), dv(0, 0));
            CHECK((double)out.t <= t_true + 1e-3);
            CHECK(g >= target - 1e-4 && g <= target + tol + 1e-4);
        }
    }
    CHECK(hits > 100 && apart > 50);
    CHECK(gave_up <= 6); /* 1 %: conservative advancement stalls only on long grazing turns */
    if (verbose())
        printf("queries: time of impact, 600 random sweeps with turning: %d hits, %d apart, %d touching at the start, "
               "%d gave up; %.1f iterations on average\n",
               hits, apart, overlapped, gave_up, (double)iters / 600);
}

/* ----------------------------------------------------------- the world */
/* A world of WORLD_SHAPES random shapes: static segments, a chain and
   polygons; dynamic circles, capsules and polygons (a few with two
   shapes), some sensors, two filter categories; stepped so that some move
   and some rest. */
typedef struct qworld {
    ga2d_world *w;
    ga2d_shape_id shapes[WORLD_SHAPES + 64];
    ga2d_geometry geom[WORLD_SHAPES + 64]; /* in its body's frame */
    ga2d_filter filter[WORLD_SHAPES + 64];
    int sensor[WORLD_SHAPES + 64];
    int n;
} qworld;

static void add_shape(qworld *q, ga2d_body_id b, const ga2d_geometry *g, test_rng *r)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_shape_id id;
    sd.is_sensor = rng_int(r, 0, 19) == 0;
    sd.filter.category_bits = rng_int(r, 0, 1) ? 1u : 2u;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE: id = ga2d_shape_create_circle(q->w, b, &sd, &g->as.circle); break;
    case GA2D_SHAPE_CAPSULE: id = ga2d_shape_create_capsule(q->w, b, &sd, &g->as.capsule); break;
    case GA2D_SHAPE_POLYGON: id = ga2d_shape_create_polygon(q->w, b, &sd, &g->as.polygon); break;
    default: id = ga2d_shape_create_segment(q->w, b, &sd, &g->as.segment); break;
    }
    CHECK(!ga2d_shape_id_is_null(id));
    q->shapes[q->n] = id;
    q->geom[q->n] = *g;
    q->filter[q->n] = sd.filter;
    q->sensor[q->n] = sd.is_sensor;
    ++q->n;
}

static void build_world(qworld *q)
{
    test_rng r = {2525};
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id ground;
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_vec pts[32];
    ga2d_shape_id segs[32];
    int i, k;
    memset(q, 0, sizeof *q);
    q->w = ga2d_world_create(&wd);
    ground = ga2d_body_create(q->w, &bd);
    /* a chain along the bottom: its segments join the list */
    for (i = 0; i < 32; ++i) pts[i] = ga2d_vec_make((ga2d_real)(-80 + 5 * i), (ga2d_real)(-40 + 3 * sin(i)));
    cd.points = pts;
    cd.count = 32;
    {
        ga2d_chain_id ch = ga2d_chain_create(q->w, ground, &cd);
        int ns = ga2d_chain_get_segments(q->w, ch, segs, 32);
        CHECK(ns == 31);
        for (i = 0; i < ns; ++i) {
            ga2d_geometry g = ga2d_shape_geometry(q->w, segs[i]);
            q->shapes[q->n] = segs[i];
            q->geom[q->n] = g;
            q->filter[q->n] = ga2d_shape_filter(q->w, segs[i]);
            q->sensor[q->n] = 0;
            ++q->n;
        }
    }
    while (q->n < WORLD_SHAPES) {
        ga2d_body_id b;
        ga2d_geometry g;
        int is_static = rng_int(&r, 0, 3) == 0, type;
        bd = ga2d_default_body_def();
        bd.type = is_static ? GA2D_BODY_STATIC : GA2D_BODY_DYNAMIC;
        bd.position = ga2d_vec_make((ga2d_real)rng_uniform(&r, -70, 70), (ga2d_real)rng_uniform(&r, -35, 60));
        bd.rotor = ga2d_rotor_from_angle((ga2d_real)rng_uniform(&r, -3, 3));
        b = ga2d_body_create(q->w, &bd);
        for (k = 0; k < (rng_int(&r, 0, 4) == 0 ? 2 : 1); ++k) {
            type = is_static ? (rng_int(&r, 0, 1) ? GA2D_SHAPE_SEGMENT : GA2D_SHAPE_POLYGON) : rng_int(&r, 0, 2);
            random_geometry(&r, type, &g);
            add_shape(q, b, &g, &r);
        }
    }
    for (i = 0; i < 60; ++i) CHECK_RESULT(ga2d_world_step(q->w, (ga2d_real)1.0 / 60), GA2D_OK);
}

typedef struct found { int n; ga2d_shape_id ids[WORLD_SHAPES + 64]; ga2d_real fraction[WORLD_SHAPES + 64]; } found;
static int collect(ga2d_shape_id s, void *ctx)
{
    found *f = (found *)ctx;
    f->ids[f->n++] = s;
    return 1;
}
static ga2d_real collect_ray(ga2d_shape_id s, ga2d_vec p, ga2d_vec n, ga2d_real fraction, void *ctx)
{
    found *f = (found *)ctx;
    (void)p;
    (void)n;
    f->fraction[f->n] = fraction;
    f->ids[f->n++] = s;
    return 1;
}
static int index_of(const found *f, ga2d_shape_id s)
{
    int i;
    for (i = 0; i < f->n; ++i)
        if (ga2d_shape_id_equal(f->ids[i], s)) return i;
    return -1;
}

/* The shape's own box, from its geometry and its body's transform. */
static ga2d_aabb tight_box(const qworld *q, int i)
{
    ga2d_transform x = ga2d_body_transform(q->w, ga2d_shape_body(q->w, q->shapes[i]));
    const ga2d_geometry *g = &q->geom[i];
    ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
    ga2d_real rad = 0;
    ga2d_aabb b;
    int n = 0, k;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE: pts[n++] = g->as.circle.center; rad = g->as.circle.radius; break;
    case GA2D_SHAPE_CAPSULE: pts[n++] = g->as.capsule.center1; pts[n++] = g->as.capsule.center2; rad = g->as.capsule.radius; break;
    case GA2D_SHAPE_POLYGON:
        for (k = 0; k < g->as.polygon.count; ++k) pts[n++] = g->as.polygon.vertices[k];
        rad = g->as.polygon.radius;
        break;
    case GA2D_SHAPE_SEGMENT: pts[n++] = g->as.segment.point1; pts[n++] = g->as.segment.point2; break;
    default: pts[n++] = g->as.chain_segment.segment.point1; pts[n++] = g->as.chain_segment.segment.point2; break;
    }
    b.lower = b.upper = ga2d_transform_apply(x, pts[0]);
    for (k = 1; k < n; ++k) {
        ga2d_vec p = ga2d_transform_apply(x, pts[k]);
        if (p.x < b.lower.x) b.lower.x = p.x;
        if (p.y < b.lower.y) b.lower.y = p.y;
        if (p.x > b.upper.x) b.upper.x = p.x;
        if (p.y > b.upper.y) b.upper.y = p.y;
    }
    b.lower.x -= rad, b.lower.y -= rad, b.upper.x += rad, b.upper.y += rad;
    return b;
}

/* Every query against an O(n) scan of every shape: the same set (each
   shape once), a closest hit that is the scan's least fraction, and
   counters that count exactly the shapes whose fat boxes the query's box
   meets.  Boxes and points within the bound of a boundary may go either
   way and are not counted. */
static void world_queries_match_a_scan(void)
{
    static qworld q;
    static found f;
    test_rng r = {2599};
    int t, i, aabb_total = 0, point_total = 0, ray_total = 0, shape_total = 0, cast_total = 0, unsure = 0;
    long tested = 0;
    ga2d_filter all = ga2d_default_filter(), only2 = ga2d_default_filter();
    only2.mask_bits = 2u;
    build_world(&q);
    for (t = 0; t < WORLD_QUERIES; ++t) {
        ga2d_filter filter = t % 3 == 2 ? only2 : all;
        ga2d_vec c = ga2d_vec_make((ga2d_real)rng_uniform(&r, -80, 80), (ga2d_real)rng_uniform(&r, -45, 60));
        ga2d_aabb box;
        ga2d_vec d = ga2d_vec_make((ga2d_real)rng_uniform(&r, -60, 60), (ga2d_real)rng_uniform(&r, -60, 60));
        ga2d_ray_result closest;
        double tol = TOL_K * REAL_EPS * 200; /* S: coordinates within 100 m, rays within 100 m */
        int expect_fat;
        box.lower = c;
        box.upper = ga2d_vec_make(c.x + (ga2d_real)rng_uniform(&r, 0, 15), c.y + (ga2d_real)rng_uniform(&r, 0, 15));
        /* AABB */
        f.n = 0;
        CHECK_RESULT(ga2d_world_overlap_aabb(q.w, box, filter, collect, &f), GA2D_OK);
        expect_fat = 0;
        for (i = 0; i < q.n; ++i) {
            ga2d_aabb tb = tight_box(&q, i);
            int seen = !q.sensor[i] && ga2d_should_collide(filter, q.filter[i]), in = index_of(&f, q.shapes[i]) >= 0;
            if (seen && ga2d_aabb_overlaps(ga2d_shape_fat_aabb(q.w, q.shapes[i]), box)) ++expect_fat;
            if (!seen) {
                CHECK(!in);
                continue;
            }
            if (fabs((double)tb.lower.x - (double)box.upper.x) <= tol || fabs((double)tb.upper.x - (double)box.lower.x) <= tol ||
                fabs((double)tb.lower.y - (double)box.upper.y) <= tol || fabs((double)tb.upper.y - (double)box.lower.y) <= tol) {
                ++unsure;
                continue;
            }
            CHECK(in == ga2d_aabb_overlaps(tb, box));
            aabb_total += in;
        }
        CHECK(ga2d_world_get_counters(q.w).query_shapes == expect_fat);
        tested += ga2d_world_get_counters(q.w).query_shapes;
        /* point */
        f.n = 0;
        CHECK_RESULT(ga2d_world_overlap_point(q.w, c, filter, collect, &f), GA2D_OK);
        for (i = 0; i < q.n; ++i) {
            ga2d_transform x = ga2d_body_transform(q.w, ga2d_shape_body(q.w, q.shapes[i]));
            int seen = !q.sensor[i] && ga2d_should_collide(filter, q.filter[i]), in = index_of(&f, q.shapes[i]) >= 0;
            double s;
            if (!seen || q.geom[i].type == GA2D_SHAPE_SEGMENT || q.geom[i].type == GA2D_SHAPE_CHAIN_SEGMENT) {
                CHECK(!in);
                continue;
            }
            s = sdf(&q.geom[i], dvg(ga2d_transform_apply_inv(x, c)), NULL, NULL, tol);
            if (fabs(s) <= tol) {
                ++unsure;
                continue;
            }
            CHECK(in == (s < 0));
            point_total += in;
        }
        /* rays: every hit, and the closest */
        f.n = 0;
        CHECK_RESULT(ga2d_world_cast_ray(q.w, c, d, filter, collect_ray, &f), GA2D_OK);
        closest = ga2d_world_cast_ray_closest(q.w, c, d, filter);
        {
            double least = 2;
            for (i = 0; i < q.n; ++i) {
                ga2d_ray_result one;
                int seen = !q.sensor[i] && ga2d_should_collide(filter, q.filter[i]), k = index_of(&f, q.shapes[i]);
                CHECK_RESULT(ga2d_ray_cast_shape(&q.geom[i], ga2d_body_transform(q.w, ga2d_shape_body(q.w, q.shapes[i])), c, d, &one),
                             GA2D_OK);
                if (!seen) {
                    CHECK(k < 0);
                    continue;
                }
                CHECK((k >= 0) == one.hit);
                if (k >= 0 && one.hit) {
                    CHECK(f.fraction[k] == one.fraction); /* the same cast, the same bits */
                    ++ray_total;
                }
                if (one.hit && (double)one.fraction < least) least = (double)one.fraction;
            }
            CHECK(closest.hit == (least <= 1));
            if (closest.hit) {
                CHECK((double)closest.fraction == least);
                CHECK(ga2d_body_id_equal(closest.body, ga2d_shape_body(q.w, closest.shape)));
            }
        }
    }
    /* shapes: a random proxy placed at random, its overlaps and its sweep */
    for (t = 0; t < WORLD_QUERIES; ++t) {
        ga2d_filter filter = t % 3 == 2 ? only2 : all;
        ga2d_shape_proxy p = random_proxy(&r);
        ga2d_transform x = ga2d_transform_make(ga2d_vec_make((ga2d_real)rng_uniform(&r, -80, 80), (ga2d_real)rng_uniform(&r, -45, 60)),
                                               ga2d_rotor_from_angle((ga2d_real)rng_uniform(&r, -3, 3)));
        ga2d_vec d = ga2d_vec_make((ga2d_real)rng_uniform(&r, -30, 30), (ga2d_real)rng_uniform(&r, -30, 30));
        double tol = TOL_K * REAL_EPS * 200;
        f.n = 0;
        CHECK_RESULT(ga2d_world_overlap_shape(q.w, &p, x, filter, collect, &f), GA2D_OK);
        for (i = 0; i < q.n; ++i) {
            ga2d_shape_proxy sp = ga2d_shape_proxy_of(&q.geom[i]);
            ga2d_transform xs = ga2d_body_transform(q.w, ga2d_shape_body(q.w, q.shapes[i]));
            int seen = !q.sensor[i] && ga2d_should_collide(filter, q.filter[i]), in = index_of(&f, q.shapes[i]) >= 0;
            double g;
            if (!seen) {
                CHECK(!in);
                continue;
            }
            g = brute_gap(&sp, xs, &p, x, dv(0, 0));
            if (fabs(g) <= tol) {
                ++unsure;
                continue;
            }
            CHECK(in == (g < 0));
            shape_total += in;
        }
        f.n = 0;
        CHECK_RESULT(ga2d_world_cast_shape(q.w, &p, x, d, filter, collect_ray, &f), GA2D_OK);
        for (i = 0; i < q.n; ++i) {
            ga2d_shape_proxy sp = ga2d_shape_proxy_of(&q.geom[i]);
            ga2d_ray_result one;
            int seen = !q.sensor[i] && ga2d_should_collide(filter, q.filter[i]), k = index_of(&f, q.shapes[i]);
            CHECK_RESULT(ga2d_shape_cast(&sp, ga2d_body_transform(q.w, ga2d_shape_body(q.w, q.shapes[i])), &p, x, d, &one), GA2D_OK);
            if (!seen) {
                CHECK(k < 0);
                continue;
            }
            CHECK((k >= 0) == one.hit);
            if (k >= 0 && one.hit) {
                CHECK(f.fraction[k] == one.fraction);
                ++cast_total;
            }
        }
    }
    CHECK(aabb_total > 100 && point_total > 20 && ray_total > 100 && shape_total > 20 && cast_total > 50); /* the queries found things */
    if (verbose())
        printf("queries: %d random queries of each kind over %d shapes: %d box, %d point, %d ray, %d shape and %d shape-cast "
               "finds agree with the scan, %d too close to call; a box query tested %.1f shapes on average (of %d)\n",
               WORLD_QUERIES, q.n, aabb_total, point_total, ray_total, shape_total, cast_total, unsure,
               (double)tested / WORLD_QUERIES, q.n);
    ga2d_world_destroy(q.w);
}

/* The clip protocol: -1 ignores (the ray goes on), 0 stops at once, a
   fraction clips, and clipping at each hit ends at the closest. */
typedef struct clip_ctx { int mode, calls; ga2d_real last; } clip_ctx;
static ga2d_real clip_fn(ga2d_shape_id s, ga2d_vec p, ga2d_vec n, ga2d_real fraction, void *ctx)
{
    clip_ctx *c = (clip_ctx *)ctx;
    (void)s;
    (void)p;
    (void)n;
    ++c->calls;
    c->last = fraction;
    return c->mode == 0 ? 0 : c->mode < 0 ? -1 : fraction;
}

static void ray_clip_protocol(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_filter all = ga2d_default_filter();
    clip_ctx c;
    int i;
    ga2d_ray_result closest;
    /* ten static boxes in a row along x, at 2, 4, ... 20, created in a shuffled order */
    static const int order[10] = {7, 2, 9, 0, 5, 3, 8, 1, 6, 4};
    for (i = 0; i < 10; ++i) {
        bd.position = ga2d_vec_make((ga2d_real)(2 + 2 * order[i]), 0);
        bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        ga2d_body_create(w, &bd);
    }
    closest = ga2d_world_cast_ray_closest(w, ga2d_vec_make(0, 0), ga2d_vec_make(25, 0), all);
    CHECK(closest.hit && closest.fraction == (ga2d_real)1.5 / 25 && closest.point.x == (ga2d_real)1.5);
    memset(&c, 0, sizeof c);
    c.mode = 1;
    CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_make(0, 0), ga2d_vec_make(25, 0), all, clip_fn, &c), GA2D_OK);
    CHECK(c.calls >= 1 && c.calls <= 10 && c.last == closest.fraction);
    memset(&c, 0, sizeof c);
    c.mode = -1;
    CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_make(0, 0), ga2d_vec_make(25, 0), all, clip_fn, &c), GA2D_OK);
    CHECK(c.calls == 10);
    memset(&c, 0, sizeof c);
    c.mode = 0;
    CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_make(0, 0), ga2d_vec_make(25, 0), all, clip_fn, &c), GA2D_OK);
    CHECK(c.calls == 1);
    /* a ray clipped short of everything is not called back */
    closest = ga2d_world_cast_ray_closest(w, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), all);
    CHECK(!closest.hit && ga2d_shape_id_is_null(closest.shape));
    ga2d_world_destroy(w);
}

/* Refusals: bad input, and a world that is stepping or already in a
   query; a query's callback may read the world but not change it. */
typedef struct lock_ctx { ga2d_world *w; ga2d_body_id b; ga2d_result destroy, nested, step; int calls; } lock_ctx;
static int lock_overlap(ga2d_shape_id s, void *ctx)
{
    lock_ctx *c = (lock_ctx *)ctx;
    ga2d_ray_result out;
    (void)s;
    ++c->calls;
    c->destroy = ga2d_body_destroy(c->w, c->b);
    c->nested = ga2d_world_cast_ray_closest_checked(c->w, ga2d_vec_make(0, 5), ga2d_vec_make(0, -10), ga2d_default_filter(), &out);
    c->step = ga2d_world_step(c->w, (ga2d_real)1.0 / 60);
    return 1;
}
static void lock_force(ga2d_world *w, void *ctx)
{
    lock_ctx *c = (lock_ctx *)ctx;
    ga2d_ray_result out;
    ++c->calls;
    c->nested = ga2d_world_cast_ray_closest_checked(w, ga2d_vec_make(0, 5), ga2d_vec_make(0, -10), ga2d_default_filter(), &out);
    c->destroy = ga2d_world_overlap_point(w, ga2d_vec_make(0, 0), ga2d_default_filter(), lock_overlap, ctx);
}

static void query_refusals(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_filter all = ga2d_default_filter();
    ga2d_ray_result out;
    ga2d_aabb box;
    lock_ctx c;
    size_t n0, n1;
    unsigned char *before, *after;
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    memset(&c, 0, sizeof c);
    c.w = w;
    c.b = ga2d_body_create(w, &bd);
    CHECK_RESULT(ga2d_world_cast_ray(NULL, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), all, clip_fn, &c), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), all, NULL, &c), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_make(0, 0), ga2d_vec_make(0, 0), all, clip_fn, &c), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_make((ga2d_real)NAN, 0), ga2d_vec_make(1, 0), all, clip_fn, &c), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_make(0, 0), ga2d_vec_make((ga2d_real)INFINITY, 0), all, clip_fn, &c),
                 GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_world_cast_ray_closest_checked(w, ga2d_vec_make(0, 0), ga2d_vec_make(1, 0), all, NULL),
                 GA2D_ERR_INVALID_ARGUMENT);
    CHECK(!ga2d_world_cast_ray_closest(w, ga2d_vec_make(0, 0), ga2d_vec_make(0, 0), all).hit);
    box.lower = ga2d_vec_make(1, 1);
    box.upper = ga2d_vec_make(0, 2); /* lower above upper */
    CHECK_RESULT(ga2d_world_overlap_aabb(w, box, all, lock_overlap, &c), GA2D_ERR_INVALID_ARGUMENT);
    box.upper.x = (ga2d_real)NAN;
    CHECK_RESULT(ga2d_world_overlap_aabb(w, box, all, lock_overlap, &c), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_world_overlap_point(w, ga2d_vec_make(0, 0), all, NULL, &c), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_overlap_point(w, ga2d_vec_make(0, (ga2d_real)INFINITY), all, lock_overlap, &c), GA2D_ERR_NOT_FINITE);
    CHECK(c.calls == 0);
    /* from a query's callback: nothing changes, nothing nests, no step */
    n0 = ga2d_world_snapshot_size(w);
    before = (unsigned char *)malloc(n0);
    CHECK_RESULT(ga2d_world_snapshot_save(w, before, n0), GA2D_OK);
    CHECK_RESULT(ga2d_world_overlap_point(w, ga2d_vec_make(0, 0), all, lock_overlap, &c), GA2D_OK);
    CHECK(c.calls == 1);
    CHECK_RESULT(c.destroy, GA2D_ERR_LOCKED);
    CHECK_RESULT(c.nested, GA2D_ERR_LOCKED);
    CHECK_RESULT(c.step, GA2D_ERR_LOCKED);
    CHECK(ga2d_body_is_valid(w, c.b));
    n1 = ga2d_world_snapshot_size(w);
    CHECK(n1 == n0);
    after = (unsigned char *)malloc(n1);
    CHECK_RESULT(ga2d_world_snapshot_save(w, after, n1), GA2D_OK);
    CHECK(memcmp(before, after, n0) == 0);
    /* from the force callback, inside a step */
    memset(&c, 0, sizeof c);
    c.w = w;
    c.b = ga2d_body_id_null();
    CHECK_RESULT(ga2d_world_set_force_callback(w, lock_force, &c), GA2D_OK);
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1.0 / 60), GA2D_OK);
    CHECK(c.calls >= 1);
    CHECK_RESULT(c.nested, GA2D_ERR_LOCKED);
    CHECK_RESULT(c.destroy, GA2D_ERR_LOCKED);
    /* after all that, queries work again */
    CHECK_RESULT(ga2d_world_set_force_callback(w, NULL, NULL), GA2D_OK);
    CHECK_RESULT(ga2d_world_cast_ray_closest_checked(w, ga2d_vec_make(0, 5), ga2d_vec_make(0, -10), all, &out), GA2D_OK);
    CHECK(out.hit);
    free(before);
    free(after);
    ga2d_world_destroy(w);
}

/* The body listing: live bodies in index order, however made and
   destroyed; the count whatever the capacity. */
static void list_bodies(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id made[12], got[12];
    int i, n;
    CHECK(ga2d_world_body_count(w) == 0 && ga2d_world_get_bodies(w, got, 12) == 0);
    for (i = 0; i < 12; ++i) made[i] = ga2d_body_create(w, &bd);
    CHECK_RESULT(ga2d_body_destroy(w, made[3]), GA2D_OK);
    CHECK_RESULT(ga2d_body_destroy(w, made[7]), GA2D_OK);
    CHECK_RESULT(ga2d_body_destroy(w, made[11]), GA2D_OK);
    CHECK(ga2d_world_body_count(w) == 9);
    CHECK(ga2d_world_get_bodies(w, NULL, 0) == 9);
    n = ga2d_world_get_bodies(w, got, 4);
    CHECK(n == 9);
    CHECK(ga2d_body_id_equal(got[0], made[0]) && ga2d_body_id_equal(got[3], made[4]));
    n = ga2d_world_get_bodies(w, got, 12);
    for (i = 0; i < n; ++i) CHECK(ga2d_body_is_valid(w, got[i]));
    for (i = 1; i < n; ++i) CHECK(got[i].index1 > got[i - 1].index1);
    made[3] = ga2d_body_create(w, &bd); /* takes a freed slot */
    CHECK(ga2d_world_get_bodies(w, got, 12) == 10);
    CHECK(ga2d_world_get_bodies(NULL, got, 12) == 0 && ga2d_world_body_count(NULL) == 0);
    ga2d_world_destroy(w);
}


/* Answers stay finite at the extremes (the fuzz harnesses' findings, kept
   in tests/fuzz/regress/shapes/): every comparison a ray or a shape cast
   makes lets a NaN by, so numbers that overflow the real range must not
   come out as a hit; and GJK's weights inside a triangle must not be
   0 / 0 when the triangle is tiny.  In double the same inputs do not
   overflow and the checks hold as well. */
static int ext_finite_vec(ga2d_vec v) { return (double)v.x - (double)v.x == 0 && (double)v.y - (double)v.y == 0; }

static void answers_finite_at_extremes(void)
{
    {
        /* a segment reaching -1e30, placed at 1e12: (a - p) ^ e overflows
           in float, and t = NaN passed "t < 0 || t > best" */
        ga2d_geometry g;
        ga2d_transform x;
        ga2d_ray_result r;
        memset(&g, 0, sizeof g);
        g.type = GA2D_SHAPE_SEGMENT;
        g.as.segment.point1 = ga2d_vec_make((ga2d_real)-6.125, (ga2d_real)-7.88232422);
        g.as.segment.point2 = ga2d_vec_make((ga2d_real)-1e30, (ga2d_real)-1e30);
        x.p = ga2d_vec_make((ga2d_real)1e12, (ga2d_real)1e12);
        x.q.c = (ga2d_real)0.999673843;
        x.q.s = (ga2d_real)-0.0245406143;
        CHECK(ga2d_ray_cast_shape(&g, x, ga2d_vec_make(0, (ga2d_real)0.0625),
                                  ga2d_vec_make((ga2d_real)-10.5, (ga2d_real)ldexp(1.0, -129)), &r) == GA2D_OK);
        CHECK(!r.hit || (r.fraction >= 0 && r.fraction <= 1 && ext_finite_vec(r.point) && ext_finite_vec(r.normal)));
    }
    {
        /* a 1e-10 m pentagon around a point: each d123 = n * (w ^ w) is
           about 1e-40 and underflowed to 0 in float */
        ga2d_vec a[5], b0 = ga2d_vec_make(0, 0);
        ga2d_shape_proxy pa, pb;
        ga2d_distance_result d;
        ga2d_simplex_cache cache;
        ga2d_transform x = ga2d_transform_make(ga2d_vec_make(1000, 1000), ga2d_rotor_identity());
        a[0] = ga2d_vec_make((ga2d_real)-ldexp(1.0, -39), 0);
        a[1] = ga2d_vec_make((ga2d_real)6.912159733474255e-11, (ga2d_real)-1.5279510989785194e-10);
        a[2] = ga2d_vec_make((ga2d_real)2.2737367544323206e-10, (ga2d_real)-1.1823431123048067e-10);
        a[3] = ga2d_vec_make((ga2d_real)1.1641532182693481e-10, (ga2d_real)4.001776687800884e-11);
        a[4] = ga2d_vec_make(0, (ga2d_real)1.1459633242338896e-10);
        pa = ga2d_make_proxy(a, 5, 0);
        pb = ga2d_make_proxy(&b0, 1, 0);
        memset(&cache, 0, sizeof cache);
        CHECK(ga2d_shape_distance(&pa, x, &pb, x, &cache, &d) == GA2D_OK);
        CHECK(d.distance == 0 && ext_finite_vec(d.point_a) && ext_finite_vec(d.point_b));
        /* the middle of the closest points: within the pentagon's size of B's point */
        CHECK(fabs((double)d.point_a.x - 1000) < 1e-3 && fabs((double)d.point_a.y - 1000) < 1e-3);
        CHECK(ga2d_shape_distance(&pa, ga2d_transform_identity(), &pb, ga2d_transform_identity(), NULL, &d) == GA2D_OK);
        CHECK(ext_finite_vec(d.point_a) && fabs((double)d.point_a.x) < 1e-9 && fabs((double)d.point_a.y) < 1e-9);
    }
    {
        /* a circle at -FLT_MAX swept by (-FLT_MAX, -FLT_MAX): gap / closing
           is inf / inf, and lambda = NaN passed "lambda > 1" */
        ga2d_vec a[3], c = ga2d_vec_make(-5, (ga2d_real)-FLT_MAX);
        ga2d_shape_proxy pa, pb;
        ga2d_transform xa, xb;
        ga2d_ray_result r;
        a[0] = ga2d_vec_make((ga2d_real)-0.03125, (ga2d_real)-1.78125);
        a[1] = a[2] = ga2d_vec_make((ga2d_real)2.46875, (ga2d_real)1.1875);
        pa = ga2d_make_proxy(a, 3, 0);
        pb = ga2d_make_proxy(&c, 1, (ga2d_real)0.3046875);
        xa.p = ga2d_vec_make((ga2d_real)-100000.0, (ga2d_real)-100001.53125);
        xa.q.c = (ga2d_real)-0.6116048097610474;
        xa.q.s = (ga2d_real)0.791163444519043;
        xb.p = ga2d_vec_make((ga2d_real)-99990.25, (ga2d_real)-100003.84375);
        xb.q.c = (ga2d_real)-0.9924795627593994;
        xb.q.s = (ga2d_real)-0.12241063266992569;
        CHECK(ga2d_shape_cast(&pa, xa, &pb, xb, ga2d_vec_make((ga2d_real)-FLT_MAX, (ga2d_real)-FLT_MAX), &r) == GA2D_OK);
        CHECK(!r.hit || (r.fraction >= 0 && r.fraction <= 1));
    }
}

/* The world's shape queries take a proxy and placement within the bounds
   a shape and a body keep (GA2D_MAX_COORDINATE, M): past them each is
   refused with TOO_LARGE and no callback, at them the answers are finite.
   The fuzz finding: a proxy point at -3.2e163 (double) squared to inf
   inside GJK, and a cast passed its callback a NaN point. */
typedef struct bound_ctx { int calls, finite; } bound_ctx;
static ga2d_real bound_cast(ga2d_shape_id s, ga2d_vec p, ga2d_vec n, ga2d_real fraction, void *ctx)
{
    bound_ctx *c = (bound_ctx *)ctx;
    double l2 = (double)n.x * (double)n.x + (double)n.y * (double)n.y;
    (void)s;
    ++c->calls;
    /* a unit normal, rounded: 16 eps (0 only for a hit at 0 in overlap) */
    c->finite += ext_finite_vec(p) && fraction >= 0 && fraction <= 1 && (fabs(l2 - 1) <= 16 * REAL_EPS || l2 == 0);
    return 1;
}
static int bound_overlap(ga2d_shape_id s, void *ctx)
{
    (void)s;
    ++((bound_ctx *)ctx)->calls;
    return 1;
}

static void shape_queries_bounded(void)
{
    const ga2d_real M = (ga2d_real)GA2D_MAX_COORDINATE;
    /* squares past the real range: 1e163 in double, 1e30 in float */
    const ga2d_real huge = sizeof(ga2d_real) == sizeof(double) ? (ga2d_real)1e163 : (ga2d_real)1e30;
    const ga2d_real beyond[2] = {2 * M, huge};
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_filter all = ga2d_default_filter();
    ga2d_transform x = ga2d_transform_identity();
    ga2d_vec down = ga2d_vec_make(0, -5), pts[2];
    ga2d_shape_proxy p;
    bound_ctx c;
    int i, k;
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    ga2d_body_create(w, &bd);
    /* a segment from -M to M, 2 m above the box: at the bound, each query answers */
    pts[0] = ga2d_vec_make(-M, 2);
    pts[1] = ga2d_vec_make(M, 2);
    p = ga2d_make_proxy(pts, 2, (ga2d_real)0.25);
    memset(&c, 0, sizeof c);
    CHECK_RESULT(ga2d_world_cast_shape(w, &p, x, down, all, bound_cast, &c), GA2D_OK);
    CHECK(c.calls == 1 && c.finite == 1);
    memset(&c, 0, sizeof c);
    x.p = ga2d_vec_make(0, -2); /* down onto the box */
    CHECK_RESULT(ga2d_world_overlap_shape(w, &p, x, all, bound_overlap, &c), GA2D_OK);
    CHECK(c.calls == 1);
    /* past it: each of a point, the radius, the position and a cast's end */
    for (k = 0; k < 2; ++k)
        for (i = 0; i < 4; ++i) {
            ga2d_shape_proxy q = p;
            ga2d_transform y = ga2d_transform_identity();
            ga2d_vec t = down;
            if (i == 0) q.points[1].x = beyond[k];
            if (i == 1) q.radius = beyond[k];
            if (i == 2) y.p.y = -beyond[k];
            if (i == 3) t.y = -beyond[k];
            memset(&c, 0, sizeof c);
            CHECK_RESULT(ga2d_world_cast_shape(w, &q, y, t, all, bound_cast, &c), GA2D_ERR_TOO_LARGE);
            if (i < 3) CHECK_RESULT(ga2d_world_overlap_shape(w, &q, y, all, bound_overlap, &c), GA2D_ERR_TOO_LARGE);
            CHECK(c.calls == 0);
        }
    ga2d_world_destroy(w);
}

/* Bodies the step carries far from where their start velocity reaches
   (the step fits the broadphase boxes to that reach at its start): rigid
   distance joints pulling boxes, capsules and circles 2 to 14 m to their
   1 m length in one step, in 12 directions; a force field kicking bodies
   at rest to 60 m/s within the step; a revolute motor of huge torque
   spinning a 6 m bar up from rest.  After every step each shape lies
   inside its tree box (ga2d_shape_fat_aabb: the same box function at the
   same pose, so exactly), and the world's queries find it: a ray down
   through its centre hits it, with the fraction the shape's own cast
   gives (the same arithmetic), and a point overlap at its centre lists
   it.  Sleep off, gravity 0: nothing else moves them. */
typedef struct carried_scene { ga2d_body_id kicked[6]; } carried_scene;

static void kick_field(ga2d_world *w, void *ctx)
{
    carried_scene *cs = (carried_scene *)ctx;
    int i;
    for (i = 0; i < 6; ++i) {
        /* 60 m/s more in each step of 1/60 s (F = m dv / dt) up to 150
           m/s, outward from the ring they start on */
        ga2d_real m = ga2d_body_mass_data(w, cs->kicked[i]).mass, f = m * 60 * 60;
        ga2d_vec dir = ga2d_vec_make((ga2d_real)cos(i * 1.0471975511965976), (ga2d_real)sin(i * 1.0471975511965976));
        if ((double)ga2d_vec_length(ga2d_body_velocity(w, cs->kicked[i])) > 150) continue;
        ga2d_body_apply_force(w, cs->kicked[i], ga2d_vec_scale(dir, f), ga2d_body_center(w, cs->kicked[i]));
    }
}

typedef struct found_ctx { ga2d_shape_id want; int found; ga2d_real fraction; } found_ctx;

static int found_shape(ga2d_shape_id shape, void *ctx)
{
    found_ctx *f = (found_ctx *)ctx;
    if (ga2d_shape_id_equal(shape, f->want)) f->found = 1;
    return 1;
}

static ga2d_real found_on_ray(ga2d_shape_id shape, ga2d_vec point, ga2d_vec normal, ga2d_real fraction, void *ctx)
{
    found_ctx *f = (found_ctx *)ctx;
    (void)point;
    (void)normal;
    if (ga2d_shape_id_equal(shape, f->want)) {
        f->found = 1;
        f->fraction = fraction;
    }
    return 1; /* every hit */
}

static void carried_bodies_found(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_world *w;
    ga2d_body_id anchor, hub, bar, all[64];
    carried_scene cs;
    int i, k, n = 0, step, outside = 0, missed = 0;
    wd.gravity = ga2d_vec_make(0, 0);
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    anchor = ga2d_body_create(w, &bd); /* static, shapeless */
    bd.type = GA2D_BODY_DYNAMIC;
    for (k = 0; k < 12; ++k) {
        ga2d_distance_joint_def jd = ga2d_default_distance_joint_def();
        double a = k * 0.5235987755982988, r = 2 + k;
        ga2d_body_def d = bd;
        d.position = ga2d_vec_make((ga2d_real)(r * cos(a) + 100), (ga2d_real)(r * sin(a)));
        d.polygon = ga2d_polygon_box((ga2d_real)0.25, (ga2d_real)0.25);
        all[n] = ga2d_body_create(w, &d);
        if (k % 3 != 0) { /* a circle or a capsule in place of the box */
            ga2d_circle disc;
            ga2d_capsule cap;
            ga2d_shape_id old;
            ga2d_shape_def sd = ga2d_default_shape_def();
            CHECK(ga2d_body_get_shapes(w, all[n], &old, 1) == 1);
            disc.center = ga2d_vec_make(0, 0);
            disc.radius = (ga2d_real)0.3;
            cap.center1 = ga2d_vec_make((ga2d_real)-0.3, 0);
            cap.center2 = ga2d_vec_make((ga2d_real)0.3, 0);
            cap.radius = (ga2d_real)0.2;
            if (k % 3 == 1) CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, all[n], &sd, &disc)));
            else CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_capsule(w, all[n], &sd, &cap)));
            CHECK_RESULT(ga2d_shape_destroy(w, old, 1), GA2D_OK);
        }
        jd.body_a = anchor;
        jd.body_b = all[n];
        jd.local_anchor_a = ga2d_vec_make(100, 0);
        jd.length = 1;
        CHECK(!ga2d_joint_id_is_null(ga2d_distance_joint_create(w, &jd)));
        ++n;
    }
    for (i = 0; i < 6; ++i) {
        ga2d_body_def d = bd;
        d.position = ga2d_vec_make((ga2d_real)(-100 + 5 * cos(i * 1.0471975511965976)), (ga2d_real)(50 + 5 * sin(i * 1.0471975511965976)));
        d.polygon = ga2d_polygon_box((ga2d_real)0.2, (ga2d_real)0.4);
        cs.kicked[i] = all[n++] = ga2d_body_create(w, &d);
    }
    CHECK_RESULT(ga2d_world_set_force_callback(w, kick_field, &cs), GA2D_OK);
    {
        ga2d_revolute_joint_def rj = ga2d_default_revolute_joint_def();
        ga2d_body_def d = bd;
        d.type = GA2D_BODY_STATIC;
        d.position = ga2d_vec_make(0, -100);
        hub = ga2d_body_create(w, &d);
        d = bd;
        d.position = ga2d_vec_make(0, -100);
        d.polygon = ga2d_polygon_box(3, (ga2d_real)0.1);
        bar = all[n++] = ga2d_body_create(w, &d);
        rj.body_a = hub;
        rj.body_b = bar;
        rj.enable_motor = 1;
        rj.motor_speed = 40; /* rad/s: the ends move 2 m in a step */
        rj.max_motor_torque = (ga2d_real)1e6;
        CHECK(!ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &rj)));
    }
    for (step = 0; step < 30; ++step) {
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        for (i = 0; i < n; ++i) {
            ga2d_shape_id sh;
            ga2d_geometry g;
            ga2d_transform x = ga2d_body_transform(w, all[i]);
            /* from above its reach (the bar's is 3 m) straight down */
            ga2d_vec c = ga2d_body_center(w, all[i]), o = ga2d_vec_add(c, ga2d_vec_make(0, 4)), t = ga2d_vec_make(0, -8);
            ga2d_ray_result mine;
            found_ctx f;
            CHECK(ga2d_body_get_shapes(w, all[i], &sh, 1) == 1);
            g = ga2d_shape_geometry(w, sh);
            outside += !ga2d_aabb_contains(ga2d_shape_fat_aabb(w, sh), ga2d_shape_aabb(w, sh));
            CHECK(ga2d_ray_cast_shape(&g, x, o, t, &mine) == GA2D_OK && mine.hit);
            f.want = sh;
            f.found = 0;
            CHECK_RESULT(ga2d_world_cast_ray(w, o, t, ga2d_default_filter(), found_on_ray, &f), GA2D_OK);
            missed += !(f.found && f.fraction == mine.fraction);
            f.found = 0;
            CHECK_RESULT(ga2d_world_overlap_point(w, c, ga2d_default_filter(), found_shape, &f), GA2D_OK);
            missed += !f.found;
        }
    }
    CHECK(outside == 0);
    CHECK(missed == 0);
    /* the scene did what it is for: the joints pulled their bodies in,
       the kicked bodies fly, the bar spins */
    CHECK((double)ga2d_vec_length(ga2d_vec_sub(ga2d_body_position(w, all[11]), ga2d_vec_make(100, 0))) < 1.01);
    CHECK((double)ga2d_vec_length(ga2d_body_velocity(w, cs.kicked[0])) > 100);
    CHECK(fabs((double)ga2d_body_angular_velocity(w, bar)) > 30);
    if (verbose()) printf("queries: carried bodies: %d shapes outside their tree box after a step, %d missed by a query\n", outside, missed);
    ga2d_world_destroy(w);
}

/* A body stores its centre and reads its origin back from it (c - l q),
   which rounds at the centre's size: a shape 10^7 m out moves the centre
   there and the origin by up to a metre (the float ulp at 10^7 m is
   1 m; in double the shift is 10^-9 m).  Whatever the shift, the body's
   shapes stay inside their tree boxes and the queries find them, after
   a shape is added or removed, a chain made or destroyed, or a centre of
   mass set: for a static body (no step ever refits it) and a dynamic
   one, before any step. */
static void far_centre_keeps_boxes(void)
{
    int type, op;
    for (type = 0; type < 2; ++type)
        for (op = 0; op < 4; ++op) {
            ga2d_world_def wd = ga2d_default_world_def();
            ga2d_body_def bd = ga2d_default_body_def();
            ga2d_shape_def sd = ga2d_default_shape_def();
            ga2d_world *w;
            ga2d_body_id b;
            ga2d_shape_id box, far;
            ga2d_circle c = {{(ga2d_real)9.5e6, (ga2d_real)-1.7e6}, 1};
            ga2d_vec o;
            found_ctx f;
            int k;
            wd.gravity = ga2d_vec_make(0, 0);
            w = ga2d_world_create(&wd);
            bd.type = type ? GA2D_BODY_DYNAMIC : GA2D_BODY_STATIC;
            bd.position = ga2d_vec_make((ga2d_real)-21.5, (ga2d_real)-7.25);
            bd.rotor = ga2d_rotor_from_angle((ga2d_real)2.97);
            bd.polygon = ga2d_polygon_box((ga2d_real)0.3, (ga2d_real)0.3);
            b = ga2d_body_create(w, &bd);
            CHECK(ga2d_body_get_shapes(w, b, &box, 1) == 1);
            far = ga2d_shape_create_circle(w, b, &sd, &c); /* the centre goes far out */
            CHECK(!ga2d_shape_id_is_null(far));
            for (k = 0; k < 3; ++k) {
                if (op == 0) { /* more shapes far out, each moving the centre again */
                    c.center.x = (ga2d_real)((double)c.center.x * 1.3);
                    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
                } else if (op == 1) { /* a far shape removed, then another made */
                    CHECK_RESULT(ga2d_shape_destroy(w, far, 1), GA2D_OK);
                    c.center.y = (ga2d_real)((double)c.center.y * 1.7);
                    far = ga2d_shape_create_circle(w, b, &sd, &c);
                } else if (op == 2) { /* a chain far out, made and destroyed */
                    ga2d_vec pts[2];
                    ga2d_chain_def cd = ga2d_default_chain_def();
                    ga2d_chain_id ch;
                    pts[0] = ga2d_vec_make((ga2d_real)3e6, 0);
                    pts[1] = ga2d_vec_make((ga2d_real)(3e6 + 1000.0 * (k + 1)), 500); /* apart by more than 64 eps of their size */
                    cd.points = pts;
                    cd.count = 2;
                    ch = ga2d_chain_create(w, b, &cd);
                    if (type == 0) {
                        CHECK(ch.index1 != 0);
                        if (k == 1) CHECK_RESULT(ga2d_chain_destroy(w, ch), GA2D_OK);
                    }
                } else if (type == 1) { /* a centre of mass set far out */
                    ga2d_mass m = ga2d_body_mass_data(w, b);
                    m.center = ga2d_vec_make((ga2d_real)(-4e6 * (k + 1)), (ga2d_real)(1e6 * k + 3e5));
                    CHECK_RESULT(ga2d_body_set_mass_data(w, b, m), GA2D_OK);
                }
                CHECK(ga2d_aabb_contains(ga2d_shape_fat_aabb(w, box), ga2d_shape_aabb(w, box)));
                /* a ray down through the box, from 2 m above it */
                o = ga2d_vec_scale(ga2d_vec_add(ga2d_shape_aabb(w, box).lower, ga2d_shape_aabb(w, box).upper), (ga2d_real)0.5);
                f.want = box;
                f.found = 0;
                CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_add(o, ga2d_vec_make(0, 2)), ga2d_vec_make(0, -4), ga2d_default_filter(),
                                                 found_on_ray, &f),
                             GA2D_OK);
                CHECK(f.found);
            }
            ga2d_world_destroy(w);
        }
}

/* A centre of mass set 10 m off the body's only shape (set_mass_data)
   makes the shape swing 10 m out when the body turns: a box turning at
   40 rad/s about such a centre (0.67 rad a step, its box sweeping 6.7 m)
   stays inside its tree box after every step, and the queries find it.
   (The body's reach was measured from the old centre: its boxes and the
   end-of-step test were 14 times too small.) */
static void mass_centre_off_the_shape(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_world *w;
    ga2d_body_id b;
    ga2d_shape_id sh;
    ga2d_mass m;
    int i, outside = 0, missed = 0;
    wd.gravity = ga2d_vec_make(0, 0);
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    b = ga2d_body_create(w, &bd);
    CHECK(ga2d_body_get_shapes(w, b, &sh, 1) == 1);
    m = ga2d_body_mass_data(w, b);
    m.center = ga2d_vec_make(-8, (ga2d_real)-6);
    m.inertia = m.mass * 100; /* as if the mass were 10 m away */
    CHECK_RESULT(ga2d_body_set_mass_data(w, b, m), GA2D_OK);
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, b, 40), GA2D_OK);
    for (i = 0; i < 60; ++i) {
        ga2d_aabb box;
        ga2d_vec o;
        found_ctx f;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        box = ga2d_shape_aabb(w, sh);
        outside += !ga2d_aabb_contains(ga2d_shape_fat_aabb(w, sh), box);
        o = ga2d_vec_scale(ga2d_vec_add(box.lower, box.upper), (ga2d_real)0.5);
        f.want = sh;
        f.found = 0;
        CHECK_RESULT(ga2d_world_cast_ray(w, ga2d_vec_add(o, ga2d_vec_make(0, 2)), ga2d_vec_make(0, -4), ga2d_default_filter(),
                                         found_on_ray, &f),
                     GA2D_OK);
        missed += !f.found;
    }
    CHECK(outside == 0);
    CHECK(missed == 0);
    CHECK(fabs((double)ga2d_body_angular_velocity(w, b) - 40) < 1e-3); /* it did turn: nothing else acts */
    ga2d_world_destroy(w);
}

void suite_queries(void)
{
    test_run("queries: rays against brute force", rays_against_brute_force);
    test_run("queries: ray edge cases", ray_edge_cases);
    test_run("queries: ray cast of a placed shape", ray_cast_shape_placed);
    test_run("queries: a ray ending at the real range's end", ray_cast_at_range_end);
    test_run("queries: GJK distance against brute force", distance_against_brute_force);
    test_run("queries: shape cast against brute force", shape_cast_against_brute_force);
    test_run("queries: time of impact against a sweep", toi_against_sweep);
    test_run("queries: world queries match a scan", world_queries_match_a_scan);
    test_run("queries: ray clip protocol", ray_clip_protocol);
    test_run("queries: refusals and locks", query_refusals);
    test_run("queries: list bodies", list_bodies);
    test_run("queries: answers finite at the extremes", answers_finite_at_extremes);
    test_run("queries: shape queries refuse a proxy past the coordinate bound, answer at it", shape_queries_bounded);
    test_run("queries: bodies a step carries out of their boxes are found after it", carried_bodies_found);
    test_run("queries: a far centre of mass moves no shape out of its box", far_centre_keeps_boxes);
    test_run("queries: a centre of mass set off the shape widens its reach", mass_centre_off_the_shape);
}
