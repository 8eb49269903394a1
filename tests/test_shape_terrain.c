/* Chains and conveyor belts in a world, against exact answers. */
#include "test.h"

#define DT (1.0 / 60)
#define G 10.0

static ga2d_world *flat_world(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.enable_sleep = 0;
    return ga2d_world_create(&wd);
}

/* A frictionless box and a frictionless ball slide 40 one-metre segments
   of a straight chain at 5 m/s for 6 s, crossing about 30 joins.  Every
   normal a straight chain keeps is a face normal, (-0, 1) or (0, 1)
   exactly (ga2d__chain_keeps: a straight join has no vertex normals), and
   friction is off, so every impulse has an x component of +-0 and the
   horizontal speed is never changed: it stays 5 bit for bit.  A join that
   caught (an edge normal, the ghost problem) would push back along x. */
static void chain_slide(void)
{
    int shape;
    for (shape = 0; shape < 2; ++shape) {
        ga2d_world *w = flat_world();
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_shape_def sd = ga2d_default_shape_def();
        ga2d_chain_def cd = ga2d_default_chain_def();
        ga2d_vec pts[41];
        ga2d_body_id ground, b;
        int i, exact = 1, segs;
        double vy_max = 0;
        CHECK(w != NULL);
        if (!w) return;
        for (i = 0; i < 41; ++i) pts[i] = ga2d_vec_make((ga2d_real)(-20 + i), 0);
        ground = ga2d_body_create(w, &d);
        cd.points = pts;
        cd.count = 41;
        cd.friction = 0;
        segs = ga2d_chain_get_segments(w, ga2d_chain_create(w, ground, &cd), NULL, 0);
        CHECK(segs == 40);
        d.type = GA2D_BODY_DYNAMIC;
        d.position = ga2d_vec_make(-18, (ga2d_real)(shape ? 0.25 : 0.5));
        d.velocity = ga2d_vec_make(5, 0);
        b = ga2d_body_create(w, &d);
        sd.friction = 0;
        if (shape) {
            ga2d_circle c;
            c.center = ga2d_vec_make(0, 0);
            c.radius = (ga2d_real)0.25;
            CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
        } else {
            ga2d_polygon p = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
            CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, b, &sd, &p)));
        }
        for (i = 0; i < 360; ++i) {
            ga2d_vec v;
            CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
            v = ga2d_body_velocity(w, b);
            exact &= v.x == 5;
            vy_max = fmax(vy_max, fabs((double)v.y));
        }
        CHECK(exact);
        CHECK((double)ga2d_body_position(w, b).x > 11); /* it crossed the joins: -18 + 5 * 6 = 12 */
        if (getenv("GA2D_TEST_VERBOSE"))
            printf("  shape_terrain: %s over 40 segments: vx 5 exactly every step: %d; max |vy| %.3g m/s\n", shape ? "ball" : "box",
                   exact, vy_max);
        ga2d_world_destroy(w);
    }
}

/* A box resting on a belt of tangent speed 2 m/s (mu 0.6 both, so 0.6
   mixed): while it slips, friction is mu times the normal impulse every
   substep, and the normal impulses add up to m (dv_y + g T) over a window
   (vertical momentum), so dv_x = mu (dv_y + g T) exactly up to rounding.
   Rounding (u = eps/2): a substep adds to each velocity component about 8
   times (kick, warm start, soft and relax passes at two points), each off
   by <= u (|v| + g h); over n substeps <= 8 n u (|v| + g T) for each of
   dv_x and dv_y, and mu's own <= 4 u: R = 16 n u (2 + g T) + 4 u. */
static void conveyor(void)
{
    ga2d_world *w = flat_world();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_polygon belt = ga2d_polygon_box(20, (ga2d_real)0.5);
    ga2d_body_id g, b;
    ga2d_vec v0, v1;
    const double T = 6 * DT, n = 6 * 4, u = REAL_EPS / 2, R = 16 * n * u * (2 + G * T) + 4 * u;
    int i;
    CHECK(w != NULL);
    if (!w) return;
    g = ga2d_body_create(w, &d);
    sd.tangent_speed = 2;
    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, g, &sd, &belt)));
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(0, 1);
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    b = ga2d_body_create(w, &d);
    for (i = 0; i < 4; ++i) ga2d_world_step(w, (ga2d_real)DT);
    v0 = ga2d_body_velocity(w, b);
    for (i = 0; i < 6; ++i) ga2d_world_step(w, (ga2d_real)DT);
    v1 = ga2d_body_velocity(w, b);
    CHECK((double)v1.x < 2); /* still slipping: the premise */
    CHECK_NEAR((double)v1.x - (double)v0.x, 0.6 * ((double)v1.y - (double)v0.y + G * T), R);
    if (getenv("GA2D_TEST_VERBOSE"))
        printf("  shape_terrain: belt: dv_x %.9f vs mu (dv_y + g T) %.9f (bound %.2g)\n", (double)v1.x - (double)v0.x,
               0.6 * ((double)v1.y - (double)v0.y + G * T), R);
    ga2d_world_destroy(w);
}

void suite_shape_terrain(void)
{
    test_run("shape_terrain: a box and a ball slide a straight 40-segment chain keeping vx exactly", chain_slide);
    test_run("shape_terrain: a belt drives a slipping box at mu g", conveyor);
}
