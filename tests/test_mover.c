/* A capsule character moved by examples/mover.h (move and slide on
   ga2d_world_cast_shape), against the geometry of what it walks on
   (issue 25: enough to write a platformer character that walks up slopes
   below 45 degrees, stops at walls and does not jitter on the ground).

   The sweep stops within a quarter slop of touching (ga2d_shape_cast's
   tolerance, never past it) and the mover then steps a skin (MOVER_SKIN,
   one slop) back along the surface's normal, so the character's surface
   rests between a skin and a skin and a quarter slop from what it stands
   on: SKIN_BAND.  Where it must stand still, its position must not change
   at all: the same frame, computed from the same position, gives the same
   bits. */
#include "test.h"
#include "examples/mover.h"

#define PI 3.14159265358979
#define HH 0.4   /* the capsule's half height (between its ends' centres), m */
#define RAD 0.3  /* its radius, m */
#define SKIN_LO MOVER_SKIN
#define SKIN_HI (MOVER_SKIN + GA2D_LINEAR_SLOP / 4 + 1e-5) /* + rounding of metre-sized coordinates in float, with margin */

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static double dlength(ga2d_vec a, ga2d_vec b) { return hypot((double)a.x - (double)b.x, (double)a.y - (double)b.y); }

static mover make_mover(double x, double y)
{
    mover m;
    m.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    m.half_height = (ga2d_real)HH;
    m.radius = (ga2d_real)RAD;
    m.velocity = ga2d_vec_make(0, 0);
    m.max_slope = (ga2d_real)(45 * PI / 180);
    m.on_ground = 0;
    m.ground_normal = ga2d_vec_make(0, 1);
    return m;
}

/* A chain of n points, its front up (left of travel). */
static void chain(ga2d_world *w, const double (*p)[2], int n)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_vec pts[16];
    int i;
    for (i = 0; i < n; ++i) pts[i] = ga2d_vec_make((ga2d_real)p[i][0], (ga2d_real)p[i][1]);
    cd.points = pts;
    cd.count = n;
    ga2d_chain_create(w, ga2d_body_create(w, &bd), &cd);
}

/* Standing on flat ground: lands, rests a skin above it, and from then on
   its position is the same bits every frame, walking or not. */
