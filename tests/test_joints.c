/* Joints against physics (issue 24): revolute joints.  A compound
   pendulum's period (small and large amplitude) and energy, the reaction
   force of a hanging mass and of a spinning bar, a motor of limited torque,
   limits, a rotational spring's period and damping, momentum of two joined
   bodies, a hanging chain's separation, errors and misuse, destruction,
   islands and sleep, collide_connected, snapshots and determinism.

   dt = 1/60 and 4 substeps throughout (h = 1/240 s), g = 10.  A rigid
   joint is held by a position feedback of 60 Hz (under the quarter of the
   substep rate, which caps it) and damping ratio 2, made as the soft step
   makes every spring (Catto's soft step; make_soft below):
   omega_s = 2 pi 60, bias rate b = omega_s / (2 zeta + h omega_s), mass
   scale ms = a / (1 + a), impulse scale 1 / (1 + a), a = h omega_s (2 zeta
   + h omega_s).  Two facts of that feedback are used below:
   - a joint carrying a steady force F over an effective mass m_eff (the
     inverse of its 2x2 mass matrix along F) rests where the soft pass
     adds nothing: ms b m_eff sep = impulse_scale * F h, i.e.
     sep = F / (m_eff omega_s^2) (the spring's static deflection);
   - a body turning about a joint at w drifts off it by w^2 h^2 d / 2 per
     substep (its centre moves on the tangent, its anchor turns on the
     circle), and the soft pass takes back the part h b ms of the
     separation per substep: the drift rests at w^2 h d / (2 b ms).

   With GA2D_TEST_VERBOSE set each scene prints "joints: ..." with its
   figure and bound.   */
#include "test.h"

#define DT (1.0 / 60)
#define SUB 4
#define H (DT / SUB)
#define G 10.0
#define PI 3.14159265358979323846
#define JOINT_HERTZ 60.0 /* the header's GA2D__JOINT_HERTZ, under a quarter of 240 Hz */
#define JOINT_ZETA 2.0

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
static double omega_s(void) { return 2 * PI * JOINT_HERTZ; }

static ga2d_world *make_world(double gx, double gy, int sleep)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.gravity = v2(gx, gy);
    wd.enable_sleep = sleep;
    return ga2d_world_create(&wd);
}

static void step(ga2d_world *w) { CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK); }
static void steps(ga2d_world *w, int n)
{
    int i;
    for (i = 0; i < n; ++i) step(w);
}

/* A static body with no shape at (x, y): a pivot. */
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

/* A dynamic disc of radius r (density 1) centred at its origin (x, y). */
static ga2d_body_id disc_body(ga2d_world *w, double x, double y, double angle, double r)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_body_id b;
    d.type = GA2D_BODY_DYNAMIC;
    d.position = v2(x, y);
    d.rotor = ga2d_rotor_from_angle((ga2d_real)angle);
    b = ga2d_body_create(w, &d);
    c.center = v2(0, 0);
    c.radius = (ga2d_real)r;
    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
    return b;
}

static ga2d_revolute_joint_def hinge_def(ga2d_body_id a, ga2d_body_id b, double ax, double ay, double bx, double by)
{
    ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
    d.body_a = a;
    d.body_b = b;
    d.local_anchor_a = v2(ax, ay);
    d.local_anchor_b = v2(bx, by);
    return d;
}

static ga2d_joint_id hinge(ga2d_world *w, ga2d_body_id a, ga2d_body_id b, double ax, double ay, double bx, double by)
{
    ga2d_revolute_joint_def d = hinge_def(a, b, ax, ay, bx, by);
    ga2d_joint_id j;
    CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
    return j;
}

/* A body point given in its frame (relative to its origin), in the world. */
static ga2d_vec world_point(const ga2d_world *w, ga2d_body_id b, double lx, double ly)
{
    return ga2d_transform_apply(ga2d_body_transform(w, b), v2(lx, ly));
}

static double dist(ga2d_vec a, ga2d_vec b) { return hypot((double)a.x - (double)b.x, (double)a.y - (double)b.y); }

/* Body states, bit for bit. */
typedef struct body_bits { ga2d_vec p, v; ga2d_rotor q; ga2d_real w; } body_bits;
static body_bits bits_of(const ga2d_world *w, ga2d_body_id b)
{
    body_bits s;
    memset(&s, 0, sizeof s);
    s.p = ga2d_body_position(w, b);
    s.v = ga2d_body_velocity(w, b);
    s.q = ga2d_body_rotor(w, b);
    s.w = ga2d_body_angular_velocity(w, b);
    return s;
}

/* The world distance between a joint's anchors (la on A, lb on B). */
static double anchor_gap(const ga2d_world *w, ga2d_joint_id j, ga2d_vec la, ga2d_vec lb)
{
    ga2d_body_id a = ga2d_joint_body_a(w, j), b = ga2d_joint_body_b(w, j);
    return dist(world_point(w, a, (double)la.x, (double)la.y), world_point(w, b, (double)lb.x, (double)lb.y));
}

/* Kinetic plus potential energy (g along -y) of a body. */
static double energy(const ga2d_world *w, ga2d_body_id b, double g)
{
    ga2d_mass m = ga2d_body_mass_data(w, b);
    ga2d_vec v = ga2d_body_velocity(w, b);
    double om = (double)ga2d_body_angular_velocity(w, b), vx = (double)v.x, vy = (double)v.y, mass = (double)m.mass, inertia = (double)m.inertia;
    double y = (double)ga2d_body_center(w, b).y;
    return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * om * om + mass * g * y;
}

/* The arithmetic-geometric mean: K(k) = pi / (2 AGM(1, sqrt(1 - k^2))). */
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

/* The exact period of a pendulum of small-amplitude period T0 swinging to
   amplitude th: T0 * 2 K(sin(th/2)) / pi = T0 / AGM(1, cos(th/2)). */
static double pendulum_period(double T0, double th) { return T0 / agm(1, cos(th / 2)); }

/* ============================================================ pendulum */
/* The bar: 1 m x 0.1 m, density 1, hinged at one end (its local
   (-0.5, 0)) to a static pivot at the origin, hanging at angle th0 from
   the downward vertical, released from rest. */
#define BAR_HX 0.5
#define BAR_HY 0.05
static ga2d_body_id bar_pendulum(ga2d_world *w, double th0, ga2d_joint_id *j)
{
    ga2d_body_id p = pivot_body(w, 0, 0);
    ga2d_body_id bar = box_body(w, BAR_HX * sin(th0), -BAR_HX * cos(th0), th0 - PI / 2, BAR_HX, BAR_HY, 1);
    *j = hinge(w, p, bar, 0, 0, -BAR_HX, 0);
    return bar;
}

/* Swings the pendulum and times `periods` full periods by the upward zero
   crossings of the bar's x (linear interpolation between steps).  Reports
   the mean period, the largest anchor separation and the energies. */
typedef struct swing {
    double period, max_sep, e0, e_max, e_min, e_end;
    double e_max_first, e_max_last; /* the highest energy over the first and the last tenth */
} swing;
static swing swing_pendulum(double th0, int periods)
{
    ga2d_world *w = make_world(0, -G, 0);
    ga2d_joint_id j;
    ga2d_body_id bar = bar_pendulum(w, th0, &j);
    swing s;
    int crossings = 0, tenth = periods / 10 > 0 ? periods / 10 : 1;
    long n;
    double prev = (double)ga2d_body_position(w, bar).x, first = 0, last = 0;
    s.e0 = energy(w, bar, G);
    s.e_max = s.e_min = s.e_max_first = s.e_max_last = s.e0;
    s.max_sep = 0;
    for (n = 1; crossings <= periods; ++n) {
        double x, e, sep;
        step(w);
        x = (double)ga2d_body_position(w, bar).x;
        e = energy(w, bar, G);
        sep = dist(world_point(w, bar, -BAR_HX, 0), v2(0, 0));
        if (sep > s.max_sep) s.max_sep = sep;
        if (e > s.e_max) s.e_max = e;
        if (e < s.e_min) s.e_min = e;
        if (crossings < tenth && e > s.e_max_first) s.e_max_first = e;
        if (crossings > periods - tenth) {
            if (crossings == periods - tenth + 1 && prev < 0 && x >= 0) s.e_max_last = e;
            if (e > s.e_max_last) s.e_max_last = e;
        }
        if (prev < 0 && x >= 0) {
            double tc = n * DT - DT * x / (x - prev);
            if (crossings == 0) first = tc;
            last = tc;
            ++crossings;
        }
        prev = x;
        if (n > 1000000) break; /* never: a pendulum that stopped */
    }
    s.period = (last - first) / periods;
    s.e_end = energy(w, bar, G);
    ga2d_world_destroy(w);
    return s;
}

/* The bar's numbers: m = 0.1 kg, I about its centre m (L^2 + W^2) / 12,
   about the pivot I_p = I + m d^2 (d = 0.5), small-amplitude period
   T0 = 2 pi sqrt(I_p / (m g d)), w0 = 2 pi / T0. */
static void bar_numbers(double *m, double *ip, double *T0)
{
    *m = 4 * BAR_HX * BAR_HY;
    *ip = *m * (4 * BAR_HX * BAR_HX + 4 * BAR_HY * BAR_HY) / 12 + *m * BAR_HX * BAR_HX;
    *T0 = 2 * PI * sqrt(*ip / (*m * G * BAR_HX));
}

