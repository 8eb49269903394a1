/* Motion under forces against analytic answers: projectile, torque-free
   spin, harmonic oscillator, central-force orbit, momentum, impulses,
   damping, and what each integrator costs in force evaluations.

   Rounding model used for the tolerances: a substep updates v and x with
   one multiply-add each, so each carries <= 2 eps of its magnitude.  Over
   N substeps the velocity errors add up to <= 2 N eps Vmax and, integrated
   over the run time T, move x by <= 2 N eps Vmax T; the position updates
   add <= 2 N eps Xmax.  So |x - x_exact| <= 2 N eps (Xmax + T Vmax), with
   the exact value taken from the discrete scheme itself where it differs
   from the continuous solution. */
#include "test.h"

#define PI 3.14159265358979323846

static ga2d_world *make_world(ga2d_integrator integ, ga2d_rotation_update rot, int substeps, double gy)
{
    ga2d_world_def d = ga2d_default_world_def();
    d.integrator = integ;
    d.rotation_update = rot;
    d.substeps = substeps;
    d.gravity = ga2d_vec_make(0, (ga2d_real)gy);
    return ga2d_world_create(&d);
}

static ga2d_body_id add_box(ga2d_world *w, double x, double y, double vx, double vy, double omega, double half)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.velocity = ga2d_vec_make((ga2d_real)vx, (ga2d_real)vy);
    d.angular_velocity = (ga2d_real)omega;
    d.polygon = ga2d_polygon_box((ga2d_real)half, (ga2d_real)half);
    return ga2d_body_create(w, &d);
}

/* The angle between two rotors, wrapped to (-pi, pi]: angle(a b~). */
static double rotor_diff(ga2d_rotor a, ga2d_rotor b)
{
    return (double)ga2d_rotor_angle(ga2d_rotor_mul(a, ga2d_rotor_inverse(b)));
}

static ga2d_rotor rotor_of(double angle) { return ga2d_rotor_from_angle((ga2d_real)fmod(angle, 2 * PI)); }

/* ------------------------------------------------------------- projectile */
/* Under constant gravity g, velocity Verlet and RK4 are exact:
   y = y0 + vy t - g t^2 / 2.  Symplectic Euler (v first, then x) gives
   y_n = y0 + h sum_{k=1..n} (vy - g k h) = y0 + vy t - g t^2/2 - g h t/2:
   its error is exactly the first-order term g h t / 2 (h the substep). */
static void projectile(void)
{
    const double g = 9.8, x0 = -1, y0 = 2, vx = 3, vy = 12, T = 2, dt = 1.0 / 60;
    const int substeps = 4, steps = (int)(T / dt + 0.5), N = steps * substeps;
    const double h = dt / substeps;
    int integ;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ) {
        ga2d_world *w = make_world((ga2d_integrator)integ, GA2D_ROTATION_EXACT, substeps, -g);
        ga2d_body_id b = add_box(w, x0, y0, vx, vy, 0, 0.5);
        double xmax = 0, vmax = 0, tol;
        int s;
        for (s = 1; s <= steps; ++s) {
            double t = s * dt, ex = x0 + vx * t, ey = y0 + vy * t - g * t * t / 2;
            ga2d_vec c;
            CHECK_RESULT(ga2d_world_step(w, (ga2d_real)dt), GA2D_OK);
            c = ga2d_body_center(w, b);
            if (integ == GA2D_INTEGRATOR_SYMPLECTIC_EULER) ey -= g * h * t / 2;
            xmax = fmax(xmax, fmax(fabs(ex), fabs(ey)));
            vmax = fmax(vmax, hypot(vx, vy - g * t));
            /* the model's bound, with the run so far (N_s substeps, time t) */
            tol = 2 * s * substeps * REAL_EPS * (xmax + t * vmax) + 4 * REAL_EPS * xmax;
            CHECK_NEAR(c.x, ex, tol);
            CHECK_NEAR(c.y, ey, tol);
        }
        /* the symplectic Euler term is far above rounding, so the check
           above really tells the two schemes apart */
        CHECK(g * h * T / 2 > 10 * 2 * N * REAL_EPS * (xmax + T * vmax));
        /* world time sums the dt it was given (rounded to ga2d_real) in
           double: exact for these few steps */
        CHECK_NEAR(ga2d_world_time(w), steps * (double)(ga2d_real)dt, 1e-12);
        ga2d_world_destroy(w);
    }
}

/* ------------------------------------------------------ torque-free spin */
/* With no torque, w is constant.  The exact update turns by w h each
   substep: theta = theta0 + w t.  The first-order update turns by
   atan(w h) (normalize(1 + w h e12) = exp(atan(w h) e12)):
   theta = theta0 + N atan(w h), which lags by N (w h - atan(w h)).  Per
   substep the rotor product and the series each add <= 2 eps of angle
   (|q| = 1), so the angle is within 4 N eps plus N eps |w h| for the
   rounding of w h itself. */
