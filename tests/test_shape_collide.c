/* Manifolds between the round shapes and polygons: ga2d_collide_shapes on
   exact cases worked out by hand; on random pairs of every kind (circle,
   capsule, sharp and rounded polygon, segment) against an independent
   signed distance, against itself with the arguments swapped, far from the
   origin and under a small nudge; bad input; degenerate shapes.

   Error model (that of tests/test_collide.c, eps = REAL_EPS = 2u): the
   library works in A's frame, where B's core points are xf.p + v xf.q with
   xf = xa^-1 xb.  With R the farthest core point from either body's origin
   plus both radii, each core coordinate there is within 6 eps R; a
   separation (a difference, a dot product or a length, less the radii)
   adds under 10 eps R; the normal's own error (4 eps for a rotated face
   normal) times distances <= 2R.  Below 16 eps R in all; RND = 32 eps R
   allows for the points (one more midpoint or interpolation) and for the
   reference values, computed in double from the same inputs.  A normal
   that is a difference of two points at distance d (circle centres, a
   vertex and a centre, two vertices) errs by 2 RND / d more. */
#include "test.h"

#define PI 3.14159265358979323846
#define MAXV GA2D_MAX_POLYGON_VERTICES
#define SLOP ((double)GA2D_LINEAR_SLOP)
#define MARGIN ((double)GA2D_SPECULATIVE_DISTANCE)
#define HYST (0.1 * SLOP) /* the library's hysteresis and closest-feature tolerance */
#ifndef SHAPE_PAIRS
#define SHAPE_PAIRS 150 /* random pairs per kind of pair and property */
#endif

/* far from the origin: T and its spacing (ulp), as in test_collide.c */
#ifdef GA2D_DOUBLE
#define FAR_T 1e6
#define FAR_ULP (1.0 / 8589934592.0)
#else
#define FAR_T 1e4
#define FAR_ULP (1.0 / 1024.0)
#endif

enum { K_CIRCLE, K_CAPSULE, K_SEGMENT, K_POLYGON, K_ROUNDED };
/* the pairs under test; each is also run the other way round */
static const int KINDS[][2] = {{K_CIRCLE, K_CIRCLE},   {K_CIRCLE, K_CAPSULE},  {K_CIRCLE, K_POLYGON},
                               {K_CIRCLE, K_ROUNDED},  {K_CAPSULE, K_CAPSULE}, {K_CAPSULE, K_POLYGON},
                               {K_CAPSULE, K_ROUNDED}, {K_ROUNDED, K_POLYGON}, {K_ROUNDED, K_ROUNDED},
                               {K_CIRCLE, K_SEGMENT},  {K_CAPSULE, K_SEGMENT}, {K_POLYGON, K_SEGMENT},
                               {K_ROUNDED, K_SEGMENT}};
#define NKINDS ((int)(sizeof KINDS / sizeof KINDS[0]))

static ga2d_vec V(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }
static ga2d_transform X(double x, double y) { return ga2d_transform_make(V(x, y), ga2d_rotor_identity()); }
static double len2(double x, double y) { return sqrt(x * x + y * y); }
static double dmin(double a, double b) { return a < b ? a : b; }
static double dmax(double a, double b) { return a > b ? a : b; }

static ga2d_geometry circle(double x, double y, double r)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_CIRCLE;
    g.as.circle.center = V(x, y);
    g.as.circle.radius = (ga2d_real)r;
    return g;
}

static ga2d_geometry capsule(double x1, double y1, double x2, double y2, double r)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_CAPSULE;
    g.as.capsule.center1 = V(x1, y1);
    g.as.capsule.center2 = V(x2, y2);
    g.as.capsule.radius = (ga2d_real)r;
    return g;
}

static ga2d_geometry segment(double x1, double y1, double x2, double y2)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_SEGMENT;
    g.as.segment.point1 = V(x1, y1);
    g.as.segment.point2 = V(x2, y2);
    return g;
}

static ga2d_geometry polygon(const ga2d_polygon *p)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_POLYGON;
    g.as.polygon = *p;
    return g;
}

static int collide(const ga2d_geometry *a, ga2d_transform xa, const ga2d_geometry *b, ga2d_transform xb, ga2d_manifold *m)
{
    int n;
    memset(m, 0, sizeof *m);
    n = ga2d_collide_shapes(a, xa, b, xb, m);
    CHECK(n >= 0 && n <= 2 && n == m->count);
    return n;
}

static double min_sep(const ga2d_manifold *m)
{
    double s = 1e300;
    int k;
    for (k = 0; k < m->count; ++k) s = dmin(s, (double)m->points[k].separation);
    return s;
}

/* Every manifold (as in test_collide.c): a unit normal (one normalization
   and a rotation: 4 eps), finite points, distinct ids, anchors that name
   the point from each origin (one rounding, two more for anchor_b). */
static void check_manifold_basics(const ga2d_manifold *m, ga2d_transform xa, ga2d_transform xb)
{
    int k;
    if (m->count) CHECK_NEAR(len2((double)m->normal.x, (double)m->normal.y), 1, 4 * REAL_EPS);
    if (m->count == 2) CHECK(m->points[0].id != m->points[1].id);
    for (k = 0; k < m->count; ++k) {
        const ga2d_manifold_point *p = &m->points[k];
        double px = (double)p->point.x, py = (double)p->point.y;
        double big = fabs(px) + fabs(py) + fabs((double)xa.p.x) + fabs((double)xa.p.y) + fabs((double)xb.p.x) +
                     fabs((double)xb.p.y);
        CHECK(px - px == 0 && py - py == 0 && (double)p->separation - (double)p->separation == 0);
        CHECK_NEAR(p->anchor_a.x, px - (double)xa.p.x, 2 * REAL_EPS * big);
        CHECK_NEAR(p->anchor_a.y, py - (double)xa.p.y, 2 * REAL_EPS * big);
        CHECK_NEAR(p->anchor_b.x, px - (double)xb.p.x, 4 * REAL_EPS * big);
        CHECK_NEAR(p->anchor_b.y, py - (double)xb.p.y, 4 * REAL_EPS * big);
    }
}

/* point k is at (x, y) with separation s, within tol */
static void check_point(const ga2d_manifold *m, int k, double x, double y, double s, double tol)
{
    CHECK_NEAR(m->points[k].point.x, x, tol);
    CHECK_NEAR(m->points[k].point.y, y, tol);
    CHECK_NEAR(m->points[k].separation, s, tol);
}

/* the point of m at (x, y), whichever its index; -1 if none within tol */
static int find_point(const ga2d_manifold *m, double x, double y, double tol)
{
    int k;
    for (k = 0; k < m->count; ++k)
        if (fabs((double)m->points[k].point.x - x) <= tol && fabs((double)m->points[k].point.y - y) <= tol) return k;
    return -1;
}

/* ------------------------------------------------------------ exact cases */
/* Box A (half 1 x 0.5) at (2, 3); a circle of radius 1/4 above its top
   face at local x = 1/4, its surface g above the face: one point, normal
   +y, separation g, midway at y = 3.5 + g/2, feature A's face 2.  All
   values are dyadic with few bits: every operation is exact.  g = 1/32 is
   beyond the 0.02 margin. */
static void circle_on_a_face(void)
{
    const double gaps[4] = {-1.0 / 16, 0, 1.0 / 128, 1.0 / 32};
    ga2d_polygon box = ga2d_polygon_box(1, (ga2d_real)0.5);
    ga2d_geometry a = polygon(&box), b;
    ga2d_transform xa = X(2, 3);
    ga2d_manifold m;
    int k;
    for (k = 0; k < 4; ++k) {
        double g = gaps[k];
        ga2d_transform xb = X(2.25, 3.75 + g);
        b = circle(0, 0, 0.25);
        if (collide(&a, xa, &b, xb, &m) != (k < 3)) {
            CHECK(!"one point within the margin, none beyond");
            continue;
        }
        if (!m.count) continue;
        check_manifold_basics(&m, xa, xb);
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        check_point(&m, 0, 2.25, 3.5 + g / 2, g, 0);
        CHECK(m.points[0].id == 2u << 8);
        /* the other way round: the normal from the circle to the box, B's face */
        collide(&b, xb, &a, xa, &m);
        CHECK(m.count == 1 && m.normal.x == 0 && m.normal.y == -1);
        check_point(&m, 0, 2.25, 3.5 + g / 2, g, 0);
        CHECK(m.points[0].id == (1u << 16 | 2u));
    }
}

/* A circle past the corner (0.5, 0.5) of a unit box, its centre at the
   corner plus (3, 4)/16: distance 5/16, exact (sqrt of 25/256).  The
   normal is the corner-to-centre direction (0.6, 0.8): r / d, two roundings
   (eps).  Radius 5/16 - g: separation g, exact.  The point is midway,
   corner + n g/2: the normal's error times the radius (< 1/2) and two
   roundings of values below 1: 2 eps.  Feature: A's vertex 2. */
static void circle_at_a_corner(void)
{
    const double gaps[3] = {-1.0 / 32, 1.0 / 256, 3.0 / 128};
    ga2d_polygon box = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    ga2d_geometry a = polygon(&box);
    ga2d_manifold m;
    int k;
    for (k = 0; k < 3; ++k) {
        double g = gaps[k];
        ga2d_geometry b = circle(0.5 + 3.0 / 16, 0.5 + 4.0 / 16, 5.0 / 16 - g);
        if (collide(&a, X(0, 0), &b, X(0, 0), &m) != (k < 2)) {
            CHECK(!"one point within the margin, none beyond");
            continue;
        }
        if (!m.count) continue;
        check_manifold_basics(&m, X(0, 0), X(0, 0));
        CHECK_NEAR(m.normal.x, 0.6, REAL_EPS);
        CHECK_NEAR(m.normal.y, 0.8, REAL_EPS);
        check_point(&m, 0, 0.5 + 0.6 * g / 2, 0.5 + 0.8 * g / 2, g, 2 * REAL_EPS);
        CHECK(m.points[0].id == (0x80u | 2u) << 8);
    }
}

/* A circle of radius 1/4 wholly inside a box (half 2 x 1) at (1/2, 1/4):
   the nearest face is the top (3/4 away; the right one is 3/2): normal
   +y, separation -(3/4 + 1/4) = -1, the point midway between the top face
   and the circle's far side (y = 1 and 0): y = 1/2.  Exact.  A point (a
   circle of radius 0) at the same place: separation -3/4, y = 5/8. */
