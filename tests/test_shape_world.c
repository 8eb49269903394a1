/* Bodies of round and compound shapes in a world, against analytic
   answers: a disc rolling and sliding on a slope and rolling on level
   ground, a bouncing ball, colliding discs, a compound L-shaped body, stacks
   of capsules and rounded boxes, the shape API's refusals and snapshots of
   mixed shapes.

   dt = 1/60, g = 10, default world (4 substeps, soft step) unless a test
   says otherwise; sleep off wherever a figure is measured over a fixed
   time.  u = REAL_EPS / 2 is the unit roundoff of ga2d_real; every
   tolerance below is derived in its comment from u, counted operations
   and the magnitudes they act on, or from physics.

   With GA2D_TEST_VERBOSE set, every scene prints "shape_world: ..." lines
   with its measured figures and their bounds. */
#include "test.h"

#define DT (1.0 / 60)
#define G 10.0
#define SLOP GA2D_LINEAR_SLOP
#define PI 3.14159265358979323846
#define U (REAL_EPS / 2)

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static void step(ga2d_world *w) { CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK); }

static void steps(ga2d_world *w, int n)
{
    int i;
    for (i = 0; i < n; ++i) step(w);
}

static ga2d_world *make_world(ga2d_world_def wd, int sleep)
{
    ga2d_world *w;
    wd.enable_sleep = sleep;
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    return w;
}

/* A static box of half-extents hx x hy centred at (x, y). */
static ga2d_body_id add_static_box(ga2d_world *w, double x, double y, double hx, double hy, double friction)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    d.friction = (ga2d_real)friction;
    return ga2d_body_create(w, &d);
}

/* test_solver.c's ground: half-extents 100 x 1 at y = -1, its top at y = 0. */
static ga2d_body_id add_ground(ga2d_world *w) { return add_static_box(w, 0, -1, 100, 1, 0.6); }

/* A dynamic body with no shape of its own, at (x, y). */
static ga2d_body_id add_empty_body(ga2d_world *w, double x, double y)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.polygon.count = 0;
    return ga2d_body_create(w, &d);
}

/* A disc of radius r centred on its body's origin at (x, y). */
static ga2d_body_id add_disc(ga2d_world *w, double x, double y, double r, double density, double friction, double restitution)
{
    ga2d_body_id id = add_empty_body(w, x, y);
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_shape_id s;
    sd.density = (ga2d_real)density;
    sd.friction = (ga2d_real)friction;
    sd.restitution = (ga2d_real)restitution;
    c.center = ga2d_vec_make(0, 0);
    c.radius = (ga2d_real)r;
    s = ga2d_shape_create_circle(w, id, &sd, &c);
    CHECK(!ga2d_body_id_is_null(id) && !ga2d_shape_id_is_null(s));
    return id;
}

/* The friction a contact of mu against mu gets: sqrt(mu mu), in ga2d_real
   as the library mixes it (a correctly rounded square root: the double
   root rounded to float is the float root). */
static double mixed_friction(double mu)
{
    ga2d_real m = (ga2d_real)mu, p = m * m;
    return (double)(ga2d_real)sqrt((double)p);
}

/* ============================================================ a disc on a slope
   The slope is level ground (a static box of half-extents 10 x 0.5 centred
   at (0, -0.5), its top face y = 0) under gravity tilted by theta = 20 deg:
   g = G (-sin theta, -cos theta), so the contact's normal is n = (0, 1)
   and its tangent (1, 0) exactly and the centre's coordinates stay within
   3 m (the disc, r = 0.5 m, density 1, starts touching at (2.5, r) and rolls
   towards -x: 4.6 m in 2 s).  g_t = -g.x and g_n = g.y are the stored
   components (the solver's own numbers).  Friction mu on both, so the
   contact's mu is mixed_friction(mu).  Every step records the disc's
   state and its contact. */
#define ROLL_STEPS 120
#define ROLL_R 0.5
#define ROLL_THETA (20 * PI / 180)

typedef struct roll_rec {
    double vx, vy, w, cx, cy, qc, qs; /* after the step */
    double s, nimp, timp;             /* the manifold's point: separation, impulses */
    double nx, ny;
    int contacts, points;
} roll_rec;

typedef struct roll_run_data {
    roll_rec rec[ROLL_STEPS + 1]; /* [0]: at creation; [k]: after step k */
    double m, I, gt, gn, mu;      /* the disc's mass data; gravity along -x and along y; mixed mu */
    int shapes_named;             /* every contact named the ground's and the disc's shapes */
} roll_run_data;

static void roll_record(ga2d_world *w, ga2d_body_id disc, ga2d_shape_id ds, roll_rec *r, int *named)
{
    ga2d_vec v = ga2d_body_velocity(w, disc), c = ga2d_body_position(w, disc);
    ga2d_rotor q = ga2d_body_rotor(w, disc);
    ga2d_contact_data cd[2];
    memset(r, 0, sizeof *r);
    r->vx = (double)v.x;
    r->vy = (double)v.y;
    r->w = (double)ga2d_body_angular_velocity(w, disc);
    r->cx = (double)c.x;
    r->cy = (double)c.y;
    r->qc = (double)q.c;
    r->qs = (double)q.s;
    r->contacts = ga2d_world_get_contacts(w, cd, 2);
    if (r->contacts == 1) {
        r->points = cd[0].manifold.count;
        r->nx = (double)cd[0].manifold.normal.x;
        r->ny = (double)cd[0].manifold.normal.y;
        r->s = (double)cd[0].manifold.points[0].separation;
        r->nimp = (double)cd[0].manifold.points[0].normal_impulse;
        r->timp = (double)cd[0].manifold.points[0].tangent_impulse;
        /* the ground was made first: shape A is the ground's, B the disc's */
        *named &= ga2d_shape_id_equal(cd[0].shape_b, ds) && ga2d_body_id_equal(cd[0].body_b, disc);
    }
}

static void roll_run(double mu, double gx, double gy, double x0, double vx0, double w0, roll_run_data *o)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id disc;
    ga2d_shape_id ds;
    ga2d_mass md;
    int k;
    memset(o, 0, sizeof *o);
    wd.gravity = ga2d_vec_make((ga2d_real)gx, (ga2d_real)gy);
    w = make_world(wd, 0);
    if (!w) return;
    add_static_box(w, 0, -0.5, 10, 0.5, mu);
    disc = add_disc(w, x0, ROLL_R, ROLL_R, 1, mu, 0);
    CHECK(ga2d_body_get_shapes(w, disc, &ds, 1) == 1);
    if (vx0 != 0 || w0 != 0) {
        CHECK_RESULT(ga2d_body_set_velocity(w, disc, ga2d_vec_make((ga2d_real)vx0, 0)), GA2D_OK);
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, disc, (ga2d_real)w0), GA2D_OK);
    }
    md = ga2d_body_mass_data(w, disc);
    o->m = (double)md.mass;
    o->I = (double)md.inertia;
    o->gt = -(double)ga2d_world_gravity(w).x;
    o->gn = (double)ga2d_world_gravity(w).y;
    o->mu = mixed_friction(mu);
    o->shapes_named = 1;
    roll_record(w, disc, ds, &o->rec[0], &o->shapes_named);
    for (k = 1; k <= ROLL_STEPS; ++k) {
        step(w);
        roll_record(w, disc, ds, &o->rec[k], &o->shapes_named);
    }
    ga2d_world_destroy(w);
}

/* The turn in step k (from the rotors, in double). */
static double roll_turn(const roll_run_data *o, int k)
{
    const roll_rec *a = &o->rec[k - 1], *b = &o->rec[k];
    return atan2(b->qs * a->qc - b->qc * a->qs, b->qc * a->qc + b->qs * a->qs);
}

/* The contact's lever at the end of step k.  The manifold of step k
   (made at its start, read after it) puts its point midway between the
   surfaces, rho0 = r + s/2 below the centre (s < 0: overlap), and the
   solver follows it through the step (ga2d__point_now): the point stays
   midway as the centre moves by dc along n, and stays at the disc's
   bottom as the disc turns (its comment: "only the core point turns with
   the body (a rolling disc's contact stays at its bottom ...)"; a disc's
   core point is its centre).  So the last pass of the step (the relax
   pass, after the last positions) acts at
       rho_end = r + s/2 + dc.n / 2.
   How the library does it: a round side's anchor is split into a core
   part that turns with the body, anchor + n r, and its radius along n,
   which does not; for the manifold's midway point that core part is
   -n s/2, half the overlap above the centre, not the centre.  Turned by
   phi it lifts the anchors' gap along n by (s/2)(1 - cos phi) and moves
   the lever to rho_end - (s/4)(1 - cos phi) (turned = 1 gives that one:
   8e-8 m at 9 rad/s, printed), and it puts the normal impulse
   (|s|/2) sin(phi) off the centre (see disc_rolls_down_a_slope). */
static double roll_lever_end(const roll_run_data *o, int k, int turned)
{
    const roll_rec *r = &o->rec[k];
    double rho = ROLL_R + r->s / 2 + (r->cy - o->rec[k - 1].cy) / 2;
    return turned ? rho - r->s / 4 * (1 - cos(roll_turn(o, k))) : rho;
}

/* X: the most normal impulse a substep may carry, twice the weight's
   impulse m |g| h (a premise each test checks on the manifold). */
static double roll_x(const roll_run_data *o) { return 2 * o->m * G * DT / ga2d_default_world_def().substeps; }