static void torque_free_spin(void)
{
    const double omega = 7.5, theta0 = 0.3, dt = 1.0 / 60;
    const int substeps = 4, steps = 2500, N = steps * substeps;
    const double h = dt / substeps;
    int rot, integ;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ)
        for (rot = 0; rot < GA2D_ROTATION_COUNT; ++rot) {
            ga2d_world *w = make_world((ga2d_integrator)integ, (ga2d_rotation_update)rot, substeps, 0);
            ga2d_body_def d = ga2d_default_body_def();
            ga2d_body_id b;
            double expect, tol = 4 * N * REAL_EPS + N * REAL_EPS * omega * h;
            int s;
            d.type = GA2D_BODY_DYNAMIC;
            d.rotor = ga2d_rotor_from_angle((ga2d_real)theta0);
            d.angular_velocity = (ga2d_real)omega;
            d.polygon = ga2d_polygon_box(2, 0.25);
            b = ga2d_body_create(w, &d);
            for (s = 0; s < steps; ++s) ga2d_world_step(w, (ga2d_real)dt);
            expect = rot == GA2D_ROTATION_EXACT ? theta0 + omega * N * h : theta0 + N * atan(omega * h);
            CHECK_NEAR(rotor_diff(ga2d_body_rotor(w, b), rotor_of(expect)), 0, tol);
            /* w itself never changes: no torque, no damping */
            CHECK(ga2d_body_angular_velocity(w, b) == (ga2d_real)omega);
            /* the lag of the linear update is far above the tolerance */
            if (rot == GA2D_ROTATION_LINEAR) CHECK(N * (omega * h - atan(omega * h)) > 10 * tol);
            ga2d_world_destroy(w);
        }
}

/* One substep may turn a body by any angle: the exact update reduces it
   by quarter turns before its series, so turns of 0.3 rad to 10^3 rad
   (every quadrant, both signs) must come out right.  From the identity,
   one turn: the reduction subtracts k pi/2 in two parts (error <= k eps),
   then the series and product add 2 eps: tolerance (4 + |a|) eps. */
static void large_turn_per_substep(void)
{
    const double turns[] = {0.3, -0.75, 0.79, 1.6, -2.5, 3.1, -3.3, 4.0, 7.0, -12.5, 1000.0};
    size_t i;
    for (i = 0; i < sizeof turns / sizeof turns[0]; ++i) {
        /* a kinematic body: dynamic ones are capped at a quarter pi per
           substep (tested below), kinematic ones follow their velocity */
        ga2d_world *w = make_world(GA2D_INTEGRATOR_SYMPLECTIC_EULER, GA2D_ROTATION_EXACT, 1, 0);
        ga2d_body_def d = ga2d_default_body_def();
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        ga2d_body_id b;
        d.type = GA2D_BODY_KINEMATIC;
        d.angular_velocity = (ga2d_real)(turns[i] * 64); /* dt = 1/64: a turn of turns[i] */
        b = ga2d_body_create(w, &d);
        double a = (double)(ga2d_real)(turns[i] * 64) / 64;
        ga2d_world_step(w, (ga2d_real)(1.0 / 64));
        CHECK_NEAR(rotor_diff(ga2d_body_rotor(w, b), ga2d_rotor_from_angle((ga2d_real)fmod(a, 2 * PI))), 0, (4 + fabs(a)) * REAL_EPS);
        ga2d_world_destroy(w);
    }
    /* a dynamic body turns at most a quarter pi per substep (Box2D's cap:
       faster, a thin body would tunnel through its neighbours) */
    {
        ga2d_world *w = make_world(GA2D_INTEGRATOR_SYMPLECTIC_EULER, GA2D_ROTATION_EXACT, 1, 0);
        ga2d_body_id b = add_box(w, 0, 0, 0, 0, 1000, 0.5);
        ga2d_world_step(w, (ga2d_real)(1.0 / 64));
        CHECK_NEAR(ga2d_body_angular_velocity(w, b), PI / 4 * 64, 4 * REAL_EPS * 64 * PI);
        ga2d_world_destroy(w);
    }
}

/* |q| = 1 after 10^6 steps under both updates.  The exact update ends each
   turn with a Newton step toward |q| = 1 and the linear update with a
   division by |q|, so the norm never accumulates error: it stays within a
   few eps of 1 (4 eps = 4.8e-7 in float, inside the 1e-6 asked for). */
