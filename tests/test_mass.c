/* Exact polygon mass properties against closed forms, an independent
   triangulation, invariances, and the paper's own grid integration.

   Error model for the tolerances: the library sums n wedge terms of the
   vertices taken relative to their mean; with R the largest distance of a
   vertex from that mean, each area term carries <= 4 eps R^2 of rounding,
   each moment term <= 8 eps R^3, and each inertia term <= 24 eps R^4.  So
   |dA| <= 8 n eps R^2, |dC| <= 16 n eps R^3 / A, |dI| <= 32 n eps R^4
   (the A |C - r|^2 correction adds less than the sum it corrects). */
#include "test.h"

#define PI 3.14159265358979323846
#define MAXV GA2D_MAX_POLYGON_VERTICES

typedef struct ref_mass { double area, cx, cy, inertia; } ref_mass;

/* Independent reference: fan triangles from vertex 0, each with its own
   closed form (area by the cross product, centroid = vertex mean, polar
   moment about its centroid = area (a^2 + b^2 + c^2) / 36 for sides a, b,
   c), combined by the parallel-axis theorem, in long double. */
static ref_mass reference_mass(const ga2d_polygon *p)
{
    long double A = 0, mx = 0, my = 0, J = 0, cx, cy;
    long double ta[MAXV], tx[MAXV], ty[MAXV], ti[MAXV];
    ref_mass out;
    int i, n = p->count;
    long double x0 = (long double)p->vertices[0].x, y0 = (long double)p->vertices[0].y;
    for (i = 1; i + 1 < n; ++i) {
        long double x1 = (long double)p->vertices[i].x, y1 = (long double)p->vertices[i].y;
        long double x2 = (long double)p->vertices[i + 1].x, y2 = (long double)p->vertices[i + 1].y;
        long double a2 = (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0);
        long double b2 = (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1);
        long double c2 = (x0 - x2) * (x0 - x2) + (y0 - y2) * (y0 - y2);
        ta[i] = ((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)) / 2;
        tx[i] = (x0 + x1 + x2) / 3;
        ty[i] = (y0 + y1 + y2) / 3;
        ti[i] = ta[i] * (a2 + b2 + c2) / 36;
        A += ta[i];
        mx += ta[i] * tx[i];
        my += ta[i] * ty[i];
    }
    cx = mx / A;
    cy = my / A;
    for (i = 1; i + 1 < n; ++i) J += ti[i] + ta[i] * ((tx[i] - cx) * (tx[i] - cx) + (ty[i] - cy) * (ty[i] - cy));
    out.area = (double)A;
    out.cx = (double)cx;
    out.cy = (double)cy;
    out.inertia = (double)J;
    return out;
}

/* largest distance of a vertex from the vertex mean (the R of the model) */
static double spread(const ga2d_polygon *p)
{
    double mx = 0, my = 0, R = 0;
    int i;
    for (i = 0; i < p->count; ++i) {
        mx += (double)p->vertices[i].x / p->count;
        my += (double)p->vertices[i].y / p->count;
    }
    for (i = 0; i < p->count; ++i) {
        double d = hypot((double)p->vertices[i].x - mx, (double)p->vertices[i].y - my);
        R = d > R ? d : R;
    }
    return R;
}

static ga2d_polygon make(const ga2d_vec *pts, int n)
{
    ga2d_polygon p;
    memset(&p, 0, sizeof p);
    CHECK_RESULT(ga2d_polygon_make(pts, n, &p), GA2D_OK);
    return p;
}

/* The paper's right triangle (fig. 1, eq. 22): (0,0), (w,0), (w,h) has its
   centroid at (2w/3, h/3); its inertia about it is m (w^2 + h^2) / 18
   (sides w, h, sqrt(w^2+h^2) in m (a^2+b^2+c^2)/36).  Legs 2 and 1 give
   the REFERENCES check I = 5/18 at unit density. */
