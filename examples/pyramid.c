/* pyramid.c - Box2D's pyramid: 210 boxes of 1 m in 20 rows on a static
   ground, run for 10 s at 60 steps a second in the default world.

   It prints:
     bodies    the boxes and the ground;
     steps     how many, and of what length;
     ms/step   the wall time of ga2d_world_step alone, summed over the run
               and divided by the steps (a plain mean, not a median; the
               SVG recording between steps is not timed), and the same over
               the steps taken before the pyramid fell asleep, since a
               sleeping island costs almost nothing.  A single-machine
               figure: tests/bench/ is where speed is measured;
     top box   how far the top box drifted from where it started, in cm,
               and whether it sleeps;
     svg       the animated SVG of the run it wrote (build/pyramid.svg, or
               the path given as the first argument).  Open it in a
               browser: the boxes settle, then turn from orange (awake) to
               grey (asleep) when the pyramid goes to sleep.
   Run it from the repository root (make demo does).  The exit status is
   0 when the world was built and the SVG written. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_writer.h"
#include <math.h>
#include <stdio.h>
#include <time.h>

#define BASE 20       /* boxes in the bottom row: BASE (BASE + 1) / 2 in all */
#define HZ 60         /* steps per second */
#define SECONDS 10
#define SVG_EVERY 2   /* the SVG keeps every 2nd step: 30 frames a second */

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/pyramid.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    const int steps = HZ * SECONDS;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *world = ga2d_world_create(&wd);
    ga2d_body_def bd = ga2d_default_body_def();
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    ga2d_body_id top = ga2d_body_id_null();
    ga2d_vec start, end;
    double stepping_ms = 0, awake_ms = 0, asleep_at = -1, t0, ms;
    int i, j, boxes = 0, awake_steps = 0, failed = 0;
    char caption[80];
    long bytes;
    svgw rec;

    if (!world) {
        fprintf(stderr, "pyramid: cannot create the world\n");
        return 1;
    }

    /* the ground: a static box 200 m wide whose top face is y = 0 */
    bd.position = ga2d_vec_make(0, -1);
    bd.polygon = ga2d_polygon_box(100, 1);
    failed |= ga2d_body_id_is_null(ga2d_body_create(world, &bd));

    /* row i holds boxes i .. BASE-1, each row half a box in from the last */
    bd = ga2d_default_body_def(); /* a 1 m box */
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    bd.type = GA2D_BODY_DYNAMIC;
    for (i = 0; i < BASE; ++i)
        for (j = i; j < BASE; ++j) {
            bd.position = ga2d_vec_make((ga2d_real)((i + 1) * 0.5 + (j - i) * 1.0 - BASE * 0.5),
                                        (ga2d_real)((2 * i + 1) * 0.5));
            top = ga2d_body_create(world, &bd); /* the last one is the top box */
            failed |= ga2d_body_id_is_null(top);
            ++boxes;
        }
    if (failed) {
        fprintf(stderr, "pyramid: cannot create the bodies\n");
        ga2d_world_destroy(world);
        return 1;
    }
    start = ga2d_body_position(world, top);

    /* the run: only ga2d_world_step is timed, not the recording */
    svgw_init(&rec, (double)dt, SVG_EVERY);
    svgw_record(&rec, world);
    for (i = 1; i <= steps; ++i) {
        t0 = now_ms();
        ga2d_world_step(world, dt);
        ms = now_ms() - t0;
        stepping_ms += ms;
        if (asleep_at < 0) { /* a step taken while awake */
            awake_ms += ms;
            ++awake_steps;
            if (ga2d_world_get_counters(world).awake_body_count == 0) asleep_at = (double)i / HZ;
        }
        svgw_record(&rec, world);
    }
    end = ga2d_body_position(world, top);

    printf("pyramid of %d rows (Box2D's benchmark), default world\n", BASE);
    printf("  bodies    %d: %d boxes of 1 m and the ground\n", ga2d_world_get_counters(world).body_count, boxes);
    printf("  steps     %d of 1/%d s (%d s)\n", steps, HZ, SECONDS);
    printf("  ms/step   %.3f (wall time of ga2d_world_step alone, mean over the run;\n"
           "            SVG recording not timed); %.3f over the %d steps before sleep\n",
           stepping_ms / steps, awake_ms / awake_steps, awake_steps);
    printf("  top box   drifted %.2f cm (dx %+.2f, dy %+.2f cm); %s\n",
           100 * hypot((double)(end.x - start.x), (double)(end.y - start.y)),
           100 * (double)(end.x - start.x), 100 * (double)(end.y - start.y),
           ga2d_body_is_awake(world, top) ? "awake" : "asleep");
    if (asleep_at >= 0) printf("  sleep     every box asleep from t = %.2f s\n", asleep_at);
    else printf("  sleep     still awake at t = %d s\n", SECONDS);

    snprintf(caption, sizeof caption, "pyramid: %d boxes, %d s at %d Hz", boxes, SECONDS, HZ);
    bytes = svgw_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "pyramid: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg       %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.frames);
    svgw_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
