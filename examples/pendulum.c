/* pendulum.c - two pendulums on joints, their periods against theory.

   A compound pendulum: a bar of 1 m x 0.1 m hung from a static body by a
   revolute joint at its top end.  About the pivot it has the inertia
   I = m (L^2 + w^2) / 12 + m d^2 (d = L / 2, its centre's distance from
   the pivot), and for a small swing the period
       T0 = 2 pi sqrt(I / (m g d)).
   From a larger amplitude a the period is longer, exactly
       T(a) = T0 2 K(sin(a / 2)) / pi,
   K the complete elliptic integral of the first kind (from the
   arithmetic-geometric mean: K(k) = pi / (2 agm(1, sqrt(1 - k^2)))).

   A rod pendulum: a ball of radius 0.1 m held 2 m from a static pivot by
   a distance joint, anchored at the ball's centre, so the ball does not
   swing round itself: a point mass, T0 = 2 pi sqrt(L / g), and the same
   factor for amplitude.

   Each is let go at rest from its amplitude and swings ten periods at 60
   steps a second in the default world.  It prints, per amplitude, the
   period measured (the mean time between the upward zero crossings of
   the angle, each interpolated within its step) against T(a), their
   difference, and the amplitude of the last swing (how much energy the
   step kept).  Last, the bar hanging at rest: the joint's reaction force
   on it against m g.  The exit status is 0 when every world was built. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include <math.h>
#include <stdio.h>

#define HZ 60         /* steps per second */
#define PERIODS 10    /* measured per amplitude */
#define G 10.0        /* the default gravity, m/s^2 */
#define BAR_L 1.0     /* the bar: length and width, m */
#define BAR_W 0.1
#define ROD_L 2.0     /* the rod pendulum's length, m */
#define BALL_R 0.1

static const double PI = 3.14159265358979323846;

/* K(k) = pi / (2 agm(1, k')), k' = sqrt(1 - k^2). */
static double elliptic_k(double k)
{
    double a = 1, b = sqrt(1 - k * k);
    while (fabs(a - b) > 1e-15 * a) {
        double m = (a + b) / 2;
        b = sqrt(a * b);
        a = m;
    }
    return PI / (2 * a);
}

typedef struct swing { double period, last_amplitude; int ok; } swing;

/* Lets the pendulum go from `amplitude` (radians from straight down) and
   measures its period.  rod = 0: the bar on a revolute joint; 1: the ball
   on a distance joint. */
static swing run(int rod, double amplitude, double expected_period)
{
    const ga2d_real dt = (ga2d_real)1 / HZ;
    const double arm = rod ? ROD_L : BAR_L / 2; /* pivot to centre of mass */
    ga2d_world *world = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id pivot, bob;
    ga2d_joint_id joint;
    swing out = {0, 0, 0};
    double prev = amplitude, first = -1, last = -1, peak = 0;
    int crossings = 0, i, steps = (int)(HZ * expected_period * (PERIODS + 1.5));

    if (!world) return out;
    bd.position = ga2d_vec_make(0, 0); /* the pivot: a static body with no shape */
    pivot = ga2d_body_create(world, &bd);

    /* the bob: its centre at `arm` from the pivot, at the angle `amplitude`
       from straight down; turned by it, so its angle is the swing's */
    bd.type = GA2D_BODY_DYNAMIC;
    bd.position = ga2d_vec_make((ga2d_real)(arm * sin(amplitude)), (ga2d_real)(-arm * cos(amplitude)));
    bd.rotor = ga2d_rotor_from_angle((ga2d_real)amplitude);
    if (!rod) bd.polygon = ga2d_polygon_box((ga2d_real)(BAR_W / 2), (ga2d_real)(BAR_L / 2));
    bob = ga2d_body_create(world, &bd);
    if (rod) {
        ga2d_shape_def sd = ga2d_default_shape_def();
        ga2d_circle ball = {{0, 0}, (ga2d_real)BALL_R};
        ga2d_distance_joint_def jd = ga2d_default_distance_joint_def();
        ga2d_shape_create_circle(world, bob, &sd, &ball);
        jd.body_a = pivot;
        jd.body_b = bob;                  /* anchors: the pivot's origin, the ball's centre */
        jd.length = (ga2d_real)ROD_L;
        joint = ga2d_distance_joint_create(world, &jd);
    } else {
        ga2d_revolute_joint_def jd = ga2d_default_revolute_joint_def();
        jd.body_a = pivot;
        jd.body_b = bob;
        jd.local_anchor_b = ga2d_vec_make(0, (ga2d_real)(BAR_L / 2)); /* the bar's top end */
        joint = ga2d_revolute_joint_create(world, &jd);
    }
    if (ga2d_joint_id_is_null(joint)) {
        ga2d_world_destroy(world);
        return out;
    }

    for (i = 1; i <= steps; ++i) {
        ga2d_vec c;
        double angle;
        ga2d_world_step(world, dt);
        c = ga2d_body_center(world, bob); /* the swing angle, from the pivot to the centre */
        angle = atan2((double)c.x, -(double)c.y);
        if (prev < 0 && angle >= 0) { /* an upward crossing, within this step */
            double t = (i - angle / (angle - prev)) / HZ;
            if (first < 0) first = t;
            last = t;
            ++crossings;
            if (crossings > PERIODS) break;
            peak = 0;
        }
        if (fabs(angle) > peak) peak = fabs(angle);
        prev = angle;
    }
    if (crossings >= 2) {
        out.period = (last - first) / (crossings - 1);
        out.last_amplitude = peak;
        out.ok = 1;
    }
    ga2d_world_destroy(world);
    return out;
}

