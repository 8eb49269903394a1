/* platform.c - a one-way platform and hit events.  The platform is a
   static box 8 m wide and 0.2 m thick, its top at y = 3.1 m, whose shape
   has enable_pre_solve_events: before the solver, the world asks the
   callback (world def pre_solve) about each of its touching contacts, and
   a contact the callback turns down does not push in that step.  This one
   turns down a body that is below the platform or moving up through it,
   so balls thrown up from the ground pass through it, and land on it on
   their way down.  The balls' shapes have enable_hit_events: a contact
   whose points came together faster than the world's hit_event_threshold
   (1 m/s) and pushed is reported with its approach speed
   (ga2d_world_contact_events(w).hit), for sounds and damage.

   Four balls (r = 0.25 m) leave the ground at v0 = 6, 9, 10 and 11 m/s.
   The first rises 1.8 m, short of the platform, and comes back down at
       v = v0                                   onto the ground;
   the others pass up through the platform and fall back onto it from
   their top, v0^2 / 2g, at
       v = sqrt(v0^2 - 2 g d),  d = 3.1 m (ground to platform top),
   at t = (v0 + v) / g.  A hit is reported by the step in which the ball
   reaches the surface (the default integrator's path runs a little ahead
   of the parabola, g t h / 2 lower with h = dt / 4: a few ms), and its
   approach speed is the solver's, taken as that step begins: the ball's
   speed then, |v0 - g t0|, which is up to a step of gravity, g dt =
   0.17 m/s, under the speed v of the touch itself.

   It prints, per ball, where it landed, the touch's time t, the end of
   the step that reported the hit, the hit's approach speed against the
   ball's speed as that step began and against v, and where the ball
   rests; then how often the callback turned a contact down;
   then the SVG (build/platform.svg, or the path given as the first
   argument).
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
#define BALLS 4
#define PLATFORM_Y 3.0 /* the platform's middle; it is 0.2 m thick */
#define PLATFORM_TOP 3.1

static const double V0[BALLS] = {6, 9, 10, 11};

typedef struct one_way {
    const ga2d_world *world;
    ga2d_shape_id platform;
    int turned_down;   /* contacts the callback turned down, step by step */
} one_way;

/* The world's pre-solve callback.  The normal points from shape A to shape
   B; seen from the platform it should point up at the other body, and that
   body should not be rising through it (faster than 0.5 m/s up: a body
   resting on the platform may creep up by a hair as the contact settles).
   The world is locked: this only reads it. */
static int one_way_platform(ga2d_shape_id shape_a, ga2d_shape_id shape_b, const ga2d_manifold *m, void *context)
{
    one_way *p = (one_way *)context;
    double up; /* the normal from the platform toward the other body, its y */
    ga2d_shape_id other;
    if (ga2d_shape_id_equal(shape_a, p->platform)) {
        up = (double)m->normal.y;
        other = shape_b;
    } else if (ga2d_shape_id_equal(shape_b, p->platform)) {
        up = -(double)m->normal.y;
        other = shape_a;
    } else
        return 1;
    if (up > 0.5 && (double)ga2d_body_velocity(p->world, ga2d_shape_body(p->world, other)).y < 0.5) return 1;
    ++p->turned_down;
    return 0;
}

/* The height of a ball's bottom, to the millimetre (-0.000 shown as 0). */
static double rest_y(const ga2d_world *world, ga2d_body_id id)
{
    double y = (double)ga2d_body_position(world, id).y - R;
    return fabs(y) < 5e-4 ? 0 : y;
}