static void circle_inside_a_box(void)
{
    ga2d_polygon box = ga2d_polygon_box(2, 1);
    ga2d_geometry a = polygon(&box), b = circle(0.5, 0.25, 0.25), p = circle(0.5, 0.25, 0);
    ga2d_manifold m;
    if (collide(&a, X(0, 0), &b, X(0, 0), &m) == 1) {
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        check_point(&m, 0, 0.5, 0.5, -1, 0);
        CHECK(m.points[0].id == 2u << 8);
    } else CHECK(!"one point");
    if (collide(&a, X(0, 0), &p, X(0, 0), &m) == 1) {
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        check_point(&m, 0, 0.5, 0.625, -0.75, 0);
    } else CHECK(!"one point for a point");
}

/* A point (circle of radius 0) against box (half 1 x 0.5): above the top
   face by 1/64 (exact: separation 1/64, midway y = 0.5 + 1/128), and past
   the corner (1, 0.5) by (3, 4)/256 (distance 5/256 < margin; the normal
   (0.6, 0.8) within eps as in circle_at_a_corner, the point the corner
   plus half of (3, 4)/256, exact).  Then the same point just beyond the
   margin past the corner, (12, 16)/512 (distance 0.0390625): none. */
static void point_against_a_box(void)
{
    ga2d_polygon box = ga2d_polygon_box(1, (ga2d_real)0.5);
    ga2d_geometry a = polygon(&box), p = circle(0.25, 0.5 + 1.0 / 64, 0), q = circle(1 + 3.0 / 256, 0.5 + 4.0 / 256, 0),
                  far = circle(1 + 12.0 / 512, 0.5 + 16.0 / 512, 0);
    ga2d_manifold m;
    if (collide(&a, X(0, 0), &p, X(0, 0), &m) == 1) {
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        check_point(&m, 0, 0.25, 0.5 + 1.0 / 128, 1.0 / 64, 0);
    } else CHECK(!"one point above the face");
    if (collide(&a, X(0, 0), &q, X(0, 0), &m) == 1) {
        CHECK_NEAR(m.normal.x, 0.6, REAL_EPS);
        CHECK_NEAR(m.normal.y, 0.8, REAL_EPS);
        check_point(&m, 0, 1 + 1.5 / 256, 0.5 + 2.0 / 256, 5.0 / 256, REAL_EPS);
        CHECK(m.points[0].id == (0x80u | 2u) << 8);
    } else CHECK(!"one point past the corner");
    CHECK(collide(&a, X(0, 0), &far, X(0, 0), &m) == 0);
}

/* Circle A (radius 1/2) at (1, 2), circle B (radius 1/4) at (11/8, 5/2):
   centres (3/8, 1/2) apart, distance 5/8 (exact), separation -1/8 exact,
   normal (0.6, 0.8) within eps (as above).  The point is midway between
   A's surface (A + n/2) and B's (B - n/4): A + n 7/16: the normal's error
   times 7/16 and three roundings of values below 4 (each 2 eps): 8 eps.
   Concentric circles have no line of centres: the normal is A's x axis
   (here turned by 30 degrees), separation -(1/2 + 1/4). */
static void two_circles(void)
{
    ga2d_geometry a = circle(0, 0, 0.5), b = circle(0, 0, 0.25);
    ga2d_transform xa = X(1, 2), xb = X(1.375, 2.5), xr = ga2d_transform_make(V(1, 2), ga2d_rotor_from_angle((ga2d_real)(PI / 6)));
    ga2d_manifold m;
    if (collide(&a, xa, &b, xb, &m) == 1) {
        check_manifold_basics(&m, xa, xb);
        CHECK_NEAR(m.normal.x, 0.6, REAL_EPS);
        CHECK_NEAR(m.normal.y, 0.8, REAL_EPS);
        check_point(&m, 0, 1 + 0.6 * 7 / 16, 2 + 0.8 * 7 / 16, -0.125, 8 * REAL_EPS);
        CHECK(m.points[0].id == 0);
    } else CHECK(!"one point");
    if (collide(&a, xr, &b, xr, &m) == 1) {
        CHECK(m.normal.x == xr.q.c && m.normal.y == xr.q.s);
        CHECK(m.points[0].separation == (ga2d_real)-0.75);
    } else CHECK(!"one point, concentric");
}

/* A capsule (core from local (-3/4, 0) to (0, 0), radius 1/4) lying flat
   with its surface g above the top face of box A (half 1 x 1/2), or of a
   segment along y = 1/2: two points, at the projections of the core's
   ends (x = -1/2 and 1/4), midway: y = 1/2 + g/2, separation g, normal
   +y.  Dyadic values: exact.  g = -3/8 sinks the core 1/8 into the box
   (the overlapping-core branch); it then lies 1/8 below the segment,
   which has two sides: the capsule is pushed down, normal -y, separation
   1/8 - 1/4, midway between the segment and the capsule's top (y = 5/8). */
static void capsule_lying_flat(void)
{
    const double gaps[4] = {-0.375, -1.0 / 16, 0, 1.0 / 64};
    ga2d_polygon box = ga2d_polygon_box(1, (ga2d_real)0.5);
    ga2d_geometry base[2], b = capsule(-0.75, 0, 0, 0, 0.25);
    int j, k;
    base[0] = polygon(&box);
    base[1] = segment(-1, 0.5, 1, 0.5);
    for (j = 0; j < 2; ++j)
        for (k = 0; k < 4; ++k) {
            double g = gaps[k];
            int below = j == 1 && g < -0.25;
            double y = below ? 0.5625 : 0.5 + g / 2, sep = below ? -0.125 : g;
            ga2d_transform xb = X(0.25, 0.75 + g);
            ga2d_manifold m;
            if (collide(&base[j], X(0, 0), &b, xb, &m) != 2) {
                CHECK(!"two points");
                continue;
            }
            check_manifold_basics(&m, X(0, 0), xb);
            CHECK(m.normal.x == 0 && m.normal.y == (below ? -1 : 1));
            CHECK(find_point(&m, -0.5, y, 0) >= 0 && find_point(&m, 0.25, y, 0) >= 0);
            CHECK(m.points[0].separation == (ga2d_real)sep && m.points[1].separation == (ga2d_real)sep);
        }
}

/* Capsule A along x (core (-1, 0)..(1, 0), radius 1/4) at the origin;
   capsule B along y (core (0, -1)..(0, 1), radius 1/8) at (1/4, 1/2).
   The cores cross; the least push is B up by 1/2 (down 3/2, sideways 3/4
   or 5/4): separation -1/2 - 3/8, normal +y.  One point: B's lower core
   end (1/4, -1/2) is the deepest, its upper end is 3/2 above; midway
   between A's surface (y = 1/4) and B's (-1/2 - 1/8): y = -3/16.  Exact. */
static void crossed_capsules(void)
{
    ga2d_geometry a = capsule(-1, 0, 1, 0, 0.25), b = capsule(0, -1, 0, 1, 0.125);
    ga2d_transform xb = X(0.25, 0.5);
    ga2d_manifold m;
    if (collide(&a, X(0, 0), &b, xb, &m) == 1) {
        check_manifold_basics(&m, X(0, 0), xb);
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        check_point(&m, 0, 0.25, -0.1875, -0.875, 0);
    } else CHECK(!"one point");
    if (collide(&b, xb, &a, X(0, 0), &m) == 1) {
        CHECK(m.normal.x == 0 && m.normal.y == -1);
        check_point(&m, 0, 0.25, -0.1875, -0.875, 0);
    } else CHECK(!"one point, swapped");
}

/* A rounded box (half 1/2 x 1/4, radius 1/8: core half 3/8 x 1/8) at
   (1/4, 3/4 + g) on box A (half 1 x 1/2): its flat bottom g above A's
   top face.  Two points at the core's bottom corners' x, 1/4 -+ 3/8,
   midway at y = 1/2 + g/2, separation g; exact.  g = -3/16 sinks the core
   1/16 into A (the overlapping-core branch). */
static void rounded_box_on_a_box(void)
{
    const double gaps[4] = {-0.1875, -1.0 / 16, 0, 1.0 / 128};
    ga2d_polygon box = ga2d_polygon_box(1, (ga2d_real)0.5), rb = ga2d_polygon_rounded_box((ga2d_real)0.5, (ga2d_real)0.25, (ga2d_real)0.125);
    ga2d_geometry a = polygon(&box), b = polygon(&rb);
    int k;
    CHECK(rb.count == 4 && rb.radius == (ga2d_real)0.125 && rb.vertices[2].x == (ga2d_real)0.375 && rb.vertices[2].y == (ga2d_real)0.125);
    for (k = 0; k < 4; ++k) {
        double g = gaps[k], y = 0.5 + g / 2;
        ga2d_transform xb = X(0.25, 0.75 + g);
        ga2d_manifold m;
        if (collide(&a, X(0, 0), &b, xb, &m) != 2) {
            CHECK(!"two points");
            continue;
        }
        check_manifold_basics(&m, X(0, 0), xb);
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        CHECK(find_point(&m, -0.125, y, 0) >= 0 && find_point(&m, 0.625, y, 0) >= 0);
        CHECK(m.points[0].separation == (ga2d_real)g && m.points[1].separation == (ga2d_real)g);
    }
}

/* A segment (-1, 0)..(1, 0) at (1/2, 1/4) and a circle of radius 1/4
   above it at local x = 1/4: normal +y, separation g, midway y = 1/4 +
   g/2; below it, the normal is -y (a segment has two sides).  Exact.  Past
   its end (1, 0) by (3, 4)/16: the normal (0.6, 0.8), the end's feature,
   as circle_at_a_corner. */
static void circle_on_a_segment(void)
{
    const double g = 1.0 / 64;
    ga2d_geometry a = segment(-1, 0, 1, 0), b = circle(0, 0, 0.25), c = circle(1 + 3.0 / 16, 4.0 / 16, 5.0 / 16 - g),
                  p = circle(0, 0, 0);
    ga2d_transform xa = X(0.5, 0.25);
    ga2d_manifold m;
    if (collide(&a, xa, &b, X(0.75, 0.5 + g), &m) == 1) {
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        check_point(&m, 0, 0.75, 0.25 + g / 2, g, 0);
    } else CHECK(!"one point above");
    if (collide(&a, xa, &b, X(0.75, -g), &m) == 1) {
        CHECK(m.normal.x == 0 && m.normal.y == -1);
        check_point(&m, 0, 0.75, 0.25 - g / 2, g, 0);
    } else CHECK(!"one point below");
    if (collide(&a, xa, &c, xa, &m) == 1) {
        CHECK_NEAR(m.normal.x, 0.6, REAL_EPS);
        CHECK_NEAR(m.normal.y, 0.8, REAL_EPS);
        check_point(&m, 0, 1.5 + 0.6 * g / 2, 0.25 + 0.8 * g / 2, g, 2 * REAL_EPS);
        CHECK(m.points[0].id == (0x80u | 1u) << 8);
    } else CHECK(!"one point past the end");
    /* a point on the segment's line, 1/64 past its end (-1, 0): the end
       is nearest, the normal along the line, exact */
    if (collide(&a, xa, &p, X(0.5 - 1 - 1.0 / 64, 0.25), &m) == 1) {
        CHECK(m.normal.x == -1 && m.normal.y == 0);
        check_point(&m, 0, 0.5 - 1 - 1.0 / 128, 0.25, 1.0 / 64, 0);
        CHECK(m.points[0].id == (0x80u | 0u) << 8);
    } else CHECK(!"one point on the line past the end");
}

