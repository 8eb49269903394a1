/* Joints at the extremes (issue 24; the mission's numerical stability at
   the extremes): driven past the speed caps, scaled from 1 cm to 100 m,
   far from the origin, mass ratios up to 1000:1, a long undamped run, and
   parameters at the edge of what create accepts.

   dt = 1/60 and 4 substeps unless a scene says otherwise (h = 1/240 s).
   A rigid joint is held by the soft step's position feedback: 60 Hz
   (GA2D__JOINT_HERTZ, capped at a quarter of the substep rate), damping
   ratio 2, in the biased pass (test_joints.c's top comment: make_soft
   below gives its bias rate b, mass scale ms and impulse scale).  Its two
   facts used here (derived there):
   - a joint carrying a steady force F over an effective mass m_eff rests
     apart by F / (m_eff omega_s^2) (omega_s = 2 pi 60 /s);
   - a body turning at w about a joint, its centre d from the anchor,
     drifts off it by w^2 h^2 d / 2 per substep and the biased pass takes
     back h b ms of the gap per substep: it rests at w^2 h d / (2 b ms).
   u is the unit roundoff of ga2d_real (REAL_EPS / 2); ulp(X) the spacing
   of representable numbers near X.  With GA2D_TEST_VERBOSE set each scene
   prints "joint extremes: ..." with its figures and their bounds. */
#include "test.h"

#define DT (1.0 / 60)
#define SUB 4
#define H (DT / SUB)
#define G 10.0
#define PI 3.14159265358979323846
#define JOINT_HERTZ 60.0 /* the header's GA2D__JOINT_HERTZ */
#define JOINT_ZETA 2.0   /* and GA2D__JOINT_DAMPING_RATIO */
#define U (REAL_EPS / 2)

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static ga2d_vec v2(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }

/* The soft step's spring (hertz, damping ratio, substep) in double. */
typedef struct soft { double bias, ms, is; } soft;
static soft make_soft(double hertz, double zeta, double h)
{
    soft s;
    double om = 2 * PI * hertz, a1 = 2 * zeta + h * om, a2 = h * om * a1;
    s.bias = om / a1;
    s.ms = a2 / (1 + a2);
    s.is = 1 / (1 + a2);
    return s;
}
/* The rigid joints' feedback at substep h: 60 Hz, or a quarter of 1/h. */
static double joint_hertz(double h) { return JOINT_HERTZ < 0.25 / h ? JOINT_HERTZ : 0.25 / h; }

static ga2d_world *make_world(double gx, double gy, double units, int substeps)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.gravity = v2(gx, gy);
    wd.enable_sleep = 0;
    wd.length_units_per_meter = (ga2d_real)units;
    wd.substeps = substeps;
    return ga2d_world_create(&wd);
}

static void step(ga2d_world *w) { CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK); }

/* A static body with no shape at (x, y). */
static ga2d_body_id pivot_body(ga2d_world *w, double x, double y)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.position = v2(x, y);
    return ga2d_body_create(w, &d);
}

/* A dynamic box of half extents hx, hy at (x, y), turned by angle. */
static ga2d_body_id box_body(ga2d_world *w, double x, double y, double angle, double hx, double hy, double density)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = v2(x, y);
    d.rotor = ga2d_rotor_from_angle((ga2d_real)angle);
    d.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    d.density = (ga2d_real)density;
    return ga2d_body_create(w, &d);
}

static ga2d_revolute_joint_def hinge_def(ga2d_body_id a, ga2d_body_id b, ga2d_vec la, ga2d_vec lb)
{
    ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
    d.body_a = a;
    d.body_b = b;
    d.local_anchor_a = la;
    d.local_anchor_b = lb;
    return d;
}

static ga2d_joint_id hinge(ga2d_world *w, ga2d_body_id a, ga2d_body_id b, ga2d_vec la, ga2d_vec lb)
{
    ga2d_revolute_joint_def d = hinge_def(a, b, la, lb);
    ga2d_joint_id j;
    CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
    return j;
}

static ga2d_vec world_point(const ga2d_world *w, ga2d_body_id b, ga2d_vec local)
{
    return ga2d_transform_apply(ga2d_body_transform(w, b), local);
}
static double dist(ga2d_vec a, ga2d_vec b) { return hypot((double)a.x - (double)b.x, (double)a.y - (double)b.y); }
static double len(ga2d_vec a) { return hypot((double)a.x, (double)a.y); }
static double mass_of(const ga2d_world *w, ga2d_body_id b) { return (double)ga2d_body_mass_data(w, b).mass; }

