/* bounce.c - restitution: three 1 m boxes dropped side by side from the
   same height, h0 = 2 m (bottom face above the ground), with restitution
   0.3, 0.6 and 0.9 (the ground's is 0; restitution mixes as the larger).
   A box that hits the ground at u leaves at e u, so the n-th rebound
   height is e^(2n) h0.

   The collisions are exact: each impact turns the box around at e times
   its true impact speed.  Symplectic Euler, the default integrator, keeps
   the velocity its last drift used, half a kick (g h / 2, h = dt / 4
   substeps) behind the true one; the collision phase allows for that, so
   no speed is lost from flight to flight and the heights are e^(2n) h0
   with either integrator.  GA2D_INTEGRATOR_VERLET, exact under constant
   gravity, runs the same drop again (not recorded) and both are printed.

   A rebound missing from the table ("none") was not made:
     - the collision phase turns a box around where it is when the step
       begins (up to |v| (dt + h) = 3.6 cm above the ground at 1.7 m/s),
       at the speed a true bounce would have at that height.  A hop lower
       than that height has no such speed: e = 0.3's second hop, 1.6 cm,
       is caught about 3 cm up, stopped there, and the box falls the rest
       of the way slower than the restitution threshold (1 m/s);
     - an impact slower than that threshold does not bounce, so e = 0.3
       would have no third hop anyway: its third impact would come at
       e^2 sqrt(2 g h0) = 0.57 m/s.

   It prints, per box and integrator, the first three rebound heights in m
   against e^(2n) h0.  A height is the box's bottom at the top of a flight,
   which falls between two steps: it is taken from the first step past it
   as y + u^2 / (2 g), u the slope of the path there (Verlet: the velocity
   v; symplectic Euler's positions lie on a parabola of slope v - g h / 2).
   Then the SVG of the default run (build/bounce.svg, or the path given as
   the first argument): the boxes turn grey as they come to rest and sleep.
   Run it from the repository root.  The exit status is 0 when the worlds
   were built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_writer.h"
#include <math.h>
#include <stdio.h>

#define BOXES 3
#define REBOUNDS 3
#define H0 2.0        /* m, the drop's gap under each box */
#define G 10.0        /* the default world's gravity */
#define HZ 60         /* steps per second */
#define STEPS 240     /* 4 s: e = 0.9 reaches its third top at 3.3 s */
#define SVG_EVERY 2   /* the SVG keeps every 2nd step: 30 frames a second */

static const double E[BOXES] = {0.3, 0.6, 0.9};

/* Drops the boxes in a default world with the given integrator, recording
   into rec unless it is NULL; height[i][n] is box i's n-th rebound height,
   or -1 if it made none.  Returns 0, or 1 if the world was not built. */
static int drop(ga2d_integrator integrator, svgw *rec, double height[BOXES][REBOUNDS])
{
    const ga2d_real dt = (ga2d_real)1 / HZ;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *world;
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id box[BOXES];
    double h, vy[BOXES]; /* the substep; each box's vertical velocity after the last step */
    int rising[BOXES], count[BOXES], i, k, failed = 0;

    wd.integrator = integrator;
    h = 1.0 / HZ / wd.substeps; /* the integrator's step */
    world = ga2d_world_create(&wd);
    if (!world) return 1;

    /* the ground: a static box 200 m wide whose top face is y = 0 */
    bd.position = ga2d_vec_make(0, -1);
    bd.polygon = ga2d_polygon_box(100, 1);
    failed |= ga2d_body_id_is_null(ga2d_body_create(world, &bd));

    /* the boxes, 2 m apart, their bottom faces at y = H0 */
    bd = ga2d_default_body_def(); /* a 1 m box */
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    bd.type = GA2D_BODY_DYNAMIC;
    for (i = 0; i < BOXES; ++i) {
        bd.position = ga2d_vec_make((ga2d_real)(2 * i - 2), (ga2d_real)(H0 + 0.5));
        bd.restitution = (ga2d_real)E[i];
        box[i] = ga2d_body_create(world, &bd);
        failed |= ga2d_body_id_is_null(box[i]);
        vy[i] = 0;
        rising[i] = count[i] = 0;
        for (k = 0; k < REBOUNDS; ++k) height[i][k] = -1;
    }
    if (failed) {
        ga2d_world_destroy(world);
        return 1;
    }

    if (rec) svgw_record(rec, world);
    for (k = 1; k <= STEPS; ++k) {
        ga2d_world_step(world, dt);
        if (rec) svgw_record(rec, world);
        for (i = 0; i < BOXES; ++i) {
            double v = (double)ga2d_body_velocity(world, box[i]).y;
            double y = (double)ga2d_body_position(world, box[i]).y - 0.5; /* the bottom face */
            if (!rising[i] && vy[i] < 0 && v > 0) {
                rising[i] = 1; /* turned around by an impact */
            } else if (rising[i] && v <= 0) { /* just past the top of the flight */
                double u = integrator == GA2D_INTEGRATOR_VERLET ? v : v - G * h / 2;
                rising[i] = 0;
                if (count[i] < REBOUNDS) height[i][count[i]++] = y + u * u / (2 * G);
            }
            vy[i] = v;
        }
    }
    ga2d_world_destroy(world);
    return 0;
}

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/bounce.svg";
    double euler[BOXES][REBOUNDS], verlet[BOXES][REBOUNDS];
    int i, n, failed;
    char caption[80];
    long bytes;
    svgw rec;

    svgw_init(&rec, 1.0 / HZ, SVG_EVERY);
    failed = drop(GA2D_INTEGRATOR_SYMPLECTIC_EULER, &rec, euler);
    failed |= drop(GA2D_INTEGRATOR_VERLET, NULL, verlet);
    if (failed) {
        fprintf(stderr, "bounce: cannot build the world\n");
        svgw_free(&rec);
        return 1;
    }

    printf("bounce: 1 m boxes dropped from h0 = %.0f m, %.0f s at %d Hz; rebound heights in m\n", H0,
           (double)STEPS / HZ, HZ);
    printf("   e    n   e^(2n) h0   default (sympl. Euler)   Verlet\n");
    for (i = 0; i < BOXES; ++i)
        for (n = 0; n < REBOUNDS; ++n) {
            double want = pow(E[i], 2.0 * (n + 1)) * H0;
            printf("  %.1f   %d   %9.5f", E[i], n + 1, want);
            if (euler[i][n] < 0) printf("   %9s%14s", "none", "");
            else printf("   %9.5f (%+6.2f %%)   ", euler[i][n], 100 * (euler[i][n] / want - 1));
            if (verlet[i][n] < 0) printf("%9s\n", "none");
            else printf("%9.5f (%+6.2f %%)\n", verlet[i][n], 100 * (verlet[i][n] / want - 1));
        }

    snprintf(caption, sizeof caption, "bounce: e = %.1f, %.1f, %.1f from %.0f m", E[0], E[1], E[2], H0);
    bytes = svgw_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "bounce: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg  %s (%.0f kB, %d frames, the default run; open it in a browser)\n", svg_path,
               (double)bytes / 1024, rec.frames);
    svgw_free(&rec);
    return failed;
}
