/* Exact mass properties of the round shapes: circles, capsules and
   rounded polygons, against closed forms, an independent integration of
   the true outline, analytic limits and invariances, bad input, and a
   world body.

   Notation: u = REAL_EPS/2 is the library's rounding unit, U = DBL_EPSILON/2
   the references' (they run in double).  Bounds are first order in u;
   libm's sin, cos and atan2 are taken to be within 2 ulp (<= 4 u |x|).

   --- The outline references (outline_mass) ----------------------------
   A shape is a core (1 point: a disc; 2: a capsule's segment; n >= 3: a
   convex CCW polygon) plus every point within r of it.  Its outline is
   the core's edges pushed out by r, joined at each core vertex by an arc
   of radius r spanning the turn alpha_i between the two edge normals.
   CHORDS: each arc is cut into k_i = ceil(alpha_i / THETA_MAX) equal
   pieces of angle theta and replaced by chords; the resulting N-gon Q is
   integrated by the exact polygon formulas (fan of triangles about the
   core's vertex mean o) in double.
   EXACT: one chord per arc, and the circular segments between arcs and
   chords added by their closed forms (sector less triangle) -- another
   decomposition than the library's strips and sectors, without
   discretisation error, so it checks double builds to their rounding.
   Discretisation (CHORDS): Q lies inside the shape S, and S \ Q is the circular
   segments, each of area r^2 (theta - sin theta)/2 <= r^2 theta^3 / 12, so
     dA_disc = sum r^2 theta^3 / 12      (<= pi r^2 THETA_MAX^2 / 6).
   With rho_c the largest distance from Q's centroid C_Q to a point of S:
     |C_S - C_Q| = |int_{S\Q} (x - C_Q)| / A_S <= dA_disc rho_c / A_S,
     I_S - I_Q = int_{S\Q} |x - C_Q|^2 - A_S |C_S - C_Q|^2, both terms in
     [0, dA_disc rho_c^2], so |I_S - I_Q| <= dA_disc rho_c^2.
   Rounding (rho_o = max |v_i - o| + r, N points): each point is off its
   place by <= 7 U rho_o (v - o, r cos t, the sum), which moves X_m (the
   area, first and second moments about o, m = 0, 1, 2) by <= perimeter *
   7 U rho_o * rho_o^m <= 14 pi U rho_o^(2+m); each wedge is taken against
   the short chord (d_k ^ (d_k+1 - d_k)), <= 4 U rho_o |chord| rho_o^m, in
   all <= 8 pi U rho_o^(2+m); the multipliers add <= 6 U of each term and
   the N-term sums <= N U of the sum of terms <= A rho_o^m <= pi rho_o^(2+m).
   EXACT's segments (angles adding to 2 pi) add: th - sin th within 5 U th,
   3 th - sin th (2 + cos th) within 24 U th, <= 8 U of each term else,
   <= 19 pi U rho_o^(2+m) in all, and n more terms to sum.  So with N the
   points (and segments), each X_m is within (N + 64) pi U rho_o^(2+m).

   --- The library's rounding (lib_bounds) ------------------------------
   ga2d_polygon_mass_checked sums, about ref (the vertex mean), per vertex
   a fan triangle, an edge strip and a corner sector into three sums
   (area, first moment, second moment).  With R = max |v_i - ref| and
   rho = R + r (the shape lies within rho of ref), first-order errors per
   vertex, counting roundings (A = area of the rounded shape):
   - area: triangle c/2, c = d0 ^ d1 with d = v - ref rounded: 4 u R^2 / 2;
     strip len r: len by ga2d_vec_length from e = v1 - v0 (<= 5 u), times
     r: 6 u * 2 R r; sector alpha r^2/2: alpha = atan2(np ^ ni, np . ni)
     off by <= 22 u (each stored normal's direction 3 u, the wedge and dot
     3 u, atan2 4 pi u), and two roundings of alpha r^2: <= 11 u r^2 +
     2 u pi r^2 / 2.  In all 2 R^2 + 12 R r + 16 r^2 <= 16 rho^2 (times u).
   - first moment: triangle c (d0 + d1)/6: <= 2.4 u R^3; strip m c, |c| <=
     rho off by <= 5 u rho: 24 u rho R r; sector ms (dv + b d), d = 4 r
     sin(alpha/2)/(3 alpha) <= 2r/3 off by <= 7.8 u r (|d'(alpha)| <=
     0.14 r), b off by 5 u: <= 11 u r^2 rho + 15.8 u ms rho.  In all <= 38 u
     rho^3.
   - second moment: triangle <= 3 u R^4; strip m ((len^2 + r^2)/12 + c.c)
     <= 27.8 u m rho^2 with m <= 2 R r; sector ms (r^2/2 + dv.dv + 2 d b.dv)
     <= 11 u r^2 rho^2 + 19 u ms rho^2.  In all <= 48 u rho^4.
   The terms of each sum have magnitudes adding to <= A rho^m (a piece's
   area times its distance from ref to the m-th), and recursive sums of at
   most 2n terms, the scaling and the merge add (2n + 2) u of that:
     dA <= 16 n u rho^2 + (2n + 2) u A
     dM <= 38 n u rho^3 + (2n + 2) u A rho
     dJ <= 48 n u rho^4 + (2n + 2) u A rho^2.
   assemble() turns (dA, dM, dJ) into the errors of mass, centre and
   inertia: rel = M / A (three roundings) is off by (dM + rho dA)/A +
   3 u rho, the centre ref + rel by u |C| more; I = J - A |rel|^2 by dJ +
   2 rho dM + 3 rho^2 dA + 11 u A rho^2 (J <= A rho^2), and the density's
   products by u A (mass) and u A rho^2 (inertia) more.  The sharp polygon (r = 0) is the same with
   rho = R (tests/test_mass.c's model has the same per-term sizes).

   The closed forms (circle, capsule) count their roundings where they are
   checked. */
#include "test.h"

#define PI 3.14159265358979323846
#define MAXV GA2D_MAX_POLYGON_VERTICES
#define U_LIB (REAL_EPS / 2)
#define U_REF (DBL_EPSILON / 2)
/* the largest arc piece of the outline reference: 2^15 pieces a turn,
   dA_disc <= pi r^2 THETA_MAX^2 / 6 < 2e-8 r^2 (6e-9 of a disc's area) */
#define THETA_MAX (2 * PI / 32768)

#ifdef GA2D_DOUBLE
#define FAR 1e6
#else
#define FAR 1e3
#endif

/* ------------------------------------------------------------ reporting */
static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

/* per check site of the current test: the check that came nearest its
   bound (library checks, and the references' own checks apart) */
typedef struct worst { const char *what; int line, ref; double err, tol, ratio; } worst;
static worst g_worst[64];
static int g_nworst;

static void note(const char *what, int line, int ref, double a, double b, double tol)
{
    double err = fabs(a - b), ratio = tol > 0 ? err / tol : (err > 0 ? 1e300 : 0);
    int i;
    for (i = 0; i < g_nworst && g_worst[i].line != line; ++i) {}
    if (i == g_nworst) {
        if (g_nworst == (int)(sizeof g_worst / sizeof g_worst[0])) return;
        ++g_nworst;
        g_worst[i].what = what;
        g_worst[i].line = line;
        g_worst[i].ref = ref;
        g_worst[i].ratio = -1;
    }
    if (ratio > g_worst[i].ratio) {
        g_worst[i].err = err;
        g_worst[i].tol = tol;
        g_worst[i].ratio = ratio;
    }
}

/* CHECK_NEAR, remembering the worst err/bound for the verbose report:
   NEAR checks the library, NEAR_REF a reference against another answer */
