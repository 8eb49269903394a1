/* Chains and conveyor belts in a world, against exact answers. */
#include "test.h"

#define DT (1.0 / 60)
#define G 10.0

static ga2d_world *flat_world(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.enable_sleep = 0;
    return ga2d_world_create(&wd);
}

/* A frictionless box and a frictionless ball slide 40 one-metre segments
   of a straight chain at 5 m/s for 6 s, crossing about 30 joins.  Every
   normal a straight chain keeps is a face normal, (-0, 1) or (0, 1)
   exactly (ga2d__chain_keeps: a straight join has no vertex normals), and
   friction is off, so every impulse has an x component of +-0 and the
   horizontal speed is never changed: it stays 5 bit for bit.  A join that
   caught (an edge normal, the ghost problem) would push back along x. */
static void chain_slide(void)
{
    int shape;
    for (shape = 0; shape < 2; ++shape) {
        ga2d_world *w = flat_world();
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_shape_def sd = ga2d_default_shape_def();
        ga2d_chain_def cd = ga2d_default_chain_def();
        ga2d_vec pts[41];
        ga2d_body_id ground, b;
        int i, exact = 1, segs;
        double vy_max = 0;
        CHECK(w != NULL);
        if (!w) return;
        for (i = 0; i < 41; ++i) pts[i] = ga2d_vec_make((ga2d_real)(-20 + i), 0);
        ground = ga2d_body_create(w, &d);
        cd.points = pts;
        cd.count = 41;
        cd.friction = 0;
        segs = ga2d_chain_get_segments(w, ga2d_chain_create(w, ground, &cd), NULL, 0);
        CHECK(segs == 40);
        d.type = GA2D_BODY_DYNAMIC;
        d.position = ga2d_vec_make(-18, (ga2d_real)(shape ? 0.25 : 0.5));
        d.velocity = ga2d_vec_make(5, 0);
        b = ga2d_body_create(w, &d);
        sd.friction = 0;
        if (shape) {
            ga2d_circle c;
            c.center = ga2d_vec_make(0, 0);
            c.radius = (ga2d_real)0.25;
            CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
        } else {
            ga2d_polygon p = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
            CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, b, &sd, &p)));
        }
        for (i = 0; i < 360; ++i) {
            ga2d_vec v;
            CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
            v = ga2d_body_velocity(w, b);
            exact &= v.x == 5;
            vy_max = fmax(vy_max, fabs((double)v.y));
        }
        CHECK(exact);
        CHECK((double)ga2d_body_position(w, b).x > 11); /* it crossed the joins: -18 + 5 * 6 = 12 */
        if (getenv("GA2D_TEST_VERBOSE"))
            printf("  shape_terrain: %s over 40 segments: vx 5 exactly every step: %d; max |vy| %.3g m/s\n", shape ? "ball" : "box",
                   exact, vy_max);
        ga2d_world_destroy(w);
    }
}

/* A box resting on a belt of tangent speed 2 m/s (mu 0.6 both, so 0.6
   mixed): while it slips, friction is mu times the normal impulse every
   substep, and the normal impulses add up to m (dv_y + g T) over a window
   (vertical momentum), so dv_x = mu (dv_y + g T) exactly up to rounding.
   Rounding (u = eps/2): a substep adds to each velocity component about 8
   times (kick, warm start, soft and relax passes at two points), each off
   by <= u (|v| + g h); over n substeps <= 8 n u (|v| + g T) for each of
   dv_x and dv_y, and mu's own <= 4 u: R = 16 n u (2 + g T) + 4 u. */
static void conveyor(void)
{
    ga2d_world *w = flat_world();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_polygon belt = ga2d_polygon_box(20, (ga2d_real)0.5);
    ga2d_body_id g, b;
    ga2d_vec v0, v1;
    const double T = 6 * DT, n = 6 * 4, u = REAL_EPS / 2, R = 16 * n * u * (2 + G * T) + 4 * u;
    int i;
    CHECK(w != NULL);
    if (!w) return;
    g = ga2d_body_create(w, &d);
    sd.tangent_speed = 2;
    CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, g, &sd, &belt)));
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(0, 1);
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    b = ga2d_body_create(w, &d);
    for (i = 0; i < 4; ++i) ga2d_world_step(w, (ga2d_real)DT);
    v0 = ga2d_body_velocity(w, b);
    for (i = 0; i < 6; ++i) ga2d_world_step(w, (ga2d_real)DT);
    v1 = ga2d_body_velocity(w, b);
    CHECK((double)v1.x < 2); /* still slipping: the premise */
    CHECK_NEAR((double)v1.x - (double)v0.x, 0.6 * ((double)v1.y - (double)v0.y + G * T), R);
    if (getenv("GA2D_TEST_VERBOSE"))
        printf("  shape_terrain: belt: dv_x %.9f vs mu (dv_y + g T) %.9f (bound %.2g)\n", (double)v1.x - (double)v0.x,
               0.6 * ((double)v1.y - (double)v0.y + G * T), R);
    ga2d_world_destroy(w);
}