static void paper_right_triangle(void)
{
    const double dims[][2] = {{3, 2}, {2, 1}, {1, 1}, {10, 0.5}, {0.25, 4}};
    size_t k;
    for (k = 0; k < sizeof dims / sizeof dims[0]; ++k) {
        double w = dims[k][0], h = dims[k][1], R, m;
        ga2d_vec pts[3];
        ga2d_polygon p;
        ga2d_mass ms;
        pts[0] = ga2d_vec_make(0, 0);
        pts[1] = ga2d_vec_make((ga2d_real)w, 0);
        pts[2] = ga2d_vec_make((ga2d_real)w, (ga2d_real)h);
        p = make(pts, 3);
        R = spread(&p);
        ms = ga2d_polygon_mass(&p, 2.5);
        m = 2.5 * w * h / 2;
        CHECK_NEAR(ms.mass, m, 2.5 * 8 * 3 * REAL_EPS * R * R);
        CHECK_NEAR(ms.center.x, 2 * w / 3, 16 * 3 * REAL_EPS * R * R * R / (w * h / 2) + 2 * REAL_EPS * w);
        CHECK_NEAR(ms.center.y, h / 3, 16 * 3 * REAL_EPS * R * R * R / (w * h / 2) + 2 * REAL_EPS * w);
        CHECK_NEAR(ms.inertia, m * (w * w + h * h) / 18, 2.5 * 32 * 3 * REAL_EPS * R * R * R * R);
    }
    {
        const ga2d_vec legs[3] = {{0, 0}, {2, 0}, {2, 1}};
        ga2d_polygon p = make(legs, 3);
        CHECK_NEAR(ga2d_polygon_mass(&p, 1).inertia, 5.0 / 18.0, 32 * 3 * REAL_EPS * 1.5 * 1.5 * 1.5 * 1.5);
    }
}

/* Rectangles: I = m (w^2 + h^2) / 12, centred or not. */
static void rectangles(void)
{
    const double dims[][4] = {{1, 1, 0, 0}, {2, 1, 0, 0}, {0.1, 10, 3, -2}, {100, 1, -50, 7}, {1e-3, 2e-3, 0, 0}, {4, 0.04, 1, 1}};
    size_t k;
    for (k = 0; k < sizeof dims / sizeof dims[0]; ++k) {
        double w = dims[k][0], h = dims[k][1], ox = dims[k][2], oy = dims[k][3], R = hypot(w, h) / 2, m = w * h;
        ga2d_vec pts[4];
        ga2d_polygon p;
        ga2d_mass ms;
        pts[0] = ga2d_vec_make((ga2d_real)ox, (ga2d_real)oy);
        pts[1] = ga2d_vec_make((ga2d_real)(ox + w), (ga2d_real)oy);
        pts[2] = ga2d_vec_make((ga2d_real)(ox + w), (ga2d_real)(oy + h));
        pts[3] = ga2d_vec_make((ga2d_real)ox, (ga2d_real)(oy + h));
        p = make(pts, 4);
        ms = ga2d_polygon_mass(&p, 1);
        /* the vertices themselves are rounded (ox + w in float): use the
           triangulation of the stored vertices for the centre, and the
           closed form with a tolerance that adds that rounding (4 vertices
           moved by eps |x| change A by <= perimeter eps |x|) */
        {
            double xr = (fabs(ox) + fabs(oy) + w + h) * REAL_EPS;
            double dA = 2 * (w + h) * xr;
            CHECK_NEAR(ms.mass, m, 8 * 4 * REAL_EPS * R * R + dA);
            CHECK_NEAR(ms.center.x, ox + w / 2, 16 * 4 * REAL_EPS * R * R * R / m + 2 * xr);
            CHECK_NEAR(ms.center.y, oy + h / 2, 16 * 4 * REAL_EPS * R * R * R / m + 2 * xr);
            CHECK_NEAR(ms.inertia, m * (w * w + h * h) / 12, 32 * 4 * REAL_EPS * R * R * R * R + dA * 4 * R * R);
        }
    }
}

