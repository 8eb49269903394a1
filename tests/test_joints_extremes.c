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

/* ============================================================ 2. scale */
/* The arithmetic-geometric mean: a pendulum of small-amplitude period T0
   swinging to th has the period T0 / AGM(1, cos(th/2)). */
static double agm(double a, double b)
{
    int i;
    for (i = 0; i < 40 && fabs(a - b) > 1e-16 * a; ++i) {
        double an = (a + b) / 2;
        b = sqrt(a * b);
        a = an;
    }
    return a;
}

/* A bar of length L x L/10 (density 1) hinged at its end (local (-L/2,
   0)) to a static pivot at (ox, oy), hanging at th0 from the downward
   vertical, released at rest, gravity g down.  Times `periods` periods by
   the upward crossings of the bar's x past the pivot's (interpolated),
   and reports the largest anchor gap and the lowest energy (the bar's
   kinetic and potential, its height from the pivot's). */
typedef struct swing { double period, max_sep, e0, e_min; long steps; } swing;
static swing swing_bar(ga2d_world *w, double ox, double oy, double L, double th0, double g, int periods)
{
    double d = L / 2, prev, first = 0, last = 0;
    ga2d_body_id p = pivot_body(w, ox, oy);
    ga2d_body_id bar = box_body(w, ox + d * sin(th0), oy - d * cos(th0), th0 - PI / 2, d, L / 20, 1);
    ga2d_joint_id j = hinge(w, p, bar, v2(0, 0), v2(-d, 0));
    double m = mass_of(w, bar), in = (double)ga2d_body_mass_data(w, bar).inertia;
    swing s;
    int crossings = 0;
    memset(&s, 0, sizeof s);
    s.e0 = s.e_min = m * g * ((double)ga2d_body_center(w, bar).y - oy);
    prev = (double)ga2d_body_center(w, bar).x - ox;
    for (s.steps = 1; crossings <= periods && s.steps < 100000; ++s.steps) {
        ga2d_vec v, c;
        double x, e, om, sep;
        step(w);
        v = ga2d_body_velocity(w, bar);
        c = ga2d_body_center(w, bar);
        om = (double)ga2d_body_angular_velocity(w, bar);
        e = 0.5 * m * ((double)v.x * (double)v.x + (double)v.y * (double)v.y) + 0.5 * in * om * om + m * g * ((double)c.y - oy);
        if (e < s.e_min) s.e_min = e;
        sep = anchor_gap(w, j, v2(0, 0), v2(-d, 0));
        if (sep > s.max_sep) s.max_sep = sep;
        x = (double)c.x - ox;
        if (prev < 0 && x >= 0) {
            double tc = (double)s.steps * DT - DT * x / (x - prev);
            if (crossings == 0) first = tc;
            last = tc;
            ++crossings;
        }
        prev = x;
    }
    s.period = crossings > periods ? (last - first) / periods : 0;
    return s;
}

/* The bar's small-amplitude period T0 = 2 pi sqrt(I_p / (m g d)), I_p =
   m (L^2 + (L/10)^2) / 12 + m d^2, d = L / 2: as sqrt(L / g). */
static double bar_T0(double L, double g)
{
    double d = L / 2, ip_over_m = (L * L + L * L / 100) / 12 + d * d;
    return 2 * PI * sqrt(ip_over_m / (g * d));
}

/* The bound on the bar's timed period against the exact one less the
   phase error, as test_joints.c derives it for the 1 m bar (each term
   dimensionless, so it holds at every scale): the gap s moves the centre
   out (s (m d / I_p + 1 / (2 d))), the interpolation of the crossings
   (2 w0^2 dt^3 / 8 over N periods), the amplitude lost to the feedback's
   damping ((e0 - e_min) / (8 m g d)), rounding 16 u. */
static double bar_period_bound(const swing *s, double L, double g, double m, int periods)
{
    double d = L / 2, ip = m * ((L * L + L * L / 100) / 12 + d * d), w0 = 2 * PI / bar_T0(L, g);
    return s->max_sep * (m * d / ip + 1 / (2 * d)) + 2 * w0 * w0 * DT * DT * DT / 8 / periods / bar_T0(L, g) +
           (s->e0 - s->e_min) / (8 * m * g * d) + 16 * U;
}

/* The gap bound of the swinging bar (test_joints.c, 90 degrees): the load
   along the bar m (g + w^2 d) over its effective mass m, w^2 <= 2 m g d
   (1 - cos th0) / I_p: a static sag (g + w^2 d) / omega_s^2 and the
   turning drift w^2 h d / (2 b ms); rounding 8 u of the coordinates'
   size R. */
static double bar_gap_bound(double L, double g, double th0, double R)
{
    double d = L / 2, ip_over_m = (L * L + L * L / 100) / 12 + d * d, w2 = 2 * g * d * (1 - cos(th0)) / ip_over_m;
    soft js = make_soft(JOINT_HERTZ, JOINT_ZETA, H);
    double om = 2 * PI * JOINT_HERTZ;
    return (g + w2 * d) / (om * om) + w2 * H * d / (2 * js.bias * js.ms) + 8 * U * R;
}