/* ---- joins at every angle ---------------------------------------------
   A chain of two arms of ARM metres meeting at the origin, the chain
   turning by `turn` there: left (a valley, V) for turn > 0, right (a
   hilltop, an inverted V) for turn < 0.  Its points run left to right, so
   its front is up.  A body either slides down (valley) or along (hilltop)
   the right arm toward the join from JOIN_START metres away, or is dropped
   onto the right arm just beside the join. */
#define ARM 10.0
#define JOIN_START 1.0
#define PI_D 3.14159265358979323846

typedef struct join_case {
    double turn;  /* radians, > 0 a valley */
    int box;      /* a box of half-size `size`, else a ball of radius `size` */
    double size, speed, friction;
    int drop;
} join_case;

/* The arms' unit directions walking away from the join (right arm, then
   left) and their front normals, for a chain turning by `turn`. */
static void join_arms(double turn, double e[2][2], double n[2][2])
{
    double a = turn / 2; /* each arm's slope: up for a valley, down for a hill */
    e[0][0] = cos(a), e[0][1] = sin(a);   /* right arm, from the join out */
    e[1][0] = -cos(a), e[1][1] = sin(a);  /* left arm, from the join out */
    n[0][0] = -sin(a), n[0][1] = cos(a);  /* the right arm's front (up) */
    n[1][0] = sin(a), n[1][1] = cos(a);
}

/* The two-arm chain turning by `turn`, on a new static body, with its
   arms' directions and normals (join_arms). */
static void join_chain(ga2d_world *w, double turn, double friction, double e[2][2], double n[2][2])
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_vec pts[3];
    join_arms(turn, e, n);
    pts[0] = ga2d_vec_make((ga2d_real)(ARM * e[1][0]), (ga2d_real)(ARM * e[1][1]));
    pts[1] = ga2d_vec_make(0, 0);
    pts[2] = ga2d_vec_make((ga2d_real)(ARM * e[0][0]), (ga2d_real)(ARM * e[0][1]));
    cd.points = pts;
    cd.count = 3;
    cd.friction = (ga2d_real)friction;
    CHECK(ga2d_chain_get_segments(w, ga2d_chain_create(w, ga2d_body_create(w, &d), &cd), NULL, 0) == 2);
}

/* Runs one case for 1.5 s (sleep off) and returns how far the body's
   centre came into the ground: the least signed distance above an arm's
   line, taken while its foot lies on that arm (within 0.95 ARM of the
   join: past an arm's far end the line bounds nothing, and a body that
   has left both arms is done).  Below a valley's
   ground lies what is behind either arm; below a hilltop's, what is behind
   both (in front of one arm, the centre is still above ground there).
   Negative: the centre crossed an arm. */
