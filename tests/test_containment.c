/* Containment (issue 8): a body driven non-finite by a user force, torque
   or impulse is reported by the step (which body, which error), put back
   where the step began at rest, and its neighbours stay finite. */
#include "test.h"

static int body_finite(const ga2d_world *w, ga2d_body_id id)
{
    ga2d_vec x = ga2d_body_position(w, id), v = ga2d_body_velocity(w, id);
    ga2d_rotor q = ga2d_body_rotor(w, id);
    double om = (double)ga2d_body_angular_velocity(w, id);
    return isfinite((double)x.x) && isfinite((double)x.y) && isfinite((double)v.x) && isfinite((double)v.y) &&
           isfinite((double)q.c) && isfinite((double)q.s) && isfinite(om);
}

/* A stack of five 1 m boxes with a light 0.1 m box (mass 0.01 kg) resting
   on top; `kind` drives the light box:
     0: a force of REAL_MAX / 2 at its centre: its acceleration F/m is 50
        times REAL_MAX, not finite in either precision;
     1: a torque of REAL_MAX / 2: I = m (0.1^2)/6 ~ 1.7e-5, so alpha is not
        finite either;
     2: an impulse that leaves v finite but huge (REAL_MAX / 4 per
        component over the mass cannot be applied: the setter refuses a
        non-finite result), so instead an impulse of 1e-3 REAL_MAX: v =
        0.1 REAL_MAX is finite; the step must cap it at 400 m/s without
        overflowing |v|^2, report nothing, and stay finite everywhere.
   `field`: the world has a force callback that adds nothing, so the step
   integrates on the bodies' records (ga2d__kick_gather) instead of the
   solver bodies (ga2d__compact_begin): both must contain alike. */
static void add_nothing(ga2d_world *w, void *context)
{
    (void)w;
    (void)context;
}

