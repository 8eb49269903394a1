/* hello.c - a box falls onto the ground; its position every 10 steps. */
#include <stdio.h>
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

int main(void)
{
    ga2d_world_def wd = ga2d_default_world_def(); /* gravity (0, -10) */
    ga2d_world *world = ga2d_world_create(&wd);
    if (!world) return 1;
    ga2d_body_def ground = ga2d_default_body_def(); /* static */
    ground.position = ga2d_vec_make(0, -1);
    ground.polygon = ga2d_polygon_box(20, 1); /* its top face is y = 0 */
    ga2d_body_create(world, &ground);

    ga2d_body_def bd = ga2d_default_body_def(); /* a 1 m box */
    bd.polygon = ga2d_polygon_box(0.5f, 0.5f);
    bd.type = GA2D_BODY_DYNAMIC;
    bd.position = ga2d_vec_make(0, 4);
    ga2d_body_id box = ga2d_body_create(world, &bd);

    for (int i = 1; i <= 120; ++i) { /* 2 s at 60 steps a second */
        ga2d_world_step(world, (ga2d_real)1 / 60);
        if (i % 10 != 0) continue;
        ga2d_vec p = ga2d_body_position(world, box); /* its origin: the centre */
        printf("t = %.2f s  y = %.3f m  %s\n", i / 60.0, (double)p.y,
               ga2d_body_is_awake(world, box) ? "awake" : "asleep");
    }
    ga2d_world_destroy(world);
    return 0;
}