/* Released from 5 degrees, timed over 1000 periods.  The period is the
   exact one of the amplitude, T0 / AGM(1, cos(th0/2)) (the series 1 +
   th0^2/16 + ... summed), less the integrator's phase error: symplectic
   Euler on an oscillator of w0 turns by 2 asin(w0 h / 2) per substep, a
   frequency high by (w0 h)^2 / 24 (to (w0 h)^4), so the period is short
   by that fraction (1.1e-5 here).  The other errors, bounded:
   - the joint's separation s moves the bar's centre out by up to s: I_p
     grows by 2 m d s, m g d by m g s, the period by at most
     s (m d / I_p + 1 / (2 d)) relative (its sign unknown: added to the bound);
   - the crossings' linear interpolation is off by at most w^2 dt^3 / 8 in
     time (x'' vanishes at the crossing, x''' <= w^3 x'), twice over the
     mean of N periods;
   - the amplitude's loss to the soft joint's damping: T grows with the
     amplitude as th^2/16, and the energy lost over the run (measured, at
     most e0 - e_min) bounds how far the amplitude fell: th dth = dE /
     (m g d) at small amplitude, so dT/T <= (e0 - e_min) / (8 m g d).
   Energy: symplectic Euler keeps a modified energy H~ = H + (h/2) p.V'/m
   + O(h^2) constant, so E = H~ - (h/2) p.V'/m moves about its start
   (where p = 0) by at most (h/2) max |p V'| / m <= (w0 h / 2) E_osc (E_osc
   the swing's energy m g d (1 - cos th0): p V' / m is at most w0 E_osc for
   an oscillator); the joint's spring and sag only take energy away.  So E
   never exceeds E0 + (w0 h / 2) E_osc + rounding (the energy's own: the
   centre's height |y| <= 0.5 at 2 ulp, the speeds' squares at 4 ulp, times
   m g and the energies: 8 u (m g d + E_osc)); and the last tenth's highest
   energy is no higher than the first tenth's (no growth) by more than that
   rounding. */
static void pendulum_small_amplitude(void)
{
    const int periods = 1000;
    const double th0 = 5 * PI / 180, u = REAL_EPS / 2;
    double m, ip, T0, w0, T, phase, sep_term, interp, amp, bound, e_osc, e_bound, rounding;
    swing s;
    bar_numbers(&m, &ip, &T0);
    w0 = 2 * PI / T0;
    T = pendulum_period(T0, th0);
    s = swing_pendulum(th0, periods);
    phase = (w0 * H) * (w0 * H) / 24;
    sep_term = s.max_sep * (m * BAR_HX / ip + 1 / (2 * BAR_HX));
    interp = 2 * w0 * w0 * DT * DT * DT / 8 / periods / T;
    amp = (s.e0 - s.e_min) / (8 * m * G * BAR_HX);
    bound = sep_term + interp + amp + 16 * u;
    /* the period against the exact one less the phase error, within the rest */
    CHECK_NEAR(s.period / (T * (1 - phase)), 1, bound);
    /* and against the exact one within the phase error and the rest */
    CHECK(fabs(s.period / T - 1) <= phase + bound);
    e_osc = m * G * BAR_HX * (1 - cos(th0));
    rounding = 8 * u * (m * G * BAR_HX + e_osc);
    e_bound = w0 * H / 2 * e_osc + rounding;
    CHECK(s.e_max - s.e0 <= e_bound);
    CHECK(s.e_max_last <= s.e_max_first + rounding);
    if (verbose())
        printf("joints: pendulum 5 deg: period %.7f s, exact %.7f, less the phase error %.7f: |rel| %.3g <= %.3g; "
               "energy over %d periods: max rise %.3g J <= %.3g, last tenth's max - first's %.3g <= %.3g, "
               "lost %.3g J of E_osc %.3g; max separation %.3g m\n",
               s.period, T, T * (1 - phase), fabs(s.period / (T * (1 - phase)) - 1), bound, periods, s.e_max - s.e0,
               e_bound, s.e_max_last - s.e_max_first, rounding, s.e0 - s.e_end, e_osc, s.max_sep);
}

/* Released from 90 degrees, timed over 3 periods.  The exact period of
   the amplitude T(th) = T0 / AGM(1, cos(th/2)).  The soft joint loses a
   little energy each swing, so over the timed periods the amplitude lies
   between th0 and th_end (from the energy at the end: E_end - E_bottom =
   m g d (1 - cos th_end)); T grows with the amplitude, so the measured
   period lies within [T(th_end), T(th0)], widened by the integrator's
   phase error (w0 h)^2 / 24 (the local frequency w0^2 cos th is at most
   w0^2: the linear oscillator's error bounds it), the separation's term
   as at 5 degrees and the interpolation (w^3 at most w0^3 2^(3/2)).
   The separation itself: the load along the bar (effective mass m: the
   anchor's line through the centre) is m (g + w^2 d) at most, w^2 <=
   2 m g d / I_p at the bottom: a static sag (g + w^2 d) / omega_s^2, and
   the turning drift w^2 h d / (2 b ms): their sum bounds it. */
static void pendulum_large_amplitude(void)
{
    const int periods = 3;
    const double th0 = PI / 2, u = REAL_EPS / 2;
    double m, ip, T0, w0, th_end, lo, hi, slack, w2, sep_bound, e_bottom;
    soft js = make_soft(JOINT_HERTZ, JOINT_ZETA, H);
    swing s;
    bar_numbers(&m, &ip, &T0);
    w0 = 2 * PI / T0;
    s = swing_pendulum(th0, periods);
    e_bottom = -m * G * BAR_HX;
    th_end = acos(1 - (s.e_end - e_bottom) / (m * G * BAR_HX));
    w2 = 2 * m * G * BAR_HX / ip;
    sep_bound = (G + w2 * BAR_HX) / (omega_s() * omega_s()) + w2 * H * BAR_HX / (2 * js.bias * js.ms);
    slack = (w0 * H) * (w0 * H) / 24 + s.max_sep * (m * BAR_HX / ip + 1 / (2 * BAR_HX)) +
            2 * pow(w0 * sqrt(2.0), 2) * DT * DT * DT / 8 / periods / T0 + 16 * u;
    lo = pendulum_period(T0, th_end) * (1 - slack);
    hi = pendulum_period(T0, th0) * (1 + slack);
    CHECK(s.period >= lo && s.period <= hi);
    CHECK(s.max_sep <= sep_bound);
    if (verbose())
        printf("joints: pendulum 90 deg: period %.6f s within [%.6f, %.6f] (exact %.6f at 90, %.6f at %.3f deg after "
               "the loss); max separation %.3g m <= %.3g\n",
               s.period, lo, hi, pendulum_period(T0, th0), pendulum_period(T0, th_end), th_end * 180 / PI, s.max_sep,
               sep_bound);
}

/* ========================================================= reaction */
/* A box hangs from a static pivot by its top, at rest: the joint carries
   its weight, so the reaction on it is (0, m g), and no torque.  Settled:
   the feedback's slow mode decays at omega_s (zeta - sqrt(zeta^2 - 1))
   = 150 /s, so after 2 s what is left is below rounding.  At rest every
   substep's impulse gives back exactly what gravity took (the velocity
   returns to where it was), to the rounding of v - g h + P / m: a few ulp
   of g h, so |F - m g| <= 8 u m g; the horizontal part likewise
   <= 8 u m g.  Three masses and three hanging depths. */
static void reaction_hanging_mass(void)
{
    const double u = REAL_EPS / 2;
    const double dens[3] = {0.1, 1, 30}, half[3] = {0.1, 0.25, 0.5};
    int i;
    double worst = 0;
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, -G, 0);
        ga2d_body_id p = pivot_body(w, 1, 2);
        ga2d_body_id b = box_body(w, 1, 2 - half[i], 0, half[i], half[i], dens[i]);
        ga2d_joint_id j = hinge(w, p, b, 0, 0, 0, half[i]);
        double mg;
        ga2d_vec f;
        steps(w, 120);
        mg = (double)ga2d_body_mass_data(w, b).mass * G;
        f = ga2d_joint_reaction_force(w, j);
        CHECK_NEAR(f.y, mg, 8 * u * mg);
        CHECK_NEAR(f.x, 0, 8 * u * mg);
        CHECK_NEAR(ga2d_joint_reaction_torque(w, j), 0, 0);
        if (fabs((double)f.y - mg) / mg > worst) worst = fabs((double)f.y - mg) / mg;
        ga2d_world_destroy(w);
    }
    if (verbose()) printf("joints: hanging mass: |F - m g| / m g worst %.3g <= %.3g\n", worst, 8 * u);
}

/* A hub hangs from a static post by its centre and carries HUB_SPOKES
   weights, each hinged to the hub's centre and hanging straight below it
   (one group, so they never touch): the hub has more joints than the
   solver has colours, and the last of them are solved after the colours
   (the overflow).  At rest each weight's joint carries exactly its weight
   and the post carries all of it.  Every substep the warm start gives
   back the impulses that held the bodies last substep, so the passes see
   only rounding.  Each substep's three passes (warm start, soft, relax)
   each change the hub's velocity HUB_SPOKES + 1 times, by impulses of at
   most the whole load L h, each change rounded: the hub's velocity is
   off by up to 3 (HUB_SPOKES + 1) u L h / M (M the hub's mass).  A
   weight's joint sees that, and corrects it with at most the weight's
   mass, so per substep h: |F - m g| <= 8 u m g (its own rounding, as the
   hanging mass above) + 3 (HUB_SPOKES + 1) u m L / M.  The post's force
   balances the hub: off by its own 3 (HUB_SPOKES + 1) u L + 8 u L and the
   weights' errors.  (The step's state comes to a fixed point, the same
   bits every step, within those.)  Started at rest where it will hang,
   nothing swings. */
