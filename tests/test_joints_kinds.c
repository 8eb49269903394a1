/* Joints against physics (issue 24), the kinds other than the revolute
   (tests/test_joints.c has it): distance (rod pendulum, spring, rope,
   motor), weld (rigid cantilever, soft springs), motor joint (holding a
   pose, too weak to, its caps), prismatic (slide, limits, motor,
   spring), wheel (a car's suspension, parking and driving on a slope),
   momentum of two bodies joined by each kind, errors and setters of
   every kind, and a snapshot of a world with one joint of each kind.

   dt = 1/60 and 4 substeps throughout (h = 1/240 s), g = 10.  A rigid
   joint's rows are held by the position feedback of test_joints.c's top
   comment (60 Hz, damping ratio 2, in the biased pass; a relax pass
   without it follows).  From it:
   - a row carrying a steady force F over its effective mass m_eff rests
     past its target by sep = F / (m_eff omega_s^2) (the biased pass adds
     nothing there: ms b m_eff sep = is F h, and is / (ms b) = 1 / (h
     omega_s^2)); for a 2-row block, sep = K F / omega_s^2 with K the
     block's inverse mass matrix; for an angle, tau / (I_eff omega_s^2);
   - a spring of f hertz (a joint's own, solved in both passes) rests
     where its impulse gives back the load, by the same algebra at f:
     x = F / (m_eff (2 pi f)^2), exactly the spring k = m_eff (2 pi f)^2
     of the definition;
   - a body moving at v on a circle of radius d about the joint drifts out
     by v^2 h / (2 d b ms) at rest (test_joints.c).
   With GA2D_TEST_VERBOSE set each scene prints "joint kinds: ..." with
   its figure and bound. */
#include "test.h"

#define DT (1.0 / 60)
#define SUB 4
#define H (DT / SUB)
#define G 10.0
#define PI 3.14159265358979323846
#define JOINT_HERTZ 60.0 /* the header's GA2D__JOINT_HERTZ, under a quarter of 240 Hz */
#define JOINT_ZETA 2.0
#define U (REAL_EPS / 2) /* the unit roundoff of ga2d_real */

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static ga2d_vec v2(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }

/* The soft step's spring (hertz, damping ratio, substep) in double. */
typedef struct soft { double bias, ms, is; } soft;
static soft make_soft(double hertz, double zeta, double h)
{
    soft s;
    double om = 2 * PI * hertz, a1 = 2 * zeta + h * om, a2 = h * om * a1;
    s.bias = om / a1;
    s.ms = a2 / (1 + a2);
    s.is = 1 / (1 + a2);
    return s;
}
static double omega_s2(void) { return (2 * PI * JOINT_HERTZ) * (2 * PI * JOINT_HERTZ); }

static ga2d_world *make_world(double gx, double gy)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.gravity = v2(gx, gy);
    wd.enable_sleep = 0;
    return ga2d_world_create(&wd);
}

static void step(ga2d_world *w) { CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK); }
static void steps(ga2d_world *w, int n)
{
    int i;
    for (i = 0; i < n; ++i) step(w);
}

/* A static body at (x, y) turned by angle, with no shape. */
static ga2d_body_id pivot_body(ga2d_world *w, double x, double y, double angle)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.position = v2(x, y);
    d.rotor = ga2d_rotor_from_angle((ga2d_real)angle);
    return ga2d_body_create(w, &d);
}

/* A dynamic box of half extents hx, hy at (x, y), turned by angle. */
static ga2d_body_id box_body(ga2d_world *w, double x, double y, double angle, double hx, double hy, double density)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = v2(x, y);
    d.rotor = ga2d_rotor_from_angle((ga2d_real)angle);
    d.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    d.density = (ga2d_real)density;
    return ga2d_body_create(w, &d);
}

/* A dynamic disc of radius r (density 1, friction mu) centred at its
   origin (x, y). */
static ga2d_body_id disc_body(ga2d_world *w, double x, double y, double r, double mu)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_body_id b;
    d.type = GA2D_BODY_DYNAMIC;
    d.position = v2(x, y);
    b = ga2d_body_create(w, &d);
    c.center = v2(0, 0);
    c.radius = (ga2d_real)r;
    sd.friction = (ga2d_real)mu;
    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
    return b;
}

static double mass_of(const ga2d_world *w, ga2d_body_id b) { return (double)ga2d_body_mass_data(w, b).mass; }
static double inertia_of(const ga2d_world *w, ga2d_body_id b) { return (double)ga2d_body_mass_data(w, b).inertia; }

/* A body point given in its frame (relative to its origin), in the world. */
static ga2d_vec world_point(const ga2d_world *w, ga2d_body_id b, ga2d_vec local)
{
    return ga2d_transform_apply(ga2d_body_transform(w, b), local);
}

static double dist(ga2d_vec a, ga2d_vec b) { return hypot((double)a.x - (double)b.x, (double)a.y - (double)b.y); }
static double len(ga2d_vec a) { return hypot((double)a.x, (double)a.y); }

/* Body states, bit for bit. */
typedef struct body_bits { ga2d_vec p, v; ga2d_rotor q; ga2d_real w; } body_bits;
static body_bits bits_of(const ga2d_world *w, ga2d_body_id b)
{
    body_bits s;
    memset(&s, 0, sizeof s);
    s.p = ga2d_body_position(w, b);
    s.v = ga2d_body_velocity(w, b);
    s.q = ga2d_body_rotor(w, b);
    s.w = ga2d_body_angular_velocity(w, b);
    return s;
}

static unsigned char *snapshot(const ga2d_world *w, size_t *size)
{
    unsigned char *buf;
    *size = ga2d_world_snapshot_size(w);
    buf = (unsigned char *)malloc(*size);
    if (!buf || ga2d_world_snapshot_save(w, buf, *size) != GA2D_OK) {
        test_fail(__FILE__, __LINE__, "snapshot failed");
        free(buf);
        return NULL;
    }
    return buf;
}

static int same_snapshot(const ga2d_world *w, const unsigned char *ref, size_t ref_size)
{
    size_t n;
    unsigned char *now = snapshot(w, &n);
    int same = now && ref && n == ref_size && memcmp(now, ref, n) == 0;
    free(now);
    return same;
}

/* The arithmetic-geometric mean: a pendulum of small-amplitude period
   T0 swinging to amplitude th has the period T0 / AGM(1, cos(th/2)). */
static double agm(double a, double b)
{
    int i;
    for (i = 0; i < 40 && fabs(a - b) > 1e-16 * a; ++i) {
        double an = (a + b) / 2;
        b = sqrt(a * b);
        a = an;
    }
    return a;
}
static double pendulum_period(double T0, double th) { return T0 / agm(1, cos(th / 2)); }

/* Times `periods` periods of a coordinate read each step by its upward
   zero crossings (linear interpolation between steps): the mean period,
   or 0 if fewer crossings came within max_steps. */
typedef double reader(const ga2d_world *w, ga2d_joint_id j, ga2d_body_id b);
static double time_periods(ga2d_world *w, ga2d_joint_id j, ga2d_body_id b, reader *read, int periods, int max_steps)
{
    double prev = read(w, j, b), first = 0, last = 0;
    int k, crossings = 0;
    for (k = 1; k <= max_steps && crossings <= periods; ++k) {
        double x;
        step(w);
        x = read(w, j, b);
        if (prev < 0 && x >= 0) {
            double tc = k * DT - DT * x / (x - prev);
            if (crossings == 0) first = tc;
            last = tc;
            ++crossings;
        }
        prev = x;
    }
    return crossings > periods ? (last - first) / periods : 0;
}

/* The period of an undamped spring of f hertz under the soft step
   (test_joints.c spring_period derives it: both passes solve the spring
   implicitly, e = 2 pi f h, cos W h = 1 - e^2 / (2 (1 + e^2))), and the
   bound on timing it over `periods` periods: the crossings'
   interpolation dt^2 (2 g + W^2 dt) / 8 twice over the periods (g =
   ln(1 + e^2) / h, the scheme's decay rate), plus rounding 16 u. */
static double scheme_period(double f, int periods, double *tol)
{
    double e = 2 * PI * f * H, Td = 2 * PI * H / acos(1 - e * e / (2 * (1 + e * e)));
    double gam = log(1 + e * e) / H, W = 2 * PI / Td;
    *tol = 2 * DT * DT * (2 * gam + W * W * DT) / 8 / periods + 16 * U * Td;
    return Td;
}

/* The largest eigenvalue of the critically damped spring's substep map
   (test_joints.c spring_critical), and whether both are real and
   positive: no overshoot. */
static double critical_lambda(double f, int *real_positive)
{
    double e = 2 * PI * f * H, D = (1 + e) * (1 + e), tr = (1 + 2 * e) * (D + 1) / (D * D), det = (1 + 2 * e) / (D * D);
    double disc = tr * tr / 4 - det;
    *real_positive = disc > 0 && tr / 2 - sqrt(disc) > 0;
    return tr / 2 + sqrt(disc > 0 ? disc : 0);
}

/* ============================================================ distance */
static ga2d_distance_joint_def distance_def(ga2d_body_id a, ga2d_body_id b, ga2d_vec la, ga2d_vec lb, double length)
{
    ga2d_distance_joint_def d = ga2d_default_distance_joint_def();
    d.body_a = a;
    d.body_b = b;
    d.local_anchor_a = la;
    d.local_anchor_b = lb;
    d.length = (ga2d_real)length;
    return d;
}

/* A rigid rod of length L from a static pivot to the centre of a small
   disc (r = 0.05), released at th0 from rest.  The rod pulls through the
   disc's centre, so it never turns it (its spin stays exactly 0): the
   disc's own inertia plays no part and the pendulum is the point mass's,
   T0 = 2 pi sqrt(L / g), at amplitude th0 T0 / AGM(1, cos(th0/2)).  The
   period is short of that by symplectic Euler's phase error (w0 h)^2 /
   24 (test_joints.c), and further off by:
   - the length's error s (read each step): T ~ sqrt(L), so s / (2 L);
   - the interpolation of the crossings, 2 w0^2 dt^3 / 8 over N periods;
   - the amplitude lost to the feedback's damping: dT/T = th dth / 8 and
     th dth = dE / (m g L), dE <= e0 - e_min (measured);
   rounding 16 u.  The length: the rod's load along it is m (g cos th +
   v^2 / L) <= m (g + v^2 / L) over the axis mass m (A static, the anchor
   at B's centre), v^2 <= 2 g L (1 - cos th0): a static stretch (g + v^2 /
   L) / omega_s^2 plus the turning drift v^2 h / (2 L b ms), both bounded
   as the top says; rounding 8 u L. */