static void rotor_norm_long_run(void)
{
    int rot;
    for (rot = 0; rot < GA2D_ROTATION_COUNT; ++rot) {
        ga2d_world *w = make_world(GA2D_INTEGRATOR_SYMPLECTIC_EULER, (ga2d_rotation_update)rot, 1, 0);
        ga2d_body_id b = add_box(w, 0, 0, 0, 0, 3.7, 0.5);
        double worst = 0;
        int s;
        for (s = 0; s < 1000000; ++s) {
            ga2d_rotor q;
            ga2d_world_step(w, (ga2d_real)(1.0 / 60));
            q = ga2d_body_rotor(w, b);
            worst = fmax(worst, fabs(sqrt((double)q.c * (double)q.c + (double)q.s * (double)q.s) - 1));
        }
        CHECK(worst <= 4 * REAL_EPS);
        CHECK(worst <= 1e-6);
        ga2d_world_destroy(w);
    }
}

/* ----------------------------------------------------- harmonic oscillator */
typedef struct spring { ga2d_body_id body; double k; ga2d_vec anchor; int calls; } spring;

/* F = -k (c - anchor), at the centre of mass */
static void spring_force(ga2d_world *w, void *ctx)
{
    spring *sp = (spring *)ctx;
    ga2d_vec d = ga2d_vec_sub(ga2d_body_center(w, sp->body), sp->anchor);
    ga2d_body_apply_force_to_center(w, sp->body, ga2d_vec_scale(d, (ga2d_real)-sp->k));
    ++sp->calls;
}

/* One substep of each scheme for x'' = -w^2 x as a 2x2 matrix acting on
   (x, v), in long double:
     symplectic Euler  v' = v - h w^2 x;  x' = x + h v'
     velocity Verlet   v+ = v - h/2 w^2 x; x' = x + h v+; v' = v+ - h/2 w^2 x'
     RK4               M = I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24,
                       A = [[0, 1], [-w^2, 0]] */
typedef struct mat2 { long double a, b, c, d; } mat2; /* [[a b] [c d]] */

static mat2 mat_mul(mat2 p, mat2 q)
{
    mat2 r;
    r.a = p.a * q.a + p.b * q.c; r.b = p.a * q.b + p.b * q.d;
    r.c = p.c * q.a + p.d * q.c; r.d = p.c * q.b + p.d * q.d;
    return r;
}

static mat2 scheme_matrix(int integ, long double h, long double w2)
{
    mat2 m;
    if (integ == GA2D_INTEGRATOR_SYMPLECTIC_EULER) {
        m.a = 1 - h * h * w2; m.b = h; m.c = -h * w2; m.d = 1;
    } else if (integ == GA2D_INTEGRATOR_VERLET) {
        m.a = 1 - h * h * w2 / 2; m.b = h;
        m.c = -h * w2 * (1 - h * h * w2 / 4); m.d = 1 - h * h * w2 / 2;
    } else {
        mat2 A, P, I;
        long double f[5] = {1, 1, 0.5L, 1.0L / 6, 1.0L / 24};
        int k;
        A.a = 0; A.b = h; A.c = -h * w2; A.d = 0;
        I.a = 1; I.b = 0; I.c = 0; I.d = 1;
        m = I;
        P = I;
        for (k = 1; k <= 4; ++k) {
            P = mat_mul(P, A);
            m.a += f[k] * P.a; m.b += f[k] * P.b; m.c += f[k] * P.c; m.d += f[k] * P.d;
        }
    }
    return m;
}

/* Runs the oscillator (m = 1, w = 2 pi: a 1 s period) released from rest
   at x = 1 for `steps` steps of dt, recording x after every step. */
static void run_oscillator(int integ, int substeps, double dt, int steps, double *xs, double *vs)
{
    ga2d_world *w = make_world((ga2d_integrator)integ, GA2D_ROTATION_EXACT, substeps, 0);
    spring sp;
    ga2d_body_def d = ga2d_default_body_def();
    int s;
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(1, 0);
    d.polygon = ga2d_polygon_box(0.5, 0.5); /* m = 1 at density 1 */
    sp.body = ga2d_body_create(w, &d);
    sp.k = 4 * PI * PI;
    sp.anchor = ga2d_vec_make(0, 0);
    sp.calls = 0;
    ga2d_world_set_force_callback(w, spring_force, &sp);
    for (s = 0; s < steps; ++s) {
        ga2d_world_step(w, (ga2d_real)dt);
        xs[s] = (double)ga2d_body_center(w, sp.body).x;
        if (vs) vs[s] = (double)ga2d_body_velocity(w, sp.body).x;
    }
    ga2d_world_destroy(w);
}

