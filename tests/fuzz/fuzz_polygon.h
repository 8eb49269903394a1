/* Polygon fuzzing: raw bytes -> points -> ga2d_polygon_make and
   ga2d_polygon_hull; accepted polygons go through mass, transforms, AABBs
   and the narrowphase, and every documented promise is checked:

     make / hull   a refusal leaves *out untouched; the first failing check
                   is the documented one for non-finite (NOT_FINITE) and
                   too large (TOO_LARGE) input; an accepted polygon is CCW,
                   strictly convex with the validation's margin, has unit
                   outward normals, and (hull) uses only input points and
                   leaves no input point outside it beyond its tolerance;
     mass          OK for any density in [0, 1e6] (GA2D_MAX_COORDINATE's
                   promise), finite, the area matching an independent sum,
                   the centroid inside the polygon's box, the inertia
                   between 0 and m L^2; ga2d_polygon_mass agrees;
     transforms    apply_inv undoes apply, mul composes, the AABB holds
                   every placed vertex;
     collide       a count in 0..2 (or a negative error for bad input),
                   a unit normal and finite points and separations.

   Tolerances: eps = the build's machine epsilon; L = the polygon's extent
   (the larger side of its bounding box), as in the header.  Each bound is
   derived where it is checked. */
#ifndef GA2D_FUZZ_POLYGON_H
#define GA2D_FUZZ_POLYGON_H

#include "fuzz_common.h"

#define FP_MAXV GA2D_MAX_POLYGON_VERTICES
#define FP_MAX_HULL_POINTS 32

static double fp_extent(const ga2d_vec *p, int n)
{
    double lox = (double)p[0].x, hix = lox, loy = (double)p[0].y, hiy = loy;
    int i;
    for (i = 1; i < n; ++i) {
        lox = fmin(lox, (double)p[i].x);
        hix = fmax(hix, (double)p[i].x);
        loy = fmin(loy, (double)p[i].y);
        hiy = fmax(hiy, (double)p[i].y);
    }
    return fmax(hix - lox, hiy - loy);
}

/* wedge(b - a, c - a) in double */
static double fp_wedge3(ga2d_vec a, ga2d_vec b, ga2d_vec c)
{
    double ex = (double)b.x - (double)a.x, ey = (double)b.y - (double)a.y;
    double dx = (double)c.x - (double)a.x, dy = (double)c.y - (double)a.y;
    return ex * dy - ey * dx;
}

static double fp_dist(ga2d_vec a, ga2d_vec b) { return hypot((double)b.x - (double)a.x, (double)b.y - (double)a.y); }