static void distance_rod_pendulum(void)
{
    const double Ls[2] = {1, 2}, ths[2] = {5 * PI / 180, 3 * PI / 180};
    soft js = make_soft(JOINT_HERTZ, JOINT_ZETA, H);
    int i, k;
    for (i = 0; i < 2; ++i) {
        const int periods = 10;
        ga2d_world *w = make_world(0, -G);
        double L = Ls[i], th0 = ths[i], T0 = 2 * PI * sqrt(L / G), w0 = 2 * PI / T0, T = pendulum_period(T0, th0);
        ga2d_body_id p = pivot_body(w, 0, 0, 0), b = disc_body(w, L * sin(th0), -L * cos(th0), 0.05, 0.6);
        ga2d_distance_joint_def d = distance_def(p, b, v2(0, 0), v2(0, 0), L);
        ga2d_joint_id j;
        double m = mass_of(w, b), e0, e_min, max_sep = 0, prev, first = 0, last = 0, v2max, sep_bound, phase, bound, period;
        int crossings = 0, spin_zero = 1;
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
        e0 = e_min = m * G * (double)ga2d_body_center(w, b).y;
        prev = (double)ga2d_body_position(w, b).x;
        for (k = 1; crossings <= periods && k < 100000; ++k) {
            ga2d_vec v, c;
            double x, e;
            step(w);
            v = ga2d_body_velocity(w, b);
            c = ga2d_body_center(w, b);
            e = 0.5 * m * ((double)v.x * (double)v.x + (double)v.y * (double)v.y) + m * G * (double)c.y;
            if (e < e_min) e_min = e;
            if (fabs((double)ga2d_distance_joint_current_length(w, j) - L) > max_sep)
                max_sep = fabs((double)ga2d_distance_joint_current_length(w, j) - L);
            if (ga2d_body_angular_velocity(w, b) != 0) spin_zero = 0;
            x = (double)c.x;
            if (prev < 0 && x >= 0) {
                double tc = k * DT - DT * x / (x - prev);
                if (crossings == 0) first = tc;
                last = tc;
                ++crossings;
            }
            prev = x;
        }
        period = (last - first) / periods;
        v2max = 2 * G * L * (1 - cos(th0));
        sep_bound = (G + v2max / L) / omega_s2() + v2max * H / (2 * L * js.bias * js.ms) + 8 * U * L;
        phase = (w0 * H) * (w0 * H) / 24;
        bound = max_sep / (2 * L) + 2 * w0 * w0 * DT * DT * DT / 8 / periods / T + (e0 - e_min) / (8 * m * G * L) + 16 * U;
        CHECK(spin_zero);
        CHECK(max_sep <= sep_bound);
        CHECK_NEAR(period / (T * (1 - phase)), 1, bound);
        if (verbose())
            printf("joint kinds: distance rod pendulum L %.0f m from %.0f deg: period %.7f s, exact %.7f, less the phase error "
                   "%.7f: |rel| %.3g <= %.3g; length off by %.3g m <= %.3g; the disc never turned: %d\n",
                   L, th0 * 180 / PI, period, T, T * (1 - phase), fabs(period / (T * (1 - phase)) - 1), bound, max_sep,
                   sep_bound, spin_zero);
        ga2d_world_destroy(w);
    }
}

static double read_stretch(const ga2d_world *w, ga2d_joint_id j, ga2d_body_id b)
{
    (void)b;
    return (double)ga2d_distance_joint_current_length(w, j) - 1;
}

/* A distance spring of f hertz (damping 0) holding a disc (r = 0.25) to
   a static body, rest length 1, gravity off, started 0.2 m long: the
   motion stays on the line (no force across it), a 1-dof oscillator of
   the disc's mass, which is the axis mass (A static, the anchor at B's
   centre): the scheme's period as derived for the revolute spring on
   its axial mass (scheme_period), timed over 3 periods, for 0.5, 1 and
   2 Hz. */
static void distance_spring_period(void)
{
    const double fs[3] = {0.5, 1, 2};
    int i;
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, 0);
        ga2d_body_id p = pivot_body(w, 0, 0, 0), b = disc_body(w, 1.2, 0, 0.25, 0.6);
        ga2d_distance_joint_def d = distance_def(p, b, v2(0, 0), v2(0, 0), 1);
        ga2d_joint_id j;
        double tol, Td = scheme_period(fs[i], 3, &tol), T;
        d.enable_spring = 1;
        d.hertz = (ga2d_real)fs[i];
        d.damping_ratio = 0;
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
        T = time_periods(w, j, b, read_stretch, 3, 2000);
        CHECK_NEAR(T, Td, tol);
        CHECK(fabs(Td * fs[i] - 1) <= (2 * PI * fs[i] * H) * (2 * PI * fs[i] * H) / 2); /* near 1/f, as derived */
        if (verbose())
            printf("joint kinds: distance spring %.1f Hz: period %.6f s, the scheme's %.6f (1/f = %.6f), |diff| %.3g <= %.3g\n",
                   fs[i], T, Td, 1 / fs[i], fabs(T - Td), tol);
        ga2d_world_destroy(w);
    }
}

/* The same spring with damping ratio 1 (1 and 3 Hz): the substep map's
   eigenvalues are real and positive (critical_lambda), so from 0.2 m out
   at rest the stretch falls to 0 without passing it (by more than the
   length's rounding, 8 u (1 + x0)), and after 2 s (480 substeps) it is
   below x0 480 lam^480 plus that rounding. */
static void distance_spring_critical(void)
{
    const double fs[2] = {1, 3}, x0 = 0.2;
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, 0);
        ga2d_body_id p = pivot_body(w, 0, 0, 0), b = disc_body(w, 1 + x0, 0, 0.25, 0.6);
        ga2d_distance_joint_def d = distance_def(p, b, v2(0, 0), v2(0, 0), 1);
        ga2d_joint_id j;
        int real_positive;
        double lam = critical_lambda(fs[i], &real_positive), lowest = x0, rnd = 8 * U * (1 + x0), end_bound;
        CHECK(real_positive); /* the premise */
        d.enable_spring = 1;
        d.hertz = (ga2d_real)fs[i];
        d.damping_ratio = 1;
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 120; ++k) {
            double x;
            step(w);
            x = read_stretch(w, j, b);
            if (x < lowest) lowest = x;
        }
        end_bound = x0 * 480 * pow(lam, 480) + rnd;
        CHECK(lowest >= -rnd);
        CHECK(fabs(read_stretch(w, j, b)) <= end_bound);
        if (verbose())
            printf("joint kinds: distance spring %.0f Hz, damping ratio 1: lowest stretch %.3g m (>= %.3g), after 2 s %.3g "
                   "(<= %.3g)\n", fs[i], lowest, -rnd, read_stretch(w, j, b), end_bound);
        ga2d_world_destroy(w);
    }
}

/* A rope: the limit on with range [0, L] (no rigid length).  A disc hangs
   from a static pivot d0 below it, released at rest: closer than L the
   rope's upper side is speculative and asks nothing while the substep's
   fall stays within the room left (the freely predicted length after the
   substep <= L), so the disc falls freely: after k substeps symplectic
   Euler's y0 - g h^2 k (k + 1) / 2 and v = -g h k, to rounding (each
   substep's velocity and the step's displacement summed: 2 k u of the
   figures).  Checked at every step whose free prediction stays short of
   L.  Then caught: the speculative side stops it at L, and it hangs on
   the limit's feedback, m g over the axis mass m: g / omega_s^2 past L,
   loaded at once from rest, so never more than twice that past L (plus
   the length's rounding 8 u L); after 2 s it rests there (the feedback's
   slow mode decays at 150 /s) to rounding. */
static void distance_rope(void)
{
    const double Ls[2] = {1, 2}, d0s[2] = {0.5, 0.2};
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, -G);
        double L = Ls[i], y0 = -d0s[i], worst_free = 0, worst_past = -1, rest = G / omega_s2();
        ga2d_body_id p = pivot_body(w, 0, 0, 0), b = disc_body(w, 0, y0, 0.1, 0.6);
        ga2d_distance_joint_def d = distance_def(p, b, v2(0, 0), v2(0, 0), L);
        ga2d_joint_id j;
        int free_steps = 0;
        d.enable_limit = 1;
        d.min_length = 0;
        d.max_length = (ga2d_real)L;
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 1; k <= 180; ++k) {
            double n = SUB * k, y_free = y0 - G * H * H * n * (n + 1) / 2, v_free = -G * H * n, y, past;
            step(w);
            y = (double)ga2d_body_position(w, b).y;
            past = (double)ga2d_distance_joint_current_length(w, j) - L;
            if (-y_free < L) {
                CHECK_NEAR(y, y_free, 2 * n * U * (fabs(y0) + fabs(y_free - y0)));
                CHECK_NEAR(ga2d_body_velocity(w, b).y, v_free, 2 * n * U * fabs(v_free));
                if (fabs(y - y_free) > worst_free) worst_free = fabs(y - y_free);
                ++free_steps;
            }
            if (past > worst_past) worst_past = past;
        }
        CHECK(free_steps > 10); /* the premise: a fall seen */
        CHECK(worst_past <= 2 * rest + 8 * U * L);
        CHECK_NEAR((double)ga2d_distance_joint_current_length(w, j) - L, rest, 8 * U * L);
        CHECK_NEAR(ga2d_body_velocity(w, b).y, 0, 8 * U * L / H);
        if (verbose())
            printf("joint kinds: rope %.0f m from %.1f m: free fall over %d steps within %.3g m; past L by %.3g m at most "
                   "(<= %.3g), rests %.4g past (static %.4g)\n",
                   L, d0s[i], free_steps, worst_free, worst_past, 2 * rest + 8 * U * L,
                   (double)ga2d_distance_joint_current_length(w, j) - L, rest);
        ga2d_world_destroy(w);
    }
}

/* A distance motor of max force F on a disc (r = 0.25) at 1 m (extending
   to +2 m/s) or 4 m (shortening to -1 m/s) from a static body, gravity
   off, the range [0.1, 100] on so that no rigid length holds it (the
   range's sides far: speculative, idle).  The motion stays on the line:
   as the revolute motor (test_joints.c motor_max_torque) the cap F h is
   reached in every pass until the target is near: the length's rate
   (the disc's x velocity) is F t / m within (4 u + n u / 2) of it after
   n substeps, the reaction force along the axis is F (2 u); then held at
   the target within 4 u, the motor's force at most m 8 u |v_t| / h. */
static void distance_motor(void)
{
    const double F = 0.5, targets[2] = {2, -1}, starts[2] = {1, 4};
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, 0);
        ga2d_body_id p = pivot_body(w, 0, 0, 0), b = disc_body(w, starts[i], 0, 0.25, 0.6);
        ga2d_distance_joint_def d = distance_def(p, b, v2(0, 0), v2(0, 0), starts[i]);
        ga2d_joint_id j;
        double m = mass_of(w, b), vt = targets[i], sgn = vt > 0 ? 1 : -1, t_reach = fabs(vt) * m / F, worst = 0;
        int accel = 0, held = 0;
        d.enable_limit = 1;
        d.min_length = (ga2d_real)0.1;
        d.max_length = 100;
        d.enable_motor = 1;
        d.motor_speed = (ga2d_real)vt;
        d.max_motor_force = (ga2d_real)F;
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 1; k <= 120; ++k) {
            double t = k * DT, v;
            ga2d_vec f;
            step(w);
            v = (double)ga2d_body_velocity(w, b).x;
            f = ga2d_joint_reaction_force(w, j);
            CHECK(ga2d_body_velocity(w, b).y == 0 && ga2d_body_position(w, b).y == 0);
            if (t < t_reach - DT / 2) {
                double expect = sgn * F * t / m;
                CHECK_NEAR(v, expect, (4 * U + SUB * k * U / 2) * fabs(expect));
                CHECK_NEAR(f.x, sgn * F, 2 * U * F);
                if (fabs(v - expect) / fabs(expect) > worst) worst = fabs(v - expect) / fabs(expect);
                ++accel;
            } else if (t > t_reach + 2 * DT) {
                CHECK_NEAR(v, vt, 4 * U * fabs(vt));
                CHECK_NEAR(f.x, 0, m * 8 * U * fabs(vt) / H);
                ++held;
            }
        }
        CHECK(accel > 10 && held > 10); /* the premise: both phases seen */
        if (verbose())
            printf("joint kinds: distance motor F %.1f N to %+.0f m/s on m %.4g: rate = F t / m within %.3g rel over %d steps, "
                   "then held at %.9g\n", F, vt, m, worst, accel, (double)ga2d_body_velocity(w, b).x);
        ga2d_world_destroy(w);
    }
}