#define HUB_SPOKES 40
static void reaction_hub_past_the_colours(void)
{
    const double u = REAL_EPS / 2;
    ga2d_world *w = make_world(0, -G, 0);
    ga2d_body_id post = pivot_body(w, 0, 0), hub = box_body(w, 0, 0, 0, 0.5, 0.5, 1), weight[HUB_SPOKES];
    ga2d_joint_id held = hinge(w, post, hub, 0, 0, 0, 0), spoke[HUB_SPOKES];
    ga2d_body_def d = ga2d_default_body_def();
    double load, hub_mass, worst = 0, post_bound;
    ga2d_vec f;
    int i;
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box((ga2d_real)0.1, (ga2d_real)0.1);
    d.filter.group_index = -1;
    hub_mass = (double)ga2d_body_mass_data(w, hub).mass;
    load = hub_mass * G;
    for (i = 0; i < HUB_SPOKES; ++i) {
        d.position = v2(0, -1 - 0.1 * (i % 5)); /* five depths */
        d.density = (ga2d_real)(1 + i % 3);    /* three masses */
        weight[i] = ga2d_body_create(w, &d);
        spoke[i] = hinge(w, hub, weight[i], 0, 0, 0, 1 + 0.1 * (i % 5));
        load += (double)ga2d_body_mass_data(w, weight[i]).mass * G;
    }
    steps(w, 120);
    post_bound = (3 * (HUB_SPOKES + 1) + 8) * u * load;
    for (i = 0; i < HUB_SPOKES; ++i) {
        double m = (double)ga2d_body_mass_data(w, weight[i]).mass, bound = 8 * u * m * G + 3 * (HUB_SPOKES + 1) * u * m * load / hub_mass;
        f = ga2d_joint_reaction_force(w, spoke[i]);
        CHECK_NEAR(f.y, m * G, bound);
        CHECK_NEAR(f.x, 0, bound);
        post_bound += bound;
        if (fabs((double)f.y - m * G) / bound > worst) worst = fabs((double)f.y - m * G) / bound;
    }
    f = ga2d_joint_reaction_force(w, held);
    CHECK_NEAR(f.y, load, post_bound);
    CHECK_NEAR(f.x, 0, post_bound);
    if (verbose())
        printf("joints: hub of %d weights: worst weight |F - m g| %.3g of its bound, post |F - L| %.3g of its bound\n",
               HUB_SPOKES, worst, fabs((double)f.y - load) / post_bound);
    ga2d_world_destroy(w);
}

/* The bar spins about its end (gravity off) at w: the joint holds it on
   its circle with the centripetal force, pointing at the pivot.  Per
   substep the velocity turns by w h, an impulse of 2 m v sin(w h/2) =
   m v w h (1 - (w h)^2 / 24).  The joint holds the anchors s apart (the
   turning drift, see the top: s <= w^2 h d / (2 b ms) + w^2 d / omega_s^2,
   checked): the centre's speed is w d (B's anchor at rest after the relax
   pass, |r_b| = d) on a circle of radius between d and d + s, and the
   feedback pulls the centre in by about s per the same time: the force is
   m w^2 d' (d' the centre's distance from the pivot) within 2 s / d.  Its
   direction: the last substep's, whose velocity turned about the middle of
   that substep, so it points at the pivot from half a substep's turn
   before where the bar is read (w h / 2 behind, in the turn's sense),
   within the tilt s / d of the line from A's anchor to B's.  w: the
   joint's impulse passes through the pivot, so the angular momentum about
   it, w (I + m d'^2), stays: as d' grows by s, w drops by 2 m d s / I_p.
   Rounding 16 u.  The first 3 steps, where s grows from 0 (by the
   fraction h b ms = 0.35 of what is left per substep: under 1% left after
   12), are not timed (the spin slows meanwhile: a tangential force).  Three speeds, both
   senses of turning. */
static void reaction_spinning_bar(void)
{
    const double u = REAL_EPS / 2, ws[3] = {2, 6, -10};
    soft js = make_soft(JOINT_HERTZ, JOINT_ZETA, H);
    double m, ip, T0;
    int i, k;
    double worst = 0, worst_angle = 0, worst_sep = 0;
    bar_numbers(&m, &ip, &T0);
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, 0, 0);
        ga2d_body_id p = pivot_body(w, 0, 0);
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_body_id b;
        ga2d_joint_id j;
        double w0 = ws[i], s_bound = w0 * w0 * H * BAR_HX / (2 * js.bias * js.ms) + w0 * w0 * BAR_HX / (omega_s() * omega_s());
        d.type = GA2D_BODY_DYNAMIC;
        d.position = v2(BAR_HX, 0);
        d.polygon = ga2d_polygon_box((ga2d_real)BAR_HX, (ga2d_real)BAR_HY);
        d.angular_velocity = (ga2d_real)w0;
        d.velocity = v2(0, w0 * BAR_HX);
        b = ga2d_body_create(w, &d);
        j = hinge(w, p, b, 0, 0, -BAR_HX, 0);
        for (k = 0; k < 60; ++k) {
            ga2d_vec f, c;
            double mass = (double)ga2d_body_mass_data(w, b).mass, om, dd, expect, fl, lag, cross, sep;
            step(w);
            f = ga2d_joint_reaction_force(w, j);
            c = ga2d_body_center(w, b);
            om = (double)ga2d_body_angular_velocity(w, b);
            dd = hypot((double)c.x, (double)c.y);
            sep = dist(world_point(w, b, -BAR_HX, 0), v2(0, 0));
            CHECK(sep <= s_bound);
            CHECK_NEAR(om, w0, fabs(w0) * 2 * m * BAR_HX * s_bound / ip + 16 * u * fabs(w0));
            if (sep > worst_sep) worst_sep = sep;
            if (k < 3) continue;
            expect = mass * om * om * dd * (1 - (om * H) * (om * H) / 24);
            fl = hypot((double)f.x, (double)f.y);
            CHECK_NEAR(fl / expect, 1, 2 * sep / BAR_HX + 16 * u);
            /* the angle from the pivot's direction (-c) to F, in the turn's sense */
            cross = (-(double)c.x * (double)f.y + (double)c.y * (double)f.x) / (dd * fl);
            lag = asin(cross) * (om > 0 ? 1 : -1);
            CHECK_NEAR(lag, -fabs(om) * H / 2, sep / BAR_HX + 16 * u);
            if (fabs(fl / expect - 1) > worst) worst = fabs(fl / expect - 1);
            if (fabs(lag + fabs(om) * H / 2) > worst_angle) worst_angle = fabs(lag + fabs(om) * H / 2);
        }
        if (verbose())
            printf("joints: spinning bar at %+.0f rad/s: separation %.3g m <= %.3g\n", w0, worst_sep, s_bound);
        ga2d_world_destroy(w);
    }
    if (verbose())
        printf("joints: spinning bar: |F / m w^2 d - 1| worst %.3g (<= 2 s/d); direction off the half-substep lag by "
               "%.3g rad (<= s/d)\n", worst, worst_angle);
}

/* ============================================================ motor */
/* A disc (radius 0.5, density 1) pinned at its centre to a static pivot,
   a motor of max torque T toward speed w_t.  The pin passes through the
   centre (no lever arm), so only the motor turns it: warm started at its
   cap T h, each substep adds T h / I to w exactly until the target is
   near, then the motor's impulse drops below the cap and w = w_t.  So
   w(t) = T t / I while accelerating and the reported motor torque is T
   (the cap over the substep, 2 u).  Rounding of w: n additions of one
   increment (itself rounded thrice: T h, times 1/I, 1/I itself: 4 u),
   each addition u/2 of the sum: |w - T t / I| <= (4u + n u / 2) |w| after n
   substeps.  Held: the motor's pass puts w back on w_t each substep, to 4 u
   |w_t|; its impulse is what the warm start overshot, I times that
   rounding: |torque| <= I 8 u |w_t| / h.  Gravity on (the pin carries the
   weight); both senses. */
static void motor_max_torque(void)
{
    const double u = REAL_EPS / 2, T = 0.5, targets[2] = {4, -3};
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, -G, 0);
        ga2d_body_id p = pivot_body(w, 0, 0), b = disc_body(w, 0, 0, 0, 0.5);
        ga2d_revolute_joint_def d = hinge_def(p, b, 0, 0, 0, 0);
        ga2d_joint_id j;
        double I = (double)ga2d_body_mass_data(w, b).inertia, wt = targets[i], sgn = wt > 0 ? 1 : -1, t_reach = fabs(wt) * I / T;
        double worst = 0;
        int accel_steps = 0, held_steps = 0;
        d.enable_motor = 1;
        d.motor_speed = (ga2d_real)wt;
        d.max_motor_torque = (ga2d_real)T;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 1; k <= 120; ++k) {
            double t = k * DT, om;
            step(w);
            om = (double)ga2d_body_angular_velocity(w, b);
            CHECK(ga2d_revolute_joint_speed(w, j) == ga2d_body_angular_velocity(w, b));
            if (t < t_reach - DT / 2) { /* the whole step accelerating (the next substep still below the target) */
                double expect = sgn * T * t / I;
                CHECK_NEAR(om, expect, (4 * u + SUB * k * u / 2) * fabs(expect));
                CHECK_NEAR(ga2d_revolute_joint_motor_torque(w, j), sgn * T, 2 * u * T);
                if (fabs(om - expect) / fabs(expect) > worst) worst = fabs(om - expect) / fabs(expect);
                ++accel_steps;
            } else if (t > t_reach + 2 * DT) {
                CHECK_NEAR(om, wt, 4 * u * fabs(wt));
                CHECK_NEAR(ga2d_revolute_joint_motor_torque(w, j), 0, I * 8 * u * fabs(wt) / H);
                ++held_steps;
            }
        }
        CHECK(accel_steps > 30 && held_steps > 30); /* the premise: both phases seen */
        if (verbose())
            printf("joints: motor T %.2f N m to %.1f rad/s on I %.4g: w = T t / I within %.3g rel over %d steps, "
                   "then held at %.9g, torque %.3g\n",
                   T, wt, I, worst, accel_steps, (double)ga2d_body_angular_velocity(w, b),
                   (double)ga2d_revolute_joint_motor_torque(w, j));
        ga2d_world_destroy(w);
    }
}