/* The slip at the end of step k, vx + w rho_end: the speed of the disc's
   point at the lever rho_end (below the centre; tangent (1, 0)).

   Why it is zero, and to what.  Friction is one unclamped 1-D constraint
   per pass (rolling: the cap mu x is never reached, a premise the test
   checks), decoupled from the normal (which passes through the centre),
   with the mass 1/K0, K0 = 1/m + rho0^2/I, of the step (made from the
   manifold's anchors).  The relax pass, the substep's last, applies
   dt = -vt/K0 at the lever rho_end, which leaves vt (1 - K_end/K0).  So
   |slip| <= Q + R_a:
   - Q = |1 - K_end/K0| V, V bounding the slip that last friction met:
     what the soft pass's friction left, at most the slip it met (the kick
     g h and the warm start's friction K0 mu X), plus what the anchors'
     travel between the two passes makes of the spin: the centre moves
     along n at no more than the push cap v_push, so the lever by at most
     h v_push / 2, times |w|.
   - R_a, rounding: vt = vx - rb.y w (two roundings), dt = -tmass vt, the
     accumulation and the clamp, and the two adds that apply it (to vx and
     to w): <= 8 u (|vx| + rho |w|) + 8 u K0 mu X; and the lever: the
     solver's rb.y is a handful of adds of the anchors' and centres' y
     (Y = |cy + 0.5| + 0.5 + r: the centre over the ground's, the ground's
     anchor, the disc's), and rho_end here takes the centre's stored
     heights where the solver sums the substeps' displacements: <= 16 u Y
     together, times |w|.
   Float: about 2e-5 m/s at 9 rad/s (the lever's rounding); double: Q,
   about 2e-9 m/s at 9 rad/s, against the 8e-7 m/s that the core part's
   turn makes of the lever. */
static double roll_slip_bound(const roll_run_data *o, int k, double mu_cap, double *q_out)
{
    const roll_rec *r = &o->rec[k];
    const double h = DT / ga2d_default_world_def().substeps, X = roll_x(o);
    const double rho0 = ROLL_R + r->s / 2, rho = roll_lever_end(o, k, 0);
    const double K0 = 1 / o->m + rho0 * rho0 / o->I, Ke = 1 / o->m + rho * rho / o->I;
    const double Y = fabs(r->cy + 0.5) + 0.5 + ROLL_R, w = fabs(r->w);
    const double push = (double)ga2d_default_world_def().contact_push_max_velocity;
    double V = G * h + K0 * mu_cap * X + w * h * push / 2;
    double Q = fabs(1 - Ke / K0) * V;
    if (q_out) *q_out = Q;
    return Q + 8 * U * (fabs(r->vx) + rho * w) + 8 * U * K0 * mu_cap * X + w * 16 * U * Y;
}

/* The rounding of a window's velocity and spin changes, n substeps from
   step k1 to k2, as incline_rounding counts them: every substep adds to
   vx 6 times (the kick, the warm start, the soft pass's normal and
   friction impulses, the relax pass's two), each off by <= u |v|; to w 5
   times (no kick), each <= u |w|; and each of the 5 impulse applications
   rounds its product (<= u X / m on v, 4 u rho X / I on w through the
   wedge).  V2, W2: the larger speeds, at the window's end. */
static void roll_window_rounding(const roll_run_data *o, int k1, int k2, double *dv, double *dw)
{
    const double n = (double)(k2 - k1) * ga2d_default_world_def().substeps, X = roll_x(o);
    double V = fmax(fabs(o->rec[k1].vx), fabs(o->rec[k2].vx)), W = fmax(fabs(o->rec[k1].w), fabs(o->rec[k2].w));
    *dv = n * U * (6 * V + 5 * X / o->m);
    *dw = n * U * (5 * W + 5 * 4 * ROLL_R * X / o->I);
}

/* The levers the window's friction acted at: each step's rho0 = r + s/2
   and its travel within the step, |dc.n|/2 (roll_lever_end), over every
   step of the window. */
static void roll_lever_range(const roll_run_data *o, int k1, int k2, double *lo, double *hi)
{
    int k;
    *lo = HUGE_VAL;
    *hi = -HUGE_VAL;
    for (k = k1 + 1; k <= k2; ++k) {
        const roll_rec *r = &o->rec[k];
        double rho0 = ROLL_R + r->s / 2, travel = fabs(r->cy - o->rec[k - 1].cy) / 2;
        *lo = fmin(*lo, rho0 - travel);
        *hi = fmax(*hi, rho0 + travel);
    }
}

/* The premises every disc-on-slope figure rests on: one contact of one
   point named by the disc's shape, normal (0, 1), overlapping within a
   slop, pushing with at most X a substep, and (for rolling) friction
   inside its cone: |tangent impulse| < mu * normal impulse. */
static void roll_premises(const roll_run_data *o, int rolling)
{
    int k, one = 1, flat = 1, within = 1, load = 1, cone = 1;
    for (k = 1; k <= ROLL_STEPS; ++k) {
        const roll_rec *r = &o->rec[k];
        one &= r->contacts == 1 && r->points == 1;
        flat &= r->nx == 0 && r->ny == 1;
        within &= r->s >= -SLOP && r->s <= 0;
        load &= r->nimp > 0 && r->nimp <= roll_x(o);
        if (rolling) cone &= fabs(r->timp) < o->mu * r->nimp;
    }
    CHECK(one);
    CHECK(o->shapes_named);
    CHECK(flat);
    CHECK(within);
    CHECK(load);
    CHECK(cone);
}

/* 1. A solid disc rolls down the slope (mu = 0.6 > tan(theta)/3, so it
   rolls) with a = (2/3) g sin theta and w = v / r.

   What the solver should give exactly (the lead engineer's derivation,
   checked here): the contact's lever is rho = r + s/2 (its point midway
   between the surfaces, s the manifold's separation); the normal passes
   through the centre, so the friction is a 1-D constraint decoupled from
   it, unclamped, and each pass removes the contact's slip.  By momentum
   and angular momentum over a window T,
       m dv = m g_t T - J,   I dw = rho J,   v = w rho at both ends,
   so a = dv/T = g_t m rho^2 / (m rho^2 + I) = g_t 2q / (1 + 2q), q =
   rho^2/r^2 (I = m r^2/2): (2/3) g sin theta at s = 0.  (Per substep the
   slip grows by g_t h and the friction takes g_t h / (m K_t) of it from
   v, K_t = 1/m + rho^2/I: the same a.)

   (a) At steps 30, 60, 90, 120 the slip vx + w rho_end is zero within
   roll_slip_bound, rho_end = r + s/2 + dc.n/2 the lever at the step's end
   (roll_lever_end: the midway point moves with the centre during the
   step; at rho = r + s/2 itself the slip is w dc.n/2, over rounding in
   double, printed).
   (b) Over 1 s .. 2 s (T = 1 s, n = 240 substeps; the overlap has
   settled) a against the formula at rho_mid, the middle of the window's
   levers [rho_lo, rho_hi] (roll_lever_range: the measured s of every step
   of the window, not only its ends, and the lever's travel within each).
   With the slips v_i = w_i rho_i + eps_i at the ends (levers rho_i) and
   I dw = sum(rho_j J_j) = rho_mid J + E, the momenta give
       a = g_t m rho_2 rho_mid / (I + m rho_2 rho_mid)
           + [rho_2 E / I + w_1 (rho_2 - rho_1) + eps_2 - eps_1] / (T (1 + m rho_2 rho_mid / I)),
   so the bound is
   - half the formula's change over [rho_lo, rho_hi] (the first term);
   - E: |E| <= (rho_hi - rho_lo)/2 sum |J_j|, and sum |J_j| <= 3 J
     (premise: in a substep the warm start applies the last substep's
     friction and neither pass changes it by more than that much again),
     J = m (g_t T - dv) by momentum;
   - the ends' levers, |w_1| |rho_1 - rho_2|;
   - rounding: [dv + (I/(m rho^2)) (|eps_1| + |eps_2| + rho dw)] /
     (T (1 + I/(m rho^2))), dv, dw from roll_window_rounding and eps_i the
     slips' bounds; 2 u g for h = dt/4 (dt rounded); 4 u a for the
     solver's 1/m and 1/I.
   That is 4e-4 m/s^2 in float (rounding); in double the levers' range
   and E, about 5e-7 m/s^2 with the lever as the library moves it now, and
   rounding's 1e-12 if the lever held still within the window.
   (c) |a - (2/3) g sin theta|, printed: 2e-5 of a (the lever r + s/2).

   What the library does instead (roll_lever_end): the disc's anchor
   turns about a core point half the overlap above the centre, so in a
   step turned by phi the lever is shorter by (|s|/4)(1 - cos phi), and the
   normal impulse lambda acts (|s|/2) sin(phi) off the centre, against
   the roll: I dw = rho J + B, B = -sum(lambda (|s|/2) sin phi).  In double
   (a) then misses by w (|s|/4)(1 - cos phi) (8e-7 m/s at 9 rad/s) and (b)
   by the torque's share of a (5e-6 m/s^2): both fail.  Printed: the slip
   at the library's own lever, which is zero to 1e-13 m/s. */
