/* What shapes and worlds add to contacts, against analytic answers:
   rolling resistance slowing a rolling disc, a pre-solve callback making a
   one-way platform (and, returning 0 for everything, a floor that is not
   there), hit events of a dropped box, and a box and a ball sliding the
   bottom of a closed chain loop across its joins.

   dt = 1/60, g = 10, the default world (4 substeps, soft step, symplectic
   Euler), sleep off.  u = REAL_EPS / 2 is the unit roundoff of ga2d_real,
   u_d = DBL_EPSILON / 2 that of the double arithmetic the tests do
   themselves; every tolerance is derived in its comment from u, counted
   operations and the magnitudes they act on, or from the physics and the
   solver's documented construction.

   With GA2D_TEST_VERBOSE set, every scene prints "shape_dynamics: ..."
   lines with its measured figures and their bounds. */
#include "test.h"

/* The suite, called from test_main.c.  Declared here with C linkage as
   test.h declares the others (a second declaration there is harmless). */
#ifdef __cplusplus
extern "C" {
#endif
void suite_shape_dynamics(void);
#ifdef __cplusplus
}
#endif

#define DT (1.0 / 60)
#define G 10.0
#define SLOP GA2D_LINEAR_SLOP
#define U (REAL_EPS / 2)
#define UD (DBL_EPSILON / 2)

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static void step(ga2d_world *w) { CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK); }

static ga2d_world *make_world(ga2d_world_def wd)
{
    ga2d_world *w;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    return w;
}

static int substeps(void) { return ga2d_default_world_def().substeps; }

/* The substep the library integrates with: h = dt / substeps in ga2d_real
   (ga2d_world_step), dt itself rounded to ga2d_real; dividing by 4 is
   exact. */
static double sub_h(void) { return (double)((ga2d_real)DT / (ga2d_real)substeps()); }

/* A static box of half-extents hx x hy centred at (x, y); its one shape in *shape. */
static ga2d_body_id add_static_box(ga2d_world *w, double x, double y, double hx, double hy, double friction, ga2d_shape_id *shape)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id id;
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    d.friction = (ga2d_real)friction;
    id = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(id));
    if (shape) CHECK(ga2d_body_get_shapes(w, id, shape, 1) == 1);
    return id;
}

/* A dynamic body at (x, y) with velocity (vx, vy) and one shape, a box of
   half-extents hx x hy (r = 0) or a disc of radius r centred on the origin,
   made from *sd; its shape in *shape. */
static ga2d_body_id add_dynamic(ga2d_world *w, double x, double y, double vx, double vy, double hx, double hy, double r,
                                const ga2d_shape_def *sd, ga2d_shape_id *shape)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id id;
    ga2d_shape_id s;
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.velocity = ga2d_vec_make((ga2d_real)vx, (ga2d_real)vy);
    d.polygon.count = 0;
    id = ga2d_body_create(w, &d);
    if (r > 0) {
        ga2d_circle c;
        c.center = ga2d_vec_make(0, 0);
        c.radius = (ga2d_real)r;
        s = ga2d_shape_create_circle(w, id, sd, &c);
    } else {
        ga2d_polygon p = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
        s = ga2d_shape_create_polygon(w, id, sd, &p);
    }
    CHECK(!ga2d_body_id_is_null(id) && !ga2d_shape_id_is_null(s));
    if (shape) *shape = s;
    return id;
}

/* ====================================================== free flight, exactly
   A body no contact pushes moves under symplectic Euler, per substep
       v <- fl(v + fl(g h)),   y <- fl(y + fl(v h))
   (ga2d__kick: the acceleration is the gravity vector times gravity_scale
   1 plus 0 x 1/m, both exact; ga2d__drift).  In real numbers, from (y0,
   v0) with the library's h, after j substeps
       v_j = v0 - j g h,   y_j = y0 + j h v0 - g h^2 j (j + 1) / 2,
   which at t = j h is y0 + v0 t - g t (t + h) / 2: the continuous
   y0 + v0 t - g t^2 / 2 less the scheme's lag g t h / 2.  The library's
   values differ from these by rounding only, accumulated substep by
   substep (flight_advance):
       e_v(j) = e_v(j-1) + u g h + u (|v_j| + e_v(j-1))
       e_y(j) = e_y(j-1) + h e_v(j) + u h |v_j| + u (|y_j| + e_y(j-1))
   (fl(g h) is off g h by <= u g h and the add rounds once; the drift
   moves by the library's v, off by e_v, its product and add round once
   each).  The reference's own double arithmetic adds
   4 u_d (|v0| + j g h) to v and 8 u_d (|y0| + j h |v0| + g h^2 j^2) to y
   (flight_bound). */
typedef struct flight {
    double y0, v0, h;
    long j;      /* substeps taken */
    double ev, ey; /* the library's accumulated rounding */
} flight;

static void flight_start(flight *f, double y0, double v0)
{
    f->y0 = y0;
    f->v0 = v0;
    f->h = sub_h();
    f->j = 0;
    f->ev = f->ey = 0;
}

static double flight_v(const flight *f, long j) { return f->v0 - (double)j * G * f->h; }
static double flight_y(const flight *f, long j)
{
    return f->y0 + (double)j * f->h * f->v0 - G * f->h * f->h * (double)j * (double)(j + 1) / 2;
}

static void flight_advance(flight *f, int n)
{
    int i;
    for (i = 0; i < n; ++i) {
        long j = ++f->j;
        f->ev += U * G * f->h + U * (fabs(flight_v(f, j)) + f->ev);
        f->ey += f->h * f->ev + U * f->h * fabs(flight_v(f, j)) + U * (fabs(flight_y(f, j)) + f->ey);
    }
}

static double flight_bound_v(const flight *f) { return f->ev + 4 * UD * (fabs(f->v0) + (double)f->j * G * f->h); }
static double flight_bound_y(const flight *f)
{
    double j = (double)f->j;
    return f->ey + 8 * UD * (fabs(f->y0) + j * f->h * fabs(f->v0) + G * f->h * f->h * j * j);
}

/* Where free flight ends on a surface.  A body falling onto a static
   surface (a flat face under it, n = (0, 1), no spin) is in free flight
   until a contact pushes: passes that meet a point still apart apply
   max(0, ...) = +-0 and change nothing.  With y_j the gap after substep
   j and v_j its velocity: the soft pass of substep j pushes when the
   kicked velocity would close the gap y_{j-1} within the substep (y_j <
   0); the relax pass after drift j when the gap would close within a
   substep at the same speed (y_j < |v_j| h: it brakes a point still
   apart as if a substep followed, ga2d__restitute's comment).  Both need
   the contact to touch, tested at the step's start: a manifold keeps
   points up to the speculative distance plus what the pair closes in a
   step, |v| dt (ga2d__collide_contacts).
   first_push: from f (at a step's start, falling onto a surface `below`
   under its centre) the step of the first push (0: none in 2000 steps),
   in *J its substep (counted from f's start).  *margin: how far the
   deciding quantities (each touching test, each substep's y_j - |v_j| h
   in a touching step) were from their thresholds, the least of them. */
static int first_push(flight f, double below, long *J, double *margin)
{
    const int nsub = substeps();
    const double h = sub_h(), dt = (double)(ga2d_real)DT;
    int k, i;
    *margin = HUGE_VAL;
    for (k = 1; k <= 2000; ++k) {
        double gap = flight_y(&f, f.j) - below, v = flight_v(&f, f.j), spec = GA2D_SPECULATIVE_DISTANCE + fabs(v) * dt;
        int touching = v <= 0 && gap <= spec;
        if (v <= 0) *margin = fmin(*margin, fabs(gap - spec));
        for (i = 0; i < nsub; ++i) {
            double yj, vj;
            flight_advance(&f, 1);
            yj = flight_y(&f, f.j) - below;
            vj = fabs(flight_v(&f, f.j));
            if (!touching) continue;
            *margin = fmin(*margin, fabs(yj - vj * h));
            if (yj < vj * h) {
                *J = f.j;
                return k;
            }
        }
    }
    return 0;
}

