/* The README's shapes snippet (make test cuts it out of README.md into
   build/readme/shapes_snippet.inc) run in a world: it must build as C99
   and C++11 and make what it says: a ball with one shape, a ground with
   its chain's four segments and the sensor, a world that steps. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

int main(void)
{
    ga2d_world *world = ga2d_world_create(NULL);
    if (!world) return 1;
    {
#include "shapes_snippet.inc"
        int i, ok = ga2d_body_get_shapes(world, ground, NULL, 0) == 5 && ga2d_body_get_shapes(world, ball, NULL, 0) == 1 &&
                    ga2d_shape_is_valid(world, trigger);
        for (i = 0; i < 60; ++i) ok &= ga2d_world_step(world, 1.0f / 60) == GA2D_OK;
        ga2d_world_destroy(world);
        return ok ? 0 : 1;
    }
}
