/* roll.c - rolling against sliding: a ball (a circle shape, r = 0.5 m)
   and a 1 m box let go at rest on one static slope of 20 degrees, the
   ball lower down, so the two never meet.

   The box slides (tan 20 = 0.364 > mu = 0.3) with
       a = g (sin 20 - mu cos 20)              = 0.601 m/s^2.
   The ball rolls without slipping (mu = 0.6 > tan(20) / 3: the friction a
   disc needs to roll, m g sin / 3, is inside the cone mu m g cos): its
   friction turns it as it slows it, I dw = r F with I = m r^2 / 2, so
       a = g sin 20 / (1 + I / (m r^2)) = 2/3 g sin 20 = 2.280 m/s^2
   whatever its mass and radius, and w r = v all the way.
   Friction mixes as sqrt(mu_a mu_b): the slope's is 1 and each body's is
   the square of the mu it should feel (0.09 and 0.36).

   It prints, per body, its acceleration down the slope from its velocity
   at 0.5 s and 1.5 s against the formula, and for the ball the rolling
   condition w r / v at 1.5 s (1: no slip); then the SVG of the run
   (build/roll.svg, or the path given as the first argument): the ball's
   radius line turns as it rolls, the box keeps its face on the slope.
   Run it from the repository root.  The exit status is 0 when the world
   was built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_shapes.h"
#include <math.h>
#include <stdio.h>

#define DEGREES 20
#define HZ 60        /* steps per second */
#define STEPS 150    /* 2.5 s */
#define SVG_EVERY 2  /* the SVG keeps every 2nd step: 30 frames a second */
#define R 0.5        /* the ball's radius, m */
#define MU_BOX 0.3   /* the mixed coefficients */
#define MU_BALL 0.6

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/roll.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    const double pi = 3.14159265358979323846, theta = DEGREES * pi / 180, g = 10;
    const ga2d_rotor q = ga2d_rotor_from_angle((ga2d_real)-theta); /* down the slope is +x */
    const ga2d_vec down = ga2d_rotate(q, ga2d_vec_make(1, 0));
    ga2d_world_def wd = ga2d_default_world_def(); /* gravity (0, -10) */
    ga2d_world *world = ga2d_world_create(&wd);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle disc;
    ga2d_body_id box, ball;
    double v1[2] = {0, 0}, v2[2] = {0, 0}, w2 = 0;
    double want_box = g * (sin(theta) - MU_BOX * cos(theta)), want_ball = 2.0 / 3.0 * g * sin(theta);
    int k, failed = 0;
    char caption[96];
    long bytes;
    svgs rec;

    if (!world) {
        fprintf(stderr, "roll: cannot create the world\n");
        return 1;
    }

    /* the slope: a static box 20 m x 1 m turned by -20 degrees about the
       origin, its top face the incline (local y = 0.5); friction 1 */
    bd.rotor = q;
    bd.polygon = ga2d_polygon_box(10, 0.5f);
    bd.friction = 1;
    failed |= ga2d_body_id_is_null(ga2d_body_create(world, &bd));

    /* the box, 8 m up the slope from its middle, turned with it and resting
       on it: in the slope's frame at (-8, 1) */
    bd = ga2d_default_body_def();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.rotor = q;
    bd.position = ga2d_rotate(q, ga2d_vec_make(-8, 1));
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    bd.friction = (ga2d_real)(MU_BOX * MU_BOX);
    box = ga2d_body_create(world, &bd);

    /* the ball, 4 m further down, touching the slope: a body with no shape
       of its own (the default def), given a circle */
    bd = ga2d_default_body_def();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.rotor = q; /* so its radius line starts along the slope */
    bd.position = ga2d_rotate(q, ga2d_vec_make(-4, (ga2d_real)(0.5 + R)));
    ball = ga2d_body_create(world, &bd);
    sd.friction = (ga2d_real)(MU_BALL * MU_BALL);
    disc.center = ga2d_vec_make(0, 0);
    disc.radius = (ga2d_real)R;
    failed |= ga2d_body_id_is_null(box) || ga2d_shape_id_is_null(ga2d_shape_create_circle(world, ball, &sd, &disc));
    if (failed) {
        fprintf(stderr, "roll: cannot create the bodies\n");
        ga2d_world_destroy(world);
        return 1;
    }

    svgs_init(&rec, (double)dt, SVG_EVERY);
    svgs_record(&rec, world);
    for (k = 1; k <= STEPS; ++k) {
        ga2d_world_step(world, dt);
        svgs_record(&rec, world);
        if (k == HZ / 2) {
            v1[0] = (double)ga2d_dot(ga2d_body_velocity(world, box), down);
            v1[1] = (double)ga2d_dot(ga2d_body_velocity(world, ball), down);
        }
        if (k == 3 * HZ / 2) {
            v2[0] = (double)ga2d_dot(ga2d_body_velocity(world, box), down);
            v2[1] = (double)ga2d_dot(ga2d_body_velocity(world, ball), down);
            w2 = (double)ga2d_body_angular_velocity(world, ball); /* clockwise: negative */
        }
    }

    printf("roll: a ball and a box on a %d degree slope (tan %.3f), %.1f s at %d Hz\n", DEGREES, tan(theta),
           (double)STEPS / HZ, HZ);
    printf("  box   mu %.2f  a %.4f m/s^2 vs g (sin - mu cos) %.4f  (%+.3f %%)  spin %.2g rad/s\n", MU_BOX,
           v2[0] - v1[0], want_box, 100 * ((v2[0] - v1[0]) / want_box - 1),
           (double)ga2d_body_angular_velocity(world, box));
    printf("  ball  mu %.2f  a %.4f m/s^2 vs 2/3 g sin          %.4f  (%+.3f %%)  w r / v %.5f at 1.5 s\n",
           MU_BALL, v2[1] - v1[1], want_ball, 100 * ((v2[1] - v1[1]) / want_ball - 1), -w2 * R / v2[1]);

    snprintf(caption, sizeof caption, "roll: %d deg slope, ball mu %.1f rolls, box mu %.1f slides", DEGREES,
             MU_BALL, MU_BOX);
    bytes = svgs_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "roll: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg   %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.base.frames);
    svgs_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