/* ============================================================ limits */
/* A disc pinned at its centre spins at w0 into a limit of +-0.5 rad.  The
   limit is speculative: while apart (room C > 0) its pass lets the angle
   close by at most C in the substep, and with no lever arm nothing else
   turns the disc, so the angle arrives at the limit and stops there, never
   past it by more than rounding: the angle from rotors of unit length
   (u each), its sum with the start angle (u |angle|): 8 u.  Both senses. */
static void limit_disc(void)
{
    const double u = REAL_EPS / 2, w0s[2] = {3, -3}, lo = -0.5, hi = 0.5, tol = 8 * u;
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, -G, 0);
        ga2d_body_id p = pivot_body(w, 0, 0), b = disc_body(w, 0, 0, 0, 0.5);
        ga2d_revolute_joint_def d = hinge_def(p, b, 0, 0, 0, 0);
        ga2d_joint_id j;
        double worst = 0, limit = w0s[i] > 0 ? hi : lo;
        CHECK_RESULT(ga2d_body_set_angular_velocity(w, b, (ga2d_real)w0s[i]), GA2D_OK);
        d.enable_limit = 1;
        d.lower_angle = (ga2d_real)lo;
        d.upper_angle = (ga2d_real)hi;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 60; ++k) {
            double a;
            step(w);
            a = (double)ga2d_revolute_joint_angle(w, j);
            CHECK(a >= lo - tol && a <= hi + tol);
            if (a - hi > worst) worst = a - hi;
            if (lo - a > worst) worst = lo - a;
        }
        CHECK_NEAR(ga2d_revolute_joint_angle(w, j), limit, tol); /* it came to rest on it */
        CHECK_NEAR(ga2d_body_angular_velocity(w, b), 0, tol / H);
        if (verbose())
            printf("joints: disc into the limit at %+.1f rad: past it by %.3g <= %.3g rad, rests at %.9g\n", limit, worst, tol,
                   (double)ga2d_revolute_joint_angle(w, j));
        ga2d_world_destroy(w);
    }
}

/* The bar hinged at its end, released level (joint angle 0), swings down
   into a limit at -pi/4 (gravity down) or +pi/4 (gravity up).  Here the
   pin has a lever arm: the limit's pass stops the turn, then the point's
   pass, which keeps the angular momentum about the pivot (its impulse
   acts there), gives back the fraction f = m d^2 / I_p of the closing
   speed (the centre still moving).  Each substep's two passes leave f and
   f^2 of the closing speed, and positions move after the first: from an
   impact at w_i the bar passes the limit by at most h f w_i (1 + f^2 +
   f^4 + ...) = h f w_i / (1 - f^2), w_i^2 = 2 m g d sin(pi/4) / I_p.  Then
   it rests on the limit, pressed by the weight's torque tau = m g d
   cos(pi/4) against the limit's feedback over the axial mass I (the
   centre's): tau / (I omega_s^2) past it (the static deflection). */
static void limit_pendulum(void)
{
    const double u = REAL_EPS / 2, lim = PI / 4;
    double m, ip, T0, f, wi, I, bound, rest;
    int i, k;
    bar_numbers(&m, &ip, &T0);
    f = m * BAR_HX * BAR_HX / ip;
    I = ip - m * BAR_HX * BAR_HX;
    wi = sqrt(2 * m * G * BAR_HX * sin(lim) / ip);
    rest = m * G * BAR_HX * cos(lim) / (I * omega_s() * omega_s());
    bound = H * f * wi / (1 - f * f) + rest + 8 * u;
    for (i = 0; i < 2; ++i) {
        double sgn = i == 0 ? -1 : 1, worst = 0, a = 0;
        ga2d_world *w = make_world(0, sgn * G, 0);
        ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, BAR_HX, 0, 0, BAR_HX, BAR_HY, 1);
        ga2d_revolute_joint_def d = hinge_def(p, b, 0, 0, -BAR_HX, 0);
        ga2d_joint_id j;
        d.enable_limit = 1;
        d.lower_angle = (ga2d_real)-lim;
        d.upper_angle = (ga2d_real)lim;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 120; ++k) {
            double past;
            step(w);
            a = (double)ga2d_revolute_joint_angle(w, j);
            past = sgn * a - lim;
            if (past > worst) worst = past;
        }
        CHECK(worst <= bound);
        CHECK_NEAR(a, sgn * lim, rest + 8 * u + rest); /* at rest on it: the deflection, to rounding */
        if (verbose())
            printf("joints: bar into the limit at %+.4f rad: past it by %.3g <= %.3g rad (impact %.3g rad/s, f %.3f); "
                   "rests %.3g past (static %.3g)\n",
                   sgn * lim, worst, bound, wi, f, sgn * a - lim, rest);
        ga2d_world_destroy(w);
    }
}

/* The limit's setters: lower above upper refused (INVALID_ARGUMENT), as
   is enabling a limit whose stored range is upside down; nothing changes
   (the world's snapshot bytes stay the same). */
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

static int same_snapshot(const ga2d_world *w, const unsigned char *ref, size_t ref_size)
{
    size_t n;
    unsigned char *now = snapshot(w, &n);
    int same = now && ref && n == ref_size && memcmp(now, ref, n) == 0;
    free(now);
    return same;
}

static void limit_setters(void)
{
    ga2d_world *w = make_world(0, -G, 1);
    ga2d_body_id p = pivot_body(w, 0, 0), b = box_body(w, BAR_HX, 0, 0, BAR_HX, BAR_HY, 1);
    ga2d_revolute_joint_def d = hinge_def(p, b, 0, 0, -BAR_HX, 0);
    ga2d_joint_id j, j2;
    unsigned char *ref;
    size_t n;
    d.lower_angle = 1; /* upside down, but the limit is off: accepted */
    d.upper_angle = -1;
    CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
    d.enable_limit = 1; /* on: refused */
    CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j2), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(ga2d_joint_id_is_null(j2));
    steps(w, 3);
    ref = snapshot(w, &n);
    CHECK_RESULT(ga2d_revolute_joint_enable_limit(w, j, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_revolute_joint_set_limits(w, j, (ga2d_real)0.5, (ga2d_real)0.25), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_revolute_joint_set_limits(w, j, (ga2d_real)NAN, (ga2d_real)0.25), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_revolute_joint_set_limits(w, j, 0, (ga2d_real)INFINITY), GA2D_ERR_NOT_FINITE);
    CHECK(same_snapshot(w, ref, n));
    /* equal bounds are a range (a locked hinge); then the limit turns on */
    CHECK_RESULT(ga2d_revolute_joint_set_limits(w, j, (ga2d_real)-0.25, (ga2d_real)-0.25), GA2D_OK);
    CHECK_RESULT(ga2d_revolute_joint_enable_limit(w, j, 1), GA2D_OK);
    free(ref);
    ga2d_world_destroy(w);
}

/* ============================================================ spring */
/* A rotational spring of f hertz, damping ratio zeta, on a disc pinned at
   its centre (the axial mass is the disc's I: make_soft on it is a spring
   k = I (2 pi f)^2, c = 2 zeta I 2 pi f), started 0.3 rad off at rest.
   Undamped, the continuous period is 1/f.  The soft step solves the spring
   implicitly in both passes of a substep (e = 2 pi f h, D = 1 + e (2 zeta
   + e), u = h w): the biased pass gives u1 = (u0 - e^2 x0) / D, positions
   x1 = x0 + u1, the relax pass u2 = u1 - ms (u1 + b h x1) - is (u1 - u0),
   which (ms + is = 1, ms b h = e^2 / D) is u2 = (u0 - e^2 x1) / D.  For
   zeta = 0 the map [x1 u2] = [[1, 1], [-e^2 / D, 1 / D]] [x0 u0] / D has
   det 1/D^2 and trace (D + 1)/D^2: eigenvalues D^-1 e^(+-i W h) with
   cos W h = (D + 1) / (2 D) = 1 - e^2 / (2 (1 + e^2)), the period 2 pi h
   / acos(...), long of 1/f by 11 e^2 / 24 (to e^4): checked below to be
   within e^2 / 2.  The measured period (upward zero crossings, linearly
   interpolated: a damped sine's x'' at the crossing is 2 g W |x'| / W^2 ... ,
   error <= dt^2 (2 g + W^2 dt) / 8 per crossing, g = ln D / h) over N
   periods is within twice that over N of it, plus rounding. */
static void spring_period(void)
{
    const double u = REAL_EPS / 2, fs[3] = {0.5, 1, 2}, th0 = 0.3;
    int i, k;
    for (i = 0; i < 3; ++i) {
        ga2d_world *w = make_world(0, -G, 0);
        ga2d_body_id p = pivot_body(w, 0, 0), b = disc_body(w, 0, 0, th0, 0.5);
        ga2d_revolute_joint_def d = hinge_def(p, b, 0, 0, 0, 0);
        ga2d_joint_id j;
        double e = 2 * PI * fs[i] * H, D = 1 + e * e, Td = 2 * PI * H / acos(1 - e * e / (2 * (1 + e * e)));
        double gam = log(D) / H, W = 2 * PI / Td, interp, prev, first = 0, last = 0;
        int crossings = 0, periods = 3;
        d.enable_spring = 1;
        d.hertz = (ga2d_real)fs[i];
        d.damping_ratio = 0;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        CHECK(fabs(Td * fs[i] - 1) <= e * e / 2); /* the derivation's own claim */
        prev = (double)ga2d_revolute_joint_angle(w, j);
        for (k = 1; crossings <= periods && k < 100000; ++k) {
            double a;
            step(w);
            a = (double)ga2d_revolute_joint_angle(w, j);
            if (prev < 0 && a >= 0) {
                double tc = k * DT - DT * a / (a - prev);
                if (crossings == 0) first = tc;
                last = tc;
                ++crossings;
            }
            prev = a;
        }
        interp = DT * DT * (2 * gam + W * W * DT) / 8;
        CHECK_NEAR((last - first) / periods, Td, 2 * interp / periods + 16 * u * Td);
        if (verbose())
            printf("joints: spring %.1f Hz on a disc: period %.6f s, the scheme's %.6f (1/f = %.6f), |diff| %.3g <= %.3g\n",
                   fs[i], (last - first) / periods, Td, 1 / fs[i], fabs((last - first) / periods - Td),
                   2 * interp / periods + 16 * u * Td);
        ga2d_world_destroy(w);
    }
}