/* Regular n-gon of circumradius R: A = n R^2 sin(2 pi/n) / 2 and
   I = m R^2 (1 + 2 cos^2(pi/n)) / 6 (unit square: m s^2/6; hexagon of
   side 1: 5 sqrt 3 / 8).  As n grows, I / (m R^2) = 1/2 - sin^2(pi/n)/3
   tends to the disc's 1/2.  Vertices are rounded once (eps R each), which
   moves A by <= perimeter * eps R = 2 pi eps R^2 and I by <= 4 R^2 that. */
static void regular_polygons_tend_to_disc(void)
{
    double R = 1.75, prev_gap = 1;
    int n;
    for (n = 3; n <= MAXV; ++n) {
        ga2d_polygon p = ga2d_polygon_regular(n, (ga2d_real)R);
        ga2d_mass ms = ga2d_polygon_mass(&p, 1);
        double A = n * R * R * sin(2 * PI / n) / 2, c = cos(PI / n), gap;
        double vert = 2 * PI * REAL_EPS * R * R;
        CHECK(p.count == n);
        CHECK_NEAR(ms.mass, A, 8 * n * REAL_EPS * R * R + vert);
        CHECK_NEAR(ms.center.x, 0, 16 * n * REAL_EPS * R * R * R / A + 2 * REAL_EPS * R);
        CHECK_NEAR(ms.center.y, 0, 16 * n * REAL_EPS * R * R * R / A + 2 * REAL_EPS * R);
        CHECK_NEAR(ms.inertia, A * R * R * (1 + 2 * c * c) / 6, 32 * n * REAL_EPS * R * R * R * R + 4 * R * R * vert);
        gap = 0.5 - (double)ms.inertia / ((double)ms.mass * R * R);
        /* the gap to the disc is sin^2(pi/n)/3 <= pi^2/(3 n^2), and shrinks */
        CHECK_NEAR(gap, sin(PI / n) * sin(PI / n) / 3, 64 * n * REAL_EPS);
        CHECK(gap <= PI * PI / (3.0 * n * n) + 64 * n * REAL_EPS);
        CHECK(gap < prev_gap);
        prev_gap = gap;
    }
    if (MAXV >= 6) {
        /* side 1 hexagon: circumradius 1 */
        ga2d_polygon hex = ga2d_polygon_regular(6, 1);
        CHECK_NEAR(ga2d_polygon_mass(&hex, 1).inertia, 5 * sqrt(3.0) / 8, 32 * 6 * REAL_EPS + 8 * PI * REAL_EPS);
    }
    {
        const ga2d_vec sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        ga2d_polygon p = make(sq, 4);
        CHECK_NEAR(ga2d_polygon_mass(&p, 1).inertia, 1.0 / 6.0, 32 * 4 * REAL_EPS * 0.25);
    }
}

/* A random convex polygon: the hull of random points, kept if it has at
   least 3 and at most MAXV vertices. */
static ga2d_polygon random_convex(test_rng *rng, double size, double cx, double cy)
{
    ga2d_vec pts[24];
    ga2d_polygon p;
    for (;;) {
        int n = rng_int(rng, 3, MAXV < 12 ? MAXV + 2 : 12), i;
        for (i = 0; i < n; ++i)
            pts[i] = ga2d_vec_make((ga2d_real)(cx + size * rng_uniform(rng, -1, 1)), (ga2d_real)(cy + size * rng_uniform(rng, -0.6, 0.6)));
        if (ga2d_polygon_hull(pts, n, &p) == GA2D_OK) return p;
    }
}