/* The pendulum and the spring at lengths from 1 cm to 100 m, the world's
   length unit (length_units_per_meter) and gravity scaled with them as in
   test_extremes.c: every length in the step scales, masses as L^2 (a
   shape's area), inertias as L^4, times not at all, and a joint's
   feedback is in hertz; so the scaled scene is the 1 m scene in other
   units.
   - The bar pendulum (L x L/10, released from 5 degrees, 5 periods): its
     period T0 / AGM(1, cos(th0/2)) with T0 ~ sqrt(L / g), the same at
     every scale as g = 10 L; measured against it less the phase error
     (w0 h)^2 / 24 within bar_period_bound; its anchor gap within
     bar_gap_bound, a bound proportional to L: the separation scales
     with L.
   - A distance spring of 2 Hz (damping 0) holding a box (L/5 square,
     its centre at the anchor) at rest length L below a static anchor,
     released from L/10 further down, 3 periods: the motion stays on the
     vertical (gravity and the spring act along it), a 1-dof oscillator
     about the stretch x_eq = g / (2 pi f)^2 (the soft spring's static
     deflection, exact for k = m (2 pi f)^2), of the scheme's period
     (test_joints_kinds.c's scheme_period, scale-free), within its
     interpolation bound and 16 u; the stretch read as a fraction of L.
   - At L = 1/128 and 128 (powers of two) every product and sum is the
     1 m one times a power of two, exactly: the periods and the gaps over
     L are the 1 m run's, bit for bit. */
static double read_length(const ga2d_world *w, ga2d_joint_id j) { return (double)ga2d_distance_joint_current_length(w, j); }

static void scale_runs(void)
{
    static const double scales[5] = {1, 1.0 / 128, 128, 0.01, 100};
    const double th0 = 5 * PI / 180, f = 2;
    double T1 = 0, gap1 = 0, S1 = 0;
    int i, k;
    for (i = 0; i < 5; ++i) {
        double L = scales[i], g = G * L, T, phase, w0, m, bound, gap_bound, Ts, tol, x_eq, prev, first = 0, last = 0;
        int crossings = 0, periods = 5;
        ga2d_world *w = make_world(0, -g, L, SUB);
        swing s = swing_bar(w, 0, 0, L, th0, g, periods);
        ga2d_world_destroy(w);
        w = make_world(0, -g, L, SUB);
        m = 0.1 * L * L; /* the bar: L x L/10, density 1 */
        T = bar_T0(L, g) / agm(1, cos(th0 / 2));
        w0 = 2 * PI / bar_T0(L, g);
        phase = (w0 * H) * (w0 * H) / 24;
        bound = bar_period_bound(&s, L, g, m, periods);
        gap_bound = bar_gap_bound(L, g, th0, L);
        CHECK_NEAR(s.period / (T * (1 - phase)), 1, bound);
        CHECK(s.max_sep <= gap_bound);
        /* the spring */
        {
            ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, 0, -1.1 * L, 0, L / 10, L / 10, 1);
            ga2d_distance_joint_def d = ga2d_default_distance_joint_def();
            ga2d_joint_id j;
            double e = 2 * PI * f * H, gam = log(1 + e * e) / H, W;
            Ts = 2 * PI * H / acos(1 - e * e / (2 * (1 + e * e)));
            W = 2 * PI / Ts;
            tol = 2 * DT * DT * (2 * gam + W * W * DT) / 8 / 3 + 16 * U * Ts;
            d.body_a = p;
            d.body_b = b;
            d.length = (ga2d_real)L;
            d.enable_spring = 1;
            d.hertz = (ga2d_real)f;
            d.damping_ratio = 0;
            CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
            x_eq = g / ((2 * PI * f) * (2 * PI * f));
            prev = (read_length(w, j) - L - x_eq) / L;
            for (k = 1; k < 2000 && crossings <= 3; ++k) {
                double x;
                step(w);
                x = (read_length(w, j) - L - x_eq) / L;
                if (prev < 0 && x >= 0) {
                    double tc = k * DT - DT * x / (x - prev);
                    if (crossings == 0) first = tc;
                    last = tc;
                    ++crossings;
                }
                prev = x;
            }
            CHECK(crossings > 3);
            CHECK_NEAR((last - first) / 3, Ts, tol);
        }
        if (i == 0) {
            T1 = s.period;
            gap1 = s.max_sep;
            S1 = (last - first) / 3;
        } else if (i < 3) {
            CHECK(s.period == T1 && s.max_sep / L == gap1 && (last - first) / 3 == S1);
        }
        if (verbose())
            printf("joint extremes: scale %g m (units %g per m, g %g): pendulum period %.7f s vs exact %.7f less the phase "
                   "error: |rel| %.3g <= %.3g; gap %.3g L <= %.3g L; spring 2 Hz period %.7f s vs the scheme's %.7f: |diff| "
                   "%.3g <= %.3g%s\n",
                   L, L, g, s.period, T, fabs(s.period / (T * (1 - phase)) - 1), bound, s.max_sep / L, gap_bound / L,
                   (last - first) / 3, Ts, fabs((last - first) / 3 - Ts), tol,
                   i == 1 || i == 2 ? "; the 1 m run's bits" : "");
        ga2d_world_destroy(w);
    }
}

/* ================================================= 3. far from the origin */
/* ulp(x) for |x| >= the smallest normal number */
static double ulp_of(double x)
{
    int e;
    frexp(fabs(x), &e); /* |x| = m 2^e, m in [0.5, 1) */
    return REAL_EPS * ldexp(1.0, e - 1);
}