/* The promises of an accepted polygon (from make, or from hull). */
static void fp_check_polygon(const ga2d_polygon *p)
{
    int n = p->count, i, j;
    double L, area2 = 0;
    FUZZ_CHECK(n >= 3 && n <= FP_MAXV);
    L = fp_extent(p->vertices, n);
    FUZZ_CHECK(L > 0 && fz_finite(L));
    for (i = 0; i < n; ++i) {
        ga2d_vec a = p->vertices[i], b = p->vertices[(i + 1) % n], nr = p->normals[i];
        double e = fp_dist(a, b), nl = hypot((double)nr.x, (double)nr.y);
        double ex = (double)b.x - (double)a.x, ey = (double)b.y - (double)a.y;
        FUZZ_CHECK(fz_finite_vec(a));
        /* unit normal: normalize divides by a length that is itself within
           ~2 eps of true, then rounds each component (eps/2): |n| = 1
           within 4 eps */
        FUZZ_CHECK(fabs(nl - 1) <= 4 * FZ_EPS);
        /* outward: n is the edge turned clockwise, (ey, -ex)/|e|.  The edge
           the library normalized was rounded once per component (eps/2
           relative), so n . (ey, -ex) >= |e| (1 - 4 eps) and the component
           along the edge is at most 4 eps |e| */
        FUZZ_CHECK((double)nr.x * ey - (double)nr.y * ex >= e * (1 - 4 * FZ_EPS));
        FUZZ_CHECK(fabs((double)nr.x * ex + (double)nr.y * ey) <= 4 * FZ_EPS * e);
        /* strictly convex and CCW: make accepted only if every other vertex
           is left of this edge by more than tol |e|, tol = 64 eps L.  Its own
           arithmetic rounded the edge and the offset (eps/2 relative each,
           |offset| <= sqrt2 L) and the wedge (eps |e| |offset|): under
           3 sqrt2 eps L |e| < 5 eps L |e| in all.  Recomputed here (in
           double: exact for float input up to one rounding), the wedge
           still exceeds (64 - 5 - 1) eps L |e| > 32 eps L |e|. */
        for (j = 0; j < n; ++j) {
            if (j == i || j == (i + 1) % n) continue;
            FUZZ_CHECK(fp_wedge3(a, b, p->vertices[j]) > 32 * FZ_EPS * L * e);
        }
    }
    /* area: make refused |2A| <= 2e-5 L^2 as its own sum computed it: n - 2
       wedges of offsets <= sqrt2 L, each rounded by under 2 eps (sqrt2 L)^2
       = 4 eps L^2, so the true 2A > (2e-5 - 4 n eps) L^2; the sum here
       (in double) rounds by as much again at most */
    for (i = 1; i + 1 < n; ++i) area2 += fp_wedge3(p->vertices[0], p->vertices[i], p->vertices[i + 1]);
    FUZZ_CHECK(area2 > 0);
    FUZZ_CHECK(area2 > (2e-5 - 8 * n * FZ_EPS) * L * L);
}

#ifdef FUZZ_VERBOSE
static void fp_dump(const char *what, const ga2d_polygon *p)
{
    int i;
    fprintf(stderr, "%s: %d vertices\n", what, p->count);
    for (i = 0; i < p->count; ++i) fprintf(stderr, "  (%.17g, %.17g)\n", (double)p->vertices[i].x, (double)p->vertices[i].y);
}
#define FP_DUMP(what, p) fp_dump(what, p)
#else
#define FP_DUMP(what, p) ((void)0)
#endif