static void irregular_against_triangulation(void)
{
    test_rng rng = {31};
    int t;
    for (t = 0; t < 1000; ++t) {
        double size = t < 500 ? rng_uniform(&rng, 0.1, 10) : pow(10.0, rng_uniform(&rng, -3, 3));
        ga2d_polygon p = random_convex(&rng, size, rng_uniform(&rng, -3, 3) * size, rng_uniform(&rng, -3, 3) * size);
        ref_mass ref = reference_mass(&p);
        ga2d_mass ms = ga2d_polygon_mass(&p, 1);
        double R = spread(&p), n = p.count;
        CHECK_NEAR(ms.mass, ref.area, 8 * n * REAL_EPS * R * R);
        CHECK_NEAR(ms.center.x, ref.cx, 16 * n * REAL_EPS * R * R * R / ref.area + 2 * REAL_EPS * fabs(ref.cx));
        CHECK_NEAR(ms.center.y, ref.cy, 16 * n * REAL_EPS * R * R * R / ref.area + 2 * REAL_EPS * fabs(ref.cy));
        CHECK_NEAR(ms.inertia, ref.inertia, 32 * n * REAL_EPS * R * R * R * R);
    }
}

/* Translation invariance far from the origin: 1e4 in float, 1e6 in double.
   The vertices lie on a 1/64 grid, so the translated polygon is exactly the
   same shape (1e4 + k/64 needs 20 bits).  Mass and inertia must agree
   within the model's bounds; the centre moves by T within the rounding of
   numbers of size |T| (2 eps |T|).  A formula taken about the origin
   (J_O - A |C|^2) would lose eps |T|^2 A to cancellation: the test shows
   it fails the same tolerance, so the bound really tests the method. */
static void translation_invariance(void)
{
#ifdef GA2D_DOUBLE
    const double T = 1e6;
#else
    const double T = 1e4;
#endif
    const double shifts[][2] = {{T, 0}, {0, -T}, {T, T}, {-T, 0.5 * T}};
    const double angles[] = {0, 1.1, 2.0, 2.9, 4.2, 5.3};
    ga2d_vec base[6], moved[6];
    ga2d_polygon p0, p1;
    ga2d_mass m0, m1;
    double R;
    int n = MAXV < 6 ? MAXV : 6, i;
    size_t s;
    for (i = 0; i < n; ++i)
        base[i] = ga2d_vec_make((ga2d_real)(floor(64 * 2.0 * cos(angles[i])) / 64), (ga2d_real)(floor(64 * 1.3 * sin(angles[i])) / 64));
    p0 = make(base, n);
    m0 = ga2d_polygon_mass(&p0, 1);
    R = spread(&p0) + 1.0 / 64;
    for (s = 0; s < sizeof shifts / sizeof shifts[0]; ++s) {
        double dI = 32 * n * REAL_EPS * R * R * R * R, naive_err;
        ga2d_real jr = 0, a2r = 0, mxr = 0, myr = 0, ar, cxr, cyr;
        for (i = 0; i < n; ++i) {
            moved[i] = ga2d_vec_make((ga2d_real)((double)base[i].x + shifts[s][0]), (ga2d_real)((double)base[i].y + shifts[s][1]));
            CHECK((double)moved[i].x - shifts[s][0] == (double)base[i].x); /* exactly representable */
        }
        p1 = make(moved, n);
        m1 = ga2d_polygon_mass(&p1, 1);
        CHECK_NEAR(m1.mass, m0.mass, 2 * 8 * n * REAL_EPS * R * R);
        CHECK_NEAR(m1.inertia, m0.inertia, 2 * dI);
        CHECK_NEAR((double)m1.center.x - shifts[s][0], m0.center.x, 4 * REAL_EPS * T + 2 * 16 * n * REAL_EPS * R * R * R / (double)m0.mass);
        CHECK_NEAR((double)m1.center.y - shifts[s][1], m0.center.y, 4 * REAL_EPS * T + 2 * 16 * n * REAL_EPS * R * R * R / (double)m0.mass);
        /* the naive origin formula, in ga2d_real like the library */
        for (i = 0; i < n; ++i) {
            ga2d_vec a = moved[i], b = moved[(i + 1) % n];
            ga2d_real c = ga2d_wedge(a, b);
            a2r += c;
            mxr += c * (a.x + b.x);
            myr += c * (a.y + b.y);
            jr += c * (ga2d_dot(a, a) + ga2d_dot(a, b) + ga2d_dot(b, b));
        }
        ar = a2r / 2;
        cxr = mxr / (3 * a2r);
        cyr = myr / (3 * a2r);
        naive_err = fabs((double)(jr / 12 - ar * (cxr * cxr + cyr * cyr)) - (double)m0.inertia);
        /* (NaN counts as failing: in float at (T, T) its area can cancel to 0) */
        CHECK(!(naive_err <= 2 * dI));
    }
}

