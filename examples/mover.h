/* mover.h - a capsule character that walks, falls and slides through a
   ga2d world, built on ga2d_world_cast_shape: the building blocks of a
   platformer.  The character is not a body: the world does not push it,
   it only asks the world where it may go.  Used by examples/platformer.c
   and tests/test_mover.c.

   Each frame, move_and_slide sweeps the capsule along its velocity times
   dt.  At the closest thing in the way it stops (a skin short of it, so
   the next sweep starts clear), takes out the part of the motion into
   that surface, and sweeps the rest along it, up to MOVER_ITERATIONS
   times.  A surface whose normal is within max_slope of straight up is
   ground: there the character stands (gravity does not pile up: its
   velocity is its walk along the slope) and it stays on it walking down;
   anything steeper is a wall, which it slides down under gravity. */
#ifndef MOVER_H
#define MOVER_H
#include <math.h>

#define MOVER_ITERATIONS 4
#define MOVER_SKIN 0.005 /* m: how far from a surface the character keeps (a slop) */

typedef struct mover {
    ga2d_vec position;     /* the capsule's middle */
    ga2d_real half_height; /* from the middle to each end's centre */
    ga2d_real radius;
    ga2d_vec velocity;     /* m/s */
    ga2d_real max_slope;   /* rad: steeper is a wall */
    int on_ground;
    ga2d_vec ground_normal;
} mover;

typedef struct mover_hit {
    ga2d_vec direction; /* the sweep's, to tell surfaces ahead from those beside or behind */
    ga2d_real fraction;
    ga2d_vec normal;
    int hit;
} mover_hit;

/* The closest surface ahead: one the sweep runs into (a surface it slides
   along or leaves is not in the way, even touching), clipped to as each
   is found. */
static ga2d_real mover_closest(ga2d_shape_id shape, ga2d_vec point, ga2d_vec normal, ga2d_real fraction, void *context)
{
    mover_hit *h = (mover_hit *)context;
    (void)shape;
    (void)point;
    if (ga2d_dot(normal, h->direction) > -(ga2d_real)1e-3 * ga2d_vec_length(h->direction)) return -1; /* beside or behind */
    if (h->hit && fraction >= h->fraction) return -1;
    h->hit = 1;
    h->fraction = fraction;
    h->normal = normal;
    return fraction;
}

static ga2d_shape_proxy mover_proxy(const mover *m)
{
    ga2d_vec ends[2];
    ends[0] = ga2d_vec_make(0, -m->half_height);
    ends[1] = ga2d_vec_make(0, m->half_height);
    return ga2d_make_proxy(ends, 2, m->radius);
}

/* d: where the capsule wants to go; returns the surface met, if any, and
   moves it there (a skin short). */
static mover_hit mover_sweep(const ga2d_world *w, mover *m, ga2d_vec d, ga2d_filter filter)
{
    ga2d_shape_proxy p = mover_proxy(m);
    mover_hit h;
    h.direction = d;
    h.fraction = 1;
    h.normal = ga2d_vec_make(0, 0);
    h.hit = 0;
    ga2d_world_cast_shape(w, &p, ga2d_transform_make(m->position, ga2d_rotor_identity()), d, filter, mover_closest, &h);
    if (!h.hit) {
        m->position = ga2d_vec_add(m->position, d);
        return h;
    }
    /* up to the surface, then a skin back out along its normal */
    m->position = ga2d_vec_add(m->position, ga2d_vec_scale(d, h.fraction));
    m->position = ga2d_vec_add(m->position, ga2d_vec_scale(h.normal, (ga2d_real)MOVER_SKIN));
    return h;
}

/* One frame: walk (m/s along the ground, or in the air), gravity, and the
   sweeps.  The ground found this frame is kept for the next one. */
static void move_and_slide(const ga2d_world *w, mover *m, ga2d_real walk, ga2d_vec gravity, ga2d_real dt, ga2d_filter filter)
{
    ga2d_real cos_max = (ga2d_real)cos((double)m->max_slope);
    ga2d_vec d;
    int i, was_on_ground = m->on_ground;
    if (was_on_ground) {
        /* walking follows the ground's slope: along its tangent (normal turned -90 degrees: +x for a flat floor) */
        ga2d_vec tangent = ga2d_vec_make(m->ground_normal.y, -m->ground_normal.x);
        m->velocity = ga2d_vec_scale(tangent, walk);
    } else {
        m->velocity.x = walk;
        m->velocity = ga2d_vec_add(m->velocity, ga2d_vec_scale(gravity, dt));
    }
    /* pressed onto the ground a little every frame, so walking down a slope keeps to it */
    d = ga2d_vec_scale(m->velocity, dt);
    if (was_on_ground) d = ga2d_vec_add(d, ga2d_vec_scale(m->ground_normal, -2 * (ga2d_real)MOVER_SKIN));
    m->on_ground = 0;
    for (i = 0; i < MOVER_ITERATIONS && ga2d_vec_length(d) > (ga2d_real)1e-6; ++i) {
        mover_hit h = mover_sweep(w, m, d, filter);
        ga2d_vec rest;
        if (!h.hit) break;
        if (h.normal.y >= cos_max) {
            m->on_ground = 1;
            m->ground_normal = h.normal;
        }
        /* the rest of the motion, less its part into the surface; the
           velocity too.  A slope too steep to stand on stops a walk into
           it as a wall would (its normal taken level) wherever sliding
           along it would carry the character up it; falling onto it, the
           character slides down. */
        rest = ga2d_vec_scale(d, 1 - h.fraction);
        d = ga2d_vec_sub(rest, ga2d_vec_scale(h.normal, ga2d_dot(rest, h.normal)));
        if (h.normal.y < cos_max && h.normal.y > 0 && d.y > 0 && h.normal.x != 0) {
            h.normal = ga2d_vec_make(h.normal.x > 0 ? (ga2d_real)1 : (ga2d_real)-1, 0);
            d = ga2d_vec_sub(rest, ga2d_vec_scale(h.normal, ga2d_dot(rest, h.normal)));
        }
        if (ga2d_dot(m->velocity, h.normal) < 0)
            m->velocity = ga2d_vec_sub(m->velocity, ga2d_vec_scale(h.normal, ga2d_dot(m->velocity, h.normal)));
    }
}

#endif
