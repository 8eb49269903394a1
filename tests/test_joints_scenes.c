/* Joints in the scenes games need (issue 24, "stability where games need
   it"): a car on wheel joints over a bumpy chain terrain, parked braked on
   its 15 degree ramp; a bridge of 20 planks under a heavy box that settles
   and sleeps; a ragdoll of 11 bodies with limits that comes to rest
   without jitter.  Each runs in the default world and in
   ga2d_accurate_world_def() (8 substeps).  examples/car.c, bridge.c and
   ragdoll.c are the same scenes with their figures printed.

   dt = 1/60, g = 10.  A rigid joint's rows are held by the position
   feedback of tests/test_joints.c's top comment: a spring-damper of
   omega_s = 2 pi 60 Hz and damping ratio 2 on the mass the row sees
   (GA2D__JOINT_HERTZ, under a quarter of both worlds' substep rates), so
   a row carrying a steady force F rests past its target by F / (m_eff
   omega_s^2): the row is a spring k = m_eff omega_s^2 with a damper
   c = 2 zeta m_eff omega_s, both sized by the bodies the joint joins.

   At rest every pass gives back what gravity took, and velocities are
   only the feedbacks' answers to the positions' rounding (8 u of the
   coordinates' scale S); a feedback's bias rate is below 1 / h (b h =
   h w / (2 zeta + h w) < 1), so resting speeds stay below 8 u S / h (as
   test_joints_kinds.c's car on a slope).
   With GA2D_TEST_VERBOSE set each scene prints "joint scenes: ..." with
   its figures and bounds. */
#include "test.h"

#define DT (1.0 / 60)
#define G 10.0
#define PI 3.14159265358979323846
#define JOINT_HERTZ 60.0 /* the header's GA2D__JOINT_HERTZ */
#define JOINT_ZETA 2.0
#define U (REAL_EPS / 2) /* the unit roundoff of ga2d_real */

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static ga2d_vec v2(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }
static double omega_s(void) { return 2 * PI * JOINT_HERTZ; }
static double len(ga2d_vec a) { return hypot((double)a.x, (double)a.y); }
static double substep_of(const ga2d_world_def *wd) { return DT / wd->substeps; }
static void step(ga2d_world *w) { CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK); }

/* The default world and the accurate one, each with sleep on or off. */
static ga2d_world_def world_def(int accurate, int sleep)
{
    ga2d_world_def wd = accurate ? ga2d_accurate_world_def() : ga2d_default_world_def();
    wd.gravity = v2(0, -G);
    wd.enable_sleep = sleep;
    return wd;
}
static const char *const def_name[2] = {"default", "accurate"};

/* The largest |coordinate| of the bodies' centres, plus 1 m: the scale S
   of the positions' rounding. */
static double coordinate_scale(const ga2d_world *w, const ga2d_body_id *b, int n)
{
    double s = 0;
    int i;
    for (i = 0; i < n; ++i) {
        ga2d_vec c = ga2d_body_center(w, b[i]);
        if (fabs((double)c.x) > s) s = fabs((double)c.x);
        if (fabs((double)c.y) > s) s = fabs((double)c.y);
    }
    return s + 1;
}

/* ================================================================= car */
/* The terrain, left to right, one open chain (a chain pushes to its
   left: up) of 25 cm segments: a wall, flat from x = -12 to 0, eight
   cosine bumps 20 cm high and 2 m long (their valleys are joins where
   the chain turns up, where bodies once fell through), flat to x = 20, a
   straight ramp of 15 degrees, 8 m along its slope, a plateau of 10 m and
   a wall.  The car is examples/car.c's: a 2.4 m x 0.5 m chassis (1.2 kg),
   two discs of r = 0.4 m (0.50 kg) on wheel joints 0.9 m either side of
   its middle and 0.5 m below it, a 4 Hz suspension with damping ratio
   0.7, motors at -10 rad/s (4 m/s) with at most 20 N m, friction 0.6. */
#define CAR_POINTS 256
#define BUMPS 8
#define BUMP_L 2.0
#define BUMP_H 0.2
#define SEG 0.25
#define RAMP_X 20.0
#define RAMP_L 8.0
#define SLOPE (15 * PI / 180)
#define PLATEAU_L 10.0
#define WHEEL_R 0.4
#define DRIVE (-10.0)
#define TORQUE 20.0
#define AXLE_X 0.9
#define AXLE_Y 0.5

