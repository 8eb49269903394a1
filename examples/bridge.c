/* bridge.c - a rope bridge: 20 planks of 1 m x 0.25 m joined end to end by
   revolute joints, its ends hinged to two static posts 20 m apart, and a
   heavy box (1 m, 40 times a plank's mass, twice the whole bridge's)
   dropped on its middle from 3 m above.

   Each joint's anchors are one world point given in each body's own frame
   (ga2d_body_local_point).  A joint holds when its two anchors stay
   together: their distance in the world is the joint's separation.  The
   planks span the gap exactly, so the bridge can only sag as far as the
   joints give: a rigid joint is held by a stiff spring (60 Hz position
   feedback), and the box's weight pulls the planks nearly straight, so a
   stretch of 2 cm per joint is a sag of almost 2 m.  Stretched so, the
   bridge is a trampoline whose springs are damped for a plank's mass,
   not the box's: it bounces for a long time.  Joint friction damps it:
   each joint's motor, at speed 0 with at most FRICTION N m, resists the
   planks turning against each other (as a rusty hinge).

   It prints, for the default world, the default world without joint
   friction, and ga2d_accurate_world_def() (8 substeps) with and without:
     worst     the largest joint separation over the run (mm), and the
               step it came at (the impact);
     at end    the largest separation at the end of the run (at rest);
     sag       how far the box sits below where the planks started (cm);
     asleep    the time the box and planks fell asleep (s);
     svg       the default run's animated SVG (build/bridge.svg, or the
               path given as the first argument).
   Run it from the repository root.  The exit status is 0 when the worlds
   were built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_writer.h"
#include <math.h>
#include <stdio.h>

#define PLANKS 20
#define JOINTS (PLANKS + 1)
#define DECK_Y 5.0      /* the deck's height, m */
#define BOX_DENSITY 10  /* kg/m^2: a 1 m box of 10 kg; a plank is 0.25 kg */
#define HZ 60
#define SECONDS 60
#define FRICTION 5      /* N m: each joint's friction torque (its motor at speed 0) */
#define SVG_EVERY 2

typedef struct bridge {
    ga2d_world *world;
    double friction;
    ga2d_body_id box;
    ga2d_joint_id joint[JOINTS];
    ga2d_body_id a[JOINTS], b[JOINTS];
    ga2d_vec local_a[JOINTS], local_b[JOINTS];
} bridge;

/* A revolute joint between a and b at the world point p. */
static int hinge(bridge *s, int k, ga2d_body_id a, ga2d_body_id b, ga2d_vec p)
{
    ga2d_revolute_joint_def jd = ga2d_default_revolute_joint_def();
    jd.enable_motor = s->friction > 0; /* motor_speed 0: a brake of at most max_motor_torque */
    jd.max_motor_torque = (ga2d_real)s->friction;
    jd.body_a = s->a[k] = a;
    jd.body_b = s->b[k] = b;
    jd.local_anchor_a = s->local_a[k] = ga2d_body_local_point(s->world, a, p);
    jd.local_anchor_b = s->local_b[k] = ga2d_body_local_point(s->world, b, p);
    s->joint[k] = ga2d_revolute_joint_create(s->world, &jd);
    return ga2d_joint_id_is_null(s->joint[k]);
}

