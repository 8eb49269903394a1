/* ragdoll.c - a ragdoll of 11 capsules (pelvis, torso, head, two upper
   and two lower legs, two upper and two lower arms) held by 10 revolute
   joints with limits (waist, neck, hips, knees, shoulders, elbows), thrown
   tumbling onto the ground from 3 m.

   The figure is laid out standing, facing +x, feet at y = 0: each bone a
   capsule between two points, its body origin at their middle.  A joint
   is one world point (ga2d_body_local_point gives it in each bone's
   frame), and its limits are the child's angle relative to its parent's,
   counter-clockwise positive: a leg swinging forward turns +, a knee
   bending turns -.  The bones share a negative filter group, so they do
   not collide with each other, only with the ground (joined bones would
   not anyway: collide_connected is 0 by default).  The whole figure is
   then turned and lifted, and all bones given one velocity and spin, the
   right arm and leg a kick more.

   It prints, for the default world and ga2d_accurate_world_def():
     worst     the largest joint separation over the run (the distance
               between a joint's two anchors in the world, mm), and the
               step it came at;
     at rest   the largest separation once it sleeps (mm);
     asleep    when all 11 bones fell asleep (s): a ragdoll that jitters
               on the ground never does;
     limits    the largest excursion past a joint limit over the run (deg:
               at the landing, where the ground pushes a limb through
               its limit), and at the end (a limit holding a load rests
               past it by its torque over I_eff (2 pi 60 Hz)^2: a stiff
               spring, as every rigid joint row);
     svg       the default run's animated SVG (build/ragdoll.svg, or the
               path given as the first argument).
   Run it from the repository root.  The exit status is 0 when the worlds
   were built and the SVG written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_shapes.h"
#include <math.h>
#include <stdio.h>

#define BONES 11
#define JOINTS 10
#define HZ 60
#define SECONDS 10
#define SVG_EVERY 2
#define DROP_HEIGHT 3.0 /* m, of the figure's feet before it is turned */
#define TURN 1.2        /* rad: the figure's tilt when let go */

static const double PI = 3.14159265358979323846;

/* A bone: a capsule from p1 to p2 (model frame, m) of radius r. */
typedef struct bone { double x1, y1, x2, y2, r; } bone;
static const bone BONE[BONES] = {
    {0, 0.95, 0, 1.05, 0.11},  /* 0 pelvis */
    {0, 1.17, 0, 1.43, 0.13},  /* 1 torso */
    {0, 1.66, 0, 1.72, 0.10},  /* 2 head */
    {0, 0.86, 0, 0.52, 0.07},  /* 3 upper leg, left */
    {0, 0.86, 0, 0.52, 0.07},  /* 4 upper leg, right */
    {0, 0.43, 0, 0.08, 0.06},  /* 5 lower leg, left */
    {0, 0.43, 0, 0.08, 0.06},  /* 6 lower leg, right */
    {0, 1.40, 0, 1.16, 0.05},  /* 7 upper arm, left */
    {0, 1.40, 0, 1.16, 0.05},  /* 8 upper arm, right */
    {0, 1.08, 0, 0.86, 0.045}, /* 9 lower arm, left */
    {0, 1.08, 0, 0.86, 0.045}, /* 10 lower arm, right */
};

/* A joint: parent, child, the point (model frame) and the child's angle
   range relative to the parent (rad). */
typedef struct hinge { int parent, child; double x, y, lower, upper; const char *name; } hinge;
static const hinge HINGE[JOINTS] = {
    {0, 1, 0, 1.11, -0.6, 0.3, "waist"},  {1, 2, 0, 1.56, -0.5, 0.4, "neck"},
    {0, 3, 0, 0.90, -0.4, 1.5, "hip"},    {0, 4, 0, 0.90, -0.4, 1.5, "hip"},
    {3, 5, 0, 0.475, -2.2, 0, "knee"},    {4, 6, 0, 0.475, -2.2, 0, "knee"},
    {1, 7, 0, 1.45, -0.8, 2.5, "shoulder"}, {1, 8, 0, 1.45, -0.8, 2.5, "shoulder"},
    {7, 9, 0, 1.12, 0, 2.3, "elbow"},     {8, 10, 0, 1.12, 0, 2.3, "elbow"},
};

