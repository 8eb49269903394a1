/* terrain.c - a half-pipe made of one chain: a loop of 375 points wound
   counter-clockwise (so it holds bodies inside it) whose floor runs, left
   to right, down a quarter pipe, 20 m flat in 40 segments of 0.5 m, over
   a cosine hill 1 m high and 8 m long, through a cosine bowl 1.5 m deep
   and 10 m long (both in segments of 6.25 cm), and up a second quarter
   pipe, under a ceiling.  A 1 m box and a ball (r = 0.5 m) are launched
   along the flat at 5 m/s, the ball already rolling (w = -v / r).  They
   are filtered so as not to meet each other: each measures alone.

   The chain's friction is 0.6; the box's own is 0, so it slides without
   friction (friction mixes as sqrt(mu_a mu_b)), and the ball's 0.6, so it
   rolls.  On a smooth floor neither would lose energy (the ball rolls
   without slipping, the box has no friction), so at a height y above the
   flat their speeds would be
       box:  v^2 = v0^2 - 2 g y             (its spin aside)
       ball: v^2 = v0^2 - 4/3 g y            (1/2 m v^2 + 1/2 I w^2 with
                                              I = m r^2 / 2 and w r = v)
   and on the flat the speed is v0 exactly, across every join: a body
   that caught on a join between two segments would jump (v_y != 0) and
   slow down there.

   It prints, per body:
     flat      over the joins of the flat it crosses on its first run
               (from 0.5 m past its start to 1 m before the hill): the
               largest |v_y|, and its speed's range against v0;
     hilltop   its speed as it crosses the crest (1 m up) against the
               formula;
     bowl      the same at the bowl's bottom (1.5 m down);
     svg       the animated SVG (build/terrain.svg, or the path given as
               the first argument): the two go over the hill, through the
               bowl, up the far pipe and back, the ball's radius line
               turning as it rolls.
   A chain is a polygon, not a smooth curve: where the floor turns up (a
   valley join) a body meets the next segment with a little of its speed
   into it, and loses that part (restitution 0), so the formulas are
   bounds that a finer chain approaches.  The box, riding on a corner
   wherever the slope changes, loses most (3 % of its speed at the crest
   here, 10 % with 25 cm segments); the ball, one smooth point, loses
   0.6 % (2.4 % with 25 cm segments; part of what remains shrinks with the
   time step).
   Run it from the repository root.  The exit status is 0 when the world
   was built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_shapes.h"
#include <math.h>
#include <stdio.h>

#define HZ 60          /* steps per second */
#define STEPS 480      /* 8 s */
#define SVG_EVERY 2    /* the SVG keeps every 2nd step: 30 frames a second */
#define MAX_POINTS 512
#define V0 5.0         /* m/s, the launch speed */
#define G 10.0
#define R 0.5          /* the ball's radius */
#define HILL_X 0.0     /* the hill spans HILL_X .. HILL_X + HILL_L */
#define HILL_L 8.0
#define HILL_H 1.0
#define HILL_SEGMENTS 128 /* 6.25 cm apart */
#define BOWL_X 10.0    /* the bowl spans BOWL_X .. BOWL_X + BOWL_L */
#define BOWL_L 10.0
#define BOWL_D 1.5
#define BOWL_SEGMENTS 160 /* 6.25 cm apart */
#define PIPE_R 3.0     /* the quarter pipes' radius */
#define LEFT_X -20.0   /* the flat's left end, the left pipe's foot */
#define RIGHT_X 22.0   /* the right pipe's foot */
#define CEILING 5.0

static ga2d_vec pts[MAX_POINTS];
static int npts;

static void add(double x, double y)
{
    if (npts < MAX_POINTS) pts[npts++] = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
}

/* The half-pipe's outline, counter-clockwise from the top of the left
   pipe: the floor left to right, the right wall up, the ceiling right to
   left, the left wall down (the loop closes it). */
static void build_outline(void)
{
    const double pi = 3.14159265358979323846;
    double x;
    int i;
    npts = 0;
    for (i = 0; i < 18; ++i) { /* the left pipe, 180 to 265 degrees about (LEFT_X, PIPE_R) */
        double a = pi + i * (pi / 36);
        add(LEFT_X + PIPE_R * cos(a), PIPE_R + PIPE_R * sin(a));
    }
    for (x = LEFT_X; x < HILL_X - 1e-9; x += 0.5) add(x, 0); /* the flat: 0.5 m apart */
    for (i = 0; i < HILL_SEGMENTS; ++i) { /* the hill */
        x = HILL_X + i * (HILL_L / HILL_SEGMENTS);
        add(x, HILL_H * (1 - cos(2 * pi * (x - HILL_X) / HILL_L)) / 2);
    }
    for (x = HILL_X + HILL_L; x < BOWL_X - 1e-9; x += 0.5) add(x, 0);
    for (i = 0; i < BOWL_SEGMENTS; ++i) { /* the bowl */
        x = BOWL_X + i * (BOWL_L / BOWL_SEGMENTS);
        add(x, -BOWL_D * (1 - cos(2 * pi * (x - BOWL_X) / BOWL_L)) / 2);
    }
    for (x = BOWL_X + BOWL_L; x < RIGHT_X - 1e-9; x += 0.5) add(x, 0);
    for (i = 0; i <= 18; ++i) { /* the right pipe, 270 to 360 degrees about (RIGHT_X, PIPE_R) */
        double a = 1.5 * pi + i * (pi / 36);
        add(RIGHT_X + PIPE_R * cos(a), PIPE_R + PIPE_R * sin(a));
    }
    add(RIGHT_X + PIPE_R, CEILING);
    add(LEFT_X - PIPE_R, CEILING);
}