/* Rotation and the choice of first vertex change nothing.  Rotating moves
   each vertex by its rounding (2 eps R), which moves I by <= 8 n eps R^4
   on top of the method's 32 n eps R^4: 64 n eps R^4 covers both. */
static void rotation_and_first_vertex(void)
{
    test_rng rng = {32};
    int t;
    for (t = 0; t < 300; ++t) {
        ga2d_polygon p = random_convex(&rng, rng_uniform(&rng, 0.2, 5), rng_uniform(&rng, -4, 4), rng_uniform(&rng, -4, 4));
        ga2d_polygon q;
        ga2d_mass m0 = ga2d_polygon_mass(&p, 3), m1;
        ga2d_rotor rot = ga2d_rotor_from_angle((ga2d_real)rng_uniform(&rng, -PI, PI));
        ga2d_vec pts[MAXV], c;
        double R = spread(&p), n = p.count, far = R + hypot((double)m0.center.x, (double)m0.center.y);
        int i, shift;
        for (i = 0; i < p.count; ++i) pts[i] = ga2d_rotate(rot, p.vertices[i]);
        q = make(pts, p.count);
        m1 = ga2d_polygon_mass(&q, 3);
        c = ga2d_rotate(rot, m0.center);
        CHECK_NEAR(m1.mass, m0.mass, 3 * 16 * n * REAL_EPS * far * far);
        CHECK_NEAR(m1.inertia, m0.inertia, 3 * 64 * n * REAL_EPS * far * far * far * far);
        CHECK_NEAR(m1.center.x, c.x, 32 * n * REAL_EPS * far * far * far / ((double)m0.mass / 3) + 4 * REAL_EPS * far);
        CHECK_NEAR(m1.center.y, c.y, 32 * n * REAL_EPS * far * far * far / ((double)m0.mass / 3) + 4 * REAL_EPS * far);
        for (shift = 1; shift < p.count; ++shift) {
            for (i = 0; i < p.count; ++i) pts[i] = p.vertices[(i + shift) % p.count];
            q = make(pts, p.count);
            m1 = ga2d_polygon_mass(&q, 3);
            CHECK_NEAR(m1.mass, m0.mass, 3 * 16 * n * REAL_EPS * R * R);
            CHECK_NEAR(m1.inertia, m0.inertia, 3 * 64 * n * REAL_EPS * R * R * R * R);
            CHECK_NEAR(m1.center.x, m0.center.x, 32 * n * REAL_EPS * R * R * R / ((double)m0.mass / 3) + 4 * REAL_EPS * far);
            CHECK_NEAR(m1.center.y, m0.center.y, 32 * n * REAL_EPS * R * R * R / ((double)m0.mass / 3) + 4 * REAL_EPS * far);
        }
    }
}

