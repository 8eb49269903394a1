/* sensor.c - a sensor zone counting what passes through it.  The zone is a
   static body whose one shape is an is_sensor box, 12 m wide and 2 m tall
   (y = 3 .. 5): it pushes nothing, and at the end of every step the world
   reports the shapes that began and ended overlapping it
   (ga2d_world_sensor_events).  Five balls (r = 0.25 m) are let go at rest
   above it, their bottoms h = 0.5, 1, 2, 3 and 4 m above its top; they fall
   through it onto the ground.  A sixth falls 1 m onto a ledge inside the
   zone and stays there; a box that falls through beside them has
   enable_sensor_events = 0, and is not seen (nor is the ledge, whose
   events are off too: sensors see static shapes).

   Free fall from rest: a ball's bottom reaches the zone's top after
       t_in  = sqrt(2 h / g)
   and its top leaves the zone's bottom after falling h + 2 m + 2 r:
       t_out = sqrt(2 (h + 2.5) / g).
   Events come at the end of a step: the one that reports them is the
   first step after which the ball has fallen that far.  The default
   integrator (symplectic Euler) has fallen g h^2 n (n + 1) / 2 after n
   substeps of h = dt / 4, a little ahead of g t^2 / 2, so that step ends
   less than a step after t_in (or t_out), or a hair before it.

   It prints, per ball, the step times of its begin and end events against
   t_in and t_out and against that step ("its step": the two should be the
   same); then the counts of begin and end events, and what the sensor
   holds at the end (ga2d_shape_get_sensor_overlaps: the ball on the
   ledge, asleep, is still in it); then the SVG (build/sensor.svg, or the
   path given as the first argument): the zone drawn see-through, and each
   body blue while the sensor reports it inside.
   Run it from the repository root.  The exit status is 0 when the world
   was built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_shapes.h"
#include <math.h>
#include <stdio.h>

#define HZ 60          /* steps per second */
#define STEPS 150      /* 2.5 s */
#define SVG_EVERY 2    /* the SVG keeps every 2nd step: 30 frames a second */
#define G 10.0
#define R 0.25         /* the balls' radius */
#define ZONE_BOTTOM 3.0
#define ZONE_TOP 5.0
#define FALLING 5      /* balls that fall through; one more lands on the ledge */
#define BALLS (FALLING + 1)
#define INSIDE_COLOR 0x4C8CE5u

static const double H[BALLS] = {0.5, 1, 2, 3, 4, 1}; /* each bottom's height above the zone */

typedef struct scene {
    ga2d_body_id body[BALLS + 1];  /* the balls, then the box */
    ga2d_shape_id shape[BALLS + 1];
    int inside[BALLS + 1];         /* the sensor says it is in */
    double t_in[BALLS + 1], t_out[BALLS + 1]; /* step times of its events; -1: none */
} scene;

/* The SVG's colour for a body: blue while inside the zone. */
static uint32_t tint(ga2d_body_id id, uint32_t color, void *context)
{
    const scene *s = (const scene *)context;
    int i;
    for (i = 0; i <= BALLS; ++i)
        if (ga2d_body_id_equal(id, s->body[i]) && s->inside[i]) return INSIDE_COLOR;
    return color;
}

/* The ball or box a visitor shape belongs to, or -1. */
static int which(const scene *s, ga2d_shape_id id)
{
    int i;
    for (i = 0; i <= BALLS; ++i)
        if (ga2d_shape_id_equal(id, s->shape[i])) return i;
    return -1;
}

/* The end of the first step after which a body let go at rest has fallen
   d: the default integrator (symplectic Euler) in n substeps of h has
   fallen g h^2 n (n + 1) / 2, a little ahead of g t^2 / 2. */
static double step_past(double d, int substeps, double dt)
{
    double h = dt / substeps;
    int k = 1;
    while (G * h * h * (k * substeps) * (k * substeps + 1) / 2 < d) ++k;
    return k * dt;
}

/* A static box of half-extents hw x hh centred on (x, y) with this shape def. */
static ga2d_shape_id static_box(ga2d_world *world, double x, double y, double hw, double hh, const ga2d_shape_def *sd,
                                ga2d_body_id *body)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_polygon p = ga2d_polygon_box((ga2d_real)hw, (ga2d_real)hh);
    bd.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    *body = ga2d_body_create(world, &bd);
    return ga2d_shape_create_polygon(world, *body, sd, &p);
}