/* The 1 m bar pendulum hinged at (X, X) against the same at the origin,
   released from 5 and from 90 degrees, 500 steps (5 small periods): the
   bar's centre relative to its pivot, component by component, each step.
   The joint works on differences of nearby positions (the centres'
   offset where the step began, exact for numbers within a factor 2 of
   each other, and the substeps' displacements dp, small numbers) and on
   anchors relative to the bodies, so far out it sees what it sees at
   the origin, except that a stored position is a multiple of ulp(X):
   the step ends at x0 + dp, rounded once (ulp(X)/2 a component), and the
   next step starts there.  Each such rounding is a perturbation the
   pendulum carries on (it is neutrally stable: a shift along the swing
   stays a shift of the phase, one across it the feedback takes out), so
   after n steps a component is off by at most n ulp(X)/2, and never by
   more than twice the path the bar travelled (a lost move is at most the
   move), as test_extremes.c bounds its far pyramid; plus 2 ulp(X) for
   the reading (the pivot and the centre each within ulp(X)/2 of where
   they are).  X = 1e4 in float: ulp = 2^-10 m = 0.98 mm, n ulp/2 = 0.24
   m over the run (the 5 degree swing is 4.4 cm wide: float out there
   holds the pendulum to about a ulp a step, and no better); X = 1e6 in
   double: ulp = 2^-33 m = 1.2e-10 m, n ulp/2 = 2.9e-8 m.  The joint's
   gap: bar_gap_bound (its rounding at the coordinates' size X) plus a
   ulp(X) for the stored positions the joint is fed. */
static void far_from_origin(void)
{
#ifdef GA2D_DOUBLE
    const double X = 1e6;
#else
    const double X = 1e4;
#endif
    const double ths[2] = {5 * PI / 180, PI / 2}, u = ulp_of(X + 1); /* the coordinates stay in [X - 1, X + 1]: one binade */
    const int n = 500;
    int i, k, c;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w[2];
        ga2d_body_id bar[2];
        ga2d_joint_id j[2];
        double path[2] = {0, 0}, worst = 0, worst_bound = 1, max_gap = 0, gap_bound = bar_gap_bound(1, G, ths[i], X + 1) + u;
        int within = 1;
        for (c = 0; c < 2; ++c) {
            double o = c ? X : 0, th0 = ths[i];
            ga2d_body_id p;
            w[c] = make_world(0, -G, 1, SUB);
            p = pivot_body(w[c], o, o);
            bar[c] = box_body(w[c], o + 0.5 * sin(th0), o - 0.5 * cos(th0), th0 - PI / 2, 0.5, 0.05, 1);
            j[c] = hinge(w[c], p, bar[c], v2(0, 0), v2(-0.5, 0));
        }
        for (k = 1; k <= n; ++k) {
            ga2d_vec before = ga2d_body_center(w[0], bar[0]), a, b;
            double d[2], mv[2], gap;
            step(w[0]);
            step(w[1]);
            a = ga2d_body_center(w[0], bar[0]);
            b = ga2d_body_center(w[1], bar[1]);
            mv[0] = fabs((double)a.x - (double)before.x);
            mv[1] = fabs((double)a.y - (double)before.y);
            d[0] = fabs(((double)b.x - X) - (double)a.x);
            d[1] = fabs(((double)b.y - X) - (double)a.y);
            for (c = 0; c < 2; ++c) {
                double bound;
                path[c] += mv[c];
                bound = fmin(2 * path[c], k * u / 2) + 2 * u;
                within &= d[c] <= bound;
                if (d[c] / bound > worst / worst_bound) {
                    worst = d[c];
                    worst_bound = bound;
                }
            }
            gap = anchor_gap(w[1], j[1], v2(0, 0), v2(-0.5, 0));
            if (gap > max_gap) max_gap = gap;
        }
        CHECK(within);
        CHECK(max_gap <= gap_bound);
        if (verbose())
            printf("joint extremes: bar pendulum from %.0f deg at (%g, %g) vs at the origin, %d steps: closest to its bound, "
                   "the centre differs by %.3g m (bound %.3g m; ulp %.3g m); gap %.3g m <= %.3g\n",
                   ths[i] * 180 / PI, X, X, n, worst, worst_bound, u, max_gap, gap_bound);
        for (c = 0; c < 2; ++c) ga2d_world_destroy(w[c]);
    }
}

/* ====================================================== 4. mass ratios */
/* Two hanging scenes at mass ratios R = 1, 10, 100 and 1000, gravity on,
   released straight at rest with every gap 0, each joint made with the
   upper body as A and again with the lower body as A:
   - "weight": three links (0.1 x 0.5 m, 0.05 kg) from a pivot and a
     weight of R links (a 0.5 m square) under them;
   - "light under heavy": a heavy body of R links (the square) from the
     pivot and one link under it.
   At rest each joint carries the weight under it, F_i, over its effective
   mass (1 / m_eff = 1 / m_above + 1 / m_below, the anchors on the
   vertical through the centres: no lever; 0 for the pivot) and rests
   apart by F_i / (m_eff omega_s^2) (the top).  For the weight that is
   R m g / (m_eff omega_s^2) ~ R g / omega_s^2: the soft joint's gap grows
   with the ratio (1.8 mm at 10:1 in each link-to-link joint, 14 cm at
   1000:1), which is where soft joints stop holding well: a joint's
   stiffness m_eff omega_s^2 is set by the light body's mass.
   - Loaded at once from rest, a linear spring system goes at most to
     twice its static deflection (test_joints.c's chain): every gap stays
     below twice the largest rest gap, plus rounding 16 u of the chain's
     2.5 m.
   - It comes to rest there: the feedback is a spring k_i = m_eff,i
     omega_s^2 with a damper c_i = 2 zeta m_eff,i omega_s, the same ratio
     c / k = 2 zeta / omega_s in every joint, so the joints in series are
     one spring k_s = 1 / sum (1 / k_i) with c_s = 2 zeta k_s / omega_s.
     With the whole hanging mass M lumped at the bottom (the slowest
     mode such a chain can have: more mass, softer spring), the deviation
     from rest decays at c_s / (2 M) = zeta k_s / (M omega_s) at least
     (the soft step's implicit solve only adds damping).  After t = 60 s,
     from a deviation of at most the total rest stretch A0 = sum of the
     rest gaps, every gap and the lowest body's height are within
     A0 exp(-lambda t) of the rest values (plus the rounding above):
     the bottom body hangs at the static deflection.
   Every number finite. */