/* Damping ratio 1: the map [[1 + 2e, 1], [-e^2 (1 + 2e) / D, (1 + 2e) / D]] / D
   (D = (1 + e)^2) has trace (1 + 2e)(D + 1) / D^2 and det (1 + 2e) / D^2,
   and (1 + 2e)(D + 1)^2 - 4 D^2 = 4 e^3 + ... > 0: two real positive
   eigenvalues, no oscillation: from rest the angle falls to 0 without
   passing it (by more than rounding, 8 u th0), and after 2 s (480
   substeps) it is below th0 480 lam^480, lam the slower eigenvalue
   (computed: a sum of two decaying powers from rest, the factor n
   covering roots near each other as a repeated root would bring). */
static void spring_critical(void)
{
    const double u = REAL_EPS / 2, fs[2] = {1, 3}, th0 = 0.3;
    int i, k;
    for (i = 0; i < 2; ++i) {
        ga2d_world *w = make_world(0, -G, 0);
        ga2d_body_id p = pivot_body(w, 0, 0), b = disc_body(w, 0, 0, th0, 0.5);
        ga2d_revolute_joint_def d = hinge_def(p, b, 0, 0, 0, 0);
        ga2d_joint_id j;
        double e = 2 * PI * fs[i] * H, D = (1 + e) * (1 + e), tr = (1 + 2 * e) * (D + 1) / (D * D), det = (1 + 2 * e) / (D * D);
        double disc = tr * tr / 4 - det, lam = tr / 2 + sqrt(disc > 0 ? disc : 0), lowest = th0;
        CHECK(disc > 0 && tr / 2 - sqrt(disc) > 0); /* the premise: real positive eigenvalues */
        d.enable_spring = 1;
        d.hertz = (ga2d_real)fs[i];
        d.damping_ratio = 1;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        for (k = 0; k < 120; ++k) {
            double a;
            step(w);
            a = (double)ga2d_revolute_joint_angle(w, j);
            if (a < lowest) lowest = a;
        }
        CHECK(lowest >= -8 * u * th0);
        CHECK(fabs((double)ga2d_revolute_joint_angle(w, j)) <= th0 * 480 * pow(lam, 480) + 8 * u * th0);
        if (verbose())
            printf("joints: spring %.0f Hz, damping ratio 1: lowest angle %.3g rad (>= %.3g), after 2 s %.3g\n", fs[i], lowest,
                   -8 * u * th0, (double)ga2d_revolute_joint_angle(w, j));
        ga2d_world_destroy(w);
    }
}

/* ========================================================== momentum */
/* Two boxes joined by a hinge between them, gravity off, thrown moving
   and spinning (the joint first takes out their relative motion at the
   anchor: an inner impulse).  The joint's impulses are equal and opposite,
   so the total momentum sum m v stays, to rounding: each substep applies
   the joint's impulse three times (warm start, two passes) as P / m to
   each body and adds positions' velocities, each rounded by u of the
   momentum scale p = sum m |v| plus |P| <= p: |dP| <= 12 u p per substep.
   The angular momentum about the origin, sum (c ^ m v + I w), changes
   only by the couple of those impulses acting at anchors s apart: per
   substep |s ^ P| <= s |P| = s |F| h (s and F read each step, the bound
   summed step by step at twice the step's figures, as s and F change
   within a step by less than that), plus rounding 12 u L per substep
   with the scale L = sum (|c| m |v| + I |w|). */
typedef struct momenta { double px, py, l, pscale, lscale; } momenta;
static momenta momenta_of(const ga2d_world *w, const ga2d_body_id *b, int n)
{
    momenta m;
    int i;
    memset(&m, 0, sizeof m);
    for (i = 0; i < n; ++i) {
        ga2d_mass md = ga2d_body_mass_data(w, b[i]);
        ga2d_vec v = ga2d_body_velocity(w, b[i]), c = ga2d_body_center(w, b[i]);
        double mass = (double)md.mass, in = (double)md.inertia, om = (double)ga2d_body_angular_velocity(w, b[i]);
        double vx = (double)v.x, vy = (double)v.y, cx = (double)c.x, cy = (double)c.y;
        m.px += mass * vx;
        m.py += mass * vy;
        m.l += mass * (cx * vy - cy * vx) + in * om;
        m.pscale += mass * hypot(vx, vy);
        m.lscale += hypot(cx, cy) * mass * hypot(vx, vy) + in * fabs(om);
    }
    return m;
}

static void momentum_two_bodies(void)
{
    const double u = REAL_EPS / 2;
    ga2d_world *w = make_world(0, 0, 0);
    ga2d_body_id b[2];
    ga2d_joint_id j;
    ga2d_vec la, lb, at = v2(0.05, 0.05);
    momenta m0, m;
    double pbound, lbound = 0, worst_p = 0, worst_l = 0, pscale, lscale;
    int k;
    b[0] = box_body(w, -0.5, 0, 0.2, 0.5, 0.25, 1);
    b[1] = box_body(w, 0.6, 0.1, -0.4, 0.3, 0.3, 3);
    CHECK_RESULT(ga2d_body_set_velocity(w, b[0], v2(1, 0.5)), GA2D_OK);
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, b[0], 2), GA2D_OK);
    CHECK_RESULT(ga2d_body_set_velocity(w, b[1], v2(-0.3, 1)), GA2D_OK);
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, b[1], -3), GA2D_OK);
    la = ga2d_body_local_point(w, b[0], at);
    lb = ga2d_body_local_point(w, b[1], at);
    j = hinge(w, b[0], b[1], (double)la.x, (double)la.y, (double)lb.x, (double)lb.y);
    /* the local points map back onto the world point (rounding of a turn
       and a shift of coordinates <= 1: 8 u) */
    CHECK_NEAR(dist(world_point(w, b[0], (double)la.x, (double)la.y), at), 0, 8 * u);
    CHECK_NEAR(dist(world_point(w, b[1], (double)lb.x, (double)lb.y), at), 0, 8 * u);
    m0 = momenta_of(w, b, 2);
    pscale = m0.pscale;
    lscale = m0.lscale;
    for (k = 1; k <= 180; ++k) {
        double sep, fl;
        ga2d_vec f;
        step(w);
        m = momenta_of(w, b, 2);
        if (m.pscale > pscale) pscale = m.pscale;
        if (m.lscale > lscale) lscale = m.lscale;
        f = ga2d_joint_reaction_force(w, j);
        fl = hypot((double)f.x, (double)f.y);
        sep = anchor_gap(w, j, la, lb);
        lbound += 2 * SUB * sep * fl * H;
        pbound = SUB * k * 12 * u * (2 * pscale);
        CHECK_NEAR(m.px, m0.px, pbound);
        CHECK_NEAR(m.py, m0.py, pbound);
        CHECK_NEAR(m.l, m0.l, lbound + SUB * k * 12 * u * lscale);
        if (hypot(m.px - m0.px, m.py - m0.py) > worst_p) worst_p = hypot(m.px - m0.px, m.py - m0.py);
        if (fabs(m.l - m0.l) > worst_l) worst_l = fabs(m.l - m0.l);
    }
    if (verbose())
        printf("joints: momentum over 3 s: |dP| %.3g <= %.3g (of %.3g), |dL| %.3g <= %.3g (couple %.3g + rounding %.3g, of %.3g)\n",
               worst_p, SUB * 180 * 12 * u * 2 * pscale, pscale, worst_l, lbound + SUB * 180 * 12 * u * lscale, lbound,
               SUB * 180 * 12 * u * lscale, lscale);
    ga2d_world_destroy(w);
}

/* ============================================================= chain */
/* A chain of 20 links (boxes 0.1 x 0.5, density 1, m = 0.05 kg) hanging
   straight down from a static pivot, released at rest; optionally a weight
   of 100 link masses (a 0.5 x 0.5 box) under it.  At rest each joint
   carries the weight under it, F_i, over the effective mass along the
   chain (its anchors on the chain's line, so no lever arm): 1/m_eff =
   1/m_above + 1/m_below (0 for the pivot), and rests at sep_i = F_i /
   (m_eff omega_s^2) (see the top; a chain of 10 sits on these figures).
   Released at sep 0, the load comes on at once: a linear spring system
   suddenly loaded from rest goes at most to twice its static deflection
   (the load's work F x equals the spring's k x^2 / 2 at the turn, x = 2 F /
   k; damping only lowers it), so every joint's separation stays below
   twice the largest rest value over 3 s.  The same with the accurate
   setting (8 substeps: joints at 60 Hz still, h = 1/480).  This test
   found the joints' first feedback, 2 x contact_hertz (90 Hz, omega_s h =
   2.36), unstable for straight hanging chains of more than about 11
   links (20 links: separations of 2 to 3 cm, the bottom link bouncing 28
   cm after 3 s; accurate, 180 Hz at h = 1/480, 1e27 m); the limit lay
   between 80 and 85 Hz at 4 substeps, so the feedback is now 60 Hz
   (Box2D v3's), at most a quarter of the substep rate. */