static double join_run(const join_case *jc)
{
    ga2d_world *w = flat_world();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    double e[2][2], n[2][2], least = 1e30;
    ga2d_body_id b;
    int i, k, seen = 0;
    if (!w) return -1e30;
    join_chain(w, jc->turn, jc->friction, e, n);
    d.type = GA2D_BODY_DYNAMIC;
    if (jc->drop) { /* straight above the right arm 0.3 m out from the join, clear of it by 2 m */
        d.position = ga2d_vec_make((ga2d_real)(0.3 * e[0][0]), (ga2d_real)(0.3 * e[0][1] + (2 + jc->size * 1.5) / n[0][1]));
        d.velocity = ga2d_vec_make(0, (ga2d_real)-jc->speed);
    } else { /* on the right arm, touching it, heading for the join from
                JOIN_START beyond where it would touch both arms of a valley */
        double start = JOIN_START + (jc->turn > 0 ? jc->size / tan((PI_D - jc->turn) / 2) : 0);
        d.position = ga2d_vec_make((ga2d_real)(start * e[0][0] + jc->size * n[0][0]),
                                   (ga2d_real)(start * e[0][1] + jc->size * n[0][1]));
        d.velocity = ga2d_vec_make((ga2d_real)(-jc->speed * e[0][0]), (ga2d_real)(-jc->speed * e[0][1]));
        d.rotor = ga2d_rotor_from_angle((ga2d_real)(jc->turn / 2)); /* a box lies flat on the arm */
    }
    b = ga2d_body_create(w, &d);
    sd.friction = (ga2d_real)jc->friction;
    if (jc->box) {
        ga2d_polygon p = ga2d_polygon_box((ga2d_real)jc->size, (ga2d_real)jc->size);
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, b, &sd, &p)));
    } else {
        ga2d_circle c;
        c.center = ga2d_vec_make(0, 0);
        c.radius = (ga2d_real)jc->size;
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
    }
    for (i = 0; i < 90; ++i) {
        ga2d_vec c;
        double above[2];
        int over = 0;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
        c = ga2d_body_position(w, b);
        for (k = 0; k < 2; ++k) {
            double along = (double)c.x * e[k][0] + (double)c.y * e[k][1];
            above[k] = (double)c.x * n[k][0] + (double)c.y * n[k][1];
            if (along >= 0 && along <= 0.95 * ARM) over |= 1 << k;
        }
        /* once it has left the arms (off a far end), the lines bound nothing */
        if (over) seen = 1;
        else if (seen) break;
        for (k = 0; k < 2; ++k) {
            double h = jc->turn > 0 ? above[k] : fmax(above[0], above[1]);
            if ((over >> k & 1) && h < least) least = h;
        }
    }
    ga2d_world_destroy(w);
    return least;
}

/* Whether the discrete step can be asked to hold a case: the body's
   approach along the far arm's normal, v_n, must be one that the step's
   substeps take out before the centre has crossed.  The speed v grows by
   the fall from the start (v^2 + 2 g (JOIN_START + 2 + size) at most).
   Sliding in, the far arm meets it at the turn (v_n = v sin turn);
   dropped straight down, it closes on both arms at v cos(turn/2) (their
   normals lean turn/2 off the vertical).
   - The two arms' contacts take turns in the solver's passes (Gauss-
     Seidel: alternating projections onto two half-planes whose normals
     meet at the turn c = cos turn).  The first leaves (1 - c) of the
     approach along the other's normal, each later one |c| of what is
     left; two passes a substep leave (1 - c) c^2 of it, and the
     substeps that follow cut it by c^2 each, so the centre goes at most
     h v_n (1 - c) c^2 / (1 - c^2) = h v_n c^2 / (1 + c) into the far
     face (h a substep).  That must stay within the body's size.  It
     vanishes at a right angle and grows without bound as the notch
     closes (c -> -1).
   - A sharp corner that hits a face inelastically at v_n spins a box of
     half-size a at v_n x / (I/m + x^2), x = |r ^ n| the corner's lever,
     I/m = (2/3) a^2 for a square; that peaks at x = a sqrt(2/3), at
     v_n / (2 a sqrt(2/3)).  A step turns a body by at most
     GA2D_MAX_ROTATION per substep, so the hit must need no more than
     w_cap = GA2D_MAX_ROTATION / h, or the box cannot turn as it demands
     and its corners sweep through the face within the step.
   Beyond these only continuous collision holds a body (issue 25). */
static int join_in_reach(const join_case *jc)
{
    double h = DT / 4, v = sqrt(jc->speed * jc->speed + 2 * G * (JOIN_START + 2 + jc->size));
    double vn = v * (jc->drop ? cos(jc->turn / 2) : fabs(sin(jc->turn))), c = cos(jc->turn);
    if (h * vn * c * c / (1 + c) > jc->size) return 0;
    return !jc->box || vn <= GA2D_MAX_ROTATION / h * jc->size * 2 * sqrt(2.0 / 3);
}

/* Valleys of every angle, balls and boxes, sliding into the join and
   dropped beside it, at speeds up to the cap: the centre never crosses an
   arm (bound 0: that is what crossing means; a body that went through
   shows a centre metres below), for every case the discrete step can be
   asked to hold (join_in_reach: every ball but the fastest in the
   narrowest notches, boxes up to 15 m/s of approach at 0.05 m and 150 at
   0.5 m).  The V chain's face, carried over a valley's neighbour, is what
   holds them (before, the joins dropped the contact and a 0.05 m ball
   went through at 10 m/s). */