/* The paper's numerical method (§2.2): sum over an N x N grid of cells the
   cells whose centre lies inside.  Interior cells are exact for area and
   moment, and for inertia once each adds its own polar moment h^4/6; only
   cells the boundary passes through are in error.  A convex boundary of
   length P, cut into ceil(P/h) pieces of length <= h, meets at most 4 cells
   per piece, so at most 4 (P/h + 1) cells, each off by at most h^2 in area,
   h^2 Rb in moment and h^2 Rb^2 + h^4/6 in inertia, Rb being the farthest a
   cell point gets from the centroid.  The bound falls as 1/N: the grid
   value converges to the exact one, at least as O(h).  (The hexagon's
   error is O(h) indeed: cell centres fall exactly on its edges, of small
   rational slopes, and the normals' rounding counts them in or out.)

   The triangle converges as O(h^2), and its error is derived here.  With
   h = 3/N (N a power of 2, so 3 does not divide N) its bottom and right
   edges lie on cell boundaries, and no centre lies on the hypotenuse y =
   2x/3 (centre (i + 1/2, j + 1/2) h is |2i - 3j - 1/2| h / sqrt 13 >= h /
   (2 sqrt 13) away from it, far beyond the float normal's rounding), so
   column i holds its c_i = floor((4i + 5)/6) lowest cells.  Each cell adds
   exactly its own integral of 1, x, y and r^2 about the centroid (the
   h^4/6 is the cell's own polar moment), so the grid value is the exact
   integral of g over the columns [0, c_i h]; the error is that over the
   slivers between c_i h and the chord 2x/3.  Area: 3 columns running hold
   2k, 2k + 1, 2k + 2 cells, so N columns hold (N^2 - 1)/3 cells: the grid
   area is exactly A - h^2/3.  Any g: column i's top is off the chord at
   its centre x_i by e_i = h (1/2 - frac((4i + 5)/6)) = -h/3, 0, h/3 as
   i = 0, 1, 2 mod 3, and by e_i - (2/3)(x - x_i) across it (|.| <= 2h/3).
   With phi(x) = g(x, 2x/3) on the chord, a sliver integrates to
   (e_i - (2/3)(x - x_i)) phi(x) dx up to (2h/3)^2/2 max|g_y| dx; the e_i
   terms pair off over each run of 3 columns to (h/3)(Phi_{i+2} - Phi_i),
   Phi_i the column's integral of phi, <= (2/3) h^3 max|phi'| a run, with
   one unpaired column (h^2/3) max|phi| at the end; the (x - x_i) terms
   give <= (2/3) h^3/12 max|phi'| a column.  Over the width 3:
       |error| <= h^2 [(5/6) max|phi'| + (1/3) max|phi| + (2/3) max|g_y|].
   About the centroid (2, 2/3): x - 2 gives 1.5 h^2 (phi' = 1, |phi| <= 2,
   g_y = 0); y - 2/3 gives (5/3) h^2; r^2 gives (5/6)(44/9) + (1/3)(40/9)
   + (2/3) 2 (4/3 + h) = 7.33 h^2 (phi(0) = 40/9, phi'(0) = -44/9 are the
   largest, |g_y| = 2 |y - 2/3| within 2h/3 of the chord).  Plus the grid
   sums' own rounding in double (N^2 terms: <= 8 N^2 eps_d of their sum of
   magnitudes) and the library's (the model's bounds above; the inertia
   taken about the library's centroid, off by dc, moves J by <= 2 dc |M| +
   A dc^2).  So at N = 1024 the inertia is checked to 7e-5 of its 2.17 in
   double (in float the library's own rounding bound, 5e-4, is the larger),
   where the O(h) bound allows 0.45. */