/* Rounded boxes (half 1/2, radius 1/8: core half 3/8), B at (3/4 + g,
   3/4 + g): the cores' corners (3/8, 3/8) and (3/8 + g, 3/8 + g) are
   (g, g) apart, farther than 0.1 slop along each axis (g = 1/256): two
   corners meet, one point at the true distance g sqrt2 along the
   diagonal (not a face's gap g), separation g sqrt2 - 1/4; the point
   midway between the arcs, equal radii: the corners' midpoint, exact.
   The length and the normalization round three times: 2 eps. */
static void rounded_corners_meet(void)
{
    const double g = 1.0 / 256;
    ga2d_polygon rb = ga2d_polygon_rounded_box((ga2d_real)0.5, (ga2d_real)0.5, (ga2d_real)0.125);
    ga2d_geometry a = polygon(&rb);
    ga2d_transform xb = X(0.75 + g, 0.75 + g);
    ga2d_manifold m;
    if (collide(&a, X(0, 0), &a, xb, &m) == 1) {
        check_manifold_basics(&m, X(0, 0), xb);
        CHECK_NEAR(m.normal.x, sqrt(0.5), 2 * REAL_EPS);
        CHECK_NEAR(m.normal.y, sqrt(0.5), 2 * REAL_EPS);
        check_point(&m, 0, 0.375 + g / 2, 0.375 + g / 2, g * sqrt(2.0) - 0.25, 2 * REAL_EPS);
        CHECK(m.points[0].id == (2u << 8 | 0u));
    } else CHECK(!"one point");
}

/* A rounded box (half 1/2, radius 1/8: core half 3/8) turned 45 degrees
   by q = (c, c), c = fl(sqrt 1/2), corner down over the segment (-1,
   0)..(1, 0).  Its lowest core corner (-3/8, -3/8) turns to (0,
   -2 fl(3c/8)) exactly (equal products, an exact sum); the centre at
   (1/8, fl(2 fl(3c/8) + h)) puts it at height h0 = centre.y - 2 fl(3c/8),
   exact (Sterbenz), within eps of h.  One point (the core's next corners
   are 0.53 higher, beyond the margin): normal +y, separation h0 - 1/8,
   midway between the segment and the arc's bottom: y = (h0 - 1/8)/2.
   Three roundings at most of values below 1: 2 eps.  h = -1/16 puts the
   core's corner through the segment. */
static void rounded_corner_on_a_segment(void)
{
    const double hs[3] = {0.125 + 1.0 / 128, 0.125 - 1.0 / 32, -1.0 / 16};
    ga2d_polygon rb = ga2d_polygon_rounded_box((ga2d_real)0.5, (ga2d_real)0.5, (ga2d_real)0.125);
    ga2d_geometry a = segment(-1, 0, 1, 0), b = polygon(&rb);
    ga2d_real c = (ga2d_real)0.70710678118654752, low = 2 * (c * (ga2d_real)0.375);
    int k;
    for (k = 0; k < 3; ++k) {
        ga2d_transform xb = ga2d_transform_make(ga2d_vec_make((ga2d_real)0.125, low + (ga2d_real)hs[k]), ga2d_rotor_identity());
        ga2d_manifold m;
        double h0;
        xb.q.c = xb.q.s = c;
        h0 = (double)xb.p.y - (double)low;
        CHECK_NEAR(h0, hs[k], REAL_EPS);
        if (collide(&a, X(0, 0), &b, xb, &m) != 1) {
            CHECK(!"one point");
            continue;
        }
        check_manifold_basics(&m, X(0, 0), xb);
        CHECK(m.normal.x == 0 && m.normal.y == 1);
        check_point(&m, 0, 0.125, (h0 - 0.125) / 2, h0 - 0.125, 2 * REAL_EPS);
    }
}

/* Units of 1/100 m: a circle and a capsule 1.5 units apart are inside the
   scaled margin of 2 units, beyond the unscaled 0.02 (exact values). */
static void scaled_margin(void)
{
    ga2d_geometry a = circle(0, 0, 50), b = capsule(0, -20, 0, 20, 25);
    ga2d_manifold m;
    CHECK(ga2d_collide_shapes_scaled(&a, X(0, 0), &b, X(76.5, 3), 100, &m) == 1);
    if (m.count == 1) CHECK(m.points[0].separation == (ga2d_real)1.5);
    CHECK(ga2d_collide_shapes(&a, X(0, 0), &b, X(76.5, 3), &m) == 0);
    CHECK(ga2d_collide_shapes_scaled(&a, X(0, 0), &b, X(77.5, 3), 100, &m) == 0);
}

/* Capsules (or segments) whose cores lie on one line, apart along it:
   their side normals do not separate them (SAT gap 0), their ends do.
   0.8 apart, or B tilted so that its near end is 3e-4 off A's line: no
   point.  Radius 1/8 end to end with the surfaces 1/128 apart: one point,
   normal +x, separation 1/128, midway between the caps at x = 1 + 1/8 +
   1/256 (dyadic: a few roundings of values below 2 at most, 2 eps).
   (Found as a header bug: the overlapping-core branch ran and clamped
   both clipped ends to B's near end, two points at -(radii).) */
static void collinear_apart(void)
{
    const double g = 1.0 / 128;
    ga2d_geometry a = capsule(0, 0, 1, 0, 0.1), b = capsule(2, 0, 3, 0, 0.1), bt = capsule(2, 0.0003, 3, 0.0007, 0.1),
                  s = segment(0, 0, 1, 0), t = segment(2, 0, 3, 0), c = capsule(0, 0, 1, 0, 0.125),
                  d = capsule(1.25 + g, 0, 2, 0, 0.125);
    ga2d_manifold m;
    CHECK(collide(&a, X(0, 0), &b, X(0, 0), &m) == 0);
    CHECK(collide(&a, X(0, 0), &bt, X(0, 0), &m) == 0);
    CHECK(collide(&s, X(0, 0), &t, X(0, 0), &m) == 0);
    CHECK(collide(&a, X(0, 0), &t, X(0, 0), &m) == 0);
    if (collide(&c, X(0, 0), &d, X(0, 0), &m) == 1) {
        CHECK_NEAR(m.normal.x, 1, 2 * REAL_EPS);
        CHECK_NEAR(m.normal.y, 0, 2 * REAL_EPS);
        check_point(&m, 0, 1.125 + g / 2, 0, g, 2 * REAL_EPS);
    } else CHECK(!"one point, end to end within the margin");
}

/* --------------------------------------------- placed cores, in double */
/* A shape's core placed in A's frame (world orientation, relative to A's
   origin), in double: n = 1 a point (circle), 2 a segment (capsule,
   segment; edge 0 runs v0 -> v1, edge 1 back), >= 3 a convex polygon;
   outward unit normals recomputed from the edges, and the radius. */
typedef struct core {
    int n;
    double x[MAXV], y[MAXV], nx[MAXV], ny[MAXV], r;
} core;

/* a shape's core points in its own frame, and its radius */
static int local_core(const ga2d_geometry *g, ga2d_vec *v, double *r)
{
    int i, n;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE:
        v[0] = g->as.circle.center;
        *r = (double)g->as.circle.radius;
        return 1;
    case GA2D_SHAPE_CAPSULE:
        v[0] = g->as.capsule.center1;
        v[1] = g->as.capsule.center2;
        *r = (double)g->as.capsule.radius;
        return 2;
    case GA2D_SHAPE_SEGMENT:
        v[0] = g->as.segment.point1;
        v[1] = g->as.segment.point2;
        *r = 0;
        return 2;
    default:
        n = g->as.polygon.count;
        for (i = 0; i < n; ++i) v[i] = g->as.polygon.vertices[i];
        *r = (double)g->as.polygon.radius;
        return n;
    }
}

/* the outward unit normals of a core's edges, from its points v in its
   own frame (differences of the inputs, exact to a rounding relative to
   the edge) turned by (c, s) */
static void core_normals(core *w, const ga2d_vec *v, double c, double s)
{
    int i;
    for (i = 0; w->n >= 2 && i < w->n; ++i) {
        int i2 = (i + 1) % w->n;
        double ex = (double)v[i2].x - (double)v[i].x, ey = (double)v[i2].y - (double)v[i].y, l = len2(ex, ey);
        w->nx[i] = (c * ey + s * ex) / l;
        w->ny[i] = (s * ey - c * ex) / l;
    }
}

/* g placed by x, relative to o, in double */
static void place(core *w, const ga2d_geometry *g, ga2d_transform x, ga2d_vec o)
{
    double c = (double)x.q.c, s = (double)x.q.s, px = (double)x.p.x - (double)o.x, py = (double)x.p.y - (double)o.y;
    ga2d_vec v[MAXV];
    int i;
    w->n = local_core(g, v, &w->r);
    for (i = 0; i < w->n; ++i) {
        double vx = (double)v[i].x, vy = (double)v[i].y;
        w->x[i] = px + (c * vx - s * vy);
        w->y[i] = py + (s * vx + c * vy);
    }
    core_normals(w, v, c, s);
}

/* the distance from p to the segment a-b, and the nearest point q */
static double pt_seg(double px, double py, double ax, double ay, double bx, double by, double *qx, double *qy)
{
    double ex = bx - ax, ey = by - ay, ee = ex * ex + ey * ey, t = ee > 0 ? ((px - ax) * ex + (py - ay) * ey) / ee : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    *qx = ax + t * ex;
    *qy = ay + t * ey;
    return len2(px - *qx, py - *qy);
}

/* edges of a core: a point's one edge has both ends at it, a segment's
   one edge is itself */
static int edge_count(const core *w) { return w->n < 3 ? 1 : w->n; }
static void edge_ends(const core *w, int k, double *e)
{
    int k2 = (k + 1) % w->n;
    e[0] = w->x[k];
    e[1] = w->y[k];
    e[2] = w->x[k2];
    e[3] = w->y[k2];
}

/* the length of face i of a core (n >= 2) */
static double face_len(const core *w, int i)
{
    int i2 = (i + 1) % w->n;
    return len2(w->x[i2] - w->x[i], w->y[i2] - w->y[i]);
}