static void chain_valleys_hold(void)
{
    static const double turns_deg[] = {2, 10, 30, 53.13, 90, 120, 150};
    static const double speeds[] = {1, 10, 40, 100, 200, 399};
    static const double sizes[] = {0.05, 0.5};
    static const double frictions[] = {0, 0.6};
    int ti, si, zi, fi, box, drop, runs = 0, crossed = 0, beyond = 0, held_beyond = 0;
    double worst = 1e30;
    for (ti = 0; ti < (int)(sizeof turns_deg / sizeof *turns_deg); ++ti)
        for (box = 0; box < 2; ++box)
            for (zi = 0; zi < 2; ++zi)
                for (si = 0; si < (int)(sizeof speeds / sizeof *speeds); ++si)
                    for (drop = 0; drop < 2; ++drop)
                        for (fi = 0; fi < 2; ++fi) {
                            join_case jc;
                            double least;
                            jc.turn = turns_deg[ti] * PI_D / 180;
                            jc.box = box;
                            jc.size = sizes[zi];
                            jc.speed = speeds[si];
                            jc.friction = frictions[fi];
                            jc.drop = drop;
                            least = join_run(&jc);
                            if (!join_in_reach(&jc)) { /* beyond the discrete step: reported, not required */
                                ++beyond;
                                held_beyond += least >= 0;
                                continue;
                            }
                            ++runs;
                            if (least < 0) {
                                ++crossed;
                                if (crossed <= 5)
                                    printf("  valley %.4g deg, %s %.2g m, %g m/s, mu %.1f, %s: centre %.3g m past an arm\n", turns_deg[ti],
                                           box ? "box" : "ball", jc.size, jc.speed, jc.friction, drop ? "dropped" : "sliding", -least);
                            }
                            worst = least < worst ? least : worst;
                        }
    CHECK(crossed == 0);
    CHECK(runs >= 200); /* the sweep ran: 7 turns x 2 sizes x 6 speeds x 2 x 2 of balls less the fastest few */
    /* beyond the discrete step, continuous collision (on by default)
       sweeps the body along its path and turn, and holds every one */
    CHECK(beyond > 0 && held_beyond == beyond);
    if (getenv("GA2D_TEST_VERBOSE"))
        printf("  shape_terrain: %d valley runs, %d crossed; least centre height above an arm %.4g m; beyond the step's "
               "reach %d more, %d of them held\n", runs, crossed, worst, beyond, held_beyond);
}

/* Hilltops of every angle: a body slid over the top at speeds up to the
   cap (it flies off and lands on the far arm) or dropped beside it never
   crosses an arm (bound 0, as for valleys). */
static void chain_hilltops_hold(void)
{
    static const double turns_deg[] = {2, 10, 30, 53.13, 90};
    static const double speeds[] = {1, 10, 40, 100, 200, 399};
    static const double sizes[] = {0.05, 0.5};
    int ti, si, zi, box, drop, runs = 0, crossed = 0;
    for (ti = 0; ti < (int)(sizeof turns_deg / sizeof *turns_deg); ++ti)
        for (box = 0; box < 2; ++box)
            for (zi = 0; zi < 2; ++zi)
                for (si = 0; si < (int)(sizeof speeds / sizeof *speeds); ++si)
                    for (drop = 0; drop < 2; ++drop) {
                        join_case jc;
                        jc.turn = -turns_deg[ti] * PI_D / 180;
                        jc.box = box;
                        jc.size = sizes[zi];
                        jc.speed = speeds[si];
                        jc.friction = 0.6;
                        jc.drop = drop;
                        if (!join_in_reach(&jc)) continue;
                        ++runs;
                        if (join_run(&jc) < 0) {
                            ++crossed;
                            if (crossed <= 5)
                                printf("  hilltop %.4g deg, %s %.2g m, %g m/s, %s: crossed an arm\n", turns_deg[ti], box ? "box" : "ball",
                                       jc.size, jc.speed, drop ? "dropped" : "sliding");
                        }
                    }
    CHECK(crossed == 0);
    CHECK(runs >= 100);
    if (getenv("GA2D_TEST_VERBOSE")) printf("  shape_terrain: %d hilltop runs, %d crossed\n", runs, crossed);
}

/* The distance from c to the nearer of the two arms (segments from the
   join out ARM metres). */