/* What one body did: on the flat, at the crest and at the bowl's bottom. */
typedef struct track {
    ga2d_body_id id;
    double x0;                       /* where it started */
    double max_vy, vmin, vmax;       /* on the flat, first run */
    double v_crest, v_bowl;          /* speeds when crossing, first run; -1: not reached */
    int on_flat_done;
} track;

static void follow(const ga2d_world *world, track *t)
{
    ga2d_vec c = ga2d_body_center(world, t->id), v = ga2d_body_velocity(world, t->id);
    double speed = (double)ga2d_vec_length(v), x = (double)c.x;
    if (!t->on_flat_done && x > t->x0 + 0.5 && x < HILL_X - 1) { /* clear of the start and the hill's foot */
        if (fabs((double)v.y) > t->max_vy) t->max_vy = fabs((double)v.y);
        if (speed < t->vmin) t->vmin = speed;
        if (speed > t->vmax) t->vmax = speed;
    }
    if (x >= HILL_X - 1) t->on_flat_done = 1;
    if (t->v_crest < 0 && x >= HILL_X + HILL_L / 2) t->v_crest = speed;
    if (t->v_bowl < 0 && x >= BOWL_X + BOWL_L / 2) t->v_bowl = speed;
}

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/terrain.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *world = ga2d_world_create(&wd);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_circle disc;
    ga2d_polygon square = ga2d_polygon_box(0.5f, 0.5f);
    ga2d_body_id ground;
    track t[2];
    int k, i, failed = 0;
    char caption[96];
    long bytes;
    svgs rec;

    if (!world) {
        fprintf(stderr, "terrain: cannot create the world\n");
        return 1;
    }
    /* the half-pipe: one loop chain on a static body with no other shape */
    build_outline();
    ground = ga2d_body_create(world, &bd);
    cd.points = pts;
    cd.count = npts;
    cd.is_loop = 1;
    cd.friction = 0.6f;
    failed |= ga2d_body_id_is_null(ground);
    failed |= ga2d_chain_create(world, ground, &cd).index1 == 0;

    /* the box (own friction 0) and the ball (0.6), at 5 m/s to the right;
       categories 2 and 4, each colliding with the ground (category 1) only */
    for (i = 0; i < 2; ++i) {
        bd = ga2d_default_body_def();
        bd.type = GA2D_BODY_DYNAMIC;
        bd.position = ga2d_vec_make(i == 0 ? -18.0f : -15.0f, 0.5f);
        bd.velocity = ga2d_vec_make((ga2d_real)V0, 0);
        bd.angular_velocity = i == 0 ? 0 : (ga2d_real)(-V0 / R); /* the ball rolls from the start */
        t[i].id = ga2d_body_create(world, &bd);
        t[i].x0 = (double)bd.position.x;
        t[i].max_vy = t[i].vmax = 0;
        t[i].vmin = 1e30;
        t[i].v_crest = t[i].v_bowl = -1;
        t[i].on_flat_done = 0;
        sd.friction = i == 0 ? 0 : 0.6f;
        sd.filter.category_bits = i == 0 ? 2 : 4;
        sd.filter.mask_bits = 1;
        if (i == 0) failed |= ga2d_shape_id_is_null(ga2d_shape_create_polygon(world, t[i].id, &sd, &square));
        else {
            disc.center = ga2d_vec_make(0, 0);
            disc.radius = (ga2d_real)R;
            failed |= ga2d_shape_id_is_null(ga2d_shape_create_circle(world, t[i].id, &sd, &disc));
        }
    }
    if (failed) {
        fprintf(stderr, "terrain: cannot create the bodies\n");
        ga2d_world_destroy(world);
        return 1;
    }

    svgs_init(&rec, (double)dt, SVG_EVERY);
    svgs_record(&rec, world);
    for (k = 1; k <= STEPS; ++k) {
        ga2d_world_step(world, dt);
        svgs_record(&rec, world);
        for (i = 0; i < 2; ++i) follow(world, &t[i]);
    }

    printf("terrain: a loop chain of %d points; a box and a ball at v0 = %.0f m/s, %.0f s at %d Hz\n", npts, V0,
           (double)STEPS / HZ, HZ);
    for (i = 0; i < 2; ++i) {
        double k_rot = i == 0 ? 2 * G : 4.0 / 3.0 * G; /* v^2 = v0^2 - k y */
        double crest = sqrt(V0 * V0 - k_rot * HILL_H), bowl = sqrt(V0 * V0 + k_rot * BOWL_D);
        int joins = (int)floor((-1 - LEFT_X) / 0.5) - (int)floor((t[i].x0 + 0.5 - LEFT_X) / 0.5);
        printf("  %-4s flat (%d joins): max |v_y| %.2g m/s, speed %.6f .. %.6f m/s (v0 %.1f)\n",
               i == 0 ? "box" : "ball", joins, t[i].max_vy, t[i].vmin, t[i].vmax, V0);
        printf("       hilltop %.4f m/s vs sqrt(v0^2 - %s g h) %.4f (%+.2f %%); bowl bottom %.4f vs %.4f (%+.2f %%)\n",
               t[i].v_crest, i == 0 ? "2" : "4/3", crest, 100 * (t[i].v_crest / crest - 1), t[i].v_bowl, bowl,
               100 * (t[i].v_bowl / bowl - 1));
    }

    snprintf(caption, sizeof caption, "terrain: one loop chain; a box slides, a ball rolls (v0 %.0f m/s)", V0);
    svgs_view(&rec, LEFT_X - PIPE_R - 0.5, -BOWL_D - 0.5, RIGHT_X + PIPE_R + 0.5, CEILING + 3);
    rec.pixels = 1280;
    bytes = svgs_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "terrain: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg  %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.base.frames);
    svgs_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
