/* integrators.c - the speed/accuracy trade of ga2d_physics.h's integrators.

   Three scenes with a closed-form answer, one dynamic body each, gravity 0,
   run with every integrator (symplectic Euler, velocity Verlet, RK4) at
   world steps dt = 1/30, 1/60, 1/120, 1/240 s with one substep, so the
   integrator's step h is dt.  Each row is one run:

     evals/s  force-callback calls per simulated second (the counters of
              ga2d_world_get_counters summed over the steps): 1/h for
              symplectic Euler and Verlet (Verlet reuses the field at the
              end of a step; its first step pays one extra), 4/h for RK4.
     us/s     wall time of ga2d_world_step per simulated second in
              microseconds, median of 5 runs.  A single-machine figure:
              compare the rows with each other, not with another machine.
     errors   against the exact motion, per scene (see each function).

   How to read it: error against cost.  RK4 evaluates the force 4 times a
   step, so compare it with the others at equal evaluations per second:
   RK4 at h against symplectic Euler and Verlet at h/4 (RK4 at 1/30 with
   the others at 1/120, RK4 at 1/60 with the others at 1/240).  The
   oscillator's "order" is log2 of the error ratio between h and h/2:
   about 1 for symplectic Euler, 2 for Verlet, 4 for RK4, until rounding
   (float keeps ~7 digits) flattens it.  Euler's nears 1 from above: over
   10 periods its O(h^2) phase error is as large as its O(h) error at
   h = 1/30 (1.43, 1.28, 1.16 here; 1.09, 1.05, 1.02 down to h = 1/1920).

   The rotation update acts only on a body that turns.  In scenes 1 and 2
   the body never spins, the counters report no rotor update and the
   column shows "-"; scene 3 runs both updates, exact and linear. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define REPEATS 5
#define NSIZES 4
static const double PI = 3.14159265358979323846;
static const int STEPS_PER_SECOND[NSIZES] = {30, 60, 120, 240};
static const char *const INTEGRATOR[] = {"sympl-euler", "verlet", "rk4"};
static const char *const ROTATION[] = {"exact", "linear"};

/* What a force callback needs: its body and the field's constant. */
typedef struct field { ga2d_body_id body; ga2d_real k; } field;

/* One row: its settings and what the counters and the clock said. */
typedef struct run {
    ga2d_integrator integrator;
    ga2d_rotation_update rotation;
    int hz;                 /* steps per second: h = 1/hz */
    long steps;
    long long evaluations, rotor_updates;
    double us_per_s;
} run;

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e6 + (double)ts.tv_nsec * 1e-3;
}

/* A world with no gravity and one substep, holding the body `bd`. */
static ga2d_world *build(const run *r, ga2d_force_fn *fn, field *f, const ga2d_body_def *bd)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    wd.gravity = ga2d_vec_make(0, 0);
    wd.substeps = 1;
    wd.integrator = r->integrator;
    wd.rotation_update = r->rotation;
    wd.force_callback = fn;
    wd.force_context = f;
    w = ga2d_world_create(&wd);
    if (w) f->body = ga2d_body_create(w, bd);
    if (!w || ga2d_body_id_is_null(f->body)) {
        fprintf(stderr, "integrators: cannot build the world\n");
        exit(1);
    }
    return w;
}

static void step(ga2d_world *w, run *r)
{
    ga2d_world_counters c;
    ga2d_world_step(w, (ga2d_real)(1.0 / r->hz));
    c = ga2d_world_get_counters(w);
    r->evaluations += c.force_evaluations;
    r->rotor_updates += c.rotation_updates;
}

/* The median over REPEATS fresh worlds of the stepping time alone. */
static void time_it(run *r, ga2d_force_fn *fn, field *f, const ga2d_body_def *bd)
{
    double us[REPEATS], t0, x;
    int i, j;
    long n;
    for (i = 0; i < REPEATS; ++i) {
        ga2d_world *w = build(r, fn, f, bd);
        t0 = now_us();
        for (n = 0; n < r->steps; ++n) ga2d_world_step(w, (ga2d_real)(1.0 / r->hz));
        us[i] = (now_us() - t0) / ((double)r->steps / r->hz);
        ga2d_world_destroy(w);
        for (j = i; j > 0 && us[j - 1] > us[j]; --j) { x = us[j]; us[j] = us[j - 1]; us[j - 1] = x; }
    }
    r->us_per_s = us[REPEATS / 2];
}

