/* platformer.c - a capsule character walks through a level of chain
   terrain: flat ground, a 30 degree ramp it walks up, a plateau, a
   50 degree slope it cannot climb, and a wall.  The character is not a
   body; it moves by asking the world where it may go
   (ga2d_world_cast_shape, through examples/mover.h: move and slide).

   It prints where the character got to each second: dropped onto the
   flat ground and walking right for 6 s, it climbs the 30 degree ramp
   and stops at the foot of the 50 degree slope; then it walks left for
   2 s, back down the ramp; then it stands on the ramp for 2 s, where it
   must neither slide nor jitter.  The exit status is 0 when it did all
   of that.  tests/test_mover.c checks the same moves against their
   geometry. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "mover.h"
#include <stdio.h>

#define PI 3.14159265358979

/* The level: ground at y = 0 from x = -10 to 0, a 30 degree ramp up to
   x = 4, a plateau to x = 8, a 50 degree slope up 3 m, and the level's
   walls.  The chain runs left to right: its front (left of travel) is up. */
static void build_level(ga2d_world *w)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_body_id g = ga2d_body_create(w, &bd);
    double ramp = 4 * tan(30 * PI / 180), steep = 3 / tan(50 * PI / 180);
    ga2d_vec pts[7];
    pts[0] = ga2d_vec_make(-10, 10);  /* the left wall's top */
    pts[1] = ga2d_vec_make(-10, 0);
    pts[2] = ga2d_vec_make(0, 0);
    pts[3] = ga2d_vec_make(4, (ga2d_real)ramp);
    pts[4] = ga2d_vec_make(8, (ga2d_real)ramp);
    pts[5] = ga2d_vec_make((ga2d_real)(8 + steep), (ga2d_real)(ramp + 3));
    pts[6] = ga2d_vec_make((ga2d_real)(20), (ga2d_real)(ramp + 3));
    cd.points = pts;
    cd.count = 7;
    ga2d_chain_create(w, g, &cd);
}

int main(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_filter all = ga2d_default_filter();
    ga2d_vec g = ga2d_vec_make(0, -10);
    mover m;
    double plateau = 4 * tan(30 * PI / 180), ymin = 1e9, ymax = -1e9, foot = 8; /* the steep slope's foot */
    int frame, ok = 1;
    if (!w) return 1;
    build_level(w);
    m.position = ga2d_vec_make(-5, 1);
    m.half_height = 0.4f;
    m.radius = 0.3f;
    m.velocity = ga2d_vec_make(0, 0);
    m.max_slope = (ga2d_real)(45 * PI / 180);
    m.on_ground = 0;
    m.ground_normal = ga2d_vec_make(0, 1);
    printf("Platformer: a 1.4 m capsule walks at 3 m/s through chain terrain, 60 frames/s\n");
    for (frame = 0; frame < 10 * 60; ++frame) {
        ga2d_real walk = frame < 6 * 60 ? 3 : (frame < 8 * 60 ? -3 : 0);
        move_and_slide(w, &m, walk, g, 1.0f / 60, all);
        if (frame % 60 == 59)
            printf("  t %4.1f s  x %7.3f  y %6.3f  %s\n", (frame + 1) / 60.0, (double)m.position.x, (double)m.position.y,
                   m.on_ground ? "on the ground" : "in the air");
        double x = (double)m.position.x, y = (double)m.position.y;
        if (frame == 6 * 60 - 1) {
            /* climbed the ramp (on the plateau, its feet at the plateau's height), stopped at the steep slope's foot */
            ok &= y > plateau && x > 4 && x < foot + 1;
            printf("  after walking right: %s the 30 degree ramp, %s at the 50 degree slope\n",
                   y > plateau ? "climbed" : "did NOT climb", x < foot + 1 ? "stopped" : "did NOT stop");
        }
        if (frame >= 8 * 60 + 30) {
            if (y < ymin) ymin = y;
            if (y > ymax) ymax = y;
        }
    }
    ok &= m.on_ground && ymax - ymin < 1e-6;
    printf("  standing for 1.5 s: height varies by %.3g m (%s)\n", ymax - ymin, ymax - ymin < 1e-6 ? "still" : "JITTERS");
    ga2d_world_destroy(w);
    return ok ? 0 : 1;
}