/* ================================================== 1. rolling resistance
   A solid disc (r = 0.5 m, density 1, friction 0.6 on both sides) rolls
   without slipping on level ground (a static box, its top y = 0) with
   rolling_resistance c = 0.2 on the disc, launched at v0 = 3 m/s with
   w0 = -v0/r.  The solver (ga2d__solve_contacts) adds a torque impulse
   against the spin, accumulated within +-c r times the normal impulse.

   Physics: with N = m g the normal force, friction F and the resistance's
   torque c r N against the spin, m a = F, I alpha = r F + c r N and the
   rolling a = -r alpha give a = c g / (1 + I/(m r^2)) = (2/3) c g for
   I = m r^2 / 2: 1.333 m/s^2, so it stops at t_s = v0 / a = 2.25 s.

   The disc is the contact's shape B (the ground was made first), n = (0,
   1) exactly and t = (n.y, -n.x) = (1, -0).  Per substep the disc takes
   the normal impulse lambda (what the substep's passes accumulate and
   deliver: the warm start re-applies last substep's total), the friction
   tau along x at the contact's point, rb = (rb.x, -rho) from its centre,
   and the resistance's R: at its cap c r lambda whenever the unclamped
   update, I |w| (rmass = 1/(1/I + 0)), exceeds it, which holds while
   |w| > 2 c r X / I (a premise checked: 0.07 rad/s here).  So per substep
       m dvx = tau,  m dvy = lambda - m g h,  I dw = rho tau + rb.x lambda + R,
   and over a window of n substeps, with N = sum(lambda) = m (dvy + n g h):
       I dW - m rho_mid dVx = c r N + E_rho + E_x,                        (A)
   the angular momentum about the contact point.  E_rho = sum((rho_j -
   rho_mid) tau_j): the levers the friction acted at (rho = r + s/2 plus
   half the centre's travel along n within a step, test_shape_world's
   roll_lever_range) stray from their mid value by at most half their
   range, and sum |tau pieces| <= 3 n mu X (three applications a substep,
   each within the cone mu X); E_x = sum(rb.x lambda): a disc's point
   stays under its centre (ga2d__point_now keeps a round side's point at
   its surface along n), off it by the rounding of its anchors, which are
   built from the centres' difference: |rb.x| <= 8 u (|x| + 1) (x the
   disc's abscissa, 1 the ground's and the disc's offsets), times 3 N for
   the three applications a substep.
   Rounding of (A): every substep w takes 8 updates (warm start: the
   point's impulse and the resistance's; each pass: normal, friction,
   resistance), each rounding its add by u |w| and its product by 4 u of
   its torque (<= (rho + r) X + c r X); vx 3 (warm start, the passes'
   friction; the normal's x part is 0 x lambda, exact) by u |vx| and u mu
   X / m; vy 4 (kick, warm start, the passes' normals) by u (g h + 2 X/m),
   and the kick's fl(g h) by u g h.  The solver's 1/m and 1/I are within
   u of the reciprocals of the reported mass data, and the cap's product
   rounds once: 4 u (|I dW| + m rho |dVx| + c r N).
   (B) Rolling: the slip at a step's end, eps = vx + w rho_end.  The relax
   pass's friction zeroes it (to test_shape_world's Q, the lever's travel
   within the step, and rounding), then its resistance changes w by
   dl / I with |dl| = c r |lambda_relax - lambda_soft| <= c r X: so
   |eps| <= rho c r X / I + Q + 8 u (|vx| + rho |w|) + 8 u K0 mu X
   + 16 u Y |w| (Q and the lever's rounding 16 u Y |w| as
   test_shape_world's roll_slip_bound; a priori, so loose: the measured
   slips are printed).
   (C) With v = -w rho_mid + eps' at the window's ends (eps'_i = vx_i + w_i
   rho_mid, measured), (A) gives exactly
       a = -dVx / T = [rho_mid (c r N + E) / I - (eps'_2 - eps'_1)] / (T (1 + m rho_mid^2 / I)),
   so a differs from a_model = c r rho_mid N / (T (I + m rho_mid^2)) by
   [rho |E| / I + |eps'_2 - eps'_1| + rho |R_A| / I] / (T (1 + m rho^2 / I)),
   R_A the rounding of (A) (T = n h, the time the library stepped).
   a_model in turn differs from (2/3) c g by what the lever r + s/2 (s the
   steady overlap: at first order -(2/9) (c g / r) s/2 = (1/9) c g |s| / r)
   and the load N / (m T) != g (the centre's vertical motion) make of it:
   the bound adds those two to the one above.  Window 0.5 .. 1.5 s:
   the disc moves more than half a slop every step, so every manifold is
   made anew (counters.manifolds_carried 0, a premise: see
   rolling_disc_stays_at_rest for the carried ones).
   (D) The stop: until t_s - dt the disc still rolls forward (v > 0,
   w < 0); one step after t_s its speed and its rim's speed are below
   a h, what the resistance takes in one substep (it stopped within a step
   of t_s); and it never rolls back: its centre never moves by -x more
   than a step's position rounding, 2 n_sub u (|x| + |v| h), to 1 s after
   the stop.  (That it is then at rest to rounding is
   rolling_disc_stays_at_rest, left out of the suite: it fails.) */
#define RR_C 0.2
#define RR_R 0.5
#define RR_V0 3.0
#define RR_X0 -3.0
#define RR_STEPS 210

typedef struct rr_rec {
    double vx, vy, w, cx, cy, s, nimp, timp, nx, ny;
    int contacts, points, carried;
} rr_rec;

typedef struct rr_data {
    rr_rec rec[RR_STEPS + 1];
    double m, I, mu, c;
} rr_data;

static void rr_record(ga2d_world *w, ga2d_body_id disc, rr_rec *r)
{
    ga2d_contact_data cd[2];
    ga2d_vec v = ga2d_body_velocity(w, disc), c = ga2d_body_center(w, disc);
    memset(r, 0, sizeof *r);
    r->vx = (double)v.x;
    r->vy = (double)v.y;
    r->w = (double)ga2d_body_angular_velocity(w, disc);
    r->cx = (double)c.x;
    r->cy = (double)c.y;
    r->carried = ga2d_world_get_counters(w).manifolds_carried;
    r->contacts = ga2d_world_get_contacts(w, cd, 2);
    if (r->contacts == 1) {
        r->points = cd[0].manifold.count;
        r->nx = (double)cd[0].manifold.normal.x;
        r->ny = (double)cd[0].manifold.normal.y;
        r->s = (double)cd[0].manifold.points[0].separation;
        r->nimp = (double)cd[0].manifold.points[0].normal_impulse;
        r->timp = (double)cd[0].manifold.points[0].tangent_impulse;
    }
}

