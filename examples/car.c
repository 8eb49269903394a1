/* car.c - a car (a chassis and two wheels on wheel joints with motors)
   drives over a bumpy terrain made of one chain, climbs a 15 degree ramp,
   parks on it with its motors braking (motor speed 0), drives on again and
   stops at the far end.

   The terrain, left to right (one open chain, segments of 25 cm):
     x = -12 .. 0    flat (the car starts at x = -8);
     x =   0 .. 16   eight cosine bumps, 20 cm high and 2 m long, whose
                     valleys are joins where the chain turns up;
     x =  16 .. 20   flat;
     x =  20 .. 27.7 a straight 15 degree ramp, 8 m along its slope;
     then a plateau 10 m long ending in a wall.
   The car: a 2.4 m x 0.5 m chassis of 1.2 kg; two discs of radius 0.4 m
   and 0.5 kg (density 1), on wheel joints 0.9 m either side of the
   chassis's middle, 0.5 m below it, whose suspension is a 4 Hz spring
   with damping ratio 0.7 and whose motors drive at DRIVE rad/s (clockwise:
   forward) with at most TORQUE N m, through friction 0.6.

   A wheel joint keeps the wheel's anchor on the chassis's axis: off it,
   the joint is held by its position feedback, a stiff spring (60 Hz,
   damping ratio 2, on the mass the joint sees), and the distance off the
   axis is the joint's separation.  A braked wheel is held at the
   chassis's turn by the motor (a velocity row: no position feedback), so
   a parked car can only creep by what is left of that row's speed.

   It prints, for the default world and ga2d_accurate_world_def():
     worst     the largest wheel joint separation over the run (mm);
     sink      the deepest a wheel went into the terrain (mm; a wheel
               through the chain would be 400 mm or more);
     bumps     the time from the chassis's centre at x = 0 to x = 16 (s);
     creep     how far the parked chassis moved in the 4 s after the
               first 2 s of braking (mm).  Sleep is off in both worlds:
               a sleeping car cannot creep, so it must not be what holds
               the car still;
     far end   when the car reached the plateau's end (s), counted from
               the start and including the parking time.
   and writes the default run's animated SVG (build/car.svg, or the path
   given as the first argument).  Run it from the repository root.  The
   exit status is 0 when the worlds were built, the car arrived both
   times and the SVG was written. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "svg_shapes.h"
#include <math.h>
#include <stdio.h>

#define HZ 60
#define MAX_SECONDS 40
#define SVG_EVERY 2
#define MAX_POINTS 256
#define STEP_X 0.25      /* m, the chain's segment length on the flats and bumps */
#define BUMPS 8
#define BUMP_L 2.0       /* m, a bump's length */
#define BUMP_H 0.2       /* m, its height */
#define RAMP_X 20.0      /* the ramp's foot */
#define RAMP_L 8.0       /* m, along its slope */
#define SLOPE_DEG 15.0
#define PLATEAU_L 10.0
#define WHEEL_R 0.4
#define DRIVE -10.0      /* rad/s: 4 m/s on the flat */
#define TORQUE 20.0      /* N m */
#define PARK_SECONDS 6.0 /* braked on the ramp */
#define SETTLE_SECONDS 2.0 /* of them to stop; the creep is measured over the rest */

static const double PI = 3.14159265358979323846;

typedef struct car {
    ga2d_world *world;
    ga2d_body_id chassis, wheel[2];
    ga2d_joint_id joint[2];
    ga2d_vec pts[MAX_POINTS];
    int npts;
    double ramp_top_x, ramp_top_y, end_x;
} car;

static void add(car *s, double x, double y)
{
    if (s->npts < MAX_POINTS) s->pts[s->npts++] = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
}

/* The terrain's outline, left to right (a chain pushes to its left: up). */
static void outline(car *s)
{
    const double slope = SLOPE_DEG * PI / 180;
    double x;
    int i;
    s->npts = 0;
    add(s, -12, 3); /* a wall behind the start */
    for (x = -12; x < -1e-9; x += STEP_X) add(s, x, 0);
    for (i = 0; i < (int)(BUMPS * BUMP_L / STEP_X); ++i) {
        x = i * STEP_X;
        add(s, x, BUMP_H * (1 - cos(2 * PI * x / BUMP_L)) / 2);
    }
    for (x = BUMPS * BUMP_L; x < RAMP_X - 1e-9; x += STEP_X) add(s, x, 0);
    s->ramp_top_x = RAMP_X + RAMP_L * cos(slope);
    s->ramp_top_y = RAMP_L * sin(slope);
    add(s, RAMP_X, 0);
    add(s, s->ramp_top_x, s->ramp_top_y);
    s->end_x = s->ramp_top_x + PLATEAU_L;
    add(s, s->end_x, s->ramp_top_y);
    add(s, s->end_x, s->ramp_top_y + 3); /* the wall at the far end */
}