/* Each integrator produces exactly its discrete scheme: x_n = (M^N y0).x.
   The maps preserve a norm close to the energy norm (w x, v), so rounding
   (2 eps per update of quantities <= w A, with A = 1) grows at most
   linearly: |x - x_n| <= 4 N eps A (1 + 1/w) ~ 5 N eps.  This pins each
   integrator to its scheme far more tightly than any physical bound. */
static void oscillator_follows_its_scheme(void)
{
    const double dt = 1.0 / 60, w2 = 4 * PI * PI;
    const int substeps = 4, steps = 600;
    static double xs[600];
    int integ, s;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ) {
        mat2 M = scheme_matrix(integ, (long double)dt / substeps, (long double)w2), step = M;
        long double x = 1, v = 0;
        int k;
        for (k = 1; k < substeps; ++k) step = mat_mul(step, M);
        run_oscillator(integ, substeps, dt, steps, xs, NULL);
        for (s = 0; s < steps; ++s) {
            long double nx = step.a * x + step.b * v, nv = step.c * x + step.d * v;
            x = nx;
            v = nv;
            CHECK_NEAR(xs[s], (double)x, 5.0 * (s + 1) * substeps * REAL_EPS);
        }
    }
}

/* Linear interpolation of the upward zero crossings; the period is the
   mean spacing.  Near a crossing x = A sin(w u) is linear up to a cubic
   term, so each crossing time is off by <= h (w h)^2 / 6. */
static double measured_period(const double *xs, int n, double dt, int *crossings)
{
    double first = -1, last = -1;
    int s, count = 0;
    for (s = 1; s < n; ++s)
        if (xs[s - 1] < 0 && xs[s] >= 0) {
            double t = dt * (s + xs[s - 1] / (xs[s - 1] - xs[s])); /* step s-1 is at time s*dt */
            if (count == 0) first = t;
            last = t;
            ++count;
        }
    *crossings = count;
    return count > 1 ? (last - first) / (count - 1) : 0;
}

/* Period within 0.1% at 60 Hz (one substep, h = 1/60, w h = 0.105).  The
   discrete period is known: symplectic Euler and Verlet both turn by
   2 asin(w h / 2) per step (trace of M = 2 - w^2 h^2), so T = 2 pi h /
   (2 asin(w h/2)), 0.046% short; RK4 is off by O((w h)^4).  The measured
   period must equal the discrete one within the interpolation error and
   the true one within 0.1%. */
static void oscillator_period(void)
{
    const double dt = 1.0 / 60, wh = 2 * PI * dt;
    static double xs[1200];
    int integ, crossings;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ) {
        double T;
        run_oscillator(integ, 1, dt, 1200, xs, NULL);
        T = measured_period(xs, 1200, dt, &crossings);
        CHECK(crossings >= 19);
        CHECK_NEAR(T, 1, 0.001);
        if (integ != GA2D_INTEGRATOR_RK4)
            CHECK_NEAR(T, PI * dt / asin(wh / 2), 2 * dt * wh * wh / 6 / (crossings - 1) + 1e-4 * REAL_EPS / 1.2e-7);
    }
}

/* Energy over 10^5 steps (h = 1/60, w h = 0.105), E = v^2/2 + w^2 x^2/2.
   Symplectic Euler keeps H~ = E - h w^2 x v / 2 exactly; since
   w |x v| <= E, |E - H~| <= (w h / 2) E and so |E_n - E_0| <=
   w h E_0 / (1 - w h / 2) at every n: bounded, whatever n.  Verlet keeps
   Q = v^2/2 + w^2 (1 - (w h)^2/4) x^2 / 2 (M has equal diagonal and det 1),
   so |E_n - E_0| <= (w h)^2/2 E_0 / (1 - (w h)^2/4).  Rounding adds at most
   4 N eps E_0 (linear growth, the worst case).  RK4 is not symplectic: its
   amplitude shrinks by |R(i w h)| = sqrt(1 - (wh)^6/72 + (wh)^8/576) per
   step, so E_N = E_0 |R|^(2N) -- shown at w h = 0.5 where the decay is
   far above rounding. */