static void rr_run(rr_data *o)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w = make_world(wd);
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id disc;
    ga2d_mass md;
    int k;
    memset(o, 0, sizeof *o);
    if (!w) return;
    add_static_box(w, 0, -0.5, 20, 0.5, 0.6, NULL);
    sd.friction = (ga2d_real)0.6;
    sd.rolling_resistance = (ga2d_real)RR_C;
    disc = add_dynamic(w, RR_X0, RR_R, RR_V0, 0, 0, 0, RR_R, &sd, NULL);
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, disc, (ga2d_real)(-RR_V0 / RR_R)), GA2D_OK);
    md = ga2d_body_mass_data(w, disc);
    o->m = (double)md.mass;
    o->I = (double)md.inertia;
    o->c = (double)(ga2d_real)RR_C;
    {
        ga2d_real mu = (ga2d_real)0.6, p = mu * mu; /* the mixed sqrt(mu mu), as the library rounds it */
        o->mu = (double)(ga2d_real)sqrt((double)p);
    }
    rr_record(w, disc, &o->rec[0]);
    for (k = 1; k <= RR_STEPS; ++k) {
        step(w);
        rr_record(w, disc, &o->rec[k]);
    }
    ga2d_world_destroy(w);
}

/* X: the most normal impulse a substep may carry, twice the weight's. */
static double rr_x(const rr_data *o) { return 2 * o->m * G * sub_h(); }

/* The levers of steps k1+1 .. k2 (roll_lever_range of test_shape_world):
   rho = r + s/2 and half the centre's travel along n within the step. */
static void rr_levers(const rr_data *o, int k1, int k2, double *lo, double *hi)
{
    int k;
    *lo = HUGE_VAL;
    *hi = -HUGE_VAL;
    for (k = k1 + 1; k <= k2; ++k) {
        double rho = RR_R + o->rec[k].s / 2, travel = fabs(o->rec[k].cy - o->rec[k - 1].cy) / 2;
        *lo = fmin(*lo, rho - travel);
        *hi = fmax(*hi, rho + travel);
    }
}

static void rolling_resistance_decelerates(void)
{
    static rr_data o;
    const int k1 = 30, k2 = 90, nsub = substeps();
    const double h = sub_h(), n = (double)(k2 - k1) * nsub, T = n * h;
    double X, rho_lo, rho_hi, rho, dW, dVx, dVy, N, lhs, rhs, E, RA, bA, a, a_model, e1, e2, bC, a_th, f_lo, f_hi, lever, load_term,
        bD, xmax = 0, V = 0, W = 0, worst_slip = 0, slip_bound = 0, back = 0, back_bound = 0;
    int k, one = 1, flat = 1, within = 1, load = 1, cone = 1, fresh = 1, capped = 1, forward = 1, ks;
    const rr_rec *r1, *r2;
    rr_run(&o);
    X = rr_x(&o);
    r1 = &o.rec[k1];
    r2 = &o.rec[k2];
    /* premises: one contact of one point, normal (0, 1) exactly, overlap
       within the slop, load within X, friction inside its cone, the
       resistance at its cap, every manifold made anew in the window */
    for (k = 1; k <= k2; ++k) {
        const rr_rec *r = &o.rec[k];
        one &= r->contacts == 1 && r->points == 1;
        flat &= r->nx == 0 && r->ny == 1;
        within &= r->s >= -SLOP && r->s <= 0;
        load &= r->nimp > 0 && r->nimp <= X;
        cone &= fabs(r->timp) < o.mu * r->nimp;
        if (k > k1) {
            fresh &= r->carried == 0;
            capped &= fabs(r->w) > 2 * o.c * RR_R * X / o.I;
            xmax = fmax(xmax, fabs(r->cx));
            V = fmax(V, fabs(r->vx));
            W = fmax(W, fabs(r->w));
        }
    }
    CHECK(one);
    CHECK(flat);
    CHECK(within);
    CHECK(load);
    CHECK(cone);
    CHECK(fresh);
    CHECK(capped);
    /* (A) */
    rr_levers(&o, k1, k2, &rho_lo, &rho_hi);
    rho = (rho_lo + rho_hi) / 2;
    dW = r2->w - r1->w;
    dVx = r2->vx - r1->vx;
    dVy = r2->vy - r1->vy;
    N = o.m * (dVy + n * G * h);
    lhs = o.I * dW - o.m * rho * dVx;
    rhs = o.c * RR_R * N;
    E = (rho_hi - rho_lo) / 2 * 3 * n * o.mu * X + 8 * U * (xmax + 1) * 3 * N;
    RA = o.I * n * (8 * U * W + 8 * 4 * U * ((rho_hi + RR_R) * X + o.c * RR_R * X) / o.I) +
         o.m * rho * n * (3 * U * V + 3 * U * o.mu * X / o.m) + o.c * RR_R * o.m * n * (4 * U * (G * h + 2 * X / o.m) + U * G * h) +
         4 * U * (fabs(o.I * dW) + o.m * rho * fabs(dVx) + rhs);
    bA = E + RA;
    CHECK_NEAR(lhs, rhs, bA);
    /* (B) */
    for (k = k1; k <= k2; k += 15) {
        const rr_rec *r = &o.rec[k];
        double rho_end = RR_R + r->s / 2 + (r->cy - o.rec[k - 1].cy) / 2, slip = r->vx + r->w * rho_end;
        double rho0 = RR_R + r->s / 2, K0 = 1 / o.m + rho0 * rho0 / o.I, Ke = 1 / o.m + rho_end * rho_end / o.I;
        double push = (double)ga2d_default_world_def().contact_push_max_velocity;
        double Q = fabs(1 - Ke / K0) * (G * h + K0 * o.mu * X + fabs(r->w) * h * push / 2);
        double Y = fabs(r->cy + 0.5) + 0.5 + RR_R;
        double b = rho_end * o.c * RR_R * X / o.I + Q + 8 * U * (fabs(r->vx) + rho_end * fabs(r->w)) + 8 * U * K0 * o.mu * X +
                   16 * U * Y * fabs(r->w);
        CHECK_NEAR(slip, 0, b);
        worst_slip = fmax(worst_slip, fabs(slip));
        slip_bound = b;
    }
    /* (C) */
    a = -dVx / T;
    e1 = r1->vx + r1->w * rho;
    e2 = r2->vx + r2->w * rho;
    a_model = o.c * RR_R * rho * N / (T * (o.I + o.m * rho * rho));
    bC = (rho * (E + RA) / o.I + fabs(e2 - e1)) / (T * (1 + o.m * rho_lo * rho_lo / o.I)) + 4 * U * a;
    CHECK_NEAR(a, a_model, bC);
    /* against (2/3) c g: f(rho) = c g r rho / (I/m + rho^2) is a_model at
       N = m g T; over [rho_lo, rho_hi] it is monotone (its turning point
       is at rho = sqrt(I/m) = 0.35 m), so the lever costs at most its
       value at an end less f(r) = (2/3) c g; the load N / (m T) differs
       from g by (dVy + g (n h - T)) / T with n h = T here, so by dVy / T:
       that much of f, relatively. */
    a_th = 2.0 / 3.0 * o.c * G;
    f_lo = o.c * G * RR_R * rho_lo / (o.I / o.m + rho_lo * rho_lo);
    f_hi = o.c * G * RR_R * rho_hi / (o.I / o.m + rho_hi * rho_hi);
    lever = fmax(fabs(f_lo - a_th), fabs(f_hi - a_th));
    load_term = fmax(f_lo, f_hi) * fabs(dVy) / (G * T);
    bD = lever + load_term + bC;
    CHECK_NEAR(a, a_th, bD);
    /* (D) the stop */
    {
        double ts = RR_V0 / a_th;
        int last_rolling = (int)floor(ts / DT) - 1;
        ks = (int)ceil(ts / DT) + 1;
        for (k = 1; k <= last_rolling; ++k) forward &= o.rec[k].vx > 0 && o.rec[k].w < 0;
        CHECK(forward);
        CHECK(ks + 60 <= RR_STEPS);
        CHECK(fabs(o.rec[ks].vx) < a_th * h);
        CHECK(fabs(o.rec[ks].w) * RR_R < a_th * h);
        for (k = 1; k <= ks + 60; ++k) {
            double dx = o.rec[k].cx - o.rec[k - 1].cx;
            /* rounding; and once it has stopped, the stop's settling: the
               substep that stops it can overshoot by its own deceleration,
               a h, which the soft contact and the rolling cap take back
               within the step: a backward move of at most a h DT a step */
            double b = 2 * nsub * U * (fabs(o.rec[k].cx) + fabs(o.rec[k].vx) * h) + (k > last_rolling ? a_th * h * DT : 0);
            CHECK(dx >= -b);
            if (dx < back) back = dx;
            back_bound = fmax(back_bound, b);
        }
    }
    if (verbose()) {
        printf("shape_dynamics: rolling resistance c %.1f: I dW - m rho dVx %.9f vs c r N %.9f over 0.5..1.5 s: %+.3g "
               "(bound %.3g = levers and point %.3g + rounding %.3g)\n",
               o.c, lhs, rhs, lhs - rhs, bA, E, RA);
        printf("shape_dynamics: rolling resistance slip vx + w rho_end at most %.3g m/s (a priori bound %.3g); rho %.9f..%.9f "
               "(s %.3g m)\n",
               worst_slip, slip_bound, rho_lo, rho_hi, r2->s);
        printf("shape_dynamics: rolling resistance a %.9f m/s^2 vs c r rho N/(T(I + m rho^2)) %.9f: %+.3g (bound %.3g); "
               "vs (2/3) c g %.9f: %+.3g (bound %.3g = lever r + s/2 %.3g [(1/9) c g |s|/r %.3g] + load %.3g + %.3g)\n",
               a, a_model, a - a_model, bC, a_th, a - a_th, bD, lever, o.c * G * fabs(r2->s) / (9 * RR_R), load_term, bC);
        printf("shape_dynamics: rolling resistance stop: t_s %.4f s; at step %d v %+.3g m/s, w r %+.3g m/s (bound a h %.3g); "
               "worst backward step %.3g m (bound %.3g)\n",
               RR_V0 / a_th, ks, o.rec[ks].vx, o.rec[ks].w * RR_R, a_th * h, back, back_bound);
    }
}