static void hanging_ratio(double R, int weight_scene, int lower_as_a, double *max_gap_rel, double *settle_dev,
                          double *rest_gap_max)
{
    enum { MAXN = 4 };
    const double link_m = 0.05, om = 2 * PI * JOINT_HERTZ, t_end = 60;
    ga2d_world *w = make_world(0, -G, 1, SUB);
    ga2d_body_id p = pivot_body(w, 0, 0), b[MAXN];
    ga2d_joint_id j[MAXN];
    ga2d_vec up_anchor[MAXN], low_anchor[MAXN];
    double half[MAXN], rest[MAXN], y = 0, max_rest = 0, max_gap = 0, a0 = 0, inv_ks = 0, M = 0, lambda, tol, y_rest, dev = 0;
    double round_tol = 16 * U * 2.5;
    int n = weight_scene ? 4 : 2, i, k, steps = (int)(t_end / DT), finite = 1;
    for (i = 0; i < n; ++i) {
        int heavy = weight_scene ? i == n - 1 : i == 0;
        double hw = heavy ? 0.25 : 0.05, hh = 0.25, mass = heavy ? R * link_m : link_m;
        ga2d_revolute_joint_def d;
        half[i] = hh;
        b[i] = box_body(w, 0, y - hh, 0, hw, hh, mass / (4 * hw * hh));
        up_anchor[i] = v2(0, i ? -half[i - 1] : 0);
        low_anchor[i] = v2(0, hh);
        if (lower_as_a && i > 0) d = hinge_def(b[i], b[i - 1], low_anchor[i], up_anchor[i]);
        else d = hinge_def(i ? b[i - 1] : p, b[i], up_anchor[i], low_anchor[i]);
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j[i]), GA2D_OK);
        y -= 2 * hh;
    }
    for (i = 0; i < n; ++i) {
        double below = 0, inv = (i ? 1 / mass_of(w, b[i - 1]) : 0) + 1 / mass_of(w, b[i]);
        for (k = i; k < n; ++k) below += mass_of(w, b[k]);
        rest[i] = below * G * inv / (om * om);
        if (rest[i] > max_rest) max_rest = rest[i];
        a0 += rest[i];
        inv_ks += inv / (om * om); /* 1 / k_i = 1 / (m_eff omega_s^2) */
        M += mass_of(w, b[i]);
    }
    y_rest = y + half[n - 1] - a0; /* the lowest body's centre at rest */
    lambda = JOINT_ZETA * (1 / inv_ks) / (M * om);
    tol = a0 * exp(-lambda * t_end) + round_tol;
    for (k = 0; k < steps; ++k) {
        step(w);
        for (i = 0; i < n; ++i) {
            double gap = dist(world_point(w, i ? b[i - 1] : p, up_anchor[i]), world_point(w, b[i], low_anchor[i]));
            if (gap > max_gap) max_gap = gap;
            finite &= body_finite(w, b[i]);
        }
    }
    CHECK(finite);
    CHECK(max_gap <= 2 * max_rest + round_tol);
    for (i = 0; i < n; ++i) {
        double gap = dist(world_point(w, i ? b[i - 1] : p, up_anchor[i]), world_point(w, b[i], low_anchor[i]));
        CHECK_NEAR(gap, rest[i], tol);
        if (fabs(gap - rest[i]) > dev) dev = fabs(gap - rest[i]);
    }
    CHECK_NEAR(ga2d_body_center(w, b[n - 1]).y, y_rest, tol);
    if (fabs((double)ga2d_body_center(w, b[n - 1]).y - y_rest) > dev) dev = fabs((double)ga2d_body_center(w, b[n - 1]).y - y_rest);
    *max_gap_rel = max_gap / (2 * max_rest + round_tol);
    *settle_dev = dev / tol;
    *rest_gap_max = max_rest;
    if (verbose())
        printf("joint extremes: %s %g:1, %s as A: max gap %.4g m <= %.4g (twice the largest rest gap); after %.0f s the gaps "
               "and the bottom's height off their rest values by %.3g m <= %.3g (rest stretch %.3g m, decay %.3g /s)\n",
               weight_scene ? "weight under three links" : "light under heavy", R, lower_as_a ? "the lower body" : "the upper body",
               max_gap, 2 * max_rest + round_tol, t_end, dev, tol, a0, lambda);
    ga2d_world_destroy(w);
}

