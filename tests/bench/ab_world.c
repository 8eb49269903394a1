/* ab_world.c - one build of the header for ab_steps.c (see ab_world.h):
   compiled with -DAB_SIDE=old or -DAB_SIDE=new and -I the folder of that
   build's ga2d_physics.h.  Builds scenes with scene_run.h's own body
   maker, so a world here is the world bench_scenes runs. */
#define _POSIX_C_SOURCE 199309L
#define GA2D_IMPLEMENTATION
#define GA2D_STATIC
#if !defined(BENCH_BOXES_ONLY) && !defined(AB_FULL)
#define BENCH_BOXES_ONLY /* nothing the header before shapes lacks */
#endif
#include "ga2d_physics.h"
#include "scenes.h"
#include "scene_run.h"
#include "ab_world.h"

#ifndef AB_SIDE
#error "ab_world.c: build it with -DAB_SIDE=old or -DAB_SIDE=new"
#endif
#define AB_CAT3(a, b, c) a##b##c
#define AB_NAME(side, name) AB_CAT3(ab_, side, name)
#define AB_FN(name) AB_NAME(AB_SIDE, _##name)

struct ab_world {
    ga2d_world *w;
    bench_scene s;
    ga2d_body_id *ids;
    ga2d_contact_data *contacts;
    int capacity;
    double p0[2], deepest;
    ga2d_vec start;
};

void AB_FN(free)(ab_world *a)
{
    if (!a) return;
    if (a->w) ga2d_world_destroy(a->w);
    free(a->ids);
    free(a->contacts);
    bench_scene_free(&a->s);
    free(a);
}

int AB_FN(holds)(const char *scene)
{
    bench_scene s;
    int i, fixed;
    if (bench_scene_make(scene, &s) != 0) return -1;
    fixed = s.chain_count == 0;
    for (i = 0; fixed && i < s.count; ++i) fixed = s.bodies[i].birth == 0 && s.bodies[i].death == 0;
    bench_scene_free(&s);
    return fixed;
}

ab_world *AB_FN(make)(const char *scene)
{
    ab_world *a = (ab_world *)calloc(1, sizeof *a);
    ga2d_world_def wd;
    int i, ok;
    if (!a) return NULL;
    if (bench_scene_make(scene, &a->s) != 0) {
        free(a);
        return NULL;
    }
    wd = sr_scene_def(&a->s, ga2d_default_world_def());
    a->w = ga2d_world_create(&wd);
    a->ids = (ga2d_body_id *)malloc((size_t)a->s.count * sizeof *a->ids);
    ok = a->w != NULL && a->ids != NULL;
    for (i = 0; ok && i < a->s.count; ++i) {
        ok = a->s.bodies[i].birth == 0 && a->s.bodies[i].death == 0; /* a fixed list of bodies */
        if (ok) a->ids[i] = sr__make_body(a->w, &a->s, i, 0);
        ok = ok && !ga2d_body_id_is_null(a->ids[i]);
    }
    ok = ok && sr__make_joints(a->w, &a->s, a->ids); /* AB_FULL: joint_grid's */
    if (!ok) {
        AB_FN(free)(a);
        return NULL;
    }
    a->start = ga2d_body_center(a->w, a->ids[a->s.probe]);
    sr__momentum(a->w, &a->s, a->ids, a->p0);
    return a;
}

int AB_FN(steps)(const ab_world *a) { return a->s.steps; }

double AB_FN(step)(ab_world *a)
{
    double t0, t1;
    ga2d_result r;
    int i;
    for (i = 0; i < a->s.count; ++i)
        if (a->s.bodies[i].type == BENCH_KINEMATIC) {
            ga2d_vec c = ga2d_body_center(a->w, a->ids[i]);
            double vx, vy;
            bench_scene_kinematic_velocity(&a->s, (double)c.x, (double)c.y, &vx, &vy);
            ga2d_body_set_velocity(a->w, a->ids[i], sr__vec(vx, vy));
            ga2d_body_set_angular_velocity(a->w, a->ids[i], (ga2d_real)a->s.pivot_w);
        }
    t0 = sr_now_ms();
    r = ga2d_world_step(a->w, (ga2d_real)a->s.dt);
    t1 = sr_now_ms();
    if (a->s.figure == BENCH_FIG_PENETRATION) {
        double d = sr__deepest(a->w, &a->contacts, &a->capacity);
        if (!(d <= a->deepest)) a->deepest = d;
    }
    return r == GA2D_OK ? t1 - t0 : -1;
}

double AB_FN(figure)(const ab_world *a)
{
    if (a->s.figure == BENCH_FIG_DRIFT) {
        ga2d_vec c = ga2d_body_center(a->w, a->ids[a->s.probe]);
        return hypot((double)c.x - (double)a->start.x, (double)c.y - (double)a->start.y);
    }
    if (a->s.figure == BENCH_FIG_SAG) { /* start y - end y */
        ga2d_vec c = ga2d_body_center(a->w, a->ids[a->s.probe]);
        return (double)a->start.y - (double)c.y;
    }
    if (a->s.figure == BENCH_FIG_MOMENTUM) {
        double p[2];
        sr__momentum(a->w, &a->s, a->ids, p);
        return hypot(p[0] - a->p0[0], p[1] - a->p0[1]) / hypot(a->p0[0], a->p0[1]);
    }
    return a->deepest;
}

const char *AB_FN(figure_name)(const ab_world *a) { return bench_scene_figure_name(&a->s); }