static double orient(double ax, double ay, double bx, double by, double cx, double cy)
{
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/* distance between segments a and b (ends a[0..3], b[0..3]) and the two
   nearest points: 0 for a proper crossing, else the nearest of an end to
   the other segment */
static double seg_seg(const double *a, const double *b, double *pa, double *pb)
{
    double d1 = orient(a[0], a[1], a[2], a[3], b[0], b[1]), d2 = orient(a[0], a[1], a[2], a[3], b[2], b[3]);
    double d3 = orient(b[0], b[1], b[2], b[3], a[0], a[1]), d4 = orient(b[0], b[1], b[2], b[3], a[2], a[3]);
    double best, d, qx, qy;
    int k;
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
        double t = d3 / (d3 - d4);
        pa[0] = pb[0] = a[0] + t * (a[2] - a[0]);
        pa[1] = pb[1] = a[1] + t * (a[3] - a[1]);
        return 0;
    }
    best = 1e300;
    for (k = 0; k < 2; ++k) {
        d = pt_seg(a[2 * k], a[2 * k + 1], b[0], b[1], b[2], b[3], &qx, &qy);
        if (d < best) { best = d; pa[0] = a[2 * k]; pa[1] = a[2 * k + 1]; pb[0] = qx; pb[1] = qy; }
        d = pt_seg(b[2 * k], b[2 * k + 1], a[0], a[1], a[2], a[3], &qx, &qy);
        if (d < best) { best = d; pb[0] = b[2 * k]; pb[1] = b[2 * k + 1]; pa[0] = qx; pa[1] = qy; }
    }
    return best;
}

/* the distance between two cores' boundaries and its two points */
static double core_dist(const core *a, const core *b, double *pa, double *pb)
{
    double best = 1e300, ea[4], eb[4], qa[2] = {0, 0}, qb[2] = {0, 0}, d;
    int i, j;
    pa[0] = pa[1] = pb[0] = pb[1] = 0;
    for (i = 0; i < edge_count(a); ++i)
        for (j = 0; j < edge_count(b); ++j) {
            edge_ends(a, i, ea);
            edge_ends(b, j, eb);
            d = seg_seg(ea, eb, qa, qb);
            if (d < best) { best = d; pa[0] = qa[0]; pa[1] = qa[1]; pb[0] = qb[0]; pb[1] = qb[1]; }
        }
    return best;
}

/* strictly inside a polygon core */
static int inside(const core *w, double x, double y)
{
    int i;
    if (w->n < 3) return 0;
    for (i = 0; i < w->n; ++i)
        if (!(w->nx[i] * (x - w->x[i]) + w->ny[i] * (y - w->y[i]) < 0)) return 0;
    return 1;
}

/* the gap of face i of p over q: min over q's points of n_i.(v - p_i) */
static double face_gap(const core *p, int i, const core *q)
{
    double lo = 1e300;
    int j;
    for (j = 0; j < q->n; ++j) lo = dmin(lo, p->nx[i] * (q->x[j] - p->x[i]) + p->ny[i] * (q->y[j] - p->y[i]));
    return lo;
}

/* the SAT separation over p's faces (none for a point) */
static double sat(const core *p, const core *q)
{
    double best = -1e300;
    int i;
    for (i = 0; p->n >= 2 && i < p->n; ++i) best = dmax(best, face_gap(p, i, q));
    return best;
}

/* A two-point core's gap along its own line (how far q lies past either
   end); none for others.  With the faces' gaps, the full separating-axis
   set of two segments, parallel ones included. */
static double end_gap(const core *p, const core *q)
{
    double ex, ey, l, a0, a1, lo = 1e300, hi = -1e300;
    int j;
    if (p->n != 2) return -1e300;
    ex = p->x[1] - p->x[0];
    ey = p->y[1] - p->y[0];
    l = len2(ex, ey);
    a0 = (ex * p->x[0] + ey * p->y[0]) / l;
    a1 = (ex * p->x[1] + ey * p->y[1]) / l;
    for (j = 0; j < q->n; ++j) {
        double t = (ex * q->x[j] + ey * q->y[j]) / l;
        lo = dmin(lo, t);
        hi = dmax(hi, t);
    }
    return dmax(lo - a1, a0 - hi);
}

/* The signed distance between two cores: their distance when disjoint
   (no crossing edges, neither holding the other); overlapping, minus the
   penetration depth, the largest face gap over both (the Minkowski
   difference's edges are parallel to the cores' edges; checked against a
   sampled search in brute_force). */
static double core_sd(const core *a, const core *b)
{
    double pa[2], pb[2], d = core_dist(a, b, pa, pb);
    if ((d > 0 && !inside(a, b->x[0], b->y[0]) && !inside(b, a->x[0], a->y[0])) || (a->n < 2 && b->n < 2)) return d;
    return dmax(sat(a, b), sat(b, a));
}

/* a point's signed distance from a core (negative inside a polygon) */
static double sdist(const core *w, double x, double y)
{
    double best = 1e300, e[4], qx, qy;
    int k;
    for (k = 0; k < edge_count(w); ++k) {
        edge_ends(w, k, e);
        best = dmin(best, pt_seg(x, y, e[0], e[1], e[2], e[3], &qx, &qy));
    }
    return inside(w, x, y) ? -best : best;
}

/* ------------------------------------------------------- random pairs */
typedef struct pair {
    ga2d_geometry a, b;
    ga2d_transform xa, xb;
    core wa, wb;
    double R, rnd; /* the rounding scale (see the top) and RND = 32 eps R */
} pair;

static ga2d_real on_grid(double v) { return (ga2d_real)(floor(v / FAR_ULP + 0.5) * FAR_ULP); }

/* R: the farthest core point from either origin, plus both radii */
static void measure(pair *c)
{
    double bx = (double)c->xb.p.x - (double)c->xa.p.x, by = (double)c->xb.p.y - (double)c->xa.p.y;
    const core *w[2];
    int i, k;
    place(&c->wa, &c->a, c->xa, c->xa.p);
    place(&c->wb, &c->b, c->xb, c->xa.p);
    w[0] = &c->wa;
    w[1] = &c->wb;
    c->R = 0;
    for (k = 0; k < 2; ++k)
        for (i = 0; i < w[k]->n; ++i)
            c->R = dmax(c->R, dmax(len2(w[k]->x[i], w[k]->y[i]), len2(w[k]->x[i] - bx, w[k]->y[i] - by)));
    c->R += c->wa.r + c->wb.r;
    c->rnd = 32 * REAL_EPS * c->R;
}

/* the true signed distance between the two shapes */
static double true_sd(const pair *c) { return core_sd(&c->wa, &c->wb) - c->wa.r - c->wb.r; }

static ga2d_polygon random_polygon(test_rng *r, double size)
{
    ga2d_vec pts[12];
    ga2d_polygon p;
    for (;;) {
        int i, n = rng_int(r, 3, MAXV < 12 ? MAXV : 12);
        for (i = 0; i < n; ++i) {
            double t = rng_uniform(r, 0, 2 * PI), rad = size * rng_uniform(r, 0.4, 1);
            pts[i] = V(rad * cos(t), rad * sin(t));
        }
        if (ga2d_polygon_hull(pts, n, &p) == GA2D_OK) return p;
    }
}

/* a shape of a kind, about its body's origin (a circle's or capsule's
   centre a little off it) */
static ga2d_geometry random_shape(test_rng *r, int kind)
{
    double ox = rng_uniform(r, -0.2, 0.2), oy = rng_uniform(r, -0.2, 0.2), t = rng_uniform(r, 0, 2 * PI), h;
    ga2d_polygon p;
    switch (kind) {
    case K_CIRCLE: return circle(ox, oy, rng_uniform(r, 0.05, 0.6));
    case K_CAPSULE:
        h = rng_uniform(r, 0.1, 0.7);
        return capsule(ox - h * cos(t), oy - h * sin(t), ox + h * cos(t), oy + h * sin(t), rng_uniform(r, 0.05, 0.4));
    case K_SEGMENT:
        h = rng_uniform(r, 0.2, 1.2);
        return segment(ox - h * cos(t), oy - h * sin(t), ox + h * cos(t), oy + h * sin(t));
    case K_POLYGON: p = random_polygon(r, rng_uniform(r, 0.2, 1)); return polygon(&p);
    default:
        p = random_polygon(r, rng_uniform(r, 0.2, 0.8));
        p.radius = (ga2d_real)rng_uniform(r, 0.02, 0.3);
        return polygon(&p);
    }
}

static void centroid(const core *w, double *x, double *y)
{
    int i;
    *x = *y = 0;
    for (i = 0; i < w->n; ++i) {
        *x += w->x[i] / w->n;
        *y += w->y[i] / w->n;
    }
}

/* Two shapes placed at random: A anywhere in [-2, 2]^2, B's core
   centroid sent from A's along a random ray to where the true signed
   distance (convex along the ray, negative at its start where the
   centroids meet) reaches a target drawn from three equal classes:
   overlapping (2% to 90% of the start's depth), apart within the margin
   (0.001 .. 0.019) and beyond it (0.021 .. 0.1).  Positions on the grid of
   FAR_ULP (they translate by FAR_T exactly): moved by < 1e-3, so the
   class is only a tendency. */
static void aim(test_rng *r, pair *c, const double *rel)
{
    double kind = rng_uniform(r, 0, 3), ang = rng_uniform(r, 0, 2 * PI), lo = 0, hi = 4, target, ax, ay, bx, by, ox, oy;
    double px = rng_uniform(r, -2, 2), py = rng_uniform(r, -2, 2), qa = rng_uniform(r, -PI, PI), qb = rng_uniform(r, -PI, PI);
    int k;
    if (rel) {
        qb = qa + rel[0];
        ang = qa + rel[1];
    }
    c->xa = ga2d_transform_make(ga2d_vec_make(on_grid(px), on_grid(py)), ga2d_rotor_from_angle((ga2d_real)qa));
    c->xb = ga2d_transform_make(c->xa.p, rel && rel[0] == 0 ? c->xa.q : ga2d_rotor_from_angle((ga2d_real)qb));
    measure(c);
    centroid(&c->wa, &ax, &ay);
    centroid(&c->wb, &bx, &by);
    ox = (double)c->xa.p.x + ax - bx;
    oy = (double)c->xa.p.y + ay - by;
    c->xb.p = V(ox, oy);
    measure(c);
    target = kind < 1 ? true_sd(c) * rng_uniform(r, 0.02, 0.9)
                      : (kind < 2 ? rng_uniform(r, 0.001, 0.019) : rng_uniform(r, 0.021, 0.1));
    for (k = 0; k < 40; ++k) {
        double t = (lo + hi) / 2;
        c->xb.p = V(ox + t * cos(ang), oy + t * sin(ang));
        measure(c);
        if (true_sd(c) < target) lo = t;
        else hi = t;
    }
    c->xb.p = ga2d_vec_make(on_grid(ox + hi * cos(ang)), on_grid(oy + hi * sin(ang)));
    measure(c);
}