int main(int argc, char **argv)
{
    static one_way oneway;
    const char *svg_path = argc > 1 ? argv[1] : "build/platform.svg";
    const ga2d_real dt = (ga2d_real)1 / HZ;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *world;
    ga2d_body_def bd;
    ga2d_shape_def sd;
    ga2d_body_id platform_body, ball[BALLS];
    ga2d_shape_id shape[BALLS];
    ga2d_polygon slab = ga2d_polygon_box(4, 0.1f);
    ga2d_circle disc;
    double hit_t[BALLS], hit_v[BALLS];
    int hit_on_platform[BALLS], k, i, e, hits = 0, failed = 0;
    char caption[96];
    long bytes;
    svgs rec;

    wd.pre_solve = one_way_platform;
    wd.pre_solve_context = &oneway;
    world = ga2d_world_create(&wd);
    if (!world) {
        fprintf(stderr, "platform: cannot create the world\n");
        return 1;
    }
    oneway.world = world;

    /* the ground, top y = 0 */
    bd = ga2d_default_body_def();
    bd.position = ga2d_vec_make(0, -0.5f);
    bd.polygon = ga2d_polygon_box(6, 0.5f);
    failed |= ga2d_body_id_is_null(ga2d_body_create(world, &bd));
    /* the platform: a body with no shape, given one that asks for pre-solve */
    bd = ga2d_default_body_def();
    bd.position = ga2d_vec_make(0, (ga2d_real)PLATFORM_Y);
    platform_body = ga2d_body_create(world, &bd);
    sd = ga2d_default_shape_def();
    sd.enable_pre_solve_events = 1;
    oneway.platform = ga2d_shape_create_polygon(world, platform_body, &sd, &slab);
    failed |= ga2d_shape_id_is_null(oneway.platform);

    /* the balls, resting on the ground 2 m apart, thrown up */
    sd = ga2d_default_shape_def();
    sd.enable_hit_events = 1;
    disc.center = ga2d_vec_make(0, 0);
    disc.radius = (ga2d_real)R;
    for (i = 0; i < BALLS; ++i) {
        bd = ga2d_default_body_def();
        bd.type = GA2D_BODY_DYNAMIC;
        bd.position = ga2d_vec_make((ga2d_real)(-3 + 2 * i), (ga2d_real)R);
        bd.velocity = ga2d_vec_make(0, (ga2d_real)V0[i]);
        ball[i] = ga2d_body_create(world, &bd);
        shape[i] = ga2d_shape_create_circle(world, ball[i], &sd, &disc);
        failed |= ga2d_shape_id_is_null(shape[i]);
        hit_t[i] = hit_v[i] = -1;
        hit_on_platform[i] = 0;
    }
    if (failed) {
        fprintf(stderr, "platform: cannot create the bodies\n");
        ga2d_world_destroy(world);
        return 1;
    }

    svgs_init(&rec, (double)dt, SVG_EVERY);
    svgs_record(&rec, world);
    for (k = 1; k <= STEPS; ++k) {
        ga2d_contact_events ev;
        ga2d_world_step(world, dt);
        ev = ga2d_world_contact_events(world);
        for (e = 0; e < ev.hit_count; ++e) {
            const ga2d_contact_hit_event *h = &ev.hit[e];
            ++hits;
            for (i = 0; i < BALLS; ++i)
                if ((ga2d_shape_id_equal(h->shape_a, shape[i]) || ga2d_shape_id_equal(h->shape_b, shape[i])) &&
                    hit_t[i] < 0) {
                    hit_t[i] = k * (double)dt;
                    hit_v[i] = (double)h->approach_speed;
                    hit_on_platform[i] =
                        ga2d_shape_id_equal(h->shape_a, oneway.platform) || ga2d_shape_id_equal(h->shape_b, oneway.platform);
                }
        }
        svgs_record(&rec, world);
    }

    printf("platform: one-way by pre-solve, top at %.1f m; balls thrown up, %.1f s at %d Hz\n", PLATFORM_TOP,
           (double)STEPS / HZ, HZ);
    printf("  v0 (m/s)  landed on   touch at t   hit step ends   approach   |v0 - g t0|   touch speed v   rests at\n");
    for (i = 0; i < BALLS; ++i) {
        int over = V0[i] * V0[i] > 2 * G * (PLATFORM_TOP + 2 * R); /* its top clears the platform */
        double v = over ? sqrt(V0[i] * V0[i] - 2 * G * PLATFORM_TOP) : V0[i], t = (V0[i] + v) / G;
        double t0 = hit_t[i] - (double)dt; /* when the hit's step began */
        printf("  %5.1f     %-9s   %6.4f s     %6.4f s        %6.4f     %6.4f        %6.4f          y = %.3f m\n",
               V0[i], hit_t[i] < 0 ? "(no hit)" : hit_on_platform[i] ? "platform" : "ground", t, hit_t[i], hit_v[i],
               fabs(V0[i] - G * t0), v, rest_y(world, ball[i]));
    }
    printf("  %d hit events; the callback turned a contact down %d times (balls passing up through)\n", hits,
           oneway.turned_down);

    snprintf(caption, sizeof caption, "platform: one-way by pre-solve; balls pass up, land on it");
    bytes = svgs_write(&rec, svg_path, caption);
    if (bytes < 0) {
        fprintf(stderr, "platform: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg  %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.base.frames);
    svgs_free(&rec);
    ga2d_world_destroy(world);
    return failed;
}