/* 1b. After the stop the disc should be at rest: nothing drives it (the
   ground is level, friction and the resistance are both well inside their
   caps, lambda mu and c r lambda, so each pass drives the slip and the spin
   to zero as unclamped constraints do).  What is left is rounding on the
   impulses' scale: per pass the friction and resistance updates leave the
   slip and spin to 8 u of the velocity changes they make, <= X/m and
   r X (rho + c r)/I; over the step's 8 passes (two a substep) that is
       |vx|, |w| r <= 64 u X / m   (X / m = 2 g h, and r^2 m / I = 2),
   and the centre then moves by at most n_sub (h 64 u X/m + u |x|) a step.
   Checked over 1 s from 10 steps after t_s + dt (the stop itself leaves a
   slip, -1e-4 m/s, that each pass takes a third of: (2/3)^80 of it is
   left 10 steps later).

   Still left out of the suite, as a known limit: the creep described
   below is fixed (a round side's manifold is no longer carried along), and
   the disc now settles: in float inside these bounds; in double |v|
   reaches 5.5e-13 m/s 10..70 steps after the stop (it is 6.7e-56 at the
   end), above the 64 u X / m = 5.9e-16 here: the stop leaves a slower
   mode than the per-pass third assumed above (the soft contact's own
   settling, not derived yet).

   What failed before the fix: a manifold carried along
   (ga2d__reuse_manifold: the pair moved under half a slop since its
   manifold was made) puts the point midway between the anchors carried
   with the bodies, so a disc's point lags its bottom by half of what the
   disc moved since; the normal impulse's moment about the centre, lambda
   dx / 2, then turns the disc, the resistance takes the turn out, and
   friction and resistance settle at a slip: the stored v is -1.76e-6 m/s
   in float and double (64 u X / m: 3.2e-7 and 5.9e-16) while the centre
   creeps forward by 3.2e-7 m a step (1.9e-5 m/s; bound 9e-8 and 2e-16),
   faster as the lag grows with the creep (in double: 2.4 mm in 70 s,
   when the disc has moved half a slop and its manifold is made anew; the
   lag, the point's x less the centre's, read from the contact: -0.7 mm
   at 9 s, -1.8 mm at 70 s).  Within a step ga2d__point_now keeps a round
   side's point at its surface along n; the carried manifold does not
   (and it turns the point with the disc, lifting it by r (1 - cos), the
   other thing point_now's comment avoids). */
static void rolling_disc_stays_at_rest(void)
{
    static rr_data o;
    const int nsub = substeps();
    const double h = sub_h(), a_th = 2.0 / 3.0 * RR_C * G;
    double X, bv, worst_v = 0, worst_w = 0, worst_dx = 0, bx = 0;
    int k, ks = (int)ceil(RR_V0 / a_th / DT) + 1, ok_v = 1, ok_w = 1, ok_x = 1;
    rr_run(&o);
    X = rr_x(&o);
    bv = 64 * U * X / o.m;
    CHECK(ks + 70 <= RR_STEPS);
    for (k = ks + 10; k <= ks + 70 && k <= RR_STEPS; ++k) {
        const rr_rec *r = &o.rec[k];
        double b = nsub * (h * bv + U * fabs(r->cx));
        ok_v &= fabs(r->vx) <= bv;
        ok_w &= fabs(r->w) * RR_R <= bv;
        ok_x &= fabs(r->cx - o.rec[k - 1].cx) <= b;
        worst_v = fmax(worst_v, fabs(r->vx));
        worst_w = fmax(worst_w, fabs(r->w) * RR_R);
        worst_dx = fmax(worst_dx, fabs(r->cx - o.rec[k - 1].cx));
        bx = fmax(bx, b);
    }
    CHECK(ok_v);
    CHECK(ok_w);
    CHECK(ok_x);
    if (verbose())
        printf("shape_dynamics: disc at rest after the stop: |v| up to %.3g m/s, |w| r %.3g (bound %.3g); centre moves up to %.3g m "
               "a step (bound %.3g); v at the end %+.3g m/s\n",
               worst_v, worst_w, bv, worst_dx, bx, o.rec[ks + 70].vx);
}

/* ================================================ 2. pre-solve callbacks
   The callback's record: every call, the shapes it named and whether its
   manifold was a touching one (1 or 2 points, unit normal). */
typedef struct presolve_log {
    ga2d_world *world;
    ga2d_body_id box;
    ga2d_shape_id box_shape, other_shape; /* the two shapes every call must name, other's (A) first */
    double top, half;                     /* the platform's top, the box's half height */
    int calls, step_calls, named, manifolds;
    int allow; /* 0: decline everything; 1: the one-way rule */
    ga2d_manifold last;
} presolve_log;

/* A one-way platform's rule (ga2d_pre_solve_fn's own example, made
   robust): the box passes while it comes from below, its bottom below
   the platform's top by more than a slop, or while it moves up faster
   than any contact pushes anything (contact_push_max_velocity, 0.8 m/s,
   so 1 m/s); otherwise the platform holds it. */