/* ================================================================ weld */
/* A cantilever: 5 boxes (0.5 x 0.25, density 1) welded end to end from a
   static wall at the origin, level, gravity down, rigid welds.  At rest
   joint i (1 at the wall) carries the n = 6 - i boxes beyond it: a force
   F_i = n m g and a moment about its anchor tau_i = m g a n^2 (a = 0.25
   the half length: the boxes' centres lie a, 3a, ... beyond it).  The
   feedback yields (top comment) on the angle by tau_i / (I_eff omega_s^2)
   (1/I_eff = 1/I_a + 1/I_b, the wall's 0) and on the point, vertically,
   by F_i K_yy / omega_s^2, K_yy = 1/m_a + 1/m_b + a^2/I_a + a^2/I_b (the
   anchors at +-a along the level boxes, the wall's terms 0).  The tip
   (box 5's free end) sinks by the sum of the gaps plus each joint's turn
   times its distance to the tip, 2 a n.  These are first order in the
   turns: the boxes' angles (up to th, the sum of the turns, 0.09 rad)
   shorten the moment arms by cos th, the lever arms in K by cos^2 th,
   and the tip's rise 2 a sin th: all within th^2 relative (1 - cos^2 th
   <= th^2, th - sin th <= th^3 / 6), so each joint's figures and the
   tip's match within 2 th^2 relative (a margin of 2 on the sum of those
   effects; the static fixed point itself is exact, reached after 5 s
   (the slowest mode of the chain decays in well under a second: checked
   by the tip's speed, below 1e-6 of its deflection per second)). */
static void weld_cantilever(void)
{
    const double a = 0.25, hy = 0.125;
    ga2d_world *w = make_world(0, -G);
    ga2d_body_id box[6];
    ga2d_joint_id jt[6];
    double m, I, tip_expect = 0, th = 0, worst = 0, tip, tol;
    int i;
    box[0] = pivot_body(w, 0, 0, 0);
    for (i = 1; i <= 5; ++i) {
        ga2d_weld_joint_def d = ga2d_default_weld_joint_def();
        box[i] = box_body(w, (2 * i - 1) * a, 0, 0, a, hy, 1);
        d.body_a = box[i - 1];
        d.body_b = box[i];
        d.local_anchor_a = v2(i == 1 ? 0 : a, 0);
        d.local_anchor_b = v2(-a, 0);
        CHECK_RESULT(ga2d_weld_joint_create_checked(w, &d, &jt[i]), GA2D_OK);
    }
    m = mass_of(w, box[1]);
    I = inertia_of(w, box[1]);
    for (i = 1; i <= 5; ++i) {
        double n = 6 - i, ie = i == 1 ? I : I / 2, kyy = (i == 1 ? 0 : 1 / m + a * a / I) + 1 / m + a * a / I;
        double turn = m * G * a * n * n / (ie * omega_s2()), gap = n * m * G * kyy / omega_s2();
        tip_expect += gap + turn * 2 * a * n;
        th += turn;
    }
    tol = 2 * th * th;
    steps(w, 1140);
    tip = (double)world_point(w, box[5], v2(a, 0)).y;
    steps(w, 60);
    CHECK(fabs((double)world_point(w, box[5], v2(a, 0)).y - tip) <= 1e-4 * tip_expect); /* settled */
    for (i = 1; i <= 5; ++i) {
        double n = 6 - i, ie = i == 1 ? I : I / 2, kyy = (i == 1 ? 0 : 1 / m + a * a / I) + 1 / m + a * a / I;
        double turn = m * G * a * n * n / (ie * omega_s2()), gap = n * m * G * kyy / omega_s2();
        double got_turn = (double)ga2d_body_angle(w, box[i - 1]) - (double)ga2d_body_angle(w, box[i]);
        double got_gap = dist(world_point(w, box[i - 1], v2(i == 1 ? 0 : a, 0)), world_point(w, box[i], v2(-a, 0)));
        CHECK_NEAR(got_turn / turn, 1, tol);
        CHECK_NEAR(got_gap / gap, 1, tol);
        if (verbose()) printf("  joint %d: turn %.6g (%.6g), gap %.6g (%.6g)\n", i, got_turn, turn, got_gap, gap);
        if (fabs(got_turn / turn - 1) > worst) worst = fabs(got_turn / turn - 1);
        if (fabs(got_gap / gap - 1) > worst) worst = fabs(got_gap / gap - 1);
    }
    tip = -(double)world_point(w, box[5], v2(a, 0)).y;
    CHECK_NEAR(tip / tip_expect, 1, tol);
    /* the wall's joint carries the whole beam: 5 m g and 25 m g a */
    CHECK_NEAR((double)ga2d_joint_reaction_force(w, jt[1]).y, 5 * m * G, tol * 5 * m * G);
    CHECK_NEAR((double)ga2d_joint_reaction_torque(w, jt[1]), 25 * m * G * a, tol * 25 * m * G * a);
    if (verbose())
        printf("joint kinds: weld cantilever of 5: tip sinks %.5f m, the feedback's %.5f: |rel| %.3g <= %.3g (2 th^2, th %.3f "
               "rad); each joint's turn and gap within %.3g rel\n",
               tip, tip_expect, fabs(tip / tip_expect - 1), tol, th, worst);
    ga2d_world_destroy(w);
}

/* Soft welds.  (1) A disc (r = 0.5) welded at its centre to a static
   pivot, gravity off, angular_hertz f (damping ratio 1), a torque tau
   applied every step: the angular spring, solved in both passes, rests
   where its impulse gives back tau h: angle tau / (I (2 pi f)^2), the
   spring k = I_eff (2 pi f)^2 with I_eff the disc's I (A static) exactly
   (top comment).  The bound is 10%; the scheme's rest is exact,
   so the check is the settling: critically damped, the slow eigenvalue
   lam (critical_lambda) leaves at most th 480 lam^480 of the start's
   offset th after 2 s (the run is 4 s: looser still), plus the angle's
   rounding 8 u.
   (2) The same disc hanging, linear_hertz f (damping 1), angular rigid,
   under gravity: the linear spring (a 2x2 block over the mass m, no
   lever) rests g / (2 pi f)^2 below the pivot, the same way. */
static void weld_soft(void)
{
    const double fs[3] = {1, 2, 4}, tau = 0.05;
    int i, k;
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, 0), *w2 = make_world(0, -G);
        ga2d_body_id p = pivot_body(w, 0, 0, 0), b = disc_body(w, 0, 0, 0.5, 0.6);
        ga2d_body_id p2 = pivot_body(w2, 0, 0, 0), b2 = disc_body(w2, 0, 0, 0.5, 0.6);
        ga2d_weld_joint_def d = ga2d_default_weld_joint_def();
        double om = 2 * PI * fs[i], I = inertia_of(w, b), th, sag, lam, settle, got, got_sag;
        int rp;
        d.body_a = p;
        d.body_b = b;
        d.angular_hertz = (ga2d_real)fs[i];
        d.angular_damping_ratio = 1;
        CHECK(!ga2d_joint_id_is_null(ga2d_weld_joint_create(w, &d)));
        d = ga2d_default_weld_joint_def();
        d.body_a = p2;
        d.body_b = b2;
        d.linear_hertz = (ga2d_real)fs[i];
        d.linear_damping_ratio = 1;
        CHECK(!ga2d_joint_id_is_null(ga2d_weld_joint_create(w2, &d)));
        th = tau / (I * om * om);
        sag = G / (om * om);
        lam = critical_lambda(fs[i], &rp);
        CHECK(rp);
        settle = 480 * pow(lam, 480);
        for (k = 0; k < 240; ++k) {
            CHECK_RESULT(ga2d_body_apply_torque(w, b, (ga2d_real)tau), GA2D_OK);
            step(w);
            step(w2);
        }
        got = (double)ga2d_body_angle(w, b);
        got_sag = -(double)ga2d_body_center(w2, b2).y;
        CHECK_NEAR(got, th, th * settle + 8 * U);
        CHECK(fabs(got / th - 1) <= 0.1); /* the bound */
        CHECK_NEAR(got_sag, sag, sag * settle + 8 * U);
        CHECK_NEAR(ga2d_body_center(w2, b2).x, 0, 8 * U);
        if (verbose())
            printf("joint kinds: soft weld %.0f Hz: angle under %.2f N m %.6g rad, tau / (I (2 pi f)^2) %.6g: |rel| %.3g "
                   "(<= %.3g, the issue's 0.1); linear: sag %.6g m, g / (2 pi f)^2 %.6g: |rel| %.3g\n",
                   fs[i], tau, got, th, fabs(got / th - 1), settle + 8 * U / th, got_sag, sag, fabs(got_sag / sag - 1));
        ga2d_world_destroy(w);
        ga2d_world_destroy(w2);
    }
}

/* ========================================================= motor joint */
/* A motor joint from a static body A (at (1, 2), turned 0.3 rad, anchor
   (0.5, 0) in its frame) to a box B (anchor at its centre), target
   linear offset (1, 0.5) in A's frame and angular offset 0.5 (B's angle
   0.8), gravity down, correction c = 0.3, max_force 2 m g (the hold needs
   m g), max_torque 0.2 N m.  B starts at rest 0.5 m off the target (two
   directions) and level: far from it the drive asks more than its caps
   (c 0.5 m / h^2 m is 27 m g), so it pushes at max_force (and turns at
   max_torque) with at least F / m - g = g left toward the target once
   gravity is held; it arrives within the 5 s run (checked: the pose is
   held at the end).  Below its caps, each pass asks the velocity that
   closes c of the gap, the warm start having given back gravity's kick:
   the gap shrinks by (1 - c) every substep, so the pose is held exactly
   (no sag: the drive has no spring), to rounding: the gap from
   coordinates of size S (8 u S), the drive restoring only c of a
   rounding error per substep: 8 u S / c; the same for the angle (8 u of
   the angles, 1 rad, over c).  The reaction force never exceeds
   max_force, nor the torque max_torque, beyond rounding (4 u: the clamp
   scales by a unit vector of 2 u, then by the cap, then 1/h), at any
   step, and the caps are met on the way; holding, the reaction is (0,
   m g) to rounding (8 u m g). */
static void motor_joint_holds(void)
{
    const double offs[2][2] = {{-0.5, 0}, {0.3, 0.4}};
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, -G);
        ga2d_body_id a = pivot_body(w, 1, 2, 0.3), b;
        ga2d_motor_joint_def d = ga2d_default_motor_joint_def();
        ga2d_joint_id j;
        double m, Fmax, Tmax = 0.2, worst_f = 0, worst_t = 0, S, gap, turn;
        ga2d_vec target = world_point(w, a, v2(1.5, 0.5));
        b = box_body(w, (double)target.x + offs[i][0], (double)target.y + offs[i][1], 0, 0.4, 0.2, 1);
        m = mass_of(w, b);
        Fmax = 2 * m * G;
        d.body_a = a;
        d.body_b = b;
        d.local_anchor_a = v2(0.5, 0);
        d.linear_offset = v2(1, 0.5);
        d.angular_offset = (ga2d_real)0.5;
        d.max_force = (ga2d_real)Fmax;
        d.max_torque = (ga2d_real)Tmax;
        d.correction_factor = (ga2d_real)0.3;
        CHECK_RESULT(ga2d_motor_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 300; ++k) {
            step(w);
            if (len(ga2d_joint_reaction_force(w, j)) > worst_f) worst_f = len(ga2d_joint_reaction_force(w, j));
            if (fabs((double)ga2d_joint_reaction_torque(w, j)) > worst_t) worst_t = fabs((double)ga2d_joint_reaction_torque(w, j));
        }
        CHECK(worst_f <= Fmax * (1 + 4 * U));
        CHECK(worst_t <= Tmax * (1 + 4 * U));
        CHECK(worst_f >= Fmax * (1 - 4 * U) && worst_t >= Tmax * (1 - 4 * U)); /* the premise: the caps were met */
        S = len(target) + 1;
        gap = dist(ga2d_body_position(w, b), target);
        turn = (double)ga2d_body_angle(w, b) - 0.8;
        CHECK(gap <= 8 * U * S / 0.3);
        CHECK(fabs(turn) <= 8 * U / 0.3);
        CHECK_NEAR(ga2d_joint_reaction_force(w, j).y, m * G, 8 * U * m * G);
        CHECK_NEAR(ga2d_joint_reaction_force(w, j).x, 0, 8 * U * m * G);
        if (verbose())
            printf("joint kinds: motor joint from (%+.1f, %+.1f) off: holds the pose to %.3g m (<= %.3g) and %.3g rad (<= "
                   "%.3g); force at most %.9g N (cap %.9g), torque at most %.9g N m (cap %.3g); holding %.9g N (m g %.9g)\n",
                   offs[i][0], offs[i][1], gap, 8 * U * S / 0.3, fabs(turn), 8 * U / 0.3, worst_f, Fmax, worst_t, Tmax,
                   (double)ga2d_joint_reaction_force(w, j).y, m * G);
        ga2d_world_destroy(w);
    }
}