#define NEAR(a, b, tol)                                                 \
    do {                                                                \
        note(#a, __LINE__, 0, (double)(a), (double)(b), (double)(tol)); \
        CHECK_NEAR(a, b, tol);                                          \
    } while (0)
#define NEAR_REF(a, b, tol)                                             \
    do {                                                                \
        note(#a, __LINE__, 1, (double)(a), (double)(b), (double)(tol)); \
        CHECK_NEAR(a, b, tol);                                          \
    } while (0)

static void run(const char *name, void (*fn)(void))
{
    int i;
    g_nworst = 0;
    test_run(name, fn);
    if (!verbose() || g_nworst == 0) return;
    printf("%s (%s):\n", name, REAL_NAME);
    for (i = 0; i < g_nworst; ++i)
        printf("  %s line %d %-44s worst |err| %-9.3g bound %-9.3g ratio %.3g\n", g_worst[i].ref ? "ref" : "lib",
               g_worst[i].line, g_worst[i].what, g_worst[i].err, g_worst[i].tol, g_worst[i].ratio);
}

/* ---------------------------------------------------------------- helpers */
static int same_real(ga2d_real a, ga2d_real b) { return memcmp(&a, &b, sizeof a) == 0; }

static int same_mass(ga2d_mass a, ga2d_mass b)
{
    return same_real(a.mass, b.mass) && same_real(a.center.x, b.center.x) && same_real(a.center.y, b.center.y) &&
           same_real(a.inertia, b.inertia);
}

static int mass_is_zero(ga2d_mass m)
{
    ga2d_mass z;
    memset(&z, 0, sizeof z);
    return same_mass(m, z);
}

static double dmax(double a, double b) { return a > b ? a : b; }

typedef struct bounds { double mass, center, inertia; } bounds;

/* From the errors dA, dM, dJ (per unit density) of the area, the first
   moment and the second moment about a point o, the area A, the radius
   rho about o that holds the shape, |C| and the rounding unit u: the
   errors of mass, centre (per component) and inertia (file comment). */
static bounds assemble(double dA, double dM, double dJ, double A, double rho, double absC, double density, double u)
{
    bounds b;
    b.mass = density * (dA + u * A);
    b.center = (dM + rho * dA) / A + 3 * u * rho + u * absC;
    b.inertia = density * (dJ + 2 * rho * dM + 3 * rho * rho * dA + 12 * u * A * rho * rho);
    return b;
}

/* the library's model for a rounded (or sharp, r = 0) polygon of n
   vertices, R from its vertex mean, area A, centre at |C| */
static bounds lib_bounds(int n, double R, double r, double A, double absC, double density)
{
    double u = U_LIB, rho = R + r, k = 2.0 * n + 2;
    double dA = 16 * n * u * rho * rho + k * u * A;
    double dM = 38 * n * u * rho * rho * rho + k * u * A * rho;
    double dJ = 48 * n * u * rho * rho * rho * rho + k * u * A * rho * rho;
    return assemble(dA, dM, dJ, A, rho, absC, density, u);
}

/* R of the model: the farthest vertex from the vertex mean, plus what
   rounding the library's mean (n products and sums) can move it by */
static double spread(const ga2d_polygon *p)
{
    double mx = 0, my = 0, R = 0, big = 0;
    int i, n = p->count;
    for (i = 0; i < n; ++i) {
        mx += (double)p->vertices[i].x / n;
        my += (double)p->vertices[i].y / n;
    }
    for (i = 0; i < n; ++i) {
        double d = hypot((double)p->vertices[i].x - mx, (double)p->vertices[i].y - my);
        R = dmax(R, d);
        big = dmax(big, dmax(fabs((double)p->vertices[i].x), fabs((double)p->vertices[i].y)));
    }
    return R + (n + 2) * U_LIB * big * 2;
}

/* ---------------------------------------------------- outline reference */
typedef struct ref_mass {
    double area, cx, cy, inertia; /* per unit density */
    bounds err;                   /* discretisation + rounding, unit density */
} ref_mass;

typedef struct fan { double fx, fy, px, py, a2, mx, my, j; long count; } fan;

/* adds the fan triangle (o, previous point, d) */
static void fan_add(fan *f, double dx, double dy)
{
    if (f->count++ == 0) {
        f->fx = f->px = dx;
        f->fy = f->py = dy;
        return;
    }
    {
        double ex = dx - f->px, ey = dy - f->py, c = f->px * ey - f->py * ex;
        f->a2 += c;
        f->mx += c * (f->px + dx);
        f->my += c * (f->py + dy);
        f->j += c * (f->px * f->px + f->py * f->py + f->px * dx + f->py * dy + dx * dx + dy * dy);
        f->px = dx;
        f->py = dy;
    }
}

/* angle of the outward normal (e.y, -e.x) of the edge a -> b */
static double normal_angle(double ax, double ay, double bx, double by) { return atan2(-(bx - ax), by - ay); }

enum { CHORDS = 0, EXACT = 1 };

/* Mass properties (unit density) of the core x[0..n-1], y (see the file
   comment) swept by a disc of radius r: CHORDS integrates the chord
   polygon of the outline, EXACT takes one chord an arc and adds the
   circular segments' closed forms. */
static ref_mass outline_mass(const double *x, const double *y, int n, double r, int mode)
{
    ref_mass out;
    fan f;
    double ox = 0, oy = 0, Ro = 0, rho_o, rho_c = 0, dA_disc = 0, sa = 0, smx = 0, smy = 0, sj = 0;
    double A, Mx, My, J, cx, cy, emA, emM, emJ;
    long terms;
    int i;
    memset(&f, 0, sizeof f);
    for (i = 0; i < n; ++i) {
        ox += x[i] / n;
        oy += y[i] / n;
    }
    for (i = 0; i < n; ++i) Ro = dmax(Ro, hypot(x[i] - ox, y[i] - oy));
    for (i = 0; i < n; ++i) {
        int ip = (i + 1) % n, im = (i + n - 1) % n, k, j;
        double phi0 = 0, alpha = 2 * PI, dvx = x[i] - ox, dvy = y[i] - oy;
        if (n > 1) {
            phi0 = normal_angle(x[im], y[im], x[i], y[i]);
            alpha = normal_angle(x[i], y[i], x[ip], y[ip]) - phi0;
            while (alpha <= 0) alpha += 2 * PI;
            while (alpha > 2 * PI) alpha -= 2 * PI;
        }
        k = r > 0 ? (mode == EXACT ? 1 : (int)ceil(alpha / THETA_MAX)) : 0;
        for (j = 0; j <= k; ++j) {
            double t = k > 0 ? phi0 + alpha * j / k : phi0;
            fan_add(&f, dvx + r * cos(t), dvy + r * sin(t));
        }
        if (k == 0) continue;
        if (mode == CHORDS) {
            dA_disc += k * r * r * pow(alpha / k, 3) / 12;
        } else {
            /* the segment between the arc and its chord, angle th, about
               the arc's centre v: area r^2 (th - sin th)/2, first moment
               2/3 r^3 sin^3(th/2) along the bisector w (sector less
               triangle), polar moment r^4 th/4 - r^4 sin th (2 + cos th)/12;
               moved to o by parallel axes */
            double th = alpha, s = sin(th / 2), wx = cos(phi0 + th / 2), wy = sin(phi0 + th / 2);
            double a = r * r * (th - sin(th)) / 2, mv = 2 * r * r * r * s * s * s / 3;
            double jv = r * r * r * r * (3 * th - sin(th) * (2 + cos(th))) / 12;
            sa += a;
            smx += a * dvx + mv * wx;
            smy += a * dvy + mv * wy;
            sj += jv + 2 * mv * (wx * dvx + wy * dvy) + a * (dvx * dvx + dvy * dvy);
        }
    }
    fan_add(&f, f.fx, f.fy); /* close the loop */
    A = f.a2 / 2 + sa;
    Mx = f.mx / 6 + smx;
    My = f.my / 6 + smy;
    J = f.j / 12 + sj;
    cx = Mx / A;
    cy = My / A;
    out.area = A;
    out.cx = ox + cx;
    out.cy = oy + cy;
    out.inertia = J - A * (cx * cx + cy * cy);
    /* rounding: each X_m within (N + 64) pi U rho_o^(2+m), assembled */
    terms = f.count + (mode == EXACT ? n : 0);
    rho_o = Ro + r;
    emA = (double)(terms + 64) * PI * U_REF * rho_o * rho_o;
    emM = emA * rho_o;
    emJ = emM * rho_o;
    out.err = assemble(emA, emM, emJ, A, rho_o, hypot(out.cx, out.cy), 1, U_REF);
    /* discretisation, with rho_c measured from the computed centroid (off
       C_Q by at most out.err.center per component) */
    for (i = 0; i < n; ++i) rho_c = dmax(rho_c, hypot(x[i] - out.cx, y[i] - out.cy));
    rho_c += r + 2 * out.err.center;
    out.err.mass += dA_disc;
    out.err.center += dA_disc * rho_c / A;
    out.err.inertia += dA_disc * rho_c * rho_c;
    return out;
}

/* The library's answer m (at density) against both references, and the
   references against each other: every pair within the sum of their
   bounds.  Returns the exact reference. */
static ref_mass check_outline(ga2d_mass m, const double *x, const double *y, int n, double r, bounds lib, double density)
{
    ref_mass q = outline_mass(x, y, n, r, CHORDS), e = outline_mass(x, y, n, r, EXACT);
    NEAR_REF(q.area, e.area, q.err.mass + e.err.mass);
    NEAR_REF(q.cx, e.cx, q.err.center + e.err.center);
    NEAR_REF(q.cy, e.cy, q.err.center + e.err.center);
    NEAR_REF(q.inertia, e.inertia, q.err.inertia + e.err.inertia);
    NEAR(m.mass, density * q.area, lib.mass + density * q.err.mass);
    NEAR(m.center.x, q.cx, lib.center + q.err.center);
    NEAR(m.center.y, q.cy, lib.center + q.err.center);
    NEAR(m.inertia, density * q.inertia, lib.inertia + density * q.err.inertia);
    NEAR(m.mass, density * e.area, lib.mass + density * e.err.mass);
    NEAR(m.center.x, e.cx, lib.center + e.err.center);
    NEAR(m.center.y, e.cy, lib.center + e.err.center);
    NEAR(m.inertia, density * e.inertia, lib.inertia + density * e.err.inertia);
    return e;
}

/* the exact reference of a polygon's rounded shape (for the magnitudes
   the bounds need) */
static ref_mass outline_mass_of(const ga2d_polygon *p, double r)
{
    double x[MAXV], y[MAXV];
    int i;
    for (i = 0; i < p->count; ++i) {
        x[i] = (double)p->vertices[i].x;
        y[i] = (double)p->vertices[i].y;
    }
    return outline_mass(x, y, p->count, r, EXACT);
}

static ref_mass check_polygon_outline(ga2d_mass m, const ga2d_polygon *p, double r, bounds lib, double density)
{
    double x[MAXV], y[MAXV];
    int i;
    for (i = 0; i < p->count; ++i) {
        x[i] = (double)p->vertices[i].x;
        y[i] = (double)p->vertices[i].y;
    }
    return check_outline(m, x, y, p->count, r, lib, density);
}

/* A random convex polygon: the hull of random points, kept if valid. */
static ga2d_polygon random_convex(test_rng *rng, double size, double cx, double cy)
{
    ga2d_vec pts[16];
    ga2d_polygon p;
    for (;;) {
        int n = rng_int(rng, 3, MAXV < 12 ? MAXV + 2 : 12), i;
        for (i = 0; i < n; ++i)
            pts[i] = ga2d_vec_make((ga2d_real)(cx + size * rng_uniform(rng, -1, 1)),
                                   (ga2d_real)(cy + size * rng_uniform(rng, -0.6, 0.6)));
        if (ga2d_polygon_hull(pts, n, &p) == GA2D_OK) return p;
    }
}

static ga2d_polygon make(const ga2d_vec *pts, int n)
{
    ga2d_polygon p;
    memset(&p, 0, sizeof p);
    CHECK_RESULT(ga2d_polygon_make(pts, n, &p), GA2D_OK);
    return p;
}

static double perimeter(const ga2d_polygon *p)
{
    double P = 0;
    int i;
    for (i = 0; i < p->count; ++i) {
        ga2d_vec a = p->vertices[i], b = p->vertices[(i + 1) % p->count];
        P += hypot((double)b.x - (double)a.x, (double)b.y - (double)a.y);
    }
    return P;
}

static double core_area(const ga2d_polygon *p)
{
    double a2 = 0;
    int i;
    for (i = 1; i + 1 < p->count; ++i) {
        double x1 = (double)p->vertices[i].x - (double)p->vertices[0].x;
        double y1 = (double)p->vertices[i].y - (double)p->vertices[0].y;
        double x2 = (double)p->vertices[i + 1].x - (double)p->vertices[0].x;
        double y2 = (double)p->vertices[i + 1].y - (double)p->vertices[0].y;
        a2 += x1 * y2 - y1 * x2;
    }
    return a2 / 2;
}

/* ---------------------------------------------------------------- circle */
/* m = rho pi r^2 and I = m r^2 / 2: the library rounds pi and takes three
   products for m (4 u), two more for I (6 u); the double reference the
   same counts in U.  The centre is the given one, bit for bit. */
static void circle_closed_form(void)
{
    /* the smallest radius whose inertia (r^4 pi/2 at density >= 1) stays
       a normal number, with 16x room: 2 REAL_MIN^(1/4); the largest a
       coordinate may be */
    const double radii[] = {2 * pow(REAL_MIN, 0.25), 1e-3, 0.5, 1, 7.25, 1e3, (double)GA2D_MAX_COORDINATE};
    const double densities[] = {1, 2.5, 1000};
    const double centres[][2] = {{0, 0}, {0.375, -2.5}, {FAR, -FAR}, {-FAR, 0.5 * FAR}};
    size_t i, j, k;
    for (i = 0; i < sizeof radii / sizeof radii[0]; ++i)
        for (j = 0; j < sizeof densities / sizeof densities[0]; ++j) {
            ga2d_circle c0;
            ga2d_mass m0;
            double r, rho, m, I;
            c0.center = ga2d_vec_make(0, 0);
            c0.radius = (ga2d_real)radii[i];
            r = (double)c0.radius;
            rho = (double)(ga2d_real)densities[j];
            CHECK_RESULT(ga2d_circle_mass_checked(&c0, (ga2d_real)rho, &m0), GA2D_OK);
            m = rho * PI * r * r;
            I = m * r * r / 2;
            NEAR(m0.mass, m, (4 * U_LIB + 4 * U_REF) * m);
            NEAR(m0.inertia, I, (6 * U_LIB + 6 * U_REF) * I);
            for (k = 0; k < sizeof centres / sizeof centres[0]; ++k) {
                ga2d_circle c = c0;
                ga2d_mass mk;
                c.center = ga2d_vec_make((ga2d_real)centres[k][0], (ga2d_real)centres[k][1]);
                mk = ga2d_circle_mass(&c, (ga2d_real)rho);
                /* far away or not, the same products: the same bits */
                CHECK(same_real(mk.mass, m0.mass) && same_real(mk.inertia, m0.inertia));
                CHECK(same_real(mk.center.x, c.center.x) && same_real(mk.center.y, c.center.y));
            }
        }
    /* radius 0: no area */
    {
        ga2d_circle c;
        ga2d_mass m;
        c.center = ga2d_vec_make(1, 2);
        c.radius = 0;
        CHECK_RESULT(ga2d_circle_mass_checked(&c, 3, &m), GA2D_OK);
        CHECK(m.mass == 0 && m.inertia == 0 && m.center.x == 1 && m.center.y == 2);
    }
}

/* Both outline references on a disc (a core of one point) against the
   closed form, where the answer is known (pi r^2: 4 U, pi r^4/2: 6 U),
   and the library against them. */
static void circle_outline_reference(void)
{
    const double cases[][3] = {{0, 0, 1}, {0.375, -2.5, 0.125}, {FAR, -FAR, 3.5}};
    size_t k;
    int mode;
    for (k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        ga2d_circle c;
        ga2d_mass m;
        bounds lib;
        double x, y, r;
        c.center = ga2d_vec_make((ga2d_real)cases[k][0], (ga2d_real)cases[k][1]);
        c.radius = (ga2d_real)cases[k][2];
        x = (double)c.center.x;
        y = (double)c.center.y;
        r = (double)c.radius;
        for (mode = CHORDS; mode <= EXACT; ++mode) {
            ref_mass ref = outline_mass(&x, &y, 1, r, mode);
            NEAR_REF(ref.area, PI * r * r, ref.err.mass + 4 * U_REF * PI * r * r);
            NEAR_REF(ref.cx, x, ref.err.center);
            NEAR_REF(ref.cy, y, ref.err.center);
            NEAR_REF(ref.inertia, PI * r * r * r * r / 2, ref.err.inertia + 6 * U_REF * PI * r * r * r * r / 2);
        }
        m = ga2d_circle_mass(&c, 1);
        lib.mass = 4 * U_LIB * PI * r * r;
        lib.center = 0; /* the given centre */
        lib.inertia = 6 * U_LIB * PI * r * r * r * r / 2;
        check_outline(m, &x, &y, 1, r, lib, 1);
    }
}

/* --------------------------------------------------------------- capsule */
/* Library capsule roundings (u): L by ga2d_vec_length of the rounded
   c2 - c1, <= 5; m_rect = rho L 2 r, 7; m_half = rho pi r r / 2, 4;
   mass 8.  d0 = 4 r/(3 pi), 3; the rectangle's term 21, the half discs'
   18, the inertia 22.  The centre c1 + (c2 - c1)/2: u |c2 - c1|/2 + u |C|. */
static bounds capsule_bounds(double L, double r, double absC, double density)
{
    bounds b;
    double m = density * (2 * r * L + PI * r * r), d0 = 4 * r / (3 * PI);
    double I = density * (2 * r * L * (L * L + 4 * r * r) / 12 + PI * r * r * (r * r / 2 + L * L / 4 + L * d0));
    b.mass = 8 * U_LIB * m;
    b.center = U_LIB * (L / 2 + absC);
    b.inertia = 22 * U_LIB * I;
    return b;
}

static ga2d_capsule capsule(double x1, double y1, double x2, double y2, double r)
{
    ga2d_capsule c;
    c.center1 = ga2d_vec_make((ga2d_real)x1, (ga2d_real)y1);
    c.center2 = ga2d_vec_make((ga2d_real)x2, (ga2d_real)y2);
    c.radius = (ga2d_real)r;
    return c;
}

/* Capsules against the outline integration of their true outline (two
   half circles joined by two segments), and m = rho (2 r L + pi r^2). */
static void capsule_against_outline(void)
{
    test_rng rng = {77};
    int t;
    for (t = 0; t < 24; ++t) {
        double size = pow(10.0, rng_uniform(&rng, -2, 2)), ang = rng_uniform(&rng, 0, 2 * PI);
        double L = size * rng_uniform(&rng, 0.01, 3), r = size * rng_uniform(&rng, 0.02, 1.5);
        double ox = t % 3 == 0 ? FAR : rng_uniform(&rng, -3, 3) * size, oy = t % 3 == 0 ? -FAR : rng_uniform(&rng, -3, 3) * size;
        double density = t % 2 ? 1 : (double)(ga2d_real)rng_uniform(&rng, 0.1, 10);
        ga2d_capsule c = capsule(ox - L / 2 * cos(ang), oy - L / 2 * sin(ang), ox + L / 2 * cos(ang), oy + L / 2 * sin(ang), r);
        double x[2], y[2], Ls, rs;
        ga2d_mass m;
        ref_mass ref;
        x[0] = (double)c.center1.x;
        y[0] = (double)c.center1.y;
        x[1] = (double)c.center2.x;
        y[1] = (double)c.center2.y;
        Ls = hypot(x[1] - x[0], y[1] - y[0]); /* the stored segment's length */
        rs = (double)c.radius;
        CHECK_RESULT(ga2d_capsule_mass_checked(&c, (ga2d_real)density, &m), GA2D_OK);
        ref = outline_mass(x, y, 2, rs, EXACT); /* for |C| in the bound */
        check_outline(m, x, y, 2, rs, capsule_bounds(Ls, rs, hypot(ref.cx, ref.cy), density), density);
        /* rectangle 2r x L plus a disc; the double form within 8 U (hypot
           <= 1 ulp, the differences, 4 products and 2 sums) */
        NEAR(m.mass, density * (2 * rs * Ls + PI * rs * rs),
             capsule_bounds(Ls, rs, 0, density).mass + 8 * U_REF * density * (2 * rs * Ls + PI * rs * rs));
    }
}

/* Limits and invariances. */
static void capsule_limits(void)
{
    const double radii[] = {0.125, 1, 3.75, 1e3};
    size_t i;
    for (i = 0; i < sizeof radii / sizeof radii[0]; ++i) {
        double r = radii[i];
        ga2d_capsule c0 = capsule(FAR, 0.5, FAR, 0.5, r), cz;
        ga2d_circle disc;
        ga2d_mass mc, md;
        /* zero length is the disc: the same mass and centre bits (the
           rectangle adds an exact 0, 2 m_half = m exactly), the inertia
           m (r r)/2 against ((m r) r)/2: two roundings each side, 4 u I */
        disc.center = c0.center1;
        disc.radius = c0.radius;
        mc = ga2d_capsule_mass(&c0, (ga2d_real)2.5);
        md = ga2d_circle_mass(&disc, (ga2d_real)2.5);
        CHECK(same_real(mc.mass, md.mass));
        CHECK(same_real(mc.center.x, md.center.x) && same_real(mc.center.y, md.center.y));
        NEAR(mc.inertia, md.inertia, 4 * U_LIB * (double)md.inertia);
        /* radius 0: no area, whatever the length */
        cz = capsule(-1, 2, 3 * r, -r, 0);
        CHECK_RESULT(ga2d_capsule_mass_checked(&cz, 7, &mc), GA2D_OK);
        CHECK(mc.mass == 0 && mc.inertia == 0);
    }
    /* swapping the ends: the length is |e| of e negated, the same bits;
       the centre c1 + (c2 - c1)/2 or c2 + (c1 - c2)/2, each within
       u (|e|/2 + |C|) per component of the midpoint */
    {
        test_rng rng = {5};
        int t;
        for (t = 0; t < 50; ++t) {
            double s = pow(10.0, rng_uniform(&rng, -2, 2));
            ga2d_capsule a = capsule(rng_uniform(&rng, -3, 3) * s + (t % 2 ? FAR : 0), rng_uniform(&rng, -3, 3) * s,
                                     rng_uniform(&rng, -3, 3) * s + (t % 2 ? FAR : 0), rng_uniform(&rng, -3, 3) * s,
                                     s * rng_uniform(&rng, 0.01, 2)),
                         b = a;
            ga2d_mass ma, mb;
            double L, mx, my;
            b.center1 = a.center2;
            b.center2 = a.center1;
            ma = ga2d_capsule_mass(&a, (ga2d_real)1.5);
            mb = ga2d_capsule_mass(&b, (ga2d_real)1.5);
            CHECK(same_real(ma.mass, mb.mass) && same_real(ma.inertia, mb.inertia));
            L = hypot((double)a.center2.x - (double)a.center1.x, (double)a.center2.y - (double)a.center1.y);
            mx = ((double)a.center1.x + (double)a.center2.x) / 2;
            my = ((double)a.center1.y + (double)a.center2.y) / 2;
            NEAR(ma.center.x, mx, U_LIB * (L / 2 + fabs(mx)) + U_REF * fabs(mx));
            NEAR(mb.center.x, mx, U_LIB * (L / 2 + fabs(mx)) + U_REF * fabs(mx));
            NEAR(ma.center.y, my, U_LIB * (L / 2 + fabs(my)) + U_REF * fabs(my));
            NEAR(mb.center.y, my, U_LIB * (L / 2 + fabs(my)) + U_REF * fabs(my));
        }
    }
    /* Rotations with exact images: directions (3,4)/5, (5,12)/13, (8,15)/17,
       the axes, scaled by a power of 2 so that every coordinate, square
       and root is exact, and translated by exactly representable amounts.
       The library sees the same length: mass and inertia bit for bit,
       the centre exactly the translated midpoint. */
    {
        const double dirs[][3] = {{1, 0, 1}, {0, 1, 1}, {-1, 0, 1}, {0, -1, 1}, {3, 4, 5}, {-4, 3, 5}, {-12, -5, 13}, {15, -8, 17}};
        const double shifts[][2] = {{0, 0}, {0.25, -0.5}, {FAR, FAR}, {-FAR, 0.125}};
        size_t d, s;
        for (d = 0; d < sizeof dirs / sizeof dirs[0]; ++d)
            for (s = 0; s < sizeof shifts / sizeof shifts[0]; ++s) {
                double k = 0.125, hl = dirs[d][2] * k; /* half length: 5/8 for (3,4,5) */
                ga2d_capsule base = capsule(-hl, 0, hl, 0, 0.375);
                ga2d_capsule c = capsule(shifts[s][0] - dirs[d][0] * k, shifts[s][1] - dirs[d][1] * k,
                                         shifts[s][0] + dirs[d][0] * k, shifts[s][1] + dirs[d][1] * k, 0.375);
                ga2d_mass mb = ga2d_capsule_mass(&base, 2), mc = ga2d_capsule_mass(&c, 2);
                CHECK(same_real(mb.mass, mc.mass) && same_real(mb.inertia, mc.inertia));
                CHECK((double)mc.center.x == shifts[s][0] && (double)mc.center.y == shifts[s][1]);
            }
    }
    /* Any rotation: rounding the turned ends changes L (measured on the
       stored ends, in double within 4 U L: the differences and hypot);
       mass and inertia move by what the closed form says a length change
       does, within both sides' rounding (8 u m and 22 u I each), the
       double closed forms' (the same counts in U; the masses' difference
       is exact, Sterbenz), and m'(L) = 2 rho r, I'(L) <= I'(max L), times
       the error of L. */
    {
        test_rng rng = {9};
        int t;
        double L0 = 1.75, r = 0.625, rho = 2, d0 = 4 * r / (3 * PI);
        ga2d_capsule base = capsule(-L0 / 2, 0, L0 / 2, 0, r);
        ga2d_mass mb = ga2d_capsule_mass(&base, (ga2d_real)rho);
        for (t = 0; t < 40; ++t) {
            double a = rng_uniform(&rng, 0, 2 * PI), tx = t % 2 ? FAR : 1.5, ty = t % 2 ? -FAR : 0.25;
            ga2d_capsule c = capsule(tx - L0 / 2 * cos(a), ty - L0 / 2 * sin(a), tx + L0 / 2 * cos(a), ty + L0 / 2 * sin(a), r);
            ga2d_mass mc = ga2d_capsule_mass(&c, (ga2d_real)rho);
            double L = hypot((double)c.center2.x - (double)c.center1.x, (double)c.center2.y - (double)c.center1.y);
            double Lm = dmax(L, L0) * (1 + 4 * U_REF);
            bounds b = capsule_bounds(Lm, r, 0, rho);
            double I = b.inertia / (22 * U_LIB);
            double dI = rho * (2 * r * (3 * Lm * Lm + 4 * r * r) / 12 + PI * r * r * (Lm / 2 + d0)); /* I'(Lm) */
            double I1 = rho * (2 * r * L * (L * L + 4 * r * r) / 12 + PI * r * r * (r * r / 2 + L * L / 4 + L * d0));
            double I0 = rho * (2 * r * L0 * (L0 * L0 + 4 * r * r) / 12 + PI * r * r * (r * r / 2 + L0 * L0 / 4 + L0 * d0));
            NEAR((double)mc.mass - (double)mb.mass, rho * 2 * r * (L - L0),
                 2 * b.mass + rho * 2 * r * (4 * U_REF * Lm + 4 * U_REF * fabs(L - L0)));
            NEAR((double)mc.inertia - (double)mb.inertia, I1 - I0, 2 * b.inertia + 44 * U_REF * I + dI * 4 * U_REF * Lm);
            /* |C| <= |t| + L; the double midpoint within U |C| */
            NEAR(mc.center.x, ((double)c.center1.x + (double)c.center2.x) / 2, (U_LIB + U_REF) * (fabs(tx) + L) + U_LIB * L / 2);
            NEAR(mc.center.y, ((double)c.center1.y + (double)c.center2.y) / 2, (U_LIB + U_REF) * (fabs(ty) + L) + U_LIB * L / 2);
        }
    }
}

/* ------------------------------------------------------ rounded polygons */
/* The rounded box as the box 2hw x 2hh minus four corner spandrels (an
   r x r square less a quarter disc), about the origin (the centroid, by
   symmetry): polar moments
     box          4 hw hh (hw^2 + hh^2)/3
     square       r^2 (r^2/6 + (hw - r/2)^2 + (hh - r/2)^2)
     quarter disc pi r^4/8 + 2 (cx + cy) r^3/3 + pi r^2/4 (cx^2 + cy^2)
   (its centroid 4r/(3 pi) from its centre along each axis: first moment
   r^3/3 each).  Area 4 hw hh - (4 - pi) r^2.  In double: each piece <= 12
   roundings, the combination 2 more, so within 16 U of the pieces' sum. */
static void rounded_box_closed_form(void)
{
    const double boxes[][3] = {{1, 0.5, 0.25}, {2, 2, 1.5}, {0.75, 3, 0.5}, {1, 1, 0}, {1.5, 0.5, 0.5 - 1.0 / 1024},
                               {1e-3, 2e-3, 4e-4}, {1e3, 500, 100}, {5, 0.25, 0.125}};
    size_t k;
    for (k = 0; k < sizeof boxes / sizeof boxes[0]; ++k) {
        ga2d_polygon p;
        ga2d_mass m;
        double r, cx, cy, hw, hh, A, Jbox, Jsq, Jqd, I, eA, eI;
        const double density = 1.25;
        CHECK_RESULT(ga2d_polygon_rounded_box_checked((ga2d_real)boxes[k][0], (ga2d_real)boxes[k][1],
                                                      (ga2d_real)boxes[k][2], &p),
                     GA2D_OK);
        CHECK(p.count == 4);
        /* the shape as stored: the core corner (cx, cy) rounded, then r */
        r = (double)p.radius;
        cx = (double)p.vertices[2].x;
        cy = (double)p.vertices[2].y;
        hw = cx + r;
        hh = cy + r;
        A = 4 * hw * hh - (4 - PI) * r * r;
        Jbox = 4 * hw * hh * (hw * hw + hh * hh) / 3;
        Jsq = r * r * (r * r / 6 + (hw - r / 2) * (hw - r / 2) + (hh - r / 2) * (hh - r / 2));
        Jqd = PI * r * r * r * r / 8 + 2 * (cx + cy) * r * r * r / 3 + PI * r * r / 4 * (cx * cx + cy * cy);
        I = Jbox - 4 * (Jsq - Jqd);
        /* (4 - pi) carries pi's rounding, pi U / (4 - pi) < 3.7 U of it */
        eA = 8 * U_REF * (4 * hw * hh + (4 - PI) * r * r);
        eI = 16 * U_REF * (Jbox + 4 * Jsq + 4 * Jqd);
        CHECK_RESULT(ga2d_polygon_mass_checked(&p, (ga2d_real)density, &m), GA2D_OK);
        {
            bounds b = lib_bounds(4, spread(&p), r, A, 0, density);
            ref_mass ref;
            NEAR(m.mass, density * A, b.mass + density * eA);
            NEAR(m.center.x, 0, b.center);
            NEAR(m.center.y, 0, b.center);
            NEAR(m.inertia, density * I, b.inertia + density * eI);
            /* and the outline references agree with the closed form */
            ref = check_polygon_outline(m, &p, r, b, density);
            NEAR_REF(ref.area, A, ref.err.mass + eA);
            NEAR_REF(ref.inertia, I, ref.err.inertia + eI);
        }
    }
}

/* Rounded convex polygons of every kind against the outline reference,
   and their area A + r P + pi r^2 (Steiner).  Radii from 1 % of the size
   to twice it, cores from needles to near-discs, some far away. */
static void rounded_polygon_against_outline(void)
{
    test_rng rng = {2024};
    int t;
    for (t = 0; t < 40; ++t) {
        double size = pow(10.0, rng_uniform(&rng, -2, 2)), far = t % 4 == 3 ? FAR : 0;
        ga2d_polygon p = random_convex(&rng, size, rng_uniform(&rng, -3, 3) * size + far, rng_uniform(&rng, -3, 3) * size - far);
        double r, density = t % 2 ? 1 : (double)(ga2d_real)rng_uniform(&rng, 0.1, 10), A;
        ga2d_mass m;
        ref_mass ref;
        bounds b;
        p.radius = (ga2d_real)(size * pow(10.0, rng_uniform(&rng, -2, 0.3)));
        r = (double)p.radius;
        CHECK_RESULT(ga2d_polygon_mass_checked(&p, (ga2d_real)density, &m), GA2D_OK);
        ref = outline_mass_of(&p, r);
        b = lib_bounds(p.count, spread(&p), r, ref.area, hypot(ref.cx, ref.cy), density);
        check_polygon_outline(m, &p, r, b, density);
        /* Steiner: A + r P + pi r^2.  In double: the core's fan from
           vertex 0 (n - 2 wedges of sides <= 2R, 4 U (2R)^2 each, and
           their sum, n U A), P (n hypots of rounded differences, 3 U each,
           and the sum: (n + 3) U P) times r, pi r^2 (3 U), two sums and
           the density: 8 n U R^2 + (2n + 10) U A */
        A = core_area(&p) + r * perimeter(&p) + PI * r * r;
        NEAR(m.mass, density * A, b.mass + density * U_REF * (8 * p.count * spread(&p) * spread(&p) + (2.0 * p.count + 10) * A));
    }
    /* hand-picked: a sharp spike (one corner's arc nearly a half turn), a
       regular polygon and a tiny core in a big disc */
    {
        ga2d_vec spike[3];
        ga2d_polygon ps[3];
        int i;
        spike[0] = ga2d_vec_make(0, 0);
        spike[1] = ga2d_vec_make(4, (ga2d_real)0.25);
        spike[2] = ga2d_vec_make(0, (ga2d_real)0.5);
        ps[0] = make(spike, 3);
        ps[0].radius = (ga2d_real)0.3;
        ps[1] = ga2d_polygon_regular(MAXV < 8 ? MAXV : 8, (ga2d_real)1.5);
        ps[1].radius = (ga2d_real)0.5;
        ps[2] = ga2d_polygon_regular(3, (ga2d_real)1e-2);
        ps[2].radius = (ga2d_real)2;
        for (i = 0; i < 3; ++i) {
            ga2d_mass m = ga2d_polygon_mass(&ps[i], 1);
            ref_mass ref = outline_mass_of(&ps[i], (double)ps[i].radius);
            bounds b = lib_bounds(ps[i].count, spread(&ps[i]), (double)ps[i].radius, ref.area, hypot(ref.cx, ref.cy), 1);
            check_polygon_outline(m, &ps[i], (double)ps[i].radius, b, 1);
            if (i > 0) { /* symmetric about the origin: centroid there */
                NEAR(m.center.x, 0, b.center);
                NEAR(m.center.y, 0, b.center);
            }
        }
    }
}

/* The sharp formula as it was before radii (the commit before 54e9c63),
   in the same operations: radius 0 must give its bits. */
static ga2d_mass sharp_mass_before_radii(const ga2d_polygon *p, ga2d_real density)
{
    ga2d_vec ref = ga2d_vec_make(0, 0), moment = ga2d_vec_make(0, 0), rel;
    ga2d_real area2 = 0, j12 = 0, area, inertia;
    ga2d_mass m;
    int i, n = p->count;
    for (i = 0; i < n; ++i) ref = ga2d_vec_add(ref, ga2d_vec_scale(p->vertices[i], 1 / (ga2d_real)n));
    for (i = 0; i < n; ++i) {
        ga2d_vec d0 = ga2d_vec_sub(p->vertices[i], ref);
        ga2d_vec d1 = ga2d_vec_sub(p->vertices[(i + 1) % n], ref);
        ga2d_real c = ga2d_wedge(d0, d1);
        area2 += c;
        moment = ga2d_vec_add(moment, ga2d_vec_scale(ga2d_vec_add(d0, d1), c));
        j12 += c * (ga2d_dot(d0, d0) + ga2d_dot(d0, d1) + ga2d_dot(d1, d1));
    }
    area = area2 / 2;
    rel = ga2d_vec_scale(moment, 1 / (3 * area2));
    inertia = j12 / 12 - area * ga2d_vec_length_sq(rel);
    m.mass = density * area;
    m.center = ga2d_vec_add(ref, rel);
    m.inertia = density * inertia;
    return m;
}

/* r -> 0.  Radius 0 is the sharp polygon, bit for bit.  For r > 0 the
   shape S_r contains S_0 and adds dA = r P + pi r^2 (Steiner), so with
   rho_c = max |v - C_0| + r:
     mass:    m_r - m_0 = rho dA
     centre:  |C_r - C_0| = |int_{S_r\S_0} (x - C_0)| / A_r <= dA rho_c / A_r
     inertia: I_r <= J_{C_0}(S_r) = I_0 + int |x - C_0|^2 <= I_0 + dA rho_c^2,
              I_r = J_{C_r}(S_r) >= J_{C_r}(S_0) >= I_0,
   each within both sides' rounding bounds.  Down to r = R 2^-40, far
   below rounding: the rounded result converges on the sharp one. */
static void rounded_radius_to_zero(void)
{
    test_rng rng = {404};
    int t;
    for (t = 0; t < 12; ++t) {
        ga2d_polygon p = t == 0 ? ga2d_polygon_box((ga2d_real)1.5, (ga2d_real)0.5)
                                : random_convex(&rng, pow(10.0, rng_uniform(&rng, -1, 1)), rng_uniform(&rng, -3, 3),
                                                t % 3 == 0 ? FAR : rng_uniform(&rng, -3, 3));
        const ga2d_real density = (ga2d_real)2.5;
        ga2d_mass m0 = ga2d_polygon_mass(&p, density);
        double R = spread(&p), P = perimeter(&p), A0 = (double)m0.mass / (double)density, rho_c = 0, rd = (double)density;
        bounds b0 = lib_bounds(p.count, R, 0, A0, hypot((double)m0.center.x, (double)m0.center.y), rd);
        int i, k;
        CHECK(p.radius == 0);
        CHECK(same_mass(m0, sharp_mass_before_radii(&p, density)));
        for (i = 0; i < p.count; ++i)
            rho_c = dmax(rho_c, hypot((double)p.vertices[i].x - (double)m0.center.x, (double)p.vertices[i].y - (double)m0.center.y));
        rho_c += b0.center * 2;
        for (k = 1; k <= 40; ++k) {
            ga2d_polygon q = p;
            ga2d_mass m;
            double r, dA, rc;
            bounds b;
            q.radius = (ga2d_real)ldexp(R, -k);
            r = (double)q.radius;
            dA = r * P + PI * r * r;
            rc = rho_c + r;
            m = ga2d_polygon_mass(&q, density);
            b = lib_bounds(q.count, R, r, A0 + dA, hypot((double)m.center.x, (double)m.center.y), rd);
            /* in double: P within (n + 3) U, the products and the sum 3 U
               more, the difference of the masses U */
            NEAR((double)m.mass - (double)m0.mass, rd * dA, b.mass + b0.mass + rd * (p.count + 7) * U_REF * dA);
            NEAR(m.center.x, m0.center.x, dA * rc / (A0 + dA) + b.center + b0.center);
            NEAR(m.center.y, m0.center.y, dA * rc / (A0 + dA) + b.center + b0.center);
            /* one-sided: I_0 <= I_r <= I_0 + rho dA rc^2 */
            CHECK((double)m.inertia - (double)m0.inertia >= -(b.inertia + b0.inertia));
            CHECK((double)m.inertia - (double)m0.inertia <= rd * dA * rc * rc + b.inertia + b0.inertia);
        }
    }
}

/* Parallel axes: a rounded polygon and the same one translated by T
   (vertices on a 1/64 grid, so the translated vertices are exact) have
   the same mass and inertia about their centres, and centres T apart,
   within both sides' bounds (the far one's centre bound has u |C|). */
static void rounded_translation(void)
{
    const double shifts[][2] = {{FAR, 0}, {0, -FAR}, {FAR, FAR}, {-FAR, 0.5 * FAR}};
    const double angles[] = {0, 1.1, 2.0, 2.9, 4.2, 5.3};
    const double radii[] = {0.0625, 0.5, 3};
    ga2d_vec base[6], moved[6];
    int n = MAXV < 6 ? MAXV : 6, i;
    size_t s, k;
    for (i = 0; i < n; ++i)
        base[i] = ga2d_vec_make((ga2d_real)(floor(64 * 2.0 * cos(angles[i])) / 64), (ga2d_real)(floor(64 * 1.3 * sin(angles[i])) / 64));
    for (k = 0; k < sizeof radii / sizeof radii[0]; ++k) {
        ga2d_polygon p0 = make(base, n), p1;
        ga2d_mass m0, m1;
        bounds b0, b1;
        double r = radii[k], A;
        p0.radius = (ga2d_real)r;
        m0 = ga2d_polygon_mass(&p0, (ga2d_real)0.75);
        A = (double)m0.mass / 0.75;
        b0 = lib_bounds(n, spread(&p0), r, A, hypot((double)m0.center.x, (double)m0.center.y), 0.75);
        for (s = 0; s < sizeof shifts / sizeof shifts[0]; ++s) {
            for (i = 0; i < n; ++i) {
                moved[i] = ga2d_vec_make((ga2d_real)((double)base[i].x + shifts[s][0]), (ga2d_real)((double)base[i].y + shifts[s][1]));
                CHECK((double)moved[i].x - shifts[s][0] == (double)base[i].x); /* exactly representable */
                CHECK((double)moved[i].y - shifts[s][1] == (double)base[i].y);
            }
            p1 = make(moved, n);
            p1.radius = (ga2d_real)r;
            m1 = ga2d_polygon_mass(&p1, (ga2d_real)0.75);
            b1 = lib_bounds(n, spread(&p1), r, A, hypot((double)m1.center.x, (double)m1.center.y), 0.75);
            NEAR(m1.mass, m0.mass, b0.mass + b1.mass);
            NEAR(m1.inertia, m0.inertia, b0.inertia + b1.inertia);
            /* (double) C - T: one more rounding of size |C| in U */
            NEAR((double)m1.center.x - shifts[s][0], m0.center.x, b0.center + b1.center + U_REF * fabs((double)m1.center.x));
            NEAR((double)m1.center.y - shifts[s][1], m0.center.y, b0.center + b1.center + U_REF * fabs((double)m1.center.y));
        }
    }
}

/* -------------------------------------------------------------- bad input */
static void bad_input(void)
{
    const ga2d_real qnan = (ga2d_real)NAN, pinf = (ga2d_real)INFINITY;
    ga2d_circle c;
    ga2d_capsule cap;
    ga2d_polygon p = ga2d_polygon_rounded_box(1, (ga2d_real)0.5, (ga2d_real)0.25);
    ga2d_mass m;
    c.center = ga2d_vec_make(1, 2);
    c.radius = 1;
    cap = capsule(0, 0, 1, 0, 0.5);

    /* circle */
    CHECK_RESULT(ga2d_circle_mass_checked(NULL, 1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_circle_mass_checked(&c, 1, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_circle_mass(NULL, 1)));
    CHECK_RESULT(ga2d_circle_mass_checked(&c, -1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_circle_mass(&c, -1)));
    CHECK_RESULT(ga2d_circle_mass_checked(&c, qnan, &m), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_circle_mass_checked(&c, pinf, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_circle_mass(&c, pinf)));
    c.radius = -1;
    CHECK_RESULT(ga2d_circle_mass_checked(&c, 1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_circle_mass(&c, 1)));
    c.radius = qnan;
    CHECK_RESULT(ga2d_circle_mass_checked(&c, 1, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_circle_mass(&c, 1)));
    c.radius = -pinf;
    CHECK_RESULT(ga2d_circle_mass_checked(&c, 1, &m), GA2D_ERR_NOT_FINITE);
    c.radius = 1;
    c.center.y = pinf;
    CHECK_RESULT(ga2d_circle_mass_checked(&c, 1, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_circle_mass(&c, 1)));
    /* finite input, infinite inertia: r = the largest coordinate and a
       density of 4 REAL_MAX / r^4 make m r^2 = 4 pi REAL_MAX; a quarter
       of REAL_MAX / r^4 keeps every product below pi/4 REAL_MAX */
    c.center.y = 0;
    c.radius = (ga2d_real)GA2D_MAX_COORDINATE;
    {
        double r4 = pow((double)c.radius, 4);
        CHECK_RESULT(ga2d_circle_mass_checked(&c, (ga2d_real)(4 * (REAL_MAX / r4)), &m), GA2D_ERR_TOO_LARGE);
        CHECK(mass_is_zero(ga2d_circle_mass(&c, (ga2d_real)(4 * (REAL_MAX / r4)))));
        CHECK_RESULT(ga2d_circle_mass_checked(&c, (ga2d_real)(REAL_MAX / r4 / 4), &m), GA2D_OK);
    }

    /* capsule */
    CHECK_RESULT(ga2d_capsule_mass_checked(NULL, 1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, 1, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_capsule_mass(NULL, 1)));
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, -2, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_capsule_mass(&cap, -2)));
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, qnan, &m), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, -pinf, &m), GA2D_ERR_NOT_FINITE);
    cap.radius = (ga2d_real)-0.5;
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, 1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_capsule_mass(&cap, 1)));
    cap.radius = pinf;
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, 1, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_capsule_mass(&cap, 1)));
    cap.radius = (ga2d_real)0.5;
    cap.center2.x = qnan;
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, 1, &m), GA2D_ERR_NOT_FINITE);
    cap.center2.x = 1;
    cap.center1.y = -pinf;
    CHECK_RESULT(ga2d_capsule_mass_checked(&cap, 1, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_capsule_mass(&cap, 1)));

    /* polygon */
    CHECK_RESULT(ga2d_polygon_mass_checked(NULL, 1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, 1, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_polygon_mass(NULL, 1)));
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, -1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_polygon_mass(&p, -1)));
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, qnan, &m), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, pinf, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_polygon_mass(&p, pinf)));
    p.radius = (ga2d_real)-0.25;
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, 1, &m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(mass_is_zero(ga2d_polygon_mass(&p, 1)));
    p.radius = qnan;
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, 1, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_polygon_mass(&p, 1)));
    p.radius = pinf;
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, 1, &m), GA2D_ERR_NOT_FINITE);
    CHECK(mass_is_zero(ga2d_polygon_mass(&p, 1)));
    p.radius = (ga2d_real)0.25;
    p.count = 2;
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, 1, &m), GA2D_ERR_TOO_FEW_POINTS);
    CHECK(mass_is_zero(ga2d_polygon_mass(&p, 1)));
    p.count = MAXV + 1;
    CHECK_RESULT(ga2d_polygon_mass_checked(&p, 1, &m), GA2D_ERR_TOO_MANY_POINTS);
    CHECK(mass_is_zero(ga2d_polygon_mass(&p, 1)));
}