#define CHAIN 20
static void hanging_chain(int weighted, int accurate)
{
    ga2d_world_def wd = accurate ? ga2d_accurate_world_def() : ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id p, link[CHAIN + 1];
    ga2d_joint_id jt[CHAIN + 1];
    double rest[CHAIN + 1], link_mass, max_rest = 0, max_sep = 0, off = 0, h, hz, om;
    int i, k, n = CHAIN + (weighted ? 1 : 0);
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    h = DT / wd.substeps;
    hz = JOINT_HERTZ < 0.25 / h ? JOINT_HERTZ : 0.25 / h;
    om = 2 * PI * hz;
    p = pivot_body(w, 0, 0);
    for (i = 0; i < CHAIN; ++i) link[i] = box_body(w, 0, -0.25 - 0.5 * i, 0, 0.05, 0.25, 1);
    if (weighted) link[CHAIN] = box_body(w, 0, -0.5 * CHAIN - 0.25, 0, 0.25, 0.25, 100 * 0.05 / 0.25);
    jt[0] = hinge(w, p, link[0], 0, 0, 0, 0.25);
    for (i = 1; i < n; ++i) jt[i] = hinge(w, link[i - 1], link[i], 0, -0.25, 0, 0.25);
    link_mass = (double)ga2d_body_mass_data(w, link[0]).mass;
    for (i = 0; i < n; ++i) {
        double below = 0, inv;
        int k2;
        for (k2 = i; k2 < n; ++k2) below += (double)ga2d_body_mass_data(w, link[k2]).mass; /* the weight is link[CHAIN] */
        inv = (i > 0 ? 1 / link_mass : 0) + 1 / (double)ga2d_body_mass_data(w, link[i]).mass;
        rest[i] = below * G * inv / (om * om);
        if (rest[i] > max_rest) max_rest = rest[i];
    }
    for (k = 0; k < 180; ++k) {
        step(w);
        for (i = 0; i < n; ++i) {
            double sj = anchor_gap(w, jt[i], i > 0 ? v2(0, -0.25) : v2(0, 0), v2(0, 0.25));
            if (sj > max_sep) max_sep = sj;
        }
    }
    CHECK(max_sep <= 2 * max_rest);
    for (i = 0; i < n; ++i) {
        double sj = anchor_gap(w, jt[i], i > 0 ? v2(0, -0.25) : v2(0, 0), v2(0, 0.25));
        if (fabs(sj / rest[i] - 1) > off) off = fabs(sj / rest[i] - 1);
    }
    if (verbose())
        printf("joints: chain of %d%s%s: worst separation %.3g m <= %.3g (twice the largest rest value); after 3 s the "
               "joints within %.3g of their rest values\n",
               CHAIN, weighted ? " with a weight of 100 links" : "", accurate ? ", accurate setting" : "", max_sep,
               2 * max_rest, off);
    ga2d_world_destroy(w);
}

static void chain_of_twenty(void) { hanging_chain(0, 0); }
static void chain_with_weight(void) { hanging_chain(1, 0); }
static void chain_of_twenty_accurate(void) { hanging_chain(0, 1); }
static void chain_with_weight_accurate(void) { hanging_chain(1, 1); }

/* ============================================================ errors */
/* Each refused create returns its named result, the null id, and leaves
   the world as it was (its snapshot bytes). */
typedef struct locked_probe { ga2d_revolute_joint_def def; ga2d_joint_id j; int wrong, calls; } locked_probe;
static void locked_force(ga2d_world *w, void *ctx)
{
    locked_probe *pr = (locked_probe *)ctx;
    ga2d_joint_id out;
    ++pr->calls;
    pr->wrong += ga2d_revolute_joint_create_checked(w, &pr->def, &out) != GA2D_ERR_LOCKED;
    pr->wrong += !ga2d_joint_id_is_null(out);
    pr->wrong += !ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &pr->def));
    pr->wrong += ga2d_joint_destroy(w, pr->j) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_revolute_joint_enable_motor(w, pr->j, 1) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_revolute_joint_set_motor_speed(w, pr->j, 1) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_revolute_joint_set_max_motor_torque(w, pr->j, 1) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_revolute_joint_enable_limit(w, pr->j, 1) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_revolute_joint_set_limits(w, pr->j, 0, 1) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_revolute_joint_enable_spring(w, pr->j, 1) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_revolute_joint_set_spring(w, pr->j, 1, 1) != GA2D_ERR_LOCKED;
    pr->wrong += ga2d_world_get_counters(w).joint_count != 1;
    pr->wrong += !ga2d_joint_is_valid(w, pr->j); /* getters work inside */
}

static void create_errors(void)
{
    ga2d_world *w = make_world(0, -G, 1);
    ga2d_body_id s1 = pivot_body(w, 0, 0), s2 = pivot_body(w, 3, 0), dyn = box_body(w, 1, 0, 0, 0.5, 0.1, 1);
    ga2d_body_id gone = box_body(w, 5, 0, 0, 0.5, 0.1, 1), kin;
    ga2d_body_def kd = ga2d_default_body_def();
    ga2d_revolute_joint_def ok = hinge_def(s1, dyn, 0, 0, -0.5, 0), d;
    ga2d_joint_id out;
    unsigned char *ref;
    size_t n;
    const ga2d_real bad[2] = {(ga2d_real)NAN, (ga2d_real)INFINITY};
    int i;
    kd.type = GA2D_BODY_KINEMATIC;
    kin = ga2d_body_create(w, &kd);
    CHECK_RESULT(ga2d_body_destroy(w, gone), GA2D_OK);
    steps(w, 2);
    ref = snapshot(w, &n);
#define REFUSED(def_expr, expected)                                                  \
    do {                                                                             \
        d = ok;                                                                      \
        def_expr;                                                                    \
        out.index1 = 77;                                                             \
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &out), expected);     \
        CHECK(ga2d_joint_id_is_null(out));                                           \
        CHECK(ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &d)));             \
        CHECK(same_snapshot(w, ref, n));                                             \
    } while (0)
    REFUSED(d.body_b = s1, GA2D_ERR_INVALID_ARGUMENT);  /* static with itself */
    REFUSED(d.body_a = dyn, GA2D_ERR_INVALID_ARGUMENT); /* dynamic with itself */
    REFUSED(d.body_b = s2, GA2D_ERR_INVALID_ARGUMENT);  /* both static */
    REFUSED(d.body_b = kin, GA2D_ERR_INVALID_ARGUMENT); /* static and kinematic: neither dynamic */
    REFUSED(d.body_b = gone, GA2D_ERR_STALE_ID);
    REFUSED(d.body_a = gone, GA2D_ERR_STALE_ID);
    REFUSED(d.body_a = ga2d_body_id_null(), GA2D_ERR_STALE_ID);
    for (i = 0; i < 2; ++i) {
        REFUSED(d.local_anchor_a.x = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.local_anchor_b.y = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.reference_angle = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.lower_angle = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.upper_angle = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.motor_speed = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.max_motor_torque = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.hertz = bad[i], GA2D_ERR_NOT_FINITE);
        REFUSED(d.damping_ratio = bad[i], GA2D_ERR_NOT_FINITE);
    }
    REFUSED(d.local_anchor_a.x = (ga2d_real)(2 * (double)GA2D_MAX_COORDINATE), GA2D_ERR_TOO_LARGE);
    REFUSED(d.max_motor_torque = -1, GA2D_ERR_INVALID_ARGUMENT);
    REFUSED(d.hertz = -1, GA2D_ERR_INVALID_ARGUMENT);
    REFUSED(d.damping_ratio = (ga2d_real)-0.5, GA2D_ERR_INVALID_ARGUMENT);
    REFUSED((d.enable_limit = 1, d.lower_angle = 1, d.upper_angle = (ga2d_real)0.5), GA2D_ERR_INVALID_ARGUMENT);
#undef REFUSED
    CHECK_RESULT(ga2d_revolute_joint_create_checked(w, NULL, &out), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, NULL)));
    CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &ok, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_revolute_joint_create_checked(NULL, &ok, &out), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(same_snapshot(w, ref, n));
    CHECK(ga2d_world_get_counters(w).joint_count == 0);
    free(ref);
    ga2d_world_destroy(w);
}

/* From inside the force callback (the world locked) every create, destroy
   and setter is LOCKED and the step goes on as if they were not made: the
   bodies after 30 steps are, bit for bit, those of a world whose callback
   does nothing (snapshots cannot be taken inside, and two worlds' bytes
   differ by their id tags). */
static void noop_force(ga2d_world *w, void *ctx)
{
    (void)w;
    (void)ctx;
}

static void locked_calls(void)
{
    ga2d_world *w[2];
    ga2d_body_id body[2][3];
    ga2d_joint_id joint[2];
    locked_probe pr;
    int i, k, same = 1;
    memset(&pr, 0, sizeof pr);
    for (i = 0; i < 2; ++i) {
        w[i] = make_world(0, -G, 1);
        body[i][0] = pivot_body(w[i], 0, 0);
        body[i][1] = box_body(w[i], 0.5, 0, 0, 0.5, 0.1, 1);
        body[i][2] = box_body(w[i], 2, 0, 0, 0.5, 0.1, 1);
        joint[i] = pr.j = hinge(w[i], body[i][0], body[i][1], 0, 0, -0.5, 0);
        pr.def = hinge_def(body[i][1], body[i][2], 0.5, 0, -0.5, 0);
        CHECK_RESULT(ga2d_world_set_force_callback(w[i], i == 0 ? locked_force : noop_force, &pr), GA2D_OK);
    }
    for (k = 0; k < 30; ++k)
        for (i = 0; i < 2; ++i) {
            pr.j = joint[i];
            pr.def = hinge_def(body[i][1], body[i][2], 0.5, 0, -0.5, 0);
            step(w[i]);
        }
    for (k = 0; k < 3; ++k) {
        body_bits a = bits_of(w[0], body[0][k]), b = bits_of(w[1], body[1][k]);
        if (memcmp(&a, &b, sizeof a) != 0) same = 0;
    }
    CHECK(pr.calls > 0 && pr.wrong == 0);
    CHECK(same);
    CHECK(ga2d_world_get_counters(w[0]).joint_count == 1 && ga2d_joint_is_valid(w[0], joint[0]));
    for (i = 0; i < 2; ++i) ga2d_world_destroy(w[i]);
}