/* The distance between a joint's anchors (la on A, lb on B) in the world. */
static double anchor_gap(const ga2d_world *w, ga2d_joint_id j, ga2d_vec la, ga2d_vec lb)
{
    return dist(world_point(w, ga2d_joint_body_a(w, j), la), world_point(w, ga2d_joint_body_b(w, j), lb));
}

static int body_finite(const ga2d_world *w, ga2d_body_id b)
{
    ga2d_vec p = ga2d_body_position(w, b), v = ga2d_body_velocity(w, b);
    ga2d_rotor q = ga2d_body_rotor(w, b);
    return isfinite((double)p.x) && isfinite((double)p.y) && isfinite((double)v.x) && isfinite((double)v.y) &&
           isfinite((double)q.c) && isfinite((double)q.s) && isfinite((double)ga2d_body_angular_velocity(w, b));
}

static unsigned char *snapshot(const ga2d_world *w, size_t *size)
{
    unsigned char *buf;
    *size = ga2d_world_snapshot_size(w);
    buf = (unsigned char *)malloc(*size);
    if (!buf || ga2d_world_snapshot_save(w, buf, *size) != GA2D_OK) {
        test_fail(__FILE__, __LINE__, "snapshot failed");
        free(buf);
        return NULL;
    }
    return buf;
}

/* The world saved and loaded into a fresh one: both step on bit for bit
   (n steps, every listed body's position, rotor and velocities). */
static int snapshot_replays(ga2d_world *w, const ga2d_body_id *b, int count, int n)
{
    size_t size;
    unsigned char *buf = snapshot(w, &size);
    ga2d_world *w2 = ga2d_world_create(NULL);
    int same = buf != NULL && w2 != NULL, k, i;
    if (same) same = ga2d_world_snapshot_load(w2, buf, size) == GA2D_OK;
    for (k = 0; k < n && same; ++k) {
        same = ga2d_world_step(w, (ga2d_real)DT) == ga2d_world_step(w2, (ga2d_real)DT);
        for (i = 0; i < count && same; ++i) {
            ga2d_vec p1 = ga2d_body_position(w, b[i]), p2 = ga2d_body_position(w2, b[i]);
            ga2d_vec v1 = ga2d_body_velocity(w, b[i]), v2_ = ga2d_body_velocity(w2, b[i]);
            ga2d_rotor q1 = ga2d_body_rotor(w, b[i]), q2 = ga2d_body_rotor(w2, b[i]);
            same = p1.x == p2.x && p1.y == p2.y && v1.x == v2_.x && v1.y == v2_.y && q1.c == q2.c && q1.s == q2.s &&
                   ga2d_body_angular_velocity(w, b[i]) == ga2d_body_angular_velocity(w2, b[i]);
        }
    }
    free(buf);
    if (w2) ga2d_world_destroy(w2);
    return same;
}

/* ======================================================= 1. speed caps */
/* The caps: a body moves at most GA2D_MAX_LINEAR_SPEED and turns at most
   GA2D_MAX_ROTATION per substep; a step with a body past them counts it
   in counters.speed_caps (issue 24: "a joint chain driven past the
   velocity cap shows in counters.speed_caps, as contacts do").

   A hinge motor of absurd torque (1e9 N m: T h / I is 1e8 rad/s a
   substep here) asks 1e4 rad/s of a chain of `links` bars of length L
   pinned end to end to a static pivot, gravity off.  The motor sets the
   spin near 1e4 rad/s in both passes of every substep, so each kick
   finds the first bar past the caps and counts: at least one cap a
   substep.  The caps are applied again where positions move (the
   header's ga2d__cap_motion), scaling each body's velocity (v, w) as one
   (a pinned body keeps turning about its pin), so the chain turns at
   most at w_c = min(pi/4 / h, v_max / D) (D the farthest centre from
   the pivot) and every centre moves at most v_max h a substep: checked
   as 4 v_max h a step (rounding: 16 u of the coordinates) and, at 2
   substeps, a turn of at most 2 pi/4 a step (the angle between rotors a
   step apart: at 4 substeps it would be a half turn, ambiguous).

   The joints hold.  A joint's gap g (B's anchor off A's) grows per
   substep by what the drift moves the anchors apart, and the biased pass
   takes back h b ms of it:
   - turning at w_c about the pivot, a body whose centre is D from it
     drifts off its circle by w_c^2 h^2 D / 2 (the top's turning drift,
     with the lever to the pivot);
   - the pin's velocity the solver leaves before the drift: the biased
     pass removes ms of the velocity error at the anchors and leaves its
     is = 1 - ms part; the error is at most the speed of the bar's points
     (|v| + |w| r), which the cap scales with the body to at most
     v_max + w_c D: a leftover l <= is (v_max + w_c D) for each of the
     joint's two sides (one for the pin to the static pivot);
   - the load: the chain outside the joint turning at w_c pulls with
     sum m_i w_c^2 D_i over the joint's effective mass: a static sag of
     at most w_c^2 D_max (M_out / m_eff) / omega_s^2, M_out / m_eff <= 2
     links' worth for these equal links (1 for the pivot's).
   So at rest g <= (w_c^2 h D / 2 + sides l) / (b ms) + sag, and the gap
   approaches it from 0 (a first-order recursion, monotone).  Rounding:
   16 u of the chain's length.  Before the caps were applied where
   positions move (only in the kick, ahead of the solver) this scene
   turned a 1 m bar by 41 rad a substep: its pin 15 to 43 m apart, a 4 m
   bar's 240 m, two 1 m links' 36 m.
   Every number finite, and the world saved mid-spin loads into a fresh
   world and replays bit for bit.  The velocities read after a step are
   the relax pass's, where the motor has spun the bar up again (thousands
   of rad/s): the caps bound the motion, the next kick caps and counts
   them (Box2D v3 reads the same). */