static void random_pair(test_rng *r, int ka, int kb, pair *c)
{
    c->a = random_shape(r, ka);
    c->b = random_shape(r, kb);
    aim(r, c, NULL);
}

/* A rounded (or, two times in five, sharp) box and a box or a capsule
   along x, turned alike: their faces are parallel, so A's and B's SAT
   gaps tie along the axis that separates them most */
static void parallel_pair(test_rng *r, pair *c)
{
    double hw = rng_uniform(r, 0.2, 0.8), hh = rng_uniform(r, 0.2, 0.8), rr = rng_uniform(r, -0.1, 0.15);
    double w2 = rng_uniform(r, 0.2, 0.8), h2 = rng_uniform(r, 0.2, 0.8), pick = rng_uniform(r, 0, 1);
    ga2d_polygon p = ga2d_polygon_rounded_box((ga2d_real)hw, (ga2d_real)hh, (ga2d_real)dmax(rr, 0)),
                 q = ga2d_polygon_box((ga2d_real)w2, (ga2d_real)h2);
    double rel[2];
    rel[0] = 0;
    rel[1] = rng_uniform(r, 0, 2 * PI);
    c->a = polygon(&p);
    c->b = pick < 0.5 ? polygon(&q) : capsule(-w2, 0, w2, 0, h2 / 4);
    aim(r, c, rel);
}

/* Capsules or segments on nearly one line (B turned by under 2e-3 rad),
   B sent along A's axis, a little off it: end to end, where the sides'
   normals barely separate them and the ends do */
static void collinear_pair(test_rng *r, pair *c)
{
    double h1 = rng_uniform(r, 0.1, 0.7), h2 = rng_uniform(r, 0.1, 0.7), r1 = rng_uniform(r, -0.1, 0.3),
           r2 = rng_uniform(r, -0.1, 0.3), rel[2];
    rel[0] = rng_uniform(r, -2e-3, 2e-3);
    rel[1] = rng_uniform(r, -2e-3, 2e-3) + (rng_uniform(r, 0, 1) < 0.5 ? 0 : PI);
    c->a = r1 > 0 ? capsule(-h1, 0, h1, 0, r1) : segment(-h1, 0, h1, 0);
    c->b = r2 > 0 ? capsule(-h2, 0, h2, 0, r2) : segment(-h2, 0, h2, 0);
    aim(r, c, rel);
}

/* pair number i of kind k (NKINDS: a parallel pair, NKINDS + 1: a
   collinear one): the kinds alternate as A and B */
static void kind_pair(test_rng *r, int k, int i, pair *c)
{
    if (k < NKINDS) {
        random_pair(r, KINDS[k][i & 1], KINDS[k][1 - (i & 1)], c);
        return;
    }
    if (k == NKINDS) parallel_pair(r, c);
    else collinear_pair(r, c);
    if (i & 1) {
        ga2d_geometry g = c->a;
        ga2d_transform x = c->xa;
        c->a = c->b;
        c->xa = c->xb;
        c->b = g;
        c->xb = x;
        measure(c);
    }
}

static int has_circle(const pair *c) { return c->wa.n == 1 || c->wb.n == 1; }

/* ------------------------------------------- a circle against anything */
/* The exact answer for a pair with a circle: the other shape's core h (A's
   circle when both are), the circle's centre (cx, cy) and radius rc; d, the
   centre's signed distance from h's core; q, its nearest core point (the
   foot on the nearest face when inside); u, the unit direction from q to
   the centre (the face's normal when inside or on a segment's line);
   feature, the library's name for q's feature (a face, or 0x80 | a
   vertex); flip, the circle is A (B's feature names the point); sure, 0
   when a rounding (2 RND) could change the feature: the centre that near a
   region's border, a segment's line or two equally deep faces. */
typedef struct circle_truth {
    const core *h;
    double cx, cy, rc, d, qx, qy, ux, uy;
    int feature, flip, sure, vertex;
} circle_truth;

static void truth_of(const pair *c, circle_truth *t)
{
    double tol = 2 * c->rnd, e[4];
    const core *h;
    int i, k;
    t->flip = c->wa.n == 1 && c->wb.n >= 2;
    h = t->h = t->flip ? &c->wb : &c->wa;
    t->cx = t->flip ? c->wa.x[0] : c->wb.x[0];
    t->cy = t->flip ? c->wa.y[0] : c->wb.y[0];
    t->rc = t->flip ? c->wa.r : c->wb.r;
    t->feature = 0;
    t->vertex = 1;
    if (h->n == 1) {
        t->qx = h->x[0];
        t->qy = h->y[0];
        t->d = len2(t->cx - t->qx, t->cy - t->qy);
        t->sure = t->d > tol;
    } else if (inside(h, t->cx, t->cy)) {
        double best = -1e300, second = -1e300;
        for (i = 0; i < h->n; ++i) {
            double s = h->nx[i] * (t->cx - h->x[i]) + h->ny[i] * (t->cy - h->y[i]);
            if (s > best) { second = best; best = s; t->feature = i; }
            else second = dmax(second, s);
        }
        t->d = best;
        t->ux = h->nx[t->feature];
        t->uy = h->ny[t->feature];
        t->qx = t->cx - t->ux * best;
        t->qy = t->cy - t->uy * best;
        t->sure = best - second > tol;
        t->vertex = 0;
        return;
    } else {
        double best = 1e300, qx, qy, tau = 0, len = 0;
        for (i = k = 0; i < edge_count(h); ++i) {
            double dd;
            edge_ends(h, i, e);
            dd = pt_seg(t->cx, t->cy, e[0], e[1], e[2], e[3], &qx, &qy);
            if (dd < best) {
                best = dd;
                k = i;
                t->qx = qx;
                t->qy = qy;
                len = len2(e[2] - e[0], e[3] - e[1]);
                tau = ((t->cx - e[0]) * (e[2] - e[0]) + (t->cy - e[1]) * (e[3] - e[1])) / len;
            }
        }
        t->d = best;
        if (tau > 0 && tau < len) {
            /* a segment's side: the face whose normal faces the centre */
            t->feature = h->n == 2 && h->nx[0] * (t->cx - h->x[0]) + h->ny[0] * (t->cy - h->y[0]) < 0 ? 1 : k;
            t->vertex = 0;
            t->sure = dmin(tau, len - tau) > tol && best > tol;
        } else {
            /* a vertex: the centre lies beyond both of its edges' ends */
            int v = tau <= 0 ? k : (k + 1) % h->n, p = (v + h->n - 1) % h->n, v2 = (v + 1) % h->n;
            double ex = h->x[v2] - h->x[v], ey = h->y[v2] - h->y[v], fx = h->x[v] - h->x[p], fy = h->y[v] - h->y[p];
            double past = dmin(-((t->cx - h->x[v]) * ex + (t->cy - h->y[v]) * ey) / len2(ex, ey),
                               ((t->cx - h->x[v]) * fx + (t->cy - h->y[v]) * fy) / len2(fx, fy));
            t->feature = 0x80 | v;
            t->sure = past > tol;
        }
    }
    /* a face's normal, or the direction from the nearest point */
    if (!t->vertex) {
        t->ux = h->nx[t->feature];
        t->uy = h->ny[t->feature];
    } else if (t->d > 0) {
        t->ux = (t->cx - t->qx) / t->d;
        t->uy = (t->cy - t->qy) / t->d;
    } else {
        t->ux = 1;
        t->uy = 0;
    }
}

/* The normal's tolerance: a direction between two points d apart, each
   within RND, errs by 2 RND / d; a face normal by 16 eps, as at the top,
   or, for a capsule's or segment's side placed in A's frame (its normal
   is taken from its ends there, each within 6 eps R), by 12 eps R / L
   < RND / L more, L the face's length. */
static double face_tn(const pair *c, const core *w, int i) { return 16 * REAL_EPS + c->rnd / face_len(w, i); }

static double truth_tn(const pair *c, const circle_truth *t)
{
    if (t->vertex) return 16 * REAL_EPS + 2 * c->rnd / fabs(t->d);
    return face_tn(c, t->h, t->feature);
}

/* The manifold of a pair with a circle against the exact answer: one
   point within the margin (none beyond), the true signed distance (RND),
   the point on both surfaces (each the midpoint -+ n s/2: 2 RND, and
   where the normal errs by tn, a vertex's arc is missed by r tn^2 / 2 at
   most).  When sure: the normal, the feature, and the point midway
   between q + u r_h and c - u r_c (the normal's error tn times the
   lengths |d| / 2 and |r_h - r_c| / 2 it multiplies).  Returns the class:
   0 overlapping, 1 within the margin, 2 beyond, -1 on a border. */
static int check_circle_pair(const pair *c, const ga2d_manifold *m)
{
    circle_truth t;
    double P, tn, nx, ny, s, x, y;
    const core *h;
    truth_of(c, &t);
    h = t.h;
    P = t.d - h->r - t.rc;
    tn = truth_tn(c, &t);
    if (fabs(P - MARGIN) > c->rnd) CHECK(m->count == (P <= MARGIN));
    if (m->count == 1) {
        double sg = t.flip ? -1 : 1, ph, pc, ex, ey;
        CHECK_NEAR(m->points[0].separation, P, c->rnd);
        nx = (double)m->normal.x;
        ny = (double)m->normal.y;
        s = (double)m->points[0].separation;
        x = (double)m->points[0].point.x - (double)c->xa.p.x;
        y = (double)m->points[0].point.y - (double)c->xa.p.y;
        ph = sdist(h, x - sg * nx * s / 2, y - sg * ny * s / 2) - h->r;
        pc = len2(x + sg * nx * s / 2 - t.cx, y + sg * ny * s / 2 - t.cy) - t.rc;
        CHECK(fabs(ph) <= 2 * c->rnd + h->r * tn * tn / 2 && fabs(pc) <= 2 * c->rnd);
        if (t.sure) {
            uint32_t id = h->n == 1 ? 0u : (t.flip ? 1u << 16 | (uint32_t)t.feature : (uint32_t)t.feature << 8);
            CHECK_NEAR(nx, sg * t.ux, tn);
            CHECK_NEAR(ny, sg * t.uy, tn);
            CHECK(m->points[0].id == id);
            ex = (t.qx + t.cx) / 2 + t.ux * (h->r - t.rc) / 2;
            ey = (t.qy + t.cy) / 2 + t.uy * (h->r - t.rc) / 2;
            CHECK_NEAR(x, ex, 2 * c->rnd + (fabs(t.d) + fabs(h->r - t.rc)) / 2 * tn);
            CHECK_NEAR(y, ey, 2 * c->rnd + (fabs(t.d) + fabs(h->r - t.rc)) / 2 * tn);
        }
    }
    return P < -c->rnd ? 0 : (P > c->rnd && P < MARGIN - c->rnd ? 1 : (P > MARGIN + c->rnd ? 2 : -1));
}