/* The bar hanging at rest for 1 s: the joint holds it up with m g (on the
   bar, upward) and no torque. */
static int hanging(void)
{
    ga2d_world *world = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_revolute_joint_def jd = ga2d_default_revolute_joint_def();
    ga2d_joint_id joint;
    ga2d_vec f;
    int i;
    if (!world) return 1;
    jd.body_a = ga2d_body_create(world, &bd); /* the pivot, at the origin */
    bd.type = GA2D_BODY_DYNAMIC;
    bd.position = ga2d_vec_make(0, (ga2d_real)(-BAR_L / 2));
    bd.polygon = ga2d_polygon_box((ga2d_real)(BAR_W / 2), (ga2d_real)(BAR_L / 2));
    jd.body_b = ga2d_body_create(world, &bd);
    jd.local_anchor_b = ga2d_vec_make(0, (ga2d_real)(BAR_L / 2));
    joint = ga2d_revolute_joint_create(world, &jd);
    if (ga2d_joint_id_is_null(joint)) {
        ga2d_world_destroy(world);
        return 1;
    }
    for (i = 0; i < HZ; ++i) ga2d_world_step(world, (ga2d_real)1 / HZ);
    f = ga2d_joint_reaction_force(world, joint);
    printf("hanging at rest: reaction force on the bar (%.6f, %.6f) N, torque %.2g N m; m g = %.6f N\n", (double)f.x,
           (double)f.y, (double)ga2d_joint_reaction_torque(world, joint),
           (double)ga2d_body_mass_data(world, jd.body_b).mass * G);
    ga2d_world_destroy(world);
    return 0;
}

static int report(int rod, const double *amplitudes_deg, int n, double t0)
{
    int i, failed = 0;
    printf("  %9s  %10s  %10s  %10s  %14s\n", "amplitude", "T measured", "T theory", "difference", "last swing to");
    for (i = 0; i < n; ++i) {
        double a = amplitudes_deg[i] * PI / 180, t = t0 * 2 * elliptic_k(sin(a / 2)) / PI;
        swing s = run(rod, a, t);
        if (!s.ok) {
            printf("  %8.0f°  (the world or joint was not made)\n", amplitudes_deg[i]);
            failed = 1;
            continue;
        }
        printf("  %8.0f°  %8.5f s  %8.5f s  %+9.3f %%  %12.3f°\n", amplitudes_deg[i], s.period, t,
               100 * (s.period / t - 1), s.last_amplitude * 180 / PI);
    }
    return failed;
}

int main(void)
{
    const double amplitudes[] = {5, 45, 90, 135};
    const int n = (int)(sizeof amplitudes / sizeof amplitudes[0]);
    const double d = BAR_L / 2, i_pivot_per_m = (BAR_L * BAR_L + BAR_W * BAR_W) / 12 + d * d;
    const double bar_t0 = 2 * PI * sqrt(i_pivot_per_m / (G * d)), rod_t0 = 2 * PI * sqrt(ROD_L / G);
    int failed = 0;

    printf("Pendulums on joints, %d periods each at %d steps/s (default world: 4 substeps)\n", PERIODS, HZ);
    printf("compound pendulum: a %.0f m x %.1f m bar on a revolute joint at its end,\n", BAR_L, BAR_W);
    printf("  T0 = 2 pi sqrt(I_pivot / (m g d)) = %.5f s, T(a) = T0 2 K(sin(a/2)) / pi\n", bar_t0);
    failed |= report(0, amplitudes, n, bar_t0);
    printf("rod pendulum: a ball on a %.0f m distance joint, T0 = 2 pi sqrt(L / g) = %.5f s\n", ROD_L, rod_t0);
    failed |= report(1, amplitudes, n, rod_t0);
    failed |= hanging();
    return failed;
}