/* Mass properties at `density` against an independent computation. */
static void fp_check_mass(const ga2d_polygon *p, ga2d_real density)
{
    ga2d_mass m, plain, sentinel;
    ga2d_result r;
    int n = p->count, i;
    double L = fp_extent(p->vertices, n), area2 = 0, lox, loy, hix, hiy;
    memset(&sentinel, 0x5A, sizeof sentinel);
    m = sentinel;
    r = ga2d_polygon_mass_checked(p, density, &m);
    plain = ga2d_polygon_mass(p, density);
    FP_DUMP("mass", p);
#ifdef FUZZ_VERBOSE
    fprintf(stderr, "  density %.17g: %s, mass %.17g inertia %.17g\n", (double)density, ga2d_result_string(r),
            (double)m.mass, (double)m.inertia);
#endif
    if (!fz_finite((double)density)) {
        FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE);
    } else if (density < 0) {
        FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
    } else if ((double)density <= 1e6) {
        /* GA2D_MAX_COORDINATE keeps every term finite up to density ~1e6 */
        FUZZ_CHECK(r == GA2D_OK);
    } else {
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_TOO_LARGE);
    }
    if (r != GA2D_OK) {
        FUZZ_CHECK(memcmp(&m, &sentinel, sizeof m) == 0); /* untouched */
        FUZZ_CHECK(plain.mass == 0 && plain.inertia == 0 && plain.center.x == 0 && plain.center.y == 0);
        return;
    }
    FUZZ_CHECK(memcmp(&m, &plain, sizeof m) == 0);
    FUZZ_CHECK(fz_finite((double)m.mass) && fz_finite((double)m.inertia) && fz_finite_vec(m.center));
    FUZZ_CHECK(m.mass >= 0 && m.inertia >= 0);
    for (i = 1; i + 1 < n; ++i) area2 += fp_wedge3(p->vertices[0], p->vertices[i], p->vertices[i + 1]);
    /* The library sums n wedges of offsets from the vertex mean (each
       offset <= sqrt2 L, rounded once: eps/2 relative; the mean itself
       may be off, but any interior reference gives the same exact sum);
       each wedge then carries at most 2 eps (sqrt2 L)^2 = 4 eps L^2 of
       rounding and the sum n eps/2 of the total: |2A_lib - 2A| <=
       5 n eps L^2.  Times the density (one more rounding, or an
       underflow by at most the smallest subnormal): */
    FUZZ_CHECK(fabs((double)m.mass - (double)density * (area2 / 2)) <=
               5 * n * FZ_EPS * L * L / 2 * (double)density + FZ_EPS * (double)m.mass + 2 * FZ_TINY);
    if (density > 0 && (double)m.mass >= 1e-30 && (double)m.mass <= 1e30) {
        /* the centroid lies in the polygon, so within its bounding box;
           its rounding is a few eps of (L + |centre|) */
        lox = hix = (double)p->vertices[0].x;
        loy = hiy = (double)p->vertices[0].y;
        for (i = 1; i < n; ++i) {
            lox = fmin(lox, (double)p->vertices[i].x);
            hix = fmax(hix, (double)p->vertices[i].x);
            loy = fmin(loy, (double)p->vertices[i].y);
            hiy = fmax(hiy, (double)p->vertices[i].y);
        }
        {
            double slack = 16 * FZ_EPS * (L + fabs((double)m.center.x) + fabs((double)m.center.y));
            FUZZ_CHECK((double)m.center.x >= lox - slack && (double)m.center.x <= hix + slack);
            FUZZ_CHECK((double)m.center.y >= loy - slack && (double)m.center.y <= hiy + slack);
        }
        /* 0 < I <= m max|x - C|^2 <= m (sqrt2 L)^2 = 2 m L^2 (every point
           is within the box's diagonal of C), with rounding slack.  The
           sums behind I are taken at unit density and scale as A L^2;
           below the smallest normal number / eps they lose every digit to
           underflow (a 1e-11 polygon in float), and then only I >= 0 is
           promised; the same for m L^2 (the density's product). */
        if (area2 / 2 * L * L >= 64 * FZ_REAL_MIN / FZ_EPS && (double)m.mass * L * L >= 64 * FZ_REAL_MIN / FZ_EPS) {
            FUZZ_CHECK((double)m.inertia <= 2 * (double)m.mass * L * L * (1 + 64 * FZ_EPS));
            FUZZ_CHECK(m.inertia > 0);
        }
    }
}

/* A unit rotor from a decoded angle; a finite transform. */
static ga2d_transform fp_transform(fz_reader *r, double scale)
{
    ga2d_vec p;
    ga2d_real a;
    p.x = fz_real(r, scale);
    p.y = fz_real(r, scale);
    a = fz_real(r, 4);
    if (!fz_finite_vec(p)) p = ga2d_vec_make(0, 0);
    if (!fz_finite((double)a)) a = 0;
    return ga2d_transform_make(p, ga2d_rotor_from_angle(a));
}

static double fp_norm(ga2d_vec v) { return fabs((double)v.x) + fabs((double)v.y); }