/* Too weak: max_force F = 0.5 m g, the target straight above B's start.
   The drive's force is at most F in any direction, so B's upward
   acceleration is at most F / m - g: from rest its vertical speed stays
   below -(g - F / m) t (to rounding, 2 n u of g t after n substeps) and
   it sinks.  The reaction force never exceeds F (4 u, as above). */
static void motor_joint_too_weak(void)
{
    ga2d_world *w = make_world(0, -G);
    ga2d_body_id a = pivot_body(w, 0, 0, 0), b = box_body(w, 0, -1, 0, 0.4, 0.2, 1);
    ga2d_motor_joint_def d = ga2d_default_motor_joint_def();
    ga2d_joint_id j;
    double m = mass_of(w, b), F = 0.5 * m * G, worst_f = 0, y0 = -1;
    int k;
    d.body_a = a;
    d.body_b = b;
    d.linear_offset = v2(0, 0);
    d.max_force = (ga2d_real)F;
    d.max_torque = 1;
    CHECK_RESULT(ga2d_motor_joint_create_checked(w, &d, &j), GA2D_OK);
    for (k = 1; k <= 60; ++k) {
        double t = k * DT, n = SUB * k;
        step(w);
        CHECK((double)ga2d_body_velocity(w, b).y <= -(G - F / m) * t + 2 * n * U * G * t);
        if (len(ga2d_joint_reaction_force(w, j)) > worst_f) worst_f = len(ga2d_joint_reaction_force(w, j));
    }
    CHECK(worst_f <= F * (1 + 4 * U));
    CHECK((double)ga2d_body_position(w, b).y < y0 - (G - F / m) / 2 * 0.9); /* sank over 1 s, the bound's t^2/2 less a margin */
    if (verbose())
        printf("joint kinds: motor joint of max force m g / 2 cannot hold: after 1 s at y %.4f (from %.1f; the bound %.4f), "
               "speed %.4f m/s (<= %.4f), force at most %.6g N (cap %.6g)\n",
               (double)ga2d_body_position(w, b).y, y0, y0 - (G - F / m) / 2, (double)ga2d_body_velocity(w, b).y,
               -(G - F / m), worst_f, F);
    ga2d_world_destroy(w);
}

/* =========================================================== prismatic */
static ga2d_prismatic_joint_def prismatic_def(ga2d_body_id a, ga2d_body_id b, double axis_angle)
{
    ga2d_prismatic_joint_def d = ga2d_default_prismatic_joint_def();
    d.body_a = a;
    d.body_b = b;
    d.local_axis_a = v2(2 * cos(axis_angle), 2 * sin(axis_angle)); /* any length: made unit */
    return d;
}

/* A box (0.4 x 0.2) on a frictionless slide along an axis at theta from
   the horizontal in the world: A a static body turned by 0.4 rad, the
   axis theta - 0.4 in its frame and the reference angle -0.4 (B level),
   both anchors at the box's centre.
   Gravity (0, -g): along the axis a = -g sin theta.  With A static and
   B's anchor at its centre, the normal row, the angle row and the axis
   are decoupled (the block's k12 and the axis's levers vanish), so the
   normal impulses never touch the motion along the axis: each substep
   adds a h to its speed exactly, and the translation after n substeps is
   a h^2 n (n + 1) / 2 = a t^2 / 2 (1 + 1/n), the speed a t, to rounding
   (4 n u of them); B never turns (no torque reaches it: 8 u); its anchor
   stays off the axis line by the normal row's static deflection g cos
   theta / omega_s^2, loaded from rest: at most twice that (plus 8 u of
   the coordinates), and the reaction force is m g cos theta across the
   axis after the feedback settled (its rounding below).  30, 75 and 150 degrees. */
static double read_prismatic(const ga2d_world *w, ga2d_joint_id j, ga2d_body_id b)
{
    (void)b;
    return (double)ga2d_prismatic_joint_translation(w, j);
}

static void prismatic_slide(void)
{
    const double thetas[3] = {30 * PI / 180, 75 * PI / 180, 150 * PI / 180}, phi = 0.4;
    int i, k;
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, -G);
        double th = thetas[i], acc = -G * sin(th), worst = 0, worst_n = 0, worst_turn = 0, nb, m;
        ga2d_body_id a = pivot_body(w, 0, 0, phi), b = box_body(w, 0, 0, 0, 0.4, 0.2, 1);
        ga2d_prismatic_joint_def d = prismatic_def(a, b, th - phi);
        ga2d_joint_id j;
        ga2d_vec f;
        d.reference_angle = (ga2d_real)-phi; /* B's angle less A's: B level */
        CHECK_RESULT(ga2d_prismatic_joint_create_checked(w, &d, &j), GA2D_OK);
        m = mass_of(w, b);
        nb = 2 * G * fabs(cos(th)) / omega_s2();
        for (k = 1; k <= 45; ++k) {
            double n = SUB * k, t = k * DT, s_exp = acc * H * H * n * (n + 1) / 2, s, v, c[2], off;
            ga2d_vec p;
            step(w);
            s = (double)ga2d_prismatic_joint_translation(w, j);
            v = (double)ga2d_prismatic_joint_speed(w, j);
            CHECK_NEAR(s, s_exp, 4 * n * U * fabs(s_exp));
            CHECK_NEAR(s / (acc * t * t / 2), 1 + 1 / n, 4 * n * U);
            CHECK_NEAR(v, acc * t, 4 * n * U * fabs(acc * t));
            CHECK(fabs((double)ga2d_body_angle(w, b)) <= 8 * U);
            p = ga2d_body_position(w, b);
            c[0] = cos(th);
            c[1] = sin(th);
            off = fabs(-c[1] * (double)p.x + c[0] * (double)p.y); /* across the axis line through the origin */
            CHECK(off <= nb + 8 * U * (1 + fabs(s)));
            if (fabs(s / s_exp - 1) > worst) worst = fabs(s / s_exp - 1);
            if (off > worst_n) worst_n = off;
            if (fabs((double)ga2d_body_angle(w, b)) > worst_turn) worst_turn = fabs((double)ga2d_body_angle(w, b));
        }
        f = ga2d_joint_reaction_force(w, j);
        /* the normal force feeds back the offset, read from coordinates of
           size 1 + |s|: its rounding is m omega_s^2 8 u (1 + |s|) */
        CHECK_NEAR(len(f), m * G * fabs(cos(th)), 8 * U * m * (G + omega_s2() * (1 + fabs(acc) * 0.75 * 0.75)));
        CHECK_NEAR((double)f.x * cos(th) + (double)f.y * sin(th), 0, 8 * U * m * G); /* across the axis */
        if (verbose())
            printf("joint kinds: prismatic slide at %.0f deg: translation a t^2/2 (1 + 1/n) within %.3g rel after 0.75 s "
                   "(%.6f m), speed %.6f m/s (a t %.6f); turned %.3g rad; off the axis %.3g m <= %.3g; normal force %.6g N "
                   "(m g cos %.6g)\n",
                   th * 180 / PI, worst, (double)ga2d_prismatic_joint_translation(w, j),
                   (double)ga2d_prismatic_joint_speed(w, j), acc * 0.75, worst_turn, worst_n, nb, len(f),
                   m * G * fabs(cos(th)));
        ga2d_world_destroy(w);
    }
}

/* The slide at 30 degrees into its limits [-1, 0.5]: gravity down slides
   it to the lower one, gravity up to the upper.  The limit is
   speculative: while apart the box closes no more than the room left in a
   substep, so it arrives on the limit, then rests on its feedback pressed
   by m g sin theta over the axis mass m: g sin theta / omega_s^2 past it,
   loaded at once, so never more than twice that past (plus 8 u of the
   coordinates); after 2 s at rest there to 8 u. */
static void prismatic_limits(void)
{
    const double th = 30 * PI / 180, lo = -1, hi = 0.5;
    int i, k;
    for (i = 0; i < 2; ++i) {
        double sgn = i == 0 ? -1 : 1, lim = i == 0 ? lo : hi, rest = G * sin(th) / omega_s2(), worst = -1, past;
        ga2d_world *w = make_world(0, sgn * G);
        ga2d_body_id a = pivot_body(w, 0, 0, 0), b = box_body(w, 0, 0, 0, 0.4, 0.2, 1);
        ga2d_prismatic_joint_def d = prismatic_def(a, b, th);
        ga2d_joint_id j;
        d.enable_limit = 1;
        d.lower_translation = (ga2d_real)lo;
        d.upper_translation = (ga2d_real)hi;
        CHECK_RESULT(ga2d_prismatic_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 120; ++k) {
            step(w);
            past = sgn * ((double)ga2d_prismatic_joint_translation(w, j) - lim);
            if (past > worst) worst = past;
        }
        past = sgn * ((double)ga2d_prismatic_joint_translation(w, j) - lim);
        CHECK(worst <= 2 * rest + 8 * U * 2);
        CHECK_NEAR(past, rest, 8 * U * 2);
        CHECK_NEAR(ga2d_prismatic_joint_speed(w, j), 0, 8 * U * 2 / H);
        if (verbose())
            printf("joint kinds: prismatic into its %s limit %+.1f: past it by %.3g m at most (<= %.3g), rests %.4g past "
                   "(static %.4g)\n", i == 0 ? "lower" : "upper", lim, worst, 2 * rest + 16 * U, past, rest);
        ga2d_world_destroy(w);
    }
}

/* The prismatic motor: max force F toward motor_speed along an axis at
   -50 degrees, gravity off, B's anchor at its centre (the axis's mass is
   m): as the distance motor, a = F / m until the target, then held. */
static void prismatic_motor(void)
{
    const double F = 0.8, targets[2] = {1.5, -2};
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, 0);
        ga2d_body_id a = pivot_body(w, 0, 0, 0), b = box_body(w, 0, 0, 0, 0.4, 0.2, 1);
        ga2d_prismatic_joint_def d = prismatic_def(a, b, -50 * PI / 180);
        ga2d_joint_id j;
        double m = mass_of(w, b), vt = targets[i], sgn = vt > 0 ? 1 : -1, t_reach = fabs(vt) * m / F, worst = 0;
        int accel = 0, held = 0;
        d.enable_motor = 1;
        d.motor_speed = (ga2d_real)vt;
        d.max_motor_force = (ga2d_real)F;
        CHECK_RESULT(ga2d_prismatic_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 1; k <= 120; ++k) {
            double t = k * DT, v;
            step(w);
            v = (double)ga2d_prismatic_joint_speed(w, j);
            if (t < t_reach - DT / 2) {
                double expect = sgn * F * t / m;
                CHECK_NEAR(v, expect, (8 * U + SUB * k * U) * fabs(expect));
                CHECK_NEAR(len(ga2d_joint_reaction_force(w, j)), F, 4 * U * F);
                if (fabs(v - expect) / fabs(expect) > worst) worst = fabs(v - expect) / fabs(expect);
                ++accel;
            } else if (t > t_reach + 2 * DT) {
                CHECK_NEAR(v, vt, 8 * U * fabs(vt));
                ++held;
            }
        }
        CHECK(accel > 10 && held > 10);
        if (verbose())
            printf("joint kinds: prismatic motor F %.1f N to %+.1f m/s on m %.4g: speed = F t / m within %.3g rel over %d "
                   "steps, then held at %.9g\n", F, vt, m, worst, accel, (double)ga2d_prismatic_joint_speed(w, j));
        ga2d_world_destroy(w);
    }
}