typedef struct car {
    ga2d_world *w;
    ga2d_body_id body[3]; /* chassis, rear wheel, front wheel */
    ga2d_joint_id j[2];
    ga2d_vec pts[CAR_POINTS];
    int npts;
    double end_x;
} car;

static void add_point(car *s, double x, double y)
{
    if (s->npts < CAR_POINTS) s->pts[s->npts++] = v2(x, y);
}

static void make_car(car *s, const ga2d_world_def *wd)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_chain_id chain;
    double x, top_x = RAMP_X + RAMP_L * cos(SLOPE), top_y = RAMP_L * sin(SLOPE);
    int i, k;

    s->npts = 0;
    add_point(s, -12, 3);
    for (x = -12; x < -1e-9; x += SEG) add_point(s, x, 0);
    for (i = 0; i < (int)(BUMPS * BUMP_L / SEG); ++i) add_point(s, i * SEG, BUMP_H * (1 - cos(2 * PI * i * SEG / BUMP_L)) / 2);
    for (x = BUMPS * BUMP_L; x < RAMP_X - 1e-9; x += SEG) add_point(s, x, 0);
    add_point(s, RAMP_X, 0);
    add_point(s, top_x, top_y);
    s->end_x = top_x + PLATEAU_L;
    add_point(s, s->end_x, top_y);
    add_point(s, s->end_x, top_y + 3);
    CHECK(s->npts < CAR_POINTS);

    s->w = ga2d_world_create(wd);
    CHECK(s->w != NULL);
    cd.points = s->pts;
    cd.count = s->npts;
    CHECK_RESULT(ga2d_chain_create_checked(s->w, ga2d_body_create(s->w, &bd), &cd, &chain), GA2D_OK);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.position = v2(-8, WHEEL_R + AXLE_Y);
    bd.polygon = ga2d_polygon_box((ga2d_real)1.2, (ga2d_real)0.25);
    s->body[0] = ga2d_body_create(s->w, &bd);
    for (k = 0; k < 2; ++k) {
        ga2d_wheel_joint_def jd = ga2d_default_wheel_joint_def();
        ga2d_circle disc;
        bd = ga2d_default_body_def();
        bd.type = GA2D_BODY_DYNAMIC;
        bd.position = v2(k ? -8 + AXLE_X : -8 - AXLE_X, WHEEL_R);
        s->body[1 + k] = ga2d_body_create(s->w, &bd);
        disc.center = v2(0, 0);
        disc.radius = (ga2d_real)WHEEL_R;
        sd.friction = (ga2d_real)0.6;
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(s->w, s->body[1 + k], &sd, &disc)));
        jd.body_a = s->body[0];
        jd.body_b = s->body[1 + k];
        jd.local_anchor_a = v2(k ? AXLE_X : -AXLE_X, -AXLE_Y);
        jd.hertz = 4;
        jd.damping_ratio = (ga2d_real)0.7;
        jd.enable_motor = 1;
        jd.motor_speed = (ga2d_real)DRIVE;
        jd.max_motor_torque = (ga2d_real)TORQUE;
        CHECK_RESULT(ga2d_wheel_joint_create_checked(s->w, &jd, &s->j[k]), GA2D_OK);
    }
}

/* A wheel joint's separation: the wheel's centre off the chassis's axis
   through the joint's anchor. */
static double wheel_separation(const car *s, int k)
{
    ga2d_transform xc = ga2d_body_transform(s->w, s->body[0]);
    ga2d_vec a = ga2d_transform_apply(xc, v2(k ? AXLE_X : -AXLE_X, -AXLE_Y));
    ga2d_vec axis = ga2d_rotate(xc.q, v2(0, 1));
    return fabs((double)ga2d_wedge(axis, ga2d_vec_sub(ga2d_body_position(s->w, s->body[1 + k]), a)));
}

/* How deep a wheel is in the terrain: r less its centre's distance to the
   nearest segment (negative: clear of it). */