static void fp_check_transforms(const ga2d_polygon *p, ga2d_transform x, ga2d_transform y)
{
    ga2d_aabb box = ga2d_polygon_aabb(p, x);
    ga2d_transform xy = ga2d_transform_mul(x, y), rel = ga2d_transform_inv_mul(x, y);
    int i;
    for (i = 0; i < p->count; ++i) {
        ga2d_vec v = p->vertices[i], w = ga2d_transform_apply(x, v), back = ga2d_transform_apply_inv(x, w);
        double size = fp_norm(x.p) + fp_norm(v) + fp_norm(y.p);
        if (!(size < 1e-3 * FZ_REAL_MAX)) continue; /* would overflow: no promise */
        FUZZ_CHECK(w.x >= box.lower.x && w.x <= box.upper.x && w.y >= box.lower.y && w.y <= box.upper.y);
        /* v -> p + v q -> ((p + v q) - p) q~: a rotor from the angle is unit
           within eps; each rotate rounds twice per component (2 eps |v|
           with the norm), each add/sub once (eps/2 of the sum): in all
           under 8 eps (|p| + |v|) in the 1-norm used here; results in the
           subnormal range are off by up to a few of its smallest steps */
        FUZZ_CHECK(fp_norm(ga2d_vec_sub(back, v)) <= 8 * FZ_EPS * size + 8 * FZ_TINY);
        {
            /* mul: apply(xy, v) = apply(x, apply(y, v)); each side rounds
               under 8 eps of the sizes involved; inv_mul: apply(x,
               apply(rel, v)) = apply(y, v), the same budget twice */
            ga2d_vec a = ga2d_transform_apply(xy, v), b = ga2d_transform_apply(x, ga2d_transform_apply(y, v));
            ga2d_vec c = ga2d_transform_apply(x, ga2d_transform_apply(rel, v)), d = ga2d_transform_apply(y, v);
#ifdef FUZZ_VERBOSE
            fprintf(stderr, "x (%.17g %.17g | %.17g %.17g) y (%.17g %.17g | %.17g %.17g) v (%.17g %.17g): mul %.3g inv_mul %.3g size %.3g\n",
                    (double)x.p.x, (double)x.p.y, (double)x.q.c, (double)x.q.s, (double)y.p.x, (double)y.p.y,
                    (double)y.q.c, (double)y.q.s, (double)v.x, (double)v.y, fp_norm(ga2d_vec_sub(a, b)),
                    fp_norm(ga2d_vec_sub(c, d)), size);
#endif
            FUZZ_CHECK(fp_norm(ga2d_vec_sub(a, b)) <= 16 * FZ_EPS * size + 8 * FZ_TINY);
            FUZZ_CHECK(fp_norm(ga2d_vec_sub(c, d)) <= 32 * FZ_EPS * size + 8 * FZ_TINY);
        }
    }
}

static void fp_check_collide(const ga2d_polygon *a, ga2d_transform xa, const ga2d_polygon *b, ga2d_transform xb,
                             ga2d_real units)
{
    ga2d_manifold m, sentinel;
    int k, i;
    memset(&sentinel, 0x3C, sizeof sentinel);
    m = sentinel;
    k = ga2d_collide_polygons_scaled(a, xa, b, xb, units, &m);
    if (!fz_finite((double)units)) {
        FUZZ_CHECK(k == -(int)GA2D_ERR_NOT_FINITE);
    } else if (!(units > 0)) {
        FUZZ_CHECK(k == -(int)GA2D_ERR_INVALID_ARGUMENT);
    }
    if (k < 0) {
        FUZZ_CHECK(k > -(int)GA2D_RESULT_COUNT);
        FUZZ_CHECK(memcmp(&m, &sentinel, sizeof m) == 0);
        return;
    }
    FUZZ_CHECK(k <= 2 && m.count == k);
    if (k == 0) return;
    /* everything within 1e-3 of the largest real: the offsets between the
       two placements cannot overflow */
    if (!(fp_norm(xa.p) + fp_norm(xb.p) + fp_extent(a->vertices, a->count) + fp_extent(b->vertices, b->count) <
          1e-3 * FZ_REAL_MAX))
        return;
#ifdef FUZZ_VERBOSE
    FP_DUMP("collide a", a);
    FP_DUMP("collide b", b);
    fprintf(stderr, "xa (%.9g %.9g | %.9g %.9g) xb (%.9g %.9g | %.9g %.9g) units %g: %d points, normal (%.9g, %.9g)\n",
            (double)xa.p.x, (double)xa.p.y, (double)xa.q.c, (double)xa.q.s, (double)xb.p.x, (double)xb.p.y,
            (double)xb.q.c, (double)xb.q.s, (double)units, k, (double)m.normal.x, (double)m.normal.y);
#endif
    /* a unit normal (normalize, then rotate by a unit rotor: 4 eps) */
    FUZZ_CHECK(fabs(hypot((double)m.normal.x, (double)m.normal.y) - 1) <= 8 * FZ_EPS);
    for (i = 0; i < k; ++i) {
        FUZZ_CHECK(fz_finite_vec(m.points[i].point) && fz_finite_vec(m.points[i].anchor_a) &&
                   fz_finite_vec(m.points[i].anchor_b));
        FUZZ_CHECK(fz_finite((double)m.points[i].separation));
        FUZZ_CHECK(m.points[i].normal_impulse == 0 && m.points[i].tangent_impulse == 0);
    }
}