/* The prismatic spring (f hertz, damping 0) on the same slide, gravity
   off, started 0.2 m along: the axis's mass is m, the period the
   scheme's (scheme_period), 0.5, 1 and 2 Hz. */
static void prismatic_spring(void)
{
    const double fs[3] = {0.5, 1, 2}, th = 20 * PI / 180;
    int i;
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, 0);
        ga2d_body_id a = pivot_body(w, 0, 0, 0), b = box_body(w, 0.2 * cos(th), 0.2 * sin(th), 0, 0.4, 0.2, 1);
        ga2d_prismatic_joint_def d = prismatic_def(a, b, th);
        ga2d_joint_id j;
        double tol, Td = scheme_period(fs[i], 3, &tol), T;
        d.local_anchor_b = v2(0, 0);
        d.local_anchor_a = v2(0, 0);
        d.enable_spring = 1;
        d.hertz = (ga2d_real)fs[i];
        CHECK_RESULT(ga2d_prismatic_joint_create_checked(w, &d, &j), GA2D_OK);
        T = time_periods(w, j, b, read_prismatic, 3, 2000);
        CHECK_NEAR(T, Td, tol);
        if (verbose())
            printf("joint kinds: prismatic spring %.1f Hz: period %.6f s, the scheme's %.6f, |diff| %.3g <= %.3g\n", fs[i], T,
                   Td, fabs(T - Td), tol);
        ga2d_world_destroy(w);
    }
}

/* =============================================================== wheel */
/* A car: a chassis (box 2.4 x 0.5, density 1) and two discs (r = 0.4,
   friction 0.9) on wheel joints at (+-0.9, -0.5) in the chassis's
   frame, axis y, suspension f hertz damping 0.7, motors (speed 0) of
   max torque T, on a ground box turned by `slope` (friction 0.6).  The
   chassis and wheels start turned with the ground, the wheels touching
   it. */
typedef struct car { ga2d_body_id ground, chassis, wheel[2]; ga2d_joint_id j[2]; } car;
#define WHEEL_R 0.4
static car make_car(ga2d_world *w, double slope, double hertz, double max_torque)
{
    car c;
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_rotor q = ga2d_rotor_from_angle((ga2d_real)slope);
    int k;
    bd.rotor = q;
    bd.position = v2(0.5 * sin(slope), -0.5 * cos(slope)); /* the top face through the origin */
    bd.polygon = ga2d_polygon_box(50, (ga2d_real)0.5);
    c.ground = ga2d_body_create(w, &bd);
    bd = ga2d_default_body_def();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.rotor = q;
    bd.position = ga2d_rotate(q, v2(0, WHEEL_R + 0.5));
    bd.polygon = ga2d_polygon_box((ga2d_real)1.2, (ga2d_real)0.25);
    c.chassis = ga2d_body_create(w, &bd);
    for (k = 0; k < 2; ++k) {
        ga2d_wheel_joint_def d = ga2d_default_wheel_joint_def();
        ga2d_vec p = world_point(w, c.chassis, v2(k ? 0.9 : -0.9, -0.5));
        c.wheel[k] = disc_body(w, (double)p.x, (double)p.y, WHEEL_R, 0.9);
        d.body_a = c.chassis;
        d.body_b = c.wheel[k];
        d.local_anchor_a = v2(k ? 0.9 : -0.9, -0.5);
        d.hertz = (ga2d_real)hertz;
        d.damping_ratio = (ga2d_real)0.7;
        d.enable_motor = 1;
        d.motor_speed = 0;
        d.max_motor_torque = (ga2d_real)max_torque;
        CHECK_RESULT(ga2d_wheel_joint_create_checked(w, &d, &c.j[k]), GA2D_OK);
    }
    return c;
}

/* On flat ground the suspension carries the chassis: by symmetry half
   its weight on each wheel (the wheels' own weight goes to the ground;
   the contacts' horizontal squeeze acts at both anchors, at one height,
   and turns nothing).  The spring rests where its impulse gives back its
   load S (top comment): translation S / k, k = m_eff (2 pi f)^2 with the
   axis's mass 1/m_eff = 1/m_c + 1/m_w + x^2 / I_c, x the wheel's anchor
   across the axis from the chassis's centre (0.9, less the normal row's
   tiny static give under the squeeze: read from the bodies; no lever on
   the wheel, held at its centre).  The rest is exact; the chassis's heave
   on its spring, of mass M = m_c / 2 a wheel, decays at c / (2 M) =
   zeta 2 pi f m_eff / M (c = 2 zeta m_eff 2 pi f the spring's damping),
   so after T = 10 s what is left of the start's offset (S / k, started
   uncompressed) is within e^(-rate T), taken 10 times (the mode's
   share of the start and its beat with the wheel's: a margin), plus
   rounding 16 u of the coordinates (1 m).  Checked: each spring's
   translation against its measured load S / k, S against m_c g / 2, and
   the two reactions on the wheels sum to the chassis's weight, -m_c g y,
   to the same; the forces' rounding is that of the positions they feed
   back, times the stiffness: 16 u (m_c g + k 1 m) for S, and for the sum
   also the normal rows' feedback, whose mass is at most the wheel's:
   16 u 2 (k + m_w omega_s^2) 1 m.  2, 4 and 8 Hz. */
static void wheel_suspension(void)
{
    const double fs[3] = {2, 4, 8};
    int i, k;
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, -G);
        car c = make_car(w, 0, fs[i], 50);
        double mc = mass_of(w, c.chassis), mw = mass_of(w, c.wheel[0]), ic = inertia_of(w, c.chassis), worst = 0, worst_share = 0;
        ga2d_vec sum = v2(0, 0);
        double kmax = 0, rate = 0.7 * 2 * PI * fs[i] * (1 / (1 / mc + 1 / mw + 0.81 / ic)) / (mc / 2), left = 10 * exp(-rate * 10);
        steps(w, 600);
        for (k = 0; k < 2; ++k) {
            ga2d_rotor q = ga2d_body_rotor(w, c.chassis);
            ga2d_vec axis = ga2d_rotate(q, v2(0, 1)), f = ga2d_joint_reaction_force(w, c.j[k]);
            ga2d_vec lever = ga2d_rotate_inv(q, ga2d_vec_sub(ga2d_body_center(w, c.wheel[k]), ga2d_body_center(w, c.chassis)));
            double meff = 1 / (1 / mc + 1 / mw + (double)lever.x * (double)lever.x / ic), om = 2 * PI * fs[i];
            double kk = meff * om * om, load = -((double)f.x * (double)axis.x + (double)f.y * (double)axis.y);
            double t = (double)ga2d_wheel_joint_translation(w, c.j[k]), t_exp = load / kk, t_half = mc * G / 2 / kk;
            CHECK_NEAR(t, t_exp, left * t_half + 16 * U);
            CHECK_NEAR(load, mc * G / 2, left * mc * G + 16 * U * (mc * G + kk));
            kmax = kk > kmax ? kk : kmax;
            sum = ga2d_vec_add(sum, f);
            if (fabs(t / t_exp - 1) > worst) worst = fabs(t / t_exp - 1);
            if (fabs(t / t_half - 1) > worst_share) worst_share = fabs(t / t_half - 1);
            if (verbose())
                printf("  wheel %d: compression %.9g m, load / k %.9g, m_c g / 2 / k %.9g (k %.6g N/m), lever %.9g, chassis "
                       "angle %.3g\n", k, t, t_exp, t_half, kk, (double)lever.x, (double)ga2d_body_angle(w, c.chassis));
        }
        CHECK_NEAR(sum.x, 0, left * mc * G + 16 * U * (mc * G + 2 * (kmax + mw * omega_s2())));
        CHECK_NEAR(sum.y, -mc * G, left * mc * G + 16 * U * (mc * G + 2 * (kmax + mw * omega_s2())));
        if (verbose())
            printf("joint kinds: suspension %.0f Hz: compression = load / (m_eff (2 pi f)^2) within %.3g rel, "
                   "m_c g / 2 / k within %.3g (bound %.3g + rounding); the wheels carry %.9g N (m_c g %.9g)\n",
                   fs[i], worst, worst_share, left, -(double)sum.y, mc * G);
        ga2d_world_destroy(w);
    }
}

/* Parked on a 15 degree slope with the motors braking (speed 0, max
   torque 50 N m: the hold needs m g sin(15) r / 2 ~ 1.2 N m a wheel;
   friction sqrt(0.9 0.6) = 0.73 against tan 15 = 0.27).  After 8 s to
   settle (its slowest mode decays at about 4.6 /s: what is left is below
   the rounding floor), over the next 8 s: at rest every pass gives back
   what gravity took, and velocities are only the feedbacks' answers to
   the positions' rounding (8 u of the coordinates S = 2 m); a feedback's
   bias rate is below 1 / h (b h = h w / (2 zeta + h w) < 1), so speeds
   stay below 8 u S / h and the chassis creeps no more than that times
   8 s.  Then the motors drive it up (speed -10 rad/s, clockwise, max
   torque 3 N m): while a wheel's spin relative to the chassis is under
   half the target its motor is at its cap, |torque| = 3 (2 u), never
   more (the lighter-loaded front wheel spins: slip, physical); the car
   climbs; and in the last second, both wheels at the target and
   rolling, the rear wheel's centre moves as it rolls on its contact,
   (r - d) |w| with d its depth in the ground, below 2 linear slops (the
   contacts keep one slop of overlap; the soft contact's sag, N / (m_w
   (2 pi 60)^2) ~ 1.4e-4 m, is within the other): the distance over the
   wheel's r integral |w| dt is 1 within 2 slop / r. */
static void wheel_car_on_slope(void)
{
    const double slope = 15 * PI / 180, Tmax = 3, S = 2;
    ga2d_world *w = make_world(0, -G);
    car c = make_car(w, slope, 4, 50);
    ga2d_vec x0, dir = v2(cos(slope), sin(slope)), p0 = v2(0, 0);
    double creep, speed_bound = 8 * U * S / H, creep_bound = speed_bound * 8, worst_speed = 0, climbed, worst_torque = 0;
    double at_cap = 0, rolled = 0, moved;
    int k, i, capped = 0;
    steps(w, 480);
    x0 = ga2d_body_position(w, c.chassis);
    for (k = 0; k < 480; ++k) {
        step(w);
        if (len(ga2d_body_velocity(w, c.chassis)) > worst_speed) worst_speed = len(ga2d_body_velocity(w, c.chassis));
    }
    creep = dist(ga2d_body_position(w, c.chassis), x0);
    CHECK(creep <= creep_bound);
    CHECK(worst_speed <= speed_bound);
    for (i = 0; i < 2; ++i) {
        CHECK_RESULT(ga2d_wheel_joint_set_motor_speed(w, c.j[i], -10), GA2D_OK);
        CHECK_RESULT(ga2d_wheel_joint_set_max_motor_torque(w, c.j[i], (ga2d_real)Tmax), GA2D_OK);
    }
    x0 = ga2d_body_position(w, c.chassis);
    for (k = 0; k < 180; ++k) {
        double wc;
        if (k == 120) p0 = ga2d_body_position(w, c.wheel[0]);
        step(w);
        wc = (double)ga2d_body_angular_velocity(w, c.chassis);
        for (i = 0; i < 2; ++i) {
            double tq = fabs((double)ga2d_wheel_joint_motor_torque(w, c.j[i]));
            double wrel = (double)ga2d_body_angular_velocity(w, c.wheel[i]) - wc;
            if (tq > worst_torque) worst_torque = tq;
            if (fabs(wrel) < 5) {
                CHECK_NEAR(tq, Tmax, 2 * U * Tmax);
                ++capped;
                if (tq > at_cap) at_cap = tq;
            }
        }
        if (k >= 120) rolled += fabs((double)ga2d_body_angular_velocity(w, c.wheel[0])) * WHEEL_R * DT;
    }
    moved = ((double)ga2d_body_position(w, c.wheel[0]).x - (double)p0.x) * (double)dir.x +
            ((double)ga2d_body_position(w, c.wheel[0]).y - (double)p0.y) * (double)dir.y;
    climbed = ((double)ga2d_body_position(w, c.chassis).x - (double)x0.x) * (double)dir.x +
              ((double)ga2d_body_position(w, c.chassis).y - (double)x0.y) * (double)dir.y;
    CHECK(capped > 10);
    CHECK(worst_torque <= Tmax * (1 + 2 * U));
    CHECK(climbed > 0);
    CHECK_NEAR(moved / rolled, 1, 2 * GA2D_LINEAR_SLOP / WHEEL_R);
    if (verbose())
        printf("joint kinds: car parked on 15 deg: crept %.3g m in 8 s (<= %.3g), speed at most %.3g m/s (<= %.3g); driving "
               "up: %d wheel-steps at the cap (|torque| %.9g, max %.9g <= %.3g), climbed %.3f m in 3 s; last second: moved "
               "%.4f m, rolled %.4f m: |rel| %.3g <= %.3g\n", creep, creep_bound, worst_speed, speed_bound, capped, at_cap,
               worst_torque, Tmax, climbed, moved, rolled, fabs(moved / rolled - 1), 2 * GA2D_LINEAR_SLOP / WHEEL_R);
    ga2d_world_destroy(w);
}