static double wheel_sink(const car *s, int k)
{
    ga2d_vec c = ga2d_body_position(s->w, s->body[1 + k]);
    double best = 1e30, px = (double)c.x, py = (double)c.y;
    int i;
    for (i = 0; i + 1 < s->npts; ++i) {
        double ax = (double)s->pts[i].x, ay = (double)s->pts[i].y;
        double dx = (double)s->pts[i + 1].x - ax, dy = (double)s->pts[i + 1].y - ay;
        double t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        if (hypot(px - ax - t * dx, py - ay - t * dy) < best) best = hypot(px - ax - t * dx, py - ay - t * dy);
    }
    return WHEEL_R - best;
}

static void set_motors(car *s, double speed)
{
    CHECK_RESULT(ga2d_wheel_joint_set_motor_speed(s->w, s->j[0], (ga2d_real)speed), GA2D_OK);
    CHECK_RESULT(ga2d_wheel_joint_set_motor_speed(s->w, s->j[1], (ga2d_real)speed), GA2D_OK);
}

/* The car drives from x = -8 over the bumps and up the ramp; braked
   (motor speed 0) when its middle is halfway up; parked 10 s; driven
   again to the far end.  Sleep is off: a sleeping car cannot creep, so it
   must not be what holds it.  Bounds:
   - separation: the wheel joint's rigid row (across the axis) carries the
     wheel's push along the chassis: the ground's friction on it, at most
     what the motor's torque gives, T / r, plus the wheel's weight m_w g
     (the axis tilts); the row is a spring k = m_eff omega_s^2 with
     1/m_eff = 1/m_c + 1/m_w + l^2 / I_c, l the row's lever about the
     chassis's centre: the anchor's 0.5 m below it plus the suspension's
     travel, taken at most r (the longest lever gives the smallest m_eff,
     the softest row: a bound).  A load that comes on at once
     stretches a spring to at most twice its rest F / k, damped or not:
     separation <= 2 (T / r + m_w g) / k.
   - sink: a contact keeps one linear slop of overlap, gives N / (m_w
     omega_c^2) under a load N (omega_c the contact's 2 pi 45 Hz, under a
     quarter of the substep rate) and, hit at a normal speed v_n, gives
     way at most v_n / omega_c before its spring (damping ratio 10)
     stops it; the hardest hit is the ramp's foot at v sin 15 deg (v =
     4 m/s, the motors' speed), the largest load the whole car's weight
     taken 4 times (the bumps' crests are 0.99 /m curved: v^2 kappa =
     1.6 g): sink <= slop + 4 m g / (m_w omega_c^2) + v sin(15) /
     omega_c.  A wheel through the chain would sink 0.4 m.
     Parked, both wheels touch the ramp: sink >= -slop.
   - creep: braked, the car stops, and its suspension and pitch modes
     decay (the heave's at zeta 2 pi 4 m_eff / (m_c / 2) = 7 /s, with
     m_eff the suspension's mass; the pitch's less: taken at half, 3.5
     /s) from 4 m/s over 6 s; over the next 4 s every body's speed stays
     below 4 e^(-3.5 * 6) + 8 u S / h and the chassis moves no more than
     that times 4 s. */