static run start(ga2d_integrator integrator, ga2d_rotation_update rotation, int hz, double seconds)
{
    run r;
    r.integrator = integrator;
    r.rotation = rotation;
    r.hz = hz;
    r.steps = (long)(seconds * hz + 0.5);
    r.evaluations = r.rotor_updates = 0;
    r.us_per_s = 0;
    return r;
}

static void print_run(const char *scene, const run *r)
{
    double seconds = (double)r->steps / r->hz;
    printf("%-11s %-11s %-6s 1/%-4d %8.1f %8.2f ", scene, INTEGRATOR[r->integrator],
           r->rotor_updates ? ROTATION[r->rotation] : "-", r->hz, (double)r->evaluations / seconds, r->us_per_s);
}

static void print_header(const char *title, const char *errors)
{
    printf("\n%s\n%-11s %-11s %-6s %-6s %8s %8s %s\n", title, "scene", "integrator", "rot", "h",
           "evals/s", "us/s", errors);
}

/* 1. F = -k c: x(t) = cos(2 pi t) from rest at 1 m, period 1 s, 10 s.
   Errors: the largest distance from the exact position over the run, and
   |E - E0|/E0 (E = m v^2/2 + k x^2/2) at the end and its largest value
   over the run.  The run ends after whole periods, near x = 1, v = 0,
   where the symplectic methods' bounded energy wobble (O(h) for Euler,
   O(h^2) for Verlet) passes through nearly zero: "E max" shows its size,
   "E end" shows that it does not drift.  RK4's energy decays steadily. */
static void spring(ga2d_world *w, void *ctx)
{
    const field *f = (const field *)ctx;
    ga2d_body_apply_force_to_center(w, f->body, ga2d_vec_scale(ga2d_body_center(w, f->body), -f->k));
}

static double spring_energy(const ga2d_world *w, const field *f)
{
    ga2d_vec x = ga2d_body_center(w, f->body), v = ga2d_body_velocity(w, f->body);
    double m = (double)ga2d_body_mass_data(w, f->body).mass;
    return 0.5 * m * (double)ga2d_dot(v, v) + 0.5 * (double)f->k * (double)ga2d_dot(x, x);
}

static void oscillator(void)
{
    const double seconds = 10;
    ga2d_body_def bd = ga2d_default_body_def();
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    int i, s;
    bd.type = GA2D_BODY_DYNAMIC; /* the default 1 m box, density 1: m = 1 */
    bd.position = ga2d_vec_make(1, 0);
    print_header("1. harmonic oscillator, period 1 s, 10 s", "max|x-x*|  E end      E max      order");
    for (i = 0; i < GA2D_INTEGRATOR_COUNT; ++i) {
        double previous = 0;
        for (s = 0; s < NSIZES; ++s) {
            run r = start((ga2d_integrator)i, GA2D_ROTATION_EXACT, STEPS_PER_SECOND[s], seconds);
            field f;
            ga2d_world *w;
            double omega, e0, err = 0, emax = 0, e = 0;
            long n;
            f.k = (ga2d_real)(4 * PI * PI); /* k = m omega^2, omega = 2 pi */
            w = build(&r, spring, &f, &bd);
            omega = sqrt((double)f.k / (double)ga2d_body_mass_data(w, f.body).mass);
            e0 = spring_energy(w, &f);
            for (n = 0; n < r.steps; ++n) {
                ga2d_vec c;
                double dx;
                step(w, &r);
                c = ga2d_body_center(w, f.body);
                dx = hypot((double)c.x - cos(omega * ga2d_world_time(w)), (double)c.y);
                e = fabs(spring_energy(w, &f) - e0) / e0;
                if (dx > err) err = dx;
                if (e > emax) emax = e;
            }
            time_it(&r, spring, &f, &bd);
            print_run("oscillator", &r);
            printf("%.3e  %.3e  %.3e  ", err, e, emax);
            if (previous > 0) printf("%5.2f\n", log2(previous / err));
            else printf("%5s\n", "-");
            previous = err;
            ga2d_world_destroy(w);
        }
    }
}

/* 2. F = -GM m r/|r|^3 from the origin; the circular orbit of radius 10
   with period 10 s (GM = (2 pi/10)^2 10^3), 5 orbits.  Errors at the end:
   |E - E0|/|E0| with E = m v^2/2 - GM m/|r|, |L - L0|/|L0| with
   L = m r ^ v, and the radius drift |r| - 10 in metres.  300+ steps an
   orbit resolve it well: in float (ulp ~1e-6 at |r| = 10) all three are
   rounding, growing with the step count; the double build shows the
   methods (Euler and Verlet keep L to rounding: a central kick and a
   drift along v each leave r ^ v unchanged). */