/* The makers: regular and rounded box, checked and unchecked. */
static void makers(void)
{
    const ga2d_real qnan = (ga2d_real)NAN, pinf = (ga2d_real)INFINITY;
    ga2d_polygon p, q;
    int i;
    CHECK_RESULT(ga2d_polygon_regular_checked(MAXV + 1, 1, &p), GA2D_ERR_TOO_MANY_POINTS);
    CHECK(p.count == 0);
    CHECK(ga2d_polygon_regular(MAXV + 1, 1).count == 0);
    CHECK_RESULT(ga2d_polygon_regular_checked(2, 1, &p), GA2D_ERR_TOO_FEW_POINTS);
    CHECK(ga2d_polygon_regular(2, 1).count == 0);
    CHECK_RESULT(ga2d_polygon_regular_checked(-1, 1, &p), GA2D_ERR_TOO_FEW_POINTS);
    CHECK_RESULT(ga2d_polygon_regular_checked(4, qnan, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_regular_checked(4, pinf, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_regular_checked(4, 0, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_regular_checked(4, -1, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_regular_checked(4, 1, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_regular_checked(MAXV, 1, &p), GA2D_OK);
    CHECK(p.count == MAXV && p.radius == 0);

    /* rounded box: r must be >= 0 and below both half-extents */
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, (ga2d_real)0.5, (ga2d_real)0.25, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, (ga2d_real)0.5, (ga2d_real)-0.25, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, (ga2d_real)0.5, (ga2d_real)0.5, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, (ga2d_real)0.5, (ga2d_real)0.75, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked((ga2d_real)0.5, 1, (ga2d_real)0.5, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked((ga2d_real)0.5, 1, 2, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(p.count == 0);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(0, 1, 0, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, -1, 0, &p), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(qnan, 1, 0, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, pinf, 0, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, 1, qnan, &p), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked(1, 1, pinf, &p), GA2D_ERR_NOT_FINITE);
    CHECK(ga2d_polygon_rounded_box(1, (ga2d_real)0.5, (ga2d_real)0.5).count == 0);
    CHECK(ga2d_polygon_rounded_box(1, (ga2d_real)0.5, (ga2d_real)-1).count == 0);
    CHECK(ga2d_polygon_rounded_box(1, (ga2d_real)0.5, qnan).count == 0);
    CHECK(ga2d_polygon_box(0, 1).count == 0);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked((ga2d_real)(2 * (double)GA2D_MAX_COORDINATE), 1, 0, &p),
                 GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(ga2d_polygon_rounded_box_checked((ga2d_real)1.5, (ga2d_real)0.5, (ga2d_real)0.25, &p), GA2D_OK);
    CHECK(p.count == 4 && p.radius == (ga2d_real)0.25 && p.vertices[2].x == (ga2d_real)1.25 && p.vertices[2].y == (ga2d_real)0.25);

    /* box(hw, hh) is rounded_box(hw, hh, 0), field by field, bit for bit */
    {
        const double sizes[][2] = {{1, 1}, {0.5, 0.25}, {3.75, 1e-3}, {1e3, 7}};
        size_t k;
        for (k = 0; k < sizeof sizes / sizeof sizes[0]; ++k) {
            int same;
            p = ga2d_polygon_box((ga2d_real)sizes[k][0], (ga2d_real)sizes[k][1]);
            q = ga2d_polygon_rounded_box((ga2d_real)sizes[k][0], (ga2d_real)sizes[k][1], 0);
            same = p.count == q.count && p.count == 4 && same_real(p.radius, q.radius) && p.radius == 0;
            for (i = 0; i < p.count; ++i)
                same = same && same_real(p.vertices[i].x, q.vertices[i].x) && same_real(p.vertices[i].y, q.vertices[i].y) &&
                       same_real(p.normals[i].x, q.normals[i].x) && same_real(p.normals[i].y, q.normals[i].y);
            CHECK(same);
            CHECK(same_mass(ga2d_polygon_mass(&p, 2), ga2d_polygon_mass(&q, 2)));
        }
    }
}

/* ------------------------------------------------------------ world body */
/* A dynamic body's mass data is ga2d_polygon_mass of its polygon at the
   def's density, bit for bit: the body rebuilds the polygon with
   ga2d_polygon_make (the same vertices; a box's normals come out exactly
   the axes) and keeps the radius. */
static void world_body(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_vec tri[3];
    ga2d_polygon polys[3];
    const double dens[3] = {1, 2.5, 0.75};
    int k;
    CHECK(w != NULL);
    if (!w) return;
    polys[0] = ga2d_polygon_rounded_box((ga2d_real)0.5, (ga2d_real)0.25, (ga2d_real)0.125);
    polys[1] = ga2d_polygon_rounded_box(2, 1, (ga2d_real)0.75);
    tri[0] = ga2d_vec_make(0, 0);
    tri[1] = ga2d_vec_make(2, 0);
    tri[2] = ga2d_vec_make((ga2d_real)0.5, (ga2d_real)1.5);
    polys[2] = make(tri, 3);
    polys[2].radius = (ga2d_real)0.2;
    for (k = 0; k < 3; ++k) {
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_body_id id;
        ga2d_mass got, want;
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = polys[k];
        d.density = (ga2d_real)dens[k];
        d.position = ga2d_vec_make((ga2d_real)(3 * k), 1);
        d.rotor = ga2d_rotor_from_angle((ga2d_real)(0.3 * k)); /* mass data is in the body frame */
        id = ga2d_body_create(w, &d);
        CHECK(!ga2d_body_id_is_null(id));
        if (ga2d_body_id_is_null(id)) continue;
        got = ga2d_body_mass_data(w, id);
        want = ga2d_polygon_mass(&d.polygon, d.density);
        CHECK(want.mass > 0);
        CHECK(same_mass(got, want));
        CHECK(same_real(ga2d_body_polygon(w, id)->radius, d.polygon.radius));
    }
    ga2d_world_destroy(w);
}

void suite_shape_mass(void)
{
    run("shape_mass_circle_closed_form", circle_closed_form);
    run("shape_mass_circle_outline_reference", circle_outline_reference);
    run("shape_mass_capsule_against_outline", capsule_against_outline);
    run("shape_mass_capsule_limits", capsule_limits);
    run("shape_mass_rounded_box_closed_form", rounded_box_closed_form);
    run("shape_mass_rounded_polygon_against_outline", rounded_polygon_against_outline);
    run("shape_mass_rounded_radius_to_zero", rounded_radius_to_zero);
    run("shape_mass_rounded_translation", rounded_translation);
    run("shape_mass_bad_input", bad_input);
    run("shape_mass_makers", makers);
    run("shape_mass_world_body", world_body);
}