static void stands_still(void)
{
    static const double ground[][2] = {{-50, 0}, {50, 0}};
    ga2d_world *w = ga2d_world_create(NULL);
    mover m = make_mover(0, 3);
    ga2d_vec at;
    int f, moved = 0;
    chain(w, ground, 2);
    for (f = 0; f < 120; ++f) move_and_slide(w, &m, 0, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
    CHECK(m.on_ground);
    /* its feet (the lower end's circle) a skin above y = 0 */
    CHECK((double)m.position.y - HH - RAD >= SKIN_LO - 1e-6 && (double)m.position.y - HH - RAD <= SKIN_HI);
    at = m.position;
    for (f = 0; f < 120; ++f) {
        move_and_slide(w, &m, 0, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
        moved |= m.position.x != at.x || m.position.y != at.y;
    }
    CHECK(!moved);
    /* walking: x = 2 m/s t exactly as on a floor, y unchanged */
    for (f = 0; f < 60; ++f) move_and_slide(w, &m, 2, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
    CHECK_NEAR(m.position.x, (double)at.x + 2 * 60 * (double)((ga2d_real)1.0 / 60), 60 * 4 * REAL_EPS * 2); /* 60 sums of 2 h (h the float 1/60 passed), each rounded at x ~ 2 */
    CHECK((double)m.position.y - HH - RAD >= SKIN_LO - 1e-6 && (double)m.position.y - HH - RAD <= SKIN_HI);
    if (verbose())
        printf("mover: stands %.6f m above the floor (skin %.4f to %.4f), still for 2 s, walks 2 m in 1 s to %.3g\n",
               (double)at.y - HH - RAD, SKIN_LO, SKIN_HI, (double)m.position.x - (double)at.x - 2);
    ga2d_world_destroy(w);
}

/* Ramps of every angle from 5 to 85 degrees: below 45 it walks up to the
   top, above it stops at the foot (its x there at most the foot's, less
   its radius, plus the skin band), and it never goes through. */
static void slopes(void)
{
    int deg, climbed = 0, stopped = 0;
    for (deg = 5; deg <= 85; deg += 5) {
        double a = deg * PI / 180, rise = 1, run = rise / tan(a);
        double level[4][2];
        ga2d_world *w = ga2d_world_create(NULL);
        mover m = make_mover(-3, HH + RAD + 0.01);
        int f;
        if (deg == 45) {
            ga2d_world_destroy(w);
            continue; /* exactly the limit: either is right */
        }
        level[0][0] = -50, level[0][1] = 0;
        level[1][0] = 0, level[1][1] = 0;
        level[2][0] = run, level[2][1] = rise;
        level[3][0] = run + 50, level[3][1] = rise;
        chain(w, (const double (*)[2])level, 4);
        for (f = 0; f < 10 * 60; ++f) move_and_slide(w, &m, 3, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
        /* never inside the terrain: its lower end's circle above the ground line under it */
        if (deg < 45) {
            CHECK((double)m.position.y > rise + HH + RAD); /* on the top */
            CHECK((double)m.position.x > run);
            climbed += (double)m.position.x > run;
        } else {
            /* at the foot, in the corner: never inside the slope or the
               floor, and touching the slope within three skins (a skin
               from each surface, and the level push a wall takes) */
            /* the lower circle's centre's distance from the slope's line (through the origin at angle a), in front > 0 */
            double cx = (double)m.position.x, cy = (double)m.position.y - HH, dist = -(cx * sin(a)) + cy * cos(a);
            CHECK((double)m.position.y < HH + RAD + 0.1); /* still on the flat */
            CHECK(dist >= RAD - 1e-5 && dist <= RAD + 3 * SKIN_HI);
            CHECK((double)m.position.y - HH - RAD >= -1e-5);
            stopped += (double)m.position.y < HH + RAD + 0.1;
        }
        if (verbose()) printf("mover: %d deg: at %.4f, %.4f\n", deg, (double)m.position.x, (double)m.position.y);
        ga2d_world_destroy(w);
    }
    CHECK(climbed == 8 && stopped == 8);
    if (verbose()) printf("mover: ramps of 5 to 40 degrees climbed (%d of 8), 50 to 85 stopped at the foot (%d of 8)\n", climbed, stopped);
}

/* A wall (a static box): walking into it stops a skin short, every frame
   the same, and never through; walking off a ledge falls as g t^2 / 2
   (symplectic Euler per frame: the drop after n frames is g h^2 n(n+1)/2). */
static void walls_and_ledges(void)
{
    static const double ground[][2] = {{-50, 0}, {5, 0}};
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_polygon box = ga2d_polygon_box((ga2d_real)0.5, 2);
    mover m = make_mover(0, HH + RAD + 0.01), fall;
    int f, moved = 0;
    double jitter = 0;
    ga2d_vec at;
    chain(w, ground, 2);
    bd.position = ga2d_vec_make(3, 2);
    bd.polygon = box;
    ga2d_body_create(w, &bd); /* a wall whose face is at x = 2.5 */
    for (f = 0; f < 120; ++f) move_and_slide(w, &m, 3, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
    CHECK((double)m.position.x + RAD <= 2.5 - SKIN_LO + 1e-5 && (double)m.position.x + RAD >= 2.5 - SKIN_HI);
    at = m.position;
    /* pressed against the wall and the floor at once, each sweep stops
       within its quarter-slop tolerance of one of them: the position may
       move by that much from frame to frame, no more */
    for (f = 0; f < 60; ++f) {
        ga2d_vec before = m.position;
        double step;
        move_and_slide(w, &m, 3, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
        step = dlength(before, m.position);
        if (step > jitter) jitter = step;
    }
    CHECK(jitter <= GA2D_LINEAR_SLOP / 4);
    (void)moved;
    ga2d_world_destroy(w);
    /* the ledge: a floor ending at x = 0, the character walking off it */
    {
        static const double ledge[][2] = {{-50, 0}, {0, 0}, {0, -100}};
        double y0;
        int n;
        w = ga2d_world_create(NULL);
        chain(w, ledge, 3);
        fall = make_mover(0.2, 1); /* its middle 0.2 m past the edge: held by its rounded end (radius 0.3) */
        for (f = 0; f < 30; ++f) move_and_slide(w, &fall, 0, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
        CHECK(fall.on_ground); /* held by the edge under its rounded end */
        for (f = 0; f < 60 && fall.on_ground; ++f) move_and_slide(w, &fall, 1, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
        CHECK(!fall.on_ground);
        /* then clear of the edge it falls freely: after 60 frames it is
           far below the ledge (g t^2 / 2 = 5 m in 1 s, less the frames
           spent rolling off the corner) */
        for (n = 0; n < 60; ++n) move_and_slide(w, &fall, 0, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
        CHECK(!fall.on_ground && (double)fall.position.y < -2);
        /* in the open, from rest: frame k adds g h to the speed and then
           moves by it, so n frames drop g h^2 n (n + 1) / 2 (symplectic
           Euler), to the rounding of 30 sums of numbers below 2 m */
        fall = make_mover(20, 50);
        y0 = (double)fall.position.y;
        for (n = 1; n <= 30; ++n) move_and_slide(w, &fall, 0, ga2d_vec_make(0, -10), (ga2d_real)1.0 / 60, ga2d_default_filter());
        CHECK_NEAR(y0 - (double)fall.position.y, 10.0 * (double)((ga2d_real)1.0 / 60) * (double)((ga2d_real)1.0 / 60) * 30 * 31 / 2, 30 * 4 * REAL_EPS * 50);
        ga2d_world_destroy(w);
    }
    if (verbose())
        printf("mover: stops %.5f m short of a wall (skin band %.4f to %.4f), moving at most %.3g m a frame there "
               "(bound %.4g); falls off a ledge as g t^2/2\n", 2.5 - (double)at.x - RAD, SKIN_LO, SKIN_HI, jitter, GA2D_LINEAR_SLOP / 4);
}

void suite_mover(void)
{
    test_run("mover: stands still", stands_still);
    test_run("mover: slopes", slopes);
    test_run("mover: walls and ledges", walls_and_ledges);
}
