/* newtons_cradle.c - Newton's cradle of boxes: five 1 m boxes with
   restitution 1 and no friction on a frictionless static ground.  Four
   stand in a row, touching; the first slides in at 4 m/s from 1 m away.
   An ideal cradle passes the whole motion down the row: after the impact
   the first four stand still and the last one leaves at 4 m/s, so the
   velocities go from (4, 0, 0, 0, 0) to (0, 0, 0, 0, 4).  The library's
   restitution is a collision phase solved contact after contact until
   nothing collides, so the impact runs down the touching row; the soft
   contacts alone would share it out (five boxes at 0.8 m/s together).

   It prints:
     start     the boxes' velocities before the run;
     end       their velocities after it (x and y, m/s) and whether each
               is awake: the four left behind stop and fall asleep;
     momentum  and kinetic energy, before and after: both kept;
     svg       the animated SVG of the run it wrote (build/newtons_cradle.svg,
               or the path given as the first argument).  The run is 1.5 s,
               so the last box is still in the picture when it ends.
   Run it from the repository root.  The exit status is 0 when the world
   was built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_writer.h"
#include <stdio.h>

#define BOXES 5
#define SPEED 4       /* m/s, the first box's */
#define HZ 60         /* steps per second */
#define STEPS 90      /* 1.5 s */
#define SVG_EVERY 1   /* the SVG keeps every step: 60 frames a second */

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/newtons_cradle.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *world = ga2d_world_create(&wd);
    ga2d_body_def bd = ga2d_default_body_def();
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    ga2d_body_id box[BOXES];
    double p0 = 0, e0 = 0, p1 = 0, e1 = 0;
    int i, failed = 0;
    char caption[80];
    long bytes;
    svgw rec;

    if (!world) {
        fprintf(stderr, "newtons_cradle: cannot create the world\n");
        return 1;
    }

    /* the ground: a static box 200 m wide whose top face is y = 0, no friction */
    bd.position = ga2d_vec_make(0, -1);
    bd.polygon = ga2d_polygon_box(100, 1);
    bd.friction = 0;
    failed |= ga2d_body_id_is_null(ga2d_body_create(world, &bd));

    /* box 0 at x = -2, moving right; boxes 1..4 at x = 0..3, touching */
    bd = ga2d_default_body_def(); /* a 1 m box */
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.friction = 0;
    bd.restitution = 1;
    for (i = 0; i < BOXES; ++i) {
        bd.position = ga2d_vec_make((ga2d_real)(i == 0 ? -2 : i - 1), (ga2d_real)0.5);
        bd.velocity = ga2d_vec_make(i == 0 ? (ga2d_real)SPEED : 0, 0);
        box[i] = ga2d_body_create(world, &bd);
        failed |= ga2d_body_id_is_null(box[i]);
    }
    if (failed) {
        fprintf(stderr, "newtons_cradle: cannot create the bodies\n");
        ga2d_world_destroy(world);
        return 1;
    }

    printf("Newton's cradle: %d boxes of 1 m, restitution 1, friction 0, on the ground\n", BOXES);
    printf("  start     v_x =");
    for (i = 0; i < BOXES; ++i) {
        double m = (double)ga2d_body_mass_data(world, box[i]).mass;
        printf(" %6.3f", (double)ga2d_body_velocity(world, box[i]).x);
        p0 += m * (double)ga2d_body_velocity(world, box[i]).x;
        e0 += (double)ga2d_body_kinetic_energy(world, box[i]);
    }
    printf(" m/s\n");

    svgw_init(&rec, (double)dt, SVG_EVERY);
    svgw_record(&rec, world);
    for (i = 1; i <= STEPS; ++i) {
        ga2d_world_step(world, dt);
        svgw_record(&rec, world);
    }

    printf("  end       after %.1f s (%d steps of 1/%d s):\n", (double)STEPS / HZ, STEPS, HZ);
    for (i = 0; i < BOXES; ++i) {
        ga2d_vec v = ga2d_body_velocity(world, box[i]);
        double m = (double)ga2d_body_mass_data(world, box[i]).mass;
        printf("            box %d  v = (%7.4f, %7.4f) m/s  %s\n", i + 1, (double)v.x, (double)v.y,
               ga2d_body_is_awake(world, box[i]) ? "awake" : "asleep");
        p1 += m * (double)v.x;
        e1 += (double)ga2d_body_kinetic_energy(world, box[i]);
    }
    printf("  momentum  %.4f -> %.4f kg m/s;  kinetic energy %.4f -> %.4f J\n", p0, p1, e0, e1);

    snprintf(caption, sizeof caption, "Newton's cradle: %d boxes, e = 1, %d m/s in", BOXES, SPEED);
    bytes = svgw_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "newtons_cradle: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg       %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.frames);
    svgw_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