/* Decodes n points: fresh ones, exact repeats, near-repeats and midpoints,
   placed around an offset at a scale both chosen by the input. */
static void fp_points(fz_reader *r, ga2d_vec *pts, int n)
{
    static const double scales[8] = {1, 1e-3, 1e3, 1e-20, 1e6, 1e-35, 1e30, 12.5e6};
    double scale = scales[fz_pick(r, 8)];
    ga2d_vec off;
    int i;
    off.x = fz_u8(r) < 200 ? 0 : fz_real(r, 1024);
    off.y = fz_u8(r) < 200 ? 0 : fz_real(r, 1024);
    for (i = 0; i < n; ++i) {
        int mode = fz_pick(r, 8);
        if (i > 0 && mode == 5) {
            pts[i] = pts[fz_pick(r, i)];
        } else if (i > 0 && mode == 6) {
            ga2d_vec q = pts[fz_pick(r, i)];
            int k = (int)(int8_t)fz_u8(r);
            pts[i] = ga2d_vec_make(fz_narrow((double)q.x + k * FZ_EPS * scale),
                                   fz_narrow((double)q.y + (int)(int8_t)fz_u8(r) * FZ_EPS * scale));
        } else if (i > 1 && mode == 7) {
            ga2d_vec a = pts[fz_pick(r, i)], b = pts[fz_pick(r, i)];
            pts[i] = ga2d_vec_make(fz_narrow(((double)a.x + (double)b.x) / 2), fz_narrow(((double)a.y + (double)b.y) / 2));
        } else {
            /* one read a statement: arguments are evaluated in no set order */
            ga2d_real x = fz_narrow((double)fz_real(r, scale) + (double)off.x);
            pts[i] = ga2d_vec_make(x, fz_narrow((double)fz_real(r, scale) + (double)off.y));
        }
    }
}

/* The checks the header's order promises for a refused point set: with a
   count in range, any NaN/Inf is NOT_FINITE, else any coordinate beyond
   GA2D_MAX_COORDINATE is TOO_LARGE. */
static void fp_check_order(const ga2d_vec *pts, int n, ga2d_result r)
{
    int i, nonfinite = 0, large = 0;
    for (i = 0; i < n; ++i) {
        if (!fz_finite_vec(pts[i])) nonfinite = 1;
        else if (fabs((double)pts[i].x) > (double)GA2D_MAX_COORDINATE || fabs((double)pts[i].y) > (double)GA2D_MAX_COORDINATE)
            large = 1;
    }
    if (nonfinite) FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE);
    else if (large) FUZZ_CHECK(r == GA2D_ERR_TOO_LARGE);
    else FUZZ_CHECK(r != GA2D_ERR_NOT_FINITE && r != GA2D_ERR_TOO_LARGE);
}

/* Hull: vertices are input points, and no input point lies outside an
   edge by more than the hull's tolerances allow (tol = 4 x 64 eps L): a
   point welded to a vertex (within tol of it), that vertex's edge chosen
   among ties (within tol of its line), and a neighbour dropped (points
   kept within 2 tol of the new edge) add up to 4 tol, plus rounding. */