static int build(bridge *s, const ga2d_world_def *wd, double friction)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id left, right, prev;
    int i, failed = 0;

    s->friction = friction;
    s->world = ga2d_world_create(wd);
    if (!s->world) return 1;
    bd.position = ga2d_vec_make(0, -1); /* the ground, its top at y = 0 */
    bd.polygon = ga2d_polygon_box(20, 1);
    failed |= ga2d_body_id_is_null(ga2d_body_create(s->world, &bd));
    bd.polygon = ga2d_polygon_box(0.25f, (ga2d_real)(DECK_Y / 2)); /* the posts, outside the gap */
    bd.position = ga2d_vec_make(-10.25f, (ga2d_real)(DECK_Y / 2));
    left = ga2d_body_create(s->world, &bd);
    bd.position = ga2d_vec_make(10.25f, (ga2d_real)(DECK_Y / 2));
    right = ga2d_body_create(s->world, &bd);

    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box(0.5f, 0.125f);
    prev = left;
    for (i = 0; i < PLANKS; ++i) { /* plank i spans x = -10 + i .. -9 + i */
        ga2d_body_id plank;
        bd.position = ga2d_vec_make((ga2d_real)(-9.5 + i), (ga2d_real)DECK_Y);
        plank = ga2d_body_create(s->world, &bd);
        failed |= ga2d_body_id_is_null(plank) || hinge(s, i, prev, plank, ga2d_vec_make((ga2d_real)(-10 + i), (ga2d_real)DECK_Y));
        prev = plank;
    }
    failed |= hinge(s, PLANKS, prev, right, ga2d_vec_make(10, (ga2d_real)DECK_Y));

    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    bd.density = BOX_DENSITY;
    bd.position = ga2d_vec_make(0, (ga2d_real)(DECK_Y + 3));
    s->box = ga2d_body_create(s->world, &bd);
    return failed | ga2d_body_id_is_null(s->box);
}

/* The largest distance between a joint's two anchors in the world. */
static double worst_separation(const bridge *s)
{
    double worst = 0;
    int k;
    for (k = 0; k < JOINTS; ++k) {
        ga2d_vec pa = ga2d_transform_apply(ga2d_body_transform(s->world, s->a[k]), s->local_a[k]);
        ga2d_vec pb = ga2d_transform_apply(ga2d_body_transform(s->world, s->b[k]), s->local_b[k]);
        double d = (double)ga2d_vec_length(ga2d_vec_sub(pa, pb));
        if (d > worst) worst = d;
    }
    return worst;
}

static int run(const char *name, const ga2d_world_def *wd, double friction, svgw *rec)
{
    const ga2d_real dt = (ga2d_real)1 / HZ;
    bridge s;
    double worst = 0, asleep_at = -1;
    int i, worst_step = 0;

    if (build(&s, wd, friction)) {
        fprintf(stderr, "bridge: cannot build the %s world\n", name);
        if (s.world) ga2d_world_destroy(s.world);
        return 1;
    }
    if (rec) svgw_record(rec, s.world);
    for (i = 1; i <= HZ * SECONDS; ++i) {
        double d;
        ga2d_world_step(s.world, dt);
        if (rec) svgw_record(rec, s.world);
        d = worst_separation(&s);
        if (d > worst) {
            worst = d;
            worst_step = i;
        }
        if (asleep_at < 0 && !ga2d_body_is_awake(s.world, s.box)) asleep_at = (double)i / HZ;
    }
    printf("  %-11s  worst %6.2f mm (step %3d)   at end %6.3f mm   sag %5.1f cm   ", name, 1e3 * worst, worst_step,
           1e3 * worst_separation(&s), 100 * (DECK_Y + 0.125 + 0.5 - (double)ga2d_body_center(s.world, s.box).y));
    if (asleep_at < 0) printf("still awake at %d s\n", SECONDS);
    else printf("asleep at %.2f s\n", asleep_at);
    ga2d_world_destroy(s.world);
    return 0;
}

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/bridge.svg";
    ga2d_world_def def = ga2d_default_world_def(), accurate = ga2d_accurate_world_def();
    svgw rec;
    long bytes;
    int failed = 0;

    printf("Bridge: %d planks on %d revolute joints (friction %d N m), a %d kg box dropped on it, %d s at %d steps/s\n",
           PLANKS, JOINTS, FRICTION, BOX_DENSITY, SECONDS, HZ);
    svgw_init(&rec, 1.0 / HZ, SVG_EVERY);
    failed |= run("default", &def, FRICTION, &rec);
    failed |= run("no friction", &def, 0, NULL);
    failed |= run("accurate", &accurate, FRICTION, NULL);
    failed |= run("acc. no fr.", &accurate, 0, NULL);
    bytes = svgw_write(&rec, svg_path, "A bridge of 20 planks on revolute joints, a 10 kg box dropped on it");
    if (bytes < 0) {
        fprintf(stderr, "bridge: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg          %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024, rec.frames);
    svgw_free(&rec);
    return failed;
}