static void disc_rolls_down_a_slope(void)
{
    static const int at[4] = {30, 60, 90, 120};
    const int k1 = 60, k2 = 120;
    const double T = (k2 - k1) * DT, th = ROLL_THETA;
    roll_run_data o;
    double a, rho_lo, rho_hi, rho_mid, f_lo, f_hi, f, e_term, end_term, dv, dw, eps1, eps2, R, B, ca, rho1, rho2, worst = 0;
    int i;
    roll_run(0.6, -G * sin(th), -G * cos(th), 2.5, 0, 0, &o);
    roll_premises(&o, 1);
    CHECK(o.rec[ROLL_STEPS].cx < 2.5 - 4); /* it went down the slope, as far as rolling takes it */
    /* (a) */
    for (i = 0; i < 4; ++i) {
        const roll_rec *r = &o.rec[at[i]];
        double q, bound = roll_slip_bound(&o, at[i], o.mu, &q), slip = r->vx + r->w * roll_lever_end(&o, at[i], 0);
        CHECK_NEAR(slip, 0, bound);
        worst = fmax(worst, fabs(slip) / bound);
        if (verbose())
            printf("shape_world: rolling disc step %d: v %.6f m/s, w %.6f rad/s, s %.4g m: slip vx + w rho_end %+.3g m/s "
                   "(bound %.3g, of which Q %.3g); at r + s/2 %+.3g m/s; at the library's turned lever %+.3g m/s\n",
                   at[i], r->vx, r->w, r->s, slip, bound, q, r->vx + r->w * (ROLL_R + r->s / 2),
                   r->vx + r->w * roll_lever_end(&o, at[i], 1));
    }
    /* (b) */
    a = (o.rec[k1].vx - o.rec[k2].vx) / T; /* down the slope: -x */
    roll_lever_range(&o, k1, k2, &rho_lo, &rho_hi);
    rho_mid = (rho_lo + rho_hi) / 2;
    f_lo = o.gt * o.m * rho_lo * rho_lo / (o.m * rho_lo * rho_lo + o.I);
    f_hi = o.gt * o.m * rho_hi * rho_hi / (o.m * rho_hi * rho_hi + o.I);
    f = o.gt * o.m * rho_mid * rho_mid / (o.m * rho_mid * rho_mid + o.I);
    rho1 = roll_lever_end(&o, k1, 0);
    rho2 = roll_lever_end(&o, k2, 0);
    end_term = fabs(o.rec[k1].w) * fabs(rho1 - rho2) / (T * (1 + o.m * rho_lo * rho_lo / o.I));
    e_term = rho_hi * (rho_hi - rho_lo) / 2 * 3 * o.m * (o.gt * T - a * T) / o.I / (T * (1 + o.m * rho_lo * rho_lo / o.I));
    roll_window_rounding(&o, k1, k2, &dv, &dw);
    eps1 = roll_slip_bound(&o, k1, o.mu, NULL);
    eps2 = roll_slip_bound(&o, k2, o.mu, NULL);
    ca = o.I / (o.m * rho_lo * rho_lo);
    R = (dv + ca * (eps1 + eps2 + rho_hi * dw)) / (T * (1 + o.I / (o.m * rho_hi * rho_hi))) + 2 * U * G + 4 * U * fabs(f);
    B = fabs(f_hi - f_lo) / 2 + e_term + end_term + R;
    CHECK_NEAR(a, f, B);
    if (verbose()) {
        printf("shape_world: rolling disc a over 1..2 s %.9f vs g_t 2q/(1+2q) %.9f (rho %.9f..%.9f): %+.3g m/s^2 "
               "(bound %.3g = lever range %.3g + E %.3g + ends %.3g + rounding %.3g): %.3g x the bound\n",
               a, f, rho_lo, rho_hi, a - f, B, fabs(f_hi - f_lo) / 2, e_term, end_term, R, fabs(a - f) / B);
        /* (c) */
        printf("shape_world: rolling disc a vs (2/3) g sin theta %.9f: %+.3g m/s^2 (%+.3g of it); slips at rho_end at most "
               "%.3g x their bounds\n",
               2.0 / 3.0 * G * sin(th), a - 2.0 / 3.0 * G * sin(th), a / (2.0 / 3.0 * G * sin(th)) - 1, worst);
    }
}

/* 2. The same disc with mu = 0.05 < tan(theta)/3 = 0.121: it slides,
   its point slipping down the slope faster than a substep's whole
   friction could stop it (checked at 1 s: slip > 2 K0 mu X), so every
   pass ends with the friction at the cone's edge, F = mu N.

   Momentum, exactly (incline_slides' identity): over the window the
   normal impulses N and the friction mu N give dv_down = g_t T - mu N/m
   and dv_n = g_n T + N/m (n = (0, 1) exactly, so neither leaks into the
   other), so (dv_down + mu dv_n)/T = g_t + mu g_n = g (sin - mu cos) up
   to rounding R (incline_rounding's count for one point: 6 adds a
   substep instead of 11):
       R = (1 + mu) u [6 n |v_2| + 4 (|v_1| + |v_2|)] / T + 128 (1 + mu) u g.
   A mu off by 1e-4 of itself moves the left side by 5e-5 m/s^2: above R
   in double (1e-12), not in float (2e-4).

   Spin: the friction mu lambda of each pass acts at the lever rho, so
   I dw = mu sum(rho_i lambda_i), sum(lambda) = N = m (dv_n - g_n T):
       alpha = mu rho N / (I T) = 2 mu rho (g cos theta + dv_n/T) / r^2,
   within 3 mu N (rho_hi - rho_lo) / (2 I T) for the levers' range
   (roll_lever_range; sum |lambda_i| <= 3 N, the premise of
   disc_rolls_down_a_slope (b)) and rounding: the spin's adds and the torques' products
   (roll_window_rounding's dw), the friction's clamp, accumulation and
   subtraction (8 u mu X a substep, at the lever rho), and N's own
   (m times dv_n's rounding: 6 adds a substep of |v_y| <= its ends' + g h,
   the 5 products' u X / m, and 2 u g T for h), plus 4 u alpha for the
   solver's 1/I.  That bound is the rounding in float (2e-4 of alpha) and
   below 1e-7 of alpha in double (the lever range); the normal impulse's moment (see
   disc_rolls_down_a_slope) is left out, and would show in double.
   Printed: alpha against the textbook 2 mu g cos theta / r. */
static void disc_slides_down_a_slope(void)
{
    const int k1 = 60, k2 = 120;
    const double T = (k2 - k1) * DT, th = ROLL_THETA, n = (double)(k2 - k1) * ga2d_default_world_def().substeps;
    roll_run_data o;
    double mu, X, K0, slip1, exact, ap, R, v1, v2, dvn, N, rho_lo, rho_hi, rho_mid, alpha, ap_alpha, vyn, dvn_round, Ra, Ba, textbook;
    const roll_rec *r1, *r2;
    roll_run(0.05, -G * sin(th), -G * cos(th), 2.5, 0, 0, &o);
    roll_premises(&o, 0);
    mu = o.mu;
    X = roll_x(&o);
    r1 = &o.rec[k1];
    r2 = &o.rec[k2];
    K0 = 1 / o.m + (ROLL_R + r1->s / 2) * (ROLL_R + r1->s / 2) / o.I;
    slip1 = -(r1->vx + r1->w * (ROLL_R + r1->s / 2));
    CHECK(slip1 > 2 * K0 * mu * X);
    /* momentum */
    v1 = hypot(r1->vx, r1->vy);
    v2 = hypot(r2->vx, r2->vy);
    dvn = r2->vy - r1->vy;
    exact = (-(r2->vx - r1->vx) + mu * dvn) / T;
    ap = o.gt + mu * o.gn;
    R = (1 + mu) * U * (6 * n * v2 + 4 * (v1 + v2)) / T + 128 * (1 + mu) * U * G;
    CHECK_NEAR(exact, ap, R);
    /* spin */
    N = o.m * (dvn - o.gn * T);
    roll_lever_range(&o, k1, k2, &rho_lo, &rho_hi);
    rho_mid = (rho_lo + rho_hi) / 2;
    alpha = (r2->w - r1->w) / T;
    ap_alpha = mu * rho_mid * N / (o.I * T);
    {
        double dv, dw;
        roll_window_rounding(&o, k1, k2, &dv, &dw);
        vyn = fmax(fabs(r1->vy), fabs(r2->vy)) + G * DT / ga2d_default_world_def().substeps;
        dvn_round = n * U * (6 * vyn + 5 * X / o.m) + 2 * U * G * T;
        Ra = (dw + n * 8 * U * mu * X * rho_hi / o.I + mu * rho_hi * o.m * dvn_round / o.I) / T + 4 * U * fabs(alpha);
    }
    Ba = 3 * mu * N * (rho_hi - rho_lo) / (2 * o.I * T) + Ra;
    CHECK_NEAR(alpha, ap_alpha, Ba);
    textbook = 2 * mu * G * cos(th) / ROLL_R;
    if (verbose()) {
        printf("shape_world: sliding disc mu %.2f: (dv_down + mu dv_n)/T %.9f vs g (sin - mu cos) %.9f: %+.3g m/s^2 (bound R %.3g); "
               "slip at 1 s %.3f m/s (premise > %.3g)\n",
               mu, exact, ap, exact - ap, R, slip1, 2 * K0 * mu * X);
        printf("shape_world: sliding disc alpha %.9f vs mu rho N/(I T) %.9f: %+.3g rad/s^2 (bound %.3g = lever range %.3g + "
               "rounding %.3g): %.3g x the bound; vs textbook 2 mu g cos / r %.9f: %+.3g of it\n",
               alpha, ap_alpha, alpha - ap_alpha, Ba, Ba - Ra, Ra, fabs(alpha - ap_alpha) / Ba, textbook, alpha / textbook - 1);
    }
}

/* A disc rolling on level ground (gravity (0, -g), mu = 0.1), launched at
   v = 4 m/s with w = -v/r, rolls on at v: nothing in the physics slows
   it, and nothing in the solver should.  Over 1 .. 2 s (T = 1 s), with
   the slip eps_i = vx + w rho_i at the ends (rho_i their levers,
   roll_lever_end), m dv = J + m dv_r and I dw = sum(rho_j J_j) + I dw_r
   (dv_r, dw_r: rounding, roll_window_rounding) give
       dv (1 + m rho_2 rho_mid / I) = -rho_2 E / I - w_1 (rho_2 - rho_1)
           + eps_2 - eps_1 + (m rho_2 rho_mid / I) dv_r - rho_2 dw_r,
   E = sum((rho_j - rho_mid) J_j), |E| <= (rho_hi - rho_lo)/2 3 n mu X
   (the levers' range as roll_lever_range; each of a substep's three
   friction applications within the cone mu X).  So |dv| is bounded by
   those terms over (1 + m rho_lo^2 / I): 4e-4 m/s in float (rounding),
   about 1e-11 m/s in double.  The normal
   impulse's moment (disc_rolls_down_a_slope: lambda (|s|/2) sin(phi)
   against the roll) is a rolling resistance this bound leaves out. */