typedef struct ragdoll {
    ga2d_world *world;
    ga2d_body_id bone[BONES];
    ga2d_joint_id joint[JOINTS];
    ga2d_vec local_a[JOINTS], local_b[JOINTS];
} ragdoll;

static int build(ragdoll *s, const ga2d_world_def *wd)
{
    const ga2d_rotor turn = ga2d_rotor_from_angle((ga2d_real)TURN);
    const ga2d_vec lift = ga2d_vec_make(0, (ga2d_real)DROP_HEIGHT);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    int i, failed = 0;

    s->world = ga2d_world_create(wd);
    if (!s->world) return 1;
    bd.position = ga2d_vec_make(0, -1); /* the ground, its top at y = 0 */
    bd.polygon = ga2d_polygon_box(20, 1);
    failed |= ga2d_body_id_is_null(ga2d_body_create(s->world, &bd));

    bd = ga2d_default_body_def();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.rotor = turn;
    bd.velocity = ga2d_vec_make(2, 0);
    bd.angular_velocity = 3; /* every bone the same spin: the figure tumbles as one */
    sd.filter.group_index = -1; /* bones never collide with each other */
    for (i = 0; i < BONES; ++i) {
        const bone *b = &BONE[i];
        ga2d_vec mid = ga2d_vec_make((ga2d_real)((b->x1 + b->x2) / 2), (ga2d_real)((b->y1 + b->y2) / 2));
        ga2d_capsule c;
        c.center1 = ga2d_vec_sub(ga2d_vec_make((ga2d_real)b->x1, (ga2d_real)b->y1), mid);
        c.center2 = ga2d_vec_sub(ga2d_vec_make((ga2d_real)b->x2, (ga2d_real)b->y2), mid);
        c.radius = (ga2d_real)b->r;
        bd.position = ga2d_vec_add(ga2d_rotate(turn, mid), lift);
        s->bone[i] = ga2d_body_create(s->world, &bd);
        failed |= ga2d_body_id_is_null(s->bone[i]) ||
                  ga2d_shape_id_is_null(ga2d_shape_create_capsule(s->world, s->bone[i], &sd, &c));
    }
    /* a spinning figure: each bone's velocity is the figure's at its centre;
       the right arm and leg get a kick of their own, so the sides part */
    for (i = 0; i < BONES && !failed; ++i) {
        ga2d_vec r = ga2d_vec_sub(ga2d_body_center(s->world, s->bone[i]), ga2d_body_center(s->world, s->bone[1]));
        ga2d_vec v = ga2d_vec_add(bd.velocity, ga2d_vec_scale(ga2d_vec_perp(r), bd.angular_velocity));
        if (i == 8 || i == 10) v = ga2d_vec_add(v, ga2d_vec_make(-3, 3));
        if (i == 4 || i == 6) v = ga2d_vec_add(v, ga2d_vec_make(1, 3));
        ga2d_body_set_velocity(s->world, s->bone[i], v);
    }
    for (i = 0; i < JOINTS && !failed; ++i) {
        const hinge *h = &HINGE[i];
        ga2d_revolute_joint_def jd = ga2d_default_revolute_joint_def();
        ga2d_vec p = ga2d_vec_add(ga2d_rotate(turn, ga2d_vec_make((ga2d_real)h->x, (ga2d_real)h->y)), lift);
        jd.body_a = s->bone[h->parent];
        jd.body_b = s->bone[h->child];
        jd.local_anchor_a = s->local_a[i] = ga2d_body_local_point(s->world, jd.body_a, p);
        jd.local_anchor_b = s->local_b[i] = ga2d_body_local_point(s->world, jd.body_b, p);
        jd.enable_limit = 1;
        jd.lower_angle = (ga2d_real)h->lower;
        jd.upper_angle = (ga2d_real)h->upper;
        s->joint[i] = ga2d_revolute_joint_create(s->world, &jd);
        failed |= ga2d_joint_id_is_null(s->joint[i]);
    }
    return failed;
}