/* --------------------------------------------------- two hulls (no circle) */
/* The face the manifold's normal is (within face_tn): face i of A
   (*flip = 0) or of B with normal -normal (*flip = 1), the side the id's
   flip bit names tried first (parallel faces: a segment's or capsule's
   match both); -1 for none (two vertices). */
static int ref_face(const pair *c, const ga2d_manifold *m, int *flip)
{
    double nx = (double)m->normal.x, ny = (double)m->normal.y;
    int s, i, side = m->count > 0 && (m->points[0].id >> 16 & 1u);
    for (s = 0; s < 2; ++s) {
        int f = s ? !side : side;
        const core *w = f ? &c->wb : &c->wa;
        double sg = f ? -1 : 1;
        for (i = 0; i < w->n; ++i)
            if (len2(nx - sg * w->nx[i], ny - sg * w->ny[i]) <= face_tn(c, w, i)) { *flip = f; return i; }
    }
    return -1;
}

/* Is the deepest point of inc below face i of ref inside that face's slab?
   1: inside, by more than rnd; -1: outside by more; 0: too close to tell
   (ties in depth count as inside if any is).  *gap: the face's gap. */
static int deepest_in_slab(const core *ref, int i, const core *inc, double rnd, double *gap)
{
    int j, i2 = (i + 1) % ref->n, best = -2;
    double tx = -ref->ny[i], ty = ref->nx[i];
    double len = tx * (ref->x[i2] - ref->x[i]) + ty * (ref->y[i2] - ref->y[i]);
    *gap = face_gap(ref, i, inc);
    for (j = 0; j < inc->n; ++j) {
        double dx = inc->x[j] - ref->x[i], dy = inc->y[j] - ref->y[i], u = tx * dx + ty * dy;
        int st = u > rnd && u < len - rnd ? 1 : (u < -rnd || u > len + rnd ? -1 : 0);
        if (ref->nx[i] * dx + ref->ny[i] * dy <= *gap + rnd) best = st > best ? st : best;
    }
    return best;
}

/* Each point lies midway between the surfaces: p - n s/2 on A's, p + n s/2
   on B's, to 2 RND.  On the reference side that point is the incident
   core point's foot on the face, lifted by the radius: on the surface,
   or past the face's end by the overhang the closest-feature branch
   allows (<= HYST), which only moves it out.  On the incident side it is
   the incident core point v less n r_inc: within r_inc of v, and at least
   r_inc cos(theta) out of the incident edge's line (theta: that edge's
   normal from -n; the incident edge is the most opposed one).  Two
   vertices: both exactly on.  Returns the number of points off. */
static int off_surface(const pair *c, const ga2d_manifold *m, int face, int flip)
{
    double nx = (double)m->normal.x, ny = (double)m->normal.y, tol = 2 * c->rnd, ct = -1;
    const core *inc = flip ? &c->wa : &c->wb;
    int k, j, bad = 0;
    for (j = 0; j < inc->n; ++j) ct = dmax(ct, (flip ? 1 : -1) * (nx * inc->nx[j] + ny * inc->ny[j]));
    for (k = 0; k < m->count; ++k) {
        const ga2d_manifold_point *p = &m->points[k];
        double s = (double)p->separation;
        double x = (double)p->point.x - (double)c->xa.p.x, y = (double)p->point.y - (double)c->xa.p.y;
        double ea = sdist(&c->wa, x - nx * s / 2, y - ny * s / 2) - c->wa.r;
        double eb = sdist(&c->wb, x + nx * s / 2, y + ny * s / 2) - c->wb.r;
        double er = flip ? eb : ea, ei = flip ? ea : eb;
        if (face < 0) bad += fabs(ea) > tol || fabs(eb) > tol;
        else bad += er < -tol || er > HYST + tol || ei > tol || ei < -inc->r * (1 - ct) - tol;
    }
    return bad;
}

/* The brute-force separation of two cores, independent of any face: the
   largest over unit directions of min_b d.b - max_a d.a (as in
   test_collide.c): each term is Lipschitz in the angle with constant
   <= diam <= 2R, so the true maximum lies within R dt of the best sample
   and the cells near it, resampled BF_M times, bound it from below within
   *err = R dt / BF_M. */
#define BF_N 1024
#define BF_M 32
static double gap_dir(const pair *c, double t)
{
    double dx = cos(t), dy = sin(t), lo = 1e300, hi = -1e300;
    int j;
    for (j = 0; j < c->wb.n; ++j) lo = dmin(lo, dx * c->wb.x[j] + dy * c->wb.y[j]);
    for (j = 0; j < c->wa.n; ++j) hi = dmax(hi, dx * c->wa.x[j] + dy * c->wa.y[j]);
    return lo - hi;
}

static double brute_separation(const pair *c, double *err)
{
    double g[BF_N], dt = 2 * PI / BF_N, best = -1e300, refined;
    int i, k;
    for (i = 0; i < BF_N; ++i) best = dmax(best, g[i] = gap_dir(c, i * dt));
    refined = best;
    for (i = 0; i < BF_N; ++i)
        if (g[i] >= best - c->R * dt)
            for (k = 0; k < BF_M; ++k) refined = dmax(refined, gap_dir(c, i * dt - dt / 2 + (k + 0.5) * dt / BF_M));
    *err = c->R * dt / BF_M;
    return refined;
}

/* The manifold of two hulls against the exact answer (as brute_force in
   test_collide.c, the cores' values less the radii):
   - none beyond the margin, at least one within it;
   - the SAT branch (the cores' SAT gap top, over their faces and a
     two-point core's own line, below 0.1 slop): a face is the
     reference, its gap trailing top by <= HYST (the hysteresis);
   - the closest-feature branch (top above 0.1 slop): two vertices give
     one point at the true distance along the true direction (the
     cores' nearest points); a face's gap is the cores' distance within
     HYST (the tolerance for a face to count as facing);
   - a face: every point lies on the incident core, at or above the face's
     gap; with the deepest incident point inside the face's slab, the
     deepest separation is that gap less the radii, and it is the true
     signed distance when that face is the best axis: the cores apart (the
     deepest point's foot is on the face, so the distance is at most its
     height, and at least any face's gap), or overlapping with A's and B's
     SAT gaps more than HYST apart.
   Returns the class as check_circle_pair; *exact counts the last case. */
static int check_hull_pair(const pair *c, const ga2d_manifold *m, int *exact)
{
    double P = true_sd(c), Dc = core_sd(&c->wa, &c->wb), rsum = c->wa.r + c->wb.r, tol = 2 * c->rnd;
    double sa = sat(&c->wa, &c->wb), sb = sat(&c->wb, &c->wa), s = min_sep(m), gap = 0;
    double top = dmax(dmax(sa, sb), dmax(end_gap(&c->wa, &c->wb), end_gap(&c->wb, &c->wa)));
    int flip = 0, face = m->count ? ref_face(c, m, &flip) : -1, st = 0;
    if (face >= 0)
        st = flip ? deepest_in_slab(&c->wb, face, &c->wa, c->rnd, &gap) : deepest_in_slab(&c->wa, face, &c->wb, c->rnd, &gap);
    CHECK(off_surface(c, m, face, flip) == 0);
    if (P - tol > MARGIN) CHECK(m->count == 0);
    if (P + tol < MARGIN) CHECK(m->count >= 1);
    if (Dc < 0) {
        /* the reference: the SAT depth against a search over directions */
        double err, B = brute_separation(c, &err);
        CHECK(Dc >= B - tol && Dc <= B + err + tol);
    }
    if (m->count) {
        if (top < HYST - tol) {
            CHECK(face >= 0);
            if (face >= 0) CHECK(gap >= top - HYST - tol && gap <= top + tol);
        } else if (top > HYST + tol) {
            if (face < 0) {
                double pa[2], pb[2], D = core_dist(&c->wa, &c->wb, pa, pb), tn = 16 * REAL_EPS + 2 * c->rnd / D;
                CHECK(m->count == 1);
                CHECK_NEAR(s, P, tol);
                CHECK_NEAR(m->normal.x, (pb[0] - pa[0]) / D, tn);
                CHECK_NEAR(m->normal.y, (pb[1] - pa[1]) / D, tn);
            } else CHECK(gap >= Dc - HYST - tol && gap <= Dc + tol);
        }
        if (face >= 0) {
            CHECK(s >= gap - rsum - tol);
            if (st == 1) CHECK_NEAR(s, gap - rsum, tol);
            if (st == 1 && (top > HYST + tol || (Dc < -tol && fabs(sa - sb) > HYST + tol))) {
                ++*exact;
                CHECK_NEAR(s, P, tol);
            }
        }
    }
    return P < -c->rnd ? 0 : (P > c->rnd && P < MARGIN - c->rnd ? 1 : (P > MARGIN + c->rnd ? 2 : -1));
}

/* Random pairs of every kind: the manifold against the exact answer
   (check_circle_pair, check_hull_pair).  Each kind must see each class. */
static void brute_force(void)
{
    test_rng rng = {0x5C011DE};
    int k, i, exact = 0;
    for (k = 0; k < NKINDS + 2; ++k) {
        int cls[3] = {0, 0, 0};
        for (i = 0; i < SHAPE_PAIRS; ++i) {
            pair c;
            ga2d_manifold m;
            int cl;
            kind_pair(&rng, k, i, &c);
            collide(&c.a, c.xa, &c.b, c.xb, &m);
            check_manifold_basics(&m, c.xa, c.xb);
            cl = has_circle(&c) ? check_circle_pair(&c, &m) : check_hull_pair(&c, &m, &exact);
            if (cl >= 0) ++cls[cl];
        }
        if (!(cls[0] > SHAPE_PAIRS / 5 && cls[1] > SHAPE_PAIRS / 5 && cls[2] > SHAPE_PAIRS / 5))
            test_fail(__FILE__, __LINE__, "kind %d: classes %d %d %d", k, cls[0], cls[1], cls[2]);
    }
    CHECK(exact > SHAPE_PAIRS);
}

/* the normal's tolerance for a pair's manifold: a circle pair's as its
   truth says; for hulls a face normal's face_tn, two vertices' direction
   16 eps + 2 RND / D (each end within RND, D apart) */
static double normal_tol(const pair *c, const ga2d_manifold *m)
{
    int flip = 0, face;
    if (has_circle(c)) {
        circle_truth t;
        truth_of(c, &t);
        return truth_tn(c, &t);
    }
    if ((face = ref_face(c, m, &flip)) >= 0) return face_tn(c, flip ? &c->wb : &c->wa, face);
    return 16 * REAL_EPS + 2 * c->rnd / dmax(core_sd(&c->wa, &c->wb), 0);
}

