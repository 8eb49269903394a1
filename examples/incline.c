/* incline.c - Coulomb friction on a slope: three 1 m blocks on one static
   slope of 25 degrees, each with its own friction coefficient, let go at
   rest.  A block slides when tan 25 = 0.466 > mu, with
       a = g (sin 25 - mu cos 25),
   and sticks (a = 0) otherwise.  Friction mixes as sqrt(mu_a mu_b), so
   the slope's friction is 1 and each block's is the square of the mu it
   should slide with: 0.20 (well below tan 25), 0.45 (just below it: a
   slow slide) and 0.60 (above it: it sticks).  The slope is a static box
   turned by 25 degrees rather than gravity turned, so the contact normals
   are not the axes.  The fastest block starts lowest, so none catches up
   with another.

   It prints, per block:
     mu        the mixed coefficient, and the block's own (its square);
     slid      how far it moved in the run (2 s), in m;
     a         its acceleration down the slope, from its velocity at 0.5 s
               and 1.5 s (under a constant force the default integrator's
               velocity is exact, so their difference is too), against
               g (sin 25 - mu cos 25), or 0 for a block that sticks;
     svg       the animated SVG of the run it wrote (build/incline.svg, or
               the path given as the first argument).  The block that
               sticks turns grey when it falls asleep.
   Run it from the repository root.  The exit status is 0 when the world
   was built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_writer.h"
#include <math.h>
#include <stdio.h>

#define BLOCKS 3
#define DEGREES 25
#define HZ 60         /* steps per second */
#define STEPS 120     /* 2 s */
#define SVG_EVERY 2   /* the SVG keeps every 2nd step: 30 frames a second */

int main(int argc, char **argv)
{
    static const double mu[BLOCKS] = {0.20, 0.45, 0.60};  /* mixed: sqrt(mu_block * 1) */
    static const double up[BLOCKS] = {1.5, 3.5, 5.5};     /* start, m up the slope from its middle */
    const char *svg_path = argc > 1 ? argv[1] : "build/incline.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    const double pi = 3.14159265358979323846, theta = DEGREES * pi / 180, g = 10;
    const ga2d_rotor q = ga2d_rotor_from_angle((ga2d_real)theta);
    const ga2d_vec down = ga2d_vec_make((ga2d_real)-cos(theta), (ga2d_real)-sin(theta)); /* along the slope */
    ga2d_world_def wd = ga2d_default_world_def(); /* gravity (0, -10) */
    ga2d_world *world = ga2d_world_create(&wd);
    ga2d_body_def bd = ga2d_default_body_def();
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    ga2d_body_id block[BLOCKS];
    ga2d_vec start[BLOCKS];
    double v1[BLOCKS], v2[BLOCKS];
    int i, k, failed = 0;
    char caption[80];
    long bytes;
    svgw rec;

    if (!world) {
        fprintf(stderr, "incline: cannot create the world\n");
        return 1;
    }

    /* the slope: a static box 16 m x 1 m turned by 25 degrees about the
       origin, its top face the incline; friction 1 */
    bd.rotor = q;
    bd.polygon = ga2d_polygon_box(8, (ga2d_real)0.5);
    bd.friction = 1;
    failed |= ga2d_body_id_is_null(ga2d_body_create(world, &bd));

    /* the blocks, turned with the slope and resting on its top face: in the
       slope's frame at (up, 1), half a block above its top face at 0.5 */
    bd = ga2d_default_body_def(); /* a 1 m box */
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.rotor = q;
    for (i = 0; i < BLOCKS; ++i) {
        bd.position = ga2d_rotate(q, ga2d_vec_make((ga2d_real)up[i], 1));
        bd.friction = (ga2d_real)(mu[i] * mu[i]);
        block[i] = ga2d_body_create(world, &bd);
        failed |= ga2d_body_id_is_null(block[i]);
        start[i] = ga2d_body_position(world, block[i]);
        v1[i] = v2[i] = 0;
    }
    if (failed) {
        fprintf(stderr, "incline: cannot create the bodies\n");
        ga2d_world_destroy(world);
        return 1;
    }

    svgw_init(&rec, (double)dt, SVG_EVERY);
    svgw_record(&rec, world);
    for (k = 1; k <= STEPS; ++k) {
        ga2d_world_step(world, dt);
        svgw_record(&rec, world);
        for (i = 0; i < BLOCKS; ++i) { /* the speed down the slope at 0.5 s and 1.5 s */
            if (k == HZ / 2) v1[i] = (double)ga2d_dot(ga2d_body_velocity(world, block[i]), down);
            if (k == 3 * HZ / 2) v2[i] = (double)ga2d_dot(ga2d_body_velocity(world, block[i]), down);
        }
    }

    printf("incline of %d degrees (tan %.3f), slope friction 1, %.0f s at %d Hz\n", DEGREES, tan(theta),
           (double)STEPS / HZ, HZ);
    for (i = 0; i < BLOCKS; ++i) {
        ga2d_vec d = ga2d_vec_sub(ga2d_body_position(world, block[i]), start[i]);
        double a = v2[i] - v1[i]; /* m/s gained in the second from 0.5 s to 1.5 s */
        double want = tan(theta) > mu[i] ? g * (sin(theta) - mu[i] * cos(theta)) : 0;
        printf("  block %d  mu %.2f (its own %.4f)  slid %6.3f m  a %.4f m/s^2 vs g(sin - mu cos) %.4f  %s\n", i + 1,
               mu[i], mu[i] * mu[i], (double)ga2d_vec_length(d), a, want,
               want > 0 ? "slides" : ga2d_body_is_awake(world, block[i]) ? "sticks" : "sticks (asleep)");
    }

    snprintf(caption, sizeof caption, "incline %d deg: mu %.2f, %.2f, %.2f", DEGREES, mu[0], mu[1], mu[2]);
    bytes = svgw_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "incline: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg      %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.frames);
    svgw_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