static void car_over_bumps(void)
{
    int a;
    for (a = 0; a < 2; ++a) {
        ga2d_world_def wd = world_def(a, 0);
        const double h = substep_of(&wd), park_x = RAMP_X + RAMP_L * cos(SLOPE) / 2;
        double hz_c = 45 < 0.25 / h ? 45 : 0.25 / h, omega_c = 2 * PI * hz_c;
        double worst = 0, deepest = -1, t_bumps0 = -1, t_bumps1 = -1, t_end = -1, creep, fastest = 0;
        double mc, mw, ic, m_eff, sep_bound, sink_bound, speed_bound, creep_bound, lever = AXLE_Y + WHEEL_R;
        ga2d_vec parked;
        car s;
        int i, k, b, parked_at = -1;

        make_car(&s, &wd);
        mc = (double)ga2d_body_mass_data(s.w, s.body[0]).mass;
        ic = (double)ga2d_body_mass_data(s.w, s.body[0]).inertia;
        mw = (double)ga2d_body_mass_data(s.w, s.body[1]).mass;
        m_eff = 1 / (1 / mc + 1 / mw + lever * lever / ic);
        sep_bound = 2 * (TORQUE / WHEEL_R + mw * G) / (m_eff * omega_s() * omega_s());
        sink_bound = GA2D_LINEAR_SLOP + 4 * (mc + 2 * mw) * G / (mw * omega_c * omega_c) +
                     -DRIVE * WHEEL_R * sin(SLOPE) / omega_c;
        /* drive to the ramp's middle (it is 36 m away at 4 m/s: 20 s is ample) */
        for (i = 1; i <= 20 * 60 && parked_at < 0; ++i) {
            double x;
            step(s.w);
            for (k = 0; k < 2; ++k) {
                if (wheel_separation(&s, k) > worst) worst = wheel_separation(&s, k);
                if (wheel_sink(&s, k) > deepest) deepest = wheel_sink(&s, k);
            }
            x = (double)ga2d_body_center(s.w, s.body[0]).x;
            if (t_bumps0 < 0 && x >= 0) t_bumps0 = i * DT;
            if (t_bumps1 < 0 && x >= BUMPS * BUMP_L) t_bumps1 = i * DT;
            if (x >= park_x) parked_at = i;
        }
        CHECK(parked_at > 0);
        set_motors(&s, 0);
        for (i = 0; i < 6 * 60; ++i) step(s.w);
        parked = ga2d_body_center(s.w, s.body[0]);
        speed_bound = 4 * exp(-3.5 * 6) + 8 * U * coordinate_scale(s.w, s.body, 3) / h;
        creep_bound = 4 * speed_bound;
        for (i = 0; i < 4 * 60; ++i) {
            step(s.w);
            for (b = 0; b < 3; ++b)
                if (len(ga2d_body_velocity(s.w, s.body[b])) > fastest) fastest = len(ga2d_body_velocity(s.w, s.body[b]));
            for (k = 0; k < 2; ++k) /* both wheels on the ramp: touching it, within a slop */
                CHECK(wheel_sink(&s, k) >= -GA2D_LINEAR_SLOP && wheel_sink(&s, k) <= sink_bound);
        }
        creep = len(ga2d_vec_sub(ga2d_body_center(s.w, s.body[0]), parked));
        /* drive on to the plateau's end: 12 m at 4 m/s, 10 s is ample */
        set_motors(&s, DRIVE);
        for (i = 1; i <= 10 * 60 && t_end < 0; ++i) {
            step(s.w);
            for (k = 0; k < 2; ++k) {
                if (wheel_separation(&s, k) > worst) worst = wheel_separation(&s, k);
                if (wheel_sink(&s, k) > deepest) deepest = wheel_sink(&s, k);
            }
            if ((double)ga2d_body_center(s.w, s.body[0]).x >= s.end_x - 2.5) t_end = i * DT;
        }
        CHECK(t_bumps1 > t_bumps0 && t_bumps0 > 0);
        CHECK(t_end > 0);
        CHECK(worst <= sep_bound);
        CHECK(deepest <= sink_bound);
        CHECK(fastest <= speed_bound);
        CHECK(creep <= creep_bound);
        if (verbose())
            printf("joint scenes: car (%s): wheel joints' worst separation %.3g m (<= %.3g), deepest sink %.3g m "
                   "(<= %.3g), bumps crossed in %.3g s, parked: speed %.3g m/s (<= %.3g), crept %.3g m in 4 s (<= %.3g), "
                   "far end %.3g s after driving on\n",
                   def_name[a], worst, sep_bound, deepest, sink_bound, t_bumps1 - t_bumps0, fastest, speed_bound, creep,
                   creep_bound, t_end);
        ga2d_world_destroy(s.w);
    }
}