static void oscillator_energy(void)
{
    const int N = 100000;
    const double dt = 1.0 / 60, w = 2 * PI, wh = w * dt;
    double *xs = (double *)malloc(sizeof(double) * N), *vs = (double *)malloc(sizeof(double) * N);
    int integ, s;
    if (!xs || !vs) { CHECK(!"out of memory"); free(xs); free(vs); return; }
    for (integ = 0; integ < 2; ++integ) {
        double bound = integ == GA2D_INTEGRATOR_SYMPLECTIC_EULER ? wh / (1 - wh / 2) : wh * wh / 2 / (1 - wh * wh / 4);
        double E0 = w * w / 2, first = 0, last = 0;
        run_oscillator(integ, 1, dt, N, xs, vs);
        for (s = 0; s < N; ++s) {
            double dE = fabs((vs[s] * vs[s] + w * w * xs[s] * xs[s]) / 2 - E0);
            if (s < 1000) first = fmax(first, dE);
            if (s >= N - 1000) last = fmax(last, dE);
        }
        CHECK(last <= (bound + 4 * N * REAL_EPS) * E0);
        CHECK(first <= (bound + 4 * 1000 * REAL_EPS) * E0);
    }
    {
        const double dt4 = 0.5 / w; /* w h = 0.5 */
        const int n4 = 10000;
        double r2 = 1 - pow(0.5, 6) / 72 + pow(0.5, 8) / 576, E0 = w * w / 2, E;
        run_oscillator(GA2D_INTEGRATOR_RK4, 1, dt4, n4, xs, vs);
        E = (vs[n4 - 1] * vs[n4 - 1] + w * w * xs[n4 - 1] * xs[n4 - 1]) / 2;
        CHECK_NEAR(E / E0, pow(r2, n4), 4 * n4 * REAL_EPS);
        CHECK(E / E0 < 0.5); /* a real, visible drift */
    }
    free(xs);
    free(vs);
}

/* RK4 is 4th order: halving h cuts the error at a fixed time ~16x.  The
   exact ratio for this problem follows from the scheme's matrix (error of
   M_h^N y0 against the true solution, divided by that at h/2); the
   measured ratio must be consistent with it given each error's rounding
   bound (5 N eps), and the predicted ratio itself lies in [12, 20] (16 up
   to O((w h)^2) terms).  h = 0.1 and 0.05 keep the truncation error above
   float rounding.  T = 10.3 s is off the peaks of x = cos(w t), where the
   4th-order phase error shows (at a peak only the 5th-order amplitude
   error would). */
static void rk4_fourth_order(void)
{
    const double T = 10.3, w = 2 * PI;
    static double xs[400];
    double err[2], pred[2], tol[2];
    int i;
    for (i = 0; i < 2; ++i) {
        double h = 0.1 / (1 << i);
        int n = (int)(T / h + 0.5), s;
        mat2 M = scheme_matrix(GA2D_INTEGRATOR_RK4, (long double)h, (long double)(w * w));
        long double x = 1, v = 0;
        run_oscillator(GA2D_INTEGRATOR_RK4, 1, h, n, xs, NULL);
        for (s = 0; s < n; ++s) {
            long double nx = M.a * x + M.b * v, nv = M.c * x + M.d * v;
            x = nx;
            v = nv;
        }
        err[i] = fabs(xs[n - 1] - cos(w * T));
        pred[i] = fabs((double)x - cos(w * T));
        tol[i] = 5.0 * n * REAL_EPS;
    }
    CHECK(pred[0] / pred[1] > 12 && pred[0] / pred[1] < 20);
    CHECK(err[1] > tol[1]); /* resolvable */
    CHECK((err[0] + tol[0]) / (err[1] - tol[1]) >= pred[0] / pred[1]);
    CHECK((err[0] - tol[0]) / (err[1] + tol[1]) <= pred[0] / pred[1]);
}

/* ------------------------------------------------------ central-force orbit */
typedef struct gravity_well { ga2d_body_id body; double gm; } gravity_well;

/* F = -GM m r / |r|^3 toward the origin */
static void central_force(ga2d_world *w, void *ctx)
{
    gravity_well *g = (gravity_well *)ctx;
    ga2d_vec r = ga2d_body_center(w, g->body);
    double d = (double)ga2d_vec_length(r), m = (double)ga2d_body_mass_data(w, g->body).mass;
    ga2d_body_apply_force_to_center(w, g->body, ga2d_vec_scale(r, (ga2d_real)(-g->gm * m / (d * d * d))));
}

/* A circular orbit of radius 10 and period 10 s (GM = w^2 R^3), started
   with a 10% speed excess so the orbit is eccentric.  Symplectic Euler and
   Verlet conserve L = r ^ p exactly: each kick adds a multiple of r to v
   (r ^ r = 0) and each drift a multiple of v to r (v ^ v = 0); only
   rounding changes it, <= 4 N eps |L|.  Their energy error stays bounded:
   the worst over the last orbit is no larger than over the first (plus
   rounding 4 N eps E, and the O(w h) change between orbits that comes of
   sampling a precessing orbit at other phases).  RK4's errors shrink as h^4 (checked in double:
   in float they sit below rounding at step sizes where h^4 holds). */