static void disc_rolls_on_level_ground(void)
{
    const int k1 = 60, k2 = 120;
    const double v0 = 4, n = (double)(k2 - k1) * ga2d_default_world_def().substeps;
    roll_run_data o;
    double rho1, rho2, rho_lo, rho_hi, E, dv, dw, eps1, eps2, bound, change;
    const roll_rec *r1, *r2;
    roll_run(0.1, 0, -G, -3, v0, -v0 / ROLL_R, &o);
    roll_premises(&o, 1);
    r1 = &o.rec[k1];
    r2 = &o.rec[k2];
    rho1 = roll_lever_end(&o, k1, 0);
    rho2 = roll_lever_end(&o, k2, 0);
    roll_lever_range(&o, k1, k2, &rho_lo, &rho_hi);
    E = (rho_hi - rho_lo) / 2 * 3 * n * o.mu * roll_x(&o);
    roll_window_rounding(&o, k1, k2, &dv, &dw);
    eps1 = roll_slip_bound(&o, k1, o.mu, NULL);
    eps2 = roll_slip_bound(&o, k2, o.mu, NULL);
    bound = (rho_hi * E / o.I + fabs(r1->w) * fabs(rho2 - rho1) + eps1 + eps2 + o.m * rho_hi * rho_hi / o.I * dv + rho_hi * dw) /
            (1 + o.m * rho_lo * rho_lo / o.I);
    change = r2->vx - r1->vx;
    CHECK_NEAR(change, 0, bound);
    if (verbose())
        printf("shape_world: disc rolling on level ground at %.0f m/s: speed change over 1..2 s %+.3g m/s (bound %.3g, "
               "of which the levers' range %.3g): %.3g x the bound; a %+.3g m/s^2, w %.4f rad/s, s %.3g m\n",
               v0, change, bound, rho_hi * E / o.I / (1 + o.m * rho_lo * rho_lo / o.I), fabs(change) / bound,
               change / ((k2 - k1) * DT), r2->w, r2->s);
}

/* ================================================================ a ball bounces
   3. A disc (r = 0.5 m) dropped from a gap h0 onto the ground (test_solver's,
   restitution 0) with restitution e: the mixed restitution is the larger,
   e, and the n-th apex is e^(2n) h0, each rebound over impact speed e.
   bounce_run of test_solver.c, with a disc for the box: heights are the
   disc's lowest point (its centre less r) above the ground's top.  Its
   derivation carries over unchanged: free flight keeps U = u^2 + 2 g y
   exactly (u = v under Verlet, v - g h/2 under symplectic Euler: the
   velocity its last drift used lags the true one by half a kick), the
   library bounces the true approach speed at e with the energy kept over
   the gap that remains, and the normal of a disc's one point passes
   through its centre (no spin: the point's speed is the centre's).  So
   every figure is exact up to rounding, bounded by D (bounce_run's
   comment in test_solver.c: the start's 2 u (g (r + h0) + lag^2); per
   substep 2 u (2 V^2 + 2 g h V + g Y); an impact scales the carried error
   by e^2 and adds 64 u V^2, which covers the disc's one point as it
   covered the box's 2 x 2 block; the test's own arithmetic 8 u (2 g Y +
   V^2)):
       |apex - U_n / (2 g)| <= D / (2 g),
       |ratio / e - 1| <= (D_i + D_r / e^2) / (U_i - D_i). */
typedef struct bounce_data {
    int impacts, apexes;
    double ratio[3], v_imp[3], v_reb[3], apex[3];
    double apex_tol[3], ratio_tol[3];
} bounce_data;

static void bounce_run(double h0, double e, ga2d_integrator integ, int want_impacts, bounce_data *out)
{
    const double r = 0.5;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id ball;
    const double ur = U, hs = DT / wd.substeps;
    double lag, flight_u2, U_n, D, D_i;
    int s, rising = 0;
    memset(out, 0, sizeof *out);
    wd.integrator = integ;
    lag = integ == GA2D_INTEGRATOR_SYMPLECTIC_EULER ? G * hs / 2 : 0;
    w = make_world(wd, 1);
    if (!w) return;
    add_ground(w);
    ball = add_disc(w, 0, r + h0, r, 1, 0.6, e);
    flight_u2 = U_n = lag * lag + 2 * G * h0; /* created at rest at h0 */
    D = 2 * ur * (G * (r + h0) + lag * lag);
    D_i = 8 * ur * U_n;
    for (s = 0; s < 400 && out->apexes < want_impacts; ++s) {
        double vb = (double)ga2d_body_velocity(w, ball).y, yb = (double)ga2d_body_position(w, ball).y, y, uu, V, Y, dU, meas;
        step(w);
        y = (double)ga2d_body_position(w, ball).y - r;
        uu = (double)ga2d_body_velocity(w, ball).y - lag;
        V = fmax(fabs(vb), fabs((double)ga2d_body_velocity(w, ball).y)) + G * DT;
        Y = fmax(fabs(yb), fabs(y + r)) + V * DT;
        dU = wd.substeps * 2 * ur * (2 * V * V + 2 * G * hs * V + G * Y);
        meas = 8 * ur * (2 * G * Y + V * V);
        if (vb < 0 && uu > 0 && !rising && out->impacts < want_impacts) {
            int n = out->impacts++;
            D = e * e * D + 64 * ur * V * V + dU;
            out->v_imp[n] = sqrt(flight_u2);
            out->v_reb[n] = sqrt(uu * uu + 2 * G * y);
            out->ratio[n] = out->v_reb[n] / out->v_imp[n];
            out->ratio_tol[n] = (D_i + (D + meas) / (e * e)) / (U_n - D_i);
            U_n *= e * e;
            rising = 1;
        } else {
            D += dU;
            if (rising && uu <= 0) {
                out->apex_tol[out->apexes] = (D + meas) / (2 * G);
                out->apex[out->apexes++] = y + uu * uu / (2 * G);
                flight_u2 = uu * uu + 2 * G * y;
                D_i = D + meas;
                rising = 0;
            }
        }
    }
    CHECK((double)ga2d_body_angular_velocity(w, ball) == 0); /* the impacts passed through its centre */
    ga2d_world_destroy(w);
}

/* e = 0.5 and 0.8, h0 = 2 m, three bounces (e = 0.5 still meets the
   1 m/s threshold at its third: e^2 sqrt(2 g h0) = 1.58 m/s), with the
   default integrator and with Verlet (test_solver's bounce_check). */
static void ball_bounces(void)
{
    static const double es[2] = {0.5, 0.8};
    static const ga2d_integrator integs[2] = {GA2D_INTEGRATOR_SYMPLECTIC_EULER, GA2D_INTEGRATOR_VERLET};
    const double h0 = 2;
    int i, k, n;
    for (i = 0; i < 2; ++i)
        for (k = 0; k < 2; ++k) {
            const double lag = integs[i] == GA2D_INTEGRATOR_SYMPLECTIC_EULER ? G * DT / 4 / 2 : 0;
            bounce_data b;
            bounce_run(h0, es[k], integs[i], 3, &b);
            CHECK(b.impacts == 3 && b.apexes == 3);
            for (n = 0; n < b.apexes; ++n) {
                double want = pow(es[k], 2.0 * (n + 1)) * (h0 + lag * lag / (2 * G));
                CHECK_NEAR(b.apex[n], want, b.apex_tol[n]);
                CHECK_NEAR(b.ratio[n] / es[k], 1, b.ratio_tol[n]);
                if (verbose())
                    printf("shape_world: ball bounce %s e %.1f n %d: apex %.6f m vs e^2n h0 %.6f: %+.2e m (bound %.2e); "
                           "rebound/impact / e - 1 %+.2e (bound %.2e)\n",
                           i == 0 ? "defaults" : "Verlet", es[k], n + 1, b.apex[n], want, b.apex[n] - want, b.apex_tol[n],
                           b.ratio[n] / es[k] - 1, b.ratio_tol[n]);
            }
        }
}

/* ============================================================ colliding discs
   4. No gravity.  Rounding model (test_solver's, for one point): a velocity
   update v += P/m rounds to <= 2 eps of the momentum scale M = sum m |v|.
   A step applies per contact at most 4 substeps x (warm start, soft pass,
   relax pass) x (normal, tangent) = 24 impulses at its one point, and the
   collision phase one per pass (it stops once nothing collides: after a
   pass or two, at most 32): 56 <= 64 impulses, so momentum drifts
   <= 128 eps M per step with a contact, and not at all in free flight
   (gravity 0: the kick adds an exact 0). */

/* Head on, along x, both e = 1 (r = 0.5): A at v = 5 m/s toward B at rest.
   The normal is the centres' line, (1, 0) exactly; the one impulse
   passes through both centres, so nothing turns and nothing moves in y.
   The 1-D elastic answer with the library's own masses:
       vA' = (mA - mB)/(mA + mB) v,   vB' = 2 mA/(mA + mB) v
   (equal masses: they exchange).  Densities 1 and 1, then 1 and 3.  A's
   start is varied over 32 values 1/32 of a step's travel (v dt / 32) apart,
   so the touch falls in every part of a step.  Tolerance: the rounding
   model, M = mA v, per contact step. */