static void grid_integration_converges(void)
{
    const ga2d_vec tri[3] = {{0, 0}, {3, 0}, {3, 2}};
    const ga2d_vec hexa[6] = {{0, 0}, {2, -0.5}, {3.5, 0.75}, {3, 2.5}, {1, 3}, {-0.5, 1.5}};
    const ga2d_vec *shapes[2];
    int counts[2], s, N;
    shapes[0] = tri; counts[0] = 3;
    shapes[1] = hexa; counts[1] = MAXV >= 6 ? 6 : 0;
    for (s = 0; s < 2; ++s) {
        ga2d_polygon p;
        ga2d_mass ex;
        double lox = 1e30, loy = 1e30, hix = -1e30, hiy = -1e30, P = 0, Rv = 0;
        int i;
        if (!counts[s]) continue;
        p = make(shapes[s], counts[s]);
        ex = ga2d_polygon_mass(&p, 1);
        for (i = 0; i < p.count; ++i) {
            double x = (double)p.vertices[i].x, y = (double)p.vertices[i].y;
            ga2d_vec e = ga2d_vec_sub(p.vertices[(i + 1) % p.count], p.vertices[i]);
            lox = x < lox ? x : lox; hix = x > hix ? x : hix;
            loy = y < loy ? y : loy; hiy = y > hiy ? y : hiy;
            P += (double)ga2d_vec_length(e);
            x -= (double)ex.center.x; y -= (double)ex.center.y;
            Rv = hypot(x, y) > Rv ? hypot(x, y) : Rv;
        }
        for (N = 16; N <= 1024; N *= 4) {
            double h = ((hix - lox) > (hiy - loy) ? hix - lox : hiy - loy) / N;
            double A = 0, Mx = 0, My = 0, J = 0, cells, Rb = Rv + h * sqrt(2.0);
            int ix, iy, k;
            for (ix = 0; ix * h < hix - lox; ++ix)
                for (iy = 0; iy * h < hiy - loy; ++iy) {
                    double x = lox + (ix + 0.5) * h, y = loy + (iy + 0.5) * h, dx, dy;
                    int inside = 1;
                    for (k = 0; k < p.count && inside; ++k)
                        inside = (double)p.normals[k].x * (x - (double)p.vertices[k].x) +
                                     (double)p.normals[k].y * (y - (double)p.vertices[k].y) <= 0;
                    if (!inside) continue;
                    dx = x - (double)ex.center.x;
                    dy = y - (double)ex.center.y;
                    A += h * h;
                    Mx += h * h * dx;
                    My += h * h * dy;
                    J += h * h * (dx * dx + dy * dy) + h * h * h * h / 6;
                }
            cells = 4 * (P / h + 1);
            /* plus the exact value's own rounding (model bounds, tiny) */
            CHECK_NEAR(A, ex.mass, cells * h * h + 8 * 6 * REAL_EPS * Rv * Rv);
            CHECK_NEAR(Mx / A, 0, cells * h * h * Rb / A + 16 * 6 * REAL_EPS * Rv);
            CHECK_NEAR(My / A, 0, cells * h * h * Rb / A + 16 * 6 * REAL_EPS * Rv);
            CHECK_NEAR(J, ex.inertia, cells * (h * h * Rb * Rb + h * h * h * h / 6) + 32 * 6 * REAL_EPS * Rv * Rv * Rv * Rv);
            if (s == 0) { /* the triangle, O(h^2) */
                const double dc = 16 * 6 * REAL_EPS * Rv, sum = 8 * (double)N * N * DBL_EPSILON;
                const double KJ = 5.0 / 6 * 44 / 9 + 1.0 / 3 * 40 / 9 + 2.0 / 3 * 2 * (4.0 / 3 + h);
                CHECK(N % 3 != 0);
                CHECK_NEAR(A, (double)ex.mass - h * h / 3, sum * A + 8 * 6 * REAL_EPS * Rv * Rv);
                CHECK_NEAR(Mx / A, 0, 1.5 * h * h / A + sum * Rb + dc);
                CHECK_NEAR(My / A, 0, 5.0 / 3 * h * h / A + sum * Rb + dc);
                CHECK_NEAR(J, ex.inertia,
                           KJ * h * h + sum * J + 32 * 6 * REAL_EPS * Rv * Rv * Rv * Rv + 2 * dc * (1.5 + 5.0 / 3) * h * h + 2 * A * dc * dc);
            }
        }
    }
}