/* ============================================================ momentum */
/* Two bodies joined by a joint of each kind, gravity off, thrown moving
   and spinning (the joint first takes out what it forbids: inner
   impulses).  Every joint's impulses are equal and opposite, so the
   momentum sum m v stays to rounding: a substep applies a joint's impulse
   up to 13 times (warm start, up to 6 rows in each of two passes) to
   each body, each rounded by u of the momentum scale p plus the impulse
   (at most p: |dP| <= 32 u p per substep, a margin over 26).  The angular
   momentum about the origin sum (c ^ m v + I w) moves only by the
   couple of impulses not acting at one point:
   - distance: along the line through both anchors: no couple;
   - prismatic, wheel: A's share acts at B's anchor (the lever d + ra),
     as B's does: no couple; their angular impulses are pure couples;
   - weld, motor joint (offset 0): the point impulse P acts at anchors s
     apart: |s ^ P| <= s |F| h per substep (s and F read each step, summed
     at twice the step's figures as test_joints.c does); their angular
     impulses are pure couples;
   plus rounding: 32 u per substep of the scale L = sum (|c| m |v| + I
   |w|) + (the anchors' levers and the bodies' distance) (p + |F| h). */
typedef struct momenta { double px, py, l, pscale, lscale; } momenta;
static momenta momenta_of(const ga2d_world *w, const ga2d_body_id *b)
{
    momenta m;
    int i;
    memset(&m, 0, sizeof m);
    for (i = 0; i < 2; ++i) {
        ga2d_mass md = ga2d_body_mass_data(w, b[i]);
        ga2d_vec v = ga2d_body_velocity(w, b[i]), c = ga2d_body_center(w, b[i]);
        double mass = (double)md.mass, in = (double)md.inertia, om = (double)ga2d_body_angular_velocity(w, b[i]);
        double vx = (double)v.x, vy = (double)v.y, cx = (double)c.x, cy = (double)c.y;
        m.px += mass * vx;
        m.py += mass * vy;
        m.l += mass * (cx * vy - cy * vx) + in * om;
        m.pscale += mass * hypot(vx, vy);
        m.lscale += hypot(cx, cy) * mass * hypot(vx, vy) + in * fabs(om);
    }
    return m;
}

static const char *const kind_name[GA2D_JOINT_TYPE_COUNT] = {"distance", "revolute", "prismatic", "weld", "wheel", "motor"};

/* The joint of `kind` between b[0] and b[1] for the momentum test: its
   anchors la, lb (out). */
static ga2d_joint_id join_two(ga2d_world *w, int kind, const ga2d_body_id *b, ga2d_vec *la, ga2d_vec *lb)
{
    ga2d_vec at = v2(0.05, 0.05);
    ga2d_joint_id j = ga2d_joint_id_null();
    ga2d_result r = GA2D_ERR_INVALID_ARGUMENT;
    *la = ga2d_body_local_point(w, b[0], at);
    *lb = ga2d_body_local_point(w, b[1], at);
    switch (kind) {
    case GA2D_JOINT_DISTANCE: {
        ga2d_distance_joint_def d;
        *la = v2(0.2, 0.1);
        *lb = v2(-0.1, 0.2);
        d = distance_def(b[0], b[1], *la, *lb, dist(world_point(w, b[0], *la), world_point(w, b[1], *lb)) + 0.1);
        r = ga2d_distance_joint_create_checked(w, &d, &j);
        break;
    }
    case GA2D_JOINT_WELD: {
        ga2d_weld_joint_def d = ga2d_default_weld_joint_def();
        d.body_a = b[0];
        d.body_b = b[1];
        d.local_anchor_a = *la;
        d.local_anchor_b = *lb;
        d.reference_angle = (ga2d_real)-0.6;
        d.angular_hertz = 2;
        d.angular_damping_ratio = (ga2d_real)0.3;
        r = ga2d_weld_joint_create_checked(w, &d, &j);
        break;
    }
    case GA2D_JOINT_MOTOR: {
        ga2d_motor_joint_def d = ga2d_default_motor_joint_def();
        d.body_a = b[0];
        d.body_b = b[1];
        d.local_anchor_a = *la;
        d.local_anchor_b = *lb;
        d.angular_offset = (ga2d_real)0.3;
        d.max_force = 5;
        d.max_torque = 2;
        r = ga2d_motor_joint_create_checked(w, &d, &j);
        break;
    }
    case GA2D_JOINT_PRISMATIC: {
        ga2d_prismatic_joint_def d = prismatic_def(b[0], b[1], 0.3);
        d.local_anchor_a = *la;
        d.local_anchor_b = *lb;
        d.enable_limit = 1;
        d.lower_translation = (ga2d_real)-0.2;
        d.upper_translation = (ga2d_real)0.2;
        d.enable_motor = 1;
        d.motor_speed = 1;
        d.max_motor_force = 2;
        d.enable_spring = 1;
        d.hertz = 3;
        d.damping_ratio = (ga2d_real)0.2;
        r = ga2d_prismatic_joint_create_checked(w, &d, &j);
        break;
    }
    case GA2D_JOINT_WHEEL: {
        ga2d_wheel_joint_def d = ga2d_default_wheel_joint_def();
        d.body_a = b[0];
        d.body_b = b[1];
        d.local_anchor_a = *la;
        d.local_anchor_b = *lb;
        d.hertz = 3;
        d.damping_ratio = (ga2d_real)0.5;
        d.enable_limit = 1;
        d.lower_translation = (ga2d_real)-0.1;
        d.upper_translation = (ga2d_real)0.1;
        d.enable_motor = 1;
        d.motor_speed = -2;
        d.max_motor_torque = 1;
        r = ga2d_wheel_joint_create_checked(w, &d, &j);
        break;
    }
    default: break;
    }
    CHECK_RESULT(r, GA2D_OK);
    return j;
}

static void momentum_each_kind(void)
{
    const int kinds[5] = {GA2D_JOINT_DISTANCE, GA2D_JOINT_WELD, GA2D_JOINT_MOTOR, GA2D_JOINT_PRISMATIC, GA2D_JOINT_WHEEL};
    int i, k;
    for (i = 0; i < 5; ++i) {
        ga2d_world *w = make_world(0, 0);
        ga2d_body_id b[2];
        ga2d_joint_id j;
        ga2d_vec la, lb;
        momenta m0, m;
        double pscale, lscale, lbound = 0, lround = 0, pround = 0, worst_p = 0, worst_l = 0;
        int couple = kinds[i] == GA2D_JOINT_WELD || kinds[i] == GA2D_JOINT_MOTOR;
        b[0] = box_body(w, -0.5, 0, 0.2, 0.5, 0.25, 1);
        b[1] = box_body(w, 0.6, 0.1, -0.4, 0.3, 0.3, 3);
        CHECK_RESULT(ga2d_body_set_velocity(w, b[0], v2(1, 0.5)), GA2D_OK);
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, b[0], 2), GA2D_OK);
        CHECK_RESULT(ga2d_body_set_velocity(w, b[1], v2(-0.3, 1)), GA2D_OK);
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, b[1], -3), GA2D_OK);
        j = join_two(w, kinds[i], b, &la, &lb);
        m0 = momenta_of(w, b);
        pscale = m0.pscale;
        lscale = m0.lscale;
        for (k = 1; k <= 180; ++k) {
            ga2d_vec pa, pb;
            double fl, lever;
            step(w);
            m = momenta_of(w, b);
            if (m.pscale > pscale) pscale = m.pscale;
            if (m.lscale > lscale) lscale = m.lscale;
            fl = len(ga2d_joint_reaction_force(w, j));
            pa = world_point(w, b[0], la);
            pb = world_point(w, b[1], lb);
            lever = dist(pa, ga2d_body_center(w, b[0])) + dist(pb, ga2d_body_center(w, b[1])) +
                    dist(ga2d_body_center(w, b[0]), ga2d_body_center(w, b[1]));
            if (couple) lbound += 2 * SUB * dist(pa, pb) * fl * H;
            lround += SUB * 32 * U * (lscale + lever * (pscale + fl * H));
            pround += SUB * 32 * U * (pscale + fl * H);
            CHECK_NEAR(m.px, m0.px, pround);
            CHECK_NEAR(m.py, m0.py, pround);
            CHECK_NEAR(m.l, m0.l, lbound + lround);
            if (hypot(m.px - m0.px, m.py - m0.py) > worst_p) worst_p = hypot(m.px - m0.px, m.py - m0.py);
            if (fabs(m.l - m0.l) > worst_l) worst_l = fabs(m.l - m0.l);
        }
        if (verbose())
            printf("joint kinds: momentum, %s joint, 3 s: |dP| %.3g <= %.3g (of %.3g), |dL| %.3g <= %.3g (couple %.3g + "
                   "rounding %.3g, of %.3g)\n", kind_name[kinds[i]], worst_p, pround, pscale, worst_l, lbound + lround, lbound,
                   lround, lscale);
        ga2d_world_destroy(w);
    }
}

/* ============================================================== errors */
/* Each kind's create refuses its own bad numbers with the documented
   result (the header's comments: INVALID_ARGUMENT for a length not > 0,
   a negative min_length, min above max, a negative hertz, damping ratio,
   max force or torque, an axis of length 0, a correction factor outside
   [0, 1], lower above upper with the limit on; NOT_FINITE for any NaN or
   infinity; TOO_LARGE for an offset beyond GA2D_MAX_COORDINATE; and the
   shared checks: a body with itself or two static bodies
   INVALID_ARGUMENT), the null id from both forms, and the world's
   snapshot bytes unchanged. */