typedef struct capped_chain { int links; double length; int substeps; } capped_chain;

static void motor_past_the_caps(void)
{
    static const capped_chain scenes[4] = {{1, 1, 4}, {1, 4, 4}, {1, 1, 2}, {2, 1, 4}};
    int i, k, l;
    for (i = 0; i < 4; ++i) {
        const capped_chain *cc = &scenes[i];
        const double vmax = (double)GA2D_MAX_LINEAR_SPEED, turn = (double)GA2D_MAX_ROTATION;
        double h = DT / cc->substeps, L = cc->length, D = (cc->links - 0.5) * L, wc = fmin(turn / h, vmax / D);
        double om = 2 * PI * joint_hertz(h), sep_bound, max_sep = 0, max_move = 0, max_turn = 0, lo, sag;
        double move_bound = cc->substeps * h * vmax * (1 + 16 * U) + 16 * U * cc->links * L;
        double turn_bound = cc->substeps * turn * (1 + 16 * U) + 16 * U;
        soft js = make_soft(joint_hertz(h), JOINT_ZETA, h);
        ga2d_world *w = make_world(0, 0, 1, cc->substeps);
        ga2d_body_id p = pivot_body(w, 0, 0), bar[2];
        ga2d_joint_id j[2];
        int min_caps = 1 << 30, finite = 1;
        for (l = 0; l < cc->links; ++l) {
            ga2d_revolute_joint_def jd;
            bar[l] = box_body(w, L / 2 + l * L, 0, 0, L / 2, L / 20, 1);
            jd = hinge_def(l ? bar[l - 1] : p, bar[l], v2(l ? L / 2 : 0, 0), v2(-L / 2, 0));
            if (l == 0) {
                jd.enable_motor = 1;
                jd.motor_speed = (ga2d_real)1e4;
                jd.max_motor_torque = (ga2d_real)1e9;
            }
            CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &jd, &j[l]), GA2D_OK);
        }
        lo = js.is * (vmax + wc * D);
        sag = wc * wc * D * (cc->links > 1 ? 2 : 1) / (om * om);
        sep_bound = (wc * wc * h * D / 2 + (cc->links > 1 ? 2 : 1) * lo) / (js.bias * js.ms) + sag + 16 * U * cc->links * L;
        for (k = 0; k < 120; ++k) {
            ga2d_vec c0[2];
            ga2d_rotor q0 = ga2d_body_rotor(w, bar[0]), q1;
            double tn;
            for (l = 0; l < cc->links; ++l) c0[l] = ga2d_body_center(w, bar[l]);
            step(w);
            for (l = 0; l < cc->links; ++l) {
                double sep = anchor_gap(w, j[l], v2(l ? L / 2 : 0, 0), v2(-L / 2, 0)), mv = dist(ga2d_body_center(w, bar[l]), c0[l]);
                finite &= body_finite(w, bar[l]);
                if (sep > max_sep) max_sep = sep;
                if (mv > max_move) max_move = mv;
            }
            q1 = ga2d_body_rotor(w, bar[0]);
            tn = fabs(atan2((double)q0.c * (double)q1.s - (double)q0.s * (double)q1.c,
                            (double)q0.c * (double)q1.c + (double)q0.s * (double)q1.s));
            if (tn > max_turn) max_turn = tn;
            if (ga2d_world_get_counters(w).speed_caps < min_caps) min_caps = ga2d_world_get_counters(w).speed_caps;
            if (k == 60) CHECK(snapshot_replays(w, bar, cc->links, 5));
        }
        CHECK(finite);
        CHECK(min_caps >= cc->substeps);
        CHECK(max_sep <= sep_bound);
        CHECK(max_move <= move_bound);
        if (cc->substeps == 2) CHECK(max_turn <= turn_bound);
        if (verbose())
            printf("joint extremes: motor 1e9 N m toward 1e4 rad/s on %d x %g m, %d substeps: turns at <= %.4g rad/s "
                   "(tip %.4g m/s); speed_caps >= %d a step (bound >= %d); joints apart %.3g m <= %.3g; a centre moved "
                   "%.4g m a step <= %.4g; turned %.4g rad a step%s %.4g; read after the step: %.4g m/s, %.4g rad/s\n",
                   cc->links, L, cc->substeps, wc, wc * cc->links * L, min_caps, cc->substeps, max_sep, sep_bound, max_move,
                   move_bound, max_turn, cc->substeps == 2 ? " <=" : " (unchecked)", turn_bound,
                   len(ga2d_body_velocity(w, bar[0])), fabs((double)ga2d_body_angular_velocity(w, bar[0])));
        ga2d_world_destroy(w);
    }
}