/* id of the same features seen from the other side: flip bit toggled, A's
   and B's feature bytes exchanged */
static uint32_t swap_id(uint32_t id)
{
    return ((id ^ 0x10000u) & 0x10000u) | ((id & 0xFFu) << 8) | ((id >> 8) & 0xFFu);
}

/* collide(A, B) and collide(B, A).  With a circle: the same point, one
   computation in two frames: the normal negated (each within tn of the
   truth), the same separation and point (2 RND, plus the rounding of
   xa.p + anchor), the id's feature bytes swapped (two circles: 0 both
   ways, so the flip bit only where a shape's feature is named).  Two
   hulls, as test_collide.c: when the cores' SAT gaps of A's and B's faces
   differ by more than HYST, both calls take the same reference, and
   agree as above with ids swapped (two vertices: the flip bit 0 both
   ways); otherwise each keeps its own first shape's face, and their
   deepest separations (the two face gaps, less the radii) differ by
   <= HYST.  Pairs with a value on the margin are skipped (either count is
   right there). */
static void symmetry(void)
{
    test_rng rng = {0x5133};
    int k, i, j, same = 0, ambiguous = 0;
    for (k = 0; k < NKINDS + 2; ++k)
        for (i = 0; i < SHAPE_PAIRS; ++i) {
            pair c;
            ga2d_manifold m1, m2;
            double sa, sb, rsum, tn, tp;
            int fl1 = 0, circ;
            kind_pair(&rng, k, i, &c);
            collide(&c.a, c.xa, &c.b, c.xb, &m1);
            collide(&c.b, c.xb, &c.a, c.xa, &m2);
            circ = has_circle(&c);
            rsum = c.wa.r + c.wb.r;
            sa = circ ? true_sd(&c) + rsum : sat(&c.wa, &c.wb);
            sb = circ ? sa : sat(&c.wb, &c.wa);
            if (dmin(dmin(fabs(sa - rsum - MARGIN), fabs(sb - rsum - MARGIN)),
                     dmin(fabs(true_sd(&c) - MARGIN), dmin(fabs(min_sep(&m1) - MARGIN), fabs(min_sep(&m2) - MARGIN)))) <
                2 * c.rnd)
                continue;
            CHECK((m1.count == 0) == (m2.count == 0));
            if (!m1.count || !m2.count) continue;
            if (circ || fabs(sa - sb) > HYST + 2 * c.rnd) {
                int vv = circ || ref_face(&c, &m1, &fl1) < 0;
                circle_truth t;
                ++same;
                CHECK(m1.count == m2.count);
                if (m1.count != m2.count) continue;
                tn = normal_tol(&c, &m1);
                tp = 2 * c.rnd + 4 * REAL_EPS * (fabs((double)c.xa.p.x) + fabs((double)c.xa.p.y) + fabs((double)c.xb.p.x) +
                                                 fabs((double)c.xb.p.y));
                if (circ) {
                    truth_of(&c, &t);
                    tp += (fabs(t.d) + fabs(t.h->r - t.rc)) / 2 * tn;
                }
                CHECK_NEAR(m1.normal.x, -(double)m2.normal.x, 2 * tn);
                CHECK_NEAR(m1.normal.y, -(double)m2.normal.y, 2 * tn);
                for (j = 0; j < m1.count; ++j) {
                    if (vv) CHECK((m2.points[j].id & 0xFFFFu) == (swap_id(m1.points[j].id) & 0xFFFFu));
                    else CHECK(m2.points[j].id == swap_id(m1.points[j].id));
                    CHECK_NEAR(m1.points[j].separation, m2.points[j].separation, 2 * c.rnd);
                    CHECK_NEAR(m1.points[j].point.x, m2.points[j].point.x, tp);
                    CHECK_NEAR(m1.points[j].point.y, m2.points[j].point.y, tp);
                }
                if (circ && c.wa.n != c.wb.n) CHECK(m2.points[0].id == swap_id(m1.points[0].id));
            } else {
                ++ambiguous;
                CHECK_NEAR(min_sep(&m1), min_sep(&m2), HYST + 2 * c.rnd);
            }
        }
    CHECK(same > (NKINDS + 2) * SHAPE_PAIRS / 2 && ambiguous > 10);
}

/* g placed by x as a naive world-frame collider would: in ga2d_real
   about the world origin (each coordinate rounded to T's ulp), then taken
   relative to o in double */
static void place_naive(core *w, const ga2d_geometry *g, ga2d_transform x, ga2d_vec o)
{
    ga2d_vec v[MAXV];
    int i;
    w->n = local_core(g, v, &w->r);
    for (i = 0; i < w->n; ++i) {
        ga2d_vec p = ga2d_transform_apply(x, v[i]);
        w->x[i] = (double)p.x - (double)o.x;
        w->y[i] = (double)p.y - (double)o.y;
    }
    core_normals(w, v, (double)x.q.c, (double)x.q.s);
}

/* Both transforms moved by T = (FAR_T, -FAR_T): positions are on the grid
   of T's ulp, so the moved ones are exact and the configuration the same.
   The library subtracts the positions first (exactly), so each run is
   within the error model of the exact answer, independent of T: the same
   count (pairs on the margin skipped), the same separations and anchors
   (RND), normals (2 tn), ids, and points that differ by T up to their
   rounding to T's ulp.  A naive world-frame signed distance (the cores
   rounded to T's ulp: eps T / 2 per coordinate) errs by ~eps T: shown to
   exceed the bound ten times over. */
static void far_from_origin(void)
{
    test_rng rng = {0xFA5};
    int k, i, j, n = 0;
    double worst_rnd = 0, naive_err = 0;
    for (k = 0; k < NKINDS + 2; ++k)
        for (i = 0; i < SHAPE_PAIRS; ++i) {
            pair c, f;
            ga2d_manifold m0, m1;
            core na, nb;
            double tn;
            kind_pair(&rng, k, i, &c);
            f = c;
            f.xa.p = V((double)c.xa.p.x + FAR_T, (double)c.xa.p.y - FAR_T);
            f.xb.p = V((double)c.xb.p.x + FAR_T, (double)c.xb.p.y - FAR_T);
            CHECK((double)f.xa.p.x - FAR_T == (double)c.xa.p.x && (double)f.xa.p.y + FAR_T == (double)c.xa.p.y);
            CHECK((double)f.xb.p.x - FAR_T == (double)c.xb.p.x && (double)f.xb.p.y + FAR_T == (double)c.xb.p.y);
            collide(&c.a, c.xa, &c.b, c.xb, &m0);
            collide(&f.a, f.xa, &f.b, f.xb, &m1);
            check_manifold_basics(&m1, f.xa, f.xb);
            worst_rnd = dmax(worst_rnd, c.rnd);
            place_naive(&na, &f.a, f.xa, f.xa.p);
            place_naive(&nb, &f.b, f.xb, f.xa.p);
            naive_err = dmax(naive_err, fabs(core_sd(&na, &nb) - core_sd(&c.wa, &c.wb)));
            if (dmin(fabs(true_sd(&c) - MARGIN), dmin(fabs(min_sep(&m0) - MARGIN), fabs(min_sep(&m1) - MARGIN))) < 2 * c.rnd)
                continue;
            CHECK(m0.count == m1.count);
            if (m0.count != m1.count) continue;
            n += m0.count > 0;
            tn = m0.count ? normal_tol(&c, &m0) : 0;
            if (m0.count) {
                CHECK_NEAR(m0.normal.x, m1.normal.x, 2 * tn);
                CHECK_NEAR(m0.normal.y, m1.normal.y, 2 * tn);
            }
            for (j = 0; j < m0.count; ++j) {
                CHECK(m0.points[j].id == m1.points[j].id);
                CHECK_NEAR(m0.points[j].separation, m1.points[j].separation, c.rnd);
                CHECK_NEAR(m0.points[j].anchor_a.x, m1.points[j].anchor_a.x, c.rnd);
                CHECK_NEAR(m0.points[j].anchor_a.y, m1.points[j].anchor_a.y, c.rnd);
                CHECK_NEAR(m0.points[j].anchor_b.x, m1.points[j].anchor_b.x, c.rnd);
                CHECK_NEAR(m0.points[j].anchor_b.y, m1.points[j].anchor_b.y, c.rnd);
                CHECK_NEAR((double)m1.points[j].point.x - FAR_T, m0.points[j].point.x, c.rnd + FAR_ULP);
                CHECK_NEAR((double)m1.points[j].point.y + FAR_T, m0.points[j].point.y, c.rnd + FAR_ULP);
            }
        }
    CHECK(n > (NKINDS + 2) * SHAPE_PAIRS / 2);
    CHECK(naive_err > 10 * worst_rnd);
}

/* B nudged by 1e-4: a contact that keeps its features keeps its ids.
   With a circle, the features are known exactly (truth_of, in double):
   where both placements name the same one, surely, the ids must be equal
   (and the contact comparable).  Two hulls, as test_collide.c: features
   change only where a discrete choice flips, within ~1e-4 of its
   threshold; comparable: the same count, the same kind of contact (a
   face, or two vertices) and a face normal turned by < 1e-3 (a face
   normal does not turn at all under a translation).  At least 90% of the
   contacts must be comparable. */
static void ids_under_nudge(void)
{
    test_rng rng = {0x1D5};
    int k, i, j, contacts = 0, comparable = 0;
    for (k = 0; k < NKINDS + 2; ++k)
        for (i = 0; i < SHAPE_PAIRS; ++i) {
            pair c, d;
            ga2d_manifold m0, m1;
            double t;
            int f0 = 0, f1 = 0;
            kind_pair(&rng, k, i, &c);
            t = rng_uniform(&rng, 0, 2 * PI);
            if (!collide(&c.a, c.xa, &c.b, c.xb, &m0)) continue;
            ++contacts;
            d = c;
            d.xb.p = V((double)c.xb.p.x + 1e-4 * cos(t), (double)c.xb.p.y + 1e-4 * sin(t));
            measure(&d);
            collide(&d.a, d.xa, &d.b, d.xb, &m1);
            if (has_circle(&c)) {
                circle_truth t0, t1;
                truth_of(&c, &t0);
                truth_of(&d, &t1);
                if (!(t0.sure && t1.sure && t0.feature == t1.feature) || m1.count != 1) continue;
                ++comparable;
                CHECK(m1.points[0].id == m0.points[0].id);
                continue;
            }
            if (m1.count != m0.count || (ref_face(&c, &m0, &f0) < 0) != (ref_face(&d, &m1, &f1) < 0) ||
                (ref_face(&c, &m0, &f0) >= 0 &&
                 len2((double)m1.normal.x - (double)m0.normal.x, (double)m1.normal.y - (double)m0.normal.y) >= 1e-3))
                continue;
            ++comparable;
            for (j = 0; j < m0.count; ++j)
                CHECK(m1.points[j].id == m0.points[j].id || (m0.count == 2 && m1.points[1 - j].id == m0.points[j].id));
        }
    CHECK(comparable >= contacts * 9 / 10 && contacts > (NKINDS + 2) * SHAPE_PAIRS / 2);
}