static void density_and_bad_input(void)
{
    ga2d_polygon box = ga2d_polygon_box(1, 0.5), empty = ga2d_polygon_box(0, 0);
    ga2d_mass m1 = ga2d_polygon_mass(&box, 1), m4 = ga2d_polygon_mass(&box, 4), z, sentinel, out;
    memset(&z, 0, sizeof z);
    memset(&sentinel, 0x5A, sizeof sentinel);
    /* a power-of-two density scales exactly */
    CHECK(m4.mass == 4 * m1.mass && m4.inertia == 4 * m1.inertia && m4.center.x == m1.center.x);
    CHECK(ga2d_polygon_mass(&box, 0).mass == 0);
    CHECK(memcmp(&z, &m1, sizeof z) != 0);
    {
        ga2d_mass r;
        r = ga2d_polygon_mass(NULL, 1); CHECK(memcmp(&r, &z, sizeof z) == 0);
        r = ga2d_polygon_mass(&empty, 1); CHECK(memcmp(&r, &z, sizeof z) == 0);
        r = ga2d_polygon_mass(&box, -1); CHECK(memcmp(&r, &z, sizeof z) == 0);
        r = ga2d_polygon_mass(&box, (ga2d_real)NAN); CHECK(memcmp(&r, &z, sizeof z) == 0);
        r = ga2d_polygon_mass(&box, (ga2d_real)INFINITY); CHECK(memcmp(&r, &z, sizeof z) == 0);
    }
    out = sentinel;
    CHECK_RESULT(ga2d_polygon_mass_checked(&box, (ga2d_real)NAN, &out), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_mass_checked(&box, -2, &out), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_mass_checked(&empty, 1, &out), GA2D_ERR_TOO_FEW_POINTS);
    CHECK_RESULT(ga2d_polygon_mass_checked(NULL, 1, &out), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_mass_checked(&box, 1, NULL), GA2D_ERR_INVALID_ARGUMENT);
    /* a density that overflows the inertia of a polygon at the size limit */
    {
        ga2d_polygon huge = ga2d_polygon_box(GA2D_MAX_COORDINATE / 2, GA2D_MAX_COORDINATE / 2);
        CHECK(huge.count == 4);
#ifdef GA2D_DOUBLE
        CHECK_RESULT(ga2d_polygon_mass_checked(&huge, (ga2d_real)DBL_MAX / 4, &out), GA2D_ERR_TOO_LARGE);
#else
        CHECK_RESULT(ga2d_polygon_mass_checked(&huge, (ga2d_real)FLT_MAX / 4, &out), GA2D_ERR_TOO_LARGE);
#endif
        /* at density 1e6 the documented limit still holds */
        CHECK_RESULT(ga2d_polygon_mass_checked(&huge, (ga2d_real)1e6, &out), GA2D_OK);
    }
    CHECK_RESULT(ga2d_polygon_mass_checked(&box, 2, &out), GA2D_OK);
    out = sentinel;
    CHECK_RESULT(ga2d_polygon_mass_checked(&box, -2, &out), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
#ifdef GA2D_DOUBLE
    /* double keeps polygons up to its 1e15 bound exactly: a square of side
       s = 2e15 has I = s^4 / 6 = 16e60 / 6 */
    {
        ga2d_polygon big = ga2d_polygon_box(1e15, 1e15);
        ga2d_mass mb = ga2d_polygon_mass(&big, 1);
        CHECK_NEAR(mb.mass / 4e30, 1, 32 * REAL_EPS);
        CHECK_NEAR(mb.inertia / (16e60 / 6), 1, 32 * 4 * REAL_EPS * 2);
    }
#endif
}

void suite_mass(void)
{
    test_run("mass: the paper's right triangle (eq. 22), I = m(w^2+h^2)/18", paper_right_triangle);
    test_run("mass: rectangles, I = m(w^2+h^2)/12", rectangles);
    test_run("mass: regular n-gons, closed form, tending to the disc", regular_polygons_tend_to_disc);
    test_run("mass: 1000 irregular polygons against a triangulation", irregular_against_triangulation);
    test_run("mass: invariant under translation far from the origin", translation_invariance);
    test_run("mass: invariant under rotation and the first vertex", rotation_and_first_vertex);
    test_run("mass: the paper's grid integration converges to it", grid_integration_converges);
    test_run("mass: density scaling and bad input", density_and_bad_input);
}