/* ============================================================== bridge */
/* examples/bridge.c's bridge: 20 planks of 1 m x 0.25 m (0.25 kg) on 21
   revolute joints spanning a 20 m gap exactly between two static posts,
   a 1 m box of 10 kg (40 planks; also 2.5 and 40 kg) dropped on its
   middle from 3 m above the deck.  Each joint's motor, at speed 0 with
   at most `friction` N m (5, or 0: off), is the hinge's friction
   (examples/bridge.c: a rusty hinge).

   The planks span the gap exactly, so the deck sags only as far as the
   joints stretch: each is the spring k_j = m_eff omega_s^2 along the
   deck, m_eff = m / 2 between two planks (the row along the plank, no
   lever) and m at a post, with the damper c_j = 2 zeta m_eff omega_s.
   Half the bridge (10 m, a) is 10 joints' springs in series (9 inner,
   the post's at twice the stiffness counting half, half the middle
   one's): axial k_a = k_j / 10, c_a = c_j / 10.
   - At rest: a string under its load; the posts take the whole weight
     W (box and planks) through the end planks, at angles th0, th20
     (read from them) with one horizontal tension H: H (tan th0 + tan
     th20) = W; along the string the tension is largest at the posts,
     T = H / cos th.  A joint rests stretched by its force over its
     stiffness, the force being T along the deck plus, where the box
     sits, its push on the tilted planks (below its weight m_b g): a
     separation <= (H / cos th_max + m_b g) / k, for k of each joint.
   - Settling: the box bounces on the deck, which sags under its weight
     W_b to th = d / a with th^3 = 10 W_b / (a k_j) (the half's stretch
     10 T / k_j equals a th^2 / 2 with T = W_b / (2 th); the box's weight
     alone is the smallest load, so the shallowest angle).  The box
     lowered by dy stretches each half by th dy, so the joints' dampers
     resist its bounce as c_v = 2 th^2 c_a, and the bounce's amplitude
     decays at c_v / (2 M), M the box and every plank (the most that
     moves).  The dampers alone (joint friction and the step's numerical
     damping only take more energy out) bring the box from its landing
     speed sqrt(2 g 2.375 m) to the sleep speed (0.05 m/s) within
     ln(v0 / 0.05) 2 M / c_v, and the island sleeps 0.5 s later.  That
     is why the bridge rings for tens of seconds: the dampers are sized
     for the planks' m_eff (0.125 kg), the load is 80 times that, and
     the bounce's damping ratio c_v / (2 sqrt(k_v M)) is about 0.01 (k_v
     = 2 (k_a th^2 + T / a), its stiffness).  Box2D v3 uses the same
     feedback (60 Hz, ratio 2) and rings as long (README). */
#define PLANKS 20
#define BRIDGE_JOINTS (PLANKS + 1)
#define DECK_Y 5.0

typedef struct bridge {
    ga2d_world *w;
    ga2d_body_id body[PLANKS + 1]; /* the planks, then the box */
    ga2d_body_id a[BRIDGE_JOINTS], b[BRIDGE_JOINTS];
    ga2d_joint_id j[BRIDGE_JOINTS];
    ga2d_vec la[BRIDGE_JOINTS], lb[BRIDGE_JOINTS];
} bridge;

static void hinge(bridge *s, int k, ga2d_body_id a, ga2d_body_id b, double x, double friction)
{
    ga2d_revolute_joint_def jd = ga2d_default_revolute_joint_def();
    jd.enable_motor = friction > 0;
    jd.max_motor_torque = (ga2d_real)friction;
    jd.body_a = s->a[k] = a;
    jd.body_b = s->b[k] = b;
    jd.local_anchor_a = s->la[k] = ga2d_body_local_point(s->w, a, v2(x, DECK_Y));
    jd.local_anchor_b = s->lb[k] = ga2d_body_local_point(s->w, b, v2(x, DECK_Y));
    CHECK_RESULT(ga2d_revolute_joint_create_checked(s->w, &jd, &s->j[k]), GA2D_OK);
}

static void make_bridge(bridge *s, const ga2d_world_def *wd, double friction, double box_kg)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id left, right, prev;
    int i;
    s->w = ga2d_world_create(wd);
    CHECK(s->w != NULL);
    bd.position = v2(0, -1);
    bd.polygon = ga2d_polygon_box(20, 1);
    ga2d_body_create(s->w, &bd);
    bd.polygon = ga2d_polygon_box((ga2d_real)0.25, (ga2d_real)(DECK_Y / 2));
    bd.position = v2(-10.25, DECK_Y / 2);
    left = ga2d_body_create(s->w, &bd);
    bd.position = v2(10.25, DECK_Y / 2);
    right = ga2d_body_create(s->w, &bd);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.125);
    prev = left;
    for (i = 0; i < PLANKS; ++i) {
        bd.position = v2(-9.5 + i, DECK_Y);
        s->body[i] = ga2d_body_create(s->w, &bd);
        hinge(s, i, prev, s->body[i], -10 + i, friction);
        prev = s->body[i];
    }
    hinge(s, PLANKS, prev, right, 10, friction);
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    bd.density = (ga2d_real)box_kg;
    bd.position = v2(0, DECK_Y + 3);
    s->body[PLANKS] = ga2d_body_create(s->w, &bd);
}