/* A chain of 6 links (0.5 m x 0.05 m) hanging from a pivot, its last
   link flung sideways by an impulse worth 2000 m/s (five times the cap)
   at its centre.  The first step's kick finds that link past the speed
   cap: speed_caps > 0 in that step.  Everything stays finite, every
   centre moves at most 4 v_max h a step (as above), and the world saved
   a few steps later replays bit for bit.  The joints: the flung link
   pulls the chain taut and whips it round; the gap bound of the motor
   scene with every body at the caps (w_c = v_max / D, D the chain's
   length, two sides' leftovers, the sag of the whole chain's pull over
   one link's mass: 6 m w_c^2 D / (m/2 omega_s^2)). */
static void chain_flung(void)
{
    enum { N = 6 };
    const double vmax = (double)GA2D_MAX_LINEAR_SPEED, L = 0.5, D = N * L;
    double wc = fmin((double)GA2D_MAX_ROTATION / H, vmax / (D - L / 2)), om = 2 * PI * joint_hertz(H);
    soft js = make_soft(joint_hertz(H), JOINT_ZETA, H);
    double lo = js.is * (vmax + wc * D), sep_bound, max_sep = 0, max_move = 0, m;
    double move_bound = SUB * H * vmax * (1 + 16 * U) + 16 * U * D;
    ga2d_world *w = make_world(0, -G, 1, SUB);
    ga2d_body_id p = pivot_body(w, 0, 0), link[N];
    ga2d_joint_id j[N];
    int i, k, first_caps, finite = 1;
    for (i = 0; i < N; ++i) {
        link[i] = box_body(w, 0, -L / 2 - i * L, 0, 0.025, L / 2, 1);
        j[i] = hinge(w, i ? link[i - 1] : p, link[i], v2(0, i ? -L / 2 : 0), v2(0, L / 2));
    }
    m = mass_of(w, link[N - 1]);
    sep_bound = (wc * wc * H * D / 2 + 2 * lo) / (js.bias * js.ms) + 2 * N * wc * wc * D / (om * om) + 16 * U * D;
    CHECK_RESULT(ga2d_body_apply_impulse(w, link[N - 1], v2(2000 * m, 0), ga2d_body_center(w, link[N - 1])), GA2D_OK);
    step(w);
    first_caps = ga2d_world_get_counters(w).speed_caps;
    CHECK(first_caps > 0);
    for (k = 0; k < 120; ++k) {
        ga2d_vec c0[N];
        for (i = 0; i < N; ++i) c0[i] = ga2d_body_center(w, link[i]);
        step(w);
        for (i = 0; i < N; ++i) {
            double sep = anchor_gap(w, j[i], v2(0, i ? -L / 2 : 0), v2(0, L / 2)), mv = dist(ga2d_body_center(w, link[i]), c0[i]);
            finite &= body_finite(w, link[i]);
            if (sep > max_sep) max_sep = sep;
            if (mv > max_move) max_move = mv;
        }
        if (k == 5) CHECK(snapshot_replays(w, link, N, 5));
    }
    CHECK(finite);
    CHECK(max_sep <= sep_bound);
    CHECK(max_move <= move_bound);
    if (verbose())
        printf("joint extremes: chain of %d flung at 2000 m/s: speed_caps %d in the first step (> 0); joints apart %.3g m "
               "<= %.3g; a centre moved %.4g m a step <= %.4g\n",
               N, first_caps, max_sep, sep_bound, max_move, move_bound);
    ga2d_world_destroy(w);
}

void suite_joints_extremes(void)
{
    test_run("joint extremes: a motor past the speed caps", motor_past_the_caps);
    test_run("joint extremes: a chain flung past the speed cap", chain_flung);
}