static void mass_ratios(void)
{
    static const double ratios[4] = {1, 10, 100, 1000};
    int i, scene, order;
    for (scene = 1; scene >= 0; --scene)
        for (i = 0; i < 4; ++i)
            for (order = 0; order < 2; ++order) {
                double g_rel, dev, rest;
                hanging_ratio(ratios[i], scene, order, &g_rel, &dev, &rest);
            }
}

/* ========================================================= 5. long run */
/* The 1 m bar pendulum, no damping anywhere but the joint's feedback,
   10^5 steps (28 minutes, 4e5 substeps), from 5 and from 90 degrees.
   Energy: symplectic Euler keeps a modified energy constant, so E moves
   about its start by at most (w0 h / 2) E_osc (test_joints.c's 1000
   periods: E_osc = m g d (1 - cos th0) the swing's energy, w0 the small
   swing's rate, an upper bound on p V' / m over the swing's), and the
   joint's feedback only takes energy away on the whole: E never rises
   above E0 + (w0 h / 2) E_osc + 8 u (m g d + E_osc) (rounding of the
   energy's own terms), and the last tenth's highest energy is no higher
   than the first tenth's by more than that rounding: no drift upward.
   The gap: below bar_gap_bound at the starting amplitude (the amplitude
   only falls), and the last tenth's largest gap no larger than the
   first tenth's by more than its rounding (8 u): it does not grow.
   The rotor stays of unit length within 8 eps (test_extremes.c's long
   spin). */
#if defined(__SANITIZE_ADDRESS__)
#define LONG_STEPS 20000L
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LONG_STEPS 20000L
#endif
#endif
#ifndef LONG_STEPS
#define LONG_STEPS 100000L
#endif

static void long_run(void)
{
    const double ths[2] = {5 * PI / 180, PI / 2}, L = 1, d = 0.5;
    int i;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, -G, 1, SUB);
        double th0 = ths[i], m, in, e0, e_max, e_first = -1e300, e_last = -1e300, gap_first = 0, gap_last = 0, max_gap = 0;
        double w0 = 2 * PI / bar_T0(L, G), e_osc, rounding, e_bound, gap_bound = bar_gap_bound(L, G, th0, L), worst_norm = 0, e_end = 0;
        long k, tenth = LONG_STEPS / 10;
        ga2d_body_id p = pivot_body(w, 0, 0);
        ga2d_body_id bar = box_body(w, d * sin(th0), -d * cos(th0), th0 - PI / 2, d, L / 20, 1);
        ga2d_joint_id j = hinge(w, p, bar, v2(0, 0), v2(-d, 0));
        m = mass_of(w, bar);
        in = (double)ga2d_body_mass_data(w, bar).inertia;
        e0 = e_max = m * G * (double)ga2d_body_center(w, bar).y;
        e_osc = m * G * d * (1 - cos(th0));
        rounding = 8 * U * (m * G * d + e_osc);
        e_bound = w0 * H / 2 * e_osc + rounding;
        for (k = 1; k <= LONG_STEPS; ++k) {
            ga2d_vec v, c;
            ga2d_rotor q;
            double om, e, gap, nq;
            step(w);
            v = ga2d_body_velocity(w, bar);
            c = ga2d_body_center(w, bar);
            q = ga2d_body_rotor(w, bar);
            om = (double)ga2d_body_angular_velocity(w, bar);
            e = 0.5 * m * ((double)v.x * (double)v.x + (double)v.y * (double)v.y) + 0.5 * in * om * om + m * G * (double)c.y;
            gap = anchor_gap(w, j, v2(0, 0), v2(-d, 0));
            nq = fabs(sqrt((double)q.c * (double)q.c + (double)q.s * (double)q.s) - 1);
            if (nq > worst_norm) worst_norm = nq;
            if (e > e_max) e_max = e;
            if (gap > max_gap) max_gap = gap;
            if (k <= tenth) {
                if (e > e_first) e_first = e;
                if (gap > gap_first) gap_first = gap;
            } else if (k > LONG_STEPS - tenth) {
                if (e > e_last) e_last = e;
                if (gap > gap_last) gap_last = gap;
            }
            e_end = e;
        }
        CHECK(body_finite(w, bar));
        CHECK(e_max - e0 <= e_bound);
        CHECK(e_last <= e_first + rounding);
        CHECK(max_gap <= gap_bound);
        CHECK(gap_last <= gap_first + 8 * U);
        CHECK(worst_norm <= 8 * REAL_EPS);
        if (verbose())
            printf("joint extremes: pendulum from %.0f deg, %ld steps: energy rose %.3g J <= %.3g; last tenth's highest - "
                   "first's %.3g J <= %.3g; lost %.3g of E_osc %.3g J; gap %.3g m <= %.3g, last tenth's %.3g vs first's "
                   "%.3g; ||q| - 1| %.3g <= %.3g\n",
                   th0 * 180 / PI, LONG_STEPS, e_max - e0, e_bound, e_last - e_first, rounding, e0 - e_end, e_osc, max_gap,
                   gap_bound, gap_last, gap_first, worst_norm, 8 * REAL_EPS);
        ga2d_world_destroy(w);
    }
}