static void gravity(ga2d_world *w, void *ctx)
{
    const field *f = (const field *)ctx;
    ga2d_vec r = ga2d_body_center(w, f->body);
    ga2d_real m = ga2d_body_mass_data(w, f->body).mass, d = ga2d_vec_length(r);
    ga2d_body_apply_force_to_center(w, f->body, ga2d_vec_scale(r, -f->k * m / (d * d * d)));
}

static void orbit_invariants(const ga2d_world *w, const field *f, double *e, double *l, double *radius)
{
    ga2d_vec r = ga2d_body_center(w, f->body), v = ga2d_body_velocity(w, f->body);
    double m = (double)ga2d_body_mass_data(w, f->body).mass;
    *radius = (double)ga2d_vec_length(r);
    *e = 0.5 * m * (double)ga2d_dot(v, v) - (double)f->k * m / *radius;
    *l = m * (double)ga2d_wedge(r, v);
}

static void orbit(void)
{
    const double r0 = 10, period = 10, omega = 2 * PI / period;
    ga2d_body_def bd = ga2d_default_body_def();
    int i, s;
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.05, (ga2d_real)0.05);
    bd.position = ga2d_vec_make((ga2d_real)r0, 0);
    bd.velocity = ga2d_vec_make(0, (ga2d_real)(omega * r0));
    print_header("2. central-force orbit, radius 10, period 10 s, 5 orbits", "energy     ang.mom.   radius");
    for (i = 0; i < GA2D_INTEGRATOR_COUNT; ++i) {
        for (s = 0; s < NSIZES; ++s) {
            run r = start((ga2d_integrator)i, GA2D_ROTATION_EXACT, STEPS_PER_SECOND[s], 5 * period);
            field f;
            ga2d_world *w;
            double e0, l0, d0, e, l, d;
            long n;
            f.k = (ga2d_real)(omega * omega * r0 * r0 * r0);
            w = build(&r, gravity, &f, &bd);
            orbit_invariants(w, &f, &e0, &l0, &d0);
            for (n = 0; n < r.steps; ++n) step(w, &r);
            orbit_invariants(w, &f, &e, &l, &d);
            time_it(&r, gravity, &f, &bd);
            print_run("orbit", &r);
            printf("%.3e  %.3e  %+.3e\n", fabs(e - e0) / fabs(e0), fabs(l - l0) / fabs(l0), d - d0);
            ga2d_world_destroy(w);
        }
    }
}

/* 3. No force, w = 10 rad/s from angle 0, 10 s.  Errors at the end: the
   angle against w t wrapped to (-pi, pi] (near pi: the phase is lost),
   and unwrapped (the steps' turns summed), which shows the linear
   update's lag of w h - atan(w h) per step. */
static double wrap(double a)
{
    a = fmod(a, 2 * PI);
    if (a > PI) a -= 2 * PI;
    if (a <= -PI) a += 2 * PI;
    return a;
}

static void spin(void)
{
    const double omega = 10, seconds = 10;
    ga2d_body_def bd = ga2d_default_body_def();
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    int i, j, s;
    bd.type = GA2D_BODY_DYNAMIC;
    bd.angular_velocity = (ga2d_real)omega;
    print_header("3. torque-free spin, w = 10 rad/s, 10 s", "angle      unwrapped");
    for (i = 0; i < GA2D_INTEGRATOR_COUNT; ++i) {
        for (j = 0; j < GA2D_ROTATION_COUNT; ++j) {
            for (s = 0; s < NSIZES; ++s) {
                run r = start((ga2d_integrator)i, (ga2d_rotation_update)j, STEPS_PER_SECOND[s], seconds);
                field f;
                ga2d_world *w;
                double angle = 0, turned = 0, exact;
                long n;
                w = build(&r, NULL, &f, &bd);
                for (n = 0; n < r.steps; ++n) {
                    double a;
                    step(w, &r);
                    a = (double)ga2d_body_angle(w, f.body);
                    turned += wrap(a - angle); /* each step turns less than pi */
                    angle = a;
                }
                exact = omega * ga2d_world_time(w);
                time_it(&r, NULL, &f, &bd);
                print_run("spin", &r);
                printf("%.3e  %+.3e\n", fabs(wrap(angle - exact)), turned - exact);
                ga2d_world_destroy(w);
            }
        }
    }
}

int main(void)
{
    printf("ga2d_physics integrators (ga2d_real is %s); us/s is this machine's wall time\n",
           sizeof(ga2d_real) == sizeof(double) ? "double" : "float");
    oscillator();
    orbit();
    spin();
    return 0;
}
