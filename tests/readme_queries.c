/* The README's queries snippet (make test cuts it out of README.md into
   build/readme/queries_snippet.inc) run in a world: it must build as C99
   and C++11 and answer what it says.  The world: a static ground (a box
   20 m wide, its top at y = 0), a 1 m box at (5, 0.5) and a ball of
   radius 0.5 at (-3, 0.5).  A gun at (0, 0.5) aiming +x hits the box's
   face at x = 4.5 (fraction 4.5 / 100, normal -x); the mouse on the ball
   picks the ball; a blast of 3 m at (5, 2) reaches the box and the ground
   but not the ball (8 m off). */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include <math.h>

#include "queries_snippet.inc"

int main(void)
{
    ga2d_world *world = ga2d_world_create(NULL);
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c = {{0, 0}, 0.5f};
    ga2d_body_id box, ball;
    ga2d_shape_id ball_shape;
    sight s;
    int ok = 1;
    if (!world) return 1;
    d.position = ga2d_vec_make(0, -0.5f);
    d.polygon = ga2d_polygon_box(10, 0.5f);
    ga2d_body_create(world, &d);
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(5, 0.5f);
    d.polygon = ga2d_polygon_box(0.5f, 0.5f);
    box = ga2d_body_create(world, &d);
    d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(-3, 0.5f);
    ball = ga2d_body_create(world, &d);
    ball_shape = ga2d_shape_create_circle(world, ball, &sd, &c);
    s = look(world, ga2d_vec_make(0, 0.5f), ga2d_vec_make(1, 0), ga2d_vec_make(-3, 0.6f), ga2d_vec_make(5, 2));
    /* the face is at 4.5 m: the fraction to a few ulps of 0.045, the
       normal exactly -x (the box is unturned) */
    ok &= s.hit.hit && ga2d_body_id_equal(s.hit.body, box) && fabs((double)s.hit.fraction - 0.045) < 1e-6;
    ok &= s.hit.normal.x == -1 && s.hit.normal.y == 0;
    ok &= ga2d_shape_id_equal(s.picked, ball_shape);
    ok &= s.in_blast == 2;
    ga2d_world_destroy(world);
    return ok ? 0 : 1;
}
