/* pile.c - 150 bodies of every shape poured into a bin: circles, capsules,
   boxes and rounded polygons (rounded boxes and hexagons), of mixed
   sizes, dropped six at a time from above a static bin (three box walls,
   12 m wide inside) every 0.15 s (the last at 3.6 s), then left to settle in the
   default world (sleep on).

   There is no formula for a pile; what it shows is that one of round and
   flat shapes settles and goes to sleep, with nothing lost through the
   walls.  It prints:
     shapes    how many of each;
     asleep    how many bodies sleep at 2 s intervals, and the time the
               last one fell asleep (the pile, all touching, is one island
               and falls asleep as a whole);
     lost      bodies outside the bin at the end (0: none leaked through
               a wall or the floor), and the pile's top;
     svg       the animated SVG of the run (build/pile.svg, or the path
               given as the first argument): the bodies pour in, settle,
               and turn from orange to grey as they fall asleep.
   Run it from the repository root.  The exit status is 0 when the world
   was built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_shapes.h"
#include <math.h>
#include <stdio.h>

#define BODIES 150
#define PER_ROW 6     /* bodies dropped at once */
#define ROW_EVERY 9   /* steps between drops: 0.15 s */
#define HZ 60         /* steps per second */
#define MAX_SECONDS 20
#define SVG_EVERY 2   /* the SVG keeps every 2nd step: 30 frames a second */
#define HALF_W 6.0    /* the bin's inside half-width, m */
#define WALL_H 11.0   /* its walls' height above the floor, m */

enum { CIRCLE, CAPSULE, BOX, ROUNDED_BOX, HEXAGON, KINDS };
static const char *const KIND_NAMES[KINDS] = {"circles", "capsules", "boxes", "rounded boxes", "rounded hexagons"};

/* A small deterministic generator (a 32-bit LCG): the same pile every run. */
static unsigned rng_state = 12345u;
static double rng(void) /* in [0, 1) */
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (double)(rng_state >> 8) / 16777216.0;
}

/* A static box wall of half-extents hw x hh centred on (x, y). */
static int wall(ga2d_world *world, double x, double y, double hw, double hh)
{
    ga2d_body_def bd = ga2d_default_body_def();
    bd.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    bd.polygon = ga2d_polygon_box((ga2d_real)hw, (ga2d_real)hh);
    return ga2d_body_id_is_null(ga2d_body_create(world, &bd));
}

/* One body of the given kind at (x, y), turned by angle, with a shape of
   size s (0..1); returns 1 if it could not be made. */