static void orbit_conservation(void)
{
    const double R = 10, w = 2 * PI / 10, gm = w * w * R * R * R;
    int integ;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ) {
        double dErk[2] = {0, 0};
        int pass;
        for (pass = 0; pass < (integ == GA2D_INTEGRATOR_RK4 ? 2 : 1); ++pass) {
            double dt = (integ == GA2D_INTEGRATOR_RK4 ? 0.2 : 1.0 / 60) / (1 << pass);
            int steps = (int)(50 / dt + 0.5), per_orbit = (int)(10 / dt + 0.5), s;
            ga2d_world *wd = make_world((ga2d_integrator)integ, GA2D_ROTATION_EXACT, 1, 0);
            gravity_well gw;
            double m, L0, E0, first = 0, last = 0, dL = 0;
            gw.body = add_box(wd, R, 0, 0, 1.1 * w * R, 0, 0.1);
            gw.gm = gm;
            ga2d_world_set_force_callback(wd, central_force, &gw);
            m = (double)ga2d_body_mass_data(wd, gw.body).mass;
            L0 = m * R * 1.1 * w * R;
            E0 = m * (1.21 * w * w * R * R / 2 - gm / R);
            for (s = 0; s < steps; ++s) {
                ga2d_vec r, v;
                double L, E;
                ga2d_world_step(wd, (ga2d_real)dt);
                r = ga2d_body_center(wd, gw.body);
                v = ga2d_body_velocity(wd, gw.body);
                L = m * ((double)r.x * (double)v.y - (double)r.y * (double)v.x);
                E = m * (((double)v.x * (double)v.x + (double)v.y * (double)v.y) / 2 - gm / hypot((double)r.x, (double)r.y));
                dL = fmax(dL, fabs(L - L0));
                if (s < per_orbit) first = fmax(first, fabs(E - E0));
                if (s >= steps - per_orbit) last = fmax(last, fabs(E - E0));
            }
            if (integ != GA2D_INTEGRATOR_RK4) {
                CHECK(dL <= 4 * steps * REAL_EPS * fabs(L0) * 4);
                /* the discrete orbit precesses, so the samples of the last
                   orbit fall at other phases than the first: an O(w h)
                   relative change of an O(h) deviation */
                CHECK(last <= first * (1 + w * dt) + 4 * steps * REAL_EPS * fabs(E0));
                CHECK(first < 0.05 * fabs(E0)); /* and it is small: O(h) */
            } else {
                dErk[pass] = fabs(last);
            }
            ga2d_world_destroy(wd);
        }
#ifdef GA2D_DOUBLE
        if (integ == GA2D_INTEGRATOR_RK4) CHECK(dErk[0] / dErk[1] > 10 && dErk[0] / dErk[1] < 40);
#else
        (void)dErk;
#endif
    }
}

/* ------------------------------------------------------------- momentum */
typedef struct pair_spring { ga2d_body_id a, b; double k, rest; } pair_spring;

/* A spring between two centres: equal and opposite forces (F_b = -F_a
   exactly, by negation). */
static void pair_spring_force(ga2d_world *w, void *ctx)
{
    pair_spring *p = (pair_spring *)ctx;
    ga2d_vec d = ga2d_vec_sub(ga2d_body_center(w, p->b), ga2d_body_center(w, p->a)), u;
    ga2d_real len = ga2d_vec_normalize(d, &u);
    ga2d_vec f = ga2d_vec_scale(u, (ga2d_real)(p->k * ((double)len - p->rest)));
    ga2d_body_apply_force_to_center(w, p->a, f);
    ga2d_body_apply_force_to_center(w, p->b, ga2d_vec_neg(f));
}

/* Internal forces leave total momentum unchanged; with gravity it grows by
   exactly (m_a + m_b) g t.  Each kick changes m v by m (h F / m), off from
   h F by 2 eps of it: over N substeps 4 N eps (|p| + h |F|max). */