static double worst_separation(const ragdoll *s)
{
    double worst = 0;
    int k;
    for (k = 0; k < JOINTS; ++k) {
        ga2d_vec pa = ga2d_transform_apply(ga2d_body_transform(s->world, s->bone[HINGE[k].parent]), s->local_a[k]);
        ga2d_vec pb = ga2d_transform_apply(ga2d_body_transform(s->world, s->bone[HINGE[k].child]), s->local_b[k]);
        double d = (double)ga2d_vec_length(ga2d_vec_sub(pa, pb));
        if (d > worst) worst = d;
    }
    return worst;
}

/* How far past its limits any joint is now (rad). */
static double worst_overshoot(const ragdoll *s)
{
    double worst = 0;
    int k;
    for (k = 0; k < JOINTS; ++k) {
        double a = (double)ga2d_revolute_joint_angle(s->world, s->joint[k]);
        double past = a < HINGE[k].lower ? HINGE[k].lower - a : a > HINGE[k].upper ? a - HINGE[k].upper : 0;
        if (past > worst) worst = past;
    }
    return worst;
}

static int run(const char *name, const ga2d_world_def *wd, svgs *rec)
{
    const ga2d_real dt = (ga2d_real)1 / HZ;
    ragdoll s;
    double worst = 0, overshoot = 0, asleep_at = -1;
    int i, worst_step = 0;

    if (build(&s, wd)) {
        fprintf(stderr, "ragdoll: cannot build the %s world\n", name);
        if (s.world) ga2d_world_destroy(s.world);
        return 1;
    }
    if (rec) svgs_record(rec, s.world);
    for (i = 1; i <= HZ * SECONDS; ++i) {
        double d, o;
        ga2d_world_step(s.world, dt);
        if (rec) svgs_record(rec, s.world);
        d = worst_separation(&s);
        o = worst_overshoot(&s);
        if (d > worst) {
            worst = d;
            worst_step = i;
        }
        if (o > overshoot) overshoot = o;
        if (asleep_at < 0 && ga2d_world_get_counters(s.world).awake_body_count == 0) asleep_at = (double)i / HZ;
    }
    printf("  %-8s  worst %5.2f mm (step %3d)   at rest %6.3f mm   ", name, 1e3 * worst, worst_step,
           1e3 * worst_separation(&s));
    if (asleep_at < 0) printf("still awake at %d s", SECONDS);
    else printf("asleep at %.2f s", asleep_at);
    printf("   limits passed by %.2f deg (at the landing), %.2f at rest\n", overshoot * 180 / PI,
           worst_overshoot(&s) * 180 / PI);
    ga2d_world_destroy(s.world);
    return 0;
}

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/ragdoll.svg";
    ga2d_world_def def = ga2d_default_world_def(), accurate = ga2d_accurate_world_def();
    svgs rec;
    long bytes;
    int failed = 0;

    printf("Ragdoll: %d capsules, %d revolute joints with limits, thrown spinning onto the ground, %d s at %d steps/s\n",
           BONES, JOINTS, SECONDS, HZ);
    svgs_init(&rec, 1.0 / HZ, SVG_EVERY);
    failed |= run("default", &def, &rec);
    failed |= run("accurate", &accurate, NULL);
    bytes = svgs_write(&rec, svg_path, "A ragdoll of 11 capsules on revolute joints with limits");
    if (bytes < 0) {
        fprintf(stderr, "ragdoll: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg       %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.base.frames);
    svgs_free(&rec);
    return failed;
}