static double join_distance(double e[2][2], ga2d_vec c)
{
    double best = 1e30;
    int k;
    for (k = 0; k < 2; ++k) {
        double t = (double)c.x * e[k][0] + (double)c.y * e[k][1], dx, dy;
        t = t < 0 ? 0 : (t > ARM ? ARM : t);
        dx = (double)c.x - t * e[k][0];
        dy = (double)c.y - t * e[k][1];
        best = fmin(best, sqrt(dx * dx + dy * dy));
    }
    return best;
}

/* A ball rolls over hilltops of 10 to 90 degrees from resting on the top
   (centre r from the vertex, 0.01 rad left of straight above it) with a
   0.3 m/s push, sleep off.  Over the top
   only the vertex holds it: the vertex's normals belong to the two
   segments, each keeping the half nearer its own face.  Were they dropped,
   it would sink into the corner by r (1 - cos(turn/2)), 1.9 mm at 10
   degrees; held, its centre stays r from the chain less the soft
   contact's static sag g / (2 pi f)^2, f the contact stiffness (45 Hz:
   0.13 mm; against a static body it is stiffer still).  It rolls off
   down the right arm, whose face then holds it.  At 0.3 m/s over r = 0.5
   the centripetal v^2 / r = 0.18 m/s^2 is far below g cos(turn/2), so it
   never leaves the vertex.  And one point pushes at a time: the vertex
   is one segment's, never both (two would share one load). */
static void chain_hilltop_vertex_holds(void)
{
    static const double turns_deg[] = {10, 30, 53.13, 90};
    const double r = 0.5, sag = G / ((2 * PI_D * 45) * (2 * PI_D * 45));
    double worst = 1e30;
    int ti;
    for (ti = 0; ti < 4; ++ti) {
        ga2d_world *w = flat_world();
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_shape_def sd = ga2d_default_shape_def();
        double e[2][2], n[2][2], least = 1e30;
        ga2d_body_id b;
        ga2d_circle c;
        int i, off = 0, most = 0;
        CHECK(w != NULL);
        if (!w) return;
        join_chain(w, -turns_deg[ti] * PI_D / 180, 0.6, e, n);
        d.type = GA2D_BODY_DYNAMIC;
        /* just left of the top (on the bisector both halves would tie) */
        d.position = ga2d_vec_make((ga2d_real)(-0.01 * r), (ga2d_real)(r * sqrt(1 - 1e-4)));
        d.velocity = ga2d_vec_make((ga2d_real)0.3, 0);
        b = ga2d_body_create(w, &d);
        c.center = ga2d_vec_make(0, 0);
        c.radius = (ga2d_real)r;
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
        for (i = 0; i < 120; ++i) {
            ga2d_vec p;
            CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
            p = ga2d_body_position(w, b);
            least = fmin(least, join_distance(e, p));
            { /* a ball meets a convex chain at one point: a face, or the
                 vertex as the one segment whose half of its normals it is */
                ga2d_contact_data cdata[4];
                int nc = ga2d_body_get_contacts(w, b, cdata, 4), q, k, pushing = 0;
                for (q = 0; q < nc && q < 4; ++q)
                    for (k = 0; k < cdata[q].manifold.count; ++k) pushing += cdata[q].manifold.points[k].normal_impulse > 0;
                most = pushing > most ? pushing : most;
            }
            off |= (double)p.x * e[0][0] + (double)p.y * e[0][1] > 1; /* it rolled off the top */
        }
        CHECK(least >= r - sag);
        CHECK(off);
        CHECK(most == 1);
        worst = fmin(worst, least - r);
        ga2d_world_destroy(w);
    }
    if (getenv("GA2D_TEST_VERBOSE"))
        printf("  shape_terrain: ball over hilltops: deepest %.3g m into the chain (bound %.3g)\n", -worst, sag);
}

/* A ball (r 0.5, friction 0.6 and 0) rocks for 30 s (sleep off) in a
   valley of a chain through y = -cos(2 pi x / 20), points 0.1 m apart
   (the valley's floor curves with radius 10 m), let go 0.48 m up its
   side.  Energy may leave through the contacts, never enter (before,
   each join crossed let the ball sink into the next face and the push
   out gave back more than it took: +7% in 30 s).  E = m g y + m |v|^2 / 2
   + I w^2 / 2 at the step's end may still exceed its start by what the
   step's own bookkeeping allows:
   - symplectic Euler's velocity is half a kick behind the position it
     drifted with: m g (h / 2) |v| per substep's worth, h = DT / 4, with
     |v| <= sqrt(2 g 0.48 m) (all the height as speed);
   - the soft contact's spring holds the ball sunk by up to its static sag
     g / (2 pi f)^2 (f = 45 Hz) and gives it back: m g times that.
   So E(t) <= E(0) + m g (h sqrt(2 g 0.48) / 2 + g / (2 pi 45)^2). */