static void fp_check_hull(const ga2d_polygon *h, const ga2d_vec *pts, int n)
{
    int i, j;
    double L = fp_extent(pts, n), tol = 4 * 64 * FZ_EPS * L;
#ifdef FUZZ_VERBOSE
    for (i = 0; i < n; ++i) fprintf(stderr, "  input %d: (%.9g, %.9g)\n", i, (double)pts[i].x, (double)pts[i].y);
#endif
    for (i = 0; i < h->count; ++i) {
        int found = 0;
        for (j = 0; j < n && !found; ++j) found = memcmp(&h->vertices[i], &pts[j], sizeof pts[j]) == 0;
        FUZZ_CHECK(found);
    }
    for (i = 0; i < h->count; ++i) {
        ga2d_vec a = h->vertices[i], b = h->vertices[(i + 1) % h->count];
        double e = fp_dist(a, b);
        for (j = 0; j < n; ++j) {
#ifdef FUZZ_VERBOSE
            if (!(fp_wedge3(a, b, pts[j]) >= -(4 * tol + 8 * FZ_EPS * L) * e))
                fprintf(stderr, "hull edge %d, point %d (%.9g, %.9g) outside by %.9g (tol %.9g)\n", i, j, (double)pts[j].x,
                        (double)pts[j].y, -fp_wedge3(a, b, pts[j]) / e, tol);
#endif
            FUZZ_CHECK(fp_wedge3(a, b, pts[j]) >= -(4 * tol + 8 * FZ_EPS * L) * e);
        }
    }
}