static int drop(ga2d_world *world, int kind, double x, double y, double angle, double s, ga2d_body_id *out)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_shape_id shape = ga2d_shape_id_null();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    bd.rotor = ga2d_rotor_from_angle((ga2d_real)angle);
    *out = ga2d_body_create(world, &bd); /* no shape yet: the default def has none */
    if (ga2d_body_id_is_null(*out)) return 1;
    if (kind == CIRCLE) {
        ga2d_circle c;
        c.center = ga2d_vec_make(0, 0);
        c.radius = (ga2d_real)(0.25 + 0.2 * s);
        shape = ga2d_shape_create_circle(world, *out, &sd, &c);
    } else if (kind == CAPSULE) {
        ga2d_capsule c;
        double half = 0.25 + 0.3 * s;
        c.center1 = ga2d_vec_make((ga2d_real)-half, 0);
        c.center2 = ga2d_vec_make((ga2d_real)half, 0);
        c.radius = (ga2d_real)(0.18 + 0.07 * s);
        shape = ga2d_shape_create_capsule(world, *out, &sd, &c);
    } else {
        ga2d_polygon p;
        if (kind == BOX) p = ga2d_polygon_box((ga2d_real)(0.3 + 0.2 * s), (ga2d_real)(0.25 + 0.15 * s));
        else if (kind == ROUNDED_BOX)
            p = ga2d_polygon_rounded_box((ga2d_real)(0.35 + 0.2 * s), (ga2d_real)(0.25 + 0.1 * s), 0.1f);
        else { /* a hexagon rounded by 0.08 m */
            p = ga2d_polygon_regular(6, (ga2d_real)(0.25 + 0.15 * s));
            p.radius = 0.08f;
        }
        shape = ga2d_shape_create_polygon(world, *out, &sd, &p);
    }
    return ga2d_shape_id_is_null(shape);
}

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/pile.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *world = ga2d_world_create(&wd);
    ga2d_body_id body[BODIES];
    int count[KINDS] = {0}, made = 0, k, i, failed = 0, lost = 0, asleep = 0;
    int asleep_at[MAX_SECONDS / 2], reports = 0; /* asleep at 2 s, 4 s, ... */
    double all_asleep_at = -1, top = 0;
    char caption[96];
    long bytes;
    svgs rec;

    if (!world) {
        fprintf(stderr, "pile: cannot create the world\n");
        return 1;
    }
    /* the bin: a floor whose top is y = 0 and two walls 0.5 m thick */
    failed |= wall(world, 0, -0.5, HALF_W + 1, 0.5);
    failed |= wall(world, -HALF_W - 0.5, WALL_H / 2, 0.5, WALL_H / 2);
    failed |= wall(world, HALF_W + 0.5, WALL_H / 2, 0.5, WALL_H / 2);

    svgs_init(&rec, (double)dt, SVG_EVERY);
    svgs_record(&rec, world);
    printf("pile: %d bodies poured %d at a time every %.2f s into a bin %.0f m wide, %d Hz\n", BODIES, PER_ROW,
           (double)ROW_EVERY / HZ, 2 * HALF_W, HZ);
    for (k = 1; k <= MAX_SECONDS * HZ && !failed; ++k) {
        if ((k - 1) % ROW_EVERY == 0 && made < BODIES) /* a row of six, spread across the bin, at 13 m */
            for (i = 0; i < PER_ROW && made < BODIES; ++i) {
                int kind = made % KINDS; /* in turn: rows of 6 shift by one */
                /* one draw per statement: the order of a call's arguments is the compiler's */
                double x = -HALF_W + (i + 0.5) * (2 * HALF_W / PER_ROW) + 0.4 * (rng() - 0.5);
                double y = 13 + 0.3 * rng();
                double angle = 3.14159265358979323846 * rng();
                double size = rng();
                failed |= drop(world, kind, x, y, angle, size, &body[made]);
                ++count[kind];
                ++made;
            }
        ga2d_world_step(world, dt);
        svgs_record(&rec, world);
        if (made == BODIES && all_asleep_at < 0 && ga2d_world_get_counters(world).awake_body_count == 0)
            all_asleep_at = k * (double)dt;
        if (k % (2 * HZ) == 0) {
            for (i = 0, asleep = 0; i < made; ++i) asleep += !ga2d_body_is_awake(world, body[i]);
            if (reports < MAX_SECONDS / 2) asleep_at[reports++] = asleep;
        }
        if (all_asleep_at >= 0 && k % (2 * HZ) == 0) break; /* asleep: stop at the next report */
    }
    if (failed) {
        fprintf(stderr, "pile: cannot create the bodies\n");
        svgs_free(&rec);
        ga2d_world_destroy(world);
        return 1;
    }

    printf("  shapes ");
    for (i = 0; i < KINDS; ++i) printf(" %d %s%s", count[i], KIND_NAMES[i], i + 1 < KINDS ? "," : "\n");
    for (i = 0, asleep = 0; i < BODIES; ++i) {
        ga2d_vec p = ga2d_body_center(world, body[i]);
        asleep += !ga2d_body_is_awake(world, body[i]);
        lost += fabs((double)p.x) > HALF_W || p.y < 0;
        if ((double)p.y > top) top = (double)p.y;
    }
    printf("  asleep ");
    for (i = 0; i < reports; ++i) printf(" %d at %d s%s", asleep_at[i], 2 * (i + 1), i + 1 < reports ? "," : "\n");
    if (all_asleep_at >= 0)
        printf("          all %d from %.2f s, %.2f s after the last drop (touching, the pile sleeps as one)\n",
               asleep, all_asleep_at, all_asleep_at - (double)((BODIES / PER_ROW - 1) * ROW_EVERY) / HZ);
    else
        printf("          %d of %d bodies after %d s: not all\n", asleep, BODIES, MAX_SECONDS);
    printf("  lost    %d bodies outside the bin; the highest centre is %.2f m above the floor\n", lost, top);

    snprintf(caption, sizeof caption, "pile: %d mixed shapes settle and sleep", BODIES);
    bytes = svgs_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "pile: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg     %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.base.frames);
    svgs_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