static void head_on_discs(void)
{
    static const double densities[2] = {1, 3};
    const double v = 5;
    int j, k;
    for (j = 0; j < 2; ++j) {
        double worst = -1, worst_a = 0, worst_b = 0, want_a = 0, want_b = 0;
        int bad = 0;
        for (k = 0; k < 32; ++k) {
            ga2d_world_def wd = ga2d_default_world_def();
            ga2d_world *w;
            ga2d_body_id a, b;
            double ma, mb, wa, wb, tol, dev;
            int s, contact_steps = 0, ok;
            wd.gravity = ga2d_vec_make(0, 0);
            w = make_world(wd, 0);
            if (!w) return;
            a = add_disc(w, -2 - k * (v * DT / 32), 0, 0.5, 1, 0.6, 1);
            b = add_disc(w, 2, 0, 0.5, densities[j], 0.6, 1);
            CHECK_RESULT(ga2d_body_set_velocity(w, a, ga2d_vec_make((ga2d_real)v, 0)), GA2D_OK);
            ma = (double)ga2d_body_mass_data(w, a).mass;
            mb = (double)ga2d_body_mass_data(w, b).mass;
            wa = (ma - mb) / (ma + mb) * v;
            wb = 2 * ma / (ma + mb) * v;
            for (s = 0; s < 90; ++s) {
                step(w);
                contact_steps += ga2d_world_get_counters(w).constraint_count > 0;
            }
            tol = 128 * REAL_EPS * ma * v * (contact_steps > 0 ? contact_steps : 1);
            /* as momentum: each body's error times its mass */
            dev = fmax(ma * fabs((double)ga2d_body_velocity(w, a).x - wa), mb * fabs((double)ga2d_body_velocity(w, b).x - wb));
            dev = fmax(dev, fmax(ma * fabs((double)ga2d_body_velocity(w, a).y), mb * fabs((double)ga2d_body_velocity(w, b).y)));
            ok = contact_steps > 0 && dev <= tol && ga2d_body_angular_velocity(w, a) == 0 && ga2d_body_angular_velocity(w, b) == 0;
            CHECK(ok);
            bad += !ok;
            if (dev / tol > worst) {
                worst = dev / tol;
                worst_a = (double)ga2d_body_velocity(w, a).x;
                worst_b = (double)ga2d_body_velocity(w, b).x;
                want_a = wa;
                want_b = wb;
            }
            ga2d_world_destroy(w);
        }
        if (verbose())
            printf("shape_world: head-on discs e 1, density 1 on %.0f, 32 phases: %d wrong; worst vA %.9f vB %.9f (want %.9f, %.9f), "
                   "error %.3g x its rounding tolerance (bound 1)\n",
                   densities[j], bad, worst_a, worst_b, want_a, want_b, worst);
    }
}

typedef struct momenta { double px, py, l, ke, pscale, lscale; } momenta;

/* Linear and angular momentum (about O) and kinetic energy of discs of
   radii r[i], in double from the library's figures, with their scales:
   sum m |v|, and sum m (|c - O| + r) |v| + I |w| (a contact point lies
   within r of its disc's centre). */
static momenta momenta_of(const ga2d_world *w, const ga2d_body_id *ids, const double *r, int n, ga2d_vec o)
{
    momenta m;
    int i;
    memset(&m, 0, sizeof m);
    for (i = 0; i < n; ++i) {
        ga2d_mass md = ga2d_body_mass_data(w, ids[i]);
        ga2d_vec c = ga2d_body_center(w, ids[i]), v = ga2d_body_velocity(w, ids[i]);
        double mass = (double)md.mass, inertia = (double)md.inertia, om = (double)ga2d_body_angular_velocity(w, ids[i]);
        double rx = (double)c.x - (double)o.x, ry = (double)c.y - (double)o.y, vx = (double)v.x, vy = (double)v.y;
        m.px += mass * vx;
        m.py += mass * vy;
        m.l += mass * (rx * vy - ry * vx) + inertia * om;
        m.ke += 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * om * om;
        m.pscale += mass * hypot(vx, vy);
        m.lscale += mass * (hypot(rx, ry) + r[i]) * hypot(vx, vy) + inertia * fabs(om);
    }
    return m;
}

/* Off centre: disc A (r 0.5, density 1) from (-2, 0) at (6, 0.5) m/s
   spinning at 1 rad/s, disc B (r 0.4, density 2) from (1.5, 0.45) at
   (-3, 0) spinning at -0.5 rad/s: impact parameter about 0.4 m of the 0.9
   m the radii span.  (e, mu) = (1, 0), (1, 0.6), (0, 0.6).  Linear
   momentum and angular momentum about a fixed O (sum m (c - O) ^ v + I w)
   are conserved (impulses -P and +P act at one shared point) and kinetic
   energy never grows, to the rounding model above: per step with a
   contact 128 eps of the momentum scale; L also drifts in free flight, the
   centre's x += h v rounding to eps |x - O| m |v| a substep (4 a step);
   KE rounds to <= 2 eps of itself per update, 128 eps KE per contact
   step.  With e = 1 and no friction the collision is elastic: KE at the
   end equals KE at the start within the sum of the steps' tolerances.
   (With e = 1 the separating contact never takes a normal impulse in the
   passes, so friction 0.6 changes nothing; e = 0 keeps them touching,
   and the friction acts on their spins.) */
static void off_centre_discs_conserve(void)
{
    static const double cases[3][2] = {{1, 0}, {1, 0.6}, {0, 0.6}};
    static const double radii[2] = {0.5, 0.4};
    int k;
    for (k = 0; k < 3; ++k) {
        const double e = cases[k][0], mu = cases[k][1];
        ga2d_world_def wd = ga2d_default_world_def();
        ga2d_world *w;
        ga2d_body_id ids[2];
        ga2d_vec o = ga2d_vec_make((ga2d_real)0.3, (ga2d_real)-0.7);
        momenta m0, prev, m;
        double worst_p = 0, worst_l = 0, worst_ke = 0, ke_sum_tol = 0, v0;
        int s, contact_steps = 0, steps_run = 0, ok_p = 1, ok_l = 1, ok_ke = 1;
        wd.gravity = ga2d_vec_make(0, 0);
        w = make_world(wd, 0);
        if (!w) return;
        ids[0] = add_disc(w, -2, 0, radii[0], 1, mu, e);
        ids[1] = add_disc(w, 1.5, 0.45, radii[1], 2, mu, e);
        CHECK_RESULT(ga2d_body_set_velocity(w, ids[0], ga2d_vec_make(6, (ga2d_real)0.5)), GA2D_OK);
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, ids[0], 1), GA2D_OK);
        CHECK_RESULT(ga2d_body_set_velocity(w, ids[1], ga2d_vec_make(-3, 0)), GA2D_OK);
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, ids[1], (ga2d_real)-0.5), GA2D_OK);
        m0 = prev = momenta_of(w, ids, radii, 2, o);
        v0 = (double)ga2d_body_velocity(w, ids[0]).x;
        for (s = 0; s < 90; ++s) {
            double tol_p, tol_l, tol_ke, dp, dl, dke;
            int contact;
            step(w);
            ++steps_run;
            contact = ga2d_world_get_counters(w).constraint_count > 0;
            contact_steps += contact;
            m = momenta_of(w, ids, radii, 2, o);
            tol_p = 128 * REAL_EPS * fmax(m0.pscale, m.pscale) * contact_steps;
            tol_l = (128 * contact_steps + 4 * steps_run) * REAL_EPS * fmax(m0.lscale, m.lscale);
            tol_ke = 128 * REAL_EPS * fmax(prev.ke, m.ke) * contact;
            ke_sum_tol += tol_ke;
            dp = hypot(m.px - m0.px, m.py - m0.py);
            dl = fabs(m.l - m0.l);
            dke = m.ke - prev.ke;
            worst_p = fmax(worst_p, dp / fmax(tol_p, REAL_MIN));
            worst_l = fmax(worst_l, dl / tol_l);
            worst_ke = fmax(worst_ke, dke / fmax(tol_ke, REAL_MIN));
            ok_p &= dp <= tol_p;
            ok_l &= dl <= tol_l;
            ok_ke &= dke <= tol_ke;
            prev = m;
        }
        CHECK(contact_steps > 0);
        CHECK(fabs((double)ga2d_body_velocity(w, ids[0]).x - v0) > 1); /* they did collide */
        CHECK(ok_p);
        CHECK(ok_l);
        CHECK(ok_ke);
        if (e == 1 && mu == 0) CHECK_NEAR(m.ke, m0.ke, ke_sum_tol);
        if (verbose())
            printf("shape_world: off-centre discs e %.0f mu %.1f: worst |dP|, |dL|, KE growth in a step as multiples of their "
                   "rounding tolerances: %.3g, %.3g, %.3g (bound 1); KE %.9f -> %.9f J (%+.3g, elastic bound %.3g); "
                   "spins %.6f, %.6f rad/s\n",
                   e, mu, worst_p, worst_l, worst_ke, m0.ke, m.ke, m.ke - m0.ke, ke_sum_tol,
                   (double)ga2d_body_angular_velocity(w, ids[0]), (double)ga2d_body_angular_velocity(w, ids[1]));
        ga2d_world_destroy(w);
    }
}

/* ============================================================ a compound body
   5. An L from two polygon shapes on one body, in its frame: the 3 x 1 box
   [0, 3] x [0, 1] (density 1) and the 1 x 2 box [0, 1] x [1, 3] standing on
   its left end (density 2).  Analytically (parallel axes):
       m1 = 3, c1 = (1.5, 0.5), I1 = m1 (3^2 + 1^2)/12 = 2.5;
       m2 = 4, c2 = (0.5, 2),   I2 = m2 (1^2 + 2^2)/12 = 5/3;
       M = 7, C = (m1 c1 + m2 c2)/M = (6.5/7, 9.5/7),
       I = I1 + m1 |c1 - C|^2 + I2 + m2 |c2 - C|^2.
   Rounding.  Each box's own mass properties are exact but for one
   division: its vertices are small dyadic numbers, so the reference
   (their mean), the edge wedges, the area and first moment (zero: a box
   is symmetric about its mean) are exact sums, and only j12 / 12 rounds:
   |I_i| within u.  The body's sum (ga2d__update_mass, about the first
   shape's centre c0): M exact; C = c0 + m2 (c2 - c0) (1/M): the
   reciprocal, the product and the add, <= 3 u (|c0| + |C - c0|) each
   component (call it dC, per component); I: each term m_i |c_i - C|^2
   is off by m_i (2 |c_i - C| sqrt(2) dC + 5 u |c_i - C|^2) (C's error;
   the subtraction, 2 u in the square; the two squares and their sum; the
   product), plus u I_i, plus the four adds' u |I| each. */