/* ============================================ 6. parameters at the edge */
/* A distance joint of absurd length: 1e30 m is finite and > 0, so create
   takes it (the header asks only that); its feedback asks the body to move
   out at about b 1e30 m/s.  The caps hold it: every substep the biased
   pass drives the box (0.2 m square, hanging 1 m below a static anchor,
   gravity on) past v_max, the cap where positions move scales it back
   and counts it, and the rigid relax pass takes the speed back to 0 along
   the joint before the kick sees it.  So: speed_caps at least 4 every
   step (before that cap counted, it was 0 every step: the speed was
   never seen by a kick), every number finite, and the box moves straight
   down, out along the joint and never back (the feedback only pushes
   out), at most 4 v_max h a step (the cap; rounding 16 u of its
   distance), its x staying 0 to that rounding. */
static void distance_absurd_length(void)
{
    const double vmax = (double)GA2D_MAX_LINEAR_SPEED;
    ga2d_world *w = make_world(0, -G, 1, SUB);
    ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, 0, -1, 0, 0.1, 0.1, 1);
    ga2d_distance_joint_def d = ga2d_default_distance_joint_def();
    ga2d_joint_id j;
    int k, min_caps = 1 << 30, finite = 1, n = 60;
    double y_prev = -1, worst_move = 0;
    d.body_a = p;
    d.body_b = b;
    d.length = (ga2d_real)1e30;
    CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
    for (k = 0; k < n; ++k) {
        double y;
        step(w);
        y = (double)ga2d_body_position(w, b).y;
        finite &= body_finite(w, b) && isfinite((double)ga2d_distance_joint_current_length(w, j));
        if (ga2d_world_get_counters(w).speed_caps < min_caps) min_caps = ga2d_world_get_counters(w).speed_caps;
        if (fabs(y - y_prev) > worst_move) worst_move = fabs(y - y_prev);
        CHECK(y < y_prev); /* out, down the vertical */
        y_prev = y;
    }
    CHECK(finite);
    CHECK(min_caps >= SUB);
    CHECK(worst_move <= SUB * H * vmax * (1 + 16 * U) + 16 * U * fabs(y_prev));
    CHECK(fabs((double)ga2d_body_position(w, b).x) <= 16 * U * fabs(y_prev));
    if (verbose())
        printf("joint extremes: distance joint of length 1e30 m: accepted; speed_caps >= %d a step (bound >= %d); the box "
               "moves out %.4g m a step <= %.4g, at %.4g m after %d steps, finite\n",
               min_caps, SUB, worst_move, SUB * H * vmax, -y_prev, n);
    ga2d_world_destroy(w);
}

/* Parameters at the edge of what create accepts, each as the header
   documents it, and never a NaN:
   - a distance joint of length 0: refused, INVALID_ARGUMENT ("a length
     not > 0"), the world untouched (its snapshot bytes); the smallest
     positive length (the least normal number) accepted, its anchors
     coincident at rest: the box hangs from the anchor by the rest gap of
     its weight, m g / (m omega_s^2) = g / omega_s^2 (the direction of a
     zero span is taken as x, so the joint still acts), finite, within
     twice that (sudden load) plus rounding;
   - a revolute limit with lower == upper (0.3 rad): accepted, a locked
     hinge: the bar (1 m, its end pinned, gravity across it) stays at 0.3
     rad within twice the static deflection of the weight's torque m g d
     cos(0.3) over the limit's axial mass (the bar's I about its centre):
     tau / (I omega_s^2) (test_joints.c's limit at rest), plus 8 u;
   - anchors far outside their bodies: a 0.2 m box hung from a pivot by
     a hinge whose anchor on it is 100 m above its centre, released at 5
     degrees: a pendulum of I_p = I + m 100^2 about the pivot, swinging
     with period T0 = 2 pi sqrt(I_p / (m g d)) (d = 100 m: 20 s), timed
     over 2 periods against the exact one less the phase error within
     bar_period_bound's terms (the gap's, the interpolation's, the lost
     amplitude's, 16 u), its gap below the static sag plus the turning
     drift (bar_gap_bound's terms at d = 100), finite;
   - a revolute motor with max torque 0: accepted, it does nothing: a
     disc pinned at its centre, spinning at 3 rad/s, motor toward -5
     rad/s: its spin stays 3 exactly (the clamp leaves the impulse 0),
     the reported motor torque 0;
   - spring hertz exactly at the cap (a quarter of the substep rate, 60
     Hz at 4 substeps): accepted and taken as asked; any higher (1e6,
     1e30 Hz) accepted and made at the cap: the runs are bit for bit the
     run at the cap, finite (the implicit step is stable at any e = 2 pi
     f h; at the cap e = pi/2 and its period, test_joints.c's 2 pi h /
     acos(1 - e^2 / (2 (1 + e^2))), is 7.2 substeps, printed). */
static ga2d_body_id disc_pinned(ga2d_world *w, ga2d_body_id p, double spin, ga2d_revolute_joint_def *d)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_body_id b;
    bd.type = GA2D_BODY_DYNAMIC;
    bd.angular_velocity = (ga2d_real)spin;
    b = ga2d_body_create(w, &bd);
    c.center = v2(0, 0);
    c.radius = (ga2d_real)0.5;
    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
    *d = hinge_def(p, b, v2(0, 0), v2(0, 0));
    return b;
}