static void internal_forces_keep_momentum(void)
{
    int integ;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ) {
        ga2d_world *w = make_world((ga2d_integrator)integ, GA2D_ROTATION_EXACT, 4, -10);
        ga2d_body_def d = ga2d_default_body_def();
        pair_spring ps;
        double ma, mb, p0x, p0y, pmax, T = 5, dt = 1.0 / 60;
        int s, steps = (int)(T / dt + 0.5);
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box(0.5, 0.5);
        d.velocity = ga2d_vec_make(1, 2);
        ps.a = ga2d_body_create(w, &d);
        d.position = ga2d_vec_make(3, 1);
        d.density = 3;
        d.velocity = ga2d_vec_make(-2, 0.5);
        d.angular_velocity = 1;
        ps.b = ga2d_body_create(w, &d);
        ps.k = 50;
        ps.rest = 2;
        ga2d_world_set_force_callback(w, pair_spring_force, &ps);
        ma = (double)ga2d_body_mass_data(w, ps.a).mass;
        mb = (double)ga2d_body_mass_data(w, ps.b).mass;
        p0x = ma * 1 + mb * -2;
        p0y = ma * 2 + mb * 0.5;
        pmax = 0;
        for (s = 1; s <= steps; ++s) {
            ga2d_vec va, vb;
            double px, py, tol;
            ga2d_world_step(w, (ga2d_real)dt);
            va = ga2d_body_velocity(w, ps.a);
            vb = ga2d_body_velocity(w, ps.b);
            px = ma * (double)va.x + mb * (double)vb.x;
            py = ma * (double)va.y + mb * (double)vb.y;
            pmax = fmax(pmax, fmax(ma * hypot((double)va.x, (double)va.y), mb * hypot((double)vb.x, (double)vb.y)));
            /* spring force <= k * stretch; stretch <= 10 m here */
            tol = 4.0 * s * 4 * REAL_EPS * (2 * pmax + dt * ps.k * 10);
            CHECK_NEAR(px, p0x, tol);
            CHECK_NEAR(py, p0y - (ma + mb) * 10 * s * dt, tol + 4 * REAL_EPS * (ma + mb) * 10 * T);
        }
        ga2d_world_destroy(w);
    }
}

/* ------------------------------------------------------------- impulses */
/* An impulse P at world point p: dv = P/m, dOmega = I^-1 (r ^ P) with
   r = p - c.  One multiply and one add each: 2 eps of the result. */
static void off_centre_impulse(void)
{
    ga2d_world *w = make_world(GA2D_INTEGRATOR_SYMPLECTIC_EULER, GA2D_ROTATION_EXACT, 4, -10);
    ga2d_body_id b = add_box(w, 1, 2, 0.5, -0.25, 0.75, 0.5);
    test_rng rng = {41};
    int i;
    for (i = 0; i < 200; ++i) {
        ga2d_vec P = ga2d_vec_make((ga2d_real)rng_uniform(&rng, -5, 5), (ga2d_real)rng_uniform(&rng, -5, 5));
        ga2d_vec p = ga2d_vec_make((ga2d_real)rng_uniform(&rng, -3, 3), (ga2d_real)rng_uniform(&rng, -3, 3));
        ga2d_vec v0 = ga2d_body_velocity(w, b), c = ga2d_body_center(w, b), v1;
        ga2d_real w0 = ga2d_body_angular_velocity(w, b), w1;
        ga2d_mass m = ga2d_body_mass_data(w, b);
        double r_wedge_P = (double)ga2d_wedge(ga2d_vec_sub(p, c), P);
        CHECK_RESULT(ga2d_body_apply_impulse(w, b, P, p), GA2D_OK);
        v1 = ga2d_body_velocity(w, b);
        w1 = ga2d_body_angular_velocity(w, b);
        CHECK_NEAR(v1.x, (double)v0.x + (double)P.x / (double)m.mass, 2 * REAL_EPS * (fabs((double)v1.x) + 5 / (double)m.mass));
        CHECK_NEAR(v1.y, (double)v0.y + (double)P.y / (double)m.mass, 2 * REAL_EPS * (fabs((double)v1.y) + 5 / (double)m.mass));
        CHECK_NEAR(w1, (double)w0 + r_wedge_P / (double)m.inertia, 4 * REAL_EPS * (fabs((double)w1) + fabs(r_wedge_P) / (double)m.inertia));
        /* the impulse through the centre does not turn the body */
        CHECK_RESULT(ga2d_body_apply_impulse(w, b, P, c), GA2D_OK);
        CHECK(ga2d_body_angular_velocity(w, b) == w1);
    }
    ga2d_world_destroy(w);
}

/* ------------------------------------------------------------- damping */
/* With gravity off, symplectic Euler and Verlet damp by the implicit
   factor 1/(1 + c h) per substep (stable for any c h): v_N = v0 (1+ch)^-N.
   RK4 integrates v' = -c v itself, so v_N = v0 e^(-c t) within its
   truncation error N (ch)^5/120 plus rounding.  Each multiply rounds:
   2 N eps of v0. */