static ga2d_polygon poly_rect(double x0, double y0, double x1, double y1)
{
    ga2d_vec pts[4];
    ga2d_polygon p;
    pts[0] = ga2d_vec_make((ga2d_real)x0, (ga2d_real)y0);
    pts[1] = ga2d_vec_make((ga2d_real)x1, (ga2d_real)y0);
    pts[2] = ga2d_vec_make((ga2d_real)x1, (ga2d_real)y1);
    pts[3] = ga2d_vec_make((ga2d_real)x0, (ga2d_real)y1);
    memset(&p, 0, sizeof p);
    CHECK_RESULT(ga2d_polygon_make(pts, 4, &p), GA2D_OK);
    return p;
}

/* The L's two shapes onto body id (long box first). */
static void add_l_shapes(ga2d_world *w, ga2d_body_id id, ga2d_shape_id *s)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_polygon long_box = poly_rect(0, 0, 3, 1), post = poly_rect(0, 1, 1, 3);
    s[0] = ga2d_shape_create_polygon(w, id, &sd, &long_box);
    sd.density = 2;
    s[1] = ga2d_shape_create_polygon(w, id, &sd, &post);
    CHECK(!ga2d_shape_id_is_null(s[0]) && !ga2d_shape_id_is_null(s[1]));
}

static void compound_mass_data(void)
{
    const double m1 = 3, m2 = 4, M = m1 + m2, c1x = 1.5, c1y = 0.5, c2x = 0.5, c2y = 2, I1 = 2.5, I2 = 4 * 5.0 / 12;
    const double Cx = (m1 * c1x + m2 * c2x) / M, Cy = (m1 * c1y + m2 * c2y) / M;
    const double d1 = hypot(c1x - Cx, c1y - Cy), d2 = hypot(c2x - Cx, c2y - Cy);
    const double I = I1 + m1 * d1 * d1 + I2 + m2 * d2 * d2;
    const double dCx = 3 * U * (fabs(c1x) + fabs(Cx - c1x)), dCy = 3 * U * (fabs(c1y) + fabs(Cy - c1y)), dC = fmax(dCx, dCy);
    const double dI = U * (I1 + I2) + m1 * (2 * d1 * sqrt(2.0) * dC + 5 * U * d1 * d1) + m2 * (2 * d2 * sqrt(2.0) * dC + 5 * U * d2 * d2) +
                      4 * U * I;
    ga2d_world *w = make_world(ga2d_default_world_def(), 0);
    ga2d_body_id id;
    ga2d_shape_id s[2], got[3];
    ga2d_mass md, one, kept;
    ga2d_geometry g;
    int n;
    if (!w) return;
    id = add_empty_body(w, -1, 0.3);
    add_l_shapes(w, id, s);
    md = ga2d_body_mass_data(w, id);
    CHECK((double)md.mass == M);
    CHECK_NEAR(md.center.x, Cx, dCx);
    CHECK_NEAR(md.center.y, Cy, dCy);
    CHECK_NEAR(md.inertia, I, dI);
    /* listed in creation order; the count whatever the capacity */
    n = ga2d_body_get_shapes(w, id, got, 3);
    CHECK(n == 2 && ga2d_shape_id_equal(got[0], s[0]) && ga2d_shape_id_equal(got[1], s[1]));
    memset(got, 0, sizeof got);
    CHECK(ga2d_body_get_shapes(w, id, got, 1) == 2 && ga2d_shape_id_equal(got[0], s[0]) && ga2d_shape_id_is_null(got[1]));
    CHECK(ga2d_body_get_shapes(w, id, NULL, 0) == 2);
    CHECK(ga2d_body_id_equal(ga2d_shape_body(w, s[1]), id));
    CHECK(ga2d_shape_get_type(w, s[0]) == GA2D_SHAPE_POLYGON);
    if (verbose())
        printf("shape_world: L mass data: m %.9g (exact 7), centre (%.9f, %.9f) vs (%.9f, %.9f): %+.2e, %+.2e (bounds %.2e, %.2e); "
               "I %.9f vs %.9f: %+.2e (bound %.2e)\n",
               (double)md.mass, (double)md.center.x, (double)md.center.y, Cx, Cy, (double)md.center.x - Cx,
               (double)md.center.y - Cy, dCx, dCy, (double)md.inertia, I, (double)md.inertia - I, dI);
    /* destroyed without updating the mass: the body keeps the L's */
    g = ga2d_shape_geometry(w, s[0]);
    one = ga2d_polygon_mass(&g.as.polygon, 1);
    CHECK_RESULT(ga2d_shape_destroy(w, s[1], 0), GA2D_OK);
    kept = ga2d_body_mass_data(w, id);
    CHECK(memcmp(&kept, &md, sizeof kept) == 0);
    CHECK(!ga2d_shape_is_valid(w, s[1]));
    CHECK(ga2d_body_get_shapes(w, id, got, 3) == 1 && ga2d_shape_id_equal(got[0], s[0]));
    /* a body of one shape has that shape's mass data, bit for bit (M = 0 +
       m, C = c0, I = I0: nothing to round): add another L's two shapes
       after the first long box, then destroy both with update_body_mass = 1 */
    add_l_shapes(w, id, s);
    {
        ga2d_shape_id first;
        CHECK(ga2d_body_get_shapes(w, id, got, 3) == 3);
        first = got[0];
        CHECK_RESULT(ga2d_shape_destroy(w, got[1], 1), GA2D_OK);
        CHECK_RESULT(ga2d_shape_destroy(w, got[2], 1), GA2D_OK);
        CHECK(ga2d_body_get_shapes(w, id, got, 3) == 1 && ga2d_shape_id_equal(got[0], first));
    }
    md = ga2d_body_mass_data(w, id);
    CHECK(md.mass == one.mass && md.center.x == one.center.x && md.center.y == one.center.y && md.inertia == one.inertia);
    CHECK((double)one.mass == m1 && (double)one.center.x == c1x && (double)one.center.y == c1y);
    CHECK_NEAR(one.inertia, I1, U * I1);
    ga2d_world_destroy(w);
}

/* The L dropped onto the ground (test_solver's), turned by 0.05 rad, its
   lowest corner 0.3 m up, sleep off, 3 s (the fall takes 0.25 s): it comes
   to rest on its long side, whose corners (0, 0) and (3, 0) in the body's
   frame stand 3 m apart.  As box_rests_at_its_height derives for a box,
   the solver lets each contact overlap by at most the slop and leaves no
   gap (a speculative point closes it within a substep), and resting on
   two points both carry load, so both overlap: each corner's height lies
   in [-slop, 0]; then the two differ by at most the slop and the side's
   angle is at most asin(slop / 3 m).  The centre of mass, over x = 0.93 of
   the 3 m side, is inside it: the L does not tip (its angle would be
   near 90 degrees, not near 0). */
static void compound_rests_on_its_long_side(void)
{
    ga2d_world *w = make_world(ga2d_default_world_def(), 0);
    ga2d_body_id id;
    ga2d_shape_id s[2];
    ga2d_contact_data cd[4];
    double angle, y0, y3;
    int n;
    if (!w) return;
    add_ground(w);
    id = add_empty_body(w, -1, 0.3);
    add_l_shapes(w, id, s);
    CHECK_RESULT(ga2d_body_set_transform(w, id, ga2d_vec_make(-1, (ga2d_real)0.3), ga2d_rotor_from_angle((ga2d_real)0.05)), GA2D_OK);
    steps(w, 180);
    angle = (double)ga2d_body_angle(w, id);
    y0 = (double)ga2d_transform_apply(ga2d_body_transform(w, id), ga2d_vec_make(0, 0)).y;
    y3 = (double)ga2d_transform_apply(ga2d_body_transform(w, id), ga2d_vec_make(3, 0)).y;
    n = ga2d_world_get_contacts(w, cd, 4);
    CHECK(n == 1 && cd[0].manifold.count == 2 && ga2d_shape_id_equal(cd[0].shape_b, s[0]));
    CHECK(y0 >= -SLOP && y0 <= 0);
    CHECK(y3 >= -SLOP && y3 <= 0);
    CHECK(fabs(angle) <= asin(SLOP / 3));
    if (verbose())
        printf("shape_world: L at rest: angle %.3g rad (bound %.3g), corners at %.3g and %.3g mm (bound -%.3g .. 0)\n", angle,
               asin(SLOP / 3), 1e3 * y0, 1e3 * y3, 1e3 * SLOP);
    ga2d_world_destroy(w);
}

/* ================================================================== stacks
   6. Columns of ten, 10 s, sleep off, defaults: rounded boxes (1 m
   outline, corners rounded by 0.1 m) and capsules lying flat (segment
   1 m long, radius 0.25 m: 0.5 m tall).  Bounds, as test_solver's
   stack_of_ten_stands: the top sinks by less than the 3 cm for a
   column of ten at defaults, and does not rise (by a slop); every contact
   overlaps by at most the slop (the solver's rule, box_rests_at_its_height);
   and nothing moved sideways by half its width (0.5 m: a box centred past
   the edge of the one below, a capsule centred past the end of the
   segment below, has lost its support). */
static double column_run(int capsules, double *max_dx, double *deepest)
{
    ga2d_world *w = make_world(ga2d_default_world_def(), 0);
    ga2d_body_id ids[10];
    ga2d_contact_data cd[16];
    ga2d_shape_def sd = ga2d_default_shape_def();
    const double hgt = capsules ? 0.5 : 1;
    double sink;
    int i, n, k;
    *max_dx = 0;
    *deepest = 0;
    if (!w) return HUGE_VAL;
    add_ground(w);
    for (i = 0; i < 10; ++i) {
        ga2d_shape_id sh;
        ids[i] = add_empty_body(w, 0, hgt / 2 + hgt * i);
        if (capsules) {
            ga2d_capsule c;
            c.center1 = ga2d_vec_make((ga2d_real)-0.5, 0);
            c.center2 = ga2d_vec_make((ga2d_real)0.5, 0);
            c.radius = (ga2d_real)0.25;
            sh = ga2d_shape_create_capsule(w, ids[i], &sd, &c);
        } else {
            ga2d_polygon p = ga2d_polygon_rounded_box((ga2d_real)0.5, (ga2d_real)0.5, (ga2d_real)0.1);
            sh = ga2d_shape_create_polygon(w, ids[i], &sd, &p);
        }
        CHECK(!ga2d_shape_id_is_null(sh));
    }
    steps(w, 600);
    sink = (hgt / 2 + hgt * 9) - (double)ga2d_body_position(w, ids[9]).y;
    for (i = 0; i < 10; ++i) *max_dx = fmax(*max_dx, fabs((double)ga2d_body_position(w, ids[i]).x));
    n = ga2d_world_get_contacts(w, cd, 16);
    CHECK(n == 10);
    for (i = 0; i < n && i < 16; ++i)
        for (k = 0; k < cd[i].manifold.count; ++k) *deepest = fmin(*deepest, (double)cd[i].manifold.points[k].separation);
    ga2d_world_destroy(w);
    return sink;
}