/* Setters: stale ids, non-finite and negative values refused, the world
   untouched; a stale id's getters read zero and null. */
static void setter_errors(void)
{
    ga2d_world *w = make_world(0, -G, 1);
    ga2d_body_id p = pivot_body(w, 0, 0), a = box_body(w, 0.5, 0, 0, 0.5, 0.1, 1);
    ga2d_joint_id j = hinge(w, p, a, 0, 0, -0.5, 0), stale = hinge(w, p, a, 0, 0, -0.5, 0);
    unsigned char *ref;
    size_t n;
    int x = 5;
    CHECK_RESULT(ga2d_joint_destroy(w, stale), GA2D_OK);
    CHECK_RESULT(ga2d_joint_destroy(w, stale), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_joint_destroy(w, ga2d_joint_id_null()), GA2D_ERR_STALE_ID);
    steps(w, 2);
    ref = snapshot(w, &n);
    CHECK_RESULT(ga2d_revolute_joint_enable_motor(w, stale, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_revolute_joint_set_motor_speed(w, stale, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_revolute_joint_set_max_motor_torque(w, stale, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_revolute_joint_enable_limit(w, stale, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_revolute_joint_set_limits(w, stale, 0, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_revolute_joint_enable_spring(w, stale, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_revolute_joint_set_spring(w, stale, 1, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_revolute_joint_set_motor_speed(w, j, (ga2d_real)NAN), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_revolute_joint_set_max_motor_torque(w, j, (ga2d_real)INFINITY), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_revolute_joint_set_max_motor_torque(w, j, -1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_revolute_joint_set_spring(w, j, (ga2d_real)NAN, 1), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_revolute_joint_set_spring(w, j, 1, (ga2d_real)-INFINITY), GA2D_ERR_NOT_FINITE);
    CHECK_RESULT(ga2d_revolute_joint_set_spring(w, j, -1, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_revolute_joint_set_spring(w, j, 1, -1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_revolute_joint_set_motor_speed(NULL, j, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(same_snapshot(w, ref, n));
    /* a stale id's getters */
    CHECK(!ga2d_joint_is_valid(w, stale) && ga2d_joint_is_valid(w, j));
    CHECK(ga2d_joint_get_type(w, stale) == GA2D_JOINT_TYPE_COUNT && ga2d_joint_get_type(w, j) == GA2D_JOINT_REVOLUTE);
    CHECK(ga2d_body_id_is_null(ga2d_joint_body_a(w, stale)) && ga2d_body_id_is_null(ga2d_joint_body_b(w, stale)));
    CHECK(ga2d_body_id_equal(ga2d_joint_body_a(w, j), p) && ga2d_body_id_equal(ga2d_joint_body_b(w, j), a));
    CHECK(ga2d_joint_user_data(w, stale) == NULL);
    CHECK(ga2d_joint_reaction_force(w, stale).x == 0 && ga2d_joint_reaction_force(w, stale).y == 0);
    CHECK(ga2d_joint_reaction_torque(w, stale) == 0 && ga2d_revolute_joint_angle(w, stale) == 0);
    CHECK(ga2d_revolute_joint_speed(w, stale) == 0 && ga2d_revolute_joint_motor_torque(w, stale) == 0);
    /* a slot reused by a new joint does not revive the stale id */
    {
        ga2d_revolute_joint_def d = hinge_def(p, a, 0, 0, -0.5, 0);
        ga2d_joint_id again;
        d.user_data = &x;
        d.collide_connected = 1;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &again), GA2D_OK);
        CHECK(again.index1 == stale.index1 && !ga2d_joint_id_equal(again, stale));
        CHECK(!ga2d_joint_is_valid(w, stale));
        CHECK(ga2d_joint_user_data(w, again) == &x && ga2d_joint_collide_connected(w, again) == 1);
        CHECK(ga2d_joint_collide_connected(w, j) == 0);
    }
    free(ref);
    ga2d_world_destroy(w);
}

/* ========================================================= lifetime */
/* Runs until body b sleeps (at most 5 s), returns the steps taken. */
static int sleep_steps(ga2d_world *w, ga2d_body_id b)
{
    int k;
    for (k = 1; k <= 300; ++k) {
        step(w);
        if (!ga2d_body_is_awake(w, b)) return k;
    }
    return -1;
}

/* Destroying a body destroys its joints (ids stale, joint_count down) and
   wakes the body on the other side; ga2d_joint_destroy wakes both. */
static void destroy_body_destroys_joints(void)
{
    ga2d_world *w = make_world(0, -G, 1);
    ga2d_body_id p = pivot_body(w, 0, 0), a = box_body(w, 0, -0.25, 0, 0.05, 0.25, 1), b = box_body(w, 0, -0.75, 0, 0.05, 0.25, 1);
    ga2d_body_id c = box_body(w, 0, -1.25, 0, 0.05, 0.25, 1);
    ga2d_joint_id j0 = hinge(w, p, a, 0, 0, 0, 0.25), j1 = hinge(w, a, b, 0, -0.25, 0, 0.25), j2 = hinge(w, b, c, 0, -0.25, 0, 0.25);
    CHECK(ga2d_world_get_counters(w).joint_count == 3);
    CHECK(sleep_steps(w, c) > 0);
    CHECK(!ga2d_body_is_awake(w, a) && !ga2d_body_is_awake(w, b));
    CHECK_RESULT(ga2d_body_destroy(w, a), GA2D_OK);
    CHECK(!ga2d_joint_is_valid(w, j0) && !ga2d_joint_is_valid(w, j1) && ga2d_joint_is_valid(w, j2));
    CHECK(ga2d_world_get_counters(w).joint_count == 1);
    CHECK(ga2d_body_is_awake(w, b) && ga2d_body_is_awake(w, c));
    CHECK_RESULT(ga2d_revolute_joint_set_motor_speed(w, j1, 1), GA2D_ERR_STALE_ID);
    step(w); /* b and c fall, joined */
    CHECK(ga2d_body_velocity(w, b).y < 0);
    /* a joint destroyed between two sleeping bodies wakes both */
    {
        ga2d_body_id q = pivot_body(w, 5, 0), d = box_body(w, 5, -0.25, 0, 0.05, 0.25, 1);
        ga2d_body_id e = box_body(w, 5, -0.75, 0, 0.05, 0.25, 1);
        ga2d_joint_id k1, k2;
        CHECK_RESULT(ga2d_body_destroy(w, b), GA2D_OK);
        CHECK_RESULT(ga2d_body_destroy(w, c), GA2D_OK);
        CHECK(!ga2d_joint_is_valid(w, j2) && ga2d_world_get_counters(w).joint_count == 0);
        k1 = hinge(w, q, d, 0, 0, 0, 0.25);
        k2 = hinge(w, d, e, 0, -0.25, 0, 0.25);
        CHECK(sleep_steps(w, e) > 0 && !ga2d_body_is_awake(w, d));
        CHECK_RESULT(ga2d_joint_destroy(w, k2), GA2D_OK);
        CHECK(ga2d_body_is_awake(w, d) && ga2d_body_is_awake(w, e));
        CHECK(ga2d_joint_is_valid(w, k1) && ga2d_world_get_counters(w).joint_count == 1);
    }
    ga2d_world_destroy(w);
}

/* A box asleep on a hinge to a kinematic body is woken when that body
   starts to move (its joint is not solved while the box sleeps, so
   nothing else would move it), and is carried from then on.  The carrier
   sets off at 2 m/s: a second later it has gone 2 m, and the box,
   hanging 0.5 m below on its hinge, follows it within its swing (the
   hinge holds the anchors together; the box's centre lies within 0.5 m
   of the carrier's, so at least 1.5 m along). */
static void sleeper_woken_by_moving_carrier(void)
{
    ga2d_world *w = make_world(0, -G, 1);
    ga2d_body_def kd = ga2d_default_body_def();
    ga2d_body_id k, b;
    int i, woke = -1;
    kd.type = GA2D_BODY_KINEMATIC;
    k = ga2d_body_create(w, &kd);
    b = box_body(w, 0, -0.5, 0, 0.1, 0.25, 1);
    hinge(w, k, b, 0, 0, 0, 0.5);
    CHECK(sleep_steps(w, b) > 0);
    CHECK_RESULT(ga2d_body_set_velocity(w, k, v2(2, 0)), GA2D_OK);
    for (i = 1; i <= 60; ++i) {
        step(w);
        if (woke < 0 && ga2d_body_is_awake(w, b)) woke = i;
    }
    /* woken at the end of the first step the carrier moves in */
    CHECK(woke == 1);
    CHECK((double)ga2d_body_position(w, b).x > 1.5);
    ga2d_world_destroy(w);
}

/* A chain of 6 hanging from a static body is one island: all its links
   fall asleep in the same step; an impulse on the bottom link wakes the
   top one; a box dropped on the bottom link wakes them all. */
static void chain_sleeps_as_one_island(void)
{
    ga2d_world *w = make_world(0, -G, 1);
    ga2d_body_id p = pivot_body(w, 0, 0), link[6];
    int i, k, asleep_at = -1;
    for (i = 0; i < 6; ++i) link[i] = box_body(w, 0, -0.25 - 0.5 * i, 0, 0.05, 0.25, 1);
    (void)hinge(w, p, link[0], 0, 0, 0, 0.25);
    for (i = 1; i < 6; ++i) (void)hinge(w, link[i - 1], link[i], 0, -0.25, 0, 0.25);
    for (k = 1; k <= 1200 && asleep_at < 0; ++k) {
        int n = 0;
        step(w);
        for (i = 0; i < 6; ++i) n += !ga2d_body_is_awake(w, link[i]);
        CHECK(n == 0 || n == 6); /* never some of them */
        if (n == 6) asleep_at = k;
    }
    CHECK(asleep_at > 0);
    step(w); /* asleep for a whole step: no joint solved */
    CHECK(ga2d_world_get_counters(w).joints_solved == 0);
    CHECK_RESULT(ga2d_body_apply_impulse(w, link[5], v2(0.001, 0), ga2d_body_center(w, link[5])), GA2D_OK);
    for (i = 0; i < 6; ++i) CHECK(ga2d_body_is_awake(w, link[i]));
    step(w);
    CHECK(ga2d_world_get_counters(w).joints_solved == 6);
    if (verbose()) printf("joints: a chain of 6 fell asleep as one island after %.2f s\n", asleep_at * DT);
    ga2d_world_destroy(w);
}

/* ============================================== collide_connected */
/* Two overlapping boxes joined at a common point, gravity off: with
   collide_connected 0 they get no contact (and one they had ends when the
   joint is made); with 1 they touch. */
static int touching_pairs(const ga2d_world *w, ga2d_body_id b)
{
    ga2d_contact_data cd[4];
    return ga2d_body_get_contacts(w, b, cd, 4);
}

static void collide_connected(void)
{
    int cc;
    for (cc = 0; cc < 2; ++cc) {
        ga2d_world *w = make_world(0, 0, 0);
        ga2d_body_id a = box_body(w, 0, 0, 0, 0.5, 0.5, 1), b = box_body(w, 0.6, 0, 0, 0.5, 0.5, 1);
        ga2d_revolute_joint_def d = hinge_def(a, b, 0.3, 0, -0.3, 0);
        ga2d_joint_id j;
        step(w);
        CHECK(touching_pairs(w, a) == 1); /* they overlap: a contact */
        d.collide_connected = cc;
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &j), GA2D_OK);
        CHECK(ga2d_joint_collide_connected(w, j) == cc);
        if (!cc) CHECK(touching_pairs(w, a) == 0); /* ended at once */
        steps(w, 10);
        CHECK(touching_pairs(w, a) == cc);
        CHECK(ga2d_world_get_counters(w).touching_count == cc);
        CHECK_RESULT(ga2d_joint_destroy(w, j), GA2D_OK);
        step(w);
        CHECK(touching_pairs(w, a) + touching_pairs(w, b) >= 1); /* apart from the joint they touch again (or pushed out) */
        ga2d_world_destroy(w);
    }
}

/* ====================================================== snapshots */
/* A chain of 8 links laid out level from a pivot (with a motor, a limit
   and a spring on three of its joints), so it swings. */
#define SWING 8
static void swinging_chain(ga2d_world *w, double x0, ga2d_body_id *link, ga2d_joint_id *jt)
{
    ga2d_body_id p = pivot_body(w, x0, 0);
    int i;
    for (i = 0; i < SWING; ++i) {
        ga2d_revolute_joint_def d;
        link[i] = box_body(w, x0 + 0.25 + 0.5 * i, 0, 0, 0.25, 0.05, 1);
        d = hinge_def(i ? link[i - 1] : p, link[i], i ? 0.25 : 0, 0, -0.25, 0);
        if (i == 2) {
            d.enable_motor = 1;
            d.motor_speed = 1;
            d.max_motor_torque = (ga2d_real)0.2;
        }
        if (i == 4) {
            d.enable_limit = 1;
            d.lower_angle = (ga2d_real)-0.3;
            d.upper_angle = (ga2d_real)0.3;
        }
        if (i == 6) {
            d.enable_spring = 1;
            d.hertz = 2;
            d.damping_ratio = (ga2d_real)0.3;
        }
        CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &jt[i]), GA2D_OK);
    }
}

static void snapshot_round_trip(void)
{
    int churn;
    for (churn = 0; churn < 2; ++churn) {
        ga2d_world *w = make_world(0, -G, 1), *w2 = make_world(0, -G, 1);
        ga2d_body_id link[SWING];
        ga2d_joint_id jt[SWING];
        unsigned char *buf;
        size_t n;
        int i, k, same = 1;
        swinging_chain(w, 0, link, jt);
        if (churn) { /* joints destroyed and made again: slots reused, serials new */
            ga2d_revolute_joint_def d = hinge_def(link[2], link[3], 0.25, 0, -0.25, 0);
            CHECK_RESULT(ga2d_joint_destroy(w, jt[3]), GA2D_OK);
            CHECK_RESULT(ga2d_joint_destroy(w, jt[1]), GA2D_OK);
            steps(w, 5);
            CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &jt[3]), GA2D_OK);
            d = hinge_def(link[0], link[1], 0.25, 0, -0.25, 0);
            d.enable_spring = 1;
            d.hertz = 5;
            CHECK_RESULT(ga2d_revolute_joint_create_checked(w, &d, &jt[1]), GA2D_OK);
        }
        steps(w, 30); /* mid-swing */
        buf = snapshot(w, &n);
        CHECK(buf != NULL);
        if (!buf) return;
        CHECK_RESULT(ga2d_world_snapshot_load(w2, buf, n), GA2D_OK);
        CHECK(ga2d_world_get_counters(w2).joint_count == SWING);
        for (k = 0; k < 120; ++k) {
            step(w);
            step(w2);
            for (i = 0; i < SWING; ++i) {
                body_bits a = bits_of(w, link[i]), b = bits_of(w2, link[i]);
                if (memcmp(&a, &b, sizeof a) != 0) same = 0;
            }
        }
        CHECK(same);
        {
            unsigned char *s1 = snapshot(w, &n);
            CHECK(same_snapshot(w2, s1, n));
            free(s1);
        }
        for (i = 0; i < SWING; ++i) CHECK(ga2d_joint_is_valid(w2, jt[i]));
        free(buf);
        ga2d_world_destroy(w);
        ga2d_world_destroy(w2);
    }
}

/* ===================================================== determinism */
/* The same jointed scene, alone or after unrelated bodies and joints were
   made and destroyed (other slots, other creation serials), gives the
   same bits over 120 steps. */
static void determinism_after_churn(void)
{
    ga2d_world *w[2];
    ga2d_body_id link[2][SWING];
    ga2d_joint_id jt[2][SWING];
    int i, k, same = 1;
    for (i = 0; i < 2; ++i) {
        w[i] = make_world(0, -G, 1);
        if (i == 1) {
            ga2d_body_id junk[6], q = pivot_body(w[i], 50, 50);
            ga2d_joint_id jj[5];
            int m;
            for (m = 0; m < 6; ++m) junk[m] = box_body(w[i], 50 + m, 49, 0, 0.2, 0.2, 1);
            for (m = 0; m < 5; ++m) jj[m] = hinge(w[i], m ? junk[m - 1] : q, junk[m], 0, 0, 0, 0);
            steps(w[i], 3);
            CHECK_RESULT(ga2d_joint_destroy(w[i], jj[2]), GA2D_OK);
            for (m = 0; m < 6; m += 2) CHECK_RESULT(ga2d_body_destroy(w[i], junk[m]), GA2D_OK);
            CHECK_RESULT(ga2d_body_destroy(w[i], q), GA2D_OK);
            for (m = 1; m < 6; m += 2) CHECK_RESULT(ga2d_body_destroy(w[i], junk[m]), GA2D_OK);
            CHECK(ga2d_world_get_counters(w[i]).joint_count == 0);
        }
        swinging_chain(w[i], 0, link[i], jt[i]);
    }
    for (k = 0; k < 120; ++k) {
        step(w[0]);
        step(w[1]);
        for (i = 0; i < SWING; ++i) {
            body_bits a = bits_of(w[0], link[0][i]), b = bits_of(w[1], link[1][i]);
            if (memcmp(&a, &b, sizeof a) != 0) same = 0;
        }
    }
    CHECK(same);
    for (i = 0; i < 2; ++i) ga2d_world_destroy(w[i]);
}

void suite_joints(void)
{
    test_run("joints: compound pendulum, 5 degrees, 1000 periods", pendulum_small_amplitude);
    test_run("joints: compound pendulum, 90 degrees", pendulum_large_amplitude);
    test_run("joints: reaction of a hanging mass", reaction_hanging_mass);
    test_run("joints: reaction of a hub with more joints than colours", reaction_hub_past_the_colours);
    test_run("joints: reaction of a spinning bar", reaction_spinning_bar);
    test_run("joints: motor of max torque on a disc", motor_max_torque);
    test_run("joints: limit on a disc", limit_disc);
    test_run("joints: limit on a pendulum", limit_pendulum);
    test_run("joints: limit setters", limit_setters);
    test_run("joints: spring period", spring_period);
    test_run("joints: spring, damping ratio 1", spring_critical);
    test_run("joints: momentum of two joined bodies", momentum_two_bodies);
    test_run("joints: hanging chain of 20", chain_of_twenty);
    test_run("joints: hanging chain of 20 with a weight of 100 links", chain_with_weight);
    test_run("joints: hanging chain of 20, accurate setting", chain_of_twenty_accurate);
    test_run("joints: hanging chain of 20 with a weight, accurate setting", chain_with_weight_accurate);
    test_run("joints: create errors", create_errors);
    test_run("joints: calls from a locked world", locked_calls);
    test_run("joints: setter errors and stale ids", setter_errors);
    test_run("joints: destroying a body destroys its joints", destroy_body_destroys_joints);
    test_run("joints: a chain sleeps and wakes as one island", chain_sleeps_as_one_island);
    test_run("joints: a box asleep on a hinge to a kinematic body wakes when that moves", sleeper_woken_by_moving_carrier);
    test_run("joints: collide_connected", collide_connected);
    test_run("joints: snapshot round trip mid-swing", snapshot_round_trip);
    test_run("joints: determinism after unrelated churn", determinism_after_churn);
}
