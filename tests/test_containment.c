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
        overflowing |v|^2, report nothing, and stay finite everywhere. */
static void drive(int kind)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id ids[7], light;
    ga2d_vec start;
    ga2d_result r;
    int i, all_finite = 1;
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
    if (kind == 0) CHECK_RESULT(ga2d_body_apply_force_to_center(w, light, ga2d_vec_make(0, (ga2d_real)(REAL_MAX / 2))), GA2D_OK);
    if (kind == 1) CHECK_RESULT(ga2d_body_apply_torque(w, light, (ga2d_real)(REAL_MAX / 2)), GA2D_OK);
    if (kind == 2)
        CHECK_RESULT(ga2d_body_apply_impulse(w, light, ga2d_vec_make((ga2d_real)(REAL_MAX * 1e-3), 0), ga2d_body_center(w, light)),
                     GA2D_OK);
    r = ga2d_world_step(w, (ga2d_real)1 / 60);
    if (kind < 2) {
        ga2d_vec now = ga2d_body_position(w, light);
        CHECK_RESULT(r, GA2D_ERR_NOT_FINITE);
        CHECK(ga2d_body_id_equal(ga2d_world_error_body(w), light));
        /* put back where the step began, at rest, in the first substep;
           the rest of the step (< dt) moves it as any body: from rest
           under g = 10 at most g dt^2 / 2 (1.4 mm) and g dt (0.17 m/s) */
        CHECK(fabs((double)(now.x - start.x)) <= 10.0 / 3600 && fabs((double)(now.y - start.y)) <= 10.0 / 3600);
        CHECK(fabs((double)ga2d_body_velocity(w, light).x) <= 10.0 / 60 && fabs((double)ga2d_body_velocity(w, light).y) <= 10.0 / 60);
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

static void huge_force(void) { drive(0); }
static void huge_torque(void) { drive(1); }
static void huge_impulse(void) { drive(2); }

void suite_containment(void)
{
    test_run("containment: a force that overflows is reported, the body put back, neighbours finite", huge_force);
    test_run("containment: a torque that overflows likewise", huge_torque);
    test_run("containment: a huge finite impulse is capped without overflow", huge_impulse);
}