static int presolve_cb(ga2d_shape_id a, ga2d_shape_id b, const ga2d_manifold *m, void *ctx)
{
    presolve_log *L = (presolve_log *)ctx;
    double nn = (double)m->normal.x * (double)m->normal.x + (double)m->normal.y * (double)m->normal.y;
    ++L->calls;
    ++L->step_calls;
    L->named &= ga2d_shape_id_equal(a, L->other_shape) && ga2d_shape_id_equal(b, L->box_shape);
    /* a unit normal: |n|^2 within 8 u of 1 (a normalisation's rounding) */
    L->manifolds &= m->count >= 1 && m->count <= 2 && fabs(nn - 1) <= 8 * U;
    L->last = *m;
    if (!L->allow) return 0;
    {
        ga2d_vec v = ga2d_body_velocity(L->world, L->box), c = ga2d_body_center(L->world, L->box);
        if ((double)v.y > 1 || (double)c.y - L->half < L->top - SLOP) return 0;
    }
    return 1;
}

/* The manifold the callback saw is the contact's (the same step's, read
   after it): its normal and points agree bit for bit. */
static int same_manifold(const ga2d_manifold *a, const ga2d_manifold *b)
{
    int i, same = a->count == b->count && a->normal.x == b->normal.x && a->normal.y == b->normal.y;
    for (i = 0; same && i < a->count; ++i)
        same = a->points[i].point.x == b->points[i].point.x && a->points[i].point.y == b->points[i].point.y &&
               a->points[i].separation == b->points[i].separation && a->points[i].id == b->points[i].id;
    return same;
}

/* 2a. Returning 0 for everything: a box (0.5 m, its shape with
   enable_pre_solve_events) dropped onto a floor (a static box 4 x 1 m, top
   y = 0.5) falls through it in free flight, exactly: every step its
   centre and velocity match flight_y / flight_v to flight_bound (the
   declined contact makes no constraint: counters.constraint_count is 1
   every step, the resting box's below),
   so at t = 1 s it is at y0 - g t (t + h)/2, the continuous y0 - g t^2/2
   less symplectic Euler's lag g t h / 2 (printed).  Every step in which
   the pair touches (ga2d_world_get_contacts lists it after the step) the
   callback is called once, naming the floor's shape (A, made first) and
   the box's, with that step's manifold, bit for bit.  A second box on the
   floor whose shape does not ask for pre-solve events is never passed to
   the callback and stays on the floor (its bottom within a slop of the
   top). */
static void presolve_declines_a_floor(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def(), sd_plain = ga2d_default_shape_def();
    presolve_log L;
    ga2d_body_id box, rest;
    ga2d_shape_id floor_shape, box_shape;
    flight f;
    int k, calls_match = 1, saw_same = 1, touching_steps = 0, unsolved = 1, exact_x = 1;
    double worst_y = 0, worst_v = 0, by = 0, bv = 0;
    memset(&L, 0, sizeof L);
    wd.pre_solve = presolve_cb;
    wd.pre_solve_context = &L;
    w = make_world(wd);
    if (!w) return;
    add_static_box(w, 0, 0, 2, 0.5, 0.6, &floor_shape);
    sd.enable_pre_solve_events = 1;
    box = add_dynamic(w, -0.75, 1.0, 0, 0, 0.25, 0.25, 0, &sd, &box_shape);
    rest = add_dynamic(w, 1.0, 0.75, 0, 0, 0.25, 0.25, 0, &sd_plain, NULL);
    L.world = w;
    L.box = box;
    L.box_shape = box_shape;
    L.other_shape = floor_shape;
    L.named = L.manifolds = 1;
    L.allow = 0;
    flight_start(&f, (double)ga2d_body_center(w, box).y, (double)ga2d_body_velocity(w, box).y);
    for (k = 1; k <= 60; ++k) {
        ga2d_contact_data cd[4];
        int i, nc, touching = 0;
        L.step_calls = 0;
        step(w);
        flight_advance(&f, substeps());
        nc = ga2d_world_get_contacts(w, cd, 4);
        for (i = 0; i < nc && i < 4; ++i)
            if (ga2d_shape_id_equal(cd[i].shape_b, box_shape)) {
                touching = 1;
                saw_same &= L.step_calls == 1 && same_manifold(&L.last, &cd[i].manifold);
            }
        touching_steps += touching;
        calls_match &= L.step_calls == touching;
        /* the resting box's contact is the one constraint */
        unsolved &= ga2d_world_get_counters(w).constraint_count == 1;
        {
            ga2d_vec c = ga2d_body_center(w, box), v = ga2d_body_velocity(w, box);
            double ey = fabs((double)c.y - flight_y(&f, f.j)), ev = fabs((double)v.y - flight_v(&f, f.j));
            CHECK(ey <= flight_bound_y(&f));
            CHECK(ev <= flight_bound_v(&f));
            exact_x &= c.x == (ga2d_real)-0.75 && v.x == 0 && ga2d_body_angular_velocity(w, box) == 0;
            worst_y = fmax(worst_y, ey / flight_bound_y(&f));
            worst_v = fmax(worst_v, ev / flight_bound_v(&f));
            by = flight_bound_y(&f);
            bv = flight_bound_v(&f);
        }
    }
    CHECK(touching_steps >= 5); /* it did pass through the floor's metre */
    CHECK(calls_match);
    CHECK(saw_same);
    CHECK(L.named);
    CHECK(L.manifolds);
    CHECK(unsolved);
    CHECK(exact_x);
    CHECK((double)ga2d_body_center(w, box).y < -0.5 - 0.25); /* below the floor's bottom */
    {
        double yr = (double)ga2d_body_center(w, rest).y - 0.25;
        CHECK(yr <= 0.5 && yr >= 0.5 - SLOP);
    }
    if (verbose()) {
        double t = 1, y0 = f.y0;
        printf("shape_dynamics: pre-solve declining: box fell through the floor, %d steps touching, %d calls; at 1 s y %.9f vs "
               "exact Euler y0 - g t (t + h)/2 %.9f (continuous y0 - g t^2/2 %.9f, lag g t h/2 %.4g); worst error %.3g and %.3g "
               "of the y and v bounds (%.3g m, %.3g m/s at 1 s)\n",
               touching_steps, L.calls, (double)ga2d_body_center(w, box).y, y0 - G * t * (t + f.h) / 2, y0 - G * t * t / 2,
               G * t * f.h / 2, worst_y, worst_v, by, bv);
    }
    ga2d_world_destroy(w);
}

/* 2b. A one-way platform: a thin static platform (4 x 0.1 m, top y = 3.05)
   and a box (0.5 m) thrown up from y = 1 at 8 m/s from below it, the
   callback's rule presolve_cb.  Free flight (flight_*) takes the box's
   bottom past the platform's top at 4.2 m/s and to 0.9 m above it, and
   back down; the platform declines every call while the box comes up
   (constraint_count 0), so up to the landing step every step is free
   flight to flight_bound: in particular while the box is inside the
   platform's slab it is never pushed down (nor up).  The landing step is
   first_push's, from the first step that starts falling (premise: its
   decisions 1e-5 m or more from their thresholds).  The box then rests
   on the platform: after 1.5 s its bottom is within [top - slop, top],
   its x still 0 and its speed at the level of rounding on a resting
   contact (two points solved as a block by the relax pass with the
   masses of the very anchors it measures at, so both points' normal
   speeds end at 0 to rounding: |v| <= 64 u X/m, X = 2 m g h as in 1b,
   and likewise |w| times the half width).  The callback was called in
   the passage steps, naming the platform's shape and the box's, and every
   one of those steps solved no constraint. */
