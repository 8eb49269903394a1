/* The README's joints snippet (make test cuts it out of README.md into
   build/readme/joints_snippet.inc) run in a world: it must build as C99
   and C++11 and make what it says.  The bodies it names are made here:
   a static ground at the origin, a door hanging from (0, 2), a ball 2.83 m
   out (inside its 3 m rope), two boxes side by side meeting at x = 1, and
   a press point on the ball with a cursor 0.5 m to its right. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include <math.h>

static ga2d_body_id box_at(ga2d_world *w, ga2d_real x, ga2d_real y, ga2d_real hx, ga2d_real hy)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(x, y);
    d.polygon = ga2d_polygon_box(hx, hy);
    return ga2d_body_create(w, &d);
}

int main(void)
{
    ga2d_world *world = ga2d_world_create(NULL);
    ga2d_body_def gd = ga2d_default_body_def(); /* static, no shape */
    ga2d_body_id ground, door, ball, left, right;
    ga2d_vec press, cursor;
    int ok = 1, i;
    if (!world) return 1;
    ground = ga2d_body_create(world, &gd);
    door = box_at(world, 0, 1, 0.1f, 1);              /* its top at the hinge (0, 2) */
    ball = box_at(world, 2, -2, 0.2f, 0.2f);       /* 2.83 m from the origin */
    left = box_at(world, 0.5f, -8, 0.5f, 0.5f);
    right = box_at(world, 1.5f, -8, 0.5f, 0.5f);
    press = ga2d_vec_make(2, -2);
    cursor = ga2d_vec_make(2.5f, -2);
    {
#include "joints_snippet.inc"
        /* the drag is gone: hinge, rope and weld are left */
        ok &= ga2d_world_get_counters(world).joint_count == 3 && ga2d_joint_is_valid(world, hinge) &&
              !ga2d_joint_is_valid(world, drag) && !ga2d_body_is_valid(world, pin);
        for (i = 0; i < 120; ++i) ok &= ga2d_world_step(world, 1.0f / 60) == GA2D_OK;
        /* The rope holds the ball within 3 m of the ground's origin, give
           or take its feedback spring's stretch: g / (2 pi 60 Hz)^2 =
           7e-5 m under the ball's weight, at most a few times that while
           it swings (a pendulum's tension peaks at 3 m g), so 1 cm is a
           hundred times the stretch and a broken rope (the ball falls
           1 m past it in 0.5 s) is far outside it.  The welded boxes fall
           free together: their relative angle is held by the same
           feedback with no load, so it stays at 0 to rounding (0.01 rad
           is ample).  The door hangs from its hinge, inside its limits. */
        ok &= ga2d_vec_length(ga2d_body_position(world, ball)) < 3.01f;
        ok &= fabs((double)(ga2d_body_angle(world, right) - ga2d_body_angle(world, left))) < 0.01;
        ok &= ga2d_revolute_joint_angle(world, hinge) >= -1.5f - 0.1f && ga2d_revolute_joint_angle(world, hinge) <= 1.5f + 0.1f;
        ga2d_world_destroy(world);
        return ok ? 0 : 1;
    }
}