static double bridge_separation(const bridge *s, int k)
{
    ga2d_vec pa = ga2d_transform_apply(ga2d_body_transform(s->w, s->a[k]), s->la[k]);
    ga2d_vec pb = ga2d_transform_apply(ga2d_body_transform(s->w, s->b[k]), s->lb[k]);
    return len(ga2d_vec_sub(pa, pb));
}

static void bridge_settles(void)
{
    static const double frictions[2] = {5, 0}, box_kgs[3] = {10, 2.5, 40};
    int a, f, m;
    for (m = 0; m < 3; ++m)
    for (a = 0; a < 2; ++a)
        for (f = 0; f < 2; ++f) {
            ga2d_world_def wd = world_def(a, 1);
            const double mp = 0.25, mb = box_kgs[m], half = 10, v_sleep = 0.05, time_to_sleep = 0.5;
            const double kj = mp / 2 * omega_s() * omega_s(), cj = 2 * JOINT_ZETA * mp / 2 * omega_s();
            const double th = cbrt(10 * mb * G / (half * kj)), cv = 2 * th * th * cj / 10, M = mb + PLANKS * mp;
            const double v0 = sqrt(2 * G * 2.375), t_bound = log(v0 / v_sleep) * 2 * M / cv + time_to_sleep;
            double worst = 0, rest = 0, rest_bound = 0, asleep_at = -1, th0, th20, H, thmax;
            bridge s;
            int i, k;
            make_bridge(&s, &wd, frictions[f], mb);
            for (i = 1; i <= (int)(t_bound / DT) + 1 && asleep_at < 0; ++i) {
                step(s.w);
                for (k = 0; k < BRIDGE_JOINTS; ++k)
                    if (bridge_separation(&s, k) > worst) worst = bridge_separation(&s, k);
                if (ga2d_world_get_counters(s.w).awake_body_count == 0) asleep_at = i * DT;
            }
            CHECK(asleep_at > 0 && asleep_at <= t_bound);
            th0 = fabs((double)ga2d_body_angle(s.w, s.body[0]));
            th20 = fabs((double)ga2d_body_angle(s.w, s.body[PLANKS - 1]));
            thmax = th0 > th20 ? th0 : th20;
            H = (mb + PLANKS * mp) * G / (tan(th0) + tan(th20));
            for (k = 0; k < BRIDGE_JOINTS; ++k) {
                double m_eff = k == 0 || k == PLANKS ? mp : mp / 2;
                double bound = (H / cos(thmax) + mb * G) / (m_eff * omega_s() * omega_s()), d = bridge_separation(&s, k);
                CHECK(d <= bound);
                if (d > rest) rest = d;
                if (bound > rest_bound) rest_bound = bound;
            }
            if (verbose())
                printf("joint scenes: bridge (%s, %g kg box, joint friction %g N m): asleep at %.4g s (<= %.4g: the joints' dampers "
                       "alone, decay %.3g /s), worst separation %.3g m (at impact), at rest %.3g m (<= %.3g: "
                       "tension %.4g N at the posts, sag angle %.3g rad; derived %.3g rad), sag %.3g m\n",
                       def_name[a], mb, frictions[f], asleep_at, t_bound, cv / (2 * M),
                       worst, rest, rest_bound, H / cos(thmax), thmax, th,
                       DECK_Y + 0.625 - (double)ga2d_body_center(s.w, s.body[PLANKS]).y);
            ga2d_world_destroy(s.w);
        }
}