static void presolve_one_way_platform(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    presolve_log L;
    ga2d_body_id box;
    ga2d_shape_id plat_shape, box_shape;
    flight f;
    const double top = 3.05, half = 0.25, y0 = 1, v0 = 8;
    int k, land = -1, passage_steps = 0, passage_calls = 0, declined = 1, free_ok = 1;
    double worst = 0, worst_passage = 0, m, X, bv;
    memset(&L, 0, sizeof L);
    wd.pre_solve = presolve_cb;
    wd.pre_solve_context = &L;
    w = make_world(wd);
    if (!w) return;
    add_static_box(w, 0, 3, 2, 0.05, 0.6, &plat_shape);
    sd.enable_pre_solve_events = 1;
    box = add_dynamic(w, 0, y0, 0, v0, half, half, 0, &sd, &box_shape);
    m = (double)ga2d_body_mass_data(w, box).mass;
    X = 2 * m * G * sub_h();
    L.world = w;
    L.box = box;
    L.box_shape = box_shape;
    L.other_shape = plat_shape;
    L.top = top;
    L.half = half;
    L.named = L.manifolds = 1;
    L.allow = 1;
    flight_start(&f, (double)ga2d_body_center(w, box).y, (double)ga2d_body_velocity(w, box).y);
    /* the landing step: first_push from the first step that starts falling */
    {
        flight g = f;
        long J;
        double margin;
        int k0 = 0;
        while (flight_v(&g, g.j) > 0 && k0 < 200) {
            flight_advance(&g, substeps());
            ++k0;
        }
        k = first_push(g, top + half, &J, &margin);
        CHECK(k > 0);
        land = k0 + k;
        CHECK(margin >= 1e-5); /* every decision clear of rounding */
    }
    for (k = 1; k <= land + 90; ++k) {
        ga2d_vec c, v;
        int before = L.calls;
        int below_top = (double)ga2d_body_center(w, box).y - half < top;
        step(w);
        flight_advance(&f, substeps());
        c = ga2d_body_center(w, box);
        v = ga2d_body_velocity(w, box);
        if (k < land) {
            double ey = fabs((double)c.y - flight_y(&f, f.j)), ev = fabs((double)v.y - flight_v(&f, f.j));
            int inside = (double)c.y + half > top - 0.1 && (double)c.y - half < top; /* the box overlaps the slab */
            free_ok &= ey <= flight_bound_y(&f) && ev <= flight_bound_v(&f) && c.x == 0 && v.x == 0;
            worst = fmax(worst, fmax(ey / flight_bound_y(&f), ev / flight_bound_v(&f)));
            if (inside || below_top) {
                if (inside) {
                    ++passage_steps;
                    worst_passage = fmax(worst_passage, ev);
                }
                passage_calls += L.calls - before;
                declined &= ga2d_world_get_counters(w).constraint_count == 0;
            }
        }
    }
    CHECK(free_ok);
    CHECK(passage_steps >= 2);
    CHECK(passage_calls >= passage_steps);
    CHECK(declined);
    CHECK(L.named);
    CHECK(L.manifolds);
    bv = 64 * U * X / m;
    {
        ga2d_vec c = ga2d_body_center(w, box), v = ga2d_body_velocity(w, box);
        double bottom = (double)c.y - half;
        CHECK(bottom <= top && bottom >= top - SLOP);
        CHECK(c.x == 0);
        CHECK(fabs((double)v.x) <= bv && fabs((double)v.y) <= bv);
        CHECK(fabs((double)ga2d_body_angular_velocity(w, box)) * half <= bv);
        if (verbose())
            printf("shape_dynamics: one-way platform: %d steps inside the slab (%d calls, all declined), free flight to %.3g of "
                   "its bound up to the landing step %d (largest |v - v_free| in the slab %.3g m/s); resting: bottom %.6f (top "
                   "%.2f), v (%+.3g, %+.3g) m/s, w %+.3g rad/s (bound %.3g)\n",
                   passage_steps, passage_calls, worst, land, worst_passage, bottom, top, (double)v.x, (double)v.y,
                   (double)ga2d_body_angular_velocity(w, box), bv);
    }
    ga2d_world_destroy(w);
}

/* ============================================================ 3. hit events
   A box (0.5 m, restitution 0, its shape with enable_hit_events unless
   said) dropped from rest with its bottom H above the ground (a static
   box, top y = 0).  A hit is reported (ga2d__hit_events) for a contact
   whose approach speed at the step's start (-v.n over its points, taken
   when the constraints are made) beats the threshold and whose point
   pushed (its normal impulse after the step > 0).  So the hit comes in
   the step of the first push (first_push, from the exact free flight),
   with the speed at that step's start, |v_(n_sub (k-1))|, to
   flight_bound_v plus the dot product's 4 u |v|; premise: every deciding
   quantity of first_push is 1e-5 m or more from its threshold, far above
   flight_bound_y (1e-6 m).
   Against free fall: the discrete flight keeps (|v| + g h/2)^2 + 2 g y =
   (g h/2)^2 + 2 g H (symplectic Euler's modified energy), and at the hit
   step's start the gap lies in [0, d_max), d_max = |v| dt + 10 g h^2 + |v|
   h (if the step before touched without pushing, its last gap was at
   least |v| h >= 0, else above the speculative 0.02 m plus |v| dt, more
   than that step closes; and a push at substep J <= n_sub needs y_J <
   |v_J| h, what a step and a braking substep close), so the approach
   speed lies
   in [sqrt((g h/2)^2 + 2 g (H - d_max)) - g h/2, sqrt(2 g H)]: within about
   g dt + g h of sqrt(2 g H) (the contact begins at most a step before the
   impact), checked as that interval widened by the rounding.
   The event names the ground's shape (A, made first) and the box's, its
   normal points from A to B, (0, 1) to 4 u, and its point, the
   manifold's, lies midway between the surfaces at the step's start: x
   within the bottom face's [-0.25, 0.25], y the gap / 2, both to the
   rounding of the gap (flight_bound_y) and 8 u (H + 1) for the collider's
   arithmetic.
   H = 1.2 puts the first push inside a step (J not a step's last
   substep, a premise checked): see landing_reports_one_hit for the other
   case.  Cases: threshold 0 (which means 1 m/s): one hit, in the
   predicted step, over 1.5 s; the predicted approach less 1e-3 m/s: one
   hit; plus 1e-3 m/s: none (1e-3 is more than 10 times the approach's
   rounding bound, a premise checked); the box's shape without hit events:
   none. */
typedef struct hit_pred {
    int step, J;
    double approach, gap, bv, by, lo, hi, margin;
} hit_pred;

static void hit_predict(double H, hit_pred *p)
{
    const int nsub = substeps();
    const double h = sub_h();
    flight f;
    long J = 0;
    memset(p, 0, sizeof *p);
    flight_start(&f, (double)(ga2d_real)(H + 0.25), 0);
    p->step = first_push(f, 0.25, &J, &p->margin);
    p->J = (int)J;
    flight_advance(&f, (p->step - 1) * nsub);
    p->approach = fabs(flight_v(&f, f.j));
    p->gap = flight_y(&f, f.j) - 0.25;
    p->bv = flight_bound_v(&f) + 4 * U * p->approach;
    p->by = flight_bound_y(&f);
    {
        /* H as the library has it: the centre rounded to ga2d_real */
        double Hl = f.y0 - 0.25, vmax = sqrt(2 * G * Hl) + G * h, dmax = vmax * DT + 10 * G * h * h + vmax * h;
        p->lo = sqrt(G * G * h * h / 4 + 2 * G * (Hl - dmax)) - G * h / 2;
        p->hi = sqrt(2 * G * Hl);
    }
}

/* Drops the box from H with the given threshold and hit flag; returns the
   number of hit events over 90 steps, the first in *first (step in *at). */