static int fuzz_polygon_one(const uint8_t *data, size_t size)
{
    fz_reader rd;
    ga2d_vec pts[FP_MAX_HULL_POINTS] = {{0, 0}};
    ga2d_polygon made, hull, sentinel, other;
    ga2d_result r;
    int n_make, n_hull, have_made = 0, have_hull = 0;
    fz_init(&rd, data, size);
    memset(&sentinel, 0xA5, sizeof sentinel);

    n_make = fz_pick(&rd, FP_MAXV + 3);       /* 0 .. MAX + 2 */
    n_hull = fz_pick(&rd, FP_MAX_HULL_POINTS + 1);
    fp_points(&rd, pts, n_make > n_hull ? n_make : n_hull);

    /* make */
    made = sentinel;
    r = ga2d_polygon_make(pts, n_make, &made);
    if (n_make < 3) FUZZ_CHECK(r == GA2D_ERR_TOO_FEW_POINTS);
    else if (n_make > FP_MAXV) FUZZ_CHECK(r == GA2D_ERR_TOO_MANY_POINTS);
    else fp_check_order(pts, n_make, r);
    if (r == GA2D_OK) {
        int i;
        FUZZ_CHECK(made.count == n_make);
        for (i = 0; i < n_make; ++i) FUZZ_CHECK(memcmp(&made.vertices[i], &pts[i], sizeof pts[i]) == 0);
        fp_check_polygon(&made);
        have_made = 1;
        {
            /* the hull of an accepted polygon's own vertices: the same
               polygon, or fewer vertices where the hull's 4x tolerance
               welds or drops some (a thin one may have no hull left: too
               few points, collinear or degenerate), but never a refusal
               that says the points were not convex or wound wrongly */
            ga2d_polygon h2;
            r = ga2d_polygon_hull(pts, n_make, &h2);
            FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_TOO_FEW_POINTS || r == GA2D_ERR_COLLINEAR_POINTS ||
                       r == GA2D_ERR_DEGENERATE);
            if (r == GA2D_OK) FUZZ_CHECK(h2.count <= n_make);
        }
    } else {
        FUZZ_CHECK(r > GA2D_OK && r < GA2D_RESULT_COUNT);
        FUZZ_CHECK(memcmp(&made, &sentinel, sizeof made) == 0);
    }
    FUZZ_CHECK(ga2d_polygon_make(NULL, 3, &made) == GA2D_ERR_INVALID_ARGUMENT);
    FUZZ_CHECK(ga2d_polygon_make(pts, -1, &made) == GA2D_ERR_INVALID_ARGUMENT);

    /* hull */
    hull = sentinel;
    r = ga2d_polygon_hull(pts, n_hull, &hull);
    if (n_hull >= 3) fp_check_order(pts, n_hull, r);
    else FUZZ_CHECK(r == GA2D_ERR_TOO_FEW_POINTS);
    if (r == GA2D_OK) {
        ga2d_polygon again;
        FP_DUMP("hull", &hull);
        fp_check_polygon(&hull);
        fp_check_hull(&hull, pts, n_hull);
        /* a hull is a valid polygon: validating its vertices again (as
           ga2d_body_def_validate does) accepts them */
        FUZZ_CHECK(ga2d_polygon_make(hull.vertices, hull.count, &again) == GA2D_OK);
        have_hull = 1;
    } else {
        FUZZ_CHECK(r > GA2D_OK && r < GA2D_RESULT_COUNT);
        FUZZ_CHECK(memcmp(&hull, &sentinel, sizeof hull) == 0);
    }

    /* the value constructors */
    {
        ga2d_real hw = fz_real(&rd, 4), hh = fz_real(&rd, 4), rad = fz_real(&rd, 4);
        int nreg = fz_pick(&rd, FP_MAXV + 3);
        ga2d_polygon box = ga2d_polygon_box(hw, hh), reg = ga2d_polygon_regular(nreg, rad);
        if (!(hw > 0 && hh > 0 && fz_finite((double)hw) && fz_finite((double)hh))) FUZZ_CHECK(box.count == 0);
        if (nreg < 3 || nreg > FP_MAXV || !(rad > 0)) FUZZ_CHECK(reg.count == 0);
        if (reg.count) {
            FUZZ_CHECK(reg.count == nreg);
            fp_check_polygon(&reg);
        }
        other = reg.count ? reg : ga2d_polygon_box(1, 1);
        if (box.count) {
            ga2d_mass bm;
            /* the box is not validated beyond its half-extents; its mass
               must still be computable (or refused with a code) */
            r = ga2d_polygon_mass_checked(&box, 1, &bm);
            FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_TOO_LARGE || r == GA2D_ERR_DEGENERATE);
        }
    }

    {
        ga2d_real density = fz_real_pos(&rd, 4);
        ga2d_transform x = fp_transform(&rd, 64), y = fp_transform(&rd, 64), z = fp_transform(&rd, 4);
        ga2d_real units = fz_u8(&rd) < 200 ? 1 : fz_real(&rd, 4);
        const ga2d_polygon *p = have_made ? &made : (have_hull ? &hull : NULL);
        if (p) {
            fp_check_mass(p, density);
            fp_check_mass(p, 1);
            fp_check_transforms(p, x, y);
            fp_check_collide(p, x, &other, z, units);
            fp_check_collide(&other, z, p, x, units);
            if (have_made && have_hull) fp_check_collide(&made, x, &hull, y, units);
        }
        /* bad arguments answered, not crashed on */
        FUZZ_CHECK(ga2d_polygon_mass_checked(NULL, 1, NULL) == GA2D_ERR_INVALID_ARGUMENT);
        {
            ga2d_polygon bad = sentinel;
            ga2d_manifold m;
            bad.count = FP_MAXV + 1;
            FUZZ_CHECK(ga2d_polygon_mass(&bad, 1).mass == 0);
            FUZZ_CHECK(ga2d_collide_polygons(&bad, x, &other, y, &m) == -(int)GA2D_ERR_INVALID_ARGUMENT);
            (void)ga2d_polygon_aabb(&bad, x);
        }
    }
    return 0;
}

#endif