/* ============================================================= ragdoll */
/* examples/ragdoll.c's ragdoll: 11 capsules on 10 revolute joints with
   limits (waist, neck, hips, knees, shoulders, elbows), the bones in one
   negative group, thrown tilted and tumbling onto the ground from 3 m.
   Sleep is off: it must come to rest by itself, not be frozen.
   - Rest: once every bone's speed has stayed below 8 u S / h (the top
     comment; S the bones' coordinates' scale) for 1 s (ten periods of a
     forearm's ringing on its elbow limit, which dips below the bound
     between swings while it decays), after 10 s and before 20 s (when
     the tumble dies out depends on the trajectory's last bits: the
     solver's masses following their anchors moved it past 10 s in
     double), over the next 5 s every bone's speed stays below it: no
     jitter.
   - Limits at rest: a limit that holds a load is a row like the others,
     the spring I_eff omega_s^2 on the angle (1/I_eff = 1/I_a + 1/I_b,
     the row turns both bones and moves no centre), so a joint rests
     past its limit by its torque over that, |tau| / (I_eff omega_s^2)
     (tau the joint's reaction torque, the limit's alone: no motor, no
     spring), within 1 % (the bones' leftover motion, at the rounding
     floor, changes the impulse by far less) plus the angle's rounding
     8 u pi.
   - Limits at impact: a limit is speculative (it lets a bone close on it
     no faster than it can stop), so it is passed only where something
     pushes the bone through it, the ground's hit on a limb: that load,
     over I_eff omega_s^2.  Its peak is not known beforehand; the test
     prints the run's worst excursion (examples/ragdoll.c: 4.3 degrees at
     the landing, 0.33 at rest) and checks it is gone at rest. */
#define BONES 11
#define RAG_JOINTS 10

typedef struct bone_shape { double x1, y1, x2, y2, r; } bone_shape;
static const bone_shape BONE[BONES] = {
    {0, 0.95, 0, 1.05, 0.11}, {0, 1.17, 0, 1.43, 0.13}, {0, 1.66, 0, 1.72, 0.10}, {0, 0.86, 0, 0.52, 0.07},
    {0, 0.86, 0, 0.52, 0.07}, {0, 0.43, 0, 0.08, 0.06}, {0, 0.43, 0, 0.08, 0.06}, {0, 1.40, 0, 1.16, 0.05},
    {0, 1.40, 0, 1.16, 0.05}, {0, 1.08, 0, 0.86, 0.045}, {0, 1.08, 0, 0.86, 0.045},
};
typedef struct rag_hinge { int parent, child; double y, lower, upper; } rag_hinge;
static const rag_hinge HINGE[RAG_JOINTS] = {
    {0, 1, 1.11, -0.6, 0.3}, {1, 2, 1.56, -0.5, 0.4}, {0, 3, 0.90, -0.4, 1.5}, {0, 4, 0.90, -0.4, 1.5},
    {3, 5, 0.475, -2.2, 0},  {4, 6, 0.475, -2.2, 0},  {1, 7, 1.45, -0.8, 2.5}, {1, 8, 1.45, -0.8, 2.5},
    {7, 9, 1.12, 0, 2.3},    {8, 10, 1.12, 0, 2.3},
};

static void make_ragdoll(ga2d_world *w, ga2d_body_id *bone, ga2d_joint_id *joint)
{
    const double turn = 1.2, lift = 3;
    const ga2d_rotor q = ga2d_rotor_from_angle((ga2d_real)turn);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    int i;
    bd.position = v2(0, -1);
    bd.polygon = ga2d_polygon_box(20, 1);
    ga2d_body_create(w, &bd);
    bd = ga2d_default_body_def();
    bd.type = GA2D_BODY_DYNAMIC;
    bd.rotor = q;
    sd.filter.group_index = -1;
    for (i = 0; i < BONES; ++i) {
        const bone_shape *b = &BONE[i];
        ga2d_vec mid = v2((b->x1 + b->x2) / 2, (b->y1 + b->y2) / 2);
        ga2d_capsule c;
        c.center1 = ga2d_vec_sub(v2(b->x1, b->y1), mid);
        c.center2 = ga2d_vec_sub(v2(b->x2, b->y2), mid);
        c.radius = (ga2d_real)b->r;
        bd.position = ga2d_vec_add(ga2d_rotate(q, mid), v2(0, lift));
        bone[i] = ga2d_body_create(w, &bd);
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_capsule(w, bone[i], &sd, &c)));
    }
    /* tumbling as one (2 m/s, 3 rad/s about the torso), the right arm and
       leg kicked apart */
    for (i = 0; i < BONES; ++i) {
        ga2d_vec r = ga2d_vec_sub(ga2d_body_center(w, bone[i]), ga2d_body_center(w, bone[1]));
        ga2d_vec v = ga2d_vec_add(v2(2, 0), ga2d_vec_scale(ga2d_vec_perp(r), 3));
        if (i == 8 || i == 10) v = ga2d_vec_add(v, v2(-3, 3));
        if (i == 4 || i == 6) v = ga2d_vec_add(v, v2(1, 3));
        ga2d_body_set_velocity(w, bone[i], v);
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, bone[i], 3), GA2D_OK);
    }
    for (i = 0; i < RAG_JOINTS; ++i) {
        ga2d_revolute_joint_def jd = ga2d_default_revolute_joint_def();
        ga2d_vec p = ga2d_vec_add(ga2d_rotate(q, v2(0, HINGE[i].y)), v2(0, lift));
        jd.body_a = bone[HINGE[i].parent];
        jd.body_b = bone[HINGE[i].child];
        jd.local_anchor_a = ga2d_body_local_point(w, jd.body_a, p);
        jd.local_anchor_b = ga2d_body_local_point(w, jd.body_b, p);
        jd.enable_limit = 1;
        jd.lower_angle = (ga2d_real)HINGE[i].lower;
        jd.upper_angle = (ga2d_real)HINGE[i].upper;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &jd, &joint[i]), GA2D_OK);
    }
}