static void parameters_at_the_edge(void)
{
    const double om = 2 * PI * JOINT_HERTZ;
    /* a distance joint of length 0, and of the least positive length */
    {
        ga2d_world *w = make_world(0, -G, 1, SUB);
        ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, 0, 0, 0, 0.1, 0.1, 1);
        ga2d_distance_joint_def d = ga2d_default_distance_joint_def();
        ga2d_joint_id j;
        unsigned char *ref;
        size_t n, n2;
        double worst = 0, bound = 2 * G / (om * om) + 16 * U;
        int k, finite = 1;
        d.body_a = p;
        d.body_b = b;
        d.length = 0;
        ref = snapshot(w, &n);
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_ERR_INVALID_ARGUMENT);
        CHECK(ga2d_joint_id_is_null(j));
        {
            unsigned char *now = snapshot(w, &n2);
            CHECK(now && ref && n == n2 && memcmp(now, ref, n) == 0);
            free(now);
        }
        free(ref);
        d.length = (ga2d_real)REAL_MIN;
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 120; ++k) {
            double l;
            step(w);
            l = (double)ga2d_distance_joint_current_length(w, j);
            finite &= body_finite(w, b) && isfinite(l);
            if (l > worst) worst = l;
        }
        CHECK(finite);
        CHECK(worst <= bound);
        if (verbose())
            printf("joint extremes: distance length 0 refused; length %.3g accepted: the box hangs %.3g m off the anchor "
                   "<= %.3g (twice g / omega_s^2), finite\n",
                   REAL_MIN, worst, bound);
        ga2d_world_destroy(w);
    }
    /* a revolute limit with lower == upper */
    {
        ga2d_world *w = make_world(0, -G, 1, SUB);
        const double lim = 0.3;
        ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, 0.5 * cos(lim), 0.5 * sin(lim), lim, 0.5, 0.05, 1);
        ga2d_revolute_joint_def d = hinge_def(p, b, v2(0, 0), v2(-0.5, 0));
        ga2d_joint_id j;
        double I, tau, bound, worst = 0;
        int k;
        d.enable_limit = 1;
        d.lower_angle = d.upper_angle = (ga2d_real)lim;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        I = (double)ga2d_body_mass_data(w, b).inertia;
        tau = mass_of(w, b) * G * 0.5 * cos(lim);
        bound = 2 * tau / (I * om * om) + 8 * U;
        for (k = 0; k < 120; ++k) {
            step(w);
            if (fabs((double)ga2d_revolute_joint_angle(w, j) - lim) > worst) worst = fabs((double)ga2d_revolute_joint_angle(w, j) - lim);
        }
        CHECK(body_finite(w, b));
        CHECK(worst <= bound);
        if (verbose())
            printf("joint extremes: revolute limit lower == upper = %.1f rad accepted: held within %.3g rad <= %.3g\n", lim,
                   worst, bound);
        ga2d_world_destroy(w);
    }
    /* anchors 100 m from the body */
    {
        const double D = 100, th0 = 5 * PI / 180;
        ga2d_world *w = make_world(0, -G, 1, SUB);
        ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, D * sin(th0), -D * cos(th0), th0, 0.1, 0.1, 1);
        ga2d_joint_id j = hinge(w, p, b, v2(0, 0), v2(0, D));
        double m = mass_of(w, b), I = (double)ga2d_body_mass_data(w, b).inertia, ip = I + m * D * D;
        double T0 = 2 * PI * sqrt(ip / (m * G * D)), w0 = 2 * PI / T0, T = T0 / agm(1, cos(th0 / 2)), phase = (w0 * H) * (w0 * H) / 24;
        double prev, first = 0, last = 0, max_gap = 0, e0, e_min, bound, gap_bound, w2 = 2 * m * G * D * (1 - cos(th0)) / ip;
        soft js = make_soft(JOINT_HERTZ, JOINT_ZETA, H);
        int k, crossings = 0, finite = 1;
        e0 = e_min = m * G * (double)ga2d_body_center(w, b).y;
        prev = (double)ga2d_body_center(w, b).x;
        for (k = 1; crossings <= 2 && k < 5000; ++k) {
            ga2d_vec v, c;
            double x, e, om_b = 0;
            step(w);
            v = ga2d_body_velocity(w, b);
            c = ga2d_body_center(w, b);
            om_b = (double)ga2d_body_angular_velocity(w, b);
            e = 0.5 * m * ((double)v.x * (double)v.x + (double)v.y * (double)v.y) + 0.5 * I * om_b * om_b + m * G * (double)c.y;
            if (e < e_min) e_min = e;
            if (anchor_gap(w, j, v2(0, 0), v2(0, D)) > max_gap) max_gap = anchor_gap(w, j, v2(0, 0), v2(0, D));
            finite &= body_finite(w, b);
            x = (double)c.x;
            if (prev < 0 && x >= 0) {
                double tc = k * DT - DT * x / (x - prev);
                if (crossings == 0) first = tc;
                last = tc;
                ++crossings;
            }
            prev = x;
        }
        gap_bound = (G + w2 * D) / (om * om) + w2 * H * D / (2 * js.bias * js.ms) + 8 * U * D;
        bound = max_gap * (m * D / ip + 1 / (2 * D)) + 2 * w0 * w0 * DT * DT * DT / 8 / 2 / T + (e0 - e_min) / (8 * m * G * D) + 16 * U;
        CHECK(finite);
        CHECK(crossings > 2);
        CHECK(max_gap <= gap_bound);
        CHECK_NEAR((last - first) / 2 / (T * (1 - phase)), 1, bound);
        if (verbose())
            printf("joint extremes: anchor 100 m from its body: period %.6f s vs exact %.6f less the phase error: |rel| %.3g "
                   "<= %.3g; gap %.3g m <= %.3g\n",
                   (last - first) / 2, T, fabs((last - first) / 2 / (T * (1 - phase)) - 1), bound, max_gap, gap_bound);
        ga2d_world_destroy(w);
    }
    /* a motor with max torque 0 */
    {
        ga2d_world *w = make_world(0, -G, 1, SUB);
        ga2d_body_id p = pivot_body(w, 0, 0), b;
        ga2d_revolute_joint_def d;
        ga2d_joint_id j;
        int k, same = 1;
        b = disc_pinned(w, p, 3, &d);
        d.enable_motor = 1;
        d.motor_speed = -5;
        d.max_motor_torque = 0;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 60; ++k) {
            step(w);
            same &= ga2d_body_angular_velocity(w, b) == 3 && ga2d_revolute_joint_motor_torque(w, j) == 0;
        }
        CHECK(same);
        if (verbose()) printf("joint extremes: motor of max torque 0 accepted: the spin stayed 3 rad/s exactly: %d\n", same);
        ga2d_world_destroy(w);
    }
    /* spring hertz at the cap, and above it */
    {
        static const double hz[3] = {0.25 / H, 1e6, 1e30};
        double angle[3][60], e = 2 * PI * (0.25 / H) * H, Td = 2 * PI * H / acos(1 - e * e / (2 * (1 + e * e)));
        int i, k, same = 1, finite = 1;
        for (i = 0; i < 3; ++i) {
            ga2d_world *w = make_world(0, -G, 1, SUB);
            ga2d_body_id p = pivot_body(w, 0, 0), b;
            ga2d_revolute_joint_def d;
            ga2d_joint_id j;
            b = disc_pinned(w, p, 0, &d);
            CHECK_RESULT(ga2d_body_set_transform(w, b, v2(0, 0), ga2d_rotor_from_angle((ga2d_real)0.3)), GA2D_OK);
            d.enable_spring = 1;
            d.hertz = (ga2d_real)hz[i];
            d.damping_ratio = 0;
            CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
            for (k = 0; k < 60; ++k) {
                step(w);
                angle[i][k] = (double)ga2d_revolute_joint_angle(w, j);
                finite &= isfinite(angle[i][k]) && body_finite(w, b);
                if (i > 0) same &= angle[i][k] == angle[0][k];
            }
            ga2d_world_destroy(w);
        }
        CHECK(finite);
        CHECK(same);
        if (verbose())
            printf("joint extremes: spring at the cap (%.0f Hz) accepted; 1e6 and 1e30 Hz accepted and made at the cap: the "
                   "same bits: %d; finite: %d; the scheme's period there %.4g s (1/f = %.4g s)\n",
                   0.25 / H, same, finite, Td, H * 4);
    }
}