/* ------------------------------------------------------- bad input */
/* Bad input: a negative -GA2D_ERR_*, and *out not written (either order of
   the shapes, scaled or not). */
static void expect_refused(const ga2d_geometry *a, ga2d_transform xa, const ga2d_geometry *b, ga2d_transform xb,
                           double units, ga2d_result why)
{
    ga2d_manifold m, guard;
    memset(&m, 0x5A, sizeof m);
    memcpy(&guard, &m, sizeof m);
    CHECK(ga2d_collide_shapes_scaled(a, xa, b, xb, (ga2d_real)units, &m) == -(int)why);
    CHECK(ga2d_collide_shapes_scaled(b, xb, a, xa, (ga2d_real)units, &m) == -(int)why);
    if (units == 1) {
        CHECK(ga2d_collide_shapes(a, xa, b, xb, &m) == -(int)why);
        CHECK(ga2d_collide_shapes(b, xb, a, xa, &m) == -(int)why);
    }
    CHECK(memcmp(&m, &guard, sizeof m) == 0);
}

static void bad_input(void)
{
    ga2d_polygon box = ga2d_polygon_box(1, 1);
    ga2d_geometry c = circle(0, 0, 1), cap = capsule(-1, 0, 1, 0, 0.5), seg = segment(-1, 0, 1, 0), poly = polygon(&box);
    ga2d_geometry bad[8], nf[8], pt = circle(0, 0, 0), dot = segment(0.5, 0.5, 0.5, 0.5);
    ga2d_transform x0 = X(0, 0), x1 = X(0.5, 0.25), xn = x0, xq = x0, xi = x0, xr = x0, xo = x0;
    ga2d_manifold m;
    int k;
    xn.p.x = (ga2d_real)NAN;
    xq.q.s = (ga2d_real)NAN;
    xi.p.y = (ga2d_real)INFINITY;
    xr.q.c = (ga2d_real)(1 + 1.0 / 8192); /* |q|^2 - 1 = 2^-12 + 2^-26 > 1e-4 */
    xo.q.c = (ga2d_real)(1 + 1.0 / 32768); /* 2^-14 + 2^-30 < 1e-4: accepted */
    /* INVALID_ARGUMENT: a type out of range, a polygon's normal not unit,
       a negative radius, a polygon count out of range */
    for (k = 0; k < 8; ++k) bad[k] = seg;
    bad[0].type = GA2D_SHAPE_TYPE_COUNT;
    bad[1].type = (ga2d_shape_type)7;
    bad[2] = poly;
    bad[2].as.polygon.normals[1].x = 2;
    bad[3] = circle(0, 0, -1);
    bad[4] = capsule(-1, 0, 1, 0, -0.25);
    bad[5] = poly;
    bad[5].as.polygon.radius = (ga2d_real)-0.125;
    bad[6] = poly;
    bad[6].as.polygon.count = 0;
    bad[7] = poly;
    bad[7].as.polygon.count = MAXV + 1;
    /* NOT_FINITE: a radius or a coordinate */
    nf[0] = circle(0, 0, (double)NAN);
    nf[1] = capsule(-1, 0, 1, 0, (double)INFINITY);
    nf[2] = poly;
    nf[2].as.polygon.radius = (ga2d_real)NAN;
    nf[3] = circle((double)NAN, 0, 1);
    nf[4] = capsule(-1, 0, 1, (double)INFINITY, 0.5);
    nf[5] = segment((double)NAN, 0, 1, 0);
    nf[6] = poly;
    nf[6].as.polygon.vertices[2].x = (ga2d_real)INFINITY;
    memset(&nf[7], 0, sizeof nf[7]);
    nf[7].type = GA2D_SHAPE_CHAIN_SEGMENT; /* a chain segment's ghost vertex */
    nf[7].as.chain_segment.ghost1 = V((double)NAN, 0);
    nf[7].as.chain_segment.segment.point1 = V(-1, 0);
    nf[7].as.chain_segment.segment.point2 = V(1, 0);
    nf[7].as.chain_segment.ghost2 = V(2, 0);
    for (k = 0; k < 8; ++k) {
        expect_refused(&bad[k], x0, &c, x1, 1, GA2D_ERR_INVALID_ARGUMENT);
        expect_refused(&cap, x0, &bad[k], x1, 1, GA2D_ERR_INVALID_ARGUMENT);
        expect_refused(&nf[k], x0, &poly, x1, 1, GA2D_ERR_NOT_FINITE);
        expect_refused(&seg, x0, &nf[k], x1, 1, GA2D_ERR_NOT_FINITE);
    }
    expect_refused(NULL, x0, &c, x1, 1, GA2D_ERR_INVALID_ARGUMENT);
    expect_refused(&poly, x0, NULL, x1, 1, GA2D_ERR_INVALID_ARGUMENT);
    expect_refused(&c, xn, &cap, x1, 1, GA2D_ERR_NOT_FINITE);
    expect_refused(&c, x0, &cap, xq, 1, GA2D_ERR_NOT_FINITE);
    expect_refused(&seg, xi, &cap, x1, 1, GA2D_ERR_NOT_FINITE);
    expect_refused(&c, xr, &poly, x1, 1, GA2D_ERR_INVALID_ARGUMENT);
    expect_refused(&c, x0, &c, x1, 0, GA2D_ERR_INVALID_ARGUMENT);
    expect_refused(&c, x0, &c, x1, -1, GA2D_ERR_INVALID_ARGUMENT);
    expect_refused(&c, x0, &c, x1, (double)NAN, GA2D_ERR_NOT_FINITE);
    expect_refused(&c, x0, &c, x1, (double)INFINITY, GA2D_ERR_NOT_FINITE);
    CHECK(ga2d_collide_shapes(&c, x0, &c, x1, NULL) == -(int)GA2D_ERR_INVALID_ARGUMENT);
    /* what is just within the rules is taken: a rotor within the unit
       tolerance, a zero radius, a zero-length segment */
    CHECK(collide(&c, xo, &poly, x1, &m) == 1);
    CHECK(collide(&pt, x0, &poly, x1, &m) == 1);
    CHECK(collide(&dot, x0, &poly, x1, &m) == 1);
}

/* ------------------------------------------------------- degenerate */
/* The same manifold, bit for bit */
static int same_manifold(const ga2d_manifold *a, const ga2d_manifold *b)
{
    int k, same = a->count == b->count && a->normal.x == b->normal.x && a->normal.y == b->normal.y;
    for (k = 0; same && k < a->count; ++k) {
        const ga2d_manifold_point *p = &a->points[k], *q = &b->points[k];
        same = p->point.x == q->point.x && p->point.y == q->point.y && p->anchor_a.x == q->anchor_a.x &&
               p->anchor_a.y == q->anchor_a.y && p->anchor_b.x == q->anchor_b.x && p->anchor_b.y == q->anchor_b.y &&
               p->separation == q->separation && p->id == q->id;
    }
    return same;
}

/* A capsule whose ends coincide collides as the circle of its radius
   about that point, a segment whose ends coincide as that point (a circle
   of radius 0): documented, so the same inputs must give the same
   manifold, bit for bit (the ends are placed by the same transform as the
   centre; tolerance 0), against every kind, either way round. */
static void degenerate_as_circle(void)
{
    test_rng rng = {0xDE6};
    int i, contacts = 0;
    for (i = 0; i < 2 * SHAPE_PAIRS; ++i) {
        pair c;
        ga2d_manifold m1, m2;
        double cx, cy, r;
        ga2d_geometry cap, seg, pt;
        random_pair(&rng, K_CIRCLE, i % 5, &c);
        cx = (double)c.a.as.circle.center.x;
        cy = (double)c.a.as.circle.center.y;
        r = (double)c.a.as.circle.radius;
        cap = capsule(cx, cy, cx, cy, r);
        seg = segment(cx, cy, cx, cy);
        pt = circle(cx, cy, 0);
        contacts += collide(&c.a, c.xa, &c.b, c.xb, &m1) > 0;
        collide(&cap, c.xa, &c.b, c.xb, &m2);
        CHECK(same_manifold(&m1, &m2));
        collide(&c.b, c.xb, &c.a, c.xa, &m1);
        collide(&c.b, c.xb, &cap, c.xa, &m2);
        CHECK(same_manifold(&m1, &m2));
        collide(&pt, c.xa, &c.b, c.xb, &m1);
        collide(&seg, c.xa, &c.b, c.xb, &m2);
        CHECK(same_manifold(&m1, &m2));
        collide(&c.b, c.xb, &pt, c.xa, &m1);
        collide(&c.b, c.xb, &seg, c.xa, &m2);
        CHECK(same_manifold(&m1, &m2));
    }
    CHECK(contacts > SHAPE_PAIRS);
}

void suite_shape_collide(void)
{
    test_run("shape_collide: a circle on a box's face", circle_on_a_face);
    test_run("shape_collide: a circle at a box's corner", circle_at_a_corner);
    test_run("shape_collide: a circle inside a box", circle_inside_a_box);
    test_run("shape_collide: a point against a box", point_against_a_box);
    test_run("shape_collide: two circles", two_circles);
    test_run("shape_collide: a capsule lying flat on a box and a segment", capsule_lying_flat);
    test_run("shape_collide: crossed capsules", crossed_capsules);
    test_run("shape_collide: a rounded box on a box", rounded_box_on_a_box);
    test_run("shape_collide: a circle on a segment", circle_on_a_segment);
    test_run("shape_collide: a rounded box corner-down on a segment", rounded_corner_on_a_segment);
    test_run("shape_collide: rounded corners meet", rounded_corners_meet);
    test_run("shape_collide: the margin scales with the length unit", scaled_margin);
    test_run("shape_collide: capsules and segments on one line, apart along it", collinear_apart);
    test_run("shape_collide: random pairs of every kind against the exact answer", brute_force);
    test_run("shape_collide: random pairs, A with B against B with A", symmetry);
    test_run("shape_collide: random pairs far from the origin", far_from_origin);
    test_run("shape_collide: random pairs keep their ids under a 1e-4 nudge", ids_under_nudge);
    test_run("shape_collide: bad input is refused, *out untouched", bad_input);
    test_run("shape_collide: a capsule or segment with coinciding ends is a circle", degenerate_as_circle);
}