static void columns_stand(void)
{
    int c;
    for (c = 0; c < 2; ++c) {
        double dx, deepest, sink = column_run(c, &dx, &deepest);
        CHECK(sink < 0.03);
        CHECK(sink > -SLOP);
        CHECK(deepest >= -SLOP);
        CHECK(dx < 0.5);
        if (verbose())
            printf("shape_world: column of ten %s (sleep off, 10 s): top sank %.3f cm (bound 3 cm), deepest contact %.3g mm "
                   "(bound %.3g), drift %.3g m (bound 0.5)\n",
                   c ? "capsules lying flat" : "rounded boxes", 100 * sink, -1e3 * deepest, 1e3 * SLOP, dx);
    }
}

/* ============================================================ the shape API */
static unsigned char *snap_save(const ga2d_world *w, size_t *size)
{
    unsigned char *buf;
    *size = ga2d_world_snapshot_size(w);
    buf = (unsigned char *)malloc(*size);
    if (buf && ga2d_world_snapshot_save(w, buf, *size) != GA2D_OK) {
        free(buf);
        buf = NULL;
    }
    CHECK(buf != NULL);
    return buf;
}

/* The world is as it was: its snapshot has the same bytes. */
static int same_world(const ga2d_world *w, const unsigned char *ref, size_t ref_size)
{
    size_t n;
    unsigned char *now = snap_save(w, &n);
    int same = now && ref && n == ref_size && memcmp(now, ref, n) == 0;
    free(now);
    return same;
}

static ga2d_geometry geom_circle(double x, double y, double r)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_CIRCLE;
    g.as.circle.center = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    g.as.circle.radius = (ga2d_real)r;
    return g;
}

static ga2d_geometry geom_capsule(double x1, double y1, double x2, double y2, double r)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_CAPSULE;
    g.as.capsule.center1 = ga2d_vec_make((ga2d_real)x1, (ga2d_real)y1);
    g.as.capsule.center2 = ga2d_vec_make((ga2d_real)x2, (ga2d_real)y2);
    g.as.capsule.radius = (ga2d_real)r;
    return g;
}

static ga2d_geometry geom_segment(double x1, double y1, double x2, double y2)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_SEGMENT;
    g.as.segment.point1 = ga2d_vec_make((ga2d_real)x1, (ga2d_real)y1);
    g.as.segment.point2 = ga2d_vec_make((ga2d_real)x2, (ga2d_real)y2);
    return g;
}

/* One refused creation: the checked form names the error and gives the
   null id, the typed form gives the null id too, and the world is as it
   was (its snapshot byte for byte, its body count, the body's shapes). */
static void refused(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_geometry *g, ga2d_result want,
                    const char *what)
{
    size_t size;
    unsigned char *before = snap_save(w, &size);
    int bodies = ga2d_world_get_counters(w).body_count, all_shapes = ga2d_world_get_counters(w).shape_count;
    int shapes = ga2d_body_get_shapes(w, body, NULL, 0);
    ga2d_shape_id id;
    ga2d_result r;
    id.index1 = 77;
    id.generation = 77;
    r = ga2d_shape_create_checked(w, body, def, g, &id);
    if (r != want) test_fail(__FILE__, __LINE__, "%s: \"%s\", expected \"%s\"", what, ga2d_result_string(r), ga2d_result_string(want));
    CHECK(ga2d_shape_id_is_null(id));
    if (def && g) {
        switch (g->type) {
        case GA2D_SHAPE_CIRCLE: id = ga2d_shape_create_circle(w, body, def, &g->as.circle); break;
        case GA2D_SHAPE_CAPSULE: id = ga2d_shape_create_capsule(w, body, def, &g->as.capsule); break;
        case GA2D_SHAPE_POLYGON: id = ga2d_shape_create_polygon(w, body, def, &g->as.polygon); break;
        case GA2D_SHAPE_SEGMENT: id = ga2d_shape_create_segment(w, body, def, &g->as.segment); break;
        default: break;
        }
        CHECK(ga2d_shape_id_is_null(id));
    }
    if (!same_world(w, before, size)) test_fail(__FILE__, __LINE__, "%s: the world changed", what);
    CHECK(ga2d_world_snapshot_size(w) == size);
    CHECK(ga2d_world_get_counters(w).body_count == bodies);
    CHECK(ga2d_world_get_counters(w).shape_count == all_shapes);
    CHECK(ga2d_body_get_shapes(w, body, NULL, 0) == shapes);
    free(before);
}

/* 7. Misuse, each refused with its documented error and the world left as
   it was; then a shape destroyed twice is STALE_ID the second time. */
