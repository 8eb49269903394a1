/* cantilever.c - how rigid a rigid joint is: five boxes of 0.5 m x 0.25 m
   welded end to end, the first welded to a static wall, held level under
   gravity.

   A rigid joint is a soft-step constraint: its position error is pushed
   out by a stiff spring of 60 Hz (damping ratio 2; at most a quarter of
   the substep rate), so under a steady load it gives a little, as a
   spring k = I_eff w^2 would (w = 2 pi 60, I_eff the joint's effective
   inertia: I for the weld on the wall, I / 2 between two boxes).  Weld j
   carries the moment of the n - j boxes beyond it, m g L (n - j)^2 / 2,
   so it turns by that over k, and the tip drops by the sum of each turn
   times the tip's distance from its weld:
       sag = 6 g L^2 / ((L^2 + h^2) w^2) (n^3 + 2 sum_{j=1}^{n-1} (n-j)^3)
   for boxes L x h (I = m (L^2 + h^2) / 12; the mass cancels, so the sag
   does not depend on density).  The welds' linear rows give a little
   more, their coupling a little less.  A soft weld (angular_hertz) sags
   as the same formula with its own hertz, while the angles stay small.

   It prints the tip's sag after 20 s (at rest) for the rigid welds in the
   default and the accurate world, and for soft welds of 30 Hz, each
   against the formula.  The exit status is 0 when every world was built. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include <math.h>
#include <stdio.h>

#define BOXES 5
#define L 0.5   /* m, each box's length */
#define H 0.25  /* m, its height */
#define G 10.0
#define HZ 60
#define SECONDS 20 /* the soft welds ring for seconds: their damping ratio is
                      for one box, the beam swings with all five */

static const double PI = 3.14159265358979323846;

/* The tip's sag (m) predicted for welds of `hertz`. */
static double predicted_sag(double hertz)
{
    double w = 2 * PI * hertz, sum = BOXES * BOXES * BOXES;
    int j;
    for (j = 1; j < BOXES; ++j) sum += 2.0 * (BOXES - j) * (BOXES - j) * (BOXES - j);
    return 6 * G * L * L / ((L * L + H * H) * w * w) * sum;
}

/* The tip's sag (m) after SECONDS, or -1 when the world was not built.
   angular_hertz 0: rigid. */
static double measure(const ga2d_world_def *wd, double angular_hertz)
{
    ga2d_world *world = ga2d_world_create(wd);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_weld_joint_def jd = ga2d_default_weld_joint_def();
    ga2d_body_id prev, box = ga2d_body_id_null();
    ga2d_vec tip;
    int i, failed = 0;

    if (!world) return -1;
    bd.position = ga2d_vec_make(-0.5f, 0); /* the wall: its right face at x = 0 */
    bd.polygon = ga2d_polygon_box(0.5f, 2);
    prev = ga2d_body_create(world, &bd);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)(L / 2), (ga2d_real)(H / 2));
    jd.angular_hertz = (ga2d_real)angular_hertz;
    jd.angular_damping_ratio = 1;
    for (i = 0; i < BOXES; ++i) {
        ga2d_vec join = ga2d_vec_make((ga2d_real)(i * L), 0);
        bd.position = ga2d_vec_make((ga2d_real)((i + 0.5) * L), 0);
        box = ga2d_body_create(world, &bd);
        jd.body_a = prev;
        jd.body_b = box;
        jd.local_anchor_a = ga2d_body_local_point(world, prev, join);
        jd.local_anchor_b = ga2d_body_local_point(world, box, join);
        failed |= ga2d_joint_id_is_null(ga2d_weld_joint_create(world, &jd));
        prev = box;
    }
    for (i = 0; i < HZ * SECONDS; ++i) ga2d_world_step(world, (ga2d_real)1 / HZ);
    tip = ga2d_transform_apply(ga2d_body_transform(world, box), ga2d_vec_make((ga2d_real)(L / 2), 0));
    ga2d_world_destroy(world);
    return failed ? -1 : -(double)tip.y;
}

int main(void)
{
    ga2d_world_def def = ga2d_default_world_def(), accurate = ga2d_accurate_world_def();
    const char *names[3] = {"rigid, default", "rigid, accurate", "soft 30 Hz"};
    const double hertz[3] = {0, 0, 30}, spring[3] = {60, 60, 30};
    int k, failed = 0;

    printf("Cantilever: %d boxes of %.2f m x %.2f m welded end to end to a wall, tip sag after %d s\n", BOXES, L, H,
           SECONDS);
    for (k = 0; k < 3; ++k) {
        double sag = measure(k == 1 ? &accurate : &def, hertz[k]), want = predicted_sag(spring[k]);
        if (sag < 0) {
            printf("  %-16s  (the world or a joint was not made)\n", names[k]);
            failed = 1;
            continue;
        }
        printf("  %-16s  sag %6.2f cm   springs of %2.0f Hz predict %6.2f cm\n", names[k], 100 * sag, spring[k], 100 * want);
    }
    return failed;
}