int main(int argc, char **argv)
{
    static scene s;
    const char *svg_path = argc > 1 ? argv[1] : "build/sensor.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *world = ga2d_world_create(&wd);
    ga2d_body_def bd;
    ga2d_shape_def sd;
    ga2d_body_id zone_body, ground, ledge;
    ga2d_shape_id zone, held[8];
    ga2d_circle disc;
    ga2d_polygon square = ga2d_polygon_box(0.3f, 0.3f);
    int k, i, e, begins = 0, ends = 0, inside_now, failed = 0;
    char caption[96];
    long bytes;
    svgs rec;

    if (!world) {
        fprintf(stderr, "sensor: cannot create the world\n");
        return 1;
    }
    /* the ground (top y = 0), the zone, and a ledge inside the zone's right
       end (top y = 3.5).  Sensors see static shapes too (as Box2D v3's do):
       the ledge, inside the zone from the start, would be its first
       visitor, so its sensor events are off */
    sd = ga2d_default_shape_def();
    failed |= ga2d_shape_id_is_null(static_box(world, 0, -0.5, 8, 0.5, &sd, &ground));
    sd.enable_sensor_events = 0;
    failed |= ga2d_shape_id_is_null(static_box(world, 5.5, 3.25, 0.5, 0.25, &sd, &ledge));
    sd = ga2d_default_shape_def();
    sd.is_sensor = 1;
    zone = static_box(world, 0, (ZONE_BOTTOM + ZONE_TOP) / 2, 6, (ZONE_TOP - ZONE_BOTTOM) / 2, &sd, &zone_body);
    failed |= ga2d_shape_id_is_null(zone);

    /* the balls, 2 m apart, the last over the ledge; the box between the
       first two, unseen by sensors */
    for (i = 0; i <= BALLS; ++i) {
        bd = ga2d_default_body_def();
        bd.type = GA2D_BODY_DYNAMIC;
        sd = ga2d_default_shape_def();
        if (i < BALLS) {
            bd.position = ga2d_vec_make((ga2d_real)(i < FALLING ? -4 + 2 * i : 5.5), (ga2d_real)(ZONE_TOP + H[i] + R));
            s.body[i] = ga2d_body_create(world, &bd);
            disc.center = ga2d_vec_make(0, 0);
            disc.radius = (ga2d_real)R;
            s.shape[i] = ga2d_shape_create_circle(world, s.body[i], &sd, &disc);
        } else {
            bd.position = ga2d_vec_make(-3, (ga2d_real)(ZONE_TOP + 1));
            s.body[i] = ga2d_body_create(world, &bd);
            sd.enable_sensor_events = 0;
            s.shape[i] = ga2d_shape_create_polygon(world, s.body[i], &sd, &square);
        }
        failed |= ga2d_shape_id_is_null(s.shape[i]);
        s.t_in[i] = s.t_out[i] = -1;
    }
    if (failed) {
        fprintf(stderr, "sensor: cannot create the bodies\n");
        ga2d_world_destroy(world);
        return 1;
    }

    svgs_init(&rec, (double)dt, SVG_EVERY);
    rec.color_fn = tint;
    rec.color_context = &s;
    svgs_style(&rec, zone_body, "#4c8ce5", 0.18);
    svgs_record(&rec, world);
    for (k = 1; k <= STEPS; ++k) {
        ga2d_sensor_events ev;
        ga2d_world_step(world, dt);
        ev = ga2d_world_sensor_events(world);
        for (e = 0; e < ev.begin_count; ++e) {
            i = which(&s, ev.begin[e].visitor);
            ++begins;
            if (i >= 0) {
                s.inside[i] = 1;
                if (s.t_in[i] < 0) s.t_in[i] = k * (double)dt;
            } else
                printf("  (a begin event from a shape that is no ball: slot %u)\n", (unsigned)ev.begin[e].visitor.index1);
        }
        for (e = 0; e < ev.end_count; ++e) {
            i = which(&s, ev.end[e].visitor);
            ++ends;
            if (i >= 0) {
                s.inside[i] = 0;
                if (s.t_out[i] < 0) s.t_out[i] = k * (double)dt;
            }
        }
        svgs_record(&rec, world);
    }

    printf("sensor: a zone y = %.0f .. %.0f m; balls (r = %.2f m) dropped from rest, %.1f s at %d Hz\n", ZONE_BOTTOM,
           ZONE_TOP, R, (double)STEPS / HZ, HZ);
    printf("  ball   h (m)   begin at   sqrt(2h/g)  its step     end at   sqrt(2(h+2.5)/g)  its step\n");
    for (i = 0; i < BALLS; ++i) {
        double d_in = H[i], d_out = H[i] + ZONE_TOP - ZONE_BOTTOM + 2 * R;
        printf("  %d%s %5.1f   %7.4f s   %7.4f    %7.4f", i + 1, i < FALLING ? "      " : " ledge", H[i], s.t_in[i],
               sqrt(2 * d_in / G), step_past(d_in, wd.substeps, (double)dt));
        if (i < FALLING)
            printf("    %7.4f s   %7.4f           %7.4f\n", s.t_out[i], sqrt(2 * d_out / G),
                   step_past(d_out, wd.substeps, (double)dt));
        else
            printf("    %s\n", s.t_out[i] < 0 ? "none: it rests on the ledge, inside" : "LEFT THE ZONE");
    }
    inside_now = ga2d_shape_get_sensor_overlaps(world, zone, held, 8);
    printf("  counts: %d began, %d ended; inside at the end: %d (", begins, ends, inside_now);
    for (i = 0; i < inside_now && i < 8; ++i) {
        int b = which(&s, held[i]);
        printf("%s%s %d%s", i ? ", " : "", b == BALLS ? "the box" : "ball", b + 1,
               b >= 0 && !ga2d_body_is_awake(world, s.body[b]) ? ", asleep" : "");
    }
    printf("); the box (sensor events off): %s\n", s.t_in[BALLS] < 0 ? "never seen" : "SEEN");

    snprintf(caption, sizeof caption, "sensor: balls turn blue while the zone holds them");
    svgs_view(&rec, -7, -0.5, 7, ZONE_TOP + 4 + 2.5); /* the zone, the drops and room for the caption */
    bytes = svgs_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "sensor: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg  %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.base.frames);
    svgs_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