static int hit_run(double H, double threshold, int flag, ga2d_contact_hit_event *first, int *at, ga2d_shape_id *ground_out,
                   ga2d_shape_id *box_out)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_shape_id gs, bs;
    int k, i, hits = 0;
    wd.hit_event_threshold = (ga2d_real)threshold;
    w = make_world(wd);
    if (!w) return -1;
    add_static_box(w, 0, -0.5, 5, 0.5, 0.6, &gs);
    sd.enable_hit_events = flag;
    add_dynamic(w, 0, H + 0.25, 0, 0, 0.25, 0.25, 0, &sd, &bs);
    for (k = 1; k <= 90; ++k) {
        ga2d_contact_events e;
        step(w);
        e = ga2d_world_contact_events(w);
        for (i = 0; i < e.hit_count; ++i) {
            if (hits == 0) {
                *first = e.hit[i];
                *at = k;
            }
            ++hits;
        }
    }
    *ground_out = gs;
    *box_out = bs;
    ga2d_world_destroy(w);
    return hits;
}

static void hit_events_on_landing(void)
{
    const double H = 1.2, margin = 1e-3;
    hit_pred p;
    ga2d_contact_hit_event e;
    ga2d_shape_id gs, bs;
    int at = -1, hits;
    hit_predict(H, &p);
    CHECK(p.step > 0);
    CHECK(p.J % substeps() != 0); /* the premise: the first push falls inside a step */
    CHECK(p.margin >= 1e-5);
    CHECK(margin > 10 * p.bv);
    CHECK(p.approach > 1 + margin); /* the default threshold is below it */
    /* threshold 0 (1 m/s) */
    memset(&e, 0, sizeof e);
    hits = hit_run(H, 0, 1, &e, &at, &gs, &bs);
    CHECK(hits == 1);
    CHECK(at == p.step);
    CHECK(ga2d_shape_id_equal(e.shape_a, gs) && ga2d_shape_id_equal(e.shape_b, bs));
    CHECK_NEAR(e.approach_speed, p.approach, p.bv);
    CHECK((double)e.approach_speed >= p.lo - p.bv && (double)e.approach_speed <= p.hi + p.bv);
    CHECK_NEAR(e.normal.x, 0, 4 * U);
    CHECK_NEAR(e.normal.y, 1, 4 * U);
    CHECK(fabs((double)e.point.x) <= 0.25 + 8 * U * (H + 1));
    CHECK_NEAR(e.point.y, p.gap / 2, p.by + 8 * U * (H + 1));
    if (verbose())
        printf("shape_dynamics: hit from H %.2f m: %d event at step %d (predicted %d, first push in substep %d); approach %.9f vs "
               "discrete %.9f: %+.3g (bound %.3g); vs sqrt(2 g H) %.6f: %+.4f (interval %+.4f..0, g dt %.4f); normal (%g, %g), "
               "point (%.6f, %.3g) vs gap/2 %.3g\n",
               H, hits, at, p.step, p.J, (double)e.approach_speed, p.approach, (double)e.approach_speed - p.approach, p.bv,
               sqrt(2 * G * H), (double)e.approach_speed - sqrt(2 * G * H), p.lo - p.hi, G * DT, (double)e.normal.x,
               (double)e.normal.y, (double)e.point.x, (double)e.point.y, p.gap / 2);
    /* just below and just above the approach speed; no flag */
    hits = hit_run(H, p.approach - margin, 1, &e, &at, &gs, &bs);
    CHECK(hits == 1);
    CHECK(at == p.step);
    hits = hit_run(H, p.approach + margin, 1, &e, &at, &gs, &bs);
    CHECK(hits == 0);
    if (verbose()) printf("shape_dynamics: hit threshold approach + %g m/s: %d events\n", margin, hits);
    hits = hit_run(H, 0, 0, &e, &at, &gs, &bs);
    CHECK(hits == 0);
}

/* 3b. The same drop from every H of a sweep (0.5 .. 1.5 m in steps of
   7.31 mm, the heights whose first_push decisions are 1e-5 m or more from
   their thresholds: 136 of 137): one landing, one hit, in the predicted
   step.  It failed, before the header counted a hit only for a point
   that starts pushing (one that carried no impulse from the last step),
   for the heights whose first push was the relax pass of a step's last substep (J a multiple of n_sub: 31
   of them): that pass brakes the box while it is still apart (a
   speculative point, y_J < |v_J| h), the normal impulse is positive at the
   step's end, and a hit is reported, rightly placed, with the speed at
   the step's start; the next step the box, still approaching at y_J / h,
   touches and pushes, and a second hit is reported with that speed
   whenever it beats the threshold (24 of the 31, float and double alike;
   from H = 1.36258: 5.00 m/s at step 31, then 4.10 m/s at step 32). */
static void landing_reports_one_hit(void)
{
    int i, wrong = 0, last_bad = 0, n = 0;
    double worst_h = 0;
    for (i = 0; i < 137; ++i) {
        double H = 0.5 + 0.00731 * i;
        hit_pred p;
        ga2d_contact_hit_event e;
        ga2d_shape_id gs, bs;
        int at = -1, hits;
        hit_predict(H, &p);
        if (p.margin < 1e-5) continue; /* too close to a decision to predict */
        hits = hit_run(H, 0, 1, &e, &at, &gs, &bs);
        ++n;
        if (hits != 1 || at != p.step) {
            ++wrong;
            last_bad = hits;
            worst_h = H;
        }
    }
    CHECK(wrong == 0);
    if (verbose())
        printf("shape_dynamics: hits over %d drop heights: %d not exactly one in the predicted step (last H %.5f: %d hits)\n", n,
               wrong, worst_h, last_bad);
}

/* =========================================== 4. sliding round a chain loop
   A closed chain loop (is_loop), a 40 x 10 m rectangle wound
   counter-clockwise (so it holds bodies inside), each side cut into 1 m
   segments: 100 segments, 40 along the bottom, y = 0, from x = -20 to 20.
   Friction 0 on the chain and on the body.  A box (1 x 1 m) and,
   separately, a ball (r = 0.25 m) rest on the bottom at x = -18 for 1 s,
   are then set sliding at vx = 5 m/s for 5 s: to x = 7, across 25 joins.

   Horizontal speed.  vx changes only by the x parts of impulses: the
   normal's n.x lambda and the friction's t.x tau; friction is 0 (mu =
   sqrt(0 x 0) = 0, so the clamp keeps tau = 0).  A straight chain keeps
   only face normals (ga2d__chain_keeps), n = (+-0, 1) (n.x exactly, n.y
   to its last bit: a premise checked on every manifold), so each x part
   is +-0 and adding it is
   exact: vx stays 5 bit for bit.  Whatever the normals, the bound is
       |vx - 5| <= n_sub k (u |vx| + max|n.x| X / m) per step, summed,
   k = 10 applications a substep per contact touching (each of its two
   points: the warm start, and the soft and relax passes' normal and
   friction), X = 2 m g h: with max |n.x| = 0, exact.

   Vertical speed.  At a step's end the relax pass has just solved the
   contact's point(s) without bias: a ball's one point (or the two
   contacts' coincident points at a join, the same normal) ends with its
   normal speed zero up to the rounding of that solve, which acts on
   speeds of the impulse's size: the relative velocity's ~6 operations,
   the impulse's product and accumulation, the apply's product and add:
   about 16 u of (|v_y before| + lambda/m) <= 16 u (X/m + X/m), and
   1/K vs K within 8 u of the same: 64 u X/m is comfortable.  The ball's
   point lies under its centre to the rounding of its anchors (built from
   the centres, |x| <= 20), |rb.x| <= 8 u (|x| + 1), so vy = v_n -
   w rb.x: |vy| <= 64 u X / m + 8 u (|x| + 1) |w|max.  Checked for the
   ball every step of the slide.  For the box the same argument holds
   for a contact of two points solved as a block with the masses of the
   anchors it is measured at; box_slides_loop_at_rounding checks it (in
   float; see there for double).  Here the box's vy is printed. */