static int build(car *s, const ga2d_world_def *wd)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_body_id ground;
    int k, failed = 0;

    s->world = ga2d_world_create(wd);
    if (!s->world) return 1;
    outline(s);
    ground = ga2d_body_create(s->world, &bd);
    cd.points = s->pts;
    cd.count = s->npts;
    failed |= ga2d_body_id_is_null(ground) || ga2d_chain_create(s->world, ground, &cd).index1 == 0;

    bd.type = GA2D_BODY_DYNAMIC;
    bd.position = ga2d_vec_make(-8, (ga2d_real)(WHEEL_R + 0.5));
    bd.polygon = ga2d_polygon_box(1.2f, 0.25f);
    bd.density = 1;
    s->chassis = ga2d_body_create(s->world, &bd);
    failed |= ga2d_body_id_is_null(s->chassis);
    for (k = 0; k < 2 && !failed; ++k) {
        ga2d_wheel_joint_def jd = ga2d_default_wheel_joint_def();
        ga2d_circle disc;
        bd = ga2d_default_body_def();
        bd.type = GA2D_BODY_DYNAMIC;
        bd.position = ga2d_vec_make(k ? -7.1f : -8.9f, (ga2d_real)WHEEL_R);
        s->wheel[k] = ga2d_body_create(s->world, &bd);
        disc.center = ga2d_vec_make(0, 0);
        disc.radius = (ga2d_real)WHEEL_R;
        sd.density = 1;
        sd.friction = 0.6f;
        failed |= ga2d_body_id_is_null(s->wheel[k]) ||
                  ga2d_shape_id_is_null(ga2d_shape_create_circle(s->world, s->wheel[k], &sd, &disc));
        jd.body_a = s->chassis;
        jd.body_b = s->wheel[k];
        jd.local_anchor_a = ga2d_vec_make(k ? 0.9f : -0.9f, -0.5f);
        jd.hertz = 4;
        jd.damping_ratio = 0.7f;
        jd.enable_motor = 1;
        jd.motor_speed = (ga2d_real)DRIVE;
        jd.max_motor_torque = (ga2d_real)TORQUE;
        s->joint[k] = ga2d_wheel_joint_create(s->world, &jd);
        failed |= ga2d_joint_id_is_null(s->joint[k]);
    }
    return failed;
}

/* A wheel joint's separation: how far the wheel's centre (its anchor)
   is off the chassis's axis through the joint's anchor. */
static double separation(const car *s, int k)
{
    ga2d_transform xc = ga2d_body_transform(s->world, s->chassis);
    ga2d_vec a = ga2d_transform_apply(xc, ga2d_vec_make(k ? 0.9f : -0.9f, -0.5f));
    ga2d_vec axis = ga2d_rotate(xc.q, ga2d_vec_make(0, 1));
    ga2d_vec d = ga2d_vec_sub(ga2d_body_position(s->world, s->wheel[k]), a);
    return fabs((double)ga2d_wedge(axis, d));
}

/* How deep a disc of radius r at c is in the terrain: r less its distance
   to the nearest segment (negative: clear of it). */
static double sink(const car *s, ga2d_vec c)
{
    double best = 1e30, px = (double)c.x, py = (double)c.y;
    int i;
    for (i = 0; i + 1 < s->npts; ++i) {
        double ax = (double)s->pts[i].x, ay = (double)s->pts[i].y;
        double dx = (double)s->pts[i + 1].x - ax, dy = (double)s->pts[i + 1].y - ay;
        double t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy), d;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        d = hypot(px - ax - t * dx, py - ay - t * dy);
        if (d < best) best = d;
    }
    return WHEEL_R - best;
}