/* A distance joint's range of no width: limit on, min_length = max_length
   = 0.5 m, length 1 m (its default), with and without a 2 Hz spring: the
   header keeps the distance "within [min_length, max_length]", so at 0.5
   m: the box (0.2 m square, its centre the anchor, gravity on), released
   at rest 0.5 m below a static anchor, hangs there by the rigid joint's
   rest gap g / omega_s^2 (m_eff = m: A static, no lever), within twice
   that (sudden load) plus rounding 16 u.  Before, a range of no width was
   no range: the joint held 1 m (rigid) or sprang about 1 m (spring),
   outside it. */
static void distance_range_of_no_width(void)
{
    const double om = 2 * PI * JOINT_HERTZ, bound = 2 * G / (om * om) + 16 * U;
    int spring;
    for (spring = 0; spring < 2; ++spring) {
        ga2d_world *w = make_world(0, -G, 1, SUB);
        ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, 0, -0.5, 0, 0.1, 0.1, 1);
        ga2d_distance_joint_def d = ga2d_default_distance_joint_def();
        ga2d_joint_id j;
        double worst = 0;
        int k;
        d.body_a = p;
        d.body_b = b;
        d.enable_limit = 1;
        d.min_length = d.max_length = (ga2d_real)0.5;
        d.enable_spring = spring;
        d.hertz = 2;
        CHECK_RESULT(ga2d_distance_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 120; ++k) {
            step(w);
            if (fabs((double)ga2d_distance_joint_current_length(w, j) - 0.5) > worst)
                worst = fabs((double)ga2d_distance_joint_current_length(w, j) - 0.5);
        }
        CHECK(worst <= bound);
        if (verbose())
            printf("joint extremes: distance range 0.5..0.5 m (length 1 m%s): held %.3g m off 0.5 <= %.3g\n",
                   spring ? ", spring 2 Hz" : "", worst, bound);
        ga2d_world_destroy(w);
    }
}

void suite_joints_extremes(void)
{
    test_run("joint extremes: a motor past the speed caps", motor_past_the_caps);
    test_run("joint extremes: a chain flung past the speed cap", chain_flung);
    test_run("joint extremes: a pendulum and a spring from 1 cm to 100 m", scale_runs);
    test_run("joint extremes: a pendulum far from the origin swings as one at it", far_from_origin);
    test_run("joint extremes: mass ratios 1 to 1000 hanging, both orders", mass_ratios);
    test_run("joint extremes: an undamped pendulum for 10^5 steps", long_run);
    test_run("joint extremes: a distance joint of absurd length pushes out at the cap, counted", distance_absurd_length);
    test_run("joint extremes: parameters at the edge of acceptance", parameters_at_the_edge);
    test_run("joint extremes: a distance range of no width holds there", distance_range_of_no_width);
}