typedef struct loop_result {
    int exact, normals_exact, crossed, contacts_max;
    double vy_max, w_max, nx_max, x_max, dvx, bvx, bvy;
} loop_result;

static void loop_run(int ball, loop_result *res)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w = make_world(wd);
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_vec pts[100];
    ga2d_body_id ground, b;
    ga2d_chain_id chain;
    const double h = sub_h(), r = ball ? 0.25 : 0.5;
    double m, X;
    int i, n = 0;
    memset(res, 0, sizeof *res);
    res->exact = res->normals_exact = 1;
    if (!w) return;
    for (i = 0; i < 40; ++i) pts[n++] = ga2d_vec_make((ga2d_real)(-20 + i), 0);
    for (i = 0; i < 10; ++i) pts[n++] = ga2d_vec_make(20, (ga2d_real)i);
    for (i = 0; i < 40; ++i) pts[n++] = ga2d_vec_make((ga2d_real)(20 - i), 10);
    for (i = 0; i < 10; ++i) pts[n++] = ga2d_vec_make(-20, (ga2d_real)(10 - i));
    ground = ga2d_body_create(w, &d);
    cd.points = pts;
    cd.count = n;
    cd.is_loop = 1;
    cd.friction = 0;
    chain = ga2d_chain_create(w, ground, &cd);
    CHECK(ga2d_chain_get_segments(w, chain, NULL, 0) == 100);
    sd.friction = 0;
    b = add_dynamic(w, -18, r, 0, 0, ball ? 0 : 0.5, 0.5, ball ? r : 0, &sd, NULL);
    m = (double)ga2d_body_mass_data(w, b).mass;
    X = 2 * m * G * h;
    for (i = 0; i < 60; ++i) step(w);
    CHECK_RESULT(ga2d_body_set_velocity(w, b, ga2d_vec_make(5, 0)), GA2D_OK);
    for (i = 0; i < 300; ++i) {
        ga2d_contact_data c[4];
        ga2d_vec v;
        int j, nc;
        step(w);
        v = ga2d_body_velocity(w, b);
        nc = ga2d_world_get_contacts(w, c, 4);
        CHECK(nc >= 1 && nc <= 4);
        if (nc > res->contacts_max) res->contacts_max = nc;
        for (j = 0; j < nc && j < 4; ++j) {
            res->nx_max = fmax(res->nx_max, fabs((double)c[j].manifold.normal.x));
            /* n.x = +-0 is what keeps vx exact; n.y may be 1 to its
               last bit (a round contact's unit normal made as r / |r|) */
            res->normals_exact &= c[j].manifold.normal.x == 0 && fabs((double)c[j].manifold.normal.y - 1) <= 2 * U;
        }
        res->exact &= v.x == 5;
        res->dvx = fmax(res->dvx, fabs((double)v.x - 5));
        res->bvx += substeps() * 10 * nc * (U * fabs((double)v.x) + res->nx_max * X / m);
        res->vy_max = fmax(res->vy_max, fabs((double)v.y));
        res->w_max = fmax(res->w_max, fabs((double)ga2d_body_angular_velocity(w, b)));
        res->x_max = fmax(res->x_max, fabs((double)ga2d_body_center(w, b).x));
    }
    res->crossed = (double)ga2d_body_center(w, b).x > 6.9; /* -18 + 5 x 5 = 7 */
    res->bvy = 64 * U * X / m + 8 * U * (res->x_max + 1) * res->w_max;
    ga2d_world_destroy(w);
}

static void bodies_slide_a_chain_loop(void)
{
    int ball;
    for (ball = 0; ball < 2; ++ball) {
        loop_result res;
        loop_run(ball, &res);
        CHECK(res.crossed);
        CHECK(res.normals_exact);
        CHECK(res.dvx <= res.bvx);
        if (res.nx_max == 0) CHECK(res.exact);
        if (ball) CHECK(res.vy_max <= res.bvy);
        if (verbose())
            printf("shape_dynamics: %s slides a 100-segment loop across 25 joins (up to %d contacts): vx 5 exactly every step %d "
                   "(|dvx| %.3g, bound %.3g; max |n.x| %.3g); max |vy| %.3g m/s (rounding bound %.3g%s), max |w| %.3g rad/s\n",
                   ball ? "ball" : "box", res.contacts_max, res.exact, res.dvx, res.bvx, res.nx_max, res.vy_max, res.bvy,
                   ball ? "" : ", not checked here", res.w_max);
    }
}

/* 4b. The box's vy across the joins against the rounding bound above.
   The box stands on the loop's joins (it is as wide as a segment), on
   two contacts of one point each, solved one after the other in the
   step's one relax pass: the second point's impulse moves the first
   point's speed by K12/K22 of what it removes, so the pass ends with the
   first point's speed left by Gauss-Seidel, not rounding.  In float that
   residual lies under the rounding bound (3.7e-8 against 3.2e-7 m/s);
   in double it does not (7.7e-14 against 5.9e-16), so the check runs in
   float and stays a known limit in double.  (Relaxed 8 times a substep
   instead of once, the double box keeps |vy| at 1.6e-18: the residual is
   the one pass's.)  Until the shared point sat at the box's corner
   (ga2d__share) it sat midway between anchors that slid apart and the
   box's vy reached 2.4e-5 m/s in both precisions. */
static void box_slides_loop_at_rounding(void)
{
    loop_result res;
    loop_run(0, &res);
    CHECK(res.vy_max <= res.bvy);
    if (verbose())
        printf("shape_dynamics: box on the loop: max |vy| %.3g m/s vs rounding bound %.3g; max |w| %.3g rad/s\n", res.vy_max,
               res.bvy, res.w_max);
}

void suite_shape_dynamics(void)
{
    test_run("shape_dynamics: rolling resistance slows a rolling disc at (2/3) c g and stops it by v0/a", rolling_resistance_decelerates);
    test_run("shape_dynamics: pre-solve declining everything: a box falls through a floor in exact free flight",
             presolve_declines_a_floor);
    test_run("shape_dynamics: pre-solve one-way platform: passed from below in free flight, landed on from above",
             presolve_one_way_platform);
    test_run("shape_dynamics: hit events: one on landing at the discrete free-fall speed, none above the threshold",
             hit_events_on_landing);
    test_run("shape_dynamics: a box and a ball slide a chain loop across its joins keeping vx exactly", bodies_slide_a_chain_loop);
    test_run("shape_dynamics: one landing, one hit, from every height", landing_reports_one_hit);
#ifndef GA2D_DOUBLE
    test_run("shape_dynamics: a box's vy across chain joins at rounding level (float)", box_slides_loop_at_rounding);
#endif
#ifdef GA2D_TEST_KNOWN_BUGS
    /* solver limits, described at each: they fail */
    test_run("shape_dynamics: known limit: a disc stopped by rolling resistance at rest to rounding", rolling_disc_stays_at_rest);
#ifdef GA2D_DOUBLE
    test_run("shape_dynamics: known limit: a box's vy across chain joins at rounding level (double)", box_slides_loop_at_rounding);
#endif
#else
    (void)rolling_disc_stays_at_rest;
#ifdef GA2D_DOUBLE
    (void)box_slides_loop_at_rounding;
#endif
#endif
}