static void damping(void)
{
    const double c = 2.5, v0 = 4, dt = 1.0 / 60;
    const int substeps = 4, steps = 120, N = steps * substeps;
    const double h = dt / substeps;
    int integ;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ) {
        ga2d_world *w = make_world((ga2d_integrator)integ, GA2D_ROTATION_EXACT, substeps, 0);
        ga2d_body_id b = add_box(w, 0, 0, v0, 0, v0, 0.5);
        double expect;
        int s;
        ga2d_body_set_damping(w, b, (ga2d_real)c, (ga2d_real)c);
        for (s = 0; s < steps; ++s) ga2d_world_step(w, (ga2d_real)dt);
        expect = integ == GA2D_INTEGRATOR_RK4 ? v0 * exp(-c * N * h) : v0 * pow(1 + c * h, -N);
        CHECK_NEAR(ga2d_body_velocity(w, b).x, expect, 2 * N * REAL_EPS * v0 + (integ == GA2D_INTEGRATOR_RK4 ? N * pow(c * h, 5) / 120 * v0 : 0));
        CHECK_NEAR(ga2d_body_angular_velocity(w, b), expect, 2 * N * REAL_EPS * v0 + (integ == GA2D_INTEGRATOR_RK4 ? N * pow(c * h, 5) / 120 * v0 : 0));
        ga2d_world_destroy(w);
    }
}

/* ------------------------------------------------- pay only for what is used */
typedef struct counter_ctx { int calls; } counter_ctx;
static void count_calls(ga2d_world *w, void *ctx) { (void)w; ++((counter_ctx *)ctx)->calls; }

/* Evaluations per step: symplectic Euler 1 per substep, Verlet 1 per
   substep (+1 on its first step, to start), RK4 4 per substep, none of
   them any without a callback.  Rotation updates: only bodies that turn. */
static void evaluation_counts(void)
{
    const int substeps = 3;
    int integ;
    for (integ = 0; integ < GA2D_INTEGRATOR_COUNT; ++integ) {
        ga2d_world *w = make_world((ga2d_integrator)integ, GA2D_ROTATION_EXACT, substeps, -10);
        ga2d_body_def d = ga2d_default_body_def();
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        counter_ctx cc = {0};
        ga2d_world_counters k;
        int per = integ == GA2D_INTEGRATOR_RK4 ? 4 : 1, i;
        d.type = GA2D_BODY_DYNAMIC;
        ga2d_body_create(w, &d);                       /* not turning */
        d.angular_velocity = 2;
        d.position = ga2d_vec_make(10, 0);
        ga2d_body_create(w, &d);                       /* turning */
        d.fixed_rotation = 1;
        d.position = ga2d_vec_make(20, 0);
        ga2d_body_create(w, &d);                       /* fixed: w forced 0 */
        d.type = GA2D_BODY_STATIC;
        for (i = 0; i < 100; ++i) {
            d.position = ga2d_vec_make((ga2d_real)(3 * i), -100); /* apart from all */
            ga2d_body_create(w, &d);
        }
        ga2d_world_step(w, (ga2d_real)(1.0 / 60));
        k = ga2d_world_get_counters(w);
        CHECK(k.force_evaluations == 0);
        CHECK(k.body_count == 103 && k.moving_body_count == 3);
        CHECK(k.integrated_bodies == 3 * substeps);
        CHECK(k.rotation_updates == substeps); /* the one turning body */
        ga2d_world_set_force_callback(w, count_calls, &cc);
        ga2d_world_step(w, (ga2d_real)(1.0 / 60));
        k = ga2d_world_get_counters(w);
        CHECK(k.force_evaluations == per * substeps + (integ == GA2D_INTEGRATOR_VERLET));
        CHECK(cc.calls == k.force_evaluations);
        ga2d_world_step(w, (ga2d_real)(1.0 / 60));
        k = ga2d_world_get_counters(w);
        CHECK(k.force_evaluations == per * substeps);
        CHECK(k.step_count == 3);
        ga2d_world_destroy(w);
    }
}

void suite_motion(void)
{
    test_run("motion: projectile (Verlet, RK4 exact; Euler off by g h t/2)", projectile);
    test_run("motion: torque-free spin, exact and first-order rotor update", torque_free_spin);
    test_run("motion: any turn per substep, every quadrant", large_turn_per_substep);
    test_run("motion: |q| = 1 after 10^6 steps, both rotor updates", rotor_norm_long_run);
    test_run("motion: oscillator follows each integrator's discrete scheme", oscillator_follows_its_scheme);
    test_run("motion: oscillator period within 0.1% at 60 Hz", oscillator_period);
    test_run("motion: oscillator energy bounded (Euler, Verlet), RK4 decays", oscillator_energy);
    test_run("motion: RK4 error falls ~16x when h halves", rk4_fourth_order);
    test_run("motion: orbit keeps L = r^p (Euler, Verlet), energy bounded", orbit_conservation);
    test_run("motion: equal and opposite forces keep total momentum", internal_forces_keep_momentum);
    test_run("motion: off-centre impulse dv = P/m, dOmega = I^-1 (r^P)", off_centre_impulse);
    test_run("motion: damping, implicit and continuous", damping);
    test_run("motion: force evaluations and rotor updates per step", evaluation_counts);
}