static void drive(int kind, int field)
{
    ga2d_world_def wdef = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id ids[7], light;
    ga2d_vec start, start_below;
    ga2d_result r;
    int i, all_finite = 1;
    if (field) wdef.force_callback = add_nothing;
    w = ga2d_world_create(&wdef);
    d.polygon = ga2d_polygon_box(10, (ga2d_real)0.5);
    d.position = ga2d_vec_make(0, (ga2d_real)-0.5);
    ids[0] = ga2d_body_create(w, &d);
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    for (i = 1; i <= 5; ++i) {
        d.position = ga2d_vec_make(0, (ga2d_real)(i - 0.5));
        ids[i] = ga2d_body_create(w, &d);
    }
    d.polygon = ga2d_polygon_box((ga2d_real)0.05, (ga2d_real)0.05);
    d.position = ga2d_vec_make(0, (ga2d_real)5.05);
    light = ids[6] = ga2d_body_create(w, &d);
    for (i = 0; i < 30; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
    start = ga2d_body_position(w, light);
    start_below = ga2d_body_position(w, ids[5]);
    if (kind == 0) CHECK_RESULT(ga2d_body_apply_force_to_center(w, light, ga2d_vec_make(0, (ga2d_real)(REAL_MAX / 2))), GA2D_OK);
    if (kind == 1) CHECK_RESULT(ga2d_body_apply_torque(w, light, (ga2d_real)(REAL_MAX / 2)), GA2D_OK);
    if (kind == 2)
        CHECK_RESULT(ga2d_body_apply_impulse(w, light, ga2d_vec_make((ga2d_real)(REAL_MAX * 1e-3), 0), ga2d_body_center(w, light)),
                     GA2D_OK);
    r = ga2d_world_step(w, (ga2d_real)1 / 60);
    if (kind < 2) {
        /* put back where the step began, at rest, in the first substep's
           velocity phase (the kick that overflowed); its contact's impulses
           restart from zero.  The rest of the step moves it as any body
           resting on the top box (defaults: h = dt/4, g = 10):
           - down, at most as in free fall from rest over the 3 substeps
             left: each substep's net contact impulse, its accumulated
             normal impulse, pushes up, so the velocity a drift uses is
             >= -j g h in substep j, and the drop <= h^2 g (1 + 2 + 3) =
             6 g h^2 = 1.04 mm (within the g dt^2 / 2 = 1.39 mm of a fall
             through a whole step);
           - up, relative to the top box, at most what the soft contact's
             push-out does: the soft pass leaves a point separating at
             most at its bias speed b |s| (b = omega / (2 zeta + h omega),
             45 Hz between dynamic bodies, zeta = 10: b = 13.4 /s), the
             drift moves it so, and |s| <= slop resting: <= dt b slop =
             1.11 mm over the step; sideways nothing but that contact acts
             on it (its normal up, its friction holding it to the top box),
             so the same bound covers it;
           - plus the drifts' rounding, 2 u |x| a substep (u = eps/2).
           Its speed: down at most the free fall's 3 g h = 0.125 m/s; the
           relax pass takes the push-out speed back out of it, leaving
           that of its support, which rests: within g dt (0.17 m/s) either
           way. */
        const ga2d_world_def wd = ga2d_default_world_def();
        const double g = -(double)wd.gravity.y, h = 1.0 / 60 / wd.substeps, dt = 1.0 / 60;
        const double om = 2 * 3.14159265358979323846 * fmin((double)wd.contact_hertz, 0.25 / h);
        const double b = om / (2 * (double)wd.contact_damping_ratio + h * om);
        const double fall = g * h * h * (wd.substeps - 1) * wd.substeps / 2, rise = dt * b * GA2D_LINEAR_SLOP;
        ga2d_vec now = ga2d_body_position(w, light), below = ga2d_body_position(w, ids[5]);
        double dx = (double)now.x - (double)start.x, dy = (double)now.y - (double)start.y;
        double rdx = dx - ((double)below.x - (double)start_below.x), rdy = dy - ((double)below.y - (double)start_below.y);
        double rnd = 2 * wd.substeps * (REAL_EPS / 2) * (fabs((double)now.x) + fabs((double)now.y) + 1);
        CHECK_RESULT(r, GA2D_ERR_NOT_FINITE);
        CHECK(ga2d_body_id_equal(ga2d_world_error_body(w), light));
        CHECK(dy >= -(fall + rnd));
        CHECK(rdy <= rise + 2 * rnd && fabs(rdx) <= rise + 2 * rnd);
        CHECK(fabs((double)ga2d_body_velocity(w, light).x) <= g * dt && fabs((double)ga2d_body_velocity(w, light).y) <= g * dt);
    } else {
        CHECK_RESULT(r, GA2D_OK);
        CHECK(ga2d_body_id_is_null(ga2d_world_error_body(w)));
        /* capped: 400 m/s (within the cap's rounding, a few eps) */
        CHECK(fabs((double)ga2d_body_velocity(w, light).x) <= 400 * (1 + 16 * REAL_EPS));
    }
    for (i = 0; i < 7; ++i) all_finite &= body_finite(w, ids[i]);
    CHECK(all_finite);
    /* and the world goes on: the next steps report nothing */
    for (i = 0; i < 30; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
    CHECK(ga2d_body_id_is_null(ga2d_world_error_body(w)));
    for (i = 0; i < 7; ++i) all_finite &= body_finite(w, ids[i]);
    CHECK(all_finite);
    ga2d_world_destroy(w);
}

static void huge_force(void) { drive(0, 0); }
static void huge_torque(void) { drive(1, 0); }
static void huge_impulse(void) { drive(2, 0); }
static void huge_force_field(void) { drive(0, 1); }
static void huge_torque_field(void) { drive(1, 1); }

void suite_containment(void)
{
    test_run("containment: a force that overflows is reported, the body put back, neighbours finite", huge_force);
    test_run("containment: a torque that overflows likewise", huge_torque);
    test_run("containment: a huge finite impulse is capped without overflow", huge_impulse);
    test_run("containment: with a force callback, a force that overflows likewise", huge_force_field);
    test_run("containment: with a force callback, a torque that overflows likewise", huge_torque_field);
}