/* How far joint k is past its limits (rad; 0 within them). */
static double past_limit(const ga2d_world *w, const ga2d_joint_id *joint, int k)
{
    double a = (double)ga2d_revolute_joint_angle(w, joint[k]);
    return a < HINGE[k].lower ? HINGE[k].lower - a : a > HINGE[k].upper ? a - HINGE[k].upper : 0;
}

static void ragdoll_rests(void)
{
    int a;
    for (a = 0; a < 2; ++a) {
        ga2d_world_def wd = world_def(a, 0);
        const double h = substep_of(&wd);
        ga2d_world *w = ga2d_world_create(&wd);
        ga2d_body_id bone[BONES];
        ga2d_joint_id joint[RAG_JOINTS];
        double impact = 0, fastest = 0, speed_bound = 0, past_rest = 0, worst_ratio = 0;
        int i, k, resting;
        make_ragdoll(w, bone, joint);
        for (i = 0, resting = 0; i < 20 * 60; ++i) {
            step(w);
            for (k = 0; k < RAG_JOINTS; ++k)
                if (past_limit(w, joint, k) > impact) impact = past_limit(w, joint, k);
            ++resting;
            for (k = 0; k < BONES; ++k)
                if (!(len(ga2d_body_velocity(w, bone[k])) <= 8 * U * coordinate_scale(w, bone, BONES) / h)) resting = 0;
            if (i >= 10 * 60 && resting >= 60) break;
        }
        CHECK(i < 20 * 60);
        for (i = 0; i < 5 * 60; ++i) {
            double bound = 8 * U * coordinate_scale(w, bone, BONES) / h;
            step(w);
            if (bound > speed_bound) speed_bound = bound;
            for (k = 0; k < BONES; ++k) {
                double v = len(ga2d_body_velocity(w, bone[k]));
                CHECK(v <= bound);
                if (v > fastest) fastest = v;
            }
            for (k = 0; k < RAG_JOINTS; ++k) {
                double ia = (double)ga2d_body_mass_data(w, bone[HINGE[k].parent]).inertia;
                double ib = (double)ga2d_body_mass_data(w, bone[HINGE[k].child]).inertia;
                double ie = 1 / (1 / ia + 1 / ib), tau = fabs((double)ga2d_joint_reaction_torque(w, joint[k]));
                double past = past_limit(w, joint, k), bound_k = tau / (ie * omega_s() * omega_s());
                CHECK(past <= 1.01 * bound_k + 8 * U * PI);
                if (past > past_rest) past_rest = past;
                if (bound_k > 0 && past / bound_k > worst_ratio) worst_ratio = past / bound_k;
            }
        }
        if (verbose())
            printf("joint scenes: ragdoll (%s, sleep off): at rest after 10 s, over 5 s: fastest bone %.3g m/s (<= %.3g); "
                   "limits passed by %.3g deg at rest (its torque / (I_eff omega_s^2) times %.6f), %.3g deg at impact\n",
                   def_name[a], fastest, speed_bound, past_rest * 180 / PI, worst_ratio, impact * 180 / PI);
        ga2d_world_destroy(w);
    }
}

void suite_joints_scenes(void)
{
    test_run("joint scenes: car over bumps, parked on 15 deg", car_over_bumps);
    test_run("joint scenes: bridge under a box settles and sleeps", bridge_settles);
    test_run("joint scenes: ragdoll comes to rest without jitter", ragdoll_rests);
}