static void shape_api_refusals(void)
{
    ga2d_world *w = make_world(ga2d_default_world_def(), 1);
    ga2d_body_id dyn, wall, gone, forged;
    ga2d_shape_def sd = ga2d_default_shape_def(), bad;
    ga2d_geometry g;
    ga2d_shape_id id, seg;
    ga2d_vec cw[4];
    size_t size;
    unsigned char *before;
    if (!w) return;
    add_ground(w);
    dyn = add_disc(w, 0, 2, 0.5, 1, 0.6, 0);
    wall = add_static_box(w, 5, 1, 0.5, 0.5, 0.6);
    gone = add_disc(w, 3, 2, 0.5, 1, 0.6, 0);
    steps(w, 10); /* contacts, a moving body, a sleeping one later */
    CHECK_RESULT(ga2d_body_destroy(w, gone), GA2D_OK);
    forged = dyn;
    forged.generation ^= 0x5a5a;

    g = geom_circle(0, 0, 0.25);
    refused(w, gone, &sd, &g, GA2D_ERR_STALE_ID, "a destroyed body");
    refused(w, forged, &sd, &g, GA2D_ERR_STALE_ID, "a forged body id");
    refused(w, ga2d_body_id_null(), &sd, &g, GA2D_ERR_STALE_ID, "the null body id");
    g = geom_circle(0, 0, -0.25);
    refused(w, dyn, &sd, &g, GA2D_ERR_INVALID_ARGUMENT, "a negative radius");
    g = geom_circle(0, 0, 0);
    refused(w, dyn, &sd, &g, GA2D_ERR_DEGENERATE, "a circle of radius 0 on a dynamic body (no mass)");
    g = geom_circle(0, 0, 0.25);
    g.as.circle.radius = (ga2d_real)NAN;
    refused(w, dyn, &sd, &g, GA2D_ERR_NOT_FINITE, "a NaN radius");
    g = geom_circle(0, 0, 0.25);
    g.as.circle.center.x = (ga2d_real)NAN;
    refused(w, dyn, &sd, &g, GA2D_ERR_NOT_FINITE, "a NaN centre");
    g = geom_circle(2 * (double)GA2D_MAX_COORDINATE, 0, 0.25);
    refused(w, dyn, &sd, &g, GA2D_ERR_TOO_LARGE, "a centre beyond GA2D_MAX_COORDINATE");
    g = geom_capsule(0.5, 0.25, 0.5, 0.25, 0.25);
    refused(w, dyn, &sd, &g, GA2D_ERR_DEGENERATE, "a capsule of zero length (a circle)");
    g = geom_capsule(-0.5, 0, 0.5, 0, -0.1);
    refused(w, dyn, &sd, &g, GA2D_ERR_INVALID_ARGUMENT, "a capsule of negative radius");
    g = geom_segment(-1, 0, 1, 0);
    refused(w, dyn, &sd, &g, GA2D_ERR_INVALID_ARGUMENT, "a segment on a dynamic body");
    g = geom_segment(1, 1, 1, 1);
    refused(w, wall, &sd, &g, GA2D_ERR_DEGENERATE, "a segment of zero length");
    /* polygons: ga2d_polygon_make's checks on the vertices */
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_POLYGON;
    g.as.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    cw[0] = g.as.polygon.vertices[0];
    cw[1] = g.as.polygon.vertices[3];
    cw[2] = g.as.polygon.vertices[2];
    cw[3] = g.as.polygon.vertices[1];
    memcpy(g.as.polygon.vertices, cw, sizeof cw);
    refused(w, dyn, &sd, &g, GA2D_ERR_CLOCKWISE, "a clockwise polygon");
    g.as.polygon.count = 2;
    refused(w, dyn, &sd, &g, GA2D_ERR_TOO_FEW_POINTS, "a polygon of two points");
    /* the def's material */
    g = geom_circle(0, 0, 0.25);
    bad = sd;
    bad.density = -1;
    refused(w, dyn, &bad, &g, GA2D_ERR_INVALID_ARGUMENT, "a negative density");
    bad = sd;
    bad.friction = (ga2d_real)NAN;
    refused(w, dyn, &bad, &g, GA2D_ERR_NOT_FINITE, "a NaN friction");
    bad = sd;
    bad.restitution = -1;
    refused(w, dyn, &bad, &g, GA2D_ERR_INVALID_ARGUMENT, "a negative restitution");
    /* bad arguments */
    refused(w, dyn, NULL, &g, GA2D_ERR_INVALID_ARGUMENT, "a NULL def");
    refused(w, dyn, &sd, NULL, GA2D_ERR_INVALID_ARGUMENT, "a NULL geometry");
    g.type = GA2D_SHAPE_TYPE_COUNT;
    refused(w, dyn, &sd, &g, GA2D_ERR_INVALID_ARGUMENT, "a type out of range");
    before = snap_save(w, &size);
    CHECK_RESULT(ga2d_shape_create_checked(w, dyn, &sd, &g, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(ga2d_shape_id_is_null(ga2d_shape_create_circle(w, dyn, &sd, NULL)));
    CHECK(same_world(w, before, size));
    free(before);

    /* the same segment on the static body is made (the refusals above were
       about what they named), and destroying it twice is STALE_ID */
    g = geom_segment(-1, 0, 1, 0);
    CHECK_RESULT(ga2d_shape_create_checked(w, wall, &sd, &g, &seg), GA2D_OK);
    CHECK(ga2d_shape_get_type(w, seg) == GA2D_SHAPE_SEGMENT);
    CHECK_RESULT(ga2d_shape_destroy(w, seg, 1), GA2D_OK);
    before = snap_save(w, &size);
    CHECK_RESULT(ga2d_shape_destroy(w, seg, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_shape_destroy(w, ga2d_shape_id_null(), 1), GA2D_ERR_STALE_ID);
    CHECK(!ga2d_shape_is_valid(w, seg));
    CHECK(ga2d_body_id_is_null(ga2d_shape_body(w, seg)));
    CHECK(ga2d_shape_get_type(w, seg) == GA2D_SHAPE_TYPE_COUNT);
    CHECK(same_world(w, before, size));
    free(before);
    /* a destroyed body's shapes go with it */
    CHECK(ga2d_body_get_shapes(w, dyn, &id, 1) == 1);
    CHECK_RESULT(ga2d_body_destroy(w, dyn), GA2D_OK);
    CHECK(!ga2d_shape_is_valid(w, id));
    CHECK_RESULT(ga2d_shape_destroy(w, id, 1), GA2D_ERR_STALE_ID);
    CHECK(ga2d_body_get_shapes(w, dyn, NULL, 0) == 0);
    steps(w, 2);
    ga2d_world_destroy(w);
}

/* ================================================================ snapshots
   8. A scene of mixed shapes: the ground, a static ramp made of a segment,
   discs, capsules, rounded boxes, triangles and the compound L, thrown
   with spin.  After 1 s (a pile still moving, warm-start impulses in its
   contacts) save; step 2 s more: that is the truth.  Loading the snapshot
   back into the same world, and into a fresh default world, and stepping
   the same 2 s gives the same state bit for bit (positions, rotors,
   velocities, spins of every body), as test_snapshot.c requires of boxes. */
#define MIX_BODIES 14
typedef struct mix_state { ga2d_real f[MIX_BODIES][7]; } mix_state;

static void mix_read(const ga2d_world *w, const ga2d_body_id *ids, mix_state *st)
{
    int i;
    memset(st, 0, sizeof *st);
    for (i = 0; i < MIX_BODIES; ++i) {
        ga2d_vec p = ga2d_body_position(w, ids[i]), v = ga2d_body_velocity(w, ids[i]);
        ga2d_rotor q = ga2d_body_rotor(w, ids[i]);
        st->f[i][0] = p.x;
        st->f[i][1] = p.y;
        st->f[i][2] = q.c;
        st->f[i][3] = q.s;
        st->f[i][4] = v.x;
        st->f[i][5] = v.y;
        st->f[i][6] = ga2d_body_angular_velocity(w, ids[i]);
    }
}

static void mix_build(ga2d_world *w, ga2d_body_id *ids)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_geometry g;
    ga2d_shape_id s[2];
    int i, k = 0;
    ids[k++] = add_ground(w);
    {
        ga2d_body_def d = ga2d_default_body_def();
        d.polygon.count = 0;
        ids[k] = ga2d_body_create(w, &d);
        g = geom_segment(-8, 3, -3, 0.5);
        CHECK_RESULT(ga2d_shape_create_checked(w, ids[k], &sd, &g, &s[0]), GA2D_OK);
        ++k;
    }
    for (i = 0; i < 3; ++i) {
        ga2d_body_id b = add_empty_body(w, -6 + 0.7 * i, 4 + 1.1 * i);
        sd.restitution = (ga2d_real)(0.2 * i);
        g = i == 1 ? geom_capsule(-0.4, 0, 0.4, 0, 0.2) : geom_circle(0, 0, 0.3 + 0.1 * i);
        CHECK_RESULT(ga2d_shape_create_checked(w, b, &sd, &g, &s[0]), GA2D_OK);
        ids[k++] = b;
    }
    sd.restitution = 0;
    for (i = 0; i < 6; ++i) {
        ga2d_body_id b = add_empty_body(w, -1.5 + 1.1 * (i % 3), 0.6 + 1.2 * (i / 3));
        memset(&g, 0, sizeof g);
        g.type = GA2D_SHAPE_POLYGON;
        if (i % 2 == 0) {
            g.as.polygon = ga2d_polygon_rounded_box((ga2d_real)0.5, (ga2d_real)0.4, (ga2d_real)0.1);
        } else {
            ga2d_vec tri[3];
            tri[0] = ga2d_vec_make((ga2d_real)-0.5, (ga2d_real)-0.3);
            tri[1] = ga2d_vec_make((ga2d_real)0.5, (ga2d_real)-0.3);
            tri[2] = ga2d_vec_make(0, (ga2d_real)0.5);
            CHECK_RESULT(ga2d_polygon_make(tri, 3, &g.as.polygon), GA2D_OK);
        }
        CHECK_RESULT(ga2d_shape_create_checked(w, b, &sd, &g, &s[0]), GA2D_OK);
        if (i == 4) { /* a second shape: a disc on top */
            g = geom_circle(0, 0.7, 0.25);
            CHECK_RESULT(ga2d_shape_create_checked(w, b, &sd, &g, &s[1]), GA2D_OK);
        }
        ids[k++] = b;
    }
    for (i = 0; i < 2; ++i) {
        ga2d_body_id b = add_empty_body(w, 3 + 0.5 * i, 1 + 4 * i);
        add_l_shapes(w, b, s);
        ids[k++] = b;
    }
    ids[k] = add_disc(w, 6, 6, 0.35, 2, 0.3, 0.5);
    CHECK_RESULT(ga2d_body_set_velocity(w, ids[k], ga2d_vec_make(-4, 1)), GA2D_OK);
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, ids[k], 5), GA2D_OK);
    ++k;
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, ids[2], -3), GA2D_OK);
    CHECK_RESULT(ga2d_body_set_velocity(w, ids[12], ga2d_vec_make(-1, 0)), GA2D_OK);
    CHECK(k == MIX_BODIES);
}

static void mixed_snapshot_is_bit_identical(void)
{
    ga2d_world *w = make_world(ga2d_default_world_def(), 1), *f;
    ga2d_body_id ids[MIX_BODIES];
    mix_state truth, again, fresh;
    unsigned char *snap;
    size_t size;
    if (!w) return;
    mix_build(w, ids);
    steps(w, 60);
    {
        /* still moving: some body faster than 0.1 m/s */
        double fastest = 0;
        int i;
        for (i = 0; i < MIX_BODIES; ++i) fastest = fmax(fastest, (double)ga2d_vec_length(ga2d_body_velocity(w, ids[i])));
        CHECK(fastest > 0.1);
    }
    snap = snap_save(w, &size);
    if (!snap) return;
    steps(w, 120);
    mix_read(w, ids, &truth);
    CHECK(ga2d_world_get_counters(w).touching_count >= 8); /* a pile, not a scatter */
    CHECK_RESULT(ga2d_world_snapshot_load(w, snap, size), GA2D_OK);
    steps(w, 120);
    mix_read(w, ids, &again);
    CHECK(memcmp(&truth, &again, sizeof truth) == 0);
    f = make_world(ga2d_default_world_def(), 1);
    if (f) {
        CHECK_RESULT(ga2d_world_snapshot_load(f, snap, size), GA2D_OK);
        steps(f, 120);
        mix_read(f, ids, &fresh);
        CHECK(memcmp(&truth, &fresh, sizeof truth) == 0);
        ga2d_world_destroy(f);
    }
    if (verbose())
        printf("shape_world: mixed-shape snapshot (%d bodies, %d touching contacts, %lu bytes): reloaded %s, fresh world %s\n",
               MIX_BODIES, ga2d_world_get_counters(w).touching_count, (unsigned long)size,
               memcmp(&truth, &again, sizeof truth) == 0 ? "bit-identical" : "DIFFERENT",
               memcmp(&truth, &fresh, sizeof truth) == 0 ? "bit-identical" : "DIFFERENT");
    free(snap);
    ga2d_world_destroy(w);
}

void suite_shape_world(void)
{
    test_run("shape_world: a disc rolls down a slope at (2/3) g sin theta, w = v / rho", disc_rolls_down_a_slope);
    test_run("shape_world: a disc slides down a slope, F = mu N, spun by its friction", disc_slides_down_a_slope);
    test_run("shape_world: a disc rolling on level ground keeps its speed", disc_rolls_on_level_ground);
    test_run("shape_world: a ball's bounce heights are e^2n h0", ball_bounces);
    test_run("shape_world: discs head on with e = 1 obey the 1-D elastic formulas", head_on_discs);
    test_run("shape_world: off-centre discs conserve momentum, energy never grows", off_centre_discs_conserve);
    test_run("shape_world: a compound L's mass data are the sum of its shapes'", compound_mass_data);
    test_run("shape_world: a dropped L comes to rest on its long side", compound_rests_on_its_long_side);
    test_run("shape_world: columns of rounded boxes and of capsules stand", columns_stand);
    test_run("shape_world: the shape API refuses misuse and leaves the world as it was", shape_api_refusals);
    test_run("shape_world: snapshots of mixed shapes step on bit for bit", mixed_snapshot_is_bit_identical);
}