static void create_errors(void)
{
    ga2d_world *w = make_world(0, -G);
    ga2d_body_id s1 = pivot_body(w, 0, 0, 0), s2 = pivot_body(w, 3, 0, 0), dyn = box_body(w, 1, 0, 0, 0.5, 0.1, 1);
    ga2d_distance_joint_def dd0 = distance_def(s1, dyn, v2(0, 0), v2(0, 0), 1), dd;
    ga2d_weld_joint_def wd0 = ga2d_default_weld_joint_def(), wd;
    ga2d_motor_joint_def md0 = ga2d_default_motor_joint_def(), md;
    ga2d_prismatic_joint_def pd0 = prismatic_def(s1, dyn, 0.3), pd;
    ga2d_wheel_joint_def hd0 = ga2d_default_wheel_joint_def(), hd;
    const ga2d_real bad[2] = {(ga2d_real)NAN, (ga2d_real)-INFINITY};
    ga2d_joint_id out;
    unsigned char *ref;
    size_t n;
    int i, refused = 0;
    wd0.body_a = md0.body_a = hd0.body_a = s1;
    wd0.body_b = md0.body_b = hd0.body_b = dyn;
    steps(w, 2);
    ref = snapshot(w, &n);
#define REFUSED(kind, def0, def, change, expected)                                              \
    do {                                                                                        \
        def = def0;                                                                             \
        change;                                                                                 \
        out.index1 = 77;                                                                        \
        CHECK_RESULT(ga2d_##kind##_joint_create_checked(w, &def, &out), expected);              \
        CHECK(ga2d_joint_id_is_null(out));                                                      \
        CHECK(ga2d_joint_id_is_null(ga2d_##kind##_joint_create(w, &def)));                      \
        CHECK(same_snapshot(w, ref, n));                                                        \
        ++refused;                                                                              \
    } while (0)
#define D(change, expected) REFUSED(distance, dd0, dd, change, expected)
#define W(change, expected) REFUSED(weld, wd0, wd, change, expected)
#define M(change, expected) REFUSED(motor, md0, md, change, expected)
#define P(change, expected) REFUSED(prismatic, pd0, pd, change, expected)
#define WH(change, expected) REFUSED(wheel, hd0, hd, change, expected)
    /* the shared checks, through each kind */
    D(dd.body_b = s1, GA2D_ERR_INVALID_ARGUMENT);
    W(wd.body_a = dyn, GA2D_ERR_INVALID_ARGUMENT);
    M(md.body_b = s2, GA2D_ERR_INVALID_ARGUMENT);
    P(pd.body_a = ga2d_body_id_null(), GA2D_ERR_STALE_ID);
    WH(hd.local_anchor_b.x = bad[0], GA2D_ERR_NOT_FINITE);
    /* distance */
    D(dd.length = 0, GA2D_ERR_INVALID_ARGUMENT);
    D(dd.length = -1, GA2D_ERR_INVALID_ARGUMENT);
    D((dd.min_length = 2, dd.max_length = 1), GA2D_ERR_INVALID_ARGUMENT);
    D((dd.enable_limit = 1, dd.min_length = 2, dd.max_length = 1), GA2D_ERR_INVALID_ARGUMENT);
    D(dd.min_length = (ga2d_real)-0.1, GA2D_ERR_INVALID_ARGUMENT);
    D(dd.hertz = -1, GA2D_ERR_INVALID_ARGUMENT);
    D(dd.damping_ratio = -1, GA2D_ERR_INVALID_ARGUMENT);
    D(dd.max_motor_force = -1, GA2D_ERR_INVALID_ARGUMENT);
    /* weld */
    W(wd.linear_hertz = -1, GA2D_ERR_INVALID_ARGUMENT);
    W(wd.angular_hertz = -1, GA2D_ERR_INVALID_ARGUMENT);
    W(wd.linear_damping_ratio = -1, GA2D_ERR_INVALID_ARGUMENT);
    W(wd.angular_damping_ratio = -1, GA2D_ERR_INVALID_ARGUMENT);
    /* motor joint */
    M(md.correction_factor = (ga2d_real)-0.01, GA2D_ERR_INVALID_ARGUMENT);
    M(md.correction_factor = (ga2d_real)1.01, GA2D_ERR_INVALID_ARGUMENT);
    M(md.max_force = -1, GA2D_ERR_INVALID_ARGUMENT);
    M(md.max_torque = -1, GA2D_ERR_INVALID_ARGUMENT);
    M(md.linear_offset.y = (ga2d_real)(2 * (double)GA2D_MAX_COORDINATE), GA2D_ERR_TOO_LARGE);
    /* prismatic */
    P(pd.local_axis_a = v2(0, 0), GA2D_ERR_INVALID_ARGUMENT);
    P((pd.enable_limit = 1, pd.lower_translation = 1, pd.upper_translation = 0), GA2D_ERR_INVALID_ARGUMENT);
    P(pd.max_motor_force = -1, GA2D_ERR_INVALID_ARGUMENT);
    P(pd.hertz = -1, GA2D_ERR_INVALID_ARGUMENT);
    P(pd.damping_ratio = -1, GA2D_ERR_INVALID_ARGUMENT);
    /* wheel */
    WH(hd.local_axis_a = v2(0, 0), GA2D_ERR_INVALID_ARGUMENT);
    WH((hd.enable_limit = 1, hd.lower_translation = 1, hd.upper_translation = 0), GA2D_ERR_INVALID_ARGUMENT);
    WH(hd.max_motor_torque = -1, GA2D_ERR_INVALID_ARGUMENT);
    WH(hd.hertz = -1, GA2D_ERR_INVALID_ARGUMENT);
    WH(hd.damping_ratio = -1, GA2D_ERR_INVALID_ARGUMENT);
    for (i = 0; i < 2; ++i) {
        ga2d_real x = bad[i];
        D(dd.length = x, GA2D_ERR_NOT_FINITE);
        D(dd.min_length = x, GA2D_ERR_NOT_FINITE);
        D(dd.max_length = x, GA2D_ERR_NOT_FINITE);
        D(dd.hertz = x, GA2D_ERR_NOT_FINITE);
        D(dd.damping_ratio = x, GA2D_ERR_NOT_FINITE);
        D(dd.motor_speed = x, GA2D_ERR_NOT_FINITE);
        D(dd.max_motor_force = x, GA2D_ERR_NOT_FINITE);
        D(dd.local_anchor_a.y = x, GA2D_ERR_NOT_FINITE);
        W(wd.reference_angle = x, GA2D_ERR_NOT_FINITE);
        W(wd.linear_hertz = x, GA2D_ERR_NOT_FINITE);
        W(wd.angular_hertz = x, GA2D_ERR_NOT_FINITE);
        W(wd.linear_damping_ratio = x, GA2D_ERR_NOT_FINITE);
        W(wd.angular_damping_ratio = x, GA2D_ERR_NOT_FINITE);
        M(md.linear_offset.x = x, GA2D_ERR_NOT_FINITE);
        M(md.angular_offset = x, GA2D_ERR_NOT_FINITE);
        M(md.max_force = x, GA2D_ERR_NOT_FINITE);
        M(md.max_torque = x, GA2D_ERR_NOT_FINITE);
        M(md.correction_factor = x, GA2D_ERR_NOT_FINITE);
        P(pd.local_axis_a.x = x, GA2D_ERR_NOT_FINITE);
        P(pd.reference_angle = x, GA2D_ERR_NOT_FINITE);
        P(pd.lower_translation = x, GA2D_ERR_NOT_FINITE);
        P(pd.upper_translation = x, GA2D_ERR_NOT_FINITE);
        P(pd.motor_speed = x, GA2D_ERR_NOT_FINITE);
        P(pd.max_motor_force = x, GA2D_ERR_NOT_FINITE);
        P(pd.hertz = x, GA2D_ERR_NOT_FINITE);
        P(pd.damping_ratio = x, GA2D_ERR_NOT_FINITE);
        WH(hd.local_axis_a.y = x, GA2D_ERR_NOT_FINITE);
        WH(hd.lower_translation = x, GA2D_ERR_NOT_FINITE);
        WH(hd.upper_translation = x, GA2D_ERR_NOT_FINITE);
        WH(hd.motor_speed = x, GA2D_ERR_NOT_FINITE);
        WH(hd.max_motor_torque = x, GA2D_ERR_NOT_FINITE);
        WH(hd.hertz = x, GA2D_ERR_NOT_FINITE);
        WH(hd.damping_ratio = x, GA2D_ERR_NOT_FINITE);
    }
#undef D
#undef W
#undef M
#undef P
#undef WH
#undef REFUSED
    CHECK_RESULT(ga2d_distance_joint_create_checked(w, NULL, &out), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_weld_joint_create_checked(w, &wd0, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_motor_joint_create_checked(NULL, &md0, &out), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(same_snapshot(w, ref, n));
    CHECK(ga2d_world_get_counters(w).joint_count == 0);
    /* the defs as given are good: each is made */
    CHECK_RESULT(ga2d_distance_joint_create_checked(w, &dd0, &out), GA2D_OK);
    CHECK_RESULT(ga2d_weld_joint_create_checked(w, &wd0, &out), GA2D_OK);
    CHECK_RESULT(ga2d_motor_joint_create_checked(w, &md0, &out), GA2D_OK);
    CHECK_RESULT(ga2d_prismatic_joint_create_checked(w, &pd0, &out), GA2D_OK);
    CHECK_RESULT(ga2d_wheel_joint_create_checked(w, &hd0, &out), GA2D_OK);
    CHECK(ga2d_world_get_counters(w).joint_count == 5);
    if (verbose()) printf("joint kinds: %d bad defs refused, the world untouched\n", refused);
    free(ref);
    ga2d_world_destroy(w);
}

/* Every setter of every kind, called with a value its own kind takes:
   on a joint of another kind INVALID_ARGUMENT, on a stale id STALE_ID,
   on its own kind OK; each refused call leaves the snapshot bytes. */
#define SETTERS 35
static ga2d_result call_setter(ga2d_world *w, ga2d_joint_id j, int s, int *kind)
{
    static const int kinds[SETTERS] = {
        GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE,
        GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE,
        GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE,
        GA2D_JOINT_WELD,     GA2D_JOINT_WELD,     GA2D_JOINT_MOTOR,    GA2D_JOINT_MOTOR,    GA2D_JOINT_MOTOR,
        GA2D_JOINT_MOTOR,    GA2D_JOINT_PRISMATIC, GA2D_JOINT_PRISMATIC, GA2D_JOINT_PRISMATIC, GA2D_JOINT_PRISMATIC,
        GA2D_JOINT_PRISMATIC, GA2D_JOINT_PRISMATIC, GA2D_JOINT_PRISMATIC, GA2D_JOINT_WHEEL, GA2D_JOINT_WHEEL,
        GA2D_JOINT_WHEEL,    GA2D_JOINT_WHEEL,    GA2D_JOINT_WHEEL,    GA2D_JOINT_WHEEL,    GA2D_JOINT_WHEEL};
    *kind = kinds[s];
    switch (s) {
    case 0: return ga2d_revolute_joint_enable_motor(w, j, 1);
    case 1: return ga2d_revolute_joint_set_motor_speed(w, j, 1);
    case 2: return ga2d_revolute_joint_set_max_motor_torque(w, j, 1);
    case 3: return ga2d_revolute_joint_enable_limit(w, j, 0);
    case 4: return ga2d_revolute_joint_set_limits(w, j, -1, 1);
    case 5: return ga2d_revolute_joint_enable_spring(w, j, 0);
    case 6: return ga2d_revolute_joint_set_spring(w, j, 1, 1);
    case 7: return ga2d_distance_joint_set_length(w, j, 1);
    case 8: return ga2d_distance_joint_enable_limit(w, j, 0);
    case 9: return ga2d_distance_joint_set_length_range(w, j, 0, 2);
    case 10: return ga2d_distance_joint_enable_spring(w, j, 0);
    case 11: return ga2d_distance_joint_set_spring(w, j, 1, 1);
    case 12: return ga2d_distance_joint_enable_motor(w, j, 0);
    case 13: return ga2d_distance_joint_set_motor_speed(w, j, 1);
    case 14: return ga2d_distance_joint_set_max_motor_force(w, j, 1);
    case 15: return ga2d_weld_joint_set_linear_spring(w, j, 0, 0);
    case 16: return ga2d_weld_joint_set_angular_spring(w, j, 0, 0);
    case 17: return ga2d_motor_joint_set_linear_offset(w, j, v2(0, 0));
    case 18: return ga2d_motor_joint_set_angular_offset(w, j, 0);
    case 19: return ga2d_motor_joint_set_max_force(w, j, 1);
    case 20: return ga2d_motor_joint_set_max_torque(w, j, 1);
    case 21: return ga2d_prismatic_joint_enable_limit(w, j, 0);
    case 22: return ga2d_prismatic_joint_set_limits(w, j, -1, 1);
    case 23: return ga2d_prismatic_joint_enable_motor(w, j, 0);
    case 24: return ga2d_prismatic_joint_set_motor_speed(w, j, 1);
    case 25: return ga2d_prismatic_joint_set_max_motor_force(w, j, 1);
    case 26: return ga2d_prismatic_joint_enable_spring(w, j, 0);
    case 27: return ga2d_prismatic_joint_set_spring(w, j, 1, 1);
    case 28: return ga2d_wheel_joint_enable_spring(w, j, 1);
    case 29: return ga2d_wheel_joint_set_spring(w, j, 1, 1);
    case 30: return ga2d_wheel_joint_enable_limit(w, j, 0);
    case 31: return ga2d_wheel_joint_set_limits(w, j, -1, 1);
    case 32: return ga2d_wheel_joint_enable_motor(w, j, 0);
    case 33: return ga2d_wheel_joint_set_motor_speed(w, j, 1);
    default: return ga2d_wheel_joint_set_max_motor_torque(w, j, 1);
    }
}

/* One joint of each kind between s (static) and a dynamic box, in
   GA2D_JOINT_* order (the momentum test's defs, and a default revolute). */
static void one_of_each(ga2d_world *w, ga2d_body_id s, ga2d_body_id *dyn, ga2d_joint_id *j)
{
    int kind;
    for (kind = 0; kind < GA2D_JOINT_TYPE_COUNT; ++kind) {
        ga2d_body_id b[2];
        ga2d_vec la, lb;
        b[0] = s;
        b[1] = dyn[kind];
        if (kind == GA2D_JOINT_REVOLUTE) {
            ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
            d.body_a = s;
            d.body_b = dyn[kind];
            CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j[kind]), GA2D_OK);
        } else {
            j[kind] = join_two(w, kind, b, &la, &lb);
        }
        CHECK(ga2d_joint_get_type(w, j[kind]) == (ga2d_joint_type)kind);
    }
}

static void setter_errors(void)
{
    ga2d_world *w = make_world(0, -G);
    ga2d_body_id s = pivot_body(w, 0, 0, 0), dyn[GA2D_JOINT_TYPE_COUNT];
    ga2d_joint_id j[GA2D_JOINT_TYPE_COUNT], stale;
    unsigned char *ref;
    size_t n;
    int kind, sidx, wrong_kind = 0, own = 0;
    for (kind = 0; kind < GA2D_JOINT_TYPE_COUNT; ++kind) dyn[kind] = box_body(w, 2.0 * kind, -1, 0, 0.3, 0.2, 1);
    one_of_each(w, s, dyn, j);
    stale = j[GA2D_JOINT_WELD];
    CHECK_RESULT(ga2d_joint_destroy(w, stale), GA2D_OK);
    steps(w, 3);
    ref = snapshot(w, &n);
    for (sidx = 0; sidx < SETTERS; ++sidx) {
        int sk;
        CHECK_RESULT(call_setter(w, stale, sidx, &sk), GA2D_ERR_STALE_ID);
        for (kind = 0; kind < GA2D_JOINT_TYPE_COUNT; ++kind) {
            if (kind == GA2D_JOINT_WELD) continue; /* destroyed: its slot is stale */
            (void)call_setter(NULL, j[kind], sidx, &sk); /* its kind only */
            if (sk == kind) continue;
            CHECK_RESULT(call_setter(w, j[kind], sidx, &sk), GA2D_ERR_INVALID_ARGUMENT);
            ++wrong_kind;
        }
    }
    CHECK(same_snapshot(w, ref, n));
    /* the other kinds' getters read 0 on a joint not theirs */
    CHECK(ga2d_distance_joint_current_length(w, j[GA2D_JOINT_PRISMATIC]) == 0);
    CHECK(ga2d_prismatic_joint_translation(w, j[GA2D_JOINT_WHEEL]) == 0);
    CHECK(ga2d_prismatic_joint_speed(w, j[GA2D_JOINT_DISTANCE]) == 0);
    CHECK(ga2d_wheel_joint_translation(w, j[GA2D_JOINT_PRISMATIC]) == 0);
    CHECK(ga2d_wheel_joint_motor_torque(w, j[GA2D_JOINT_REVOLUTE]) == 0);
    CHECK(ga2d_revolute_joint_angle(w, j[GA2D_JOINT_MOTOR]) == 0);
    free(ref);
    /* each setter on its own kind: OK */
    for (sidx = 0; sidx < SETTERS; ++sidx) {
        int sk;
        ga2d_joint_id target;
        (void)call_setter(NULL, stale, sidx, &sk);
        if (sk == GA2D_JOINT_WELD) {
            ga2d_weld_joint_def d = ga2d_default_weld_joint_def();
            d.body_a = s;
            d.body_b = dyn[GA2D_JOINT_WELD];
            CHECK_RESULT(ga2d_weld_joint_create_checked(w, &d, &j[GA2D_JOINT_WELD]), GA2D_OK);
        }
        target = j[sk];
        CHECK_RESULT(call_setter(w, target, sidx, &sk), GA2D_OK);
        ++own;
    }
    /* values the kinds refuse through their setters (the world unchanged) */
    ref = snapshot(w, &n);
    CHECK_RESULT(ga2d_distance_joint_set_length(w, j[GA2D_JOINT_DISTANCE], 0), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_distance_joint_set_length(w, j[GA2D_JOINT_DISTANCE], (ga2d_real)NAN), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_distance_joint_set_length_range(w, j[GA2D_JOINT_DISTANCE], 2, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_distance_joint_set_length_range(w, j[GA2D_JOINT_DISTANCE], -1, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_distance_joint_set_length_range(w, j[GA2D_JOINT_DISTANCE], 0, (ga2d_real)INFINITY), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_distance_joint_set_spring(w, j[GA2D_JOINT_DISTANCE], -1, 0), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_distance_joint_set_max_motor_force(w, j[GA2D_JOINT_DISTANCE], -1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_distance_joint_set_motor_speed(w, j[GA2D_JOINT_DISTANCE], (ga2d_real)NAN), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_weld_joint_set_linear_spring(w, j[GA2D_JOINT_WELD], 1, -1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_weld_joint_set_angular_spring(w, j[GA2D_JOINT_WELD], (ga2d_real)INFINITY, 0), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_motor_joint_set_linear_offset(w, j[GA2D_JOINT_MOTOR], v2(0, (double)NAN)), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_motor_joint_set_linear_offset(w, j[GA2D_JOINT_MOTOR], v2(2 * (double)GA2D_MAX_COORDINATE, 0)),
                 GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(ga2d_motor_joint_set_angular_offset(w, j[GA2D_JOINT_MOTOR], (ga2d_real)NAN), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_motor_joint_set_max_force(w, j[GA2D_JOINT_MOTOR], -1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_motor_joint_set_max_torque(w, j[GA2D_JOINT_MOTOR], (ga2d_real)-INFINITY), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_prismatic_joint_set_limits(w, j[GA2D_JOINT_PRISMATIC], 1, 0), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_prismatic_joint_set_max_motor_force(w, j[GA2D_JOINT_PRISMATIC], -1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_prismatic_joint_set_spring(w, j[GA2D_JOINT_PRISMATIC], 1, (ga2d_real)NAN), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_wheel_joint_set_limits(w, j[GA2D_JOINT_WHEEL], 1, 0), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_wheel_joint_set_max_motor_torque(w, j[GA2D_JOINT_WHEEL], -1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_wheel_joint_set_spring(w, j[GA2D_JOINT_WHEEL], -1, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_wheel_joint_set_motor_speed(w, j[GA2D_JOINT_WHEEL], (ga2d_real)INFINITY), GA2D_ERR_NOT_FINITE);
    CHECK(same_snapshot(w, ref, n));
    if (verbose())
        printf("joint kinds: %d setters: %d calls on joints of other kinds refused, %d on a stale id, %d on their own kind OK\n",
               SETTERS, wrong_kind, SETTERS, own);
    free(ref);
    ga2d_world_destroy(w);
}

/* ============================================================ snapshot */
/* A world with one joint of each kind (the momentum test's defs, from a
   static body to six boxes), gravity on, 30 steps into the motion: saved,
   loaded into a fresh world; both step 120 times bit for bit alike (the
   bodies, and every joint's reaction force and torque), and their
   snapshots end alike. */
static void snapshot_each_kind(void)
{
    ga2d_world *w = make_world(0, -G), *w2 = make_world(0, -G);
    ga2d_body_id s = pivot_body(w, 0, 0, 0), dyn[GA2D_JOINT_TYPE_COUNT];
    ga2d_joint_id j[GA2D_JOINT_TYPE_COUNT];
    unsigned char *buf;
    size_t n;
    int kind, k, same = 1;
    for (kind = 0; kind < GA2D_JOINT_TYPE_COUNT; ++kind) {
        dyn[kind] = box_body(w, 0.4 * kind - 1, -0.5 - 0.2 * kind, 0.3 * kind, 0.3, 0.2, 1);
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, dyn[kind], (ga2d_real)(kind - 2)), GA2D_OK);
    }
    one_of_each(w, s, dyn, j);
    steps(w, 30);
    buf = snapshot(w, &n);
    if (!buf) return;
    CHECK_RESULT(ga2d_world_snapshot_load(w2, buf, n), GA2D_OK);
    CHECK(ga2d_world_get_counters(w2).joint_count == GA2D_JOINT_TYPE_COUNT);
    for (k = 0; k < 120; ++k) {
        step(w);
        step(w2);
        for (kind = 0; kind < GA2D_JOINT_TYPE_COUNT; ++kind) {
            body_bits a = bits_of(w, dyn[kind]), b = bits_of(w2, dyn[kind]);
            ga2d_vec fa = ga2d_joint_reaction_force(w, j[kind]), fb = ga2d_joint_reaction_force(w2, j[kind]);
            ga2d_real ta = ga2d_joint_reaction_torque(w, j[kind]), tb = ga2d_joint_reaction_torque(w2, j[kind]);
            if (memcmp(&a, &b, sizeof a) != 0 || memcmp(&fa, &fb, sizeof fa) != 0 || memcmp(&ta, &tb, sizeof ta) != 0) same = 0;
        }
    }
    CHECK(same);
    {
        unsigned char *s1 = snapshot(w, &n);
        CHECK(same_snapshot(w2, s1, n));
        free(s1);
    }
    for (kind = 0; kind < GA2D_JOINT_TYPE_COUNT; ++kind) CHECK(ga2d_joint_get_type(w2, j[kind]) == (ga2d_joint_type)kind);
    free(buf);
    ga2d_world_destroy(w);
    ga2d_world_destroy(w2);
}

void suite_joints_kinds(void)
{
    test_run("joints (kinds): distance rod pendulum", distance_rod_pendulum);
    test_run("joints (kinds): distance spring period", distance_spring_period);
    test_run("joints (kinds): distance spring, damping ratio 1", distance_spring_critical);
    test_run("joints (kinds): distance rope", distance_rope);
    test_run("joints (kinds): distance motor", distance_motor);
    test_run("joints (kinds): weld cantilever of 5", weld_cantilever);
    test_run("joints (kinds): soft weld", weld_soft);
    test_run("joints (kinds): motor joint holds a pose", motor_joint_holds);
    test_run("joints (kinds): motor joint too weak", motor_joint_too_weak);
    test_run("joints (kinds): prismatic slide", prismatic_slide);
    test_run("joints (kinds): prismatic limits", prismatic_limits);
    test_run("joints (kinds): prismatic motor", prismatic_motor);
    test_run("joints (kinds): prismatic spring", prismatic_spring);
    test_run("joints (kinds): wheel suspension", wheel_suspension);
    test_run("joints (kinds): car on a slope", wheel_car_on_slope);
    test_run("joints (kinds): momentum of each kind", momentum_each_kind);
    test_run("joints (kinds): create errors", create_errors);
    test_run("joints (kinds): setter errors", setter_errors);
    test_run("joints (kinds): snapshot with each kind", snapshot_each_kind);
}