static void set_motors(car *s, double speed)
{
    int k;
    for (k = 0; k < 2; ++k) ga2d_wheel_joint_set_motor_speed(s->world, s->joint[k], (ga2d_real)speed);
}

static int run(const char *name, const ga2d_world_def *wd, svgs *rec)
{
    const double slope = SLOPE_DEG * PI / 180;
    const ga2d_real dt = (ga2d_real)1 / HZ;
    car s;
    double worst = 0, deepest = -1, t_bumps0 = -1, t_bumps1 = -1, t_park = -1, t_end = -1, creep = 0;
    ga2d_vec parked = ga2d_vec_make(0, 0);
    int i, k, worst_step = 0;

    if (build(&s, wd)) {
        fprintf(stderr, "car: cannot build the %s world\n", name);
        if (s.world) ga2d_world_destroy(s.world);
        return 1;
    }
    if (rec) svgs_record(rec, s.world);
    for (i = 1; i <= HZ * MAX_SECONDS && t_end < 0; ++i) {
        double t = (double)i / HZ, x;
        ga2d_world_step(s.world, dt);
        if (rec) svgs_record(rec, s.world);
        for (k = 0; k < 2; ++k) {
            double d = separation(&s, k), z = sink(&s, ga2d_body_position(s.world, s.wheel[k]));
            if (d > worst) {
                worst = d;
                worst_step = i;
            }
            if (z > deepest) deepest = z;
        }
        x = (double)ga2d_body_center(s.world, s.chassis).x;
        if (t_bumps0 < 0 && x >= 0) t_bumps0 = t;
        if (t_bumps1 < 0 && x >= BUMPS * BUMP_L) t_bumps1 = t;
        /* park when the chassis's middle is halfway up the ramp */
        if (t_park < 0 && x >= RAMP_X + RAMP_L * cos(slope) / 2) {
            t_park = t;
            set_motors(&s, 0);
        }
        if (t_park > 0 && fabs(t - (t_park + SETTLE_SECONDS)) < 0.5 / HZ) parked = ga2d_body_center(s.world, s.chassis);
        if (t_park > 0 && fabs(t - (t_park + PARK_SECONDS)) < 0.5 / HZ) {
            ga2d_vec now = ga2d_body_center(s.world, s.chassis);
            creep = (double)ga2d_vec_length(ga2d_vec_sub(now, parked));
            set_motors(&s, DRIVE);
        }
        if (x >= s.end_x - 2.5) t_end = t;
    }
    printf("  %-8s  worst %5.2f mm (at %5.2f s)   sink %5.2f mm   bumps %5.2f s   creep %.4f mm   ", name, 1e3 * worst,
           (double)worst_step / HZ, 1e3 * deepest, t_bumps1 - t_bumps0, 1e3 * creep);
    if (t_end < 0) printf("far end not reached in %d s\n", MAX_SECONDS);
    else printf("far end at %.2f s\n", t_end);
    ga2d_world_destroy(s.world);
    return t_end < 0;
}

int main(int argc, char **argv)
{
    const char *svg_path = argc > 1 ? argv[1] : "build/car.svg";
    ga2d_world_def def = ga2d_default_world_def(), accurate = ga2d_accurate_world_def();
    svgs rec;
    long bytes;
    int failed = 0;

    printf("Car: a chassis on two wheel joints (4 Hz suspension, motors %.0f rad/s, %.0f N m) over %d bumps of %.0f cm, "
           "parked %.0f s on a %.0f deg ramp, %d steps/s\n", -DRIVE, TORQUE, BUMPS, 100 * BUMP_H, PARK_SECONDS, SLOPE_DEG,
           HZ);
    def.enable_sleep = accurate.enable_sleep = 0;
    svgs_init(&rec, 1.0 / HZ, SVG_EVERY);
    failed |= run("default", &def, &rec);
    failed |= run("accurate", &accurate, NULL);
    bytes = svgs_write(&rec, svg_path, "A car on wheel joints over bumps made of one chain, parked on a 15 degree ramp");
    if (bytes < 0) {
        fprintf(stderr, "car: cannot write %s (run from the repository root, after make)\n", svg_path);
        failed = 1;
    } else
        printf("  svg       %s (%.0f kB, %d frames; open it in a browser)\n", svg_path, (double)bytes / 1024,
               rec.base.frames);
    svgs_free(&rec);
    return failed;
}