static void chain_valley_energy(void)
{
    const double r = 0.5, h0 = 0.48, L = 20, A = 1;
    int fi;
    for (fi = 0; fi < 2; ++fi) {
        ga2d_world *w = flat_world();
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_shape_def sd = ga2d_default_shape_def();
        ga2d_chain_def cd = ga2d_default_chain_def();
        static ga2d_vec pts[401];
        double m = PI_D * r * r, I = m * r * r / 2, x0, e0 = 0, worst = -1e30, last = 0, tol;
        double sag = G / ((2 * PI_D * 45) * (2 * PI_D * 45));
        ga2d_body_id ground, b;
        ga2d_circle c;
        int i;
        CHECK(w != NULL);
        if (!w) return;
        for (i = 0; i < 401; ++i) pts[i] = ga2d_vec_make((ga2d_real)(-L + 0.1 * i), (ga2d_real)(-A * cos(2 * PI_D * (-L + 0.1 * i) / L)));
        ground = ga2d_body_create(w, &d);
        cd.points = pts;
        cd.count = 401;
        cd.friction = (ga2d_real)(fi ? 0.6 : 0);
        CHECK(ga2d_chain_get_segments(w, ga2d_chain_create(w, ground, &cd), NULL, 0) == 400);
        /* let go where the surface is h0 above the floor, on the normal r out */
        x0 = -acos(1 - h0 / A) * L / (2 * PI_D);
        {
            double slope = A * 2 * PI_D / L * sin(2 * PI_D * x0 / L), nl = sqrt(1 + slope * slope);
            d.position = ga2d_vec_make((ga2d_real)(x0 - slope / nl * r), (ga2d_real)(-A * cos(2 * PI_D * x0 / L) + r / nl));
        }
        d.type = GA2D_BODY_DYNAMIC;
        b = ga2d_body_create(w, &d);
        sd.friction = cd.friction;
        c.center = ga2d_vec_make(0, 0);
        c.radius = (ga2d_real)r;
        CHECK(!ga2d_shape_id_is_null(ga2d_shape_create_circle(w, b, &sd, &c)));
        tol = m * G * (DT / 4 * sqrt(2 * G * h0) / 2 + sag);
        for (i = 0; i <= 1800; ++i) {
            ga2d_vec p = ga2d_body_position(w, b), v = ga2d_body_velocity(w, b);
            double om = (double)ga2d_body_angular_velocity(w, b);
            double vx = (double)v.x, vy = (double)v.y;
            double e = m * G * (double)p.y + m * (vx * vx + vy * vy) / 2 + I * om * om / 2;
            if (i == 0) e0 = e;
            worst = fmax(worst, e - e0);
            last = e - e0;
            if (i < 1800) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
        }
        CHECK(worst <= tol);
        if (getenv("GA2D_TEST_VERBOSE"))
            printf("  shape_terrain: ball rocking in a chain valley, mu %.1f: energy at most %+.3g J above its start (bound %.3g), "
                   "%+.2f%% of the swing after 30 s\n",
                   fi ? 0.6 : 0.0, worst, tol, 100 * last / (m * G * h0));
        ga2d_world_destroy(w);
    }
}

void suite_shape_terrain(void)
{
    test_run("shape_terrain: a box and a ball slide a straight 40-segment chain keeping vx exactly", chain_slide);
    test_run("shape_terrain: a belt drives a slipping box at mu g", conveyor);
    test_run("shape_terrain: valleys of every angle hold balls and boxes at speeds up to the cap", chain_valleys_hold);
    test_run("shape_terrain: hilltops of every angle hold balls and boxes at speeds up to the cap", chain_hilltops_hold);
    test_run("shape_terrain: a ball rolling over a hilltop is held by its vertex", chain_hilltop_vertex_holds);
    test_run("shape_terrain: a ball rocking in a chain's valley never gains energy", chain_valley_energy);
}
